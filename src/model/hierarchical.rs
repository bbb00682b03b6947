//! The hierarchical model (`docs/design.md` §3b): roots meshed at `root_size`, the luminaires'
//! direct light on them (at a few points of each) as the first source term, then passes of refinement iterated with
//! a solve (`kernel::refine_with_solves`). Before every solve the leaves are split where
//! the direct light of the luminaires, the sun and the openings varies over them by more
//! than the error allowed (their shadow boundaries and the fall-off under them), and `L0 = L_e + B·D` is integrated on the
//! leaves as on a uniform mesh (`luminaire::patch_lights`), except that a shadow edge is
//! cut into finer pieces only while a piece's light could change the leaf's reflected
//! luminance by more than the oracle's `ε`. The refinement solves
//! use GMRES(30) to [`REFINEMENT_RESIDUAL`]; the final solve is the caller's, with the
//! case's method and stopping rule, on the final leaves.

use super::range::{check_blocks, check_source, check_transport};
use super::readers::{direct_importance, readers};
use super::source::source_term;
use super::system::{AssemblyStats, HierarchyRecord, Model, ModelError};
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, Patch};
use crate::kernel::hierarchy::{Hierarchy, Options, sample_points};
use crate::kernel::{Factored, Footprint, Kernel, Refined, refine_with_solves};
use crate::luminaire::{DirectLight, Light, OPENING_ETA, PatchLight, Source, arriving_at, incoming, patch_lights};
use crate::material::Block;
use crate::progress::Progress;
use crate::scene::{Hierarchical, Scene};
use crate::sky::{self, Cuts, Opening, SHADOW_SHARE, Sky, glimpse};
use crate::solve::{Method, SolveParams, System, solve};
use crate::transfer::exposure::measure_exposure;
use crate::visibility::{Faces, SightFrom, Visibility};
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::time::Instant;

/// Relative residual of the solves between refinement passes: the oracle needs the field
/// to a fraction of the link tolerance, not to the final stopping rule.
pub const REFINEMENT_RESIDUAL: f64 = 1e-5;

/// The openings' cuts for the roots' seed light, a first guess only: pieces of
/// [`OPENING_ETA`], shadow edges cut while a piece holds [`SHADOW_SHARE`] of the opening's
/// light, as on a patch (`luminaire::patch`).
const SEED: Cuts = Cuts { eta: OPENING_ETA, shadow_share: SHADOW_SHARE };

/// New leaves whose direct light is integrated between two progress reports.
const LEAF_BATCH: usize = 4096;

/// The luminaires' light on every node that has been a leaf (by node id): computed once
/// per element, with the roots' ray caster (the elements keep their root's face).
struct LightCache {
    lights: Vec<Option<PatchLight>>,
}

impl LightCache {
    /// The direct light on the current leaves of `h`, in unknown order, computing it only
    /// for the leaves new since the last call; `progress` hears of them [`LEAF_BATCH`] at a
    /// time.
    fn on_leaves(
        &mut self,
        h: &Hierarchy,
        sources: &[Source],
        directions: &DirectionSet,
        progress: &dyn Progress,
    ) -> DirectLight {
        let leaves = h.tree().leaves();
        self.lights.resize(h.tree().len(), None);
        let new: Vec<u32> = leaves.iter().copied().filter(|&id| self.lights[id as usize].is_none()).collect();
        let patches: Vec<Patch> = new.iter().filter_map(|&id| h.tree().node(id).patch().copied()).collect();
        let least: Vec<f64> = new.iter().map(|&id| worth_cutting(h, id)).collect();
        let what = format!("direct light on {} new leaves: leaves done", new.len());
        let batches = new.chunks(LEAF_BATCH).zip(patches.chunks(LEAF_BATCH)).zip(least.chunks(LEAF_BATCH));
        let mut done = 0;
        for ((ids, patches), least) in batches {
            for (id, light) in ids.iter().zip(patch_lights(sources, patches, h.visibility(), directions, least, &[])) {
                self.lights[*id as usize] = Some(light);
            }
            done += ids.len() as u64;
            progress.at(done, &what);
        }
        let mut direct = DirectLight::none(sources);
        leaves.iter().filter_map(|&id| self.lights[id as usize].as_ref()).for_each(|l| direct.add(l));
        direct
    }
}

/// The flux (lm) below which a shadowed piece of element `id` is not cut further: what
/// would change its reflected luminance by the error the oracle allows a link,
/// `ρ ΔΦ/(π A) = ε`.
pub(super) fn worth_cutting(h: &Hierarchy, id: u32) -> f64 {
    let node = h.tree().node(id);
    match node.albedo > 0.0 {
        true => h.epsilon() * PI * node.area / node.albedo,
        false => f64::INFINITY,
    }
}

/// Links the roots, refines with the solve, and returns the model on the final leaves,
/// with the tree's skeleton and links when `keep` (for a kernel file).
pub fn build(
    scene: &Scene,
    parameters: Hierarchical,
    progress: &dyn Progress,
    keep: bool,
) -> Result<Model, ModelError> {
    let d = &scene.discretization;
    let directions = d.directions.set();
    let k = directions.len();
    let blocks: Vec<Block> = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    check_blocks(scene, &blocks, k)?;
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let windows: Vec<(&Opening, &Sky)> = sources.iter().filter_map(window_of).collect();
    let Seed { roots, visibility: root_visibility, light: root_light, l0: root_l0, mesh_seconds, seconds } =
        seed(scene, parameters, &sources, &blocks, progress)?;
    let root_light_seconds = seconds;
    let readers = readers(scene, &sources, &root_visibility, &directions);
    let mut light_seconds = 0.0;
    let t = Instant::now();
    let hierarchy_options = options(scene, parameters);
    // The passes grow in cost as the links multiply: counted, with no time left forecast;
    // the linking tells its rounds' pairs settled, a batch at a time, between the solves.
    progress.begin("refinement", 0);
    let mut h = Hierarchy::new(
        &roots,
        root_visibility,
        directions.clone(),
        blocks.clone(),
        hierarchy_options,
        &root_l0,
        progress,
    )?;
    let mut cache = LightCache { lights: Vec::new() };
    let mut pass = 0;
    let mut source = |h: &mut Hierarchy| -> Result<Vec<f64>, ModelError> {
        pass += 1;
        crate::interrupt::check(|| format!("the hierarchical kernel's refinement pass {pass}"))?;
        let start = Instant::now();
        h.split_leaves(&|visibility, patch, albedo, epsilon| {
            varies(&sources, &windows, visibility, patch, albedo, epsilon)
        });
        let direct = cache.on_leaves(h, &sources, &directions, progress);
        let leaves = h.leaf_mesh();
        let l0 = source_term(&blocks, &leaves, &direct, k);
        check_source(scene, &leaves, &direct, &l0, k)?;
        light_seconds += start.elapsed().as_secs_f64();
        Ok(l0)
    };
    let mut solves = 0;
    let mut solver = |kernel: &Kernel, b: &[f64], scale: f64| -> Result<Vec<f64>, ModelError> {
        let g = &kernel.g;
        let (what, bytes, nonzeros, patches, cells) =
            ("hierarchical kernel", g.bytes(), g.nnz() as f64, g.rows() / k, k);
        Footprint { what, bytes, nonzeros, patches, cells }.check(d.memory_limit)?;
        let params = SolveParams { tolerance: (REFINEMENT_RESIDUAL * scale).min(0.5), ..SolveParams::default() };
        let operator = Factored::new(kernel);
        let system = System { operator: &operator, explicit: None, areas: &[], l0: b };
        let (x, _) = solve(Method::Gmres { restart: 30 }, &system, &params, &mut |_, _| {})?;
        solves += 1;
        progress.at(solves, "refinement: passes solved");
        Ok(x)
    };
    let steered = !readers.is_empty() && hierarchy_options.reading_weight > 0.0;
    let mut readings = |h: &Hierarchy, x: &[f64]| -> Result<Option<Vec<f64>>, ModelError> {
        Ok(steered.then(|| direct_importance(&readers, &h.leaf_mesh(), h.visibility(), &directions, x)))
    };
    let Refined { kernel, leaves: mesh, l0, history, .. } =
        refine_with_solves(&mut h, &mut source, &mut solver, &mut readings, progress)?;
    progress.end();
    let kernel_seconds = t.elapsed().as_secs_f64() - light_seconds;
    let direct = cache.on_leaves(&h, &sources, &directions, progress);
    let t_bvh = Instant::now();
    let visibility = Visibility::build_for(&scene.surfaces, &mesh);
    let bvh_seconds = t_bvh.elapsed().as_secs_f64();
    let stats = AssemblyStats {
        mesh_seconds,
        bvh_seconds,
        kernel_seconds,
        light_seconds: root_light_seconds + light_seconds,
        pairs: kernel.g.hierarchy().map_or(0, |g| g.links()),
        rays: history.iter().map(|p| p.rays).sum::<usize>() + root_light.rays + direct.rays,
        balance: None,
    };
    let census = h.census();
    let structure = keep.then(|| h.into_structure());
    let record =
        HierarchyRecord { parameters, patch_size: d.patch_size, roots: roots.len(), history, census, structure };
    check_transport(scene, &mesh, &kernel.g, k)?;
    let faces = Faces::of(&mesh);
    let materials = scene.materials.iter().map(|m| m.model.clone()).collect();
    Ok(Model {
        mesh,
        visibility,
        faces,
        kernel,
        materials,
        l0,
        sources,
        direct,
        mirrors: Vec::new(),
        stats,
        hierarchy: Some(record),
    })
}

/// The roots of a hierarchy, their ray caster, the seed of their direct light and their
/// source term, and the seconds meshing and lighting them took.
pub(super) struct Seed {
    pub roots: Mesh,
    pub visibility: Visibility,
    pub light: DirectLight,
    pub l0: Vec<f64>,
    pub mesh_seconds: f64,
    pub seconds: f64,
}

/// The roots of `scene` at `parameters.root_size` with their exposed areas, and their
/// seed light and source term under `sources` with the materials' `blocks`.
pub(super) fn seed(
    scene: &Scene,
    parameters: Hierarchical,
    sources: &[Source],
    blocks: &[Block],
    progress: &dyn Progress,
) -> Result<Seed, ModelError> {
    let t = Instant::now();
    let directions = scene.discretization.directions.set();
    let mut roots = Mesh::build(&scene.surfaces, parameters.root_size);
    let mesh_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let visibility = Visibility::build_for(&scene.surfaces, &roots);
    measure_exposure(&mut roots, &visibility, progress);
    crate::interrupt::check(|| "the roots' exposed areas".into())?;
    let light = seed_light(sources, &roots, &visibility, &directions, progress);
    crate::interrupt::check(|| "the direct light on the roots".into())?;
    let l0 = source_term(blocks, &roots, &light, directions.len());
    check_source(scene, &roots, &light, &l0, directions.len())?;
    Ok(Seed { roots, visibility, light, l0, mesh_seconds, seconds: t.elapsed().as_secs_f64() })
}

/// The hierarchy's options from the case: its link tolerance, finest patches, passes and
/// memory limit, the rest default.
pub(super) fn options(scene: &Scene, parameters: Hierarchical) -> Options {
    let d = &scene.discretization;
    Options {
        tolerance: parameters.link_tolerance,
        patch_size: d.patch_size,
        memory_limit: d.memory_limit,
        passes: parameters.passes,
        ..Options::default()
    }
}

/// The luminaires' light on the roots, only to seed the oracle's first guess (each root's
/// own light is integrated exactly once it is a leaf): `D_d` averaged over the oracle's
/// sample points of each root, one shadow ray per point and source; `progress` hears of
/// each root (a signal's stop leaves the roots after it dark: `crate::interrupt`, the
/// caller checks).
fn seed_light(
    sources: &[Source],
    roots: &Mesh,
    visibility: &Visibility,
    directions: &DirectionSet,
    progress: &dyn Progress,
) -> DirectLight {
    let k = directions.len();
    progress.begin("direct light on the roots", roots.patches.len() as u64);
    let arriving: Vec<f64> = roots
        .patches
        .par_iter()
        .flat_map_iter(|patch| {
            let frame = patch.frame();
            let mut mean = vec![0.0; k];
            let mut points = 0.0;
            for x in sample_points(patch).take_while(|_| !crate::interrupt::asked()) {
                let d = arriving_at(sources, visibility, directions, x, &frame, patch.face, SEED);
                mean.iter_mut().zip(d).for_each(|(m, d)| *m += d);
                points += 1.0;
            }
            progress.advance(1);
            mean.into_iter().map(move |m| m / f64::max(points, 1.0))
        })
        .collect();
    progress.end();
    let points: usize = roots.patches.iter().map(|p| sample_points(p).count()).sum();
    DirectLight { arriving, rays: points * sources.len(), ..DirectLight::none(sources) }
}

/// True when the direct light of `sources` (whose openings are `windows`) reflected by
/// `patch` (albedo `albedo`) varies over it by more than `epsilon` (cd/m²):
/// `ρ (E_max − E_min)/π` over the oracle's sample points of the element
/// (`hierarchy::sample_points`). The luminaires' and the sun's light is looked at
/// with one shadow ray per point and source; the openings' with a glimpse
/// (`sky::glimpse`, 16 rays per point and opening), only where their unshadowed light
/// could make up the difference.
pub(super) fn varies(
    sources: &[Source],
    windows: &[(&Opening, &Sky)],
    visibility: &Visibility,
    patch: &Patch,
    albedo: f64,
    epsilon: f64,
) -> bool {
    if sources.is_empty() || albedo <= 0.0 {
        return false;
    }
    let allowed = epsilon * PI / albedo;
    let points: Vec<DVec3> = sample_points(patch).collect();
    let lit: Vec<f64> = points.iter().map(|&x| point_light(sources, visibility, patch, x)).collect();
    let lamps = spread(lit.iter().copied());
    if lamps > allowed || windows.is_empty() {
        return lamps > allowed;
    }
    let n = patch.normal;
    let unshadowed: Vec<f64> =
        points.iter().flat_map(|&x| windows.iter().map(move |(w, sky)| sky::unshadowed(sky, w, x, n))).collect();
    let most = unshadowed.chunks(windows.len()).map(|u| u.iter().sum::<f64>()).fold(0.0, f64::max);
    if lamps + most <= allowed {
        return false;
    }
    let shadowed = points.iter().zip(unshadowed.chunks(windows.len())).zip(&lit).map(|((&x, u), e)| {
        let sight = SightFrom::new(visibility, x, n, patch.face);
        e + windows.iter().zip(u).map(|((w, _), u)| u * glimpse::seen_share(w, x, n, &sight)).sum::<f64>()
    });
    spread(shadowed) > allowed
}

/// `max − min` of `values` (0 for none).
fn spread(values: impl Iterator<Item = f64>) -> f64 {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| (lo.min(e), hi.max(e)));
    (hi - lo).max(0.0)
}

/// The illuminance (lx) of the luminaires and the sun at the point `x` of `patch`.
fn point_light(sources: &[Source], visibility: &Visibility, patch: &Patch, x: DVec3) -> f64 {
    let incoming = sources.iter().filter_map(|s| incoming(s, visibility, x, patch.face));
    incoming.map(|(towards, normal)| normal * towards.dot(patch.normal).max(0.0)).sum()
}

/// The opening and sky of a window's source.
pub(super) fn window_of(source: &Source) -> Option<(&Opening, &Sky)> {
    match &source.light {
        Light::Window { window, sky } => Some((window, sky)),
        _ => None,
    }
}
