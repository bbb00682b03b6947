//! The hierarchical kernel (`docs/design.md` §3b): the element trees and the cluster tree
//! above them, the links the oracle accepted, what it refines with, its caches, and the
//! work spent. `new` links from one self-link of the top cluster, with an ambient first
//! guess of the field for brightness. Its verbs, one file each: `refine` one more pass
//! with a solved field (`pass.rs`), `split_leaves` along the direct light (luminaires, sun, openings)
//! (`split.rs`), `operator` its `G` on the current leaves, balanced (`balanced.rs`),
//! `leaf_mesh`, `emission` and `prolong` on the leaves (`leaves.rs`). The kernel `K = B·G`
//! over that `G`, and the passes iterated with solves, are `crate::kernel`'s.

use super::cuts;
use super::grading::grade;
use super::history::Work;
use super::link::Link;
use super::memo::Memo;
use super::node::NONE;
use super::openness;
use super::options::Options;
use super::oracle::Oracle;
use super::partition::Partition;
use super::refine::Stopped;
use super::tree::Tree;
use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::material::Block;
use crate::progress::Progress;
use crate::transfer::exposure::Backs;
use crate::visibility::Visibility;
use std::time::Instant;

/// The hierarchical form of `G` over a coarse mesh's patches, and what refines it.
pub struct Hierarchy {
    pub(super) tree: Tree,
    pub(super) links: Vec<Link>,
    pub(super) visibility: Visibility,
    /// The backs of the roots' faces, for the exposed area of new elements.
    pub(super) backs: Backs,
    pub(super) directions: DirectionSet,
    pub(super) blocks: Vec<Block>,
    pub(super) options: Options,
    pub(super) oracle: Oracle,
    /// What is kept from one operator to the next (`memo.rs`).
    pub(super) memo: Memo,
    /// Work spent so far.
    pub(super) work: Work,
    /// The receivers linked, when only one part's (`options.part`).
    pub(super) partition: Option<Partition>,
}

/// Reflectance assumed for the ambient estimate at most (the estimate grows as 1/(1 − ρ)).
const AMBIENT_ALBEDO: f64 = 0.95;

impl Hierarchy {
    /// The roots are the patches of `roots` (e.g. `Mesh::build(scene, root_size)`, with
    /// their exposed areas measured by `transfer::exposure::measure_exposure` through
    /// `visibility`, the roots' ray caster), with one block per material; `l0` is the source term on the roots (`x[root·K + k]`,
    /// cd/m²), which with the ambient term of its interreflections is the first guess of
    /// the field. Links start from the top cluster's self-link; the linking stops with the
    /// reason on a signal or beyond `options.memory_limit`; `progress` hears of the pairs
    /// settled.
    pub fn new(
        roots: &Mesh,
        visibility: Visibility,
        directions: DirectionSet,
        blocks: Vec<Block>,
        options: Options,
        l0: &[f64],
        progress: &dyn Progress,
    ) -> Result<Hierarchy, Stopped> {
        let start = Instant::now();
        let (mut h, guess) = Hierarchy::unlinked(roots, visibility, directions, blocks, options, l0);
        let roots: Vec<u32> = (0..roots.len() as u32).collect();
        let mut brightness = h.brightness(&roots, &guess);
        let Hierarchy { tree, visibility, backs, options, .. } = &mut h;
        let exposed = |p: &crate::geometry::Patch| backs.exposed_area(visibility, p);
        let rays = grade(tree, &mut brightness, visibility, &exposed, options.patch_size);
        h.work.rays += rays;
        let top = h.tree.top();
        let candidates = if top == NONE { Vec::new() } else { vec![(top, top)] };
        h.refine_candidates(&mut brightness, candidates, progress)?;
        h.work.seconds += start.elapsed().as_secs_f64();
        Ok(h)
    }

    /// The roots and their clusters with no link yet, the oracle's allowance set from the
    /// first guess of the field, which is returned with it (as [`Hierarchy::new`] takes its
    /// arguments).
    pub(super) fn unlinked(
        roots: &Mesh,
        visibility: Visibility,
        directions: DirectionSet,
        blocks: Vec<Block>,
        options: Options,
        l0: &[f64],
    ) -> (Hierarchy, Vec<f64>) {
        let albedo: Vec<f64> = blocks.iter().map(|b| largest_albedo(b, &directions)).collect();
        let backs = Backs::of(roots);
        let exposed: Vec<f64> = roots.patches.iter().map(|p| p.exposed).collect();
        let mut tree = Tree::new(roots, &albedo, &exposed);
        tree.set_cuts(cuts::of(&tree, roots.len(), options.patch_size));
        let open = openness::open_facing(&mut tree, &visibility);
        tree.set_open(open);
        let share = cell_shares(&directions);
        let (guess, ambient) = first_guess(&tree, l0, &share);
        let oracle = Oracle { epsilon: options.tolerance * ambient, patch_size: options.patch_size };
        let mut h = Hierarchy {
            tree,
            links: Vec::new(),
            visibility,
            backs,
            directions,
            blocks,
            options,
            oracle,
            memo: Memo::default(),
            work: Work::default(),
            partition: None,
        };
        h.partition = options.part.map(|part| Partition::new(&h.tree, part));
        (h, guess)
    }

    /// The element trees and the cluster tree above them.
    pub fn tree(&self) -> &Tree {
        &self.tree
    }

    /// The links the oracle accepted.
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// The work spent so far: rays, leaves split, seconds of linking.
    pub fn work(&self) -> Work {
        self.work
    }

    /// The blocks of the materials, one per material.
    pub fn blocks(&self) -> &[Block] {
        &self.blocks
    }

    /// The options the hierarchy was built with.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The direction cells of every leaf.
    pub fn directions(&self) -> &DirectionSet {
        &self.directions
    }

    /// The ray caster of the roots (the scene's surfaces as meshed for the roots).
    pub fn visibility(&self) -> &Visibility {
        &self.visibility
    }

    /// The partition of the receivers, when only one part's were linked.
    pub fn partition(&self) -> Option<&Partition> {
        self.partition.as_ref()
    }

    /// The error allowed per link in the last pass, cd/m².
    pub fn epsilon(&self) -> f64 {
        self.oracle.epsilon
    }
}

/// The first guess of the field on the roots (node `i` is root `i`): the source term
/// `l0` plus the ambient term of progressive radiosity (Cohen, Chen, Wallace & Greenberg
/// 1988), `ρ̄ L̄0 / (1 − ρ̄)` with area-weighted means (`L̄0` weighted over cells by `share`),
/// so that the first pass links the surfaces the sources do not reach sensibly too; and the
/// ambient term, cd/m².
fn first_guess(tree: &Tree, l0: &[f64], share: &[f64]) -> (Vec<f64>, f64) {
    let k = share.len();
    let (mut area, mut source, mut reflected) = (0.0, 0.0, 0.0);
    for (i, cells) in l0.chunks(k).enumerate() {
        let n = tree.node(i as u32);
        area += n.exposed;
        source += n.exposed * cells.iter().zip(share).map(|(l, s)| l * s).sum::<f64>();
        reflected += n.exposed * n.albedo;
    }
    if area <= 0.0 {
        return (l0.to_vec(), 0.0);
    }
    let albedo = (reflected / area).min(AMBIENT_ALBEDO);
    let ambient = albedo * source / area / (1.0 - albedo);
    (l0.iter().map(|l| l + ambient).collect(), ambient)
}

/// `μ_d/π` of every cell (they sum to 1).
pub(super) fn cell_shares(directions: &DirectionSet) -> Vec<f64> {
    directions.cells().iter().map(|c| c.projected / std::f64::consts::PI).collect()
}

/// The largest fraction of light arriving in any cell that `block` reflects or transmits.
fn largest_albedo(block: &Block, directions: &DirectionSet) -> f64 {
    (0..directions.len()).map(|d| block.albedo(d, directions)).map(|(a, t)| a + t).fold(0.0, f64::max)
}
