//! The characteristic coefficients of J5 at a trim, cleared of the trim's denominator by step 8
//! and divided by their own powers of it ([`Reduced`]): what the Hopf polynomial `Delta4` is built
//! from, in any [`Mode`] ([`hopf_in`]), by the routines of the exact path.

use super::compiled::Cleared;
use super::dense::{Dense2, IPoly};
use super::elimination::Coeff;
use super::isolate::Uncertified;
use super::mode::{at_origin, constant, Mode};
use crate::derivation::hopf::{stripped_delta4_in, TRIM_FACTOR_POWERS};
use crate::derivation::{Clearing, TrimProducts};
use crate::interval::I;

/// `den^10 Delta4 / den^4` of a trim `t_i = num_i / den` (the Hopf polynomial with the factor
/// the exact path strips, `analysis::strip`) from the lifted characteristic coefficients: each
/// `C_k = den^k c_k(num / den)` by step 8, divided by its own power of `den`
/// ([`TRIM_FACTOR_POWERS`], a certified exact division of a polynomial of low degree), and
/// Delta4 with that factor taken out ([`stripped_delta4_in`]): the routines of the exact path,
/// in the ring `m`. Dividing the expanded degree-48 polynomial by `den^4` instead would lose
/// eight digits of its middle coefficients. Without aileron yaw only: delta_a must not occur
/// ([`Uncertified::Uncovered`] otherwise).
pub(super) fn hopf_in<M: Mode>(
    m: &mut M,
    groups: &[Cleared; 5],
    lifted: &[Vec<Dense2<M::Num>>; 5],
    num: &[M::Value],
    den: &M::Value,
) -> Result<Reduced<M::Coef>, Uncertified> {
    let uncovered = |_| Uncertified::Uncovered;
    let scale = M::univariate(den).map_err(uncovered)?;
    for n in num {
        M::univariate(n).map_err(uncovered)?;
    }
    // A trim at the origin (every numerator zero: the zero-sideslip trim at delta_e = 0) makes
    // each `C_k = den^k c_k(0)`, whose surplus powers of `den` would give Delta4 multiple roots
    // at den's roots: there the whole power is divided out and Delta4 taken of `c_k(0)` itself
    // (`f = 1`), the exact path's polynomial once it strips den's roots.
    let origin = at_origin::<M>(num);
    let mut c = Vec::with_capacity(5);
    let mut products = TrimProducts::new(m, den, 1);
    for (k, power) in TRIM_FACTOR_POWERS.iter().enumerate() {
        let cleared = M::univariate(&m.clear_with(&groups[k], &lifted[k], num, den, &mut products))
            .map_err(uncovered)?;
        let power = if origin { k as u32 + 1 } else { *power };
        c.push(
            cleared
                .div_exact(&scale.pow(power))
                .ok_or(Uncertified::Degenerate)?,
        );
    }
    Ok(Reduced {
        c: c.try_into()
            .unwrap_or_else(|_| unreachable!("five coefficients")),
        f: if origin {
            M::Coef::constant(I::point(1.0))
        } else {
            scale
        },
    })
}

/// The characteristic coefficients at a trim, cleared and divided by their own powers of the
/// trim's denominator `f` (`c'_k = C_k / f^(e_k)`), and `f`: what the Hopf polynomial is built
/// from.
#[derive(Clone, Debug)]
pub(super) struct Reduced<C> {
    pub(super) c: [C; 5],
    pub(super) f: C,
}

impl<C: Coeff> Reduced<C> {
    /// `Delta4(C) / f^4`, the Hopf polynomial with det A's factor stripped.
    pub(super) fn delta4(&self) -> C {
        stripped_delta4_in(&mut InCoef(std::marker::PhantomData), &self.c, &self.f)
    }
}

impl Reduced<IPoly> {
    /// The same in `u = P0^2` ([`IPoly::in_square`]): every ingredient is even in P0 (see
    /// [`EnclosedHopf::positive_roots`]).
    pub(super) fn in_square(&self) -> Option<Reduced<IPoly>> {
        let [c1, c2, c3, c4, c5] = &self.c;
        Some(Reduced {
            c: [
                c1.in_square()?,
                c2.in_square()?,
                c3.in_square()?,
                c4.in_square()?,
                c5.in_square()?,
            ],
            f: self.f.in_square()?,
        })
    }

    /// The same at `P0 = x0 + y`, in `y`.
    pub(super) fn shift(&self, x0: f64) -> Reduced<IPoly> {
        let x0 = I::point(x0);
        Reduced {
            c: std::array::from_fn(|k| self.c[k].shift(x0)),
            f: self.f.shift(x0),
        }
    }
}

/// The coefficient ring of a [`Mode`] as a ring of step 8 (for the Hopf polynomial, whose
/// ingredients are free of delta_a).
pub(super) struct InCoef<C>(std::marker::PhantomData<C>);

impl<C: Coeff> Clearing for InCoef<C> {
    type Value = C;
    fn lift(&mut self, p: &crate::algebra::Poly) -> C {
        C::constant(constant(p))
    }
    fn add(&mut self, a: &C, b: &C) -> C {
        a.add(b)
    }
    fn mul(&mut self, a: &C, b: &C) -> C {
        a.mul(b)
    }
}
