//! `[discretization]` without `kernel` (or `kernel = "auto"`): the kernel chosen by its size
//! (`docs/design.md` §3 and §3b).
//!
//! The uniform kernel while its forecast stays at most [`UNIFORM_PAIRS`] facing pairs of
//! patches: there it is the reference, every solver and norm works on it (`direct`, exact
//! ‖K‖₂, `ugo kernel`), and it reads contact corners better than the hierarchy at equal leaf
//! size (docs/hierarchy.md, "The kernel chosen by size"). Above, its pairs grow as
//! `patch_size⁻⁴` and the hierarchical kernel takes over with its defaults
//! ([`Hierarchical::over`]): leaves down to the patch size, roots [`super::ROOTS`] times it.

use super::check::number;
use super::discretization::{ChosenBySize, Hierarchical, KernelKind};
use crate::directions::Scheme;
use crate::geometry::Surface;
use crate::kernel::Forecast;

/// Facing pairs up to which the kernel chosen by size is the uniform one. The Cornell box
/// at 0.025 m has 9.45 M (27 s, 0.67 GB on 2 cores); past this the uniform kernel's time
/// and memory grow as the pairs do, the hierarchy's about as its leaves.
pub const UNIFORM_PAIRS: f64 = 1e7;

/// The kernel for `surfaces` meshed at `patch_size` with `directions`, and why.
pub fn by_size(patch_size: f64, directions: Scheme, surfaces: &[Surface]) -> (KernelKind, ChosenBySize) {
    let facing_pairs = Forecast::uniform(surfaces, 0, patch_size, &directions.set()).facing_pairs;
    let chosen = ChosenBySize { patch_size, facing_pairs };
    match facing_pairs <= UNIFORM_PAIRS {
        true => (KernelKind::Uniform, chosen),
        false => (KernelKind::Hierarchical(Hierarchical::over(patch_size)), chosen),
    }
}

impl std::fmt::Display for ChosenBySize {
    /// The choice in a sentence, for `ugo info` and `ugo solve`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (pairs, h) = (self.facing_pairs, number(self.patch_size));
        if pairs <= UNIFORM_PAIRS {
            return write!(f, "the uniform kernel: {pairs:.3e} facing pairs at {h} m, at most {UNIFORM_PAIRS:.0e}");
        }
        write!(
            f,
            "the hierarchical kernel: the uniform one would have {} facing pairs at {h} m, over \
             {UNIFORM_PAIRS:.0e}; roots of {} m, leaves down to {h} m (--kernel uniform for the uniform mesh)",
            crate::kernel::figure(pairs),
            number(Hierarchical::over(self.patch_size).root_size)
        )
    }
}
