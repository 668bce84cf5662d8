//! The criterion at a roll rate that is itself a number ([`OnCurve`]): a function of another
//! parameter of the walk along a branch, with its derivatives in that parameter.
//!
//! Where the primary branch turns in P0, the walk follows it in delta_a instead
//! ([`super::turn`]): the roll rate on the branch is then a function `P0(delta_a)`, enclosed
//! with its derivatives in delta_a over a piece ([`super::slope::Taylor2`]) or at one aileron
//! ([`super::slope::Slope`]). Every lifted polynomial in P0 is evaluated at that number by
//! Horner's scheme in its arithmetic, which applies the chain rule: the results carry their
//! derivatives along the branch in delta_a, as [`super::mode::OverPiece`]'s carry them in P0.

use super::dense::Dense2;
use super::elimination::Scalar;
use super::mode::{in_aileron_each, Da, Mode};
use super::num::Num;
use crate::derivation::Clearing;
use crate::interval::I;
use std::borrow::Cow;

/// The criterion at the roll rate `.0`, a number `T` (with derivatives in the walk's
/// parameter): values are polynomials in delta_a with coefficients `T`.
pub(super) struct OnCurve<T>(pub(super) T);

impl<T: Num> Clearing for OnCurve<T> {
    type Value = Da<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Da<T> {
        Da::lift(p)
    }
    fn add(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.add(b)
    }
    fn mul(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.mul(b)
    }
}

impl<T: Num> Mode for OnCurve<T> {
    type Num = I;
    type Coef = Scalar<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<I>) -> Cow<'a, Da<T>> {
        Cow::Owned(in_aileron_each(&p.0, |c| {
            c.0.iter().rev().fold(T::constant(I::point(0.0)), |acc, k| {
                acc * self.0 + T::constant(*k)
            })
        }))
    }
    fn in_aileron(v: &Da<T>) -> Vec<Scalar<T>> {
        v.c[..v.len].iter().map(|c| Scalar(*c)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certified::dense::Dense;
    use crate::certified::slope::Taylor2;

    /// `(1 + 2 P0^2) + (3 P0) delta_a` at `P0 = p(s) = s^2` (s over [0.9, 1.1]): the
    /// coefficients' values and derivatives in `s` by the chain rule, computed by hand:
    /// `1 + 2 s^4` (derivatives `8 s^3`, `24 s^2`) and `3 s^2` (`6 s`, `6`).
    #[test]
    fn lifted_polynomials_carry_the_chain_rule() {
        let s = I::new(0.9, 1.1);
        let p = Taylor2::variable(s) * Taylor2::variable(s);
        let poly = Dense2(vec![
            Dense(vec![I::point(1.0), I::point(0.0), I::point(2.0)]),
            Dense(vec![I::point(0.0), I::point(3.0)]),
        ]);
        let da = OnCurve(p).lifted(&poly);
        assert_eq!(da.len, 2);
        for x in [0.9_f64, 1.0, 1.1] {
            let want = [
                [1.0 + 2.0 * x.powi(4), 8.0 * x.powi(3), 24.0 * x * x],
                [3.0 * x * x, 6.0 * x, 6.0],
            ];
            for (c, w) in da.c.iter().zip(want) {
                for (e, v) in [c.v, c.d, c.dd].into_iter().zip(w) {
                    assert!(e.lo <= v && v <= e.hi, "{e:?} vs {v}");
                }
            }
        }
    }
}
