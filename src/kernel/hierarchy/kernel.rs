//! The hierarchical kernel (`docs/design.md` §3b): the trees, the links that the oracle accepted,
//! and the passes that made them. `new` links from one self-link of the top cluster, with
//! an ambient first guess of the field for brightness; `refine` refines again with a solved
//! field; `operator` applies `K` on the current leaves; `leaf_mesh` and `source` give the
//! leaves as a `Mesh` and their `L0`.

use super::history::Pass;
use super::link::Link;
use super::node::NONE;
use super::operator::Operator;
use super::oracle::Oracle;
use super::push::SeenCache;
use super::refine::{Settings, children_pairs, refine, split_node};
use super::tree::Tree;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN, Patch};
use crate::material::Block;
use crate::transfer::closure::Closure;
use crate::transfer::exposure::Backs;
use crate::transfer::form_factor::Quadrature;
use crate::visibility::Visibility;
use rayon::prelude::*;
use std::time::Instant;

/// How the hierarchy refines.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Error allowed per link relative to the scene's mean reflected luminance: a link is
    /// refined while `ρ_p ΔF_pq L_q > ε = tolerance · L̄_r` (dimensionless), `L̄_r` the
    /// area-weighted mean of `x − L0`: of the ambient term in the first pass, of the solved
    /// field in the later ones. Default 1e-2.
    pub tolerance: f64,
    /// The finest patches (the discretization's `patch_size`): elements whose longest edge
    /// is at most this do not split, m. Default 0.05 m.
    pub patch_size: f64,
    /// Outer quadrature of the element factors. Default `eta = 1`, `max_depth = 4`: a link
    /// is accepted when its factor varies over the pair by less than the tolerance allows,
    /// which bounds the error of the un-refined rule already; a fan triangle is split only
    /// while it is larger than its distance to the other element (graded towards shared
    /// edges as before). With the uniform kernel's `eta = 0.25` the lecture hall evaluated
    /// 318 M point factors instead of 152 M and took 70 s instead of 49 s, for readings
    /// within 0.07 % (`docs/hierarchy.md`, "Element factors"); its depth 7 changes the
    /// closure of a box's leaves by less than 1e-7 and costs 3.4 times the assembly.
    pub quadrature: Quadrature,
    /// Most refinement passes of [`super::iterate`], the initial linking included. Default 4.
    pub passes: usize,
    /// Balance the operator to the leaves' closures (`balance.rs`). Default true; off, the
    /// links' own row and column sums stand.
    pub balance: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tolerance: DEFAULT_TOLERANCE,
            patch_size: 0.05,
            quadrature: Quadrature { eta: 1.0, max_depth: 4 },
            passes: 4,
            balance: true,
        }
    }
}

/// The link tolerance unless one is given: the one default of `Options::tolerance` and of a
/// case's `link_tolerance`.
pub const DEFAULT_TOLERANCE: f64 = 1e-2;

/// The hierarchical form of `K = B·G` over a coarse mesh's patches.
pub struct Hierarchy {
    tree: Tree,
    links: Vec<Link>,
    visibility: Visibility,
    /// The backs of the roots' faces, for the exposed area of new elements.
    backs: Backs,
    directions: DirectionSet,
    blocks: Vec<Block>,
    options: Options,
    oracle: Oracle,
    /// Each node's closure rays (`transfer::closure`), measured when it is first a leaf of
    /// an operator; `None` until then.
    closure: Vec<Option<Closure>>,
    /// The push's weights of the last operator (`push.rs`).
    seen: SeenCache,
    /// Each node's balancing factors (receiving, sending) when it was last a balanced
    /// leaf: where the next operator's balancing starts (`balance.rs`).
    factors: Vec<Option<(f64, f64)>>,
    history: Vec<Pass>,
}

/// Reflectance assumed for the ambient estimate at most (the estimate grows as 1/(1 − ρ)).
const AMBIENT_ALBEDO: f64 = 0.95;

impl Hierarchy {
    /// The roots are the patches of `roots` (e.g. `Mesh::build(scene, root_size)`), with
    /// one block per material; `l0` is the source term on the roots (`x[root·K + k]`,
    /// cd/m²), which with the ambient term of its interreflections is the first guess of
    /// the field. Links start from the top cluster's self-link.
    pub fn new(roots: &Mesh, directions: DirectionSet, blocks: Vec<Block>, options: Options, l0: &[f64]) -> Hierarchy {
        let start = Instant::now();
        let albedo: Vec<f64> = blocks.iter().map(|b| largest_albedo(b, &directions)).collect();
        let visibility = Visibility::build(roots);
        let backs = Backs::of(roots);
        let exposed: Vec<f64> = roots.patches.par_iter().map(|p| backs.exposed_area(&visibility, p)).collect();
        let tree = Tree::new(roots, &albedo, &exposed);
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
            closure: Vec::new(),
            seen: SeenCache::default(),
            factors: Vec::new(),
            history: Vec::new(),
        };
        let roots: Vec<u32> = (0..roots.len() as u32).collect();
        let mut brightness = h.brightness(&roots, &guess);
        let top = h.tree.top();
        let candidates = if top == NONE { Vec::new() } else { vec![(top, top)] };
        let rays = h.refine_candidates(&mut brightness, candidates);
        h.record(1, rays, start);
        h
    }

    /// Splits leaf elements, down to the smallest element size, while
    /// `varies(visibility, element, albedo, ε)` says that the light they receive from outside the links
    /// (the luminaires') changes over them by more than the error allowed (`ε`, cd/m²):
    /// their shadow boundaries. Links stay where they are (a split element is still covered
    /// by its ancestors' links). Returns the number of elements split.
    pub fn split_leaves(&mut self, varies: &(dyn Fn(&Visibility, &Patch, f64, f64) -> bool + Sync)) -> usize {
        let (patch_size, epsilon) = (self.options.patch_size, self.oracle.epsilon);
        let mut todo = self.tree.leaves();
        let mut splits = 0;
        while !todo.is_empty() {
            let (tree, visibility) = (&self.tree, &self.visibility);
            let chosen: Vec<u32> = todo
                .par_iter()
                .copied()
                .filter(|&id| {
                    let node = tree.node(id);
                    tree.can_split(id, patch_size)
                        && node.patch().is_some_and(|p| varies(visibility, p, node.albedo, epsilon))
                })
                .collect();
            todo.clear();
            for id in chosen {
                if !self.tree.node(id).is_leaf() {
                    continue; // the twin of an element split just before
                }
                let (visibility, backs) = (&self.visibility, &self.backs);
                self.tree.split(id, &|p| backs.exposed_area(visibility, p));
                splits += 1;
                todo.extend_from_slice(self.tree.children(id));
            }
        }
        if let Some(last) = self.history.last_mut() {
            last.source_splits += splits;
            last.leaves = self.tree.leaves().len();
            last.nodes = self.tree.len();
        }
        splits
    }

    /// One more pass with the field `x` of the current leaves (the order of
    /// [`Hierarchy::operator`]): every link the oracle now rejects is refined. Returns the
    /// number of links refined (0: the hierarchy is final for this field).
    pub fn refine(&mut self, x: &[f64]) -> usize {
        let start = Instant::now();
        let leaves = self.tree.leaves();
        self.oracle.epsilon = self.options.tolerance * self.mean_reflected(&leaves, x);
        let mut brightness = self.brightness(&leaves, x);
        let (mut redo, mut keep) = (Vec::new(), Vec::with_capacity(self.links.len()));
        for link in std::mem::take(&mut self.links) {
            let (p, q) = (link.receiver, link.source);
            let error = self.oracle.error(self.tree.node(p).albedo, link.bound, brightness[q as usize]);
            match self.oracle.choose(&self.tree, p, q).filter(|_| self.oracle.refines(error)) {
                Some(n) => redo.push((p, q, n)),
                None => keep.push(link),
            }
        }
        self.links = keep;
        let mut candidates = Vec::with_capacity(4 * redo.len());
        let (visibility, backs) = (&self.visibility, &self.backs);
        for &(p, q, n) in &redo {
            split_node(&mut self.tree, &mut brightness, n, &|e| backs.exposed_area(visibility, e));
            children_pairs(&self.tree, p, q, n, &mut candidates);
        }
        let rays = self.refine_candidates(&mut brightness, candidates);
        self.record(redo.len(), rays, start);
        redo.len()
    }

    fn refine_candidates(&mut self, brightness: &mut Vec<f64>, candidates: Vec<(u32, u32)>) -> usize {
        let settings = Settings {
            visibility: &self.visibility,
            backs: &self.backs,
            oracle: self.oracle,
            quadrature: &self.options.quadrature,
            directions: &self.directions,
        };
        refine(&mut self.tree, brightness, &settings, candidates, &mut self.links)
    }

    fn record(&mut self, refined: usize, rays: usize, start: Instant) {
        let pass = Pass {
            pass: self.history.len(),
            links: self.links.len(),
            refined,
            leaves: self.tree.leaves().len(),
            nodes: self.tree.len(),
            rays,
            epsilon: self.oracle.epsilon,
            seconds: start.elapsed().as_secs_f64(),
            ..Pass::default()
        };
        self.history.push(pass);
    }

    /// Notes the time of the solve that followed the last pass, s.
    pub fn record_solve(&mut self, seconds: f64) {
        if let Some(last) = self.history.last_mut() {
            last.solve_seconds = seconds;
        }
    }

    /// Area-weighted mean over the leaves of `x − L0` (exitance-weighted over cells), cd/m².
    fn mean_reflected(&self, leaves: &[u32], x: &[f64]) -> f64 {
        let share = cell_shares(&self.directions);
        let (mut sum, mut area) = (0.0, 0.0);
        for (l, &id) in leaves.iter().enumerate() {
            let node = self.tree.node(id);
            let cells = x.get(l * share.len()..(l + 1) * share.len()).unwrap_or(&[]);
            let value: f64 = cells.iter().zip(&share).map(|(v, s)| v * s).sum();
            sum += node.exposed * (value - node.emission);
            area += node.exposed;
        }
        if area > 0.0 { (sum / area).max(0.0) } else { 0.0 }
    }

    /// Largest value under every node of the leaf field `x` (cd/m²).
    fn brightness(&self, leaves: &[u32], x: &[f64]) -> Vec<f64> {
        let k = self.directions.len();
        let mut b = vec![0.0; self.tree.len()];
        for (l, &id) in leaves.iter().enumerate() {
            let cells = x.get(l * k..(l + 1) * k).unwrap_or(&[]);
            b[id as usize] = cells.iter().copied().fold(0.0, f64::max);
        }
        for id in self.tree.preorder().into_iter().rev() {
            let parent = self.tree.node(id).parent;
            if parent != NONE {
                b[parent as usize] = f64::max(b[parent as usize], b[id as usize]);
            }
        }
        b
    }

    /// `K` on the current leaves, balanced to their closures unless `options.balance` is
    /// off (the rays of new leaves' closures count in the last pass's).
    pub fn operator(&mut self) -> Operator {
        let mut operator = Operator::new(&self.tree, &self.links, &self.blocks, &self.directions, &mut self.seen);
        if self.options.balance {
            let leaves = operator.leaves().to_vec();
            let rays = self.measure_closure(&leaves);
            let targets = self.closure_targets(&operator, &leaves);
            let areas: Vec<f64> = leaves.iter().map(|&id| self.tree.node(id).exposed).collect();
            let start = leaves.iter().map(|&id| self.last_factors(id)).unzip();
            let report = operator.balance(&targets, &areas, start);
            self.factors.resize(self.tree.len(), None);
            for (l, &id) in leaves.iter().enumerate() {
                self.factors[id as usize] = Some((operator.receive[l], operator.send[l]));
            }
            if let Some(last) = self.history.last_mut() {
                last.rays += rays;
                last.balance = Some(report);
            }
        }
        operator
    }

    /// The balancing factors node `id` had as a leaf of the last operator, else those of its
    /// nearest ancestor that was one (a leaf split since), else 1.
    fn last_factors(&self, id: u32) -> (f64, f64) {
        let mut at = id;
        loop {
            if let Some(&Some(f)) = self.factors.get(at as usize) {
                return f;
            }
            match self.tree.node(at).parent {
                NONE => return (1.0, 1.0),
                parent => at = parent,
            }
        }
    }

    /// Measures the closure of the `leaves` not yet measured; returns the rays taken.
    fn measure_closure(&mut self, leaves: &[u32]) -> usize {
        self.closure.resize(self.tree.len(), None);
        let (tree, backs, visibility) = (&self.tree, &self.backs, &self.visibility);
        let todo: Vec<u32> = leaves.iter().copied().filter(|&id| self.closure[id as usize].is_none()).collect();
        let measured: Vec<(Closure, usize)> = todo
            .par_iter()
            .map(|&id| match tree.node(id).patch() {
                Some(p) if p.exposed > 0.0 => backs.closure(visibility, p),
                _ => (Closure::default(), 0),
            })
            .collect();
        todo.iter().zip(&measured).for_each(|(&id, &(c, _))| self.closure[id as usize] = Some(c));
        measured.iter().map(|m| m.1).sum()
    }

    /// Each leaf's row sum to balance to: its links' own (`G·1`, unbalanced) unless its
    /// closure rays tell it apart from the closure (all of them met a front and the row is
    /// not 1, or it lies beyond three standard errors), then the rays' closure.
    fn closure_targets(&self, operator: &Operator, leaves: &[u32]) -> Vec<f64> {
        let k = operator.cells();
        let mut rows = vec![0.0; operator.dim()];
        operator.arriving(&vec![1.0; operator.dim()], &mut rows);
        leaves
            .iter()
            .zip(rows.chunks(k))
            .map(|(&id, row)| {
                let row: f64 = row.iter().sum();
                let rays = self.closure[id as usize].unwrap_or_default();
                if rays.cast == 0 || rays.admits(row) { row } else { rays.share() }
            })
            .collect()
    }

    /// The leaves as a mesh, in unknown order: each leaf (with its twin) its own face,
    /// twins paired, the surface's emission; usable by `Visibility`, the explicit assembly,
    /// probes and output.
    pub fn leaf_mesh(&self) -> Mesh {
        let leaves = self.tree.leaves();
        let mut index = vec![NONE; self.tree.len()];
        leaves.iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
        let mut patches = Vec::with_capacity(leaves.len());
        let mut faces = 0u32;
        for (l, &id) in leaves.iter().enumerate() {
            let node = self.tree.node(id);
            let Some(&patch) = node.patch() else { continue };
            let twin = match node.kind {
                super::node::Kind::Element { twin, .. } if twin != NONE => index[twin as usize],
                _ => NO_TWIN,
            };
            let face = if twin != NO_TWIN && (twin as usize) < l {
                patches.get(twin as usize).map_or(faces, |p: &Patch| p.face)
            } else {
                faces += 1;
                faces - 1
            };
            patches.push(Patch { face, twin, ..patch });
        }
        let emission = leaves.iter().map(|&id| self.tree.node(id).emission).collect();
        Mesh { patches, emission, faces: faces as usize }
    }

    /// The leaves' own emission in every cell, cd/m² (`L0` without luminaires).
    pub fn emission(&self) -> Vec<f64> {
        let k = self.directions.len();
        self.tree.leaves().iter().flat_map(|&id| std::iter::repeat_n(self.tree.node(id).emission, k)).collect()
    }

    /// The field `x` of `old`'s leaves on the current leaves: each new leaf takes the value
    /// of the old leaf it lies in (refinement only splits).
    pub fn prolong(&self, old: &Operator, x: &[f64]) -> Vec<f64> {
        let k = self.directions.len();
        let mut index = vec![NONE; self.tree.len()];
        old.leaves().iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
        let mut out = Vec::with_capacity(self.tree.len() * k);
        for id in self.tree.leaves() {
            let mut n = id;
            while n != NONE && index[n as usize] == NONE {
                n = self.tree.node(n).parent;
            }
            match (n != NONE).then(|| index[n as usize] as usize).and_then(|l| x.get(l * k..(l + 1) * k)) {
                Some(values) => out.extend_from_slice(values),
                None => out.extend(std::iter::repeat_n(0.0, k)),
            }
        }
        out
    }

    /// The element trees and the cluster tree above them.
    pub fn tree(&self) -> &Tree {
        &self.tree
    }

    /// The links the oracle accepted.
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// One record per refinement pass.
    pub fn history(&self) -> &[Pass] {
        &self.history
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
fn cell_shares(directions: &DirectionSet) -> Vec<f64> {
    directions.cells().iter().map(|c| c.projected / std::f64::consts::PI).collect()
}

/// The largest fraction of light arriving in any cell that `block` reflects or transmits.
fn largest_albedo(block: &Block, directions: &DirectionSet) -> f64 {
    (0..directions.len()).map(|d| block.albedo(d, directions)).map(|(a, t)| a + t).fold(0.0, f64::max)
}
