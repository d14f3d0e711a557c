//! Writing a file safely: into a new file beside the target, synced, then renamed over it, so
//! that a failed or interrupted save never leaves a half-written file or loses an older one.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// A save that failed, with the path it was for.
#[derive(Debug)]
pub struct SaveError {
    pub path: PathBuf,
    pub error: io::Error,
}

impl std::fmt::Display for SaveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot save {}: {}", self.path.display(), self.error)
    }
}

impl std::error::Error for SaveError {}

/// Writes `path` through `write`, atomically.
///
/// The old file (if any) stays whole until the new one is complete.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> Result<(), SaveError> {
    let failed = |error| SaveError {
        path: path.to_owned(),
        error,
    };
    let name = path.file_name().ok_or_else(|| {
        failed(io::Error::new(
            io::ErrorKind::InvalidInput,
            "not a file name",
        ))
    })?;
    let mut partial_name = std::ffi::OsString::from(".");
    partial_name.push(name);
    partial_name.push(format!(".{}.partial", std::process::id()));
    let partial = path.with_file_name(partial_name);
    let result = File::create(&partial).and_then(|mut file| {
        write(&mut file)?;
        file.flush()?;
        file.sync_all()?;
        fs::rename(&partial, path)
    });
    if let Err(error) = result {
        // Nothing half-written is left behind; the old file was never touched.
        let _ = fs::remove_file(&partial);
        return Err(failed(error));
    }
    Ok(())
}
