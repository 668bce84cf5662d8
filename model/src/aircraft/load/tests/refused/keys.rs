//! Refused files with unknown, misplaced or missing keys and tables, or tables of both formats.

use super::*;

pub(super) fn key_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "a missing key, named at its table's header",
            replace("m_alpha = -13.52504\n", ""),
            6,
            &[
                "derivatives.m_alpha",
                "missing required key",
                "expected `m_alpha = <number>`",
            ],
        )
        .kind(is!(MissingKey))
        .column(1),
        refused(
            "an unknown derivative, with the closest suggested",
            replace("l_p = -21.7529", "l_pp = -21.7529"),
            9,
            &[
                "unknown key `derivatives.l_pp`",
                "did you mean `l_p`?",
                "expected one of",
            ],
        )
        .kind(is!(UnknownKey)),
        refused(
            "an unknown top-level key",
            replace("name = \"T\"", "nmae = \"T\""),
            1,
            &["`nmae`", "did you mean `name`?"],
        )
        .kind(is!(UnknownKey)),
        refused(
            "a key in the wrong case",
            replace("C = 0.959", "c = 0.959"),
            3,
            &["`inertia.c`", "did you mean `C`?"],
        )
        .kind(is!(UnknownKey)),
        refused(
            "a key of another table",
            replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nspeed = 3\n"),
            20,
            &["`derivatives.speed`", "belongs in the `[flight]` table"],
        ),
        refused(
            "a misspelt flight key",
            replace("speed = 150.0", "sped = 150.0"),
            21,
            &["`flight.sped`", "did you mean `speed`?"],
        ),
        refused(
            "an unknown key close to none",
            replace("l_p = -21.7529", "roll_damping = -21.7529"),
            9,
            &["`derivatives.roll_damping`", "expected one of `z_alpha`"],
        )
        .never_says(&["did you mean"]),
        refused(
            "an unknown table",
            format!("{GOOD}[extra]\nx = 1\n"),
            22,
            &["unknown key `extra`"],
        ),
        refused(
            "a missing `[derivatives]`, named at line 1",
            GOOD.split("[derivatives]").next().unwrap(),
            1,
            &[
                "missing table `[derivatives]`",
                "expected `[derivatives]` with keys `z_alpha`",
            ],
        )
        .kind(is!(MissingTable)),
        refused(
            "a missing `[inertia]`, named at line 1",
            replace("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", ""),
            1,
            &["missing table `[inertia]`", "expected `[inertia]` with"],
        )
        .kind(is!(MissingTable)),
        refused(
            "a table given as a number",
            format!(
                "inertia = 3\n{}",
                GOOD.replacen("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", "", 1)
            ),
            1,
            &[
                "key `inertia`",
                "expected a table `[inertia]`",
                "found an integer",
            ],
        )
        .kind(is!(NotATable)),
        refused(
            "a table given as an array of tables",
            replace("[flight]\nspeed = 150.0\n", "[[flight]]\nspeed = 150.0\n"),
            20,
            &["key `flight`", "expected a table", "found an array"],
        )
        .kind(is!(NotATable)),
        refused(
            "a body-axis key in a dimensional `[inertia]`",
            replace("E = 0.705\n", "E = 0.705\nixz = 3\n"),
            6,
            &["`inertia.ixz`", "expected either the dimensional"],
        )
        .kind(is!(MixedFormats)),
        refused(
            "a body-axis key in a dimensional `[flight]`",
            replace("speed = 150.0", "speed = 150.0\naltitude = 3000"),
            22,
            &["`flight.altitude`", "not a mix"],
        ),
        refused(
            "a body-axis table in a dimensional file",
            format!("{GOOD}[geometry]\nmass = 1\n"),
            22,
            &[
                "table `[geometry]` given together with `[derivatives]`",
                "not a mix",
            ],
        ),
    ]
}
