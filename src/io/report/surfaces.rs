//! The report's room and materials (`docs/report.md`): every material with its
//! reflectance, and every surface's mean illuminance on its front side, derived from the
//! stored field: over the patches of the surface that are not the back twin of another
//! (`/mesh/twin`), one row per side they face (by their normal: a wall is vertical, a
//! ceiling faces down; a box has a row for each), `E_avg = Σ A_i E_i / Σ A_i` with `A_i`
//! from `/mesh/areas` and `E_i` from `/field/illuminance`, `E_min` and `E_max` the
//! patches' least and largest.

use super::super::read::Result;
use super::h5::H5;
use super::html::{escape, number, section, table};
use crate::geometry::NO_TWIN;
use crate::io::StoredSolution;
use crate::material::MaterialModel;

/// A material's parameters as a lighting engineer reads them.
fn reflectance(model: &MaterialModel) -> String {
    match *model {
        MaterialModel::Lambert { reflectance, transmittance: t } if t > 0.0 => {
            format!("diffuse, ρ = {reflectance:.2}, τ = {t:.2}")
        }
        MaterialModel::Lambert { reflectance, .. } => format!("diffuse, ρ = {reflectance:.2}"),
        MaterialModel::Phong { diffuse, specular, exponent } => {
            format!("Phong, ρ_d = {diffuse:.2}, ρ_s = {specular:.2}, n = {exponent}")
        }
        MaterialModel::Mirror { reflectance } => format!("mirror, ρ = {reflectance:.2}"),
        MaterialModel::Ggx { diffuse, specular, roughness } => {
            format!("GGX, ρ_d = {diffuse:.2}, ρ_s = {specular:.2}, α = {roughness}")
        }
    }
}

/// The materials' table.
pub(super) fn materials(stored: &StoredSolution) -> String {
    let rows: Vec<Vec<String>> =
        stored.scene.materials.iter().map(|m| vec![escape(&m.name), escape(&reflectance(&m.model))]).collect();
    let head = ["material", "reflectance"].map(str::to_string);
    section("materials", "Materials", &table("materials", &head, &rows))
}

/// The sides a patch may face, by its normal (y up).
const SIDES: [&str; 4] = ["up (floor)", "down (ceiling)", "vertical (wall)", "sloped"];

/// The index in [`SIDES`] of the side a patch whose normal has this `y` faces.
fn side(y: f64) -> usize {
    match y {
        y if y > 0.7 => 0,
        y if y < -0.7 => 1,
        y if y.abs() < 0.3 => 2,
        _ => 3,
    }
}

/// Every surface's area, facing and illuminance on its front side, lx.
pub(super) fn surfaces(h: &H5, stored: &StoredSolution) -> Result<String> {
    let patches = &stored.mesh.patches;
    let e = h.numbers_of("field/illuminance", patches.len())?;
    let scene = &stored.scene;
    let mut rows = Vec::new();
    // the front patches of surface s facing side k, in bucket 4·s + k
    let mut buckets = vec![Vec::new(); scene.surfaces.len() * SIDES.len()];
    for (i, p) in patches.iter().enumerate().filter(|(i, p)| p.twin == NO_TWIN || p.twin as usize > *i) {
        buckets[p.surface as usize * SIDES.len() + side(p.normal.y)].push(i);
    }
    for (b, front) in buckets.iter().enumerate().filter(|(_, f)| !f.is_empty()) {
        let area: f64 = front.iter().map(|&i| patches[i].area).sum();
        let mean = front.iter().map(|&i| patches[i].area * e[i]).sum::<f64>() / area;
        let min = front.iter().map(|&i| e[i]).fold(f64::INFINITY, f64::min);
        let max = front.iter().map(|&i| e[i]).fold(f64::NEG_INFINITY, f64::max);
        let material = &scene.materials[patches[front[0]].material as usize];
        rows.push(vec![
            escape(&scene.surfaces[b / SIDES.len()].name),
            escape(&material.name),
            SIDES[b % SIDES.len()].to_string(),
            number(area, 2),
            number(mean, 1),
            number(min, 1),
            number(max, 1),
        ]);
    }
    let head =
        ["surface", "material", "faces", "area (m²)", "E_avg (lx)", "E_min (lx)", "E_max (lx)"].map(str::to_string);
    let note = super::html::paragraph(
        "Mean illuminance on each surface's front side: the patches' illuminance weighted by their area \
         (E_min and E_max: the least and largest patch).",
    );
    Ok(section("surfaces", "Surfaces: wall, ceiling and floor illuminance", &(note + &table("surfaces", &head, &rows))))
}
