//! Whether the inertia coefficients `C`, `D`, `E` of a dimensional file are those of one rigid
//! body.
//!
//! The three coefficients are ratios of only two independent quantities (the moments up to
//! scale): C = (iz - ix)/iy and D = (iy - ix)/iz solve to iy/ix = (1 + D)/(1 - C D) and
//! iz/ix = (1 + C)/(1 - C D), so E = (iz - iy)/ix = (C - D)/(1 - C D), or, without the division,
//! r(C, D, E) = C - D - E + C D E = 0. Within [-1, 1]^3 (the triangle inequalities, checked
//! before) the zero set of r is the closure of the coefficients of rigid bodies: with
//! C = tanh a and D = tanh b it is E = tanh(a - b), plus the lines C = D = -1 (laminae in the
//! y-z plane, ix = iy + iz, any E) and C = D = 1 (the limit of ever more slender bodies).
//!
//! Tabled coefficients are rounded (Table A.1 gives three decimals: aircraft A's C and D imply
//! E = 0.7026, the table says 0.705), so a file passes when some point within
//! [`INERTIA_TOLERANCE`] of its C, D, E in each coordinate lies on that zero set. r is affine in
//! each coordinate, so over that box it takes its extremes at the corners: there is a zero iff
//! the corners do not all have one sign. C = D = 1 exactly is refused: it makes ix = 0.
//!
//! Only the nominal aircraft is checked: an `[uncertainty]` box moves C, D and E independently,
//! so most of its points are no rigid body's (the proof covers them as data, not as bodies).

use super::{AircraftError, Cx, Key, Node, Number, Table};
use crate::aircraft::rational_to_f64;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// How far from those of one rigid body each of `C`, `D`, `E` may be: twice the rounding of
/// data given to three decimals, as in Table A.1.
pub(super) const INERTIA_TOLERANCE: &str = "0.001";

impl Cx<'_> {
    /// Refuses `C`, `D`, `E` (read from `table`, each within [-1, 1]) that no rigid body has
    /// to within [`INERTIA_TOLERANCE`], naming the keys and the E that C and D imply.
    pub(super) fn one_rigid_body(
        &self,
        table: &Table<'_>,
        given: &[(&Key, &Node, Number)],
    ) -> Result<(), AircraftError> {
        let entry = |k: &str| given.iter().find(|(key, _, _)| key.name == k);
        let (Some(c), Some(d), Some(e)) = (entry("C"), entry("D"), entry("E")) else {
            return Ok(());
        };
        let key = |k: &Key| format!("`{}.{}`", table.name, k.name);
        let one = BigRational::one();
        if c.2.exact == one && d.2.exact == one {
            return Err(AircraftError::InconsistentInertia {
                at: self.at_value(d.0, d.1),
                problem: format!(
                    "{} = {} and {} = {} make ix = 0 (iz = ix + iy and iy = ix + iz): a rod \
                     along x, not a rigid body, for which E = (iz - iy)/ix is undefined",
                    key(c.0),
                    c.2.written,
                    key(d.0),
                    d.2.written
                ),
            });
        }
        if near_a_rigid_body([&c.2.exact, &d.2.exact, &e.2.exact]) {
            return Ok(());
        }
        Err(AircraftError::InconsistentInertia {
            at: self.at_value(e.0, e.1),
            problem: format!(
                "{} = {}, {} = {}, {} = {} are no rigid body's: C and D imply E = (C - D)/(1 - C \
                 D) = {}",
                key(c.0),
                c.2.written,
                key(d.0),
                d.2.written,
                key(e.0),
                e.2.written,
                implied_e(&c.2.exact, &d.2.exact)
            ),
        })
    }
}

/// Whether some point within [`INERTIA_TOLERANCE`] of `[c, d, e]` in each coordinate (and
/// within [-1, 1]) has r = C - D - E + C D E = 0: whether the corners of that box do not all
/// give r one sign.
fn near_a_rigid_body(cde: [&BigRational; 3]) -> bool {
    let tolerance = BigRational::new(1.into(), 1000.into());
    let one = BigRational::one();
    let ends = |x: &BigRational| {
        [
            (x - &tolerance).max(-one.clone()),
            (x + &tolerance).min(one.clone()),
        ]
    };
    let [cs, ds, es] = cde.map(ends);
    let r = |c: &BigRational, d: &BigRational, e: &BigRational| c - d - e + c * d * e;
    let values: Vec<BigRational> = cs
        .iter()
        .flat_map(|c| ds.iter().map(move |d| (c, d)))
        .flat_map(|(c, d)| es.iter().map(move |e| r(c, d, e)))
        .collect();
    values.iter().any(|v| !v.is_positive()) && values.iter().any(|v| !v.is_negative())
}

/// (C - D)/(1 - C D) to four decimals, for messages.
fn implied_e(c: &BigRational, d: &BigRational) -> String {
    let denominator = BigRational::one() - c * d;
    if denominator.is_zero() {
        return "undefined (C = D = -1: a lamina in the y-z plane, any E)".to_string();
    }
    let e = rational_to_f64(&((c - d) / denominator));
    format!("{}", (e * 1e4).round() / 1e4 + 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> BigRational {
        crate::aircraft::decimal_to_rational(s).unwrap()
    }

    #[test]
    fn coefficients_of_moments_lie_on_the_relation_exactly() {
        // ix = 2, iy = 5, iz = 6: C = 4/5, D = 3/6, E = 1/2, and (C - D)/(1 - C D) = 0.3/0.6
        let (c, d, e) = (q("0.8"), q("0.5"), q("0.5"));
        assert!((&c - &d - &e + &c * &d * &e).is_zero());
        assert_eq!(implied_e(&c, &d), "0.5");
        assert!(near_a_rigid_body([&c, &d, &e]));
        assert!(!near_a_rigid_body([&c, &d, &q("0.52")]));
    }

    #[test]
    fn table_a1_is_within_the_tolerance() {
        assert_eq!(implied_e(&q("0.959"), &q("0.786")), "0.7026");
        assert!(near_a_rigid_body([&q("0.959"), &q("0.786"), &q("0.705")]));
        assert!(near_a_rigid_body([&q("0.949"), &q("0.716"), &q("0.727")]));
    }
}
