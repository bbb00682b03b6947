//! Grid points that do not stand in the room (issue 37, point 1): a point inside a solid,
//! or under a surface nearer than the grid's spacing. Its reading is the dark inside of a
//! solid or of a gap narrower than a cell, not the light of the area the cell stands for,
//! so `grid.rs` leaves it out of `E_avg`, `E_min`, `E_max` and `U0` (`docs/design.md` §5).
//!
//! One ray from the point along the grid's normal (the side that receives light): the
//! first face it meets is the back of a one-sided surface (the point is inside a solid,
//! whatever the distance), or any face nearer than the spacing (a desk top over the plane).

use crate::model::Model;
use crate::readout::gather::Receiver;
use crate::scene::Grid;
use glam::DVec3;

/// Why a grid point is left out: the surface over it and how.
#[derive(Debug, Clone, PartialEq)]
pub struct Obstruction {
    /// The surface met first along the grid's normal (index into the scene's surfaces).
    pub surface: usize,
    /// The ray met that surface's back: the point is inside a solid.
    pub inside: bool,
    /// Distance from the point to that surface along the normal, m.
    pub distance: f64,
}

/// A grid's spacing: the longer side of its cells, m.
pub fn spacing(grid: &Grid) -> f64 {
    let [nu, nv] = grid.resolution;
    (grid.edge_u.length() / nu as f64).max(grid.edge_v.length() / nv as f64)
}

/// What stands over the point `p` of a grid facing the unit `n` with cells `spacing` m
/// wide, if it is to be left out.
pub fn obstruction(model: &Model, p: DVec3, n: DVec3, spacing: f64) -> Option<Obstruction> {
    let (mesh, faces) = (&model.mesh, &model.faces);
    let ignore = Receiver::at(model, p, n).ignore;
    let hit = faces.landing(mesh, &model.visibility, p, n, ignore)?;
    let distance = (hit.point - p).dot(n);
    let inside = hit.facing.is_none();
    let surface = mesh.patches[faces.first(hit.face)].surface as usize;
    (inside || distance < spacing).then_some(Obstruction { surface, inside, distance })
}

/// The obstruction of every point of `grid`.
pub fn obstructions(model: &Model, grid: &Grid, points: &[DVec3]) -> Vec<Option<Obstruction>> {
    let s = spacing(grid);
    points.iter().map(|&p| obstruction(model, p, grid.normal, s)).collect()
}
