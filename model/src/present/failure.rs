//! Why a command of `model` did not finish, and its exit code: bad input (exit 2, as for clap's
//! usage errors), an output that could not be written (exit 1), or stdout closed by its reader
//! (`| head`: a quiet end, like other Unix tools).

use crate::aircraft::Aircraft;
use std::path::Path;

/// Exit code for bad input (file, key or value), as for clap's usage errors.
pub const BAD_INPUT: u8 = 2;

/// Exit code of `emit --check` when outputs are stale, and of a requested output that could not
/// be written.
pub const FAILED: u8 = 1;

/// Why a command did not finish.
#[derive(Debug)]
pub enum Failure {
    /// Bad input: file, key or value (exit 2).
    Input(String),
    /// An output could not be written (exit 1).
    Output(String),
    /// stdout was closed by its reader (`| head`): end quietly, like other Unix tools.
    Closed,
}

impl From<String> for Failure {
    fn from(msg: String) -> Failure {
        Failure::Input(msg)
    }
}

/// A write to stdout failed.
pub fn stdout_error(e: std::io::Error) -> Failure {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        Failure::Closed
    } else {
        Failure::Output(format!("cannot write to stdout: {e}"))
    }
}

/// An error of a computation for `ac`, prefixed with its (escaped) name.
pub fn named(ac: &Aircraft, e: impl std::fmt::Display) -> Failure {
    Failure::Input(format!("{}: {e}", crate::aircraft::shown(&ac.name)))
}

/// Writes a requested output file (`--csv`): see [`crate::files::write_output`].
pub fn write_file(path: &Path, contents: &[u8]) -> Result<(), Failure> {
    crate::files::write_output(path, contents).map_err(|e| {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            // `--csv /dev/stdout | head`: as for stdout itself.
            Failure::Closed
        } else {
            Failure::Output(format!("cannot write {}: {e}", path.display()))
        }
    })
}
