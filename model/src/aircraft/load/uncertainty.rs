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
//! end is exact (the literals as written). A relative width is one number followed by exactly
//! one `%` (whitespace allowed around either). Rejected, with file, line and key: an unknown
//! key, a string that is no such percentage, a negative width or percentage, an empty interval
//! (lo > hi), ends beyond f64, an interval of `l_delta_a` that contains zero, or coefficient
//! intervals that let it reach zero (that flips the sign of the aileron authority), an interval
//! of C, D or E outside [-1, 1] (no rigid body has such an inertia coefficient: the triangle
//! inequalities of the principal moments bound |C|, |D|, |E| by 1), and a box that takes a
//! derivative beyond [`SANE_FACTOR`] times the largest nominal derivative magnitude ([`Sane`]).
//! C, D and E move independently in a box: the consistency of the three (`inertia.rs`) is a
//! condition on the nominal aircraft only.
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
        let sane = Sane::of(Param::ALL.iter().skip(3).map(|p| (*p, aircraft.exact(*p))));
        let mut out = Vec::new();
        for (key, value) in table.entries {
            let param = Param::ALL
                .iter()
                .copied()
                .find(|p| p.key() == key.name)
                .ok_or_else(|| self.unknown_uncertain(table, key, false))?;
            let (lo, hi) = self.interval(table, key, value, aircraft.exact(param))?;
            out.push(self.checked(table, (key, value), param, (lo, hi), &sane)?);
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
        let sane = Sane::of(
            Param::ALL
                .iter()
                .skip(3)
                .map(|p| (*p, converted.derivative(*p))),
        );
        let mut out = Vec::new();
        // The entries of the coefficient coordinates, for the joint check below.
        let mut coordinates: Vec<(&Key, &Node, usize)> = Vec::new();
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
                coordinates.push((key, value, out.len()));
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
                convert(&i).derivative(param).clone()
            };
            let (a, b) = (at(&lo), at(&hi));
            let ends = if a <= b { (a, b) } else { (b, a) };
            out.push(self.checked(table, (key, value), param, ends, &sane)?);
        }
        for p in Param::ALL.iter().skip(3) {
            self.joint_range(table, *p, &coordinates, &out, converted, &sane)?;
        }
        Ok(out)
    }

    /// The exact range of derivative `p` over the box of the coefficient coordinates (its
    /// nominal value plus each coordinate's extreme moves), refused, at the coordinate that
    /// moves it most, when it may make the aileron authority vanish or leaves the sane range.
    fn joint_range(
        &self,
        table: &Table<'_>,
        p: Param,
        coordinates: &[(&Key, &Node, usize)],
        out: &[Uncertain],
        converted: &Converted,
        sane: &Sane,
    ) -> Result<(), AircraftError> {
        let moves: Vec<(&Key, &Node, BigRational, BigRational)> = coordinates
            .iter()
            .filter_map(|&(key, value, i)| {
                let u = &out[i];
                let c = u.coefficient.as_ref()?;
                let (_, a) = c.moves.iter().find(|(q, _)| *q == p)?;
                let (x, y) = (a * (&u.lo - &c.nominal), a * (&u.hi - &c.nominal));
                Some(if x <= y {
                    (key, value, x, y)
                } else {
                    (key, value, y, x)
                })
            })
            .collect();
        let Some((key, value, _, _)) = moves
            .iter()
            .max_by(|a, b| (&a.3 - &a.2).cmp(&(&b.3 - &b.2)))
        else {
            return Ok(());
        };
        let nominal = converted.derivative(p);
        let lo = moves.iter().fold(nominal.clone(), |s, m| s + &m.2);
        let hi = moves.iter().fold(nominal.clone(), |s, m| s + &m.3);
        let bad = |expected: String| AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table.name, &key.name),
            expected,
            value: format!("{} in [{}, {}]", p.key(), show(&lo), show(&hi)),
        };
        if p == Param::LDeltaA && !keeps_sign(&lo, &hi) {
            return Err(bad(
                "coefficient intervals that keep the sign of l_delta_a over the box (0 inside \
                 flips the sign of the aileron authority)"
                    .to_string(),
            ));
        }
        if !sane.contains(&lo, &hi) {
            return Err(bad(sane.expected()));
        }
        Ok(())
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
            Kind::String(s) if s.contains('%') => {
                let r = percentage(s).ok_or_else(|| {
                    bad(
                        "a relative uncertainty: one number followed by exactly one `%` \
                         (whitespace allowed around either), e.g. \"10%\"",
                        self.written(value),
                    )
                })?;
                if r.is_negative() {
                    return Err(bad(
                        "a percentage >= 0 (a negative width)",
                        self.written(value),
                    ));
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

    /// `param` in `[lo, hi]`, or the error (at `key`) for an interval that leaves the sane
    /// range, flips the sign of l_delta_a or makes the inertia unphysical.
    fn checked(
        &self,
        table: &Table<'_>,
        (key, value): (&Key, &Node),
        param: Param,
        (lo, hi): (BigRational, BigRational),
        sane: &Sane,
    ) -> Result<Uncertain, AircraftError> {
        let bad = |expected: &str| AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table.name, &key.name),
            expected: expected.to_string(),
            value: if key.name == param.key() {
                format!("[{}, {}]", show(&lo), show(&hi))
            } else {
                format!("{} in [{}, {}]", param.key(), show(&lo), show(&hi))
            },
        };
        let inertia = matches!(param, Param::C | Param::D | Param::E);
        if !inertia && !sane.contains(&lo, &hi) {
            return Err(bad(&sane.expected()));
        }
        if param == Param::LDeltaA && !keeps_sign(&lo, &hi) {
            return Err(bad(
                "an interval of l_delta_a that keeps its sign (0 inside flips the sign of the \
                 aileron authority)",
            ));
        }
        if inertia {
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

/// The number of a relative width: one number followed by exactly one `%`, whitespace allowed
/// around either.
fn percentage(s: &str) -> Option<BigRational> {
    let number = s.trim().strip_suffix('%')?;
    if number.contains('%') {
        return None;
    }
    decimal_to_rational(number)
}

/// How far beyond the nominal aircraft's scale a box may take a derivative.
const SANE_FACTOR: i64 = 1000;

/// The range every derivative of a box must stay within: [`SANE_FACTOR`] times the largest
/// magnitude among the nominal aircraft's derivatives (its scale, in its own units; nonzero,
/// since l_delta_a is). Beyond it a box is no uncertainty of this aircraft but other aircraft,
/// and the powers of its ends that the proof's interval arithmetic forms run out of f64 (a
/// width of "1e300%" has finite ends, yet no proof over it means anything).
struct Sane {
    /// The nominal derivative of largest magnitude.
    largest: Param,
    /// Its magnitude.
    magnitude: BigRational,
}

impl Sane {
    fn of<'q>(derivatives: impl Iterator<Item = (Param, &'q BigRational)>) -> Sane {
        let (largest, magnitude) = derivatives
            .map(|(p, v)| (p, v.abs()))
            .max_by(|a, b| a.1.cmp(&b.1))
            .unwrap_or((Param::LDeltaA, BigRational::one()));
        Sane { largest, magnitude }
    }

    fn bound(&self) -> BigRational {
        &self.magnitude * BigRational::from_integer(BigInt::from(SANE_FACTOR))
    }

    fn contains(&self, lo: &BigRational, hi: &BigRational) -> bool {
        let bound = self.bound();
        -&bound <= *lo && *hi <= bound
    }

    fn expected(&self) -> String {
        format!(
            "a box whose derivatives stay within {SANE_FACTOR} times the largest nominal \
             derivative magnitude (|{}| = {}: within [-{b}, {b}]), so that it is an uncertainty \
             of this aircraft and the proof's arithmetic stays within f64",
            self.largest.key(),
            show(&self.magnitude),
            b = show(&self.bound()),
        )
    }
}

/// Whether every value of `[lo, hi]` has the same nonzero sign (the aileron authority l_delta_a
/// may not vanish or flip anywhere in the box).
fn keeps_sign(lo: &BigRational, hi: &BigRational) -> bool {
    !lo.is_zero() && !hi.is_zero() && lo.is_negative() == hi.is_negative()
}

/// An end for messages: as f64, in scientific notation when its digits would be many.
fn show(q: &BigRational) -> String {
    let x = crate::aircraft::rational_to_f64(q);
    if x != 0.0 && !(1e-4..1e16).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
