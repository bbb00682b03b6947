//! Light scenes by superposition (`docs/design.md` §1: `L = (I − K)⁻¹ L0` is linear in the
//! sources). Each group of sources (`[[luminaire]]` and `[[surface]]` `group` keys) is solved
//! alone against the case's one kernel, every solve started from the solutions already
//! known (`solve::Projection`, the case's own field first); every `[[light_scene]]` is then
//! `x_s = Σ_g f_{s,g} x_g`, read out (patch illuminance, energy, probes) by the model relit
//! with its dimmed sources, exactly as a solve of the case with those sources would be. Its
//! grid readings and the residual samples of its error bars ((5.5), (5.6)) are `Σ_g f_{s,g}`
//! of the groups', each group's read once for every light scene with the groups' cut along
//! shadow edges (`readout::group_readouts`, `readout::cut`), and the bar's formula is
//! applied to its own samples. For the hierarchical kernel the hierarchy is the one refined
//! under the case's own light (every group on at factor 1); each group is solved on it as
//! it stands.

use super::error::StudyError;
use crate::io::{GroupField, IoError, LightSceneField, LightScenes, StoredSolution};
use crate::kernel::{Explicit, Factored};
use crate::luminaire::Source;
use crate::model::{Model, SourceTerm};
use crate::progress::Progress;
use crate::readout::energy::EnergyBalance;
use crate::readout::field::Field;
use crate::readout::glare_grid::read_glare_grids;
use crate::readout::grid::{read_grids_cut_by, read_grids_each};
use crate::readout::group_readouts::GroupReadouts;
use crate::readout::illuminance::{arriving, patch_illuminance};
use crate::readout::lit::Lit;
use crate::readout::probe::{ProbeReading, read_probes};
use crate::readout::residual_samples::ResidualSamples;
use crate::readout::ugr::read_observers;
use crate::render::LitScene;
use crate::scene::{LightScene, Scene};
use crate::solve::{Method, Projection, SolveParams, System};
use std::path::Path;

/// How the groups are solved.
#[derive(Debug, Clone, Copy)]
pub struct GroupSolves {
    /// The method of every group's solve.
    pub method: Method,
    /// Its stopping rule.
    pub params: SolveParams,
    /// Start each solve from the known solutions (else cold, to measure what that saves).
    pub warm: bool,
}

/// Solves every group of `scene` on `model` and reads out every light scene; `x` is the
/// solution of the case's own light (all groups on), the first known solution. `model` is
/// relit by each light scene in turn and given back as it came.
pub fn solve_light_scenes(
    scene: &Scene,
    model: &mut Model,
    x: &[f64],
    how: &GroupSolves,
    progress: &dyn Progress,
) -> Result<LightScenes, StudyError> {
    let terms = group_terms(scene, model, |_| true);
    let fields = solve_groups(scene, model, x, &terms, how, progress)?;
    let xs: Vec<&[f64]> = fields.iter().map(|g| g.solve.x.as_slice()).collect();
    let all: Vec<&LightScene> = scene.lighting.scenes.iter().collect();
    let (scenes, shared) = read_light_scenes(scene, model, &terms, &xs, &all, None, progress)?;
    Ok(LightScenes { groups: fields, scenes, shared })
}

/// Each group's source term alone on `model` (`Model::source_term_of`), in the order of
/// the scene's groups; a group `g` for which `wanted(g)` is false gets an empty term (no
/// light traced: a group off in every light scene read).
pub(super) fn group_terms(scene: &Scene, model: &Model, wanted: impl Fn(usize) -> bool) -> Vec<SourceTerm> {
    let groups = scene.lighting.groups.iter().enumerate();
    groups
        .map(|(i, g)| match wanted(i) {
            true => model.source_term_of(&g.luminaires, &g.surfaces),
            false => model.source_term_of(&[], &[]),
        })
        .collect()
}

/// The light scenes `light_scenes` of `scene` from the groups' source terms `terms` and
/// fields `xs` (one per group of the scene): `x_s = Σ_g f_{s,g} x_g` and its readouts,
/// `model` relit by each light scene in turn and given back as it came. Shared by the solve
/// (every light scene) and `ugo readout` (the new or changed ones). The grid readings and
/// error bars are those of `Σ_g f_{s,g}` of the groups' (`readout::group_readouts`):
/// `stored` when they were read at these probes and grids, else read here; they are
/// returned with the light scenes (`None` when there is none).
pub(super) fn read_light_scenes(
    scene: &Scene,
    model: &mut Model,
    terms: &[SourceTerm],
    xs: &[&[f64]],
    light_scenes: &[&LightScene],
    stored: Option<GroupReadouts>,
    progress: &dyn Progress,
) -> Result<(Vec<LightSceneField>, Option<GroupReadouts>), StudyError> {
    let base = model.sources.clone();
    let mut own = None;
    let mut scenes = Vec::with_capacity(light_scenes.len());
    for &light_scene in light_scenes {
        let parts: Vec<(f64, &SourceTerm)> = light_scene.factors.iter().copied().zip(terms).collect();
        let relit = model.relight(dimmed(scene, &base, light_scene), SourceTerm::superpose(&parts));
        own.get_or_insert(relit);
        scenes.push(read_out(scene, model, light_scene, xs, progress));
    }
    let shared = scenes.first().map(|at| match stored.filter(|s| s.fits(xs.len(), &at.probes)) {
        Some(stored) => stored,
        None => group_readouts(scene, model, &base, terms, xs, &at.probes, progress),
    });
    for s in scenes.iter_mut() {
        let Some(shared) = &shared else { break };
        let (grids, samples) = shared.of_light_scene(&s.factors);
        s.grid_errors = samples.bars(&mut s.probes, &grids);
        s.grids = grids;
    }
    if let Some((sources, term)) = own {
        model.relight(sources, term);
    }
    crate::interrupt::check(|| "the light scenes' readouts".to_string())?;
    Ok((scenes, shared))
}

/// Each group's grid readings and residual samples (at the probes `probes` read, and at
/// its grids), its field `xs[g]` read on `model` relit by the group alone (its luminaires
/// placed as in `base`, its source term `terms[g]`), every gather cut along shadow edges as
/// any group's field asks (`readout::cut`), so that `Σ_g f_g` of them is the reading of
/// `Σ_g f_g x_g` cut so. All the groups are read together, each under its own light
/// (`readout::lit`), where the model allows it, else group by group on `model` relit by
/// each, which is then left relit by the last group.
fn group_readouts(
    scene: &Scene,
    model: &mut Model,
    base: &[Source],
    terms: &[SourceTerm],
    xs: &[&[f64]],
    probes: &[ProbeReading],
    progress: &dyn Progress,
) -> GroupReadouts {
    let k = model.kernel.cells();
    let fields: Vec<Field> = xs.iter().map(|x| Field::from_unknowns(x, k)).collect();
    let by: Vec<&Field> = fields.iter().collect();
    let alone = |g: usize| LightScene {
        name: String::new(),
        factors: (0..terms.len()).map(|h| if h == g { 1.0 } else { 0.0 }).collect(),
    };
    let sources: Vec<Vec<Source>> = (0..terms.len()).map(|g| dimmed(scene, base, &alone(g))).collect();
    let apart: Option<Vec<Lit>> =
        fields.iter().zip(&sources).zip(terms).map(|((f, s), t)| Lit::apart(model, f, s, &t.emission)).collect();
    if let Some(lits) = apart.filter(|l| !l.is_empty()) {
        let grids = read_grids_each(&scene.grids, model, &lits, &by, progress);
        let samples = ResidualSamples::of_each(probes, &grids[0], model, &lits, &by, progress);
        return GroupReadouts { grids, samples };
    }
    let (grids, samples) = (0..terms.len())
        .map(|g| {
            model.relight(sources[g].clone(), terms[g].clone());
            let grids = read_grids_cut_by(&scene.grids, model, &fields[g], &by, progress);
            let samples = ResidualSamples::of(probes, &grids, model, &fields[g], &by, progress);
            (grids, samples)
        })
        .unzip();
    GroupReadouts { grids, samples }
}

/// The case's kernel as every group's solve takes it: factored, formed explicitly when the
/// method needs it, with the patches' exposed areas; made once for all the groups.
pub(super) struct Operators<'a> {
    model: &'a Model,
    factored: Factored<'a>,
    explicit: Option<Explicit>,
    areas: Vec<f64>,
}

impl<'a> Operators<'a> {
    /// The operators of `model` for the method of `how`.
    pub(super) fn new(model: &'a Model, how: &GroupSolves) -> Result<Self, StudyError> {
        let explicit = match how.method.needs_explicit() {
            true => Some(Explicit(model.kernel.explicit(how.params.memory_limit)?)),
            false => None,
        };
        let areas = model.mesh.patches.iter().map(|p| p.exposed).collect();
        Ok(Operators { model, factored: Factored::new(&model.kernel), explicit, areas })
    }

    /// The system `x = l0 + K x`.
    pub(super) fn system<'b>(&'b self, l0: &'b [f64]) -> System<'b> {
        System::of(&self.model.kernel, &self.factored, self.explicit.as_ref(), &self.areas, l0)
    }
}

/// Each group's field, solved in the order of the groups.
fn solve_groups(
    scene: &Scene,
    model: &Model,
    x: &[f64],
    terms: &[SourceTerm],
    how: &GroupSolves,
    progress: &dyn Progress,
) -> Result<Vec<GroupField>, StudyError> {
    let operators = Operators::new(model, how)?;
    let mut projection = Projection::new(how.warm);
    if how.warm {
        projection.learn(&operators.factored, x.to_vec());
    }
    let mut fields = Vec::with_capacity(terms.len());
    for (group, term) in scene.lighting.groups.iter().zip(terms) {
        let system = operators.system(&term.l0);
        let label = format!("group {}", group.name);
        progress.begin(&label, how.params.max_iterations as u64);
        let solved = projection.solve(how.method, &system, &how.params, &mut |n, r| {
            progress.at(n as u64, &format!("{label}: {} {r:.1e}", how.method.name()))
        });
        progress.end();
        let (emission, direct) = (term.emission.clone(), term.direct.clone());
        fields.push(GroupField { name: group.name.clone(), emission, direct, solve: solved? });
    }
    Ok(fields)
}

/// The luminaires of `scene` placed (`base`, one per luminaire) and dimmed by the factor
/// of their group in `light_scene`.
pub fn dimmed(scene: &Scene, base: &[Source], light_scene: &LightScene) -> Vec<Source> {
    let mut factor = vec![0.0; base.len()];
    for (group, &f) in scene.lighting.groups.iter().zip(&light_scene.factors) {
        group.luminaires.iter().for_each(|&i| factor.get_mut(i).into_iter().for_each(|x| *x = f));
    }
    base.iter().zip(factor).map(|(s, f)| s.scaled(f)).collect()
}

/// The light scene's field `Σ_g f_g x_g` (`xs` the groups' fields) and its readouts on
/// `model`, relit by it (the observers' and glare grids' UGR from its dimmed luminaires
/// and its own background), without its grids and error bars (`read_light_scenes` sets
/// them).
fn read_out(
    scene: &Scene,
    model: &Model,
    light_scene: &LightScene,
    xs: &[&[f64]],
    progress: &dyn Progress,
) -> LightSceneField {
    let mut x = vec![0.0; model.l0.len()];
    for (&f, group) in light_scene.factors.iter().zip(xs) {
        x.iter_mut().zip(group.iter()).for_each(|(x, g)| *x += f * g);
    }
    let k = model.kernel.cells();
    let field = Field::from_unknowns(&x, k);
    let probes = read_probes(&scene.probes, model, &field, progress);
    let observers = read_observers(&scene.observers, model, &field);
    let glare_grids = read_glare_grids(&scene.glare_grids, model, &field);
    LightSceneField {
        name: light_scene.name.clone(),
        factors: light_scene.factors.clone(),
        emission: model.mesh.emission.clone(),
        source: model.l0.clone(),
        illuminance: patch_illuminance(&arriving(model, &x), k),
        direct_illuminance: patch_illuminance(&model.direct.arriving, k),
        energy: EnergyBalance::of(model, &x, scene.surfaces.len()),
        probes,
        grids: Vec::new(),
        grid_errors: Vec::new(),
        observers,
        glare_grids,
        field,
    }
}

/// The stored solution `stored` of the file `path` with the field of its light scene
/// `name`, ready for rendering with its luminaires dimmed as the light scene says.
pub fn lit_light_scene(path: &Path, mut stored: StoredSolution, name: &str) -> Result<LitScene, IoError> {
    crate::io::read_light_scene(path, &mut stored, name)?;
    let base: Vec<Source> = stored.scene.luminaires.iter().map(Source::of).collect();
    let Some(light_scene) = stored.scene.lighting.scenes.iter().find(|s| s.name == name) else {
        let why = format!("its stored scene has no [[light_scene]] \"{name}\", though the file holds its field");
        return Err(crate::io::IoError::NotASolution { path: path.to_path_buf(), why });
    };
    let sources = dimmed(&stored.scene, &base, light_scene);
    Ok(super::view::lit_scene_with(stored, sources))
}
