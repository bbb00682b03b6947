//! How the hierarchical kernel refines (`docs/design.md` §3b, "Oracle"): the link tolerance
//! and its floor for dim receivers, the readings' weight, the finest patches, the element
//! factors' quadrature, the most passes, whether the operator is balanced, the memory it
//! may take and the part of the receivers it links; one default each.

use super::partition::Part;
use crate::transfer::form_factor::Quadrature;

/// How the hierarchy refines.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Error allowed per link relative to the scene's mean reflected luminance: a link is
    /// refined while `ρ_p ΔF_pq L_q > ε = tolerance · L̄_r` (dimensionless), `L̄_r` the
    /// area-weighted mean of `x − L0`: of the ambient term in the first pass, of the solved
    /// field in the later ones. Default 1e-2.
    pub tolerance: f64,
    /// How far a dim receiver's allowance follows its own light, as a share of `L̄_r`: in
    /// the passes after the first, a link into node `p` is refined while its error exceeds
    /// `ε · max(min(L_p, L̄_r), dim_floor · L̄_r) / L̄_r`, `L_p` the least reflected luminance
    /// of the leaves under `p` (`brightness.rs`). 1 gives every receiver the scene's `ε`.
    /// Default [`DIM_FLOOR`].
    pub dim_floor: f64,
    /// How strongly the readings steer the refinement (3b.3b, `brightness.rs`): with
    /// readings, a link into `p` is refined while its error exceeds `ε` divided by the
    /// larger of its dim gain and `reading_weight · L̄_r c_p`, `c_p` the readings'
    /// importance under `p` (the relative change of the readings per cd/m² of error over
    /// `p`). 0 lets no reading steer it. Default [`READING_WEIGHT`].
    pub reading_weight: f64,
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
    /// Most refinement passes of [`super::iterate`], the initial linking included. Default
    /// [`DEFAULT_PASSES`].
    pub passes: usize,
    /// Balance the operator to the leaves' closures (`balance.rs`). Default true; off, the
    /// links' own row and column sums stand.
    pub balance: bool,
    /// Bytes the links, the candidates and the tree may take: refinement stops with a
    /// refusal when a round would start beyond it. Default half the machine's memory.
    pub memory_limit: u64,
    /// Link only the receivers of one part (`partition.rs`): the pairs whose receiver lies
    /// wholly in other parts are dropped unevaluated. Default `None`: every receiver.
    pub part: Option<Part>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tolerance: DEFAULT_TOLERANCE,
            dim_floor: DIM_FLOOR,
            reading_weight: READING_WEIGHT,
            patch_size: 0.05,
            quadrature: Quadrature { eta: 1.0, max_depth: 4 },
            passes: DEFAULT_PASSES,
            balance: true,
            memory_limit: crate::kernel::memory::default_limit(),
            part: None,
        }
    }
}

/// The most refinement passes unless a number is given, the initial linking included.
pub const DEFAULT_PASSES: usize = 4;

/// The link tolerance unless one is given: the one default of `Options::tolerance` and of a
/// case's `link_tolerance`.
pub const DEFAULT_TOLERANCE: f64 = 1e-2;

/// The default [`Options::dim_floor`]: a receiver's allowance follows its reflected light
/// down to three tenths of the scene's mean. On the open box's hard probes
/// (`docs/hierarchy.md`, "Dim receivers' own allowance") 47 of 240 read beyond 1 % with 1 (no floor), 31 with
/// 0.3, 29 with 0.1 and 28 with 0.03, at 187, 241, 268 and 273 thousand links; the Cornell
/// box's hierarchy 15 with 0.3 and with 0.1; the lecture hall's links grow by 11 % with 0.3
/// and by 50 % with 0.1.
pub const DIM_FLOOR: f64 = 0.3;

/// The default [`Options::reading_weight`], chosen on the open box's tuning probes
/// (`tests/data/accuracy/tuning/open-box.csv`, 91 probes apart from the committed set's:
/// 12 beyond 1 % with 10, 9 with 30, 7 with 60, 5 with 100, 3 with 200 and with 400) and
/// reported on its committed 240 (14 beyond 1 % with 30, 2 with 200, for 2.6 times the
/// links); the Cornell box's hierarchy, on which 30 was first chosen, reads 3 of 240 beyond
/// 1 % from 30 up. `docs/hierarchy.md`, "The readings' importance".
pub const READING_WEIGHT: f64 = 200.0;
