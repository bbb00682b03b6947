//! The plan of an illuminance grid: the grid seen from the side its normal points to, so
//! that it is never mirrored. The plan's up is the world's up (`+y`, as for the cameras)
//! made perpendicular to the normal, its right `up × normal`, so that right × up =
//! normal: the viewer stands on the normal's side. A floor or a ceiling (normal `±y`) has
//! `+x` to the right: seen from above (`+y`), `z` grows down the page, as on a plan of a
//! y-up world; seen from below, up the page. The axes read world coordinates in metres
//! where they lie along world axes, else the distance from the grid's origin.

use crate::scene::Grid;
use glam::{DVec2, DVec3};

/// One axis of the plan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Unit vector of the plan's rightward (or upward) direction, in the world.
    pub along: DVec3,
    /// The world coordinate its ticks read (0, 1, 2 for x, y, z), or `None`: the distance
    /// from the grid's origin.
    pub world: Option<usize>,
}

impl Axis {
    fn of(direction: DVec3) -> Axis {
        let axis = (0..3).find(|&k| direction[k].abs() > 1.0 - 1e-9);
        Axis { along: direction, world: axis }
    }

    /// The plan coordinate of `p`, metres, growing rightward (upward).
    pub fn plan(&self, p: DVec3, origin: DVec3) -> f64 {
        match self.world {
            Some(_) => self.along.dot(p),
            None => self.along.dot(p - origin),
        }
    }

    /// What a tick at plan coordinate `c` reads: a world coordinate or a distance, m.
    pub fn reading(&self, c: f64) -> f64 {
        match self.world {
            Some(k) => c * self.along[k].signum(),
            None => c,
        }
    }

    /// The axis's caption: `x, m` or, off the world axes, `m from the grid's origin`.
    pub fn caption(&self) -> String {
        match self.world {
            Some(k) => format!("{}, m", ["x", "y", "z"][k]),
            None => "m from the grid's origin".into(),
        }
    }
}

/// The plan's frame of a grid: its rightward and upward axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// The plan's rightward direction.
    pub right: Axis,
    /// The plan's upward direction.
    pub up: Axis,
    origin: DVec3,
}

impl Frame {
    /// The frame of `grid`: up is the world's up (`+y`, as the cameras') made
    /// perpendicular to the normal, right is `up × normal`; a floor or ceiling (normal
    /// `±y`) has `+x` to the right.
    pub fn of(grid: &Grid) -> Frame {
        let n = grid.normal;
        let (right, up) = if n.cross(DVec3::Y).length() < 1e-9 {
            (DVec3::X, n.cross(DVec3::X).normalize())
        } else {
            let up = (DVec3::Y - n * n.dot(DVec3::Y)).normalize();
            (up.cross(n).normalize(), up)
        };
        Frame { right: Axis::of(right), up: Axis::of(up), origin: grid.origin }
    }

    /// `p` on the plan, metres (rightward, upward).
    pub fn plan(&self, p: DVec3) -> DVec2 {
        DVec2::new(self.right.plan(p, self.origin), self.up.plan(p, self.origin))
    }
}

/// Where the plan lies in the picture: a rectangle of pixels and the metres it shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// The plot's left, top, right and bottom pixel.
    pub plot: [i32; 4],
    /// The plan coordinates at the plot's lower-left corner, m.
    pub corner: DVec2,
    /// Pixels per metre.
    pub scale: f64,
}

impl Layout {
    /// The plan rectangle `[low, high]` (m) drawn at most `size` pixels on its longer
    /// side, with its lower-left corner at pixel `(left, top + height)`.
    pub fn fit(low: DVec2, high: DVec2, size: f64, (left, top): (i32, i32)) -> Layout {
        let span = (high - low).max(DVec2::splat(1e-9));
        let scale = size / span.max_element();
        let (w, h) = ((span.x * scale).round().max(1.0) as i32, (span.y * scale).round().max(1.0) as i32);
        Layout { plot: [left, top, left + w, top + h], corner: low, scale }
    }

    /// The pixel (fractional) of plan point `q`.
    pub fn pixel(&self, q: DVec2) -> DVec2 {
        let d = (q - self.corner) * self.scale;
        DVec2::new(self.plot[0] as f64 + d.x, self.plot[3] as f64 - d.y)
    }

    /// The plan point at pixel `(x, y)`.
    pub fn point(&self, x: f64, y: f64) -> DVec2 {
        self.corner + DVec2::new(x - self.plot[0] as f64, self.plot[3] as f64 - y) / self.scale
    }
}
