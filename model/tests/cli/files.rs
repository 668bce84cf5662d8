//! What the commands write and how they fail: closed pipes, devices and symlinks, files that
//! cannot be written, colour off a terminal, an emit killed midway, degenerate aircraft.

use super::*;

#[test]
fn degenerate_aircraft_give_errors_or_partial_reports_never_panics() {
    // C D = 0 (the P0^4 coefficient of det A): det A is only quadratic in P0.
    // D = 0 makes E = C for a rigid body.
    let (dir, cd0) = variant(
        "cd0",
        &[("D = 0.786", "D = 0.0"), ("E = 0.705", "E = 0.959")],
    );
    let out = model(&["analyze", cd0.to_str().unwrap(), "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rep = model(&[
        "report",
        cd0.to_str().unwrap(),
        "--out",
        dir.join("r").to_str().unwrap(),
    ]);
    assert!(
        rep.status.success(),
        "{}",
        String::from_utf8_lossy(&rep.stderr)
    );

    // No rudder authority: no zero-sideslip schedule; the rest of the report still appears.
    let (dir2, ndr0) = variant("ndr0", &[("n_delta_r = -1.0", "n_delta_r = 0.0")]);
    let sim = model(&[
        "simulate",
        ndr0.to_str().unwrap(),
        "--delta-a-deg",
        "-5",
        "--zero-sideslip",
    ]);
    assert_eq!(sim.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&sim.stderr).contains("n_delta_r"));
    let rep = model(&[
        "report",
        ndr0.to_str().unwrap(),
        "--out",
        dir2.join("r").to_str().unwrap(),
    ]);
    assert!(
        rep.status.success(),
        "{}",
        String::from_utf8_lossy(&rep.stderr)
    );
    let md = std::fs::read_to_string(dir2.join("r/summary.md")).unwrap();
    assert!(
        md.contains("Not computed for this aircraft") && md.contains("Fig. 9"),
        "{md}"
    );
    assert!(md.contains("fig01_bifurcation.png"));

    // No roll damping, stiffness or coupling: det J5 vanishes along the whole trim curve. (E = 0
    // needs C = D for a rigid body.)
    let (dir3, flat) = variant(
        "flat",
        &[
            ("E = 0.705", "E = 0.0"),
            ("C = 0.959", "C = 0.786"),
            ("l_p = -21.7529", "l_p = 0.0"),
            ("l_r = 1.5207", "l_r = 0.0"),
            ("l_beta = -110.45", "l_beta = 0.0"),
        ],
    );
    let out = model(&["analyze", flat.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("vanishes identically"));

    let out = model(&["analyze", "A", "--delta-e-deg", "1e308"]);
    assert_eq!(out.status.code(), Some(2));
    for d in [dir, dir2, dir3] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[cfg(unix)]
#[test]
fn stdout_write_errors_end_quietly_on_a_closed_pipe_and_loudly_otherwise() {
    use std::process::Stdio;
    // /dev/full: one line naming stdout and the OS error, exit 1, no panic.
    let full = std::fs::File::create("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["analyze", "A"])
        .stdout(full)
        .output()
        .unwrap();
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("stdout") && err.contains("os error 28"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    // A reader that has gone (`| head -1` after its line): quiet, exit 0.
    let mut child = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["continue", "B", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stderr(&out), "");
}

#[cfg(unix)]
#[test]
fn csv_goes_into_devices_and_through_symlinks_and_failures_are_reported() {
    let dir = scratch("csv-targets");
    let sim = |csv: &str| {
        model(&[
            "simulate",
            "A",
            "--delta-a-deg",
            "-5",
            "--t-end",
            "2",
            "--csv",
            csv,
        ])
    };
    let out = sim("/dev/full");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("/dev/full"), "{}", stderr(&out));
    assert!(
        !std::fs::metadata("/dev/full").unwrap().is_file(),
        "device kept"
    );
    // /dev/stdout: the rows arrive on stdout, and /dev/stdout stays what it was.
    let out = sim("/dev/stdout");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("t_s,alpha_rad"));
    assert!(std::fs::symlink_metadata("/dev/stdout")
        .unwrap()
        .file_type()
        .is_symlink());
    // A symlink: its target gets the rows, the link stays a link.
    let target = dir.join("target.csv");
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let out = sim(link.to_str().unwrap());
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read_to_string(&target)
        .unwrap()
        .starts_with("t_s,"));
    // A directory in the way: named, exit 1.
    let out = sim(dir.to_str().unwrap());
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("cannot write"), "{}", stderr(&out));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An old run's folder, whatever it holds (a directory where a figure goes, temporaries of a
/// killed run), is replaced whole by the next run; a temporary folder of a killed run beside it
/// is removed.
#[test]
fn plot_replaces_an_old_runs_folder_whole() {
    let base = scratch("plot-replace");
    let dir = base.join("figs");
    std::fs::create_dir_all(dir.join("fig07_det_k.png")).unwrap();
    std::fs::write(dir.join(".model-output"), "plot\n").unwrap();
    std::fs::write(dir.join(".fig01_bifurcation.svg.tmp-4194305-0"), "half").unwrap();
    std::fs::write(dir.join("summary.md"), "an old report's summary").unwrap();
    // A killed run's temporary folder (no process has PID 4194305).
    std::fs::create_dir_all(base.join(".figs.tmp-4194305-0")).unwrap();
    let out = model(&["plot", "B", "--out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 22, "{names:?}");
    assert!(
        names
            .iter()
            .all(|n| n.starts_with("fig") || n == ".model-output"),
        "{names:?}"
    );
    assert!(dir.join("fig07_det_k.png").is_file());
    assert_eq!(
        std::fs::read_dir(&base).unwrap().count(),
        1,
        "only the folder"
    );
    std::fs::remove_dir_all(&base).unwrap();
}

#[test]
fn no_colour_codes_when_not_on_a_terminal_even_in_ci() {
    let out = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["analyze", "A", "--no-such-option"])
        .env("CI", "true")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(!out.stderr.contains(&0x1b), "{}", stderr(&out));
    let help = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["report", "--help"])
        .env("CI", "true")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&help.stdout);
    assert!(!help.stdout.contains(&0x1b));
    assert!(
        text.contains("summary.json") && text.contains("--out <DIR>"),
        "{text}"
    );
}

/// Every file under `dir`, relative, with its contents.
fn tree(dir: &std::path::Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    let mut files = std::collections::BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                todo.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().to_path_buf();
                files.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    files
}

#[test]
fn emit_killed_at_random_points_leaves_all_old_or_all_new_and_the_next_run_cleans_up() {
    let root = scratch("emit-kill");
    let emit = |check: bool| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_model"));
        c.args(["emit", "--root", root.to_str().unwrap()]);
        if check {
            c.arg("--check");
        }
        c
    };
    let start = std::time::Instant::now();
    assert!(emit(false).output().unwrap().status.success());
    let full_run = start.elapsed();
    let new = tree(&root);
    assert!(new.len() >= 5, "{:?}", new.keys());
    let old: std::collections::BTreeMap<PathBuf, Vec<u8>> = new
        .iter()
        .map(|(p, c)| (p.clone(), [c.as_slice(), b"\n// old\n"].concat()))
        .collect();
    // Pseudo-random delays (xorshift, seed printed): half over the whole run, half over its
    // last fifth, where the files are written.
    let mut seed = u64::from(std::process::id()).wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    println!("seed {seed}, full run {full_run:?}");
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 10_000) as f64 / 10_000.0
    };
    let (mut all_old, mut all_new) = (0, 0);
    let runs = 24;
    for i in 0..runs {
        for (p, c) in &old {
            std::fs::write(root.join(p), c).unwrap();
        }
        let u = next();
        let frac = if i % 2 == 0 { 1.2 * u } else { 0.8 + 0.3 * u };
        let mut child = emit(false)
            .stdout(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(full_run.mul_f64(frac));
        let _ = child.kill();
        let _ = child.wait();
        // Right after the kill: old, new, or committed (journal present, finished next run).
        let now = tree(&root);
        let visible: std::collections::BTreeMap<_, _> = now
            .iter()
            .filter(|(p, _)| {
                !p.to_string_lossy().contains(".tmp-") && !p.ends_with(".emit-journal")
            })
            .map(|(p, c)| (p.clone(), c.clone()))
            .collect();
        let committed = now.keys().any(|p| p.ends_with(".emit-journal"));
        assert!(
            visible == old || visible == new || committed,
            "run {i}: a mix of old and new files without a journal"
        );
        // The next run (`emit --check`) finishes or discards what the killed one left.
        let _ = emit(true).output().unwrap();
        let after = tree(&root);
        assert!(
            after
                .keys()
                .all(|p| !p.to_string_lossy().contains(".tmp-") && !p.ends_with(".emit-journal")),
            "run {i}: leftovers {:?}",
            after.keys().collect::<Vec<_>>()
        );
        if after == old {
            all_old += 1;
        } else if after == new {
            all_new += 1;
        } else {
            panic!("run {i} (killed at {frac:.2} of a run): neither all old nor all new");
        }
    }
    println!("{runs} killed runs: {all_old} left every old file, {all_new} every new file");
    std::fs::remove_dir_all(&root).unwrap();
}
