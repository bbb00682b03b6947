//! One part's rows of the operator from the part files (issue 36, point 4; `docs/petsc.md`,
//! "The operator from the part files"), the second round of the partitioned build: with
//! every part's links written (`part.rs`), part `i` rebuilds the one-process tree from all
//! parts' splits and the links that reach its leaves (`hierarchy::Hierarchy::rebuilt`),
//! splits the leaves along the direct light as `hierarchical.rs` does before a solve (all
//! of them, so that every part numbers the unknowns alike), and forms for its own leaves
//! the push rows, `L0 = L_e + B·D` and `D` (`docs/design.md` (2.4), §3b), for its own
//! bundles the gather rows, and each own leaf's closure rays. Balancing and the solve need
//! the global operator: the distributed program does them (`tools/petsc`).

use super::hierarchical::{options, seed, varies, window_of, worth_cutting};
use super::part::PartLinks;
use super::range::check_blocks;
use super::source::source_term;
use super::system::ModelError;
use crate::geometry::{Mesh, NO_TWIN, Patch};
use crate::kernel::hierarchy::{Hierarchy, Kind, NamedLink, Options, Part, Rows};
use crate::luminaire::{DirectLight, Source, patch_lights};
use crate::material::Block;
use crate::progress::Progress;
use crate::scene::{Hierarchical, Scene};
use std::time::Instant;

/// A part's rows of the operator and of the source term.
pub struct PartRows {
    /// Which part of how many.
    pub part: Part,
    /// Direction cells per leaf.
    pub cells: usize,
    /// The tree, the gather rows of its bundles, the push rows and closures of its leaves.
    pub rows: Rows,
    /// `L0` of its leaves, `x[l·K + k]` from its first leaf, cd/m².
    pub l0: Vec<f64>,
    /// `D` of its leaves (the luminaires' light arriving, in the units of `G x`).
    pub arriving: Vec<f64>,
    /// Each own leaf's exposed area, m², and whether it emits.
    pub exposed: Vec<f64>,
    /// See `exposed`.
    pub emits: Vec<bool>,
    /// Each own leaf's material and twin (an unknown's leaf index, or [`NO_TWIN`]).
    pub material: Vec<u32>,
    /// See `material`.
    pub twin: Vec<u32>,
    /// The materials' blocks.
    pub blocks: Vec<Block>,
    /// The links that reached its leaves (its own and those into clusters over it).
    pub reaching: usize,
    /// Occlusion rays and seconds of this round.
    pub rays: usize,
    /// See `rays`.
    pub seconds: f64,
}

/// The rows of part `part` of the hierarchy of `scene`, from the links of every part
/// (`parts`, one per part, joined and of this case); `progress` hears of the seed light.
pub fn part_rows(
    scene: &Scene,
    parameters: Hierarchical,
    part: Part,
    parts: &[&PartLinks],
    progress: &dyn Progress,
) -> Result<PartRows, ModelError> {
    let start = Instant::now();
    let directions = scene.discretization.directions.set();
    let k = directions.len();
    let blocks: Vec<Block> = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    check_blocks(scene, &blocks, k)?;
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let windows: Vec<_> = sources.iter().filter_map(window_of).collect();
    let seed = seed(scene, parameters, &sources, &blocks, progress)?;
    let splits: Vec<_> = parts.iter().flat_map(|p| p.splits.iter().cloned()).collect();
    let links = parts
        .iter()
        .flat_map(|p| p.links.iter())
        .map(|l| -> NamedLink { (&l.receiver, &l.source, l.factor, l.visible, &l.pieces) });
    let part_options = Options { part: Some(part), ..options(scene, parameters) };
    let (roots, visibility) = (&seed.roots, seed.visibility);
    let mut h = Hierarchy::rebuilt(
        roots,
        visibility,
        directions.clone(),
        blocks.clone(),
        part_options,
        &seed.l0,
        &splits,
        links,
    )
    .map_err(ModelError::Parts)?;
    let reaching = h.links().len();
    h.split_leaves(&|visibility, patch, albedo, epsilon| {
        varies(&sources, &windows, visibility, patch, albedo, epsilon)
    });
    let rows = h.part_rows(progress).map_err(ModelError::Parts)?;
    let index = leaf_index(&h, &rows);
    let (l0, direct) = own_source(&h, &rows, &index, &sources, &blocks);
    let own = &rows.leaves[rows.own_leaves.clone()];
    let node = |id: &u32| h.tree().node(*id);
    Ok(PartRows {
        part,
        cells: k,
        exposed: own.iter().map(|id| node(id).exposed).collect(),
        emits: own.iter().map(|id| node(id).emission > 0.0).collect(),
        material: own.iter().map(|id| node(id).patch().map_or(0, |p| p.material)).collect(),
        twin: own.iter().map(|&id| twin_of(&h, id).map_or(NO_TWIN, |t| index[t as usize])).collect(),
        blocks,
        reaching,
        rays: h.work().rays + seed.light.rays + direct.rays,
        seconds: start.elapsed().as_secs_f64(),
        l0,
        arriving: direct.arriving[..own.len() * k].to_vec(),
        rows,
    })
}

/// `L0` and the direct light of the part's own leaves: integrated as `hierarchical.rs`
/// integrates every leaf's, on the own leaves and their twins (whose light a transmitting
/// material brings through); `L0` and `D` of the own leaves first. `index` is each leaf's
/// index among the unknowns, by node id.
fn own_source(
    h: &Hierarchy,
    rows: &Rows,
    index: &[u32],
    sources: &[Source],
    blocks: &[Block],
) -> (Vec<f64>, DirectLight) {
    let k = h.directions().len();
    let own = rows.own_leaves.clone();
    let twin_leaf = |id: u32| twin_of(h, id).map(|t| index[t as usize] as usize);
    let mut behind: Vec<usize> =
        rows.leaves[own.clone()].iter().filter_map(|&id| twin_leaf(id)).filter(|l| !own.contains(l)).collect();
    behind.sort_unstable();
    // where leaf `l` (an own leaf or the twin of one) stands among the patches lit here
    let at = |l: usize| match own.contains(&l) {
        true => Some(l - own.start),
        false => behind.binary_search(&l).ok().map(|b| own.len() + b),
    };
    let nodes: Vec<u32> = own.clone().chain(behind.iter().copied()).map(|l| rows.leaves[l]).collect();
    let patches: Vec<Patch> = nodes
        .iter()
        .map(|&id| {
            let twin = twin_leaf(id).and_then(at).map_or(NO_TWIN, |i| i as u32);
            Patch { twin, ..*h.tree().node(id).patch().expect("a leaf is an element") }
        })
        .collect();
    let least: Vec<f64> = nodes.iter().map(|&id| worth_cutting(h, id)).collect();
    let mut direct = DirectLight::none(sources);
    patch_lights(sources, &patches, h.visibility(), h.directions(), &least, &[]).iter().for_each(|l| direct.add(l));
    let emission = nodes.iter().map(|&id| h.tree().node(id).emission).collect();
    let mesh = Mesh { patches, emission, faces: 0 };
    let l0 = source_term(blocks, &mesh, &direct, k);
    (l0[..own.len() * k].to_vec(), direct)
}

/// Each leaf's index among the unknowns, by node id.
fn leaf_index(h: &Hierarchy, rows: &Rows) -> Vec<u32> {
    let mut index = vec![NO_TWIN; h.tree().len()];
    rows.leaves.iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
    index
}

/// The twin element of leaf `id`, if it has one.
fn twin_of(h: &Hierarchy, id: u32) -> Option<u32> {
    match h.tree().node(id).kind {
        Kind::Element { twin, .. } if twin != crate::kernel::hierarchy::NONE => Some(twin),
        _ => None,
    }
}
