//! Peak resident memory of one stretch of work: the kernel's high-water mark (`VmHWM`)
//! reset before it and read after it, less the resident size before it. Linux only;
//! elsewhere, or where the reset is not allowed, there is no figure.

/// A stretch of work whose peak memory is measured.
pub struct Peak {
    /// Resident bytes before the stretch, when the high-water mark could be reset.
    before: Option<f64>,
}

impl Peak {
    /// Starts measuring: resets the high-water mark (Linux `clear_refs` 5).
    pub fn start() -> Peak {
        let before = status("VmRSS:");
        Peak { before: before.filter(|_| reset()) }
    }

    /// Bytes above the resident size at the start, at the peak since; `None` when the
    /// high-water mark could not be reset.
    pub fn bytes(&self) -> Option<f64> {
        status("VmHWM:").zip(self.before).map(|(peak, before)| (peak - before).max(0.0))
    }
}

/// Resets this process's peak-RSS counter; false when the system does not support it
/// (the peak then stays above the resident size).
fn reset() -> bool {
    std::fs::write("/proc/self/clear_refs", "5").is_ok()
        && status("VmHWM:").zip(status("VmRSS:")).is_some_and(|(peak, now)| peak <= now + 4.0 * 1024.0 * 1024.0)
}

/// A `kB` line (`VmHWM:`, `VmRSS:`) of this process's status, bytes.
fn status(key: &str) -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(key))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024.0)
}
