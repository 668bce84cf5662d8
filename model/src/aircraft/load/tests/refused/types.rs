//! Refused files whose values have the wrong type: a string, a boolean, an array or a table where
//! a number or a table is expected.

use super::*;

pub(super) fn type_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "a number written as a string",
            replace("l_beta = -110.45", "l_beta = \"-110.45\""),
            11,
            &["derivatives.l_beta", "expected a number, found a string"],
        )
        .kind(is!(WrongType)),
        refused(
            "a boolean for a number",
            replace("m_q = -1.815", "m_q = true"),
            13,
            &["derivatives.m_q", "expected a number", "boolean"],
        ),
        refused(
            "an array for a number",
            replace("m_q = -1.815", "m_q = [-1.815]"),
            13,
            &["derivatives.m_q", "found an array"],
        ),
        refused(
            "a date-time for a number",
            replace("m_q = -1.815", "m_q = 1979-05-27"),
            13,
            &["derivatives.m_q", "found a date-time"],
        ),
        refused(
            "an inline table for a number",
            replace("m_q = -1.815", "m_q = { v = 1 }"),
            13,
            &["derivatives.m_q", "found a table"],
        ),
        refused(
            "a string for an inertia coefficient",
            replace("D = 0.786", "D = \"x\""),
            4,
            &["inertia.D", "expected a number"],
        ),
        refused(
            "a string for the speed",
            replace("speed = 150.0", "speed = \"fast\""),
            21,
            &["flight.speed", "expected a number"],
        ),
        refused(
            "a number for the name",
            replace("name = \"T\"", "name = 3"),
            1,
            &["`name`", "expected a string, found an integer"],
        ),
        refused(
            "a name with an escaped BEL",
            replace("name = \"T\"", "name = \"Air\\u0007craft\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `Air\\u{7}craft`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped ESC",
            replace("name = \"T\"", "name = \"Evil\\u001b[31m\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `Evil\\u{1b}[31m`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped newline",
            replace("name = \"T\"", "name = \"two\\nlines\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `two\\nlines`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped tab",
            replace("name = \"T\"", "name = \"tab\\there\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `tab\\there`",
            ],
        )
        .kind(is!(InvalidValue)),
    ]
}
