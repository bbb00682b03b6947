//! One run at a time per output path (issue 37, point 7): two solves writing one
//! `OUT.h5` would each rename their files over the other's, and the winner's HDF5 file
//! could end beside the other run's CSV and PNG files. A run takes [`OutputLock`] on its
//! output before any work, an advisory lock (`flock`) on `OUT.h5.lock` beside it, and a
//! second run is refused at once naming the path. The lock file is removed when the run
//! ends; one left by a process that was killed holds no lock and is taken over.

use super::IoError;
use std::fs::{File, OpenOptions, TryLockError};
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};

/// The lock of one output path, held until dropped.
#[derive(Debug)]
pub struct OutputLock {
    path: PathBuf,
    _file: File,
}

impl OutputLock {
    /// Takes the lock of `output`, or refuses when another process holds it.
    pub fn take(output: &Path) -> Result<OutputLock, IoError> {
        let mut name = output.file_name().unwrap_or_default().to_owned();
        name.push(".lock");
        let path = output.with_file_name(name);
        // A holder that ends between our open and our lock unlinks the file we opened:
        // lock again until the locked file is the one at the path.
        loop {
            let file = OpenOptions::new()
                .create(true)
                .truncate(false)
                .write(true)
                .open(&path)
                .map_err(|e| IoError::write(&path, e))?;
            match file.try_lock() {
                Ok(()) => {}
                Err(TryLockError::WouldBlock) => return Err(IoError::Busy { path: output.to_path_buf(), lock: path }),
                Err(TryLockError::Error(e)) => return Err(IoError::write(&path, e)),
            }
            let held = file.metadata().map_err(|e| IoError::write(&path, e))?;
            if std::fs::metadata(&path).is_ok_and(|now| now.ino() == held.ino() && now.dev() == held.dev()) {
                return Ok(OutputLock { path, _file: file });
            }
        }
    }
}

impl Drop for OutputLock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}
