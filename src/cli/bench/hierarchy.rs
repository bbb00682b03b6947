//! The hierarchical kernel's part of `ugo bench` (issue 14, point 6; `docs/design.md` §3b): the
//! case built and solved at a sequence of leaf sizes (`patch_size`) under the same roots and
//! link tolerance, and per size the leaves N, links, nodes, occlusion rays, time, memory
//! and links/N², with the growth exponents of links and of time against N fitted by least
//! squares on the logarithms (the uniform kernel's pairs grow as N²).

use super::peak::Peak;
use super::scaling::slope;
use anyhow::{Result, bail};
use serde::Serialize;
use std::time::Instant;
use ugo::kernel::Factored;
use ugo::model::{HierarchyRecord, Model};
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::solve::{SolveParams, successive_approximation};

/// One leaf size of the curve.
#[derive(Debug, Clone, Serialize)]
pub struct Level {
    /// The edge the leaves split down to, m.
    pub patch_size: f64,
    /// Root elements (patches at `--root-size`).
    pub roots: usize,
    /// Leaf elements N (the unknowns per direction cell).
    pub leaves: usize,
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
    pub levels: Vec<Level>,
    /// `p` of `links ∝ N^p`.
    pub links_exponent: f64,
    /// `p` of `time ∝ N^p`.
    pub time_exponent: f64,
}

/// Builds and solves the hierarchical `scene` with its leaves down to `patch_size`.
pub fn level(scene: &Scene, patch_size: f64) -> Result<(Level, Model)> {
    let mut scene = scene.clone();
    scene.discretization.patch_size = patch_size;
    let peak = Peak::start();
    let t = Instant::now();
    let model = Model::build(&scene, &Silent)?;
    let refinement_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let params = SolveParams { tolerance: 1e-8, max_iterations: 10_000, ..SolveParams::default() };
    successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {})?;
    let solve_seconds = t.elapsed().as_secs_f64();
    let Some(record) = &model.hierarchy else { bail!("the model was not built hierarchically") };
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
        solve_seconds: solve,
        seconds: build + solve,
        operator_bytes: model.kernel.g.bytes(),
        peak_bytes: peak,
    }
}

/// The case's own level `own` with one more for every leaf size in `sizes` (default: 4,
/// 2.8, 2 and 1.4 times the case's), sorted by N, printed, with the exponents.
pub fn curve(scene: &Scene, tolerance: f64, sizes: &[f64], own: Level) -> Result<Curve> {
    let sizes: Vec<f64> =
        if sizes.is_empty() { [4.0, 2.8, 2.0, 1.4].map(|f| f * own.patch_size).to_vec() } else { sizes.to_vec() };
    let mut levels = vec![own];
    for s in sizes {
        if !(s.is_finite() && s > 0.0) {
            bail!("--scaling takes positive leaf sizes in metres with --kernel hierarchical, got {s}");
        }
        if levels.iter().all(|l| l.patch_size != s) {
            levels.push(level(scene, s)?.0);
        }
    }
    levels.sort_by_key(|l| l.leaves);
    let links_exponent = slope(levels.iter().map(|l| (l.leaves as f64, l.links as f64)));
    let time_exponent = slope(levels.iter().map(|l| (l.leaves as f64, l.seconds)));
    let curve = Curve { levels, links_exponent, time_exponent };
    print(&curve, tolerance);
    Ok(curve)
}

/// The curve as a table.
fn print(c: &Curve, tolerance: f64) {
    println!(
        "  hierarchy (link tolerance {tolerance:e}; refine + solve, Neumann to 1e-8): links ∝ N^{:.2}, time ∝ N^{:.2}",
        c.links_exponent, c.time_exponent
    );
    println!(
        "    {:>10} {:>6} {:>8} {:>10} {:>9} {:>9} {:>11} {:>7} {:>8} {:>8} {:>8} {:>9}",
        "patch size",
        "roots",
        "leaves N",
        "links",
        "links/N²",
        "nodes",
        "rays",
        "passes",
        "refine s",
        "solve s",
        "op MiB",
        "+peak MiB"
    );
    let mib = |b: f64| b / (1u64 << 20) as f64;
    for l in &c.levels {
        let peak = l.peak_bytes.map_or("-".into(), |b| format!("{:.0}", mib(b)));
        println!(
            "    {:>9.4} {:>6} {:>8} {:>10} {:>9.2e} {:>9} {:>11} {:>7} {:>8.2} {:>8.3} {:>8.1} {:>9}",
            l.patch_size,
            l.roots,
            l.leaves,
            l.links,
            l.links_per_n2,
            l.nodes,
            l.rays,
            l.passes,
            l.refinement_seconds,
            l.solve_seconds,
            mib(l.operator_bytes),
            peak
        );
    }
}
