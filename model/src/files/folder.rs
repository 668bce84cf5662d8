//! A folder of outputs (`--out DIR` of `envelope`, `clear`, `report`, `plot`) that is whole or
//! absent: its files are written into a temporary sibling `.DIR.tmp-PID-N` (same parent, so
//! the final rename is atomic), and only when every file is there does the folder take `DIR`'s
//! place: the previous run's folder is renamed away to `.DIR.old-PID-N`, the new one renamed
//! in, the old one deleted. Ctrl-C, a crash or a second run at the same moment therefore never
//! leaves a folder that mixes two runs or lacks files: a reader sees the old run's folder, the
//! new one, or (between the two renames) none. A killed run's temporary and old folders are
//! removed by the next run into the same `DIR`.
//!
//! Because `DIR` is replaced whole, only a folder that a run of `model` wrote (it holds the
//! marker file [`MARKER`]) or an empty one is replaced; any other existing folder is refused,
//! so that `--out .` or `--out ~` can never delete a user's files.
//!
//! ```
//! use model::files::folder::Staged;
//!
//! let dir = std::env::temp_dir().join(format!("model-folder-doc-{}", std::process::id()));
//! let out = dir.join("run");
//! for text in ["first", "second"] {
//!     let staged = Staged::begin(&out, "doc").unwrap(); // checked before any work
//!     std::fs::write(staged.path().join("a.txt"), text).unwrap();
//!     staged.commit().unwrap();
//! }
//! assert_eq!(std::fs::read_to_string(out.join("a.txt")).unwrap(), "second");
//! // Nothing but the folder itself is left beside it.
//! assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
//! std::fs::remove_dir_all(&dir).unwrap();
//! ```

use super::{alive, create_dir_all, file_name, parent, resolve_links, temp_path};
use std::io::{Error, ErrorKind};
use std::path::{Path, PathBuf};

/// The file inside every folder a run of `model` writes; its text names the command. A folder
/// holding it may be replaced by the next run.
pub const MARKER: &str = ".model-output";

/// A folder being written: files go into [`Staged::path`]; [`Staged::commit`] puts the folder
/// in place whole. Dropped without a commit, the temporary folder is removed and `DIR` keeps
/// its previous contents.
#[derive(Debug)]
pub struct Staged {
    target: PathBuf,
    tmp: PathBuf,
    committed: bool,
}

impl Staged {
    /// Checks that `target` can be written (a folder name, its parent creatable and writable,
    /// `target` itself absent, or a writable folder that is empty or was written by `model`),
    /// creates the parent and the temporary folder, and removes what killed runs into `target`
    /// left. `command` (e.g. `envelope`) is written into the marker. The error names the path
    /// and what is wrong with it.
    pub fn begin(target: &Path, command: &str) -> Result<Staged, String> {
        let target = resolve_links(target).map_err(|e| format!("{}: {e}", target.display()))?;
        let bad = |why: &str| format!("--out {}: {why}", target.display());
        if target.file_name().is_none() {
            return Err(bad(
                "expected the name of a folder to write (not `.`, `..` or `/`)",
            ));
        }
        match std::fs::metadata(&target) {
            Ok(m) if !m.is_dir() => {
                return Err(bad(
                    "it exists and is not a folder; expected a folder to write",
                ))
            }
            Ok(m) if m.permissions().readonly() => return Err(bad("the folder is read-only")),
            Ok(_) => replaceable(&target).map_err(|e| bad(&e))?,
            Err(_) => {}
        }
        let dir = parent(&target).unwrap_or(Path::new("."));
        create_dir_all(dir).map_err(|e| bad(&format!("cannot create {}: {e}", dir.display())))?;
        if std::fs::metadata(dir).is_ok_and(|m| m.permissions().readonly()) {
            return Err(bad(&format!("its parent {} is read-only", dir.display())));
        }
        remove_stale_folders(&target);
        let tmp = temp_path(&target, "");
        std::fs::create_dir(&tmp)
            .and_then(|()| std::fs::write(tmp.join(MARKER), format!("{command}\n")))
            .map_err(|e| {
                let _ = std::fs::remove_dir_all(&tmp);
                bad(&format!("cannot write in {}: {e}", dir.display()))
            })?;
        Ok(Staged {
            target,
            tmp,
            committed: false,
        })
    }

    /// The temporary folder to write the files into.
    pub fn path(&self) -> &Path {
        &self.tmp
    }

    /// The folder the files end up in.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Puts the written folder in `target`'s place: the previous folder (if any) is renamed
    /// away, the new one renamed in, the previous one deleted. When another run puts its folder
    /// in place between the two renames, that one is renamed away too and this run's wins. On
    /// an error the previous folder is put back.
    pub fn commit(mut self) -> std::io::Result<()> {
        let mut olds = Vec::new();
        let mut result = Ok(());
        for _ in 0..100 {
            let old = old_path(&self.target);
            match std::fs::rename(&self.target, &old) {
                Ok(()) => olds.push(old),
                Err(e) if e.kind() == ErrorKind::NotFound => {}
                Err(e) => {
                    result = Err(e);
                    break;
                }
            }
            result = std::fs::rename(&self.tmp, &self.target);
            match &result {
                Err(e) if taken(e) => continue,
                _ => break,
            }
        }
        self.committed = result.is_ok();
        if !self.committed {
            // The previous folder goes back where it was.
            if let Some(last) = olds.pop() {
                let _ = std::fs::rename(last, &self.target);
            }
        }
        for old in olds {
            let _ = std::fs::remove_dir_all(old);
        }
        result
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.tmp);
        }
    }
}

/// Whether renaming failed because a folder took the target's place (another run's).
fn taken(e: &Error) -> bool {
    matches!(
        e.kind(),
        ErrorKind::AlreadyExists | ErrorKind::DirectoryNotEmpty
    )
}

/// A fresh name for the previous folder of `target`: `.NAME.old-PID-N`.
fn old_path(target: &Path) -> PathBuf {
    let tmp = temp_path(target, "");
    let name = file_name(&tmp).replacen(".tmp-", ".old-", 1);
    tmp.with_file_name(name)
}

/// `Ok` when the existing folder `dir` may be replaced: empty, or written by `model`.
fn replaceable(dir: &Path) -> Result<(), String> {
    let mut entries = std::fs::read_dir(dir).map_err(|e| e.to_string())?;
    if dir.join(MARKER).is_file() {
        return Ok(());
    }
    match entries.next() {
        None => Ok(()),
        Some(e) => Err(format!(
            "the folder exists and holds files `model` did not write (e.g. {}); it would be \
             replaced whole: name a new or empty folder, or remove this one",
            e.map(|e| e.file_name().to_string_lossy().into_owned())
                .unwrap_or_default()
        )),
    }
}

/// Removes the temporary and old folders `.NAME.tmp-PID-N` and `.NAME.old-PID-N` of `target`
/// whose process no longer exists; returns how many were removed.
pub fn remove_stale_folders(target: &Path) -> usize {
    let dir = parent(target).unwrap_or(Path::new("."));
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let name = file_name(target);
    let mut removed = 0;
    for e in entries.flatten() {
        let entry = e.file_name().to_string_lossy().into_owned();
        let rest = [".tmp-", ".old-"]
            .iter()
            .find_map(|kind| entry.strip_prefix(&format!(".{name}{kind}")));
        let Some(rest) = rest else { continue };
        let pid: String = rest.chars().take_while(char::is_ascii_digit).collect();
        let dead = pid.parse::<u32>().is_ok_and(|pid| !alive(pid));
        if dead && e.path().is_dir() && std::fs::remove_dir_all(e.path()).is_ok() {
            removed += 1;
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::files::tests::{names, temp_dir};

    #[test]
    fn an_uncommitted_folder_leaves_the_previous_one_untouched() {
        let dir = temp_dir("folder-drop");
        let out = dir.join("out");
        let s = Staged::begin(&out, "test").unwrap();
        std::fs::write(s.path().join("a"), "1").unwrap();
        s.commit().unwrap();
        let s = Staged::begin(&out, "test").unwrap();
        std::fs::write(s.path().join("b"), "2").unwrap();
        drop(s);
        assert_eq!(names(&out), [MARKER, "a"]);
        assert_eq!(names(&dir), ["out"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn folders_of_killed_runs_are_removed_and_foreign_folders_refused() {
        let dir = temp_dir("folder-stale");
        let out = dir.join("out");
        // PIDs above the kernel's limit (2^22) belong to no process.
        for d in [".out.tmp-4194305-0", ".out.old-4194306-1"] {
            std::fs::create_dir_all(dir.join(d).join("sub")).unwrap();
        }
        std::fs::create_dir_all(dir.join(".other.tmp-4194305-0")).unwrap();
        Staged::begin(&out, "test").unwrap().commit().unwrap();
        assert_eq!(names(&dir), [".other.tmp-4194305-0", "out"]);
        // A folder of the user's own files is never replaced.
        let mine = dir.join("mine");
        std::fs::create_dir_all(&mine).unwrap();
        std::fs::write(mine.join("notes.txt"), "keep").unwrap();
        let e = Staged::begin(&mine, "test").unwrap_err();
        assert!(e.contains("notes.txt") && e.contains("mine"), "{e}");
        let file = dir.join("file");
        std::fs::write(&file, "x").unwrap();
        let e = Staged::begin(&file, "test").unwrap_err();
        assert!(e.contains("not a folder"), "{e}");
        assert!(Staged::begin(&file.join("sub"), "test").is_err());
        assert!(Staged::begin(Path::new("."), "test").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
