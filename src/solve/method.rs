//! The closed set of solvers, selected by name (`--method`, `--methods`), dispatched once.

use super::LinOp;
use super::algorithm::Algorithm;
use super::outcome::{SolveError, SolveInfo, SolveParams, norm};
use super::range::OutOfRange;
use super::{bicgstab, direct, direct_sparse, gauss_seidel, gmres, southwell, successive_approximation};
use crate::kernel::{Explicit, Factored, Kernel};

/// A method of `docs/design.md` §4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Successive approximation (reflection orders).
    Neumann,
    /// Gauss–Seidel sweeps on the explicit product `B·G`.
    GaussSeidel,
    /// Progressive refinement, one-cell case only.
    Southwell,
    /// Restarted GMRES(m).
    Gmres {
        /// Restart length `m`.
        restart: usize,
    },
    /// BiCGSTAB.
    Bicgstab,
    /// LU of `I − K`: dense up to `direct::DENSE_MAX` unknowns, sparse beyond.
    Direct,
    /// Sparse LU of `I − K` whatever the size.
    DirectSparse,
}

/// Default GMRES restart length.
pub const RESTART: usize = 30;

/// The methods by name (`gmres` also as `gmres:M` for a restart length `M`).
const BY_NAME: [(&str, Method); 8] = [
    ("neumann", Method::Neumann),
    ("successive", Method::Neumann),
    ("gauss-seidel", Method::GaussSeidel),
    ("southwell", Method::Southwell),
    ("gmres", Method::Gmres { restart: RESTART }),
    ("bicgstab", Method::Bicgstab),
    ("direct", Method::Direct),
    ("direct-sparse", Method::DirectSparse),
];

impl Method {
    /// All names `parse` accepts, for error messages.
    pub fn names() -> String {
        let names: Vec<&str> = BY_NAME.iter().map(|(name, _)| *name).collect();
        format!("{}, gmres:M", names.join(", "))
    }

    /// The method of a name of `--method` (`neumann`, …, `gmres:M`); `None` if unknown.
    pub fn parse(name: &str) -> Option<Method> {
        if let Some((_, method)) = BY_NAME.iter().find(|(n, _)| *n == name) {
            return Some(*method);
        }
        let m = name.strip_prefix("gmres:")?.parse::<usize>().ok().filter(|&m| m >= 1)?;
        Some(Method::Gmres { restart: m })
    }

    /// Short name for tables and files.
    pub fn name(&self) -> String {
        match self {
            Method::Neumann => "neumann".into(),
            Method::GaussSeidel => "gauss-seidel".into(),
            Method::Southwell => "southwell".into(),
            Method::Gmres { restart } => format!("gmres({restart})"),
            Method::Bicgstab => "bicgstab".into(),
            Method::Direct => "direct".into(),
            Method::DirectSparse => "direct-sparse".into(),
        }
    }

    /// True when the method needs the explicit product `B·G`.
    pub fn needs_explicit(&self) -> bool {
        matches!(self, Method::GaussSeidel | Method::Southwell | Method::Direct | Method::DirectSparse)
    }
}

/// The system `x = L0 + K x` as the methods need it.
pub struct System<'a> {
    /// `K` applied matrix-free (the factored operator, or a reduced one).
    pub operator: &'a dyn LinOp,
    /// The explicit matrix of the same operator, required when [`Method::needs_explicit`].
    pub explicit: Option<&'a Explicit>,
    /// The weight of each unknown for Southwell's choice of shooter: the patch areas of a
    /// one-cell (radiosity) system; empty where Southwell does not apply.
    pub areas: &'a [f64],
    /// The source term `L0`, cd/m².
    pub l0: &'a [f64],
}

impl<'a> System<'a> {
    /// The full angular system of `kernel` through its factored operator `factored`.
    pub fn of(
        kernel: &Kernel,
        factored: &'a Factored,
        explicit: Option<&'a Explicit>,
        areas: &'a [f64],
        l0: &'a [f64],
    ) -> Self {
        let areas = if kernel.cells() == 1 { areas } else { &[] };
        System { operator: factored, explicit, areas, l0 }
    }
}

/// Solves `system` with `method` (its GMRES restart given to the method in `params`). A zero
/// source (luminaires that light only black surfaces) has the exact solution `x = 0`,
/// returned without iterating.
pub fn solve(
    method: Method,
    system: &System,
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let System { operator, explicit, areas, l0 } = *system;
    if l0.iter().all(|&l| l == 0.0) {
        let info = SolveInfo {
            method: Algorithm::ZeroSource,
            iterations: 0,
            applications: 0,
            residual_history: vec![0.0],
            application_history: vec![0],
            time_history: vec![0.0],
            seconds: 0.0,
        };
        return Ok((vec![0.0; l0.len()], info));
    }
    let explicit = || explicit.ok_or(SolveError::Unsupported { method: "this method", needs: "the explicit kernel" });
    let (x, info) = match method {
        Method::Neumann => successive_approximation(operator, l0, params, progress)?,
        Method::GaussSeidel => gauss_seidel(explicit()?, l0, params, progress)?,
        Method::Southwell => southwell(explicit()?, areas, l0, params, progress)?,
        Method::Gmres { restart } => gmres(operator, l0, &SolveParams { restart, ..*params }, progress)?,
        Method::Bicgstab => bicgstab(operator, l0, params, progress)?,
        Method::Direct => direct(explicit()?, l0, params, progress)?,
        Method::DirectSparse => direct_sparse(explicit()?, l0, params, progress)?,
    };
    let size = norm(&x);
    if !size.is_finite() {
        let range = OutOfRange::of(info.method, Some(info.iterations), "the solution's norm ‖x‖₂", size, &x);
        return Err(SolveError::OutOfRange(Box::new(range)));
    }
    let growth = size / norm(l0);
    if growth.is_nan() || growth > MAX_GROWTH {
        return Err(SolveError::Singular { method: info.method, growth });
    }
    Ok((x, info))
}

/// `‖x‖/‖L0‖` beyond which `I − K` is taken as singular: no physical scene amplifies its
/// emission 10¹⁰ times, and double precision cannot resolve such a solution anyway.
const MAX_GROWTH: f64 = 1e10;
