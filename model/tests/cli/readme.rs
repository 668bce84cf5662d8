//! The README as a new user meets it: short, a first screen with the install line and the two
//! commands, and, for every command of that screen, the output the README shows for it as the
//! tool prints it; the opening of the tour's F-104 output; and the output of `analyze A` that
//! the user's guide explains.

use super::*;

/// Lines a terminal or a repository page shows before the reader scrolls.
const FIRST_SCREEN_LINES: usize = 40;

/// The README is the way in; the reference material lives in the user's guide under docs/.
const MAX_README_LINES: usize = 300;

fn text(path: &str) -> String {
    std::fs::read_to_string(repo(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The fenced block of `lang` that follows the first `after` in the repository's file `path`.
fn shown_block(path: &str, after: &str, lang: &str) -> String {
    let file = text(path);
    let at = file
        .find(after)
        .unwrap_or_else(|| panic!("{path} has no `{after}`"));
    let rest = &file[at + after.len()..];
    let fence = format!("```{lang}\n");
    let start = rest
        .find(&fence)
        .unwrap_or_else(|| panic!("{path}: no {lang} block after `{after}`"))
        + fence.len();
    let end = start + rest[start..].find("```").unwrap();
    rest[start..end].to_string()
}

/// The first screen of the README.
fn first_screen() -> String {
    text("README.md")
        .lines()
        .take(FIRST_SCREEN_LINES)
        .map(|line| format!("{line}\n"))
        .collect()
}

/// Every line of the `sh` blocks of `markdown`.
fn shell_lines(markdown: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut inside = false;
    for line in markdown.lines() {
        if line.starts_with("```") {
            inside = !inside && line == "```sh";
        } else if inside {
            lines.push(line.to_string());
        }
    }
    lines
}

/// What follows `cargo run --release -p model -- ` in the first screen's commands.
fn first_screen_model_commands() -> Vec<String> {
    shell_lines(&first_screen())
        .iter()
        .filter_map(|line| line.strip_prefix("cargo run --release -p model -- "))
        .map(str::to_string)
        .collect()
}

#[test]
fn the_readme_is_shorter_than_300_lines() {
    let lines = text("README.md").lines().count();
    assert!(
        lines < MAX_README_LINES,
        "README.md has {lines} lines: move reference material into docs/"
    );
}

#[test]
fn the_first_screen_holds_the_install_line_and_the_two_commands() {
    let screen = first_screen();
    let commands = shell_lines(&screen);
    assert!(
        commands
            .iter()
            .any(|c| c.contains("rustup") && c.contains("pip install jsbsim==1.3.3")),
        "no install line in the first {FIRST_SCREEN_LINES} lines:\n{screen}"
    );
    assert_eq!(first_screen_model_commands(), ["analyze A"], "{screen}");
    // The test command; tests/tests/tidy.rs checks that it is .ci/run's stages.
    assert!(
        commands
            .iter()
            .any(|c| c.starts_with("cargo fmt --all -- --check && ")),
        "no test command in the first {FIRST_SCREEN_LINES} lines:\n{screen}"
    );
    // Each command says how long its first build takes.
    let words: Vec<&str> = screen.split_whitespace().collect();
    assert!(
        words.windows(2).filter(|w| w[1] == "minutes").count() >= 2,
        "the first build's time of each command:\n{screen}"
    );
}

/// Each command of the first screen runs, and prints exactly the block the README shows after
/// "`ARGS` prints".
#[test]
fn the_first_screen_commands_print_what_the_readme_shows() {
    for command in first_screen_model_commands() {
        let args: Vec<&str> = command.split_whitespace().collect();
        let out = model(&args);
        assert_eq!(out.status.code(), Some(0), "{command}: {}", stderr(&out));
        assert_eq!(
            shown_block("README.md", &format!("`{command}` prints"), "text"),
            String::from_utf8_lossy(&out.stdout),
            "the README's output of `{command}`"
        );
    }
}

#[test]
fn the_guide_explains_the_real_output_of_analyze_a() {
    let text = model(&["analyze", "A"]);
    assert_eq!(
        shown_block("docs/analyze.md", "`analyze A` prints", "text"),
        String::from_utf8_lossy(&text.stdout)
    );
    let json = model(&["analyze", "A", "--json"]);
    assert_eq!(
        shown_block("docs/analyze.md", "`analyze A --json` prints", "json"),
        String::from_utf8_lossy(&json.stdout)
    );
}

/// The tour's JSBSim jet: the output the README and the guide's worked example show for the
/// unloaded F-104 opens what `analyze` prints for the import the README names. Skipped with a
/// message when the JSBSim models are not installed.
#[test]
fn the_tours_f104_output_opens_what_analyze_prints() {
    if model::jsbsim::catalogue::root(None).is_none() {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
        return;
    }
    let source = "jsbsim:f104 --altitude-m 6096 --mach 0.53 --load-factor 0";
    let command = format!("cargo run --release -p model -- analyze \"{source}\"");
    assert!(
        shell_lines(&text("README.md"))
            .iter()
            .any(|line| line.starts_with(&command)),
        "the README's tour no longer shows `{command}`"
    );
    let out = model(&["analyze", source]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let printed = String::from_utf8_lossy(&out.stdout);
    for (page, after) in [
        ("README.md", "the output opens with"),
        (
            "docs/jsbsim.md",
            "the principal axis 0.98 deg below the flight path) it jumps:",
        ),
    ] {
        let shown = shown_block(page, after, "text");
        assert!(
            printed.starts_with(&shown),
            "{page} shows\n{shown}\nbut analyze prints\n{printed}"
        );
    }
}
