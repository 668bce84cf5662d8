//! The module tower of `model` (rust-analyzer's habit of checking architecture in a test): each
//! top-level module of `model/src` names only modules below it in [`LAYERS`], so data flows one
//! way, from the exact algebra and the aircraft up to the commands. The emitter and the
//! certified route share the straight-line program below both and never name each other. Test
//! files (`tests.rs`, `tests/`) may reach up, to check a module against an independent one.

use sources::rust_files;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

#[path = "support/sources.rs"]
mod sources;

/// The top-level modules of `model/src`, bottom first.
const LAYERS: &[&str] = &[
    "random",
    "files",
    "interval",
    "spectrum",
    "algebra",
    "aircraft",
    "equations",
    "roots",
    "derivation",
    "specialise",
    "pss_model",
    "program",
    "certified",
    "simulation",
    "continuation",
    "analysis",
    "clearance",
    "emit",
    "jsbsim",
    "six_dof",
    "envelope",
    "plot",
    "present",
];

/// Pairs of modules that must not name each other, whatever their layers.
const INDEPENDENT: &[(&str, &str)] = &[("emit", "certified")];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../model/src")
}

/// The non-test Rust files of top-level module `m`: `m.rs` and everything under `m/`.
fn files_of(m: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let file = src().join(format!("{m}.rs"));
    if file.exists() {
        out.push(file);
    }
    let below_m = src().join(m);
    let mut below = Vec::new();
    if below_m.is_dir() {
        rust_files(&below_m, &mut below);
    }
    out.extend(below.into_iter().filter(|p| {
        let inner = p.strip_prefix(&below_m).unwrap_or(p);
        p.file_name().is_some_and(|n| n != "tests.rs")
            && !inner.components().any(|c| c.as_os_str() == "tests")
    }));
    out
}

/// The first path segment after each `crate::` in the code (comments left out), grouped
/// imports `crate::{a::X, b}` included.
fn named_modules(text: &str) -> BTreeSet<String> {
    let code: String = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    let mut out = BTreeSet::new();
    for (at, _) in code.match_indices("crate::") {
        let rest = &code[at + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            out.extend(group_heads(group));
        } else {
            out.insert(ident(rest).to_string());
        }
    }
    out
}

/// The leading identifier of `s`.
fn ident(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

/// The first segment of every item of a `{...}` group whose opening brace is just before `s`.
fn group_heads(s: &str) -> Vec<String> {
    let (mut depth, mut heads, mut item_start) = (1usize, Vec::new(), true);
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 1 => item_start = true,
            c if item_start && !c.is_whitespace() => {
                heads.push(ident(&s[i..]).to_string());
                item_start = false;
            }
            _ => {}
        }
        if depth == 0 {
            break;
        }
    }
    heads
}

fn violations() -> Vec<String> {
    let mut out = Vec::new();
    for (level, m) in LAYERS.iter().enumerate() {
        for file in files_of(m) {
            let text = std::fs::read_to_string(&file).expect("UTF-8 source");
            for named in named_modules(&text) {
                let above = LAYERS[level + 1..].contains(&named.as_str());
                let barred = INDEPENDENT
                    .iter()
                    .any(|&(a, b)| (a, b) == (m, named.as_str()) || (b, a) == (m, named.as_str()));
                if above || barred {
                    out.push(format!("{} names crate::{named}", file.display()));
                }
            }
        }
    }
    out
}

#[test]
fn every_module_of_the_library_is_in_the_tower() {
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(src()).expect("model/src") {
        let path = entry.expect("directory entry").path();
        let name = path.file_stem().and_then(|n| n.to_str()).unwrap_or("");
        if !matches!(name, "lib" | "main") && !LAYERS.contains(&name) {
            missing.push(name.to_string());
        }
    }
    missing.dedup();
    assert!(
        missing.is_empty(),
        "modules missing from LAYERS: {missing:?}"
    );
}

#[test]
fn no_module_names_one_above_it_or_a_module_it_must_stay_apart_from() {
    let v = violations();
    assert!(v.is_empty(), "imports against the tower:\n{}", v.join("\n"));
}

#[test]
fn the_scan_sees_plain_and_grouped_imports_but_not_comments() {
    let text =
        "use crate::analysis::X;\n// crate::plot\nuse crate::{emit::a, certified::{b, c}};\n\
                let g = crate::aircraft::G;";
    let seen: Vec<String> = named_modules(text).into_iter().collect();
    assert_eq!(seen, ["aircraft", "analysis", "certified", "emit"]);
}
