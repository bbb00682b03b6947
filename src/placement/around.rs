//! A candidate point on a surface and what lies around it: the first surface along its
//! normal, and the walls across its surface, found by [`RAYS`] rays along the surface
//! (turned by a random angle, [`OFFSET`] above it) out to [`REACH`]. A wall is a
//! patch that a ray meets from its front, standing across the surface (its normal within
//! 17° of the surface's plane): with the surface it makes a concave edge.

use super::shell::Shell;
use super::sight::{Seen, Sight};
use crate::geometry::Frame;
use glam::DVec3;
use std::f64::consts::TAU;

/// How far in front of its surface a probe reads, m: off the surface, so that it is not
/// read as lying on it, and far from any solid behind it.
pub const OFFSET: f64 = 1e-3;

/// Rays along the surface.
pub const RAYS: usize = 8;

/// How far along the surface walls are looked for, m.
pub const REACH: f64 = 0.6;

/// A point on a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spot {
    /// The patch it lies on.
    pub patch: usize,
    /// The point, on the patch, m.
    pub point: DVec3,
    /// The patch's frame (its normal the receiving side).
    pub frame: Frame,
    /// The patch's face.
    pub face: u32,
    /// The patch lies on the room's shell.
    pub shell: bool,
}

impl Spot {
    /// The surface's unit normal.
    pub fn normal(&self) -> DVec3 {
        self.frame.normal
    }

    /// The same surface at `point`.
    pub fn moved(&self, point: DVec3) -> Spot {
        Spot { point, ..*self }
    }

    /// Where a probe of this spot reads: [`OFFSET`] in front of the surface.
    pub fn probe(&self) -> DVec3 {
        self.point + self.normal() * OFFSET
    }
}

/// A wall across the surface of a spot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wall {
    /// A point of it, m.
    pub point: DVec3,
    /// Its unit normal, facing the spot.
    pub normal: DVec3,
    /// It lies on the room's shell.
    pub shell: bool,
    /// The spot's distance from its plane, m.
    pub distance: f64,
}

impl Wall {
    /// True when `other` lies in the same plane (within a millimetre and 2.5°).
    pub fn same_plane(&self, other: &Wall) -> bool {
        self.normal.dot(other.normal) > 0.999 && (other.point - self.point).dot(self.normal).abs() < 1e-3
    }
}

/// What a spot sees.
#[derive(Debug, Clone, PartialEq)]
pub struct Around {
    /// The first surface along the normal.
    pub ahead: Option<Seen>,
    /// The walls across the surface, one per plane, nearest first.
    pub walls: Vec<Wall>,
    /// The rays (along the normal and the surface) that met the back of a surface.
    pub backs: usize,
}

impl Around {
    /// Inside a solid: most rays meet the backs of surfaces.
    pub fn inside(&self) -> bool {
        2 * self.backs > RAYS + 1
    }

    /// Not inside a solid, and nothing within 2 mm in front of the surface.
    pub fn clear(&self) -> bool {
        !self.inside() && self.ahead.is_none_or(|s| s.distance > 2e-3 && s.patch.is_some())
    }

    /// The facing surface ahead within `distance`, m.
    pub fn facing_within(&self, distance: f64) -> Option<(Seen, usize)> {
        self.ahead.filter(|s| s.distance <= distance).and_then(|s| s.patch.map(|p| (s, p)))
    }

    /// The walls whose planes lie within `distance` of the spot, m.
    pub fn walls_within(&self, distance: f64) -> impl Iterator<Item = &Wall> {
        self.walls.iter().filter(move |w| w.distance <= distance)
    }
}

/// What `spot` sees; the rays along the surface turned by `turn` (a share of a full turn).
pub fn look(sight: &Sight, shell: &Shell, spot: &Spot, turn: f64) -> Around {
    let (origin, n) = (spot.probe(), spot.normal());
    let ahead = sight.first(spot.point, n, spot.face);
    let mut backs = usize::from(ahead.is_some_and(|s| s.patch.is_none()));
    let mut walls: Vec<Wall> = Vec::new();
    for k in 0..RAYS {
        let angle = TAU * (turn + k as f64 / RAYS as f64);
        let u = spot.frame.world(DVec3::new(angle.cos(), angle.sin(), 0.0));
        let Some(seen) = sight.first(origin, u, spot.face) else { continue };
        let Some(patch) = seen.patch else {
            backs += 1;
            continue;
        };
        let m = sight.normal(patch);
        if seen.distance > REACH || m.dot(n).abs() > 0.3 {
            continue;
        }
        let point = origin + u * seen.distance;
        let shell = shell.holds(&sight.world.mesh.patches[patch]);
        let wall = Wall { point, normal: m, shell, distance: (spot.point - point).dot(m) };
        if !walls.iter().any(|w| w.same_plane(&wall)) {
            walls.push(wall);
        }
    }
    walls.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    Around { ahead, walls, backs }
}
