//! The flags of `ugo bench`.

use crate::cli::options::Discretize;
use std::path::PathBuf;

/// What `ugo bench` measures.
#[derive(Debug, clap::Args)]
pub struct BenchOptions {
    /// The case to measure on (default: the bundled Cornell box).
    #[arg(default_value = "cases/cornell-box.toml")]
    pub(super) case: PathBuf,
    #[command(flatten)]
    pub(super) discretize: Discretize,
    /// Occlusion rays to time.
    #[arg(long, default_value_t = 2_000_000)]
    pub(super) rays: usize,
    /// Also time every BVH layout (with a correctness column).
    #[arg(long)]
    pub(super) layouts: bool,
    /// Patch sizes of the scaling curve, m (default: 2.5, 2, 1.5 and 1.25 times the case's);
    /// with `--kernel hierarchical`, the leaves' patch sizes under the same roots (default:
    /// 4, 2.8, 2 and 1.4 times the case's).
    #[arg(long, value_delimiter = ',')]
    pub(super) scaling: Vec<f64>,
    /// Also time dense LU (faer against nalgebra) at these sizes.
    #[arg(long, value_delimiter = ',')]
    pub(super) lu: Vec<usize>,
    /// Write the figures as JSON here.
    #[arg(long)]
    pub(super) json: Option<PathBuf>,
    /// Write the rays, triangles and matrix for `docs/peers/peers.py` into this folder.
    #[arg(long)]
    pub(super) export: Option<PathBuf>,
}
