//! A write that runs out of room, told in plain words (issue 37, point 7): the disk full
//! (`ENOSPC`) or the process's file-size limit reached (`EFBIG`, `ulimit -f`).
//!
//! By default the kernel kills a process that writes past its file-size limit with
//! SIGXFSZ, before the writer can remove its temporary file; [`survive_size_limit`] catches
//! the signal instead, so the write fails with `EFBIG` and `io::atomic` cleans up. The HDF5
//! library quotes these failures in its own words (`"File too large"`, `"addr overflow"`,
//! several lines deep); [`plain`] replaces them with what happened and the limit.

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// `strerror(ENOSPC)`, as the HDF5 library and `std::io::Error` quote it.
const DISK_FULL: &str = "No space left on device";
/// `strerror(EFBIG)`.
const TOO_LARGE: &str = "File too large";

/// Catches SIGXFSZ for the rest of the process, so that a write past the file-size limit
/// fails with `EFBIG` instead of killing the process.
pub fn survive_size_limit() -> std::io::Result<()> {
    signal_hook::flag::register(signal_hook::consts::SIGXFSZ, Arc::new(AtomicBool::new(false))).map(|_| ())
}

/// The process's file-size limit in bytes (`Max file size` of `/proc/self/limits`), if
/// there is one.
fn size_limit() -> Option<u64> {
    let limits = std::fs::read_to_string("/proc/self/limits").ok()?;
    let line = limits.lines().find(|l| l.starts_with("Max file size"))?;
    line.split_whitespace().nth(3)?.parse().ok()
}

/// `why` a write of `tmp` failed, in plain words when it ran out of room: the disk is full,
/// or the file reached the size limit; otherwise `why` as it was.
pub fn plain(tmp: &Path, why: String) -> String {
    if why.contains(DISK_FULL) {
        return "the disk is full (no space left on the device); free some space or write elsewhere".to_string();
    }
    let written = std::fs::metadata(tmp).map_or(0, |m| m.len());
    match size_limit() {
        Some(limit) if why.contains(TOO_LARGE) || written >= limit => format!(
            "the file-size limit was reached ({limit} bytes, `ulimit -f`): the file needs more; raise the limit \
             or write a smaller model"
        ),
        _ => why,
    }
}
