//! Links (`docs/design.md` §3b, "Links"): a receiver node `p` gathers `F_pq x̄_q` from a source
//! node `q`. Between two elements `F_pq = (1/A_p) ∫_p F_{dA→q} dA` by the exact contour
//! integral and adaptive quadrature (`form_factor::pair_integral`), times the visible
//! fraction; for `K > 1` split by cells `(d, m)` like `G[(i,d),(j,m)]`: the mean of the
//! integral binned from either end (`binned_pair_integral`), as the uniform kernel's
//! `T^{d,m} = v (S_pq^{d,m} + S_qp^{m,d})/2`, so that `A_p F_pq^{d,m} = A_q F_qp^{m,d}`. A link of a cluster uses the cluster's projected area across
//! the link (Sillion 1995 with the directional area of Christensen et al. 1997: from its
//! vector areas, `vector_areas.rs`, exact for elements of a few normals in any orientation,
//! where the isotropic mean cosine 1/4 is off by up to 4×), and the light a cluster receives arrives from all
//! cells alike (`μ_d/π` each), so it holds in any frame.

use super::node::Node;
use super::pieces::{Piece, Pieces};
use super::sight::Sight;
use super::tree::Tree;
use crate::directions::DirectionSet;
use crate::geometry::Patch;
use crate::transfer::far_field::far_pair_integral;
use crate::transfer::form_factor::{Binning, Quadrature, binned_pair_integral, pair_integral};
use std::f64::consts::PI;

/// Receiver cell of a piece that arrives from all directions alike (`μ_d/π` in cell `d`).
pub const ALL_CELLS: u16 = u16::MAX;

/// A link from source `source` to receiver `receiver` (node ids), in 32 bytes (issue 35,
/// point 3; `docs/performance.md`): the fractions in f32, the factor in f64.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// The node that gathers, `p`.
    pub receiver: u32,
    /// The node gathered from, `q`.
    pub source: u32,
    /// `F_pq` with visibility, dimensionless; between elements that `p`'s four points
    /// do not see at all (`visible` 0), `F_pq` unoccluded, for `p`'s leaves to see by their
    /// own rays (`push.rs`).
    pub factor: f64,
    /// The visible fraction in `factor`: free segments of 4 or 16, exact in f32.
    pub visible: f32,
    /// What the oracle multiplies by `ρ_p L_q`: the variation of the factor over the two
    /// nodes, its largest value where visibility is partial, a bound for a cluster (an
    /// estimate: f32 is ample).
    pub bound: f32,
    /// The factor by cells; empty means the one piece `(0, 0, factor)` (`K = 1`).
    pub pieces: Pieces,
}

impl Link {
    /// The link from `source` to `receiver` with its factor, visible fraction, oracle's
    /// bound and cell pieces (the fractions rounded to f32).
    pub fn new(receiver: u32, source: u32, factor: f64, visible: f64, bound: f64, pieces: Vec<Piece>) -> Link {
        Link { receiver, source, factor, visible: visible as f32, bound: bound as f32, pieces: pieces.into() }
    }

    /// Whether the tested segments were all free, some blocked, or all blocked.
    pub fn sight(&self) -> Sight {
        Sight::of(f64::from(self.visible))
    }
}

/// `F_pq` of two elements with visible fraction `visible`, and its cell pieces when binned.
pub fn element_factor(
    p: &Patch,
    q: &Patch,
    visible: f64,
    quadrature: &Quadrature,
    binning: Option<&Binning>,
) -> (f64, Vec<Piece>) {
    let Some(binning) = binning else {
        let integral = far_pair_integral(p, q).unwrap_or_else(|| pair_integral(p, q, quadrature).adaptive);
        return (visible * integral / p.area, Vec::new());
    };
    let (mut bins, mut back) = (Vec::new(), Vec::new());
    let whole = binned_pair_integral(p, q, quadrature, binning, &mut bins);
    binned_pair_integral(q, p, quadrature, binning, &mut back);
    let half = 0.5 * visible / p.area;
    bins.iter_mut().for_each(|b| b.2 *= half);
    bins.extend(back.iter().map(|&(m, d, f)| (d, m, half * f)));
    (visible * whole.adaptive / p.area, merged(bins))
}

/// The factor of a link with a cluster at one end (or both), and its one piece: the two
/// ends' projected areas across the line between their centres,
/// `F_pq = P_p(u) P_q(−u) / (A_p π d²)` (`Tree::projected`).
pub fn cluster_factor(tree: &Tree, (p, q): (u32, u32), directions: &DirectionSet) -> (f64, Vec<Piece>) {
    let factor = projected_transfer(tree, p, q);
    let (p, q) = (tree.node(p), tree.node(q));
    let (u, _) = axis(p, q);
    let cell_p = cell(p, u, directions);
    let cell_q = match cell(q, -u, directions) {
        ALL_CELLS => 0,
        m => m,
    };
    let pieces = if directions.len() > 1 { vec![(cell_p, cell_q, factor)] } else { Vec::new() };
    (factor, pieces)
}

/// `P_p(u) P_q(−u) / (A_p π d²)` along the line between the centres of nodes `p` and `q`, at
/// most 1 (`docs/design.md` (3b.2)): the factor of a link with a cluster at one end, and the
/// estimate by which a leaf takes its share of what its element ancestor gathers from a
/// cluster (`push.rs`).
pub fn projected_transfer(tree: &Tree, p: u32, q: u32) -> f64 {
    let (u, distance) = axis(tree.node(p), tree.node(q));
    let area = tree.node(p).area;
    (tree.projected(p, u) * tree.projected(q, -u) / (area * PI * distance * distance)).min(1.0)
}

/// The unit direction from `p`'s centre to `q`'s and their distance (at least the gap
/// between their bounding boxes), m.
pub fn axis(p: &Node, q: &Node) -> (glam::DVec3, f64) {
    let offset = q.centre() - p.centre();
    let distance = offset.length().max(p.box_distance(q));
    (offset / distance, distance)
}

/// The cell of `u` in an element's frame; [`ALL_CELLS`] for a cluster (cell 0 as a source:
/// a cluster's value is the same in all).
fn cell(node: &Node, u: glam::DVec3, directions: &DirectionSet) -> u16 {
    match node.patch() {
        Some(patch) => directions.lookup(patch.frame().local(u)) as u16,
        None => ALL_CELLS,
    }
}

/// Pieces merged by cell pair, in `(d, m)` order.
fn merged(mut bins: Vec<Piece>) -> Vec<Piece> {
    bins.sort_unstable_by_key(|&(d, m, _)| (d, m));
    let mut out: Vec<Piece> = Vec::with_capacity(bins.len());
    for (d, m, f) in bins {
        match out.last_mut() {
            Some(last) if last.0 == d && last.1 == m => last.2 += f,
            _ => out.push((d, m, f)),
        }
    }
    out.shrink_to_fit();
    out
}
