//! The `--out` folders of `clear`, `envelope`, `report` and `plot`: whole or absent when a run
//! is killed at a random moment of its write phase or two runs write into one folder at once;
//! `--out` checked before any work; every command that writes says what it wrote on stderr.

use super::{model, repo, scratch, stderr};
use model::random::Rng;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant, SystemTime};

/// Every file of `dir` (relative name, contents); `None` when `dir` does not exist.
fn snapshot(dir: &Path) -> Option<BTreeMap<String, Vec<u8>>> {
    let entries = std::fs::read_dir(dir).ok()?;
    let mut files = BTreeMap::new();
    for e in entries {
        let e = e.unwrap();
        let name = e.file_name().to_string_lossy().into_owned();
        let bytes = std::fs::read(e.path()).unwrap();
        let bytes = if name.ends_with(".md") {
            untimed(&String::from_utf8(bytes).unwrap()).into_bytes()
        } else {
            bytes
        };
        files.insert(name, bytes);
    }
    Some(files)
}

/// `text` with the proof's time (`N slabs, 0.31 s;`, the one number of a clearance's summary
/// that differs between two runs of the same command) replaced by `T`.
fn untimed(text: &str) -> String {
    let line = |l: &str| match l.find(" slabs, ").zip(l.find(" s;")) {
        Some((i, j)) if i + 8 <= j => format!("{}T{}", &l[..i + 8], &l[j..]),
        _ => l.to_string(),
    };
    text.lines().map(line).collect::<Vec<_>>().join("\n")
}

/// A `--out` folder's run written cleanly into a scratch folder, as the reference of a whole
/// run.
fn reference(args: &[&str], tag: &str) -> BTreeMap<String, Vec<u8>> {
    let dir = scratch(tag).join("out");
    let mut argv = args.to_vec();
    argv.extend(["--out", dir.to_str().unwrap()]);
    let out = model(&argv);
    assert!(out.status.success(), "{}", stderr(&out));
    snapshot(&dir).unwrap()
}

/// The run `args --out dir`, started.
fn spawn(args: &[&str], dir: &Path) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .args(["--out", dir.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

/// The regular files under `base` (any depth) with their modification times, but for the
/// marker of a folder `model` writes (its temporary folder is made before any work): when this
/// changes, a run has begun writing its outputs, wherever it puts them.
fn files_under(base: &Path) -> BTreeSet<(PathBuf, SystemTime)> {
    let mut found = BTreeSet::new();
    let mut stack = vec![base.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
            let Ok(meta) = e.metadata() else { continue };
            if meta.is_dir() {
                stack.push(e.path());
            } else if e.file_name() != ".model-output" {
                found.insert((e.path(), meta.modified().unwrap()));
            }
        }
    }
    found
}

/// The folder `dir` is absent or equal, file for file and byte for byte, to one of `runs`.
fn assert_whole(dir: &Path, runs: &[&BTreeMap<String, Vec<u8>>], what: &str) {
    if let Some(found) = snapshot(dir) {
        assert!(
            runs.iter().any(|r| **r == found),
            "{what}: a folder that is no whole run: {:?}",
            found.keys().collect::<Vec<_>>()
        );
    }
}

/// Two runs of a command whose folders differ, for the kill and concurrency checks: the
/// clearance of aircraft A's box with two seeds, and, with the JSBSim models installed, the
/// F-104's envelope over two grids (the probe).
fn pairs() -> Vec<(Vec<String>, Vec<String>)> {
    let a = repo("aircraft/a_uncertain.toml");
    let clear = |seed: &str| -> Vec<String> {
        ["clear", &a, "--samples", "50", "--seed", seed]
            .map(String::from)
            .to_vec()
    };
    let mut v = vec![(clear("1"), clear("2"))];
    if model::jsbsim::catalogue::root(None).is_some() {
        let env = |mach: &str| -> Vec<String> {
            ["envelope", "jsbsim:f104", "--altitude-m", "0:12000:12000"]
                .iter()
                .chain(&["--mach", mach])
                .map(|s| s.to_string())
                .collect()
        };
        v.push((env("0.3:0.6:0.3"), env("0.4:0.7:0.3")));
    } else {
        eprintln!("envelope part skipped: the JSBSim models are not installed");
    }
    v
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// Runs killed (SIGKILL, as a crash) at seeded random moments of their write phase, while
/// their folder holds the other run's files: the folder is always one whole run, and the next
/// run removes what the killed ones left beside it.
#[test]
fn a_run_killed_while_writing_leaves_a_whole_folder() {
    let mut rng = Rng::new(44);
    for (k, (first, second)) in pairs().iter().enumerate() {
        let (first, second) = (strs(first), strs(second));
        let refs = [
            &reference(&first, &format!("kill-ref1-{k}")),
            &reference(&second, &format!("kill-ref2-{k}")),
        ];
        assert_ne!(refs[0], refs[1], "the two runs must differ");
        let base = scratch(&format!("kill-{k}"));
        let dir = base.join("out");
        let mut killed_while_writing = 0;
        for trial in 0..10 {
            let args = if trial % 2 == 0 { &second } else { &first };
            let before = files_under(&base);
            let mut child = spawn(args, &dir);
            let start = Instant::now();
            while files_under(&base) == before && child.try_wait().unwrap().is_none() {
                assert!(start.elapsed() < Duration::from_secs(120), "no write phase");
                std::thread::sleep(Duration::from_micros(200));
            }
            std::thread::sleep(Duration::from_micros(rng.next_u64() % 40_000));
            if child.try_wait().unwrap().is_none() {
                killed_while_writing += 1;
            }
            let _ = child.kill();
            child.wait().unwrap();
            assert_whole(&dir, &refs, &format!("{} killed, trial {trial}", args[0]));
        }
        assert!(killed_while_writing > 0, "no run was killed while writing");
        let out = model(&[&first[..], &["--out", dir.to_str().unwrap()]].concat());
        assert!(out.status.success(), "{}", stderr(&out));
        assert_eq!(snapshot(&dir).as_ref(), Some(refs[0]));
        let left: Vec<_> = std::fs::read_dir(&base).unwrap().flatten().collect();
        assert_eq!(
            left.len(),
            1,
            "{:?}",
            left.iter().map(|e| e.file_name()).collect::<Vec<_>>()
        );
        println!(
            "{}: {killed_while_writing} of 10 runs killed while writing",
            first[0]
        );
    }
}

/// Two runs into one folder at the same moment: both succeed, and the folder is one of them,
/// whole, never a mix.
#[test]
fn two_runs_into_one_folder_leave_one_whole_run() {
    for (k, (first, second)) in pairs().iter().enumerate() {
        let (first, second) = (strs(first), strs(second));
        let refs = [
            &reference(&first, &format!("pair-ref1-{k}")),
            &reference(&second, &format!("pair-ref2-{k}")),
        ];
        let base = scratch(&format!("pair-{k}"));
        let dir = base.join("out");
        for trial in 0..8 {
            let mut a = spawn(&first, &dir);
            let mut b = spawn(&second, &dir);
            assert!(a.wait().unwrap().success() && b.wait().unwrap().success());
            assert_whole(&dir, &refs, &format!("{} trial {trial}", first[0]));
            assert!(dir.is_dir());
        }
        assert_eq!(
            std::fs::read_dir(&base).unwrap().count(),
            1,
            "only the folder"
        );
    }
}

/// `--out` that cannot be written is refused with exit 2 naming it, before any work: nothing
/// is printed (the answer is printed before the files are written), no folder appears.
#[test]
fn out_is_checked_before_any_work() {
    let base = scratch("out-check");
    let file = base.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let foreign = base.join("mine");
    std::fs::create_dir_all(&foreign).unwrap();
    std::fs::write(foreign.join("notes.txt"), "keep").unwrap();
    let read_only = base.join("read-only");
    std::fs::create_dir_all(&read_only).unwrap();
    let mut perms = std::fs::metadata(&read_only).unwrap().permissions();
    perms.set_readonly(true);
    std::fs::set_permissions(&read_only, perms).unwrap();
    let a = repo("aircraft/a_uncertain.toml");
    let cases: [(PathBuf, &str); 5] = [
        (file.clone(), "not a folder"),
        (file.join("sub"), "not a directory"),
        (foreign.clone(), "notes.txt"),
        (read_only.clone(), "read-only"),
        (read_only.join("sub"), "read-only"),
    ];
    for (dir, why) in &cases {
        let d = dir.to_str().unwrap();
        for args in [
            vec!["clear", &a, "--out", d],
            vec!["report", "B", "--out", d],
            vec!["plot", "A", "--out", d],
        ] {
            let out = model(&args);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            assert!(err.contains(d) && err.contains(why), "{args:?}: {err}");
            assert!(
                out.stdout.is_empty(),
                "{args:?}: work was done before the check"
            );
        }
    }
    assert_eq!(
        std::fs::read_to_string(foreign.join("notes.txt")).unwrap(),
        "keep"
    );
    assert_eq!(std::fs::read_dir(&read_only).unwrap().count(), 0);
    let mut perms = std::fs::metadata(&read_only).unwrap().permissions();
    #[allow(clippy::permissions_set_readonly_false)]
    perms.set_readonly(false);
    std::fs::set_permissions(&read_only, perms).unwrap();
    std::fs::remove_dir_all(&base).unwrap();
}

/// Each command that writes names on stderr each file or folder it wrote, one line apiece;
/// `report` and `plot` without `--out` write into `out/<command>-<aircraft>`.
#[test]
fn every_command_that_writes_says_what_it_wrote() {
    let base = scratch("wrote");
    let at = |name: &str| base.join(name).to_string_lossy().into_owned();
    let a = repo("aircraft/a_uncertain.toml");
    let runs: [(Vec<&str>, String); 5] = [
        (vec!["clear", &a, "--samples", "10", "--out"], at("clear")),
        (vec!["plot", "B", "--out"], at("plot")),
        (vec!["report", "B", "--out"], at("report")),
        (
            vec!["simulate", "A", "--delta-a-deg", "-5", "--csv"],
            at("sim.csv"),
        ),
        (vec!["continue", "A", "--csv"], at("cont.csv")),
    ];
    for (mut args, path) in runs {
        args.push(&path);
        let out = model(&args);
        let err = stderr(&out);
        assert!(out.status.success(), "{args:?}: {err}");
        let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("wrote ")).collect();
        assert_eq!(lines.len(), 1, "{args:?}: {err}");
        assert!(
            lines[0].starts_with(&format!("wrote {path}: ")),
            "{}",
            lines[0]
        );
        assert!(Path::new(&path).exists());
    }
    // The default folder, relative to the working directory.
    let out = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["plot", "B"])
        .current_dir(&base)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).starts_with("wrote out/plot-b: 21 files: 7 figures"),
        "{}",
        stderr(&out)
    );
    assert!(base.join("out/plot-b/fig01_bifurcation.png").is_file());
    std::fs::remove_dir_all(&base).unwrap();
}
