//! The Hopf polynomial at the trim of an aircraft with aileron yaw, before delta_a is eliminated:
//! in dense arithmetic (polynomials in delta_a whose coefficients are dense polynomials in P0)
//! and with det A's factor `det(A)^4` taken out before any product.
//!
//! With aileron yaw (`n_delta_a != 0`) the trim numerators are affine in delta_a, so
//! `det(A)^10 Delta4` at the trim is a polynomial in P0 and delta_a (degree 6 in delta_a and
//! 48 in P0 for a JSBSim jet), and the Hopf polynomial in P0 is its resultant with the trim
//! condition. Generic sparse arithmetic and the resultant of the full product spend most of
//! `analyze`'s time there. Here the cleared characteristic coefficients are divided by their own
//! powers of det A ([`TRIM_FACTOR_POWERS`], which hold coefficient by coefficient in delta_a) and
//! Delta4 is built by [`stripped_delta4_in`]: `det(A)^10 Delta4 / det(A)^4`, of degree 16 less
//! in P0, whose resultant is 32 degrees lower. Its roots are those of the full product except
//! det A's, which the caller strips from either.

use super::univariate;
use crate::algebra::Poly;
use crate::derivation::hopf::{stripped_delta4_in, TRIM_FACTOR_POWERS};
use crate::derivation::{clear_trim, Clearing};
use crate::equations::symbols;
use crate::roots::UPoly;

/// A polynomial in delta_a with dense coefficients in P0: `[p_0, p_1, ...]` stands for
/// `sum_i p_i delta_a^i`, without trailing zeros.
pub type InAileronDense = Vec<UPoly>;

/// `det(A)^10 Delta4(c(num / den)) / det(A)^4` as a polynomial in delta_a with dense
/// coefficients in P0, for trim numerators `num` affine in delta_a and `den` = det A in P0;
/// `None` when a power of [`TRIM_FACTOR_POWERS`] does not divide its coefficient exactly (then
/// the caller takes the full product), or `den` holds delta_a.
pub fn stripped_hopf_in_aileron(
    c: &[Poly; 5],
    t: &[crate::algebra::Sym],
    num: &[Poly],
    den: &Poly,
) -> Option<InAileronDense> {
    let ring = &mut Bivariate;
    let num: Vec<InAileronDense> = num.iter().map(|n| ring.lift(n)).collect();
    let den_v = ring.lift(den);
    let [den_p0] = den_v.as_slice() else {
        return None;
    };
    let mut reduced = Vec::with_capacity(5);
    for (k, power) in TRIM_FACTOR_POWERS.iter().enumerate() {
        let cleared = clear_trim(ring, &c[k], t, &num, &den_v, k as u32 + 1);
        let divisor = (0..*power).fold(UPoly::from_i64s(&[1]), |acc, _| acc.mul(den_p0));
        let quotient: Option<InAileronDense> =
            cleared.iter().map(|p| p.div_exact(&divisor)).collect();
        reduced.push(quotient?);
    }
    let reduced: [InAileronDense; 5] = reduced.try_into().ok()?;
    Some(stripped_delta4_in(ring, &reduced, &den_v))
}

/// `p` (a polynomial in P0 and delta_a) as a polynomial in delta_a with dense coefficients.
pub fn dense_in_aileron(p: &Poly) -> InAileronDense {
    Bivariate.lift(p)
}

/// The polynomial `sum_i p_i delta_a^i` of `p` as a [`Poly`].
pub fn from_in_aileron(p: &[UPoly]) -> Poly {
    let da = Poly::var(symbols().delta_a);
    let mut power = Poly::int(1);
    let mut out = Poly::zero();
    for c in p {
        out = &out + &(&super::from_univariate(c) * &power);
        power = &power * &da;
    }
    out
}

/// Polynomials in delta_a with dense coefficients in P0 as the ring of step 8.
struct Bivariate;

impl Bivariate {
    fn trimmed(mut v: InAileronDense) -> InAileronDense {
        while v.last().is_some_and(UPoly::is_zero) {
            v.pop();
        }
        v
    }
}

impl Clearing for Bivariate {
    type Value = InAileronDense;
    fn lift(&mut self, p: &Poly) -> InAileronDense {
        let s = symbols();
        Bivariate::trimmed(
            p.coeffs(s.delta_a)
                .iter()
                .map(|c| univariate(c, s.p0))
                .collect(),
        )
    }
    fn add(&mut self, a: &InAileronDense, b: &InAileronDense) -> InAileronDense {
        let n = a.len().max(b.len());
        let zero = UPoly::zero();
        Bivariate::trimmed(
            (0..n)
                .map(|i| a.get(i).unwrap_or(&zero).add(b.get(i).unwrap_or(&zero)))
                .collect(),
        )
    }
    fn mul(&mut self, a: &InAileronDense, b: &InAileronDense) -> InAileronDense {
        if a.is_empty() || b.is_empty() {
            return Vec::new();
        }
        let mut out = vec![UPoly::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].add(&x.mul(y));
            }
        }
        Bivariate::trimmed(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};
    use crate::derivation::hopf::{cleared_coefficients, hopf_at};
    use crate::specialise::{parametric, parametric_characteristic, specialisation};
    use num_rational::BigRational;

    /// Aircraft B with aileron yaw: the stripped polynomial times `det(A)^4` is the sparse
    /// route's `det(A)^10 Delta4` at the trim, exactly.
    #[test]
    fn stripped_polynomial_times_det_a_to_the_fourth_is_the_full_one() {
        let s = symbols();
        let ac = Aircraft::b().with(Param::NDeltaA, BigRational::new((-3).into(), 2.into()));
        let de = 2f64.to_radians();
        let values = specialisation(&ac, de);
        let par = parametric();
        let c = parametric_characteristic()
            .clone()
            .map(|ck| ck.subs_values(&values));
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        let num: Vec<Poly> = par.trim.iter().map(|n| n.subs_values(&values)).collect();
        let den = par.det_a.subs_values(&values);
        assert!(num.iter().any(|n| n.contains(s.delta_a)), "aileron yaw");
        let stripped = stripped_hopf_in_aileron(&c, &t4, &num, &den).expect("the powers divide");
        let den4 = (0..4).fold(Poly::int(1), |acc, _| &acc * &den);
        let full = hopf_at(&cleared_coefficients(&c, &t4, &num, &den));
        assert_eq!(&from_in_aileron(&stripped) * &den4, full);
    }
}
