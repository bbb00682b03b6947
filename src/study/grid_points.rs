//! Warnings about a grid's points (issue 37, point 1): the points left out of its
//! statistics (inside a solid or under a surface nearer than the spacing,
//! `readout::obstructed`), counted and named; and a grid whose receiving side faces away
//! from every source (luminaire, sun, opening, emitting surface), which reads only the
//! light reflected back at it.

use crate::io::{LeftOut, Warning};
use crate::luminaire::Light;
use crate::model::Model;
use crate::readout::obstructed::{Obstruction, obstructions, spacing};
use crate::scene::{Grid, Scene};

/// Left-out points named one by one in a warning; the rest are counted.
pub const NAMED: usize = 4;

/// One warning per grid of `scene` with points left out of its statistics: the model alone
/// shows them (the same test as `GridReading`'s), so `--strict` refuses them before the
/// solve.
pub fn left_out(scene: &Scene, model: &Model) -> Vec<Warning> {
    let obstructed = |g: &Grid| obstructions(model, g, &g.points());
    scene.grids.iter().map(|g| (g, obstructed(g))).filter_map(|(g, o)| left_out_of(scene, g, &o)).collect()
}

fn left_out_of(scene: &Scene, grid: &Grid, obstructed: &[Option<Obstruction>]) -> Option<Warning> {
    let left_out = obstructed.iter().filter(|o| o.is_some()).count();
    if left_out == 0 {
        return None;
    }
    let [nu, _] = grid.resolution;
    let named = obstructed
        .iter()
        .enumerate()
        .filter_map(|(i, o)| o.as_ref().map(|o| (i, o)))
        .take(NAMED)
        .map(|(i, o)| LeftOut {
            cell: [i % nu, i / nu],
            surface: scene.surfaces[o.surface].name.clone(),
            inside: o.inside,
            distance: o.distance,
        })
        .collect();
    Some(Warning::GridPointsLeftOut {
        grid: grid.name.clone(),
        left_out,
        points: obstructed.len(),
        spacing: spacing(grid),
        named,
    })
}

/// One warning per grid whose receiving side faces no source.
pub fn facing_away(scene: &Scene, model: &Model) -> Vec<Warning> {
    scene
        .grids
        .iter()
        .filter(|g| !faces_a_source(g, model))
        .map(|g| Warning::GridFacesAway { grid: g.name.clone(), normal: g.normal.to_array() })
        .collect()
}

/// Some source lies on the grid's receiving side (the grid is a plane: a point's side is
/// the same from every point of it), or sends parallel light onto that side.
fn faces_a_source(g: &Grid, model: &Model) -> bool {
    let above = |q: glam::DVec3| (q - g.origin).dot(g.normal) > 0.0;
    let lamps = model.sources.iter().any(|s| match &s.light {
        Light::Point { position, .. } => above(*position),
        Light::Parallel { direction, .. } => direction.dot(g.normal) < 0.0,
        Light::Window { window, .. } => window.polygon.vertices().iter().any(|&v| above(v)),
    });
    let emitters = model.mesh.emitters();
    lamps || emitters.iter().any(|&i| model.mesh.patches[i as usize].polygon.vertices().iter().any(|&v| above(v)))
}
