//! `[discretization]` without `method` (or `method = "auto"`): the kernel chosen by its size
//! (issue 14, point 8; `docs/design.md` §3 and §3b).
//!
//! The explicit kernel while its forecast stays at most [`EXPLICIT_PAIRS`] facing pairs of
//! patches: there it is the reference, every solver and norm works on it (`direct`, exact
//! ‖K‖₂, `ugo kernel`), and it reads contact corners better than the hierarchy at equal leaf
//! size (docs/hierarchy.md, "The kernel chosen by size"). Above, its pairs grow as
//! `patch_size⁻⁴` and the hierarchical kernel takes over: its elements split down to the patch
//! size asked for, roots [`ROOTS`] times it, the default link tolerance.

use super::description::{Assembly, Automatic, Discretization};
use crate::directions::Scheme;
use crate::geometry::Surface;
use crate::kernel::Forecast;

/// Facing pairs up to which the kernel chosen by size is the explicit one. The Cornell box
/// at 0.025 m has 9.45 M (27 s, 0.67 GB on 2 cores); past this the explicit kernel's time
/// and memory grow as the pairs do, the hierarchy's about as its leaves.
pub const EXPLICIT_PAIRS: f64 = 1e7;

/// The hierarchy's roots, in patch sizes: two quadtree levels above its smallest leaves.
pub const ROOTS: f64 = 4.0;

impl Discretization {
    /// The discretization of a case that does not name its `method`, meshed at
    /// `patch_size` with `directions` over `surfaces`.
    pub fn automatic(patch_size: f64, directions: Scheme, surfaces: &[Surface]) -> Discretization {
        let facing_pairs = Forecast::explicit(surfaces, 0, patch_size, &directions.set()).facing_pairs;
        let automatic = Some(Automatic { asked: patch_size, facing_pairs });
        if facing_pairs <= EXPLICIT_PAIRS {
            return Discretization { patch_size, directions, assembly: Assembly::Explicit, automatic };
        }
        Discretization { automatic, ..Discretization::hierarchical_down_to(patch_size, directions) }
    }

    /// The hierarchy chosen above [`EXPLICIT_PAIRS`]: elements split down to `patch_size`
    /// from roots [`ROOTS`] times it, the default link tolerance.
    pub fn hierarchical_down_to(patch_size: f64, directions: Scheme) -> Discretization {
        let tolerance = crate::kernel::hierarchy::Options::default().tolerance;
        let assembly = Assembly::Hierarchical { tolerance, smallest: patch_size };
        Discretization { patch_size: ROOTS * patch_size, directions, assembly, automatic: None }
    }
}

impl std::fmt::Display for Automatic {
    /// The choice in a sentence, for `ugo info` and `ugo solve`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (pairs, h) = (self.facing_pairs, self.asked);
        if pairs <= EXPLICIT_PAIRS {
            return write!(f, "the explicit kernel: {pairs:.3e} facing pairs at {h} m, at most {EXPLICIT_PAIRS:.0e}");
        }
        write!(
            f,
            "the hierarchical kernel: the explicit one would have {pairs:.3e} facing pairs at {h} m, over \
             {EXPLICIT_PAIRS:.0e}; roots of {} m, elements split down to {h} m (--assembly explicit for the uniform mesh)",
            ROOTS * h
        )
    }
}
