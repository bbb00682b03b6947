//! The hierarchical kernel through `Model::build` (`[discretization] kernel =
//! "hierarchical"`): the white furnace and the energy balance on the leaves, its explicit
//! expansion against its matrix-free application, `direct` on the expansion against GMRES,
//! and CIE 171 5.8 (a point luminaire in a closed cube) against its closed form.

use super::{box_with_block, relative_difference};
use crate::support::{furnace, furnace_with_standing_block};
use std::f64::consts::PI;
use std::path::Path;
use ugo::kernel::{Explicit, Factored};
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::energy::EnergyBalance;
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::solve::{LinOp, Method, SolveParams, System, solve};

/// `scene` with roots at its patch size and leaves down to `patch_size`.
fn hierarchical(mut scene: Scene, link_tolerance: f64, patch_size: f64) -> (Scene, Model) {
    let root_size = scene.discretization.patch_size;
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size,
        link_tolerance,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    scene.discretization.patch_size = patch_size;
    let model = Model::build(&scene, &Silent).expect("fits in memory");
    (scene, model)
}

fn solved(model: &Model, method: Method) -> Vec<f64> {
    let limit = 1 << 30;
    let explicit = method.needs_explicit().then(|| Explicit(model.kernel.explicit(limit).expect("fits")));
    let factored = Factored::new(&model.kernel);
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let system = System::of(&model.kernel, &factored, explicit.as_ref(), &areas, &model.l0);
    let params =
        SolveParams { tolerance: 1e-11, max_iterations: 10_000, memory_limit: limit, ..SolveParams::default() };
    solve(method, &system, &params, &mut |_, _| {}).expect("converges").0
}

#[test]
fn the_white_furnace_holds_on_every_leaf_and_the_energy_closes() {
    let (scene, model) = hierarchical(furnace(1.0, 0.8, 1.0, 1.0), 1e-2, 0.1);
    let x = solved(&model, Method::Gmres { restart: 30 });
    let worst = x.iter().map(|l| (l / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    let energy = EnergyBalance::of(&model, &x, scene.surfaces.len());
    let record = model.hierarchy.as_ref().expect("a hierarchical model");
    eprintln!(
        "model furnace: {} roots → {} leaves, worst |L/5 − 1| = {worst:.2e}, absorbed/emitted − 1 = {:.2e}",
        record.roots,
        model.mesh.len(),
        energy.absorbed / energy.emitted - 1.0
    );
    assert!(model.mesh.len() > record.roots, "the hierarchy refined nothing");
    assert!(worst < 1e-3, "worst relative error {worst}");
    // a leaf's sending factor is held within 1 ± 3 tolerances (balance.rs): the columns its
    // links cannot carry stay short, and the energy closes to 2.2e-4 here (within 1e-4 free)
    assert!((energy.absorbed / energy.emitted - 1.0).abs() < 5e-4, "{energy:?}");
}

#[test]
fn the_expansion_is_the_operator_and_direct_agrees_with_gmres() {
    let (_, model) = hierarchical(box_with_block(0.6), 3e-2, 0.1);
    let expanded = Explicit(model.kernel.explicit(1 << 30).expect("fits"));
    let factored = Factored::new(&model.kernel);
    let x: Vec<f64> = (0..factored.dim()).map(|i| 1.0 + 0.5 * (i as f64 * 0.37).sin()).collect();
    let (mut a, mut b) = (vec![0.0; x.len()], vec![0.0; x.len()]);
    LinOp::apply(&expanded, &x, &mut a);
    LinOp::apply(&factored, &x, &mut b);
    let difference = relative_difference(&a, &b);
    eprintln!(
        "expansion: {} unknowns, {} non-zeros, max |Δ(Kx)|/max|Kx| = {difference:.1e}",
        x.len(),
        expanded.0.nnz()
    );
    assert!(difference < 1e-12, "expansion differs by {difference}");
    let (direct, gmres) = (solved(&model, Method::Direct), solved(&model, Method::Gmres { restart: 30 }));
    let difference = relative_difference(&direct, &gmres);
    assert!(difference < 1e-8, "direct and GMRES differ by {difference}");
}

#[test]
fn cie_5_8_a_point_source_in_a_closed_cube_through_the_hierarchy() {
    let scene = Scene::load(Path::new("cases/cie171/5.8-interreflection.toml")).unwrap_or_else(|e| panic!("{e}"));
    let (scene, model) = hierarchical(scene, 3e-3, 0.125);
    let x = solved(&model, Method::Gmres { restart: 30 });
    let energy = EnergyBalance::of(&model, &x, scene.surfaces.len());
    let area: f64 = model.mesh.patches.iter().map(|p| p.area).sum();
    let mut gx = vec![0.0; x.len()];
    model.kernel.apply_transport(&x, &mut gx);
    let indirect = model.mesh.patches.iter().zip(&gx).map(|(p, g)| p.area * PI * g).sum::<f64>() / area;
    let exact = 0.95 * 10_000.0 / (96.0 * 0.05);
    let record = model.hierarchy.as_ref().expect("a hierarchical model");
    let splits: usize = record.history.iter().map(|p| p.source_splits).sum();
    eprintln!(
        "5.8 hierarchical: {} roots → {} leaves ({splits} split along the luminaire's light), E_ind {indirect:.2} lx, exact {exact:.2} lx, absorbed/emitted − 1 = {:.2e}",
        record.roots,
        model.mesh.len(),
        energy.absorbed / energy.emitted - 1.0
    );
    assert!(splits > 0, "the luminaire's fall-off over the walls split nothing");
    // cluster links do not conserve energy exactly; ρ = 0.95 amplifies their error 20×
    assert!((energy.absorbed / energy.emitted - 1.0).abs() < 1e-2, "{energy:?}");
    assert!((indirect / exact - 1.0).abs() < 1e-2, "E_ind {indirect} against {exact}");
}

/// A block standing on the floor off the roots' grid, rotated: leaves straddle its
/// contacts, and at the loose tolerance 1e-2 the links alone lose light where a few rays
/// decide a cluster pair's visibility. Balanced to the leaves' closures (1 here: the room
/// is closed), `K·1 = ρ` on every exposed leaf and the furnace holds; `K·1 ≤ ρ` anywhere,
/// or `K`'s spectral radius could pass 1.
#[test]
fn balanced_around_an_off_grid_contact_the_furnace_closes_on_every_exposed_leaf() {
    let (scene, model) = hierarchical(furnace_with_standing_block(0.5), 1e-2, 0.125);
    let record = model.hierarchy.as_ref().expect("a hierarchical model");
    let balance = record.history.iter().rev().find_map(|p| p.balance).expect("balanced");
    let factored = Factored::new(&model.kernel);
    let ones = vec![1.0; factored.dim()];
    let mut k1 = vec![0.0; ones.len()];
    LinOp::apply(&factored, &ones, &mut k1);
    // leaves wholly outside the block (a leaf across its edge keeps the contact error)
    let exposed = |i: &usize| model.mesh.patches[*i].exposed == model.mesh.patches[*i].area;
    let worst_row = (0..model.mesh.len()).filter(exposed).map(|i| (k1[i] / 0.8 - 1.0).abs()).fold(0.0, f64::max);
    let largest = k1.iter().fold(0.0f64, |m, v| m.max(*v)) / 0.8;
    let x = solved(&model, Method::Gmres { restart: 30 });
    let worst = (0..model.mesh.len()).filter(exposed).map(|i| (x[i] / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    let energy = EnergyBalance::of(&model, &x, scene.surfaces.len());
    let partly = model.mesh.patches.iter().filter(|p| p.exposed > 0.0 && p.exposed < p.area).count();
    eprintln!(
        "balanced contact: {} leaves ({partly} straddling), {balance:?}; worst |K·1/ρ − 1| {worst_row:.2e}, \
         largest K·1/ρ {largest:.6}, furnace worst {worst:.2e}, absorbed/emitted − 1 = {:.2e}",
        model.mesh.len(),
        energy.absorbed / energy.emitted - 1.0
    );
    assert!(partly > 0, "no leaf straddles the block's contacts");
    assert!(worst_row < 1e-3 && largest < 1.0 + 1e-3, "rows: worst {worst_row}, largest {largest}");
    assert!(worst < 3e-3, "furnace worst {worst}");
    // sending factors held within 1 ± 3 tolerances (balance.rs): −3.0e-4 here
    assert!((energy.absorbed / energy.emitted - 1.0).abs() < 5e-4, "{energy:?}");
}
