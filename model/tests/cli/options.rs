//! The options as a user meets them: every command's help in one layout, every aircraft
//! argument's help naming the `jsbsim:` source, `convert` taking that source, `import` trimmed
//! at 1 g without a load factor, and bad edges refused before any work with a true message.

use super::*;

/// The fixture model (tests/fixtures/jsbsim_jet.xml) as a `jsbsim:` source at `condition`.
fn jet(condition: &str) -> String {
    let xml = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/jsbsim_jet.xml");
    format!("jsbsim:{} {condition}", xml.display())
}

fn fixture() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/jsbsim_jet.xml")
        .to_string_lossy()
        .into_owned()
}

/// `model CMD --help` of every command: what it does, `Usage: model CMD`, its arguments and
/// options under clap's headings; an `<AIRCRAFT>` (or `<SOURCE>`) says how to name a JSBSim
/// model. `model help import` is the same text as `model import --help`.
#[test]
fn every_command_has_help_in_one_layout() {
    for cmd in [
        "analyze", "continue", "report", "plot", "simulate", "clear", "envelope", "convert",
        "import", "emit",
    ] {
        let out = model(&[cmd, "--help"]);
        assert_eq!(out.status.code(), Some(0), "{cmd}");
        let text = String::from_utf8_lossy(&out.stdout);
        let usage = format!("\n\nUsage: model {cmd} ");
        assert!(text.contains(&usage), "{cmd}: {text}");
        assert!(text.contains("\n\nOptions:\n"), "{cmd}: {text}");
        assert!(text.contains("  -h, --help "), "{cmd}: {text}");
        if cmd != "emit" {
            assert!(text.contains("\n\nArguments:\n"), "{cmd}: {text}");
            assert!(
                text.contains("\"jsbsim:MODEL") || cmd == "import",
                "{cmd}: {text}"
            );
        }
    }
    assert_eq!(
        model(&["help", "import"]).stdout,
        model(&["import", "--help"]).stdout
    );
}

/// `convert` takes a `jsbsim:` source as the other commands do: the import's file, converted.
#[test]
fn convert_accepts_a_jsbsim_source() {
    let source = jet("--altitude-m 6096 --mach 0.6");
    let out = model(&["convert", &source]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains(&format!("from {source}")), "{text}");
    assert!(
        text.contains("[derivatives]") && text.contains("l_delta_a = "),
        "{text}"
    );
}

/// Without --load-factor or --alpha-deg the import is trimmed at 1 g: the same file as with
/// --load-factor 1 (the usage shows both as optional, and they are).
#[test]
fn an_import_without_load_factor_is_the_1_g_trim() {
    let base = [
        "import",
        "jsbsim",
        &fixture(),
        "--altitude-m",
        "6096",
        "--mach",
        "0.6",
    ];
    let plain = model(&base);
    let one_g = model(&[&base[..], &["--load-factor", "1"]].concat());
    assert!(plain.status.success(), "{}", stderr(&plain));
    assert_eq!(plain.stdout, one_g.stdout);
}

/// Refused at once, exit 2, with a message that is true: a tolerance below what the proof can
/// resolve (the smallest one named), the top of the atmosphere accepted and one metre above it
/// refused, a JSBSim root that is a file, and a `--set` that makes the model's lift infinite
/// (named with the property).
#[test]
fn bad_edges_are_refused_before_any_work_with_a_true_message() {
    let limit = std::time::Duration::from_secs(20);
    let out = model_within(
        &[
            "clear",
            &repo("aircraft/a_uncertain.toml"),
            "--tolerance",
            "1e-300",
        ],
        limit,
    )
    .expect("refused at once");
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("--tolerance = 1e-300: expected a finite tolerance of at least 1e-12 rad/s"),
        "{err}"
    );

    let at = |h: &str| {
        model(&[
            "import",
            "jsbsim",
            &fixture(),
            "--altitude-m",
            h,
            "--mach",
            "2",
            "--alpha-deg",
            "2",
        ])
    };
    let top = at("86000");
    assert!(top.status.success(), "{}", stderr(&top));
    let above = at("86001");
    assert_eq!(above.status.code(), Some(2));
    assert!(
        stderr(&above).contains(
            "altitude 86001 m is outside the standard atmosphere (expected 0 to 86,000 m)"
        ),
        "{}",
        stderr(&above)
    );

    let out = model(&[
        "import",
        "jsbsim",
        "f104",
        "--altitude-m",
        "6000",
        "--mach",
        "0.5",
        "--jsbsim-root",
        &fixture(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains(&format!(
            "the JSBSim root {} is a file; expected the folder holding aircraft/",
            fixture()
        )),
        "{err}"
    );

    let out = model(&[
        "import",
        "jsbsim",
        &fixture(),
        "--altitude-m",
        "6096",
        "--mach",
        "0.6",
        "--set",
        "fcs/flap-pos-deg=1e308",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("`fcs/flap-pos-deg`") && err.contains("is inf"),
        "{err}"
    );
    assert!(
        err.trim_end()
            .ends_with("(with --set fcs/flap-pos-deg=1e308)"),
        "{err}"
    );
}

/// `import jsbsim --list` calls a model importable exactly when `--list --analyze` at its
/// reference condition (3000 m, Mach 0.3, 1 g) imports it: one check. Skipped without the
/// JSBSim models.
#[test]
fn list_and_list_analyze_agree_on_what_imports() {
    if model::jsbsim::catalogue::root(None).is_none() {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
        return;
    }
    let list = String::from_utf8(model(&["import", "jsbsim", "--list"]).stdout).unwrap();
    let table = model(&[
        "import",
        "jsbsim",
        "--list",
        "--analyze",
        "--altitude-m",
        "3000",
        "--mach",
        "0.3",
    ]);
    let table = String::from_utf8(table.stdout).unwrap();
    let listed: Vec<(String, bool)> = list
        .lines()
        .skip(1)
        .map(|l| {
            let mut w = l.split_whitespace();
            (w.next().unwrap().to_string(), w.next() == Some("ok"))
        })
        .collect();
    assert!(listed.len() > 50, "{list}");
    for (name, ok) in &listed {
        let row = table
            .lines()
            .find(|l| l.starts_with(&format!("| {name} |")))
            .unwrap_or_else(|| panic!("{name} not in {table}"));
        let imported = !row.starts_with(&format!("| {name} | no:"));
        assert_eq!(*ok, imported, "{name}: --list vs {row}");
    }
    for refused in ["c172x", "mk82"] {
        assert!(listed.iter().any(|(n, ok)| n == refused && !ok), "{list}");
    }
}
