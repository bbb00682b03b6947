//! [`BenchError`]: why a measurement of `ugo bench` gave no figure.

use crate::io::IoError;
use crate::model::ModelError;
use crate::solve::SolveError;
use std::path::PathBuf;
use thiserror::Error;

/// Why a measurement gave no figure.
#[derive(Debug, Error)]
pub enum BenchError {
    /// No two patches of the mesh face each other: no occlusion ray or kernel entry to time.
    #[error(
        "no two of its {patches} patches face each other, so there are no occlusion rays or kernel entries to \
         time; bench a case with interreflection (e.g. cases/cornell-box.toml)"
    )]
    NoFacingPairs {
        /// The mesh's patches.
        patches: usize,
    },
    /// A leaf size of the hierarchical curve that is not a positive length.
    #[error("--scaling takes positive leaf sizes in metres with --kernel hierarchical, got {0}")]
    LeafSize(f64),
    /// A level of the hierarchical curve whose model was built otherwise.
    #[error("the model was not built hierarchically")]
    NotHierarchical,
    /// The model could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The solve failed.
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// The pool of threads could not be built.
    #[error(transparent)]
    Threads(#[from] rayon::ThreadPoolBuildError),
    /// The folder of the peers' files could not be created.
    #[error("cannot create {}", .0.display())]
    Folder(PathBuf, #[source] std::io::Error),
    /// A file could not be written.
    #[error(transparent)]
    Io(#[from] IoError),
    /// The peers' metadata could not be written as JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
}
