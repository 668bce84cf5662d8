//! The optional `[uncertainty]` table: an exact interval for each uncertain parameter.
//!
//! ```toml
//! [uncertainty]
//! l_p = "10%"              # relative: nominal +- 10 % of |nominal|
//! n_beta = 0.5             # absolute half-width: nominal +- 0.5
//! l_beta = [-115.0, -105.0] # an interval [lo, hi], lo <= hi
//! ```
//!
//! Keys are those of [`Param::ALL`] in a dimensional file (its `[inertia]` C, D, E and
//! `[derivatives]`), and the `[coefficients]` keys in a nondimensional body-axis file. Every
//! end is exact (the literals as written). Rejected, with file, line and key: an unknown key, a
//! negative width or percentage, an empty interval (lo > hi), an interval of `l_delta_a` that
//! contains zero, or coefficient intervals that let it reach zero (that flips the sign of the
//! aileron authority), and an interval of C, D or E outside [-1, 1] (no rigid body has such an
//! inertia coefficient: the triangle inequalities of the principal moments bound |C|, |D|, |E|
//! by 1).
//!
//! A nondimensional file's coefficient enters the model through the conversion of
//! [`convert`](crate::aircraft::convert), which is linear in the coefficients. A coefficient that
//! moves one derivative (every one with `ixz = 0`; with `ixz != 0` those the principal-axis
//! rotation leaves alone: `CL_alpha`, `CY_beta`, the `Cm`) becomes that derivative's interval,
//! the conversion of its two ends. One that moves several (with `ixz != 0` the rotation mixes
//! `Cl_x` and `Cn_x` into both `l_x` and `n_x`) is a coordinate of its own: its interval, its
//! nominal value and the exact slope of each derivative it moves ([`CoefficientMap`]).

use super::{qualified, shorten, AircraftError, Cx, Key, Kind, Node, Table};
use crate::aircraft::convert::{convert, slopes, BodyAxisInput, Coefficient, Converted};
use crate::aircraft::{decimal_to_rational, Aircraft, CoefficientMap, Param, Uncertain};
use crate::interval::I;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

impl Cx<'_> {
    /// `[uncertainty]` of a dimensional file: the interval of each parameter named, in the
    /// order written.
    pub(super) fn uncertainty(
        &self,
        table: &Table<'_>,
        aircraft: &Aircraft,
    ) -> Result<Vec<Uncertain>, AircraftError> {
        let mut out = Vec::new();
        for (key, value) in table.entries {
            let param = Param::ALL
                .iter()
                .copied()
                .find(|p| p.key() == key.name)
                .ok_or_else(|| self.unknown_uncertain(table, key, false))?;
            let (lo, hi) = self.interval(table, key, value, aircraft.exact(param))?;
            out.push(self.checked(table, key, value, param, lo, hi)?);
        }
        Ok(out)
    }

    /// `[uncertainty]` of a nondimensional body-axis file: the interval of each coefficient
    /// that moves one derivative, converted (by the same [`convert`] as the nominal data) to
    /// that derivative's interval; each coefficient that moves several (`ixz != 0`, decided by
    /// its exact slopes) as a coordinate of its own.
    pub(super) fn body_axis_uncertainty(
        &self,
        table: &Table<'_>,
        input: &BodyAxisInput,
        converted: &Converted,
    ) -> Result<Vec<Uncertain>, AircraftError> {
        let mut out = Vec::new();
        // The last coefficient coordinate that moves l_delta_a, for the joint check below.
        let mut aileron: Option<(&Key, &Node)> = None;
        for (key, value) in table.entries {
            let c = Coefficient::ALL
                .iter()
                .copied()
                .find(|c| c.key() == key.name)
                .ok_or_else(|| self.unknown_uncertain(table, key, true))?;
            let (lo, hi) = self.interval(table, key, value, input.coefficient(c))?;
            let param = c.derivative();
            let moves = slopes(input, c);
            if moves.iter().any(|(p, _)| *p != param) {
                // Several derivatives move together: the coordinate is the coefficient.
                if moves.iter().any(|(p, _)| *p == Param::LDeltaA) {
                    aileron = Some((key, value));
                }
                out.push(Uncertain {
                    param,
                    lo,
                    hi,
                    coefficient: Some(CoefficientMap {
                        key: c.key(),
                        nominal: input.coefficient(c).clone(),
                        moves,
                    }),
                });
                continue;
            }
            let at = |x: &BigRational| {
                let mut i = input.clone();
                i.coefficients[c as usize] = x.clone();
                convert(&i)
            };
            let (at_lo, at_hi) = (at(&lo), at(&hi));
            let (a, b) = (at_lo.derivative(param), at_hi.derivative(param));
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            out.push(self.checked(table, key, value, param, lo.clone(), hi.clone())?);
        }
        // The aileron authority keeps its sign over the whole box: l_delta_a's exact range,
        // its nominal value plus each coefficient's extreme moves.
        if let Some((key, value)) = aileron {
            let nominal = converted.derivative(Param::LDeltaA).clone();
            let (lo, hi) = out
                .iter()
                .filter_map(|u| Some((u, u.coefficient.as_ref()?)))
                .flat_map(|(u, c)| {
                    c.moves
                        .iter()
                        .filter(|(p, _)| *p == Param::LDeltaA)
                        .map(move |(_, a)| {
                            let (x, y) = (a * (&u.lo - &c.nominal), a * (&u.hi - &c.nominal));
                            if x <= y {
                                (x, y)
                            } else {
                                (y, x)
                            }
                        })
                })
                .fold((nominal.clone(), nominal), |(lo, hi), (x, y)| {
                    (lo + x, hi + y)
                });
            if !keeps_sign(&lo, &hi) {
                return Err(AircraftError::InvalidValue {
                    at: self.at_value(key, value),
                    key: qualified(table.name, &key.name),
                    expected: "coefficient intervals that keep the sign of l_delta_a over the \
                               box (0 inside flips the sign of the aileron authority)"
                        .to_string(),
                    value: format!("l_delta_a in [{}, {}]", show(&lo), show(&hi)),
                });
            }
        }
        Ok(out)
    }

    /// The interval `[lo, hi]` written for `key`: a relative `"10%"` or an absolute half-width
    /// about `nominal`, or the two ends.
    fn interval(
        &self,
        table: &Table<'_>,
        key: &Key,
        value: &Node,
        nominal: &BigRational,
    ) -> Result<(BigRational, BigRational), AircraftError> {
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
                (nominal - &half, nominal + &half)
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
                (nominal - &n.exact, nominal + &n.exact)
            }
        };
        // A width written within f64 can still carry an end past it ("1e310%", or an end just
        // above f64::MAX, which rounds to MAX but is enclosed up to infinity): each end is
        // enclosed as the proof encloses it.
        let finite = |q: &BigRational| {
            let i = I::from_q(q);
            i.lo.is_finite() && i.hi.is_finite()
        };
        if !(finite(&lo) && finite(&hi)) {
            return Err(bad(
                "an interval whose ends are finite doubles (nominal -/+ the width leaves the \
                 range of f64)",
                self.written(value),
            ));
        }
        Ok((lo, hi))
    }

    /// `param` in `[lo, hi]`, or the error (at `key`) for an interval that flips the sign of
    /// l_delta_a or makes the inertia unphysical.
    fn checked(
        &self,
        table: &Table<'_>,
        key: &Key,
        value: &Node,
        param: Param,
        lo: BigRational,
        hi: BigRational,
    ) -> Result<Uncertain, AircraftError> {
        let bad = |expected: &str| AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table.name, &key.name),
            expected: expected.to_string(),
            value: format!("[{}, {}]", show(&lo), show(&hi)),
        };
        if param == Param::LDeltaA && !keeps_sign(&lo, &hi) {
            return Err(bad(
                "an interval of l_delta_a that keeps its sign (0 inside flips the sign of the \
                 aileron authority)",
            ));
        }
        if matches!(param, Param::C | Param::D | Param::E) {
            let one = BigRational::one();
            if hi > one || lo < -one {
                return Err(bad(
                    "an inertia coefficient interval within [-1, 1] (the triangle inequalities \
                     of the principal moments; outside, the inertia is unphysical)",
                ));
            }
        }
        Ok(Uncertain::param(param, lo, hi))
    }

    /// The unknown-key error of `[uncertainty]`, listing the keys of the file's format (and
    /// saying where a key of the other format belongs).
    fn unknown_uncertain(&self, table: &Table<'_>, key: &Key, body_axis: bool) -> AircraftError {
        let params: Vec<&str> = Param::ALL.iter().map(|p| p.key()).collect();
        let coefficients: Vec<&str> = Coefficient::ALL.iter().map(|c| c.key()).collect();
        let (own, other, other_format) = if body_axis {
            (coefficients, params, "a dimensional file's")
        } else {
            (params, coefficients, "a nondimensional file's")
        };
        let hint = if other.contains(&key.name.as_str()) {
            Some(format!(
                "`{}` is {other_format} key; this file takes its uncertainty per {}",
                key.name,
                if body_axis {
                    "coefficient"
                } else {
                    "derivative and C, D, E"
                }
            ))
        } else {
            super::suggestion_among(&own, &key.name)
        };
        AircraftError::UnknownKey {
            at: self.at_key(key),
            key: qualified(table.name, &key.name),
            hint,
            expected: super::list(&own),
        }
    }

    fn end(&self, table: &Table<'_>, key: &Key, node: &Node) -> Result<BigRational, AircraftError> {
        self.number(table.name, key, node).map(|n| n.exact)
    }
}

/// Whether every value of `[lo, hi]` has the same nonzero sign (the aileron authority l_delta_a
/// may not vanish or flip anywhere in the box).
fn keeps_sign(lo: &BigRational, hi: &BigRational) -> bool {
    !lo.is_zero() && !hi.is_zero() && lo.is_negative() == hi.is_negative()
}

fn show(q: &BigRational) -> String {
    format!("{}", crate::aircraft::rational_to_f64(q))
}
