//! Memory-bound parts of `ugo bench`: a STREAM-like triad (`a = b + s·c`, 24 bytes per
//! element) giving the machine's attainable bandwidth, and the sparse products of the
//! solver measured in bytes of matrix traffic per second (values, column indices and row
//! pointers: `Transport::bytes`) against it.

use rayon::prelude::*;
use std::time::Instant;
use ugo::kernel::Transport;
use ugo::solve::LinOp;

/// Elements per triad array (3 × 256 MiB: far beyond any cache).
const TRIAD: usize = 1 << 25;

/// Best-of-`repeats` seconds of `f`.
pub fn best(repeats: usize, mut f: impl FnMut()) -> f64 {
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

/// Seconds per `y = G x` (best of 10).
pub fn spmv_seconds(g: &Transport) -> f64 {
    let x = vec![1.0; g.rows()];
    let mut y = vec![0.0; g.rows()];
    best(10, || g.apply(&x, &mut y))
}

/// Seconds per application of an operator (best of 10).
pub fn apply_seconds(op: &dyn LinOp) -> f64 {
    let x = vec![1.0; op.dim()];
    let mut y = vec![0.0; op.dim()];
    best(10, || op.apply(&x, &mut y))
}
