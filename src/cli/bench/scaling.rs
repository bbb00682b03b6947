//! The uniform kernel's scaling curve of `ugo bench`, printed: time against the number of
//! patches with the fitted exponent, and per patch size the pairs, non-zeros, assembly and
//! solve time and peak memory.

use ugo::study::bench::Scaling;

/// The curve as a table.
pub fn print(curve: &Scaling) {
    say!("  scaling (assemble + solve, Neumann to 1e-8), time ∝ N^{:.2}", curve.exponent);
    say!(
        "    {:>10} {:>9} {:>11} {:>11} {:>10} {:>9} {:>11}",
        "patch m",
        "patches",
        "pairs",
        "non-zeros",
        "assembly s",
        "solve s",
        "+peak MiB"
    );
    for s in &curve.steps {
        let peak = s.peak_bytes.map_or("-".into(), |b| format!("{:.0}", b / (1u64 << 20) as f64));
        say!(
            "    {:>10.4} {:>9} {:>11} {:>11} {:>10.2} {:>9.3} {:>11}",
            s.patch_size,
            s.patches,
            s.pairs,
            s.nonzeros,
            s.assembly_seconds,
            s.solve_seconds,
            peak
        );
    }
}
