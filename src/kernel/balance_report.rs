//! What balancing did to a kernel (`docs/design.md` §3, "Balancing"): the uniform kernel's
//! exchange areas (`uniform/balance.rs`) and the hierarchy's leaves (`hierarchy/balance.rs`)
//! report how far they moved in the same terms.

/// How far balancing moved the exchange areas.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BalanceReport {
    /// `max |D_r² − 1|`: the largest relative change of a row.
    pub max_correction: f64,
    /// Largest relative row-sum mismatch left, `max |(D T D 1)_r / target_r − 1|`.
    pub residual: f64,
    /// Gauss–Seidel sweeps spent.
    pub iterations: usize,
    /// True when every enclosed patch's cells carry exactly their projected solid angle
    /// (balanced by `(patch, cell)`); false when balanced by patch only.
    pub by_cell: bool,
}
