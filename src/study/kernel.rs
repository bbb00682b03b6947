//! The kernel of a solve, assembled or reused (issue 15, `docs/kernel-file.md`): with
//! `--kernel-file FILE.h5` the uniform `G` of an earlier `--save-kernel` is read instead of
//! assembled when the case's fingerprint matches the stored one; a change of a part that
//! `G` depends on (geometry, discretization, visibility, version, the materials of a
//! hierarchical kernel) is refused naming it; a change of the reflectances or the
//! luminaires only rebuilds `B`, `D` and `L0` around the stored `G` (`docs/design.md` §3).
//! The hierarchical kernel is neither saved nor reused (its links live on a tree of
//! elements refined along the solved field; the reason is in the docs).

use crate::io::{IoError, KernelRecord, Loaded, StoredKernel, read_kernel};
use crate::kernel::Transport;
use crate::model::{Change, Fingerprint, Model, ModelError, NotThisMesh, Part, StoredParts};
use crate::progress::Progress;
use crate::scene::{KernelKind, Scene};
use std::path::{Path, PathBuf};
use std::time::Instant;
use thiserror::Error;

/// Why a kernel could not be saved or reused.
#[derive(Debug, Error)]
pub enum KernelError {
    /// The kernel file could not be read or written.
    #[error(transparent)]
    Io(#[from] IoError),
    /// The stored kernel was made for another case: parts `G` depends on changed.
    #[error(
        "{} was assembled for another case: {} changed; G depends on it, so the kernel is not reused \
         (assemble it again with `ugo solve CASE --save-kernel`)",
        path.display(),
        changes.iter().map(Change::to_string).collect::<Vec<_>>().join(", ")
    )]
    Mismatch {
        /// The kernel file.
        path: PathBuf,
        /// The parts that changed.
        changes: Vec<Change>,
    },
    /// The hierarchical kernel is neither saved nor reused.
    #[error(
        "the hierarchical kernel (the case's kernel, chosen by size, or --kernel) is neither saved nor \
         reused: its links join elements of a tree refined along the solved field and the luminaires' light, \
         which a kernel file does not hold; use the uniform kernel (--kernel uniform) to save or reuse G"
    )]
    Hierarchical,
    /// The stored `G` does not fit the case's mesh.
    #[error(transparent)]
    Mesh(#[from] NotThisMesh),
    /// The model around the stored kernel could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// The model of `scene`: assembled, or around the `G` of `kernel` when given; with the
/// fingerprint to store when `save`. Refuses the hierarchical kernel in either case.
pub fn model_with_kernel(
    scene: &Scene,
    kernel: Option<&Path>,
    save: bool,
    progress: &dyn Progress,
) -> Result<(Model, KernelRecord), KernelError> {
    if (save || kernel.is_some()) && matches!(scene.discretization.kernel, KernelKind::Hierarchical(_)) {
        return Err(KernelError::Hierarchical);
    }
    let fingerprint = (save || kernel.is_some()).then(|| Fingerprint::of(scene));
    let Some(path) = kernel else {
        let model = Model::build(scene, progress)?;
        return Ok((model, KernelRecord { save: fingerprint, loaded: None }));
    };
    let ours = fingerprint.clone().unwrap_or_else(|| Fingerprint::of(scene));
    let t = Instant::now();
    let stored = read_kernel(path)?;
    let seconds = t.elapsed().as_secs_f64();
    let changes = ours.changes_from(&stored.fingerprint);
    let (rebuilt, refused): (Vec<Change>, Vec<Change>) = changes.into_iter().partition(|c| c.part.rebuilt().is_some());
    if !refused.is_empty() {
        return Err(KernelError::Mismatch { path: path.to_path_buf(), changes: refused });
    }
    let changed = |part: Part| rebuilt.iter().any(|c| c.part == part);
    let StoredKernel { kernel, direct, .. } = stored;
    let Transport::Uniform(g) = kernel.g else { return Err(KernelError::Hierarchical) };
    let parts = StoredParts {
        g,
        blocks: (!changed(Part::Reflectances)).then_some(kernel.blocks),
        direct: (!changed(Part::Luminaires)).then_some(direct),
        read_seconds: seconds,
    };
    let model = Model::with_kernel(scene, parts)?;
    let loaded = Loaded { path: path.to_path_buf(), rebuilt, seconds };
    Ok((model, KernelRecord { save: save.then_some(ours), loaded: Some(loaded) }))
}
