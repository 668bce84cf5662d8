//! The optional `[uncertainty]` table: an exact interval for each uncertain parameter.
//!
//! ```toml
//! [uncertainty]
//! l_p = "10%"              # relative: nominal +- 10 % of |nominal|
//! n_beta = 0.5             # absolute half-width: nominal +- 0.5
//! l_beta = [-115.0, -105.0] # an interval [lo, hi], lo <= hi
//! ```
//!
//! Keys are those of [`Param::ALL`] (the dimensional file's `[inertia]` C, D, E and
//! `[derivatives]`). Every end is exact (the literals as written). Rejected, with file, line and
//! key: an unknown key, a negative width or percentage, an empty interval (lo > hi), an interval
//! of `l_delta_a` that contains zero (flips the sign of the aileron authority), and an interval of
//! C, D or E outside [-1, 1] (no rigid body has such an inertia coefficient: the triangle
//! inequalities of the principal moments bound |C|, |D|, |E| by 1).

use super::{qualified, shorten, AircraftError, Cx, Key, Kind, Node, Table};
use crate::aircraft::{decimal_to_rational, Aircraft, Param, Uncertain};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// The error for an `[uncertainty]` table in a nondimensional file (not supported yet).
pub(super) fn not_in_body_axis(cx: &Cx<'_>, key: &Key) -> AircraftError {
    AircraftError::InvalidValue {
        at: cx.at_key(key),
        key: "uncertainty".to_string(),
        expected: "an `[uncertainty]` table only in a dimensional principal-axis file (per \
                   derivative and C, D, E; write the file with `model convert` first)"
            .to_string(),
        value: "[uncertainty]".to_string(),
    }
}

impl Cx<'_> {
    /// `[uncertainty]`: the interval of each parameter named, in the order written.
    pub(super) fn uncertainty(
        &self,
        _key: &Key,
        table: &Table<'_>,
        aircraft: &Aircraft,
    ) -> Result<Vec<Uncertain>, AircraftError> {
        let mut out = Vec::new();
        for (key, value) in table.entries {
            let param = Param::ALL
                .iter()
                .copied()
                .find(|p| p.key() == key.name)
                .ok_or_else(|| self.unknown(table.name, key))?;
            let nominal = aircraft.exact(param).clone();
            let bad = |expected: &str, written: String| AircraftError::InvalidValue {
                at: self.at_value(key, value),
                key: qualified(table.name, &key.name),
                expected: expected.to_string(),
                value: shorten(&written),
            };
            let (lo, hi) = match &value.kind {
                Kind::String(s) if s.trim().ends_with('%') => {
                    let pct = s.trim().trim_end_matches('%').trim();
                    let r = decimal_to_rational(pct)
                        .ok_or_else(|| bad("a relative uncertainty such as \"10%\"", s.clone()))?;
                    if r.is_negative() {
                        return Err(bad("a percentage >= 0 (a negative width)", s.clone()));
                    }
                    let half = nominal.abs() * r / BigRational::from_integer(BigInt::from(100));
                    (&nominal - &half, &nominal + &half)
                }
                Kind::Array(items) => {
                    let ends: Vec<BigRational> = match items.as_slice() {
                        [a, b] => vec![self.end(table, key, a)?, self.end(table, key, b)?],
                        _ => {
                            return Err(bad(
                                "an interval of two numbers [lo, hi]",
                                self.written(value),
                            ))
                        }
                    };
                    if ends[0] > ends[1] {
                        return Err(bad(
                            "a non-empty interval [lo, hi] with lo <= hi",
                            self.written(value),
                        ));
                    }
                    (ends[0].clone(), ends[1].clone())
                }
                _ => {
                    let n = self.number(table.name, key, value).map_err(|_| {
                        bad(
                            "a relative uncertainty \"10%\", an absolute half-width >= 0, or an \
                             interval [lo, hi]",
                            self.written(value),
                        )
                    })?;
                    if n.exact.is_negative() {
                        return Err(bad("a half-width >= 0 (a negative width)", n.written));
                    }
                    (&nominal - &n.exact, &nominal + &n.exact)
                }
            };
            let range = format!("[{}, {}]", show(&lo), show(&hi));
            if param == Param::LDeltaA
                && (lo.is_zero() || hi.is_zero() || lo.is_negative() != hi.is_negative())
            {
                return Err(bad(
                    "an interval of l_delta_a that keeps its sign (0 inside flips the sign of \
                     the aileron authority)",
                    range,
                ));
            }
            if matches!(param, Param::C | Param::D | Param::E) {
                let one = BigRational::one();
                if hi > one || lo < -one {
                    return Err(bad(
                        "an inertia coefficient interval within [-1, 1] (the triangle \
                         inequalities of the principal moments; outside, the inertia is \
                         unphysical)",
                        range,
                    ));
                }
            }
            out.push(Uncertain { param, lo, hi });
        }
        Ok(out)
    }

    fn end(&self, table: &Table<'_>, key: &Key, node: &Node) -> Result<BigRational, AircraftError> {
        self.number(table.name, key, node).map(|n| n.exact)
    }
}

fn show(q: &BigRational) -> String {
    format!("{}", crate::aircraft::rational_to_f64(q))
}
