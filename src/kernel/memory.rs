//! Memory of the kernel: bytes per stored non-zero and per pair in assembly, the default
//! limit (half the machine's RAM), and the [`Footprint`] of a matrix about to be formed
//! (the hierarchy's links after a pass, the explicit product `B·G`), which
//! `super::refusal` checks against the limit.

/// Bytes per stored non-zero of a CSR matrix (f64 value, usize column index).
pub const BYTES_PER_NONZERO: u64 = 16;
/// Transient bytes per unordered pair during assembly (row work plus symmetric rows).
pub(super) const ASSEMBLY_BYTES_PER_PAIR: f64 = (24 + 2 * 16) as f64;

/// Half of the memory the process may take: the least of the machine's physical memory
/// (`/proc/meminfo`), its control group's limit (`memory.max`, cgroup v2, or
/// `memory.limit_in_bytes`, v1) and its address space (`ulimit -v`, "Max address space" of
/// `/proc/self/limits`); 8 GiB where none is known. Half, because the limit bounds the
/// kernel's forecast, and the mesh, the solver's vectors and the threads' stacks take
/// their share besides.
pub fn default_limit() -> u64 {
    let read = |path: &str| std::fs::read_to_string(path).ok();
    let physical = read("/proc/meminfo").and_then(|s| physical_memory(&s));
    let group = read("/sys/fs/cgroup/memory.max").or_else(|| read("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    let address_space = read("/proc/self/limits").and_then(|s| address_space_limit(&s));
    let least = [physical, group.and_then(|s| cgroup_limit(&s)), address_space].into_iter().flatten().min();
    least.map_or(8 << 30, |bytes| bytes / 2)
}

/// `MemTotal` of `/proc/meminfo`, bytes.
pub fn physical_memory(meminfo: &str) -> Option<u64> {
    let kib = meminfo.lines().find(|l| l.starts_with("MemTotal:"))?.split_whitespace().nth(1)?.parse::<u64>().ok()?;
    Some(kib * 1024)
}

/// A control group's memory limit, bytes (`None` for `max`, unlimited).
pub fn cgroup_limit(text: &str) -> Option<u64> {
    text.trim().parse().ok()
}

/// The soft limit of "Max address space" in `/proc/self/limits`, bytes (`None` when
/// unlimited).
pub fn address_space_limit(limits: &str) -> Option<u64> {
    let line = limits.lines().find(|l| l.starts_with("Max address space"))?;
    line["Max address space".len()..].split_whitespace().next()?.parse().ok()
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
