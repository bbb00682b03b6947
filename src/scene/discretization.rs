//! The one record of how a case is discretized (`docs/design.md` §2, §3, §3b): what the case's
//! `[discretization]` and the command line ask for ([`Asked`]), resolved and checked once,
//! by the same rules for a key as for a flag, into a [`Discretization`].
//!
//! Each parameter has one meaning. `patch_size` is the edge of the finest patches: every
//! patch of the uniform kernel, the leaves the hierarchy may split down to. `root_size` is
//! the edge of the hierarchy's roots (default [`ROOTS`] times `patch_size`), and
//! `link_tolerance` the error its oracle allows a link. Without `kernel` (or with
//! `kernel = "auto"`) the kernel is chosen by size (`automatic.rs`).

use super::check::number;
use super::error::SceneError;
use crate::directions::Scheme;
use crate::kernel::Precision;
use std::path::Path;

/// The hierarchy's roots, in patch sizes, unless `root_size` is given: two quadtree levels
/// above its smallest leaves.
pub const ROOTS: f64 = 4.0;

/// How a case is discretized, resolved from the case and the command line.
#[derive(Debug, Clone, PartialEq)]
pub struct Discretization {
    /// Edge of the finest patches, m: every patch of the uniform kernel, the smallest leaves
    /// of the hierarchical one.
    pub patch_size: f64,
    /// Direction cells of every patch (default one cell: radiosity).
    pub directions: Scheme,
    /// How the transport `G` is built.
    pub kernel: KernelKind,
    /// Precision of the stored uniform `G`.
    pub precision: Precision,
    /// Largest kernel memory allowed, bytes.
    pub memory_limit: u64,
    /// Set when the case left the kernel to its size: what the choice was made from.
    pub chosen_by_size: Option<ChosenBySize>,
}

/// `kernel`: how the transport `G` is built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KernelKind {
    /// Every facing pair of patches of `patch_size` gets its entries (`docs/design.md` §3).
    Uniform,
    /// Element trees over roots, links where the oracle accepts them (`docs/design.md` §3b).
    Hierarchical(Hierarchical),
}

/// The hierarchical kernel's own parameters (its leaves go down to `patch_size`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hierarchical {
    /// Edge of the roots, the largest elements, m.
    pub root_size: f64,
    /// Error allowed per link relative to the mean reflected luminance (dimensionless).
    pub link_tolerance: f64,
    /// Most refinement passes, the initial linking included (`--passes`; default
    /// [`Hierarchical::DEFAULT_PASSES`]): 1 solves on the initial linking alone, as the
    /// partitioned solve's parts build it (`docs/petsc.md`, "Parts").
    pub passes: usize,
}

/// Why the kernel was chosen by size (`automatic.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChosenBySize {
    /// The patch size the choice was made at, m.
    pub patch_size: f64,
    /// Unordered pairs of facing patches the uniform kernel would have at it.
    pub facing_pairs: f64,
    /// What the choice was made for.
    pub reason: SizeReason,
}

/// What decided the kernel chosen by size (`automatic.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SizeReason {
    /// Uniform: affordable, its patches fine against corners and contacts.
    FinePatches,
    /// Uniform: affordable, with mirrors, which only it carries by images.
    Mirrors,
    /// Hierarchical: uniform patches coarse against corners and contacts.
    CoarsePatches,
    /// Hierarchical: the uniform kernel would have too many facing pairs.
    TooManyPairs,
}

impl Discretization {
    /// The uniform kernel at `patch_size`, one direction cell, the default precision and
    /// memory limit: a scene made in code rather than read from a case.
    pub fn uniform(patch_size: f64) -> Discretization {
        Discretization {
            patch_size,
            directions: Scheme::Cells(1),
            kernel: KernelKind::Uniform,
            precision: Precision::default(),
            memory_limit: crate::kernel::memory::default_limit(),
            chosen_by_size: None,
        }
    }
}

impl KernelKind {
    /// The names `kernel` takes.
    pub const NAMES: &'static str = "\"uniform\", \"hierarchical\" or \"auto\"";

    /// The kernel's name as `kernel` spells it.
    pub fn name(&self) -> &'static str {
        match self {
            KernelKind::Uniform => "uniform",
            KernelKind::Hierarchical(_) => "hierarchical",
        }
    }
}

/// `kernel` as asked for, before a choice by size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KernelAsked {
    /// Chosen by size.
    Auto,
    /// [`KernelKind::Uniform`].
    Uniform,
    /// [`KernelKind::Hierarchical`] with the `root_size` and `link_tolerance` asked for.
    Hierarchical,
}

impl KernelAsked {
    /// `"auto"`, `"uniform"` or `"hierarchical"`; `"explicit"`, the old name of the
    /// uniform kernel, too.
    pub fn parse(name: &str) -> Option<KernelAsked> {
        match name {
            "auto" => Some(KernelAsked::Auto),
            "uniform" | "explicit" => Some(KernelAsked::Uniform),
            "hierarchical" => Some(KernelAsked::Hierarchical),
            _ => None,
        }
    }

    /// The name `kernel` gives it.
    pub fn name(&self) -> &'static str {
        match self {
            KernelAsked::Auto => "auto",
            KernelAsked::Uniform => "uniform",
            KernelAsked::Hierarchical => "hierarchical",
        }
    }
}

/// Where a value was asked for: a key of the case's `[discretization]` (as spelled there)
/// or a flag of the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// The key, as the case spells it.
    Key(&'static str),
    /// The flag, e.g. `--patch-size`.
    Flag(&'static str),
}

/// A value and where it was asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Given<T> {
    /// The value as given.
    pub value: T,
    /// Where it was given.
    pub origin: Origin,
}

impl<T> Given<T> {
    /// Values given by `key` of the case's `[discretization]`.
    pub fn key(key: &'static str) -> impl Fn(T) -> Given<T> {
        move |value| Given { value, origin: Origin::Key(key) }
    }

    /// Values given by the command line's `flag`.
    pub fn flag(flag: &'static str) -> impl Fn(T) -> Given<T> {
        move |value| Given { value, origin: Origin::Flag(flag) }
    }
}

/// What the case and the command line ask of the discretization; `None` leaves a value to
/// the other, then to its default.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Asked {
    /// The finest patches' edge, m.
    pub patch_size: Option<Given<f64>>,
    /// The hierarchy's roots' edge, m.
    pub root_size: Option<Given<f64>>,
    /// The hierarchy's error allowed per link (dimensionless).
    pub link_tolerance: Option<Given<f64>>,
    /// The hierarchy's most refinement passes.
    pub passes: Option<Given<usize>>,
    /// The kernel, or the choice by size.
    pub kernel: Option<Given<KernelAsked>>,
    /// Direction cells of every patch.
    pub directions: Option<Scheme>,
    /// Precision of the stored uniform `G`.
    pub precision: Option<Precision>,
    /// Largest kernel memory allowed, GiB.
    pub memory_limit: Option<Given<f64>>,
}

impl Asked {
    /// `self` with every value that `over` gives in its place.
    pub fn overridden_by(&self, over: &Asked) -> Asked {
        Asked {
            patch_size: over.patch_size.or(self.patch_size),
            root_size: over.root_size.or(self.root_size),
            link_tolerance: over.link_tolerance.or(self.link_tolerance),
            passes: over.passes.or(self.passes),
            kernel: over.kernel.or(self.kernel),
            directions: over.directions.or(self.directions),
            precision: over.precision.or(self.precision),
            memory_limit: over.memory_limit.or(self.memory_limit),
        }
    }

    /// The discretization asked for, checked, with the defaults; a kernel left to size
    /// chosen by `by_size` (given the patch size and directions). Errors name the key of
    /// `case` or the flag the value came from.
    pub(super) fn resolve(
        &self,
        case: &Path,
        by_size: impl FnOnce(f64, Scheme) -> (KernelKind, ChosenBySize),
    ) -> Result<Discretization, SceneError> {
        let at = Checker { case };
        let patch_size = self.patch_size.ok_or_else(|| at.error(Origin::Key("patch_size"), "is required"))?;
        let patch_size = at.positive(patch_size, "a length in metres")?;
        let directions = self.directions.unwrap_or(Scheme::Cells(1));
        let memory_limit = match self.memory_limit {
            Some(gib) => (at.positive(gib, "a number of GiB")? * (1u64 << 30) as f64) as u64,
            None => crate::kernel::memory::default_limit(),
        };
        let asked = self.kernel.map_or(KernelAsked::Auto, |k| k.value);
        // a kernel chosen by flag leaves the case's hierarchy keys aside; any other mix is refused
        let by_flag = matches!(self.kernel, Some(Given { origin: Origin::Flag(_), .. }));
        let stray = [self.root_size, self.link_tolerance]
            .into_iter()
            .flatten()
            .find(|given| !(by_flag && matches!(given.origin, Origin::Key(_))));
        if asked != KernelAsked::Hierarchical
            && let Some(given) = stray
        {
            let message = "applies only to the hierarchical kernel (kernel = \"hierarchical\", --kernel hierarchical)";
            return Err(at.error(given.origin, message));
        }
        let (kernel, chosen_by_size) = match asked {
            KernelAsked::Uniform => (KernelKind::Uniform, None),
            KernelAsked::Hierarchical => (KernelKind::Hierarchical(self.hierarchical(&at, patch_size)?), None),
            KernelAsked::Auto => {
                let (kernel, chosen) = by_size(patch_size, directions);
                (kernel, Some(chosen))
            }
        };
        let kernel = match (kernel, self.passes) {
            (KernelKind::Hierarchical(h), Some(_)) => {
                KernelKind::Hierarchical(Hierarchical { passes: self.passes(&at)?, ..h })
            }
            (KernelKind::Uniform, Some(given)) => {
                return Err(at.error(given.origin, "applies only to the hierarchical kernel (--kernel hierarchical)"));
            }
            (kernel, None) => kernel,
        };
        let precision = self.precision.unwrap_or_default();
        Ok(Discretization { patch_size, directions, kernel, precision, memory_limit, chosen_by_size })
    }

    /// The most refinement passes asked for (at least 1), else the default.
    fn passes(&self, at: &Checker) -> Result<usize, SceneError> {
        match self.passes {
            Some(given) if given.value == 0 => {
                Err(at.error(given.origin, "must be at least 1 (the initial linking is the first pass)"))
            }
            Some(given) => Ok(given.value),
            None => Ok(Hierarchical::DEFAULT_PASSES),
        }
    }

    /// `root_size`, `link_tolerance` and `passes`, checked against `patch_size`.
    fn hierarchical(&self, at: &Checker, patch_size: f64) -> Result<Hierarchical, SceneError> {
        let passes = self.passes(at)?;
        let root_size = match self.root_size {
            Some(given) => at.positive(given, "a length in metres")?,
            None => ROOTS * patch_size,
        };
        if let Some(given) = self.root_size.filter(|_| root_size < patch_size) {
            let message =
                format!("({root_size} m) must not be smaller than patch_size ({patch_size} m), the finest leaves");
            return Err(at.error(given.origin, message));
        }
        let Some(given) = self.link_tolerance else {
            return Ok(Hierarchical { root_size, link_tolerance: Hierarchical::DEFAULT_LINK_TOLERANCE, passes });
        };
        let link_tolerance = at.positive(given, "a number")?;
        if link_tolerance >= 1.0 {
            let message = format!(
                "must be below 1 (an error per link relative to the mean luminance), got {}",
                number(link_tolerance)
            );
            return Err(at.error(given.origin, message));
        }
        Ok(Hierarchical { root_size, link_tolerance, passes })
    }
}

impl Hierarchical {
    /// The link tolerance unless one is given (the hierarchy's own default).
    pub const DEFAULT_LINK_TOLERANCE: f64 = crate::kernel::hierarchy::DEFAULT_TOLERANCE;
    /// The most refinement passes unless a number is given (the hierarchy's own default).
    pub const DEFAULT_PASSES: usize = crate::kernel::hierarchy::DEFAULT_PASSES;

    /// The hierarchy with its default roots and tolerance over leaves of `patch_size`.
    pub fn over(patch_size: f64) -> Hierarchical {
        Hierarchical {
            root_size: ROOTS * patch_size,
            link_tolerance: Hierarchical::DEFAULT_LINK_TOLERANCE,
            passes: Hierarchical::DEFAULT_PASSES,
        }
    }
}

/// Errors that name the key in the case file or the flag.
struct Checker<'a> {
    case: &'a Path,
}

impl Checker<'_> {
    fn error(&self, origin: Origin, message: impl Into<String>) -> SceneError {
        match origin {
            Origin::Key(key) => SceneError::new(self.case, "[discretization]", key, message),
            Origin::Flag(flag) => SceneError::new(self.case, "", "", format!("{flag} {}", message.into())),
        }
    }

    /// A finite number greater than 0 (`what` it is, for the message).
    fn positive(&self, given: Given<f64>, what: &str) -> Result<f64, SceneError> {
        match given.value.is_finite() && given.value > 0.0 {
            true => Ok(given.value),
            false => {
                Err(self.error(given.origin, format!("must be {what} greater than 0, got {}", number(given.value))))
            }
        }
    }
}
