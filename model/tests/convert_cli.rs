//! `model convert` end to end: a nondimensional body-axis file in, a dimensional file out that
//! loads as the same aircraft; bad files exit 2 naming file, line and key.

use std::path::PathBuf;
use std::process::{Command, Output};

fn model(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .output()
        .expect("run the model binary")
}

fn repo(path: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(path)
        .to_string_lossy()
        .into_owned()
}

fn scratch(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("model-convert-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn convert_prints_a_dimensional_file_that_loads_as_the_same_aircraft() {
    let src = repo("aircraft/fighter.toml");
    let out = model(&["convert", &src]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("# Principal x axis tilt: 1.04"), "{text}");
    assert!(
        text.contains("[derivatives]") && text.contains("[limits]"),
        "{text}"
    );
    let converted = scratch("fighter-dimensional.toml", &text);
    let a = model::aircraft::load(std::path::Path::new(&src)).unwrap();
    let b = model::aircraft::load(&converted).unwrap();
    assert_eq!(a, b);
}

#[test]
fn convert_refuses_dimensional_and_bad_files_with_exit_2() {
    let out = model(&["convert", &repo("aircraft/a.toml")]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("a.toml:1:1") && err.contains("already"),
        "{err}"
    );

    let text = std::fs::read_to_string(repo("aircraft/fighter.toml")).unwrap();
    let bad = scratch(
        "bad-mass.toml",
        &text.replacen("mass = 9300.0", "mass = -9300.0", 1),
    );
    for cmd in ["convert", "analyze"] {
        let out = model(&[cmd, bad.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("bad-mass.toml:") && err.contains("geometry.mass") && err.contains("> 0"),
            "{cmd}: {err}"
        );
    }
}
