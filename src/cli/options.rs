//! The options that several subcommands share: overrides of the case file's
//! `[discretization]` and of its `[solver]` stopping rule, and the typed values of the
//! flags that name a choice (parsed by clap, never compared as strings afterwards).

use ugo::directions::Scheme;
use ugo::io::Scale;
use ugo::kernel::Precision;
use ugo::scene::{Asked, Given, KernelAsked, KernelKind};
use ugo::solve::Method;

/// Options that override the case file's `[discretization]`, key by key; checked with the
/// case's keys by the same rules (`Scene::discretize`).
#[derive(clap::Args, Clone, Debug)]
pub struct Discretize {
    /// Edge of the finest patches, m: every patch of the uniform kernel, the leaves the
    /// hierarchical one splits down to (default: the case's `patch_size`).
    #[arg(long, allow_negative_numbers = true)]
    pub patch_size: Option<f64>,
    /// Largest kernel memory allowed, GiB (default: half of the least of the machine's RAM, the control group's limit and `ulimit -v`).
    #[arg(long, allow_negative_numbers = true)]
    pub memory_limit: Option<f64>,
    /// Direction cells per patch: a count K (equal solid angle), `klems` or `tregenza`
    /// (default: the case's `directions`, else 1).
    #[arg(long, value_parser = scheme, allow_negative_numbers = true)]
    pub directions: Option<Scheme>,
    /// Precision of the stored transport matrix G: `f64` (16 bytes per non-zero) or `f32`
    /// (f32 values and u32 indices, 8 bytes; products still accumulate in f64).
    #[arg(long, value_enum)]
    pub precision: Option<PrecisionArg>,
    /// How the transport is built: `uniform` (every facing pair of patches), `hierarchical`
    /// (element trees from roots of `--root-size` down to `--patch-size`, links where the
    /// oracle accepts them; docs/hierarchy.md) or `auto`. Default: the case's `kernel`;
    /// without one, the uniform kernel up to 10⁷ facing pairs at patches of at most 0.05 m
    /// (or with mirrors), else the hierarchical one with its defaults. A saved kernel is
    /// `--kernel-file`.
    #[arg(long, value_parser = kernel)]
    pub kernel: Option<KernelAsked>,
    /// Edge of the hierarchical kernel's roots, m (default: the case's `root_size`, else 4
    /// times the patch size).
    #[arg(long, allow_negative_numbers = true)]
    pub root_size: Option<f64>,
    /// Error allowed per link of the hierarchical kernel, relative to the mean reflected
    /// luminance (default: the case's `link_tolerance`, else 1e-2).
    #[arg(long, allow_negative_numbers = true)]
    pub link_tolerance: Option<f64>,
    /// Most refinement passes of the hierarchical kernel, the initial linking included
    /// (default 4; 1 solves on the initial linking alone, as the partitioned solve does).
    #[arg(long)]
    pub passes: Option<usize>,
}

impl Discretize {
    /// What the flags ask of the discretization.
    pub fn asked(&self) -> Asked {
        Asked {
            patch_size: self.patch_size.map(Given::flag("--patch-size")),
            root_size: self.root_size.map(Given::flag("--root-size")),
            link_tolerance: self.link_tolerance.map(Given::flag("--link-tolerance")),
            passes: self.passes.map(Given::flag("--passes")),
            kernel: self.kernel.map(Given::flag("--kernel")),
            directions: self.directions,
            precision: self.precision.map(Precision::from),
            memory_limit: self.memory_limit.map(Given::flag("--memory-limit")),
        }
    }
}

/// `--kernel`.
fn kernel(name: &str) -> Result<KernelAsked, String> {
    KernelAsked::parse(name).ok_or_else(|| {
        format!("--kernel must be {}, got \"{name}\" (a saved kernel is read with --kernel-file)", KernelKind::NAMES)
    })
}

/// Options that override the case file's `[solver]` stopping rule.
#[derive(clap::Args, Clone, Debug)]
pub struct Stopping {
    /// Relative residual at which the iteration stops (default: the case's `[solver]`).
    #[arg(long, allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
    /// Most iterations (default: the case's `[solver]`).
    #[arg(long, allow_negative_numbers = true)]
    pub max_iterations: Option<usize>,
    /// Turn every warning into an error: the case's and those found before the solve stop
    /// it; those about the solved field stop after the solution is written with them.
    #[arg(long)]
    pub strict: bool,
    /// Print every warning's whole text (by default one line each; the whole text is in
    /// the output's /warnings).
    #[arg(long)]
    pub verbose: bool,
}

/// `--directions`.
fn scheme(name: &str) -> Result<Scheme, String> {
    Scheme::parse(name).ok_or_else(|| format!("--directions must be {}, got \"{name}\"", Scheme::NAMES))
}

/// Longest GMRES restart: `M + 1` Krylov vectors of the system's length are kept.
pub const MAX_RESTART: usize = 1000;

/// Highest reflection order `--orders` records (each order is one product with K).
pub const MAX_ORDER: usize = 100_000;

/// `--method`, `--methods`.
pub fn method(name: &str) -> Result<Method, String> {
    match Method::parse(name) {
        Some(Method::Gmres { restart }) if restart > MAX_RESTART => Err(format!(
            "gmres:M keeps M + 1 vectors of the system's length: M must lie in 1..={MAX_RESTART}, got {restart}"
        )),
        Some(m) => Ok(m),
        None => Err(format!("unknown method \"{name}\"; known: {}", Method::names())),
    }
}

/// One entry of `--orders`.
pub fn order(text: &str) -> Result<usize, String> {
    let n: usize = text.parse().map_err(|e| format!("a reflection order is a whole number ≥ 0: {e}"))?;
    if n > MAX_ORDER {
        return Err(format!("at most {MAX_ORDER} reflections (one product with K each), got {n}"));
    }
    Ok(n)
}

/// `--precision`.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum PrecisionArg {
    F64,
    F32,
}

impl From<PrecisionArg> for Precision {
    fn from(p: PrecisionArg) -> Precision {
        match p {
            PrecisionArg::F64 => Precision::Double,
            PrecisionArg::F32 => Precision::Single,
        }
    }
}

/// `--shading` (the gather's ray count is a flag of its own).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadingArg {
    /// The stored patch values.
    Flat,
    /// Interpolated across each surface's patches.
    Smooth,
    /// One more reflection at every hit point.
    Gather,
}

/// `--false-colour`.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum ScaleArg {
    Log,
    Linear,
    /// Blue negative, white 0, red positive, symmetric about 0 (eigenvectors, `--mode`).
    Signed,
}

impl From<ScaleArg> for Scale {
    fn from(s: ScaleArg) -> Scale {
        match s {
            ScaleArg::Log => Scale::Log,
            ScaleArg::Linear => Scale::Linear,
            ScaleArg::Signed => Scale::Signed,
        }
    }
}

/// `--basis`: hemispherical harmonics (with --lmax) or the truncated SVD of each
/// material block (with --rank).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BasisArg {
    Sh,
    Svd,
}

/// `--basis`.
pub fn basis(name: &str) -> Result<BasisArg, String> {
    match name {
        "sh" => Ok(BasisArg::Sh),
        "svd" => Ok(BasisArg::Svd),
        other => Err(format!("--basis takes `sh` or `svd`, got \"{other}\"")),
    }
}
