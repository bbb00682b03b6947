//! Any bytes (text, JSON, raw arrays) written as one file through the atomic writer: a
//! failed or interrupted write leaves the previous file as it was.

use super::{IoError, atomic};
use std::io::Write;
use std::path::Path;

/// Writes `data` to `path`, atomically (`io::atomic`).
pub fn write_bytes(path: &Path, data: &[u8]) -> Result<(), IoError> {
    atomic(path, |tmp| {
        let mut file = std::fs::File::create(tmp).map_err(|e| e.to_string())?;
        file.write_all(data).map_err(|e| e.to_string())
    })
}
