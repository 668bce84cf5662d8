//! File output, the one place for it: a result file is either complete or absent, never
//! half-written; devices and FIFOs are written straight into; a set of files (the generated
//! crate) is replaced all at once or not at all; temporary files of killed runs are removed by
//! the next run.
//!
//! Temporary files are named `.NAME.tmp-PID-N[.EXT]` next to their target `NAME` (PID: the
//! writing process). A run that writes into a folder first removes every such file there of a
//! process that no longer exists, whatever its target: a killed `report` leaves megabytes of
//! figure temporaries that the next `simulate --csv` into that folder removes.
//!
//! ```
//! use model::files::write_atomic;
//!
//! // A new file in a new directory, then replaced whole; no temporary file is left beside it.
//! let dir = std::env::temp_dir().join(format!("model-files-doc-{}", std::process::id()));
//! let path = dir.join("out").join("result.csv");
//! write_atomic(&path, b"p0,det_k\n").unwrap();
//! write_atomic(&path, b"p0,det_k\n1.7,0\n").unwrap();
//! assert_eq!(std::fs::read(&path).unwrap(), b"p0,det_k\n1.7,0\n");
//! assert_eq!(std::fs::read_dir(path.parent().unwrap()).unwrap().count(), 1);
//! std::fs::remove_dir_all(&dir).unwrap();
//! ```

pub mod folder;

use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `contents` to `path` as a user asked for it on the command line (`--csv FILE`):
///
/// * a regular file or a new name: atomically ([`write_atomic`]);
/// * a symbolic link: atomically to the file it points to (the link stays a link);
/// * a device, FIFO or socket (`/dev/stdout`, `/dev/null`, a named pipe): written straight
///   into, never replaced; an error of the device (`/dev/full`: no space left) is returned.
pub fn write_output(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    match std::fs::metadata(path) {
        Ok(m) if !m.is_file() && !m.is_dir() => {
            let mut f = std::fs::OpenOptions::new().write(true).open(path)?;
            f.write_all(contents)?;
            f.flush()
        }
        _ => write_atomic(&resolve_links(path)?, contents),
    }
}

/// The file a chain of symbolic links ends at (the path itself when it is no link), also when
/// that file does not exist yet.
fn resolve_links(path: &Path) -> std::io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(std::io::Error::other(format!(
        "{}: too many levels of symbolic links",
        path.display()
    )))
}

/// `std::fs::create_dir_all`, saying what is wrong when `dir` is an existing file (the OS only
/// says "File exists").
pub fn create_dir_all(dir: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| {
        if e.kind() == std::io::ErrorKind::AlreadyExists && !dir.is_dir() {
            std::io::Error::new(e.kind(), "it exists and is not a directory")
        } else {
            e
        }
    })
}

/// Writes `contents` to `path` through a temporary file in the same directory and a rename,
/// creating the directory if needed; an existing file keeps its permissions. On any error the
/// temporary file is removed and `path` keeps its previous contents (or stays absent).
/// Temporary files that killed runs left in `path`'s folder are removed first.
pub fn write_atomic(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    if let Some(dir) = parent(path) {
        create_dir_all(dir)?;
    }
    remove_stale_temporaries_in(parent(path).unwrap_or(Path::new(".")));
    let tmp = temp_path(path, "");
    let result = stage(&tmp, path, contents).and_then(|()| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes and syncs `tmp`, with the permissions of `target` if it exists.
fn stage(tmp: &Path, target: &Path, contents: &[u8]) -> std::io::Result<()> {
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(tmp)?;
    f.write_all(contents)?;
    f.sync_all()?;
    if let Ok(m) = std::fs::metadata(target) {
        std::fs::set_permissions(tmp, m.permissions())?;
    }
    Ok(())
}

fn parent(path: &Path) -> Option<&Path> {
    path.parent().filter(|d| !d.as_os_str().is_empty())
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// A fresh temporary path next to `target`: `.NAME.tmp-PID-N` followed by `suffix` (e.g.
/// `.png`, for writers that pick the format from the extension).
pub fn temp_path(target: &Path, suffix: &str) -> PathBuf {
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    target.with_file_name(format!(
        ".{}.tmp-{}-{n}{suffix}",
        file_name(target),
        std::process::id()
    ))
}

/// Whether process `pid` exists. Where this cannot be told (no `/proc`), every other process
/// counts as gone.
fn alive(pid: u32) -> bool {
    pid == std::process::id()
        || (Path::new("/proc/self").exists() && Path::new(&format!("/proc/{pid}")).exists())
}

/// Removes the temporary files `.NAME.tmp-PID...` of `target` = `NAME` whose process PID no
/// longer exists (left by a killed run); returns how many were removed.
pub fn remove_stale_temporaries(target: &Path) -> usize {
    let dir = parent(target).unwrap_or(Path::new("."));
    remove_stale(dir, &format!(".{}.tmp-", file_name(target)))
}

/// Removes every temporary file `.NAME.tmp-PID...` in `dir` whose process PID no longer exists
/// (for a folder of outputs, some of which the next run may not write again); returns how
/// many were removed.
pub fn remove_stale_temporaries_in(dir: &Path) -> usize {
    remove_stale(dir, ".")
}

fn remove_stale(dir: &Path, prefix: &str) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let mut removed = 0;
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if !name.starts_with(prefix) {
            continue;
        }
        let Some((_, rest)) = name.rsplit_once(".tmp-") else {
            continue;
        };
        let pid: String = rest.chars().take_while(char::is_ascii_digit).collect();
        if let Ok(pid) = pid.parse::<u32>() {
            if !alive(pid) && e.path().is_file() && std::fs::remove_file(e.path()).is_ok() {
                removed += 1;
            }
        }
    }
    removed
}

/// Replaces a set of files under `root` all at once: every file is staged to a temporary name
/// first; then a journal `root/journal` listing the renames is written atomically (the commit
/// point); then the renames are made and the journal removed. A run killed before the journal
/// exists leaves every old file in place (its temporaries are removed by the next run); one
/// killed after it is finished by [`recover`], which every writer of the set calls first.
/// `files` holds paths relative to `root` and their contents.
pub fn replace_all(root: &Path, journal: &str, files: &[(PathBuf, &[u8])]) -> std::io::Result<()> {
    recover(root, journal, files.iter().map(|(p, _)| p.as_path()))?;
    let mut staged: Vec<(PathBuf, PathBuf)> = Vec::new();
    let result = (|| {
        for (rel, contents) in files {
            let path = root.join(rel);
            if let Some(dir) = parent(&path) {
                create_dir_all(dir)?;
            }
            let tmp = temp_path(&path, "");
            staged.push((tmp.clone(), path.clone()));
            stage(&tmp, &path, contents)?;
        }
        let mut list = String::new();
        for (tmp, path) in &staged {
            let rel = |p: &Path| p.strip_prefix(root).unwrap_or(p).display().to_string();
            list += &format!("{}\t{}\n", rel(tmp), rel(path));
        }
        write_atomic(&root.join(journal), list.as_bytes())
    })();
    if let Err(e) = result {
        for (tmp, _) in &staged {
            let _ = std::fs::remove_file(tmp);
        }
        return Err(e);
    }
    finish(root, journal)
}

/// Finishes a [`replace_all`] that was killed after its commit point (renames the staged files
/// listed in `root/journal`, removes the journal), then removes stale temporaries of `files`
/// (relative to `root`).
pub fn recover<'a>(
    root: &Path,
    journal: &str,
    files: impl IntoIterator<Item = &'a Path>,
) -> std::io::Result<()> {
    if root.join(journal).exists() {
        finish(root, journal)?;
    }
    for f in files {
        remove_stale_temporaries(&root.join(f));
    }
    remove_stale_temporaries(&root.join(journal));
    Ok(())
}

fn finish(root: &Path, journal: &str) -> std::io::Result<()> {
    let path = root.join(journal);
    let list = std::fs::read_to_string(&path)?;
    for line in list.lines() {
        let Some((tmp, target)) = line.split_once('\t') else {
            continue;
        };
        let tmp = root.join(tmp);
        if tmp.exists() {
            std::fs::rename(&tmp, root.join(target))?;
        }
    }
    std::fs::remove_file(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn temp_dir(tag: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("files-test-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    pub(super) fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn writes_whole_files_and_leaves_no_temporary_behind() {
        let dir = temp_dir("whole");
        let path = dir.join("sub").join("out.txt");
        write_atomic(&path, b"first").unwrap();
        write_atomic(&path, b"second").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"second");
        assert_eq!(
            names(path.parent().unwrap()),
            ["out.txt"],
            "only the file itself"
        );
        // A path whose parent is a file cannot be written; nothing is left behind.
        assert!(write_atomic(&path.join("x"), b"no").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn temporaries_of_dead_processes_are_removed_by_the_next_write_into_their_folder() {
        let dir = temp_dir("stale");
        let path = dir.join("out.csv");
        // PID 0 and PIDs above the kernel's limit (2^22) belong to no process.
        let dead = [".out.csv.tmp-4194305", ".out.csv.tmp-4194306-3.png"];
        for d in dead {
            std::fs::write(dir.join(d), b"partial").unwrap();
        }
        // One of another file (a killed report's figure) goes too; one of a live process
        // (this one) is kept.
        let live = format!(".out.csv.tmp-{}-99", std::process::id());
        std::fs::write(dir.join(&live), b"in progress").unwrap();
        std::fs::write(dir.join(".fig01.png.tmp-4194305-1.png"), b"x").unwrap();
        write_atomic(&path, b"data").unwrap();
        assert_eq!(names(&dir), [live.clone(), "out.csv".to_string()]);
        assert_eq!(remove_stale_temporaries_in(&dir), 0);
        // The sweep of one target's temporaries keeps those of other files.
        std::fs::write(dir.join(".other.csv.tmp-4194305"), b"x").unwrap();
        std::fs::write(dir.join(".out.csv.tmp-4194305"), b"x").unwrap();
        assert_eq!(remove_stale_temporaries(&path), 1);
        assert_eq!(remove_stale_temporaries_in(&dir), 1);
        assert_eq!(names(&dir), [live, "out.csv".to_string()]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn output_follows_symlinks_and_writes_into_devices() {
        let dir = temp_dir("links");
        let target = dir.join("target.csv");
        std::fs::write(&target, b"old").unwrap();
        let link = dir.join("link.csv");
        std::os::unix::fs::symlink("target.csv", &link).unwrap();
        write_output(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
        // A dangling link: the file is created where it points.
        let dangling = dir.join("dangling.csv");
        std::os::unix::fs::symlink("made.csv", &dangling).unwrap();
        write_output(&dangling, b"made").unwrap();
        assert_eq!(std::fs::read(dir.join("made.csv")).unwrap(), b"made");
        // Devices are written into, never replaced; their errors are reported.
        write_output(Path::new("/dev/null"), b"nothing").unwrap();
        assert!(!std::fs::metadata("/dev/null").unwrap().is_file());
        if Path::new("/dev/full").exists() {
            assert!(write_output(Path::new("/dev/full"), b"x").is_err());
            assert!(!std::fs::metadata("/dev/full").unwrap().is_file());
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_set_is_replaced_whole_and_a_committed_journal_is_finished() {
        let dir = temp_dir("set");
        let files = [
            (PathBuf::from("a.txt"), b"new a".as_slice()),
            (PathBuf::from("sub/b.txt"), b"new b".as_slice()),
        ];
        replace_all(&dir, ".journal", &files).unwrap();
        assert_eq!(std::fs::read(dir.join("sub/b.txt")).unwrap(), b"new b");
        assert_eq!(names(&dir), ["a.txt", "sub"]);
        // A run killed after its commit point: one file renamed, one still staged.
        std::fs::write(dir.join("a.txt"), b"newer a").unwrap();
        std::fs::write(dir.join("sub/.b.txt.tmp-4194305-0"), b"newer b").unwrap();
        std::fs::write(
            dir.join(".journal"),
            "a-gone\ta.txt\nsub/.b.txt.tmp-4194305-0\tsub/b.txt\n",
        )
        .unwrap();
        recover(&dir, ".journal", files.iter().map(|(p, _)| p.as_path())).unwrap();
        assert_eq!(std::fs::read(dir.join("sub/b.txt")).unwrap(), b"newer b");
        assert_eq!(names(&dir), ["a.txt", "sub"]);
        assert_eq!(names(&dir.join("sub")), ["b.txt"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
