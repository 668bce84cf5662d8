//! Where a command's files go, and what it says about them. One rule for every command:
//! `--out DIR` names the folder a command writes its files into (`report`, `plot`, `envelope`,
//! `clear`); a command that writes exactly one file names it (`import --out FILE`, `simulate
//! --csv FILE`, `continue --csv FILE`). `report` and `plot`, whose only product is files,
//! write into `out/<command>-<aircraft>/` without `--out`; `envelope` and `clear` print their
//! answer and write files only when asked. A folder is checked writable before any work and
//! appears whole or not at all ([`crate::files::folder`]); each command says on stderr what it
//! wrote, one line per file or folder.

use super::failure::Failure;
use crate::files::folder::{Staged, MARKER};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The folder `command` writes into for `aircraft` without `--out`: `out/<command>-<name>`,
/// `<name>` the built-in's letter, a file's stem or a JSBSim model's name, in lower case.
pub fn default_folder(command: &str, aircraft: &str) -> PathBuf {
    let name = match aircraft.strip_prefix("jsbsim:") {
        Some(rest) => rest.split_whitespace().next().unwrap_or(""),
        None => Path::new(aircraft)
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or(""),
    };
    let slug: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect();
    Path::new("out").join(format!("{command}-{slug}"))
}

/// `--out DIR` checked and its temporary folder made, before any work: a bad `DIR` is bad
/// input (exit 2), named.
pub fn begin_folder(dir: &Path, command: &str) -> Result<Staged, Failure> {
    Staged::begin(dir, command).map_err(Failure::Input)
}

/// Puts the written folder in place and says so on stderr, one line: the folder and what is in
/// it.
pub fn commit_folder(staged: Staged) -> Result<(), Failure> {
    let what = contents(staged.path());
    let target = staged.target().to_path_buf();
    staged
        .commit()
        .map_err(|e| Failure::Output(format!("cannot write {}: {e}", target.display())))?;
    wrote(&target, &what);
    Ok(())
}

/// Says on stderr that `path` was written, with `what` it holds.
pub fn wrote(path: &Path, what: &str) {
    eprintln!("wrote {}: {what}", path.display());
}

/// What a folder of outputs holds, in a few words: its plain files by name, then its figures
/// (stems with more than one of SVG, PNG and CSV) counted.
fn contents(dir: &Path) -> String {
    let mut stems: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let entries = std::fs::read_dir(dir).into_iter().flatten().flatten();
    for e in entries {
        let name = e.file_name().to_string_lossy().into_owned();
        if name == MARKER {
            continue;
        }
        let (stem, ext) = name.rsplit_once('.').unwrap_or((&name, ""));
        stems
            .entry(stem.to_string())
            .or_default()
            .push(ext.to_string());
    }
    let mut files = Vec::new();
    let mut figures = 0;
    let mut formats = std::collections::BTreeSet::new();
    let mut count = 0;
    for (stem, exts) in &stems {
        count += exts.len();
        if exts.iter().any(|e| e == "svg" || e == "png") {
            figures += 1;
            formats.extend(exts.iter().map(|e| e.to_uppercase()));
        } else {
            files.extend(exts.iter().map(|e| format!("{stem}.{e}")));
        }
    }
    if figures > 0 {
        let formats: Vec<String> = formats.into_iter().collect();
        files.push(format!(
            "{figures} figure{} ({} each)",
            if figures == 1 { "" } else { "s" },
            formats.join(", ")
        ));
    }
    format!("{count} files: {}", files.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_folders_are_named_after_the_command_and_the_aircraft() {
        let f = |c, a| default_folder(c, a).display().to_string();
        assert_eq!(f("report", "A"), "out/report-a");
        assert_eq!(f("plot", "aircraft/c.toml"), "out/plot-c");
        assert_eq!(
            f("report", "jsbsim:f104 --altitude-m 6096 --mach 0.5"),
            "out/report-f104"
        );
        assert_eq!(f("plot", "out/F 16.toml"), "out/plot-f-16");
    }
}
