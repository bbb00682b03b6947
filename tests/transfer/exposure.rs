//! Exposed area (`transfer::exposure`): a block standing on the floor of a closed room
//! hides the floor under it. Every patch's exposed area against its foot print; then the
//! white furnace (every surface `ρ = 0.8`, emitting 1 cd/m²: `L = 5` on every exposed
//! patch, and absorbed = emitted) with the block standing on the floor, through the
//! uniform and the hierarchical kernels, with the hidden patches (under the block, behind
//! it on the walls, the block's own bottom and back) left out.

use crate::support::{build, furnace, lambert, solve, surface};
use glam::DVec3;
use ugo::geometry::{Emission, Mesh, Shape};
use ugo::model::Model;
use ugo::readout::energy::EnergyBalance;
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::transfer::exposure::measure_exposure;
use ugo::visibility::Visibility;

/// The 1 m furnace cube (`ρ = 0.8`, emitting 1 cd/m², `patch` m patches) with a block
/// `lo`–`hi` of the same material, emitting too.
fn with_block(lo: [f64; 3], hi: [f64; 3], patch: f64) -> Scene {
    let mut s = furnace(1.0, 0.8, 1.0, patch);
    s.materials.push(lambert("block", 0.8));
    let block = Shape::Box { min: DVec3::from(lo), max: DVec3::from(hi), rotate_y_deg: 0.0 };
    s.surfaces.push(surface("block", block, 1, false, Some(Emission::Luminance(1.0))));
    s
}

/// Exposed share of every floor patch (`y = 0`, facing up) by its centre `(x, z)`.
fn floor_shares(scene: &Scene, patch: f64) -> Vec<(f64, f64, f64)> {
    let mut mesh = Mesh::build(&scene.surfaces, patch);
    let visibility = Visibility::build(&mesh);
    measure_exposure(&mut mesh, &visibility, &ugo::progress::Silent);
    let floor = mesh.patches.iter().filter(|p| p.surface == 0 && p.normal.y > 0.5 && p.centroid.y.abs() < 1e-9);
    floor.map(|p| (p.centroid.x, p.centroid.z, p.exposed / p.area)).collect()
}

#[test]
fn a_block_standing_on_the_floor_hides_its_foot_print() {
    // the foot print covers patches [0, 0.5] × [0, 0.25] and half of [0, 0.5] × [0.25, 0.5]
    let scene = with_block([0.0, 0.0, 0.0], [0.5, 0.3, 0.375], 0.25);
    let shares = floor_shares(&scene, 0.25);
    assert_eq!(shares.len(), 16);
    for (x, z, share) in shares {
        let expected = match (x < 0.5, z) {
            (true, z) if z < 0.25 => 0.0,
            (true, z) if z < 0.5 => 0.5,
            _ => 1.0,
        };
        assert_eq!(share, expected, "floor patch at ({x}, {z})");
    }
}

#[test]
fn a_raised_block_or_a_two_sided_panel_hides_nothing() {
    let raised = with_block([0.0, 0.1, 0.0], [0.5, 0.3, 0.5], 0.25);
    assert!(floor_shares(&raised, 0.25).iter().all(|s| s.2 == 1.0), "a block 0.1 m above the floor");
    let mut panel = furnace(1.0, 0.8, 1.0, 0.25);
    let shape = Shape::Rectangle { origin: DVec3::new(0.0, 0.3, 0.0), edge_u: DVec3::Z * 0.5, edge_v: DVec3::X * 0.5 };
    panel.surfaces.push(ugo::geometry::Surface { two_sided: true, ..surface("panel", shape, 0, false, None) });
    assert!(floor_shares(&panel, 0.25).iter().all(|s| s.2 == 1.0), "a two-sided panel 0.3 m above the floor");
}

/// The furnace's worst relative error over the patches with exposed area, and its energy
/// balance's `|absorbed − emitted| / emitted`.
fn furnace_errors(scene: &Scene, model: &Model, x: &[f64]) -> (f64, f64) {
    let exposed = |i: &usize| model.mesh.patches[*i].exposed > 0.0;
    let worst = (0..model.mesh.len()).filter(exposed).map(|i| (x[i] / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    let energy = EnergyBalance::of(model, x, scene.surfaces.len());
    (worst, (energy.absorbed / energy.emitted - 1.0).abs())
}

/// The furnace's errors with the block standing against two walls (`lo = 0`) or floating
/// `lo` m above the floor, through the uniform kernel (`patch` m patches) or the
/// hierarchical one (roots `patch`, leaves down to 0.125 m). The block's edges are on the
/// patches' grid, so every patch is exposed or hidden (a patch that straddles a contact
/// line is `docs/design.md` §3's "Contacts" error).
fn furnace_with_block(lo: f64, link_tolerance: Option<f64>, patch: f64) -> (f64, f64) {
    let mut scene = with_block([0.0, lo, 0.0], [0.5, 0.25 + lo, 0.375], patch);
    if let Some(link_tolerance) = link_tolerance {
        scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
            root_size: patch,
            link_tolerance,
            passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
        });
        scene.discretization.patch_size = 0.125;
    }
    let model = build(&scene);
    let errors = furnace_errors(&scene, &model, &solve(&model));
    eprintln!(
        "{} patches, block at {lo} m: worst {:.2e}, absorbed against emitted {:.2e}",
        model.mesh.len(),
        errors.0,
        errors.1
    );
    errors
}

/// The white furnace's bound, relative.
const FURNACE: f64 = 1e-3;

/// Standing on the floor, the block's contacts cost nothing: the furnace holds as well as
/// with the block floating (where the occlusion's sampling sets the error), in either
/// kernel. Without the exposed areas, the furnace's closure fails where patches are
/// hidden: the uniform kernel's worst error against 5 is measured in `docs/hierarchy.md`.
#[test]
fn the_white_furnace_holds_around_a_block_standing_on_the_floor() {
    for (link_tolerance, patch) in [(None, 0.125), (Some(1e-3), 0.5)] {
        let (standing, floating) =
            (furnace_with_block(0.0, link_tolerance, patch), furnace_with_block(0.125, link_tolerance, patch));
        // below the white furnace's 1e-3 both are the hierarchy's own floor: its sending
        // factors are held within 1 ± 3 tolerances (docs/hierarchy.md, "Sending factors held
        // to the links' error"), 2.98e-4 standing against 2.91e-4 floating
        let (worst, balance) = (floating.0.max(FURNACE), floating.1.max(FURNACE));
        assert!(standing.0 <= worst && standing.0 < 1e-2, "worst error {standing:?} against {floating:?}");
        assert!(standing.1 <= balance && standing.1 < 3e-3, "balance {standing:?} against {floating:?}");
    }
}

/// Patches half under the block (off the grid of 0.25 m patches) read the furnace's 5 to
/// within the error of straddling the block's side (`docs/design.md` §3, "Contacts"); spread
/// over their whole area they would read about `1 + 0.8 · 5/2 = 3`.
#[test]
fn patches_half_under_a_block_read_the_furnace_within_the_contact_error() {
    let scene = with_block([0.0, 0.0, 0.0], [0.5, 0.25, 0.375], 0.25);
    let model = build(&scene);
    let x = solve(&model);
    let half: Vec<(f64, f64)> = (0..model.mesh.len())
        .map(|i| (model.mesh.patches[i].exposed / model.mesh.patches[i].area, x[i]))
        .filter(|&(share, _)| share > 0.0 && share < 1.0)
        .collect();
    let worst = half.iter().map(|&(_, l)| (l / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    eprintln!("{} patches partly hidden: {half:?}, worst {worst:.3}", half.len());
    assert!(!half.is_empty() && worst < 0.1, "{half:?}");
}
