//! The hand-written source tree as the architecture tests read it: every Rust file below a
//! folder, build output, git's folder, hidden folders and `generated/` left out. Shared by
//! `tidy.rs` and `layers.rs`.

use std::path::{Path, PathBuf};

/// Appends every `.rs` file below `dir` to `out`.
pub fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable source tree") {
        let path = entry.expect("directory entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if path.is_dir() {
            if !matches!(name, "target" | ".git" | "generated") && !name.starts_with('.') {
                rust_files(&path, out);
            }
        } else if name.ends_with(".rs") {
            out.push(path);
        }
    }
}
