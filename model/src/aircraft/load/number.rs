//! Numbers as the exact rationals of the literals written: a TOML integer or decimal, or a
//! string `"p/q"`, each also rounded to f64 and kept as written for messages.

use super::super::{decimal_to_rational, f64_to_rational, rational_to_f64};
use super::{qualified, shorten, AircraftError, Cx, Key, Kind, Node, Table};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::str::FromStr;

/// A number as read: exact, rounded, and as written.
pub(super) struct Number {
    pub(super) exact: BigRational,
    pub(super) float: f64,
    pub(super) written: String,
}

/// A string `"p/q"` (optional sign, decimal integers, q != 0) as the exact fraction it denotes.
fn fraction_to_rational(s: &str) -> Option<BigRational> {
    let (p, q) = s.trim().split_once('/')?;
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let unsigned = p.strip_prefix(['-', '+']).unwrap_or(p);
    if !digits(unsigned) || !digits(q) || q.len() > 1000 || p.len() > 1000 {
        return None;
    }
    let q = BigInt::from_str(q).ok()?;
    if q.is_zero() {
        return None;
    }
    Some(BigRational::new(BigInt::from_str(p).ok()?, q))
}

/// What a number key accepts when the literal cannot be read as a finite f64-range number.
pub(super) const F64_RANGE: &str =
    "a finite number within the range of f64 (magnitude at most 1.7976931348623157e308)";
pub(super) const I64_RANGE: &str = "an integer within the 64-bit range (-9223372036854775808 to \
     9223372036854775807; write larger magnitudes as decimals, e.g. `1.5e20`)";

impl Cx<'_> {
    pub(super) fn number(
        &self,
        table: &str,
        key: &Key,
        value: &Node,
    ) -> Result<Number, AircraftError> {
        let written = self.written(value);
        let out_of_range = |expected: &str| AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table, &key.name),
            expected: expected.to_string(),
            value: shorten(&written),
        };
        let exact = match &value.kind {
            Kind::Integer(i) => BigRational::from_integer(BigInt::from(*i)),
            Kind::Float(x) if !x.is_finite() => {
                return Err(AircraftError::NotFinite {
                    at: self.at_value(key, value),
                    key: qualified(table, &key.name),
                    value: written,
                })
            }
            // The literal as written (in full: `written` is shortened for messages), never the
            // f64 the parser made of it.
            Kind::Float(x) => match value.span.as_ref().and_then(|s| self.text.get(s.clone())) {
                Some(literal) => decimal_to_rational(&literal.trim().replace('_', ""))
                    .ok_or_else(|| out_of_range(F64_RANGE))?,
                None => f64_to_rational(*x).ok_or_else(|| out_of_range(F64_RANGE))?,
            },
            Kind::String(s) if s.contains('/') => fraction_to_rational(s).ok_or_else(|| {
                out_of_range(
                    "a number, or an exact fraction as a string `\"p/q\"` with decimal \
                     integers p and q, q != 0",
                )
            })?,
            other => {
                return Err(AircraftError::WrongType {
                    at: self.at_value(key, value),
                    key: qualified(table, &key.name),
                    expected: "a number",
                    found: other.describe(),
                })
            }
        };
        let float = rational_to_f64(&exact);
        if !float.is_finite() {
            return Err(out_of_range(F64_RANGE));
        }
        Ok(Number {
            exact,
            float,
            written,
        })
    }

    /// A number that must be > 0 (and, through [`Cx::number`], finite).
    pub(super) fn positive(
        &self,
        table: &Table<'_>,
        entry: &(Key, Node),
        expected: &str,
    ) -> Result<Number, AircraftError> {
        let (key, value) = entry;
        let n = self.number(table.name, key, value)?;
        if !n.exact.is_positive() {
            return Err(AircraftError::InvalidValue {
                at: self.at_value(key, value),
                key: qualified(table.name, &key.name),
                expected: expected.to_string(),
                value: shorten(&n.written),
            });
        }
        Ok(n)
    }

    /// A required key that must be > 0.
    pub(super) fn required_positive(
        &self,
        table: &Table<'_>,
        key: &str,
        what: &str,
    ) -> Result<Number, AircraftError> {
        let entry = table
            .get(key)
            .ok_or_else(|| self.missing_key(table, key, format!("`{key} = <number>`, {what}")))?;
        self.positive(table, entry, what)
    }
}
