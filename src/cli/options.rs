//! The options that several subcommands share: overrides of the case file's
//! `[discretization]` and of its `[solver]` stopping rule.

/// Options that override the case file's `[discretization]`.
#[derive(clap::Args, Clone, Debug)]
pub struct Discretize {
    /// Target patch edge length, m (default: the case's `patch_size`).
    #[arg(long)]
    pub patch_size: Option<f64>,
    /// Largest kernel memory allowed, GiB (default: half the machine's RAM).
    #[arg(long)]
    pub memory_limit: Option<f64>,
    /// Direction cells per patch: a count K (equal solid angle), `klems` or `tregenza`
    /// (default: the case's `directions`, else 1).
    #[arg(long)]
    pub directions: Option<String>,
    /// Precision of the stored transport matrix G: `f64` (16 bytes per non-zero) or `f32`
    /// (f32 values and u32 indices, 8 bytes; products still accumulate in f64).
    #[arg(long)]
    pub precision: Option<String>,
}

/// Options that override the case file's `[solver]` stopping rule.
#[derive(clap::Args, Clone, Debug)]
pub struct Stopping {
    /// Relative residual at which the iteration stops (default: the case's `[solver]`).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Most iterations (default: the case's `[solver]`).
    #[arg(long)]
    pub max_iterations: Option<usize>,
}
