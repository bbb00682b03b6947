//! The hierarchical kernel's curve (issue 14, point 6; `docs/design.md` §3b): the case built
//! and solved at a sequence of leaf sizes (`patch_size`) under the same roots and link
//! tolerance, and per size the leaves N, links, nodes, occlusion rays, time (and of it the
//! linking's and the operators'), memory and links/N², with the growth exponents of links
//! and of time against N fitted by least squares on the logarithms (the uniform kernel's
//! pairs grow as N²).

use super::error::BenchError;
use super::peak::Peak;
use super::scaling::{build_and_solve, slope};
use crate::model::{HierarchyRecord, Model};
use crate::scene::Scene;
use serde::Serialize;

/// One leaf size of the curve.
#[derive(Debug, Clone, Serialize)]
pub struct Level {
    /// The edge the leaves split down to, m.
    pub patch_size: f64,
    /// Root elements (patches at `--root-size`).
    pub roots: usize,
    /// Leaf elements N (the unknowns per direction cell).
    pub leaves: usize,
    /// Links.
    pub links: usize,
    /// `links / N²`: the share of the uniform kernel's pairs the links stand for.
    pub links_per_n2: f64,
    /// Links with a cluster at one end or both.
    pub cluster_links: usize,
    /// Nodes of the hierarchy (clusters and elements).
    pub nodes: usize,
    /// Occlusion rays: every refinement pass's and the luminaires' direct light.
    pub rays: usize,
    /// Refinement passes (each followed by a solve).
    pub passes: usize,
    /// The model's build: roots, luminaires' light, every pass and its solve, s.
    pub refinement_seconds: f64,
    /// Of the build, the passes' linking and refining, s.
    pub linking_seconds: f64,
    /// Of the build, the passes' operators (the push's weights, the pull, the new leaves'
    /// closure rays, the balancing), s.
    pub operator_seconds: f64,
    /// The final solve on the leaves (Neumann to 1e-8), s.
    pub solve_seconds: f64,
    /// `refinement_seconds + solve_seconds`.
    pub seconds: f64,
    /// Bytes the operator holds (links, pieces, node tables).
    pub operator_bytes: f64,
    /// Peak resident memory during the level above the resident size before it, bytes;
    /// `None` off Linux.
    pub peak_bytes: Option<f64>,
}

/// The curve and its fitted exponents.
#[derive(Debug, Clone, Serialize)]
pub struct Curve {
    /// The levels, sorted by N.
    pub levels: Vec<Level>,
    /// `p` of `links ∝ N^p`.
    pub links_exponent: f64,
    /// `p` of `time ∝ N^p`.
    pub time_exponent: f64,
}

/// Builds and solves the hierarchical `scene` with its leaves down to `patch_size`.
pub fn level(scene: &Scene, patch_size: f64) -> Result<(Level, Model), BenchError> {
    let mut scene = scene.clone();
    scene.discretization.patch_size = patch_size;
    let peak = Peak::start();
    let (model, refinement_seconds, solve_seconds) = build_and_solve(&scene)?;
    let Some(record) = &model.hierarchy else { return Err(BenchError::NotHierarchical) };
    let level = counts(record, &model, patch_size, refinement_seconds, solve_seconds, peak.bytes());
    Ok((level, model))
}

/// The level's counts from the hierarchy's record and the model.
fn counts(
    record: &HierarchyRecord,
    model: &Model,
    patch_size: f64,
    build: f64,
    solve: f64,
    peak: Option<f64>,
) -> Level {
    let leaves = model.mesh.len();
    let links = model.stats.pairs;
    Level {
        patch_size,
        roots: record.roots,
        leaves,
        links,
        links_per_n2: links as f64 / (leaves as f64).powi(2),
        cluster_links: record.census.cluster_links,
        nodes: record.history.last().map_or(0, |p| p.nodes),
        rays: model.stats.rays,
        passes: record.history.len(),
        refinement_seconds: build,
        linking_seconds: record.history.iter().map(|p| p.seconds).sum(),
        operator_seconds: record.history.iter().map(|p| p.operator_seconds).sum(),
        solve_seconds: solve,
        seconds: build + solve,
        operator_bytes: model.kernel.g.bytes(),
        peak_bytes: peak,
    }
}

/// The case's own level `own` with one more for every leaf size in `sizes` (default: 4,
/// 2.8, 2 and 1.4 times the case's), sorted by N, with the exponents.
pub fn curve(scene: &Scene, sizes: &[f64], own: Level) -> Result<Curve, BenchError> {
    let sizes: Vec<f64> =
        if sizes.is_empty() { [4.0, 2.8, 2.0, 1.4].map(|f| f * own.patch_size).to_vec() } else { sizes.to_vec() };
    let mut levels = vec![own];
    for s in sizes {
        if !(s.is_finite() && s > 0.0) {
            return Err(BenchError::LeafSize(s));
        }
        if levels.iter().all(|l| l.patch_size != s) {
            levels.push(level(scene, s)?.0);
        }
    }
    levels.sort_by_key(|l| l.leaves);
    let links_exponent = slope(levels.iter().map(|l| (l.leaves as f64, l.links as f64)));
    let time_exponent = slope(levels.iter().map(|l| (l.leaves as f64, l.seconds)));
    Ok(Curve { levels, links_exponent, time_exponent })
}
