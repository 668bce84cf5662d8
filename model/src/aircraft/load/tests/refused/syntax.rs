//! Refused files whose text is no TOML the reader can take: cut off, control characters,
//! syntax errors.

use super::*;

pub(super) fn syntax_refusals() -> Vec<Refusal> {
    vec![
        // The parser stops there without a message of its own.
        refused(
            "a value cut off at the end of the file",
            "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\nE = ",
            5,
            &["inertia.E", "expected a number"],
        )
        .kind(is!(Syntax)),
        // A cut-off header has the parser's own message.
        refused(
            "a table header cut off at the end of the file",
            "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\n[deriv",
            5,
            &["table header"],
        )
        .kind(is!(Syntax)),
        refused(
            "a number with two decimal points",
            replace("l_p = -21.7529", "l_p = -21.75.29"),
            9,
            &["TOML syntax error"],
        )
        .kind(is!(Syntax)),
        refused(
            "an unclosed array, found where the next line starts",
            replace("l_r = 1.5207", "l_r = [1.5207"),
            11,
            &["syntax", "expected"],
        )
        .kind(is!(Syntax)),
        refused(
            "a duplicate key",
            replace("l_r = 1.5207", "l_p = 1.5207"),
            10,
            &["l_p"],
        )
        .kind(is!(Syntax)),
        refused(
            "a NUL inside a string",
            replace("name = \"T\"", "name = \"T\0\""),
            1,
            &["key `name`", "U+0000 (NUL)", "expected printable text"],
        )
        .kind(is!(ControlCharacter))
        .column(10),
        refused(
            "a NUL in a comment after a value",
            replace("l_p = -21.7529", "l_p = -21.7529 # \0"),
            9,
            &["key `derivatives.l_p`", "U+0000"],
        ),
        refused(
            "an ESC in a comment line of its own",
            replace("[derivatives]\n", "[derivatives]\n# \u{1b}[31m\n"),
            7,
            &["line 7", "U+001B (ESC)"],
        ),
    ]
}
