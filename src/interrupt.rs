//! A stop asked for from outside the process: SIGINT (Ctrl-C) or SIGTERM (issue 18,
//! item 8).
//!
//! The first signal is only noted. The long loops poll it — the uniform kernel's rows
//! (`kernel::assemble`), the hierarchy's refinement passes (`model`), every solver's
//! iterations (`solve`) — and so does the output writer (`io::atomic`) before it renames a
//! file: each ends with [`Interrupted`], so that the command removes its temporary files,
//! leaves the previous outputs as they were, says what it has not written and exits with
//! `128 +` the signal's number (130 for SIGINT, 143 for SIGTERM). A second signal stops at
//! once, for work that does not poll (a direct LU factorization, a render): the temporary
//! files being written (held by a [`Temporary`]) are removed and the process exits with the
//! same status.
//!
//! Loops that return no `Result` (a render's pixels, the tracers' rows, chunks and paths, the
//! readouts' probes and grid points) skip the rest of their work once [`asked`] is true and
//! return what they have: the caller that owns the stage ends it with [`check`] before the
//! result is used, so nothing partial is printed or written (issue 37, point 6).
//!
//! Nothing is installed until [`install`] is called: the command line does; a library
//! caller keeps the default handlers, and [`requested`] stays `None`.

use signal_hook::consts::{SIGINT, SIGTERM};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicI32, Ordering};
use thiserror::Error;

/// The first signal received, 0 before any.
static SIGNAL: AtomicI32 = AtomicI32::new(0);
/// The temporary files being written, removed by a second signal's stop.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Work stopped because a signal asked for it.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("interrupted by {} during {during}", signal_name(*.signal))]
pub struct Interrupted {
    /// The signal's number (`SIGINT`, `SIGTERM`).
    pub signal: i32,
    /// What was stopped (`"the assembly of G"`, `"GMRES, iteration 12"`).
    pub during: String,
}

impl Interrupted {
    /// The process's exit status after the stop: `128 +` the signal's number.
    pub fn exit_status(&self) -> u8 {
        exit_status(self.signal)
    }
}

/// The name of a signal this module handles.
pub fn signal_name(signal: i32) -> &'static str {
    match signal {
        SIGINT => "SIGINT",
        SIGTERM => "SIGTERM",
        _ => "a signal",
    }
}

fn exit_status(signal: i32) -> u8 {
    u8::try_from(128 + signal).unwrap_or(1)
}

/// Handles SIGINT and SIGTERM for the rest of the process: the first is noted for
/// [`requested`], a second stops at once (see the module's documentation).
pub fn install() -> std::io::Result<()> {
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM])?;
    std::thread::Builder::new().name("signals".into()).spawn(move || {
        for signal in signals.forever() {
            if SIGNAL.compare_exchange(0, signal, Ordering::SeqCst, Ordering::SeqCst).is_err() {
                stop_now(signal);
            }
        }
    })?;
    Ok(())
}

/// The second signal: the temporary files removed, the process ended without unwinding
/// (the main thread may be inside the HDF5 library).
fn stop_now(signal: i32) -> ! {
    let temporaries = TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner());
    for path in temporaries.iter() {
        let _ = std::fs::remove_file(path);
    }
    eprintln!(
        "ugo: stopped at once by a second {}: {} temporary file(s) removed, nothing more written; \
         previous files are left as they were",
        signal_name(signal),
        temporaries.len()
    );
    signal_hook::low_level::exit(i32::from(exit_status(signal)))
}

/// The stop asked for, if any, with what it interrupts.
pub fn requested(during: impl FnOnce() -> String) -> Option<Interrupted> {
    match SIGNAL.load(Ordering::Relaxed) {
        0 => None,
        signal => Some(Interrupted { signal, during: during() }),
    }
}

/// Whether a stop has been asked for (see the module's documentation for the loops that
/// poll it).
pub fn asked() -> bool {
    SIGNAL.load(Ordering::Relaxed) != 0
}

/// `Err` when a stop has been asked for; `during` names the work it interrupts.
pub fn check(during: impl FnOnce() -> String) -> Result<(), Interrupted> {
    requested(during).map_or(Ok(()), Err)
}

/// A temporary file being written: removed by a second signal's stop while this lives.
pub struct Temporary {
    path: PathBuf,
}

impl Temporary {
    /// Registers `path`.
    pub fn hold(path: &Path) -> Temporary {
        TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner()).push(path.to_path_buf());
        Temporary { path: path.to_path_buf() }
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        let mut temporaries = TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = temporaries.iter().position(|p| *p == self.path) {
            temporaries.swap_remove(i);
        }
    }
}
