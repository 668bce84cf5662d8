//! The command-line tool end to end, as a user runs it: `analyze` (analyze.rs), the other
//! commands (commands.rs), what they write and how they fail (files.rs), their `--out`
//! folders (folders.rs), the JSBSim import of a small model (jsbsim.rs), the 6-DOF
//! (six_dof.rs), and the README's first screen and the outputs the README and the user's guide
//! show (readme.rs).

use std::path::PathBuf;
use std::process::{Command, Output};

#[path = "../support/mod.rs"]
mod support;

mod analyze;
mod answers;
mod commands;
mod envelope_speed;
mod files;
mod folders;
mod jsbsim;
mod options;
mod readme;
mod six_dof;

use support::{json, model, reference};

fn repo(path: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(path)
        .to_string_lossy()
        .into_owned()
}

/// A file with `text` in a temporary folder.
fn scratch_file(name: &str, text: &str) -> PathBuf {
    let path = scratch(&format!("convert-{name}")).join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Aircraft A's file with some values replaced, written to a temporary folder.
fn variant(tag: &str, replace: &[(&str, &str)]) -> (PathBuf, PathBuf) {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut text = std::fs::read_to_string(repo("aircraft/a.toml")).unwrap();
    for (from, to) in replace {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let path = dir.join(format!("{tag}.toml"));
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

/// A fresh temporary folder for one test.
fn scratch(tag: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// `model args` killed after `limit`: `Some(output)` when it ended in time, `None` on a hang.
fn model_within(args: &[&str], limit: std::time::Duration) -> Option<Output> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while start.elapsed() < limit {
        if child.try_wait().unwrap().is_some() {
            return Some(child.wait_with_output().unwrap());
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    None
}
