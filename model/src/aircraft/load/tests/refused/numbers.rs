//! Refused files whose numbers are out of range or not allowed: beyond f64 or i64, not finite,
//! not positive, zero aileron authority.

use super::*;

pub(super) fn number_refusals() -> Vec<Refusal> {
    let digits = "7".repeat(400);
    vec![
        refused(
            "a NaN",
            replace("n_r = -0.2608", "n_r = nan"),
            17,
            &["derivatives.n_r", "expected a finite number", "`nan`"],
        )
        .kind(is!(NotFinite))
        .column(7),
        refused(
            "a negative infinity",
            replace("E = 0.705", "E = -inf"),
            5,
            &["inertia.E", "expected a finite number", "`-inf`"],
        )
        .kind(is!(NotFinite)),
        refused(
            "an infinite speed",
            replace("speed = 150.0", "speed = +inf"),
            21,
            &["flight.speed", "finite"],
        ),
        refused(
            "a zero aileron authority written 0",
            replace("l_delta_a = -327.28", "l_delta_a = 0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "a zero aileron authority written 0.0",
            replace("l_delta_a = -327.28", "l_delta_a = 0.0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "a zero aileron authority written -0.0",
            replace("l_delta_a = -327.28", "l_delta_a = -0.0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "an integer beyond i64",
            replace("l_p = -21.7529", "l_p = 99999999999999999999"),
            9,
            &[
                "key `derivatives.l_p`",
                "expected an integer within the 64-bit range",
            ],
        )
        .kind(is!(InvalidValue))
        .column(7),
        refused(
            "a float beyond f64",
            replace("m_q = -1.815", "m_q = 1e309"),
            13,
            &["key `derivatives.m_q`", "range of f64", "`1e309`"],
        ),
        refused(
            "a 400-digit integer, shown shortened",
            replace("m_q = -1.815", &format!("m_q = {digits}")),
            13,
            &["key `derivatives.m_q`", "64-bit range", "(400 characters)"],
        )
        .shorter_than(400),
        refused(
            "a 400-digit float",
            replace("m_q = -1.815", &format!("m_q = {digits}.5")),
            13,
            &["key `derivatives.m_q`", "range of f64"],
        ),
        refused(
            "a speed beyond f64",
            replace("speed = 150.0", "speed = -1e400"),
            21,
            &["flight.speed", "finite"],
        ),
        // accepted by the parser as 0.0, but the literal is beyond exact reading
        refused(
            "an exponent beyond exact reading",
            replace("m_q = -1.815", "m_q = 1e-100000"),
            13,
            &["derivatives.m_q", "range of f64"],
        ),
        // inside an inline table the key is still found
        refused(
            "a float beyond f64 in an inline table",
            replace(CDE, "").replacen(
                "[inertia]\n",
                "inertia = { ix = 1, iy = 1e999, iz = 3 }\n",
                1,
            ),
            2,
            &["key `inertia.iy`", "range of f64"],
        ),
        refused(
            "a speed whose g/V leaves f64 (subnormal)",
            replace("speed = 150.0", "speed = 1e-320"),
            21,
            &["key `flight.speed`", "g/V", "1e-320"],
        ),
        refused(
            "a speed whose g/V leaves f64 (below f64)",
            replace("speed = 150.0", "speed = 1e-400"),
            21,
            &["key `flight.speed`", "g/V", "1e-400"],
        ),
        refused(
            "a zero speed",
            replace("speed = 150.0", "speed = 0"),
            21,
            &["flight.speed", "expected a speed in m/s > 0", "`0`"],
        )
        .kind(is!(InvalidSpeed)),
        refused(
            "a negative speed",
            replace("speed = 150.0", "speed = -3.5"),
            21,
            &["flight.speed", "> 0"],
        ),
    ]
}
