//! The kernel of a solve, assembled or reused (issues 15 and 36, `docs/kernel-file.md`): with
//! `--kernel-file FILE.h5` the `G` of an earlier `--save-kernel` (the uniform matrix, or the
//! hierarchy's tree, links and operator) is read instead of assembled or refined when the
//! case's fingerprint matches the stored one; a change of a part that `G` depends on
//! (geometry, discretization, visibility, version, the mirrors of a uniform kernel) is
//! refused naming it; a change of the reflectances or the luminaires only rebuilds `B`, `D`
//! and `L0` around the stored `G` (`docs/design.md` §3), and for a hierarchy the summary says
//! that its tree was refined under the file's light, not the case's.

use crate::io::{IoError, KernelRecord, Loaded, StoredKernel, read_kernel};
use crate::model::{Change, Fingerprint, Model, ModelError, NotThisMesh, Part, StoredParts};
use crate::progress::Progress;
use crate::scene::Scene;
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
    /// The stored `G` does not fit the case's mesh.
    #[error(transparent)]
    Mesh(#[from] NotThisMesh),
    /// The model around the stored kernel could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// The model of `scene`: assembled, or around the `G` of `kernel` when given; with the
/// fingerprint to store when `save` (and the hierarchy's links kept for it).
pub fn model_with_kernel(
    scene: &Scene,
    kernel: Option<&Path>,
    save: bool,
    progress: &dyn Progress,
) -> Result<(Model, KernelRecord), KernelError> {
    let fingerprint = (save || kernel.is_some()).then(|| Fingerprint::of(scene));
    let Some(path) = kernel else {
        let model = if save { Model::build_to_save(scene, progress)? } else { Model::build(scene, progress)? };
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
    let StoredKernel { kernel, direct, hierarchy, .. } = stored;
    let hierarchical = hierarchy.is_some();
    let parts = StoredParts {
        g: kernel.g,
        blocks: (!changed(Part::Reflectances)).then_some(kernel.blocks),
        direct: (!changed(Part::Luminaires)).then_some(direct),
        hierarchy,
        read_seconds: seconds,
    };
    let model = Model::with_kernel(scene, parts)?;
    let loaded = Loaded { path: path.to_path_buf(), rebuilt, seconds, hierarchical };
    Ok((model, KernelRecord { save: save.then_some(ours), loaded: Some(loaded) }))
}
