//! The refused files, one table of cases: each names the file, the line, the key and what was
//! expected; the cases are grouped by what is wrong (syntax, keys, types, numbers, inertia).

use super::*;

/// One refused file: what it shows, the file, the line its error names, and what the message
/// says; optionally also the error's kind, its column, what the message must not say, and a
/// bound on its length.
struct Refusal {
    case: &'static str,
    text: String,
    line: usize,
    says: &'static [&'static str],
    kind: Option<fn(&AircraftError) -> bool>,
    column: Option<usize>,
    never_says: &'static [&'static str],
    shorter_than: Option<usize>,
}

/// The test that an error is of one `AircraftError` variant.
macro_rules! is {
    ($variant:ident) => {
        |e: &AircraftError| matches!(e, AircraftError::$variant { .. })
    };
}

mod inertia;
mod keys;
mod numbers;
mod syntax;
mod types;

use inertia::inertia_refusals;
use keys::key_refusals;
use numbers::number_refusals;
use syntax::syntax_refusals;
use types::type_refusals;

fn refused(
    case: &'static str,
    text: impl Into<String>,
    line: usize,
    says: &'static [&'static str],
) -> Refusal {
    Refusal {
        case,
        text: text.into(),
        line,
        says,
        kind: None,
        column: None,
        never_says: &[],
        shorter_than: None,
    }
}

impl Refusal {
    fn kind(self, kind: fn(&AircraftError) -> bool) -> Self {
        Refusal {
            kind: Some(kind),
            ..self
        }
    }

    fn column(self, column: usize) -> Self {
        Refusal {
            column: Some(column),
            ..self
        }
    }

    fn never_says(self, never_says: &'static [&'static str]) -> Self {
        Refusal { never_says, ..self }
    }

    fn shorter_than(self, bound: usize) -> Self {
        Refusal {
            shorter_than: Some(bound),
            ..self
        }
    }

    /// Parses the file and checks the error as `err` does, and the optional properties.
    fn check(&self) {
        let case = self.case;
        let e = match parse(&self.text, FILE) {
            Ok(a) => panic!("{case}: expected an error, got {a:?}"),
            Err(e) => e,
        };
        let msg = e.to_string();
        assert!(msg.contains(FILE), "{case}: no file name in: {msg}");
        let line = self.line;
        assert!(
            msg.contains(&format!("{FILE}:{line}:")),
            "{case}: no line {line} in: {msg}"
        );
        for n in self.says {
            assert!(msg.contains(n), "{case}: no `{n}` in: {msg}");
        }
        assert_eq!(e.location().map(|l| l.line), Some(line), "{case}: {msg}");
        if let Some(kind) = self.kind {
            assert!(kind(&e), "{case}: wrong kind: {e:?}");
        }
        if let Some(column) = self.column {
            assert_eq!(
                e.location().map(|l| l.column),
                Some(column),
                "{case}: {msg}"
            );
        }
        for n in self.never_says {
            assert!(!msg.contains(n), "{case}: `{n}` in: {msg}");
        }
        if let Some(bound) = self.shorter_than {
            assert!(msg.len() < bound, "{case}: {msg}");
        }
    }
}

/// The inertia coefficients of `GOOD`, one per line.
const CDE: &str = "C = 0.959\nD = 0.786\nE = 0.705\n";

#[test]
fn refused_files_name_their_line_key_and_expectation() {
    let tables = [
        syntax_refusals(),
        key_refusals(),
        type_refusals(),
        number_refusals(),
        inertia_refusals(),
    ];
    for refusal in tables.iter().flatten() {
        refusal.check();
    }
}
