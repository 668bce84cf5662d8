//! Tidy checks of the hand-written sources (rust-analyzer's habit): every Rust file opens with a
//! `//!` line saying what it is, and comments cite equations in one form, "Eq. N" or "Eqs N-M",
//! so that a search for "Eq. 27" finds every mention; and no comment cites an issue number
//! (comments describe the code as it is, git keeps its history). Generated files
//! (`// @generated`) are exempt; they are checked by `model emit --check`. No hand-written file
//! grows past 800 lines (one concept per file).

use sources::rust_files;
use std::path::{Path, PathBuf};

#[path = "support/sources.rs"]
mod sources;

fn hand_written() -> Vec<(PathBuf, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for dir in ["model", "derive", "tests"] {
        rust_files(&root.join(dir), &mut files);
    }
    files.sort();
    files
        .into_iter()
        .filter_map(|p| {
            let text = std::fs::read_to_string(&p).expect("UTF-8 source");
            (!text.starts_with("// @generated")).then_some((p, text))
        })
        .collect()
}

#[test]
fn every_hand_written_source_file_opens_with_a_module_doc_line() {
    let files = hand_written();
    assert!(files.len() > 50, "found only {} files", files.len());
    let missing: Vec<_> = files
        .iter()
        .filter(|(_, text)| !text.starts_with("//!"))
        .map(|(p, _)| p.display().to_string())
        .collect();
    assert!(
        missing.is_empty(),
        "files without a leading //! line: {missing:?}"
    );
}

/// A comment's citation in a form other than "Eq. N" / "Eqs N-M", if any.
fn stray_citation(comment: &str) -> Option<&'static str> {
    let w: Vec<&str> = comment.split_whitespace().collect();
    let number = |s: &str| s.starts_with(|c: char| c.is_ascii_digit());
    for pair in w.windows(2) {
        let (a, b) = (pair[0].trim_start_matches('('), pair[1]);
        if !number(b) {
            continue;
        }
        match a {
            "Eqs." => return Some("\"Eqs. N\" (write \"Eqs N-M\")"),
            "Eq" | "Equation" | "Equations" | "eq." | "Eqn" => {
                return Some("\"Eq N\" (write \"Eq. N\")")
            }
            "Eq." if b.contains('-') => return Some("\"Eq. N-M\" (write \"Eqs N-M\")"),
            _ => {}
        }
    }
    None
}

/// `file:line: why` for every comment (from `//` to the end of its line) of the hand-written
/// sources that `check` flags with `why`.
fn flagged_comments(check: impl Fn(&str) -> Option<String>) -> Vec<String> {
    let mut flagged = Vec::new();
    for (p, text) in hand_written() {
        for (i, line) in text.lines().enumerate() {
            if let Some(why) = line.find("//").and_then(|at| check(&line[at..])) {
                flagged.push(format!("{}:{}: {why}", p.display(), i + 1));
            }
        }
    }
    flagged
}

#[test]
fn comments_cite_equations_as_eq_n_or_eqs_n_m() {
    let stray = flagged_comments(|c| stray_citation(c).map(str::to_string));
    assert!(stray.is_empty(), "{stray:#?}");
}

#[test]
fn the_citation_check_sees_each_stray_form() {
    assert!(stray_citation("Eq. 27 and Eqs 28-31").is_none());
    assert!(stray_citation("Eqs. 6-10").is_some());
    assert!(stray_citation("Eq 5").is_some());
    assert!(stray_citation("Eq. 1-2").is_some());
}

/// A comment's citation of an issue number ("issue N", "issues N", "issue #N", any case; also
/// "issue-N" and "issue#N" in one word), if any, in lower case. Comments describe the code as it
/// is: the paper's section or equation, the claim, the source of a number; git keeps which
/// issue asked for what.
fn issue_citation(comment: &str) -> Option<String> {
    let bare = |w: &str| {
        w.trim_matches(|c: char| !c.is_ascii_alphanumeric())
            .to_lowercase()
    };
    let words: Vec<String> = comment.split_whitespace().map(bare).collect();
    let number = |s: &str| s.starts_with(|c: char| c.is_ascii_digit());
    for (i, word) in words.iter().enumerate() {
        let Some(rest) = word
            .strip_prefix("issues")
            .or_else(|| word.strip_prefix("issue"))
        else {
            continue;
        };
        match (rest, words.get(i + 1)) {
            ("", Some(next)) if number(next) => return Some(format!("{word} {next}")),
            (joined, _) if joined.starts_with(['-', '#']) && number(&joined[1..]) => {
                return Some(word.clone())
            }
            _ => {}
        }
    }
    None
}

#[test]
fn comments_cite_no_issue_numbers() {
    let cited = flagged_comments(|c| issue_citation(c).map(|what| format!("cites \"{what}\"")));
    assert!(cited.is_empty(), "{cited:#?}");
}

#[test]
fn the_issue_check_sees_each_citation_form() {
    assert!(issue_citation("Eq. 27, section V: an issue of 3 roots, tissue 4").is_none());
    let hopf = issue_citation("the Hopf criterion (issue 10), beyond the paper");
    assert_eq!(hopf.as_deref(), Some("issue 10"));
    assert!(issue_citation("Issue 11: the certified route").is_some());
    assert!(issue_citation("Issues 3 and 11's speed targets").is_some());
    assert!(issue_citation("as in issue #12").is_some());
    assert_eq!(
        issue_citation("(the issue-10).").as_deref(),
        Some("issue-10")
    );
}

/// The README's test command is what CI runs: `.ci/run` runs it stage by stage (to time each),
/// and its stages joined by ` && ` are the command of the README's fenced block, letter for
/// letter, and of the user's guide's page on contributing.
#[test]
fn ci_runs_the_readme_test_command_stage_by_stage() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let ci = std::fs::read_to_string(root.join(".ci/run")).expect(".ci/run");
    let block = ci
        .split_once("STAGES=(\n")
        .and_then(|(_, rest)| rest.split_once("\n)\n"))
        .expect("a STAGES=( ... ) array in .ci/run")
        .0;
    let stages: Vec<String> = block
        .lines()
        .map(|line| {
            let quoted = line.trim();
            let inner = &quoted[1..quoted.len() - 1];
            inner.split_once('|').expect("name|command").1.to_string()
        })
        .collect();
    assert!(stages.len() >= 5, "{stages:?}");
    let command = stages.join(" && ");
    let fenced = format!("```sh\n{command}\n```");
    for page in ["README.md", "docs/contributing.md"] {
        let text = std::fs::read_to_string(root.join(page)).expect(page);
        assert!(
            text.contains(&fenced),
            "the test command of {page} is not the stages of .ci/run:\n{command}"
        );
    }
}

/// One concept per file: a hand-written source longer than this holds several, and is split
/// into files named for what they hold.
const MAX_LINES: usize = 800;

#[test]
fn no_hand_written_source_file_is_longer_than_800_lines() {
    let long: Vec<String> = hand_written()
        .into_iter()
        .filter(|(_, text)| text.lines().count() > MAX_LINES)
        .map(|(p, text)| format!("{} ({} lines)", p.display(), text.lines().count()))
        .collect();
    assert!(
        long.is_empty(),
        "files over {MAX_LINES} lines:\n{}",
        long.join("\n")
    );
}
