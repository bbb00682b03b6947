//! Direct solution of `(I − K) x = L0` by LU with partial pivoting (faer): dense up to
//! [`DENSE_MAX`] unknowns when at least [`DENSE_FILL`] of the matrix is non-zero, sparse LU
//! of the explicit matrix otherwise. faer's dense LU was
//! measured against nalgebra's with `ugo bench --lu` (`docs/experiments.md`). The memory
//! of the factors is checked before factoring: `8 n²` bytes dense; for the sparse LU its
//! fill-in is bounded by the same `8 n²`, which is what is checked. The factorization runs on
//! a thread of its own while the caller looks for a signal (`crate::interrupt`).

use super::algorithm::Algorithm;
use super::history::History;
use super::history::residual_norm;
use super::outcome::{SolveError, SolveInfo, SolveParams};
use super::range::OutOfRange;
use crate::kernel::Explicit;
use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Col, Mat};

/// The name of the thread that factors (as `/proc/PID/task/*/comm` shows it).
pub const FACTORIZATION_THREAD: &str = "ugo-lu";
/// How often a factorization's wait looks for a signal.
const POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// Above this many unknowns the LU is sparse.
pub const DENSE_MAX: usize = 8000;
/// Below this fraction of non-zeros the LU is sparse (measured with `ugo compare
/// --methods direct,direct-sparse`: dense 1.8× faster at 70 % fill, sparse 1.4× faster at
/// 8 %; `docs/solvers.md`).
pub const DENSE_FILL: f64 = 0.2;

/// Solves `x = L0 + K x` by LU of `I − K`; refuses (with the estimate) when the factors
/// could exceed `params.memory_limit` bytes. `progress` hears of the one solve.
pub fn direct(
    k: &Explicit,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let n = k.dim() as f64;
    let fill = k.0.nnz() as f64 / (n * n);
    lu(k, l0, params.memory_limit, k.dim() > DENSE_MAX || fill < DENSE_FILL, progress)
}

/// [`direct`] with the sparse LU whatever the size (to compare the two paths).
pub fn direct_sparse(
    k: &Explicit,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    lu(k, l0, params.memory_limit, true, progress)
}

fn lu(
    k: &Explicit,
    l0: &[f64],
    limit: u64,
    sparse: bool,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let n = k.dim();
    let method = if sparse { Algorithm::SparseLu } else { Algorithm::DenseLu };
    let mut history = History::start(method, l0)?;
    let need = 8.0 * (n as f64) * (n as f64) * 2.0;
    if need > limit as f64 {
        let gib = (1u64 << 30) as f64;
        return Err(SolveError::TooLarge(format!(
            "the LU factors of {n} unknowns could need {:.2} GiB, over the limit of {:.2} GiB; use GMRES \
             (matrix-free), a coarser patch_size or fewer direction cells",
            need / gib,
            limit as f64 / gib
        )));
    }
    let mut row_sums = vec![0.0; n];
    k.apply(&vec![1.0; n], &mut row_sums);
    if row_sums.iter().any(|v| !v.is_finite()) {
        let range = OutOfRange::of(method, None, "a row sum of K", f64::NAN, &row_sums);
        return Err(SolveError::OutOfRange(Box::new(range)));
    }
    let rhs = Col::<f64>::from_fn(n, |i| l0[i]);
    let x: Col<f64> = if !sparse {
        let mut a = Mat::<f64>::identity(n, n);
        for (i, row) in k.0.outer_iterator().enumerate() {
            for (j, &v) in row.iter() {
                a[(i, j)] -= v;
            }
        }
        on_its_own_thread("the dense LU", move || a.partial_piv_lu().solve(&rhs))?
    } else {
        let mut triplets: Vec<Triplet<usize, usize, f64>> = (0..n).map(|i| Triplet::new(i, i, 1.0)).collect();
        for (i, row) in k.0.outer_iterator().enumerate() {
            triplets.extend(row.iter().map(|(j, &v)| Triplet::new(i, j, -v)));
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &triplets)
            .map_err(|_| SolveError::TooLarge("cannot build the sparse matrix I − K".into()))?;
        let factored = on_its_own_thread("the sparse LU", move || a.sp_lu().map(|lu| lu.solve(&rhs)))?;
        factored.map_err(|_| SolveError::Breakdown {
            method: "sparse LU",
            iterations: 0,
            why: "the factorization failed (singular I − K?)",
        })?
    };
    let x: Vec<f64> = (0..n).map(|i| x[i]).collect();
    if x.iter().any(|v| !v.is_finite()) {
        // L0 and K are finite (checked above): a zero pivot.
        return Err(SolveError::Singular { method, growth: f64::INFINITY });
    }
    let mut scratch = vec![0.0; n];
    let residual = residual_norm(k, l0, &x, &mut scratch) / history.scale;
    history.record(residual, 1, &x)?;
    progress(1, residual);
    Ok((x, history.finish(0)))
}

/// Runs `work` (`what`, for a signal's message) on a thread of its own, named
/// [`FACTORIZATION_THREAD`], and waits for it, looking for a signal every [`POLL`]: faer's
/// factorizations cannot stop midway, so a signal leaves the thread to end with the process
/// instead of waiting the factorization out.
fn on_its_own_thread<T: Send + 'static>(
    what: &'static str,
    work: impl FnOnce() -> T + Send + 'static,
) -> Result<T, SolveError> {
    let spawned = std::thread::Builder::new().name(FACTORIZATION_THREAD.into()).spawn(work);
    let worker = spawned.map_err(|e| SolveError::NoThread { what, why: e.to_string() })?;
    while !worker.is_finished() {
        crate::interrupt::check(|| what.to_string())?;
        std::thread::sleep(POLL);
    }
    worker.join().map_err(|panic| std::panic::resume_unwind(panic))
}
