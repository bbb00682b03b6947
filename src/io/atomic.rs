//! The one way ugo writes an output file: to a temporary name beside it, checked, then
//! renamed over it, so that a reader (or a crash, a full disk, a second `ugo` writing the
//! same path) never sees a half-written file and a failed write leaves the previous file
//! byte for byte.
//!
//! * The temporary name is unique to the process and the call,
//!   `<name>.<pid>.<nonce>.tmp`: two processes writing the same path each write their own
//!   file and the later rename wins whole.
//! * Every write is checked by the writer; then the file is flushed to the disk
//!   (`fsync`, which reports a delayed `EIO`/`ENOSPC`/`EFBIG`) and reopened in its format
//!   (HDF5 is opened again, which refuses a truncated file; PNG and EXR headers are
//!   read) before the rename.
//! * A failure removes the temporary file, and is told in plain words when the disk is
//!   full or the file-size limit was reached (`io::no_room`, which also keeps SIGXFSZ from
//!   killing the process mid-write). Temporary files of processes that are no
//!   longer running (killed, out of power) are removed by the next write of the same path.
//! * A stop asked for by a signal (`crate::interrupt`) is checked before the write and
//!   again before the rename: the temporary file is removed and the target left as it
//!   was. While it is written the temporary is held for a second signal's immediate stop,
//!   which removes it too.

use super::IoError;
use crate::interrupt::Temporary;
use std::ffi::OsString;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Runs `write` on a fresh temporary name beside `path`, verifies the file and renames it
/// to `path`; removes the temporary file when any step fails or a stop is asked for.
pub fn atomic(path: &Path, write: impl FnOnce(&Path) -> Result<(), String>) -> Result<(), IoError> {
    remove_stale(path);
    let stopped = |during: &str| {
        crate::interrupt::requested(|| during.to_string())
            .map(|stop| IoError::Interrupted { path: path.to_path_buf(), stop })
    };
    if let Some(e) = stopped("the work before it") {
        return Err(e);
    }
    let tmp = temporary(path);
    let held = Temporary::hold(&tmp);
    let done = write(&tmp).and_then(|()| verify(&tmp));
    if let Some(e) = stopped("its writing") {
        let _ = std::fs::remove_file(&tmp);
        return Err(e);
    }
    let done = done
        .and_then(|()| std::fs::rename(&tmp, path).map_err(|e| format!("cannot rename {} to it: {e}", tmp.display())));
    drop(held);
    match done {
        Ok(()) => {
            // The rename itself reaches the disk with the folder's entry.
            if let Ok(folder) = std::fs::File::open(folder(path)) {
                let _ = folder.sync_all();
            }
            Ok(())
        }
        Err(why) => {
            let why = super::no_room::plain(&tmp, why);
            let _ = std::fs::remove_file(&tmp);
            Err(IoError::write(path, why))
        }
    }
}

/// [`atomic`] for a PNG drawn by plotters, which picks the format from the name's
/// extension: `draw` writes `<name>.<pid>.<nonce>.tmp.png`, renamed on success.
pub fn atomic_png(path: &Path, draw: impl FnOnce(&Path) -> Result<(), String>) -> Result<(), IoError> {
    atomic(path, |tmp| {
        let png = tmp.with_extension("tmp.png");
        let _held = Temporary::hold(&png);
        let done = draw(&png).and_then(|()| std::fs::rename(&png, tmp).map_err(|e| e.to_string()));
        if done.is_err() {
            let _ = std::fs::remove_file(&png);
        }
        done
    })
}

/// [`atomic`] for a file written as a stream: `body` writes through a buffer, flushed and
/// checked before the rename.
pub fn atomic_stream(
    path: &Path,
    body: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<(), IoError> {
    atomic(path, |tmp| {
        let mut w = std::io::BufWriter::new(std::fs::File::create(tmp).map_err(|e| e.to_string())?);
        body(&mut w).and_then(|()| std::io::Write::flush(&mut w)).map_err(|e| e.to_string())
    })
}

/// `<name>.<pid>.<nonce>.tmp` beside `path`.
pub fn temporary(path: &Path) -> PathBuf {
    static CALLS: AtomicU64 = AtomicU64::new(0);
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos() as u64);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let nonce = crate::random::Rng::stream(nanos, call).next_u64() & 0xffff_ffff;
    let mut name = path.file_name().map_or_else(OsString::new, |n| n.to_owned());
    name.push(format!(".{}.{nonce:08x}.tmp", std::process::id()));
    path.with_file_name(name)
}

fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Removes `<name>.<pid>.<nonce>.tmp…` beside `path` left by processes that no longer run
/// (known from `/proc`; nothing is removed where there is no `/proc`).
pub fn remove_stale(path: &Path) {
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else { return };
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(folder(path)) else { return };
    for entry in entries.flatten() {
        let file = entry.file_name();
        let Some(rest) = file.to_str().and_then(|f| f.strip_prefix(name)).and_then(|r| r.strip_prefix('.')) else {
            continue;
        };
        let mut parts = rest.splitn(3, '.');
        let (Some(pid), Some(nonce), Some(tail)) = (parts.next(), parts.next(), parts.next()) else { continue };
        let ours = pid.parse::<u32>().is_ok()
            && nonce.len() == 8
            && nonce.bytes().all(|b| b.is_ascii_hexdigit())
            && (tail == "tmp" || tail.starts_with("tmp."));
        if ours && !Path::new("/proc").join(pid).exists() {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

const HDF5: &[u8] = b"\x89HDF\r\n\x1a\n";
const PNG: &[u8] = b"\x89PNG\r\n\x1a\n";
const EXR: &[u8] = &[0x76, 0x2f, 0x31, 0x01];

/// Flushes `tmp` to the disk and reopens it in its format.
fn verify(tmp: &Path) -> Result<(), String> {
    let mut file = std::fs::File::open(tmp).map_err(|e| format!("cannot reopen {}: {e}", tmp.display()))?;
    file.sync_all().map_err(|e| format!("cannot flush {} to the disk: {e}", tmp.display()))?;
    let mut head = Vec::with_capacity(8);
    file.by_ref().take(8).read_to_end(&mut head).map_err(|e| format!("cannot read {} back: {e}", tmp.display()))?;
    let broken = |e: &dyn std::fmt::Display| format!("the file written does not read back ({e})");
    if head.starts_with(HDF5) {
        // Opening checks the superblock against the file's size: a file cut short by a
        // full disk or a size limit is refused here (h5dump would refuse it too).
        let h5 = hdf5::File::open(tmp).map_err(|e| broken(&e))?;
        h5.member_names().map_err(|e| broken(&e))?;
        h5.close().map_err(|e| broken(&e))?;
    } else if head.starts_with(PNG) {
        ::image::ImageReader::open(tmp)
            .and_then(|r| r.with_guessed_format())
            .map_err(|e| broken(&e))?
            .into_dimensions()
            .map_err(|e| broken(&e))?;
    } else if head.starts_with(EXR) {
        exr::meta::MetaData::read_from_file(tmp, false).map_err(|e| broken(&e))?;
    }
    Ok(())
}
