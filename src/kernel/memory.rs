//! Memory of the kernel: bytes per stored non-zero and per pair in assembly, the default
//! limit (half the machine's RAM), and the [`Footprint`] of a matrix about to be formed
//! (the hierarchy's links after a pass, the explicit product `B·G`), which
//! `super::refusal` checks against the limit.

/// Bytes per stored non-zero of a CSR matrix (f64 value, usize column index).
pub const BYTES_PER_NONZERO: u64 = 16;
/// Transient bytes per unordered pair during assembly (row work plus symmetric rows).
pub(super) const ASSEMBLY_BYTES_PER_PAIR: f64 = (24 + 2 * 16) as f64;

/// Half of the machine's physical memory (from `/proc/meminfo`), or 8 GiB where unknown.
pub fn default_limit() -> u64 {
    let total_kib = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("MemTotal:"))?.split_whitespace().nth(1)?.parse::<u64>().ok());
    total_kib.map_or(8 << 30, |k| k * 1024 / 2)
}

/// What a stored matrix would hold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footprint {
    /// What the matrix is, as the refusal names it.
    pub what: &'static str,
    /// Bytes it would take.
    pub bytes: f64,
    /// Non-zeros it would hold.
    pub nonzeros: f64,
    /// Patches of the mesh.
    pub patches: usize,
    /// Direction cells per patch.
    pub cells: usize,
}
