//! Light scenes by superposition (`study::solve_light_scenes`): a light scene equals a
//! separate full solve of the case with its luminaires and emitting surfaces dimmed, to
//! 1e-10 on the field, the patch illuminance and the probes, and on the grids to what the
//! shared cut along shadow edges changes ([`CUT`]: the groups' readings are shared); with the
//! hierarchical kernel, on the hierarchy refined under the case's own light, it equals the
//! solve on that fixed hierarchy of the source term of the dimmed sources integrated at
//! once.

use std::path::Path;
use ugo::io::LightSceneField;
use ugo::io::Solution;
use ugo::kernel::Factored;
use ugo::luminaire::direct_light;
use ugo::model::{Model, SourceTerm};
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::grid::{read_grids, read_grids_cut_by};
use ugo::readout::grid_error::GridErrorBars;
use ugo::readout::illuminance::{arriving, patch_illuminance};
use ugo::readout::probe::read_probes;
use ugo::readout::readings::{Readings, read_field, read_unbarred};
use ugo::readout::residual_samples::ResidualSamples;
use ugo::scene::Scene;
use ugo::solve::{Method, SolveParams, System, solve};
use ugo::study::{GroupSolves, Job, dimmed, solve_case, solve_light_scenes};

/// A grey room with a ceiling panel (group "panel"), a bulb (group "left") and a
/// Lambertian downlight (no group: "default"), a probe and a grid; maintenance factor 0.8.
/// `{A}`, `{B}` and `{PANEL}` are the bulb's and the downlight's multiplier and the panel's
/// flux, `{DISCRETIZATION}` the discretization's keys ([`UNIFORM`] or [`HIERARCHICAL`]).
const ROOM: &str = r#"
[discretization]
{DISCRETIZATION}

[solver]
method = "gmres"
tolerance = 1e-13

[lighting]
maintenance_factor = 0.8

[[material]]
name = "grey"
type = "lambert"
reflectance = 0.6

[[surface]]
name = "room"
shape = "box"
material = "grey"
inside = true
min = [0, 0, 0]
max = [3, 2.5, 4]

[[surface]]
name = "block"
shape = "box"
material = "grey"
min = [1.2, 0, 1.5]
max = [1.8, 0.9, 2.2]

[[surface]]
name = "panel"
shape = "rectangle"
material = "grey"
origin = [0.5, 2.49, 0.5]
edge_u = [0, 0, 0.5]
edge_v = [0.5, 0, 0]
emission = { flux = {PANEL} }
group = "panel"

[[luminaire]]
name = "bulb"
type = "isotropic"
flux = 1000
position = [1, 2, 1]
multiplier = {A}
group = "left"

[[luminaire]]
name = "downlight"
type = "lambertian"
intensity = 300
position = [2, 2.4, 3]
multiplier = {B}

[[probe]]
name = "floor"
position = [0.7, 0, 2.6]
normal = [0, 1, 0]

[[probe]]
name = "wall"
position = [0, 1.2, 2]
normal = [1, 0, 0]

[[grid]]
name = "work plane"
origin = [0.1, 0.8, 0.1]
edge_u = [2.8, 0, 0]
edge_v = [0, 0, 3.8]
resolution = [5, 7]

[[light_scene]]
name = "dimmed"
groups = { left = 0.3, default = 0.6, panel = 0.5 }

[[light_scene]]
name = "bulb-only"
groups = { left = true, panel = false }
"#;

const UNIFORM: &str = "patch_size = 0.5\nkernel = \"uniform\"";
const HIERARCHICAL: &str = "patch_size = 0.25\nkernel = \"hierarchical\"\nlink_tolerance = 0.05\nroot_size = 0.5";

/// The room with the bulb, the downlight and the panel at these outputs.
fn room(discretization: &str, a: f64, b: f64, panel: f64) -> Scene {
    let text = ROOM
        .replace("{DISCRETIZATION}", discretization)
        .replace("{A}", &a.to_string())
        .replace("{B}", &b.to_string())
        .replace("{PANEL}", &panel.to_string());
    Scene::parse(Path::new("room.toml"), text).expect("the room is valid")
}

fn job() -> Job {
    let params = SolveParams { tolerance: 1e-13, ..SolveParams::default() };
    Job { methods: vec![Method::Gmres { restart: 30 }], params, ..Job::default() }
}

fn solved(scene: &Scene) -> Solution {
    solve_case(scene, &job(), &ugo::progress::Silent).expect("the room solves")
}

/// `max |a − b| / max |b|`.
fn relative(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale
}

/// A light scene's grid points are `Σ_g f_g` of its groups' readings, each gather cut along
/// shadow edges as any group's field asks (`readout::cut`), more finely than the light
/// scene's own field alone asks: a piece the own rule leaves uncut errs by at most
/// `SHADOW_CUT` (1e-4) of all the point's light, so a reading of the dimmed sources'
/// field alone differs by that per such piece (measured 2.6e-4 on the uniform kernel,
/// 8.0e-4 on the hierarchy, of the largest point).
const CUT: f64 = 2e-3;

/// What a light scene and its reference are compared on: field, patch illuminance,
/// probes (luminance, illuminance, direct) and grid points.
struct Readouts {
    field: Vec<f64>,
    illuminance: Vec<f64>,
    probes: Vec<f64>,
    grid: Vec<f64>,
}

impl Readouts {
    fn of(s: &LightSceneField) -> Readouts {
        Readouts {
            field: s.field.luminance.iter().copied().collect(),
            illuminance: s.illuminance.clone(),
            probes: s.probes.iter().flat_map(|p| [p.luminance, p.illuminance, p.direct]).collect(),
            grid: s.grids[0].illuminance.clone(),
        }
    }

    /// To 1e-10, the grid to `grid` (a light scene's against a field read alone: [`CUT`]).
    fn assert_equal(&self, reference: &Readouts, what: &str, grid: f64) {
        let checks = [
            ("field", relative(&self.field, &reference.field), 1e-10),
            ("illuminance", relative(&self.illuminance, &reference.illuminance), 1e-10),
            ("grid", relative(&self.grid, &reference.grid), grid),
        ];
        for (name, error, tolerance) in checks {
            assert!(error < tolerance, "{what}: {name} differs by {error:e}");
        }
        for (a, b) in self.probes.iter().zip(&reference.probes) {
            assert!((a - b).abs() <= 1e-10 * b.abs().max(1e-300), "{what}: probe reading {a} against {b}");
        }
        assert!(reference.probes.iter().all(|&p| p > 0.0), "{what}: the probes see light");
    }
}

#[test]
fn a_light_scene_equals_a_full_solve_with_its_sources_dimmed() {
    let scene = room(UNIFORM, 1.0, 1.0, 500.0);
    let mut s = solved(&scene);
    let how = GroupSolves { method: Method::Gmres { restart: 30 }, params: job().params, warm: true };
    let light = solve_light_scenes(&scene, &mut s.model, &s.x, &how, &ugo::progress::Silent).unwrap();
    // `solve_case` returns the case with its light scenes solved the same way
    let own = s.light_scenes.as_ref().expect("solve_case solves the light scenes");
    Readouts::of(&own.scenes[0]).assert_equal(&Readouts::of(&light.scenes[0]), "solve_case's own", 1e-10);
    let names: Vec<&str> = light.groups.iter().map(|g| g.name.as_str()).collect();
    assert_eq!(names, ["panel", "left", "default"]);
    assert!(light.groups[2].solve.start < 1e-8, "the last group is the case's field less the others");
    // The model is given back lit by the case's own sources.
    assert_eq!(s.model.l0, solved(&scene).model.l0);

    let dimmed = solved(&room(UNIFORM, 0.3, 0.6, 250.0));
    let reference = Readouts {
        field: dimmed.x.clone(),
        illuminance: dimmed.illuminance.clone(),
        probes: dimmed.probes.iter().flat_map(|p| [p.luminance, p.illuminance, p.direct]).collect(),
        grid: dimmed.grids[0].illuminance.clone(),
    };
    Readouts::of(&light.scenes[0]).assert_equal(&reference, "dimmed", CUT);
    let e = (&light.scenes[0].energy, &dimmed.energy);
    assert!((e.0.emitted - e.1.emitted).abs() < 1e-10 * e.1.emitted && (e.0.absorbed - e.1.absorbed).abs() < 1e-9);

    // Off is a source left out: the downlight removed (with the light scenes that name its
    // group), the panel dark.
    let text = ROOM.replace("{DISCRETIZATION}", UNIFORM).replace("{A}", "1").replace("{PANEL}", "0");
    let (cut, probes, scenes) = (
        text.find("[[luminaire]]\nname = \"downlight\"").unwrap(),
        text.find("[[probe]]").unwrap(),
        text.find("[[light_scene]]").unwrap(),
    );
    let only = Scene::parse(Path::new("room.toml"), format!("{}{}", &text[..cut], &text[probes..scenes])).unwrap();
    let alone = solved(&only);
    let reference = Readouts {
        field: alone.x.clone(),
        illuminance: alone.illuminance.clone(),
        probes: alone.probes.iter().flat_map(|p| [p.luminance, p.illuminance, p.direct]).collect(),
        grid: alone.grids[0].illuminance.clone(),
    };
    Readouts::of(&light.scenes[1]).assert_equal(&reference, "bulb-only", CUT);
}

#[test]
fn on_a_fixed_hierarchy_a_light_scene_equals_the_solve_of_its_dimmed_sources() {
    let scene = room(HIERARCHICAL, 1.0, 1.0, 500.0);
    let mut s = solved(&scene);
    assert!(s.model.hierarchy.is_some());
    let how = GroupSolves { method: Method::Bicgstab, params: job().params, warm: true };
    let light = solve_light_scenes(&scene, &mut s.model, &s.x, &how, &ugo::progress::Silent).unwrap();
    for (light_scene, factors) in scene.lighting.scenes.iter().zip([[0.5, 0.3, 0.6], [0.0, 1.0, 0.0]]) {
        let model = &mut s.model;
        let sources = dimmed(&scene, &model.sources, light_scene);
        let direct = direct_light(
            &sources,
            &model.mesh,
            &model.visibility,
            &model.kernel.directions,
            &model.direct.least,
            &model.mirrors,
        );
        let emission = model.mesh.patches.iter().zip(&model.mesh.emission);
        let emission: Vec<f64> = emission.map(|(p, &e)| if p.surface == 2 { factors[0] * e } else { e }).collect();
        let own =
            (std::mem::replace(&mut model.sources, sources), std::mem::replace(&mut model.mesh.emission, emission));
        let own_direct = std::mem::replace(&mut model.direct, direct);
        let l0 = model.source_term();
        let factored = Factored::new(&model.kernel);
        let system = System { operator: &factored, explicit: None, areas: &[], l0: &l0 };
        let (x, _) = solve(Method::Gmres { restart: 30 }, &system, &job().params, &mut |_, _| {}).unwrap();
        let k = model.kernel.cells();
        let field = Field::from_unknowns(&x, k);
        let reference = Readouts {
            illuminance: patch_illuminance(&arriving(model, &x), k),
            probes: read_probes(&scene.probes, model, &field, &Silent)
                .iter()
                .flat_map(|p| [p.luminance, p.illuminance, p.direct])
                .collect(),
            grid: read_grids(&scene.grids, model, &field, &Silent)[0].illuminance.clone(),
            field: x,
        };
        let index = scene.lighting.scenes.iter().position(|l| l.name == light_scene.name).unwrap();
        Readouts::of(&light.scenes[index]).assert_equal(&reference, &light_scene.name, CUT);
        (model.sources, model.mesh.emission) = own;
        model.direct = own_direct;
    }
}

/// The model a light scene is solved on is the case's: its groups change no patch.
#[test]
fn the_groups_of_a_hierarchical_case_are_solved_on_its_one_hierarchy() {
    let scene = room(HIERARCHICAL, 1.0, 1.0, 500.0);
    let model = Model::build(&scene, &ugo::progress::Silent).unwrap();
    let g = &scene.lighting.groups;
    let terms: Vec<_> = g.iter().map(|g| model.source_term_of(&g.luminaires, &g.surfaces)).collect();
    assert!(terms.iter().all(|t| t.l0.len() == model.l0.len() && t.emission.len() == model.mesh.len()));
    let sum: Vec<f64> = (0..model.l0.len()).map(|i| terms.iter().map(|t| t.l0[i]).sum()).collect();
    // The groups' light is integrated on the leaves with each shadow edge cut as far as the
    // refinement cut the case's own (`DirectLight::least`), each source's pieces on their
    // own: the groups add up to the case's light to round-off, measured 7e-18 (with every
    // edge cut six levels deep instead, as before, 6.8e-4 on the 1,010 wholly exposed
    // leaves and 2.3e-3 over all 1,020).
    let k = model.kernel.cells();
    let exposed = |i: &usize| model.mesh.patches[i / k].exposed == model.mesh.patches[i / k].area;
    let whole: Vec<usize> = (0..model.l0.len()).filter(exposed).collect();
    let pick = |v: &[f64]| whole.iter().map(|&i| v[i]).collect::<Vec<f64>>();
    let (all, exposed) = (relative(&sum, &model.l0), relative(&pick(&sum), &pick(&model.l0)));
    assert!(exposed < 1e-12 && all < 1e-12, "wholly exposed leaves {exposed}, all {all}");
}

#[test]
fn the_light_without_one_group_is_the_other_groups_light() {
    // `Model::source_term_without` (the daylight alone of a case with luminaires is its own
    // light less theirs, docs/daylight.md): the case's light less the first group's equals
    // the other groups' integrated afresh, to round-off.
    let scene = room(HIERARCHICAL, 1.0, 1.0, 500.0);
    let model = Model::build(&scene, &Silent).unwrap();
    let (first, rest) = scene.lighting.groups.split_first().expect("groups");
    let luminaires: Vec<usize> = rest.iter().flat_map(|g| g.luminaires.iter().copied()).collect();
    let surfaces: Vec<usize> = rest.iter().flat_map(|g| g.surfaces.iter().copied()).collect();
    let without = model.source_term_without(&first.luminaires, &first.surfaces);
    let others = model.source_term_of(&luminaires, &surfaces);
    assert!(others.l0.iter().any(|&v| v > 0.0) && first.luminaires.len() + first.surfaces.len() > 0);
    let apart = relative(&without.l0, &others.l0);
    assert!(apart < 1e-12, "L0 {apart:e}");
    assert!(relative(&without.direct.intercepted, &others.direct.intercepted) < 1e-12);
    let emitted = without.emission.iter().zip(&others.emission).all(|(a, b)| (a - b).abs() <= 1e-12 * b.abs().max(1.0));
    assert!(emitted, "the surfaces' emission differs");
}

/// With light scenes the case's own error bars are its groups' residual samples summed at
/// factor 1 (`study::solve`), not gathered again: equal, to the solves' tolerance, to those
/// of the case's own field gathered with the groups' cut.
#[test]
fn the_cases_own_error_bars_are_its_groups_summed() {
    let scene = room(UNIFORM, 1.0, 1.0, 500.0);
    let s = solved(&scene);
    let light = s.light_scenes.as_ref().expect("the light scenes");
    let k = s.model.kernel.cells();
    let fields: Vec<Field> = light.groups.iter().map(|g| Field::from_unknowns(&g.solve.x, k)).collect();
    let by: Vec<&Field> = fields.iter().collect();
    let mut alone = read_unbarred(&scene, &s.model, &s.field, &Silent);
    alone.set_bars(&ResidualSamples::of(&alone.probes, &alone.grids, &s.model, &s.field, &by, &Silent));
    let ours: Vec<f64> = s.probes.iter().map(|p| p.error.expect("a bar")).collect();
    let theirs: Vec<f64> = alone.probes.iter().map(|p| p.error.expect("a bar")).collect();
    let grid = |e: &[GridErrorBars]| e[0].points.iter().copied().filter(|b| !b.is_nan()).collect::<Vec<f64>>();
    let d = [relative(&ours, &theirs), relative(&grid(&s.grid_errors), &grid(&alone.grid_errors))];
    assert!(d[0] <= 1e-9 && d[1] <= 1e-9, "probes', grid's bars differ by {d:?} of the largest");
    assert!(ours.iter().all(|b| *b > 0.0), "every probe has a bar: {ours:?}");
}

/// A light scene's grid readings and error bars, `Σ_g f_g` of its groups' readings and
/// residual samples (read once for all the light scenes: `readout::group_readouts`), the
/// bar's formula applied to its own, equal those read from its own field alone on the
/// model relit by its dimmed sources, its gathers cut along shadow edges by the groups'
/// rules (`readout::cut`), to 1e-12 of the largest. Cut by its own rule alone they differ by
/// what each cut leaves: a grid point by a few 1e-4 here ([`CUT`]), a bar by a few per cent.
#[test]
fn a_light_scenes_shared_grids_and_error_bars_equal_those_of_its_field_alone() {
    let scene = room(UNIFORM, 1.0, 1.0, 500.0);
    let mut s = solved(&scene);
    let how = GroupSolves { method: Method::Gmres { restart: 30 }, params: job().params, warm: true };
    let light = solve_light_scenes(&scene, &mut s.model, &s.x, &how, &Silent).unwrap();
    let shared = light.shared.as_ref().expect("the groups' readouts");
    assert_eq!((shared.grids.len(), shared.samples.len()), (3, 3), "one per group");
    let model = &mut s.model;
    let k = model.kernel.cells();
    let fields: Vec<Field> = light.groups.iter().map(|g| Field::from_unknowns(&g.solve.x, k)).collect();
    let by: Vec<&Field> = fields.iter().collect();
    let terms: Vec<SourceTerm> =
        scene.lighting.groups.iter().map(|g| model.source_term_of(&g.luminaires, &g.surfaces)).collect();
    let bars = |r: &Readings| {
        let points = r.grid_errors.iter().flat_map(|g| g.points.iter().chain([&g.average, &g.min, &g.u0]));
        let probes = r.probes.iter().map(|p| p.error.expect("a point sensor has a bar"));
        probes.chain(points.copied()).filter(|b| !b.is_nan()).collect::<Vec<f64>>()
    };
    for (light_scene, ours) in scene.lighting.scenes.iter().zip(&light.scenes) {
        let parts: Vec<(f64, &SourceTerm)> = light_scene.factors.iter().copied().zip(&terms).collect();
        let sources = dimmed(&scene, &model.sources, light_scene);
        let own = model.relight(sources, SourceTerm::superpose(&parts));
        let mut alone = read_unbarred(&scene, model, &ours.field, &Silent);
        alone.grids = read_grids_cut_by(&scene.grids, model, &ours.field, &by, &Silent);
        alone.set_bars(&ResidualSamples::of(&alone.probes, &alone.grids, model, &ours.field, &by, &Silent));
        let by_itself = read_field(&scene, model, &ours.field, &Silent);
        model.relight(own.0, own.1);
        let ours = Readings {
            probes: ours.probes.clone(),
            grids: ours.grids.clone(),
            grid_errors: ours.grid_errors.clone(),
            observers: Vec::new(),
            glare_grids: Vec::new(),
        };
        let name = &light_scene.name;
        let grid = |r: &Readings| r.grids[0].illuminance.clone();
        let d = [relative(&grid(&ours), &grid(&alone)), relative(&bars(&ours), &bars(&alone))];
        assert!(d[0] <= 1e-12 && d[1] <= 1e-12, "{name}: grid, bars differ by {d:?} of the largest");
        // cut by its own rule: the grid within [`CUT`]; the bars measured 2.9e-2 ("dimmed")
        // and 6.8e-3 ("bulb-only") of the largest: a bar is a small difference of gathers, and
        // a piece left uncut errs by up to `RELIT_SHADOW_CUT` (1e-3) of one
        let d = [relative(&grid(&ours), &grid(&by_itself)), relative(&bars(&ours), &bars(&by_itself))];
        assert!(d[0] <= CUT && d[1] <= 0.05, "{name}: grid, bars against its own cut {d:?}");
    }
}
