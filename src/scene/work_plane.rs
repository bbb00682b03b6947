//! `work_plane = { height = 0.75, border = 0.5 }` of a `[[grid]]` (issue 37, point 1): the
//! horizontal grid over the scene's floor plan (the surfaces' bounding box in x and z) less
//! a border band, at a height, facing up (+y), with the EN 12464-1 spacing
//! `p = 0.2 · 5^log10(d)` m (`d` the longer side of the area, m) as the largest: each side
//! gets `⌈side / p⌉` points (`docs/photometry.md`, "Work planes").

use super::check::{Context, show};
use super::error::SceneError;
use glam::DVec3;
use serde::Deserialize;

/// The border band left out along the walls by default, m (EN 12464-1's 0.5 m).
pub const BORDER: f64 = 0.5;

/// `work_plane = { … }`.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWorkPlane {
    /// Height of the plane, m.
    pub height: f64,
    /// Band left out along the bounding box's sides, m.
    #[serde(default = "border")]
    pub border: f64,
}

fn border() -> f64 {
    BORDER
}

/// The largest grid spacing of EN 12464-1 for an area whose longer side is `d` m, m.
pub fn en12464_spacing(d: f64) -> f64 {
    0.2 * 5f64.powf(d.log10())
}

/// The grid a work plane stands for: origin, `edge_u` (along z), `edge_v` (along x; so
/// `edge_u × edge_v` is +y) and the points along each, over the box `(low, high)`.
pub(super) fn work_plane(
    at: &Context,
    w: &RawWorkPlane,
    (low, high): (DVec3, DVec3),
) -> Result<(DVec3, DVec3, DVec3, [usize; 2]), SceneError> {
    let height = at.finite("work_plane", w.height)?;
    let border = at.non_negative("work_plane", w.border)?;
    if !(low.y..=high.y).contains(&height) {
        let message = format!("height {height} m lies outside the scene's surfaces, y from {} to {} m", low.y, high.y);
        return Err(at.error("work_plane", message));
    }
    let (lo, hi) = (low + DVec3::splat(border), high - DVec3::splat(border));
    let (x, z) = (hi.x - lo.x, hi.z - lo.z);
    if x <= 0.0 || z <= 0.0 {
        let message = format!(
            "border {border} m leaves no area inside the surfaces' plan, from {} to {}",
            show(DVec3::new(low.x, 0.0, low.z)),
            show(DVec3::new(high.x, 0.0, high.z))
        );
        return Err(at.error("work_plane", message));
    }
    let p = en12464_spacing(x.max(z));
    let points = |side: f64| ((side / p).ceil() as usize).clamp(1, 1000);
    let origin = DVec3::new(lo.x, height, lo.z);
    Ok((origin, DVec3::new(0.0, 0.0, z), DVec3::new(x, 0.0, 0.0), [points(z), points(x)]))
}
