//! `[discretization]` without `kernel` (or `kernel = "auto"`): the kernel chosen by its size
//! and by what it reads well (`docs/design.md` §3 and §3b; docs/hierarchy.md, "The kernel
//! chosen by size").
//!
//! The uniform kernel where it is affordable (a forecast of at most [`UNIFORM_PAIRS`]
//! facing pairs) and either its patches are fine against the few centimetres from corners
//! and contacts where rooms are read (at most [`FINE_PATCH`]), or the scene has a mirror,
//! which only the uniform kernel carries by images. There it is the reference, every solver
//! and norm works on it (`direct`, exact ‖K‖₂, `ugo kernel`), and it reads contact corners
//! better than the hierarchy at equal leaf size. Otherwise the hierarchical kernel with its
//! defaults ([`Hierarchical::over`]: leaves down to the patch size, roots [`super::ROOTS`]
//! times it), whose elements are graded toward the room's edges and contacts.

use super::check::number;
use super::description::Material;
use super::discretization::{ChosenBySize, Hierarchical, KernelKind, SizeReason};
use crate::directions::Scheme;
use crate::geometry::Surface;
use crate::kernel::Forecast;

/// Facing pairs up to which the uniform kernel is affordable. The Cornell box at 0.025 m has
/// 9.45 M (27 s, 0.67 GB on 2 cores); past this the uniform kernel's time and memory grow
/// as the pairs do, the hierarchy's about as its leaves.
pub const UNIFORM_PAIRS: f64 = 1e7;

/// Largest patch, m, kept on the uniform kernel, where it reads a room's corners and
/// contacts as well as the hierarchy: the Cornell box's 240 hard probes read 22, 54 and 111
/// beyond 1 % on it at 0.05, 0.07 and 0.1 m, on the hierarchy 25, 24 and 40; the daylit
/// office's 160 read 29 on it at 0.25 m, 1 on the hierarchy (docs/hierarchy.md, "The kernel
/// chosen by size").
pub const FINE_PATCH: f64 = 0.05;

/// The kernel for `surfaces` (of `materials`) meshed at `patch_size` with `directions`, and why.
pub fn by_size(
    patch_size: f64,
    directions: Scheme,
    surfaces: &[Surface],
    materials: &[Material],
) -> (KernelKind, ChosenBySize) {
    let facing_pairs = Forecast::uniform(surfaces, 0, patch_size, &directions.set()).facing_pairs;
    let mirrors = surfaces.iter().any(|s| materials[s.material].model.is_delta());
    let reason = match () {
        _ if facing_pairs > UNIFORM_PAIRS => SizeReason::TooManyPairs,
        _ if patch_size <= FINE_PATCH => SizeReason::FinePatches,
        _ if mirrors => SizeReason::Mirrors,
        _ => SizeReason::CoarsePatches,
    };
    let kernel = match reason {
        SizeReason::FinePatches | SizeReason::Mirrors => KernelKind::Uniform,
        SizeReason::CoarsePatches | SizeReason::TooManyPairs => {
            KernelKind::Hierarchical(Hierarchical::over(patch_size))
        }
    };
    (kernel, ChosenBySize { patch_size, facing_pairs, reason })
}

impl std::fmt::Display for ChosenBySize {
    /// The choice in a sentence, for `ugo info` and `ugo solve`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (pairs, h, fine) = (self.facing_pairs, number(self.patch_size), number(FINE_PATCH));
        let roots = number(Hierarchical::over(self.patch_size).root_size);
        let hierarchy = format!("roots of {roots} m, leaves down to {h} m (--kernel uniform for the uniform mesh)");
        match self.reason {
            SizeReason::FinePatches => write!(
                f,
                "the uniform kernel: {pairs:.3e} facing pairs at {h} m, at most {UNIFORM_PAIRS:.0e}, and patches \
                 of at most {fine} m"
            ),
            SizeReason::Mirrors => write!(
                f,
                "the uniform kernel: {pairs:.3e} facing pairs at {h} m, at most {UNIFORM_PAIRS:.0e}, and mirrors, \
                 which only it carries by images (its patches over {fine} m read corners coarsely: a smaller \
                 patch_size)"
            ),
            SizeReason::CoarsePatches => write!(
                f,
                "the hierarchical kernel: uniform patches of {h} m, over {fine} m, read a room's corners and \
                 contacts a few per cent off; {hierarchy}"
            ),
            SizeReason::TooManyPairs => write!(
                f,
                "the hierarchical kernel: the uniform one would have {} facing pairs at {h} m, over \
                 {UNIFORM_PAIRS:.0e}; {hierarchy}",
                crate::kernel::figure(pairs),
            ),
        }
    }
}
