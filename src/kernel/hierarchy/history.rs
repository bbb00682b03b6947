//! The refinement history (`docs/design.md` §3b, "Oracle": solve, refine where the current
//! field says it matters, solve again): one record per pass.

use crate::kernel::BalanceReport;

/// What one refinement pass produced and cost.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pass {
    /// 0 for the initial linking, then 1, 2, … after each solve.
    pub pass: usize,
    /// Links after the pass.
    pub links: usize,
    /// Links of the previous pass that the oracle refined (the initial self-link in pass 0).
    pub refined: usize,
    /// Leaf elements (unknowns per cell) after the pass.
    pub leaves: usize,
    /// Nodes of the hierarchy (clusters and elements) after the pass.
    pub nodes: usize,
    /// Leaf elements split after the pass where the direct light (luminaires, sun, openings) varies over them
    /// ([`super::Hierarchy::split_leaves`]).
    pub source_splits: usize,
    /// Occlusion rays traced in the pass (the new leaves' closures included).
    pub rays: usize,
    /// How balancing the pass's operator to its leaves' closures went (`None`: not balanced).
    pub balance: Option<BalanceReport>,
    /// The error allowed per link in the pass, cd/m².
    pub epsilon: f64,
    /// Wall time of the pass's linking and refining, s.
    pub seconds: f64,
    /// Wall time of building the pass's operator (the push's weights, the pull, the new
    /// leaves' closure rays, the balancing), s.
    pub operator_seconds: f64,
    /// Wall time of the solve that followed the pass, s (0 until it ran).
    pub solve_seconds: f64,
}

/// Work the hierarchy has spent since it was made, counted up by its verbs: the passes'
/// records are differences of two of these.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Work {
    /// Occlusion rays traced: links tested and leaves' closures measured.
    pub rays: usize,
    /// Leaf elements split along the light from outside the links
    /// ([`super::Hierarchy::split_leaves`]).
    pub splits: usize,
    /// Wall time of linking and refining, s.
    pub seconds: f64,
    /// Wall time of building operators (`Hierarchy::operator`), s.
    pub operator_seconds: f64,
}
