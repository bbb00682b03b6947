//! The files a case names besides itself (OBJ and glTF meshes, glTF buffers, photometric
//! files): read once while validating, kept with the scene, and written into every solution
//! file, so that a stored solution is read back (and rendered) even after those files are
//! moved or deleted.

use std::cell::RefCell;
use std::path::{Path, PathBuf};

/// One file as read: the path it was named by (joined to the case file's folder), its bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseFile {
    /// The path it was named by, joined to the case file's folder.
    pub path: PathBuf,
    /// Its contents.
    pub bytes: Vec<u8>,
}

/// Where validation reads the files a case names: the disk, or copies stored in a solution
/// file (the disk for any file without a copy). Every file read is recorded.
#[derive(Debug, Default)]
pub struct CaseFiles {
    stored: Vec<CaseFile>,
    read: RefCell<Vec<CaseFile>>,
}

impl CaseFiles {
    /// Reading from the disk.
    pub fn disk() -> CaseFiles {
        CaseFiles::default()
    }

    /// Reading the stored copies first.
    pub fn stored(files: Vec<CaseFile>) -> CaseFiles {
        CaseFiles { stored: files, read: RefCell::new(Vec::new()) }
    }

    /// The bytes of `path`, recorded.
    pub fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        let bytes = match self.stored.iter().find(|f| f.path == path) {
            Some(f) => f.bytes.clone(),
            None => {
                regular_file(path)?;
                std::fs::read(path)?
            }
        };
        let mut read = self.read.borrow_mut();
        if !read.iter().any(|f| f.path == path) {
            read.push(CaseFile { path: path.to_path_buf(), bytes: bytes.clone() });
        }
        Ok(bytes)
    }

    /// Every file read, in the order first read.
    pub fn into_read(self) -> Vec<CaseFile> {
        self.read.into_inner()
    }
}

/// Refuses to read anything but a regular file: a named pipe would block the reader
/// forever (until some writer opens it), a device could stream without end.
pub fn regular_file(path: &Path) -> std::io::Result<()> {
    let kind = std::fs::metadata(path)?.file_type();
    if kind.is_file() {
        return Ok(());
    }
    let what = if kind.is_dir() { "a folder" } else { "not a regular file (a named pipe, socket or device)" };
    Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, format!("it is {what}")))
}
