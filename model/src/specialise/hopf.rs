//! The Hopf polynomial `det(A)^10 Delta4` of a specialised aircraft (beyond the paper), in dense
//! univariate arithmetic: for `analyze` at one elevator setting, and for the emitter as an
//! exact polynomial in P0 and delta_e interpolated from such univariate ones.
//!
//! Fully parametric the polynomial is out of reach (`examples/hopf_parametric_size.rs` asks for
//! a 1.1 TB allocation); per aircraft with delta_e a symbol the generic sparse route takes about
//! a second (release, A and B), while the dense route at a handful of elevator settings and an
//! exact interpolation in delta_e gives the same polynomial much faster.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::equations::symbols;
//! use model::specialise::hopf::hopf_polynomial;
//!
//! // Aircraft B's Hopf polynomial (delta_e a symbol) changes sign at its first Hopf point,
//! // P0 = 3.129030 rad/s at delta_e = 2 deg (AUTO-07p's value); A's exists too.
//! let (h, s) = (hopf_polynomial(&Aircraft::b()).unwrap(), symbols());
//! let de = 2f64.to_radians();
//! let at = |p0: f64| h.eval_f64(&|x| if x == s.p0 { p0 } else if x == s.delta_e { de } else { 0.0 });
//! assert!(at(3.1290) * at(3.1291) < 0.0);
//! assert!(hopf_polynomial(&Aircraft::a()).is_some());
//! ```

use super::{aircraft_values, from_univariate, parametric, parametric_characteristic, univariate};
use crate::aircraft::{Aircraft, Param};
use crate::algebra::{Poly, Sym, Q};
use crate::derivation::hopf::{delta4_in, hopf_symbols, orlando};
use crate::derivation::{clear_trim, Clearing};
use crate::equations::symbols;
use crate::roots::UPoly;
use num_traits::Zero;

/// `den^10 Delta4(c(num / den))` in dense univariate arithmetic, when the trim numerators `num`
/// and `den` are polynomials in P0 alone (no aileron yaw, or the zero-sideslip trim): the same
/// polynomial as [`crate::derivation::hopf::hopf_at`] of
/// [`crate::derivation::hopf::cleared_coefficients`], by the same routines (step 8's
/// [`clear_trim`], Orlando's [`delta4_in`]) in the ring of [`UPoly`]. `None` when delta_a occurs.
pub fn dense_hopf(c: &[Poly; 5], t: &[Sym], num: &[Poly], den: &Poly) -> Option<UPoly> {
    let s = symbols();
    if num.iter().chain([den]).any(|p| p.contains(s.delta_a)) {
        return None;
    }
    let ring = &mut Univariate;
    let num: Vec<UPoly> = num.iter().map(|n| univariate(n, s.p0)).collect();
    let den = univariate(den, s.p0);
    let cleared: [UPoly; 5] =
        std::array::from_fn(|k| clear_trim(ring, &c[k], t, &num, &den, k as u32 + 1));
    Some(delta4_in(ring, &cleared))
}

/// Dense univariate polynomials in P0 as the ring of step 8 (values free of the trim symbols
/// are polynomials in P0 alone).
struct Univariate;

impl Clearing for Univariate {
    type Value = UPoly;
    fn lift(&mut self, p: &Poly) -> UPoly {
        univariate(p, symbols().p0)
    }
    fn add(&mut self, a: &UPoly, b: &UPoly) -> UPoly {
        a.add(b)
    }
    fn mul(&mut self, a: &UPoly, b: &UPoly) -> UPoly {
        a.mul(b)
    }
}

/// `mu^k c_k` with `mu` the least common multiple of every coefficient's denominator, so that
/// each has integer coefficients (exact arithmetic then never reduces fractions) while Delta4
/// weighted-homogeneous of weight 10 in the `c_k`, changes by the positive constant `mu^10` only
/// (no root moves). Only for the exact polynomials: the scaled values overflow f64. Returns the
/// scaled coefficients and `mu`.
pub fn weighted_integer(c: &[Poly; 5]) -> ([Poly; 5], Q) {
    use num_integer::Integer;
    let mut mu = num_bigint::BigInt::from(1);
    for ck in c {
        for (_, q) in ck.terms() {
            mu = mu.lcm(q.to_big().denom());
        }
    }
    let m = Q::from_big(num_rational::BigRational::from_integer(mu));
    let mut scale = Q::ONE;
    let scaled = std::array::from_fn(|k| {
        scale = &scale * &m;
        c[k].scale(&scale)
    });
    (scaled, m)
}

/// The Hopf polynomial `det(A)^10 Delta4` of `aircraft` at the trim of the unconstrained roll
/// (delta_r = 0), exact, as a polynomial in P0 and delta_e; `None` with aileron yaw (then the
/// trim depends on delta_a, and the polynomial in P0 alone is a resultant, see
/// `analysis::HopfPolys`). det A is the determinant of Eq. 2 itself (no scale), so the value
/// at a trim is `det(A)^10 Delta4` of that trim, with its sign.
///
/// The trim numerators are affine in delta_e, so the degree in delta_e is at most the largest
/// weighted trim degree of a term of Delta4 (each `c_k` counts its degree in the trim); the
/// polynomial is computed by [`dense_hopf`] at that many plus one integer values of delta_e and
/// interpolated exactly (Lagrange).
pub fn hopf_polynomial(aircraft: &Aircraft) -> Option<Poly> {
    let s = symbols();
    if !aircraft.exact(Param::NDeltaA).is_zero() {
        return None;
    }
    let par = parametric();
    let base = aircraft_values(aircraft);
    let c: [Poly; 5] = parametric_characteristic()
        .clone()
        .map(|ck| ck.subs_values(&base));
    let (ci, mu) = weighted_integer(&c);
    let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
    // Degree bound in delta_e: the trim numerators are affine in it.
    assert!(
        par.trim.iter().all(|n| n.degree(s.delta_e) <= 1),
        "the trim is affine in delta_e"
    );
    let hs = hopf_symbols();
    let trim_degree: Vec<u32> = c.iter().map(|ck| ck.degree_in(&t4)).collect();
    let bound = orlando()
        .delta4
        .terms()
        .iter()
        .map(|(m, _)| (0..5).map(|k| m.exp(hs.c[k]) * trim_degree[k]).sum::<u32>())
        .max()
        .unwrap_or(0);
    let det_a_exact = par.det_a.subs_values(&base);
    let samples: Vec<(Q, UPoly)> = (0..=bound as i64)
        .map(|j| {
            let de = Q::int(j);
            let mut values = base.clone();
            values.push((s.delta_e, de.clone()));
            values.push((s.delta_r, Q::ZERO));
            let polys = [
                &par.det_a,
                &par.trim[0],
                &par.trim[1],
                &par.trim[2],
                &par.trim[3],
            ];
            let cleared = Poly::subs_values_cleared(&polys, &values)
                .expect("the parametric derivation has integer coefficients");
            let h = dense_hopf(&ci, &t4, &cleared[1..], &cleared[0])
                .expect("no aileron yaw: the trim is univariate in P0");
            // Undo the scales: lambda on det A and the numerators (lambda^10 on Delta4's weight
            // 10), mu on the coefficients (mu^10).
            let lambda = leading(&cleared[0]).div(&leading(&det_a_exact));
            let undo = (&lambda * &mu).pow(10);
            (de, h.scale(&Q::ONE.div(&undo).to_big()))
        })
        .collect();
    Some(lagrange(&samples, s.delta_e))
}

/// The coefficient of the highest power of P0 of a nonzero polynomial in P0 alone.
fn leading(p: &Poly) -> Q {
    let s = symbols();
    let cs = p
        .univariate_coeffs(s.p0)
        .expect("det A is a polynomial in P0");
    cs.into_iter()
        .rev()
        .find(|c| !c.is_zero())
        .expect("det A is not zero")
}

/// The polynomial in P0 and `x` through the points `(x_j, f_j(P0))`: `sum_j f_j L_j(x)` with the
/// Lagrange basis `L_j`, exactly.
fn lagrange(samples: &[(Q, UPoly)], x: Sym) -> Poly {
    let mut out = Poly::zero();
    for (j, (xj, fj)) in samples.iter().enumerate() {
        let mut basis = Poly::int(1);
        for (k, (xk, _)) in samples.iter().enumerate() {
            if k != j {
                let factor = &Poly::var(x) - &Poly::constant(xk.clone());
                basis = &basis * &factor.scale(&Q::ONE.div(&(xj - xk)));
            }
        }
        out = &out + &(&from_univariate(fj) * &basis);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivation::hopf::{characteristic_coefficients, cleared_coefficients, hopf_at};
    use crate::derivation::Derivation;

    /// The interpolated polynomial equals the sparse route's `det(A)^10 Delta4` with delta_e a
    /// symbol (the derivation specialised to the data only), exactly.
    #[test]
    fn interpolated_hopf_polynomial_equals_the_symbolic_one() {
        let s = symbols();
        let ac = Aircraft::b();
        let mut values = aircraft_values(&ac);
        values.push((s.delta_r, Q::ZERO));
        let d = Derivation::derive(&values);
        let c = characteristic_coefficients(&d.jacobian);
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        let want = hopf_at(&cleared_coefficients(&c, &t4, &d.trim, &d.det_a));
        let got = hopf_polynomial(&ac).unwrap();
        assert_eq!(got, want);
        assert_eq!((got.degree(s.p0), got.degree(s.delta_e)), (48, 6));
    }
}
