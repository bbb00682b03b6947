//! The memory-bound figures: a STREAM-like triad (`a = b + s·c`, 24 bytes per element)
//! giving the machine's attainable bandwidth, and the solver's products timed, the sparse
//! product in bytes of matrix traffic per second (values, column indices and row pointers:
//! `Transport::bytes`) to set against it.

use crate::kernel::Transport;
use crate::solve::LinOp;
use rayon::prelude::*;
use std::time::Instant;

/// Elements per triad array (3 × 256 MiB: far beyond any cache).
const TRIAD: usize = 1 << 25;

/// Best-of-`repeats` seconds of `f`.
fn best(repeats: usize, mut f: impl FnMut()) -> f64 {
    (0..repeats)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The triad's bandwidth, bytes/s (best of 5, all threads).
pub fn triad() -> f64 {
    let b = vec![1.0f64; TRIAD];
    let c = vec![2.0f64; TRIAD];
    let mut a = vec![0.0f64; TRIAD];
    let seconds = best(5, || {
        a.par_chunks_mut(1 << 16).zip(b.par_chunks(1 << 16)).zip(c.par_chunks(1 << 16)).for_each(|((a, b), c)| {
            a.iter_mut().zip(b).zip(c).for_each(|((a, b), c)| *a = b + 3.0 * c);
        })
    });
    std::hint::black_box(&a);
    24.0 * TRIAD as f64 / seconds
}

/// The sparse product `y = G x` of a stored `G`, timed.
#[derive(Debug, Clone, Copy)]
pub struct SparseProduct {
    /// Seconds per product (best of 10).
    pub seconds: f64,
    /// Bytes of matrix traffic per second.
    pub bytes_per_second: f64,
}

/// Times `y = G x`.
pub fn sparse_product(g: &Transport) -> SparseProduct {
    let seconds = product_seconds(g.rows(), |x, y| g.apply(x, y));
    SparseProduct { seconds, bytes_per_second: g.bytes() / seconds }
}

/// Seconds per application of an operator (best of 10).
pub fn apply_seconds(op: &dyn LinOp) -> f64 {
    product_seconds(op.dim(), |x, y| op.apply(x, y))
}

/// Seconds per `y = A x` of `n` unknowns (best of 10), `x` all ones.
fn product_seconds(n: usize, apply: impl Fn(&[f64], &mut [f64])) -> f64 {
    let x = vec![1.0; n];
    let mut y = vec![0.0; n];
    best(10, || apply(&x, &mut y))
}
