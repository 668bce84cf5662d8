//! Beyond the paper: the closed-form Hopf (oscillatory departure) criterion.
//!
//! The paper's jump criterion is `det J5 = 0`, a real eigenvalue of the PSS Jacobian through
//! zero. A complex pair through the imaginary axis (a Hopf bifurcation: a growing pitch-yaw
//! oscillation) is the other way a trim loses stability. It is derived here the same way:
//!
//! 1. The characteristic polynomial `det(s I - J5) = s^5 + c1 s^4 + c2 s^3 + c3 s^2 + c4 s + c5`
//!    of the Jacobian at the trim, its coefficients polynomials in the trim symbols; `c5 = -det
//!    J5` is the jump criterion (its constant term). `c_k` has degree at most `k` in the trim
//!    states (the entries of J5 are affine in them).
//! 2. Orlando's formula: the fourth Hurwitz determinant
//!    `Delta4 = det [[c1, c3, c5, 0], [1, c2, c4, 0], [0, c1, c3, c5], [0, 1, c2, c4]]`
//!    is, up to sign, the product of `l_i + l_j` over the ten eigenvalue pairs, so it vanishes
//!    exactly when two eigenvalues sum to zero: a pair `+-i omega` (Hopf) or `+-lambda` (a
//!    neutral saddle). Each term of Delta4 has weight 10 (`c_k` counts `k`).
//! 3. The trim is substituted and det A cleared: because Delta4 is weighted-homogeneous of weight
//!    10, substituting the cleared coefficients `C_k = det(A)^k c_k(trim)` gives
//!    `det(A)^10 Delta4` directly: the Hopf polynomial in P0 (and delta_a with aileron yaw,
//!    which is then eliminated against the trim condition exactly as for the jump polynomial).
//! 4. At a root, `s = i omega` splits `p(i omega) = 0` into the even part
//!    `c1 w^2 - c3 w + c5 = 0` and the odd part `w^2 - c2 w + c4 = 0` with `w = omega^2`;
//!    eliminating `w^2` leaves a linear equation, `omega^2 = (c1 c4 - c5) / (c1 c2 - c3)`
//!    (derived below from the characteristic polynomial, not typed). A Hopf point has
//!    `omega^2 > 0`; a neutral saddle `omega^2 < 0` (the pair is `+-sqrt(-w)`).
//!
//! ```
//! use model::algebra::{Matrix, Poly, Q};
//! use model::derivation::hopf::{at_coefficients, characteristic_coefficients, orlando};
//!
//! // Eigenvalues -1, +-2i, -3, -4: a pair on the imaginary axis with omega = 2.
//! let entry = |r: usize, c: usize| match (r, c) {
//!     (0, 0) => Poly::int(-1),
//!     (1, 2) => Poly::int(2),
//!     (2, 1) => Poly::int(-2),
//!     (3, 3) => Poly::int(-3),
//!     (4, 4) => Poly::int(-4),
//!     _ => Poly::zero(),
//! };
//! let j = Matrix::from_rows((0..5).map(|r| (0..5).map(|c| entry(r, c)).collect()).collect());
//! // det(s I - J) = (s + 1)(s^2 + 4)(s + 3)(s + 4) = s^5 + 8 s^4 + 23 s^3 + 44 s^2 + 76 s + 48.
//! let c = characteristic_coefficients(&j);
//! let value = |p: &Poly| p.as_constant().unwrap();
//! assert_eq!(c.each_ref().map(value), [8, 23, 44, 76, 48].map(Q::from));
//! // Delta4 vanishes, and omega^2 = (c1 c4 - c5) / (c1 c2 - c3) = 560 / 140 = 4.
//! let o = orlando();
//! assert!(at_coefficients(&o.delta4, &c).is_zero());
//! let (num, den) = (at_coefficients(&o.omega_sq.num, &c), at_coefficients(&o.omega_sq.den, &c));
//! assert_eq!(value(&num).div(&value(&den)), Q::from(4));
//! ```

use super::{homogenize, Clearing, Exact, Ratio, TrimGroups};
use crate::algebra::{Matrix, Poly, Sym, Q};
use std::sync::OnceLock;

/// The symbols of the generic characteristic polynomial: the eigenvalue variable `s`, the
/// coefficients `c1..c5` and `w = omega^2`.
#[derive(Debug)]
pub struct HopfSymbols {
    /// The Laplace variable of the characteristic polynomial.
    pub s: Sym,
    /// `c1..c5`, the coefficients of `s^4 .. s^0`.
    pub c: [Sym; 5],
    /// `w = omega^2` at a pair `+-i omega`.
    pub w: Sym,
    /// A common factor `f` of the coefficients, `c_k = f^(e_k) c'_k` (see [`stripped`]), and the
    /// rescaled `omega^2 / f^2` in the reduced odd part.
    pub f: Sym,
}

/// The Hopf symbols (created once, after the model's).
pub fn hopf_symbols() -> &'static HopfSymbols {
    static S: OnceLock<HopfSymbols> = OnceLock::new();
    S.get_or_init(|| {
        crate::equations::symbols();
        HopfSymbols {
            s: Sym::new("s"),
            c: std::array::from_fn(|i| Sym::new(&format!("c{}", i + 1))),
            w: Sym::new("w"),
            f: Sym::new("f_common"),
        }
    })
}

/// The generic results, in the symbols `c1..c5` only (they hold for any 5x5 matrix).
#[derive(Clone, Debug)]
pub struct Orlando {
    /// Delta4, the fourth Hurwitz determinant, in `c1..c5`.
    pub delta4: Poly,
    /// Even part of `p(i omega)` in `w = omega^2`: `c1 w^2 - c3 w + c5`.
    pub even: Poly,
    /// Odd part of `p(i omega) / (i omega)` in `w`: `w^2 - c2 w + c4`.
    pub odd: Poly,
    /// `omega^2` at a root of Delta4, rational in `c1..c5`.
    pub omega_sq: Ratio,
    /// `Res_w(even, odd) - Delta4`: identically zero (the two conditions on `w` have a common
    /// root exactly where Delta4 vanishes); a check of the whole construction.
    pub identity_residual: Poly,
    /// `+-odd` grouped by powers of `w` for step 8 with `w = omega^2`'s numerator over its
    /// denominator: `Delta4 = den^2 (+-odd)(num / den)`, the sign fixed by the derivation (see
    /// [`delta4_in`]).
    pub delta4_groups: TrimGroups,
}

/// Derives the generic Hurwitz/omega^2 results once.
pub fn orlando() -> &'static Orlando {
    static O: OnceLock<Orlando> = OnceLock::new();
    O.get_or_init(|| {
        let h = hopf_symbols();
        let c = |i: usize| Poly::var(h.c[i - 1]);
        let z = Poly::zero;
        let one = || Poly::int(1);
        let delta4 = Matrix::from_rows(vec![
            vec![c(1), c(3), c(5), z()],
            vec![one(), c(2), c(4), z()],
            vec![z(), c(1), c(3), c(5)],
            vec![z(), one(), c(2), c(4)],
        ])
        .det();
        // p(s) with s = i omega: s^(2k) = (-w)^k, s^(2k+1) = s (-w)^k.
        let char_poly = characteristic_generic();
        let (mut even, mut odd) = (Poly::zero(), Poly::zero());
        for (k, ck) in char_poly.coeffs(h.s).iter().enumerate() {
            let half = Poly::var(h.w).scale(&Q::from(-1)).pow((k / 2) as u32);
            if k % 2 == 0 {
                even = &even + &(ck * &half);
            } else {
                odd = &odd + &(ck * &half);
            }
        }
        // Normalise signs: even = c1 w^2 - c3 w + c5, odd = w^2 - c2 w + c4.
        let lead = |p: &Poly| p.coeff(h.w, 2).coeff(h.c[0], 0).as_constant();
        if lead(&odd) == Some(Q::from(-1)) {
            odd = -&odd;
        }
        if even.coeff(h.w, 2).coeff(h.c[0], 1).as_constant() == Some(Q::from(-1)) {
            even = -&even;
        }
        // Eliminate w^2: even - c1 odd is linear in w.
        let lin = &even - &(&c(1) * &odd);
        assert!(lin.degree(h.w) == 1, "even - c1 odd is linear in w");
        let omega_sq = Ratio {
            num: -lin.coeff(h.w, 0),
            den: lin.coeff(h.w, 1),
        };
        let res = even.resultant(&odd, h.w);
        let identity_residual = if (&res - &delta4).is_zero() {
            Poly::zero()
        } else {
            &res + &delta4
        };
        // Res_w(odd, even) = Res_w(odd, even - c1 odd) (odd is monic in w), and even - c1 odd =
        // den w - num is linear: so Delta4 is +-den^2 odd(num / den), step 8 of `odd` at
        // w = omega^2. Which sign is decided here, exactly.
        let w = [h.w];
        let cleared = homogenize(
            &odd,
            &w,
            std::slice::from_ref(&omega_sq.num),
            &omega_sq.den,
            2,
        );
        let signed = if (&cleared - &delta4).is_zero() {
            odd.clone()
        } else {
            assert!(
                (&cleared + &delta4).is_zero(),
                "Delta4 is +-den^2 odd(omega^2) (Orlando, resultant of the even and odd parts)"
            );
            -&odd
        };
        Orlando {
            delta4,
            even,
            odd,
            omega_sq,
            identity_residual,
            delta4_groups: TrimGroups::new(&signed, &w, 2),
        }
    })
}

/// `s^5 + c1 s^4 + ... + c5` in the generic symbols.
fn characteristic_generic() -> Poly {
    let h = hopf_symbols();
    (0..=5).fold(Poly::zero(), |acc, k| {
        let ck = if k == 0 {
            Poly::int(1)
        } else {
            Poly::var(h.c[k - 1])
        };
        &acc + &(&ck * &Poly::var(h.s).pow(5 - k as u32))
    })
}

/// The coefficients `c1..c5` of `det(s I - J)` for a 5x5 matrix of polynomials.
pub fn characteristic_coefficients(j: &Matrix) -> [Poly; 5] {
    let h = hopf_symbols();
    let n = j.rows();
    assert!(n == 5 && j.cols() == 5, "J5 is 5x5");
    let rows = (0..n)
        .map(|r| {
            (0..n)
                .map(|c| {
                    let e = -j.get(r, c);
                    if r == c {
                        &e + &Poly::var(h.s)
                    } else {
                        e
                    }
                })
                .collect()
        })
        .collect();
    let p = Matrix::from_rows(rows).det();
    let cs = p.coeffs(h.s);
    assert!(
        cs.len() == 6 && cs[5].as_constant() == Some(Q::ONE),
        "det(s I - J5) is monic of degree 5"
    );
    std::array::from_fn(|k| cs[4 - k].clone())
}

/// Substitutes `c1..c5` into a generic result.
pub fn at_coefficients(f: &Poly, c: &[Poly; 5]) -> Poly {
    let h = hopf_symbols();
    let subs: Vec<(Sym, Poly)> = h.c.iter().copied().zip(c.iter().cloned()).collect();
    f.subs_all(&subs)
}

/// The characteristic coefficients at the trim `t_i = num_i / den`, each cleared of its own
/// power of `den` (step 3): `C_k = den^k c_k(num / den)`. `Delta4(C) = den^10 Delta4(c)`.
pub fn cleared_coefficients(c: &[Poly; 5], t: &[Sym], num: &[Poly], den: &Poly) -> [Poly; 5] {
    std::array::from_fn(|k| homogenize(&c[k], t, num, den, k as u32 + 1))
}

/// The Hopf polynomial `den^10 Delta4` at the trim, from the cleared coefficients.
pub fn hopf_at(cleared: &[Poly; 5]) -> Poly {
    delta4_in(&mut Exact, cleared)
}

/// Delta4 of the values `c` of `c1..c5` in any ring of step 8 (exact polynomials, dense
/// univariate ones, enclosures in [`crate::certified`]): the one evaluation of Orlando's
/// formula every route shares.
///
/// Evaluated as `Delta4 = +-u^2 odd(v / u)` with `v / u = (c1 c4 - c5) / (c1 c2 - c3)` the
/// omega^2 of step 4 and `odd = w^2 - c2 w + c4`, i.e. `+-(v^2 - c2 u v + c4 u^2)`, derived and
/// checked exactly in [`orlando`]: seven products instead of the eighteen of the expanded
/// determinant, and in interval arithmetic a much smaller cancellation (the expanded form's
/// terms are each far larger than Delta4 near its roots).
pub fn delta4_in<C: Clearing>(ring: &mut C, c: &[C::Value; 5]) -> C::Value {
    odd_cleared_in(ring, &orlando().delta4_groups, c, None)
}

/// `+-u^2 odd(v / u)` with the grouping `groups` of an odd part (coefficients in `c1..c5` and
/// the common factor `f`), `u`, `v` the omega^2 denominator and numerator at `c`: Delta4
/// itself ([`delta4_in`]) or its reduced form ([`stripped_delta4_in`]).
fn odd_cleared_in<C: Clearing>(
    ring: &mut C,
    groups: &TrimGroups,
    c: &[C::Value; 5],
    f: Option<&C::Value>,
) -> C::Value {
    let o = orlando();
    let u = at_coefficients_in(ring, &o.omega_sq.den, c);
    let v = at_coefficients_in(ring, &o.omega_sq.num, c);
    let coefficients: Vec<&Poly> = groups.coefficients().collect();
    groups.clear_by(ring, &[v], &u, |ring, i| {
        at_values_in(ring, coefficients[i], c, f)
    })
}

/// The powers of the trim's denominator `den` that divide the cleared characteristic
/// coefficients `C_k = den^k c_k(num / den)` of J5 on the trim (Eqs 3-4, and the zero-sideslip
/// trim of Eq. 35 with its own denominator), for aircraft without aileron yaw: `C1 = den c1'`
/// (the trace of J5 does not depend on the trim), `C3 = den C3'`, `C4 = den^2 C4'`,
/// `C5 = den^3 C5'`. Found on the exact path for aircraft A, B and random aircraft and checked
/// on every aircraft of the certified route's agreement test (`tests/tests/hopf_fast.rs`); the
/// certified route divides by them with a certified remainder.
pub const TRIM_FACTOR_POWERS: [u32; 5] = [1, 0, 1, 2, 3];

/// Delta4 of coefficients `C_k = f^(e_k) c'_k` (`e` = [`TRIM_FACTOR_POWERS`]) with the power of
/// `f` that divides it taken out, derived from [`orlando`]: `u(C) = f u(c')`,
/// `v(C) = f^3 v(c')`, so `omega^2 = f^2 v(c') / u(c')`, and `Delta4(C) = f^power R(c', f)` with
/// `R = +-u'^2 odd_r(v' / u')`, `odd_r(x) = odd(f^2 x) / f^2` at the scaled coefficients.
#[derive(Clone, Debug)]
pub struct Stripped {
    /// The power of `f` that divides `Delta4(C)` (4): the factor of det A (det A1) that the
    /// exact path strips from the Hopf polynomial.
    pub power: u32,
    /// `+-odd_r` grouped by powers of its variable, coefficients in `c'` and `f`.
    groups: TrimGroups,
}

/// The derivation of [`Stripped`], checked exactly against Delta4.
pub fn stripped() -> &'static Stripped {
    static S: OnceLock<Stripped> = OnceLock::new();
    S.get_or_init(|| {
        let h = hopf_symbols();
        let o = orlando();
        let f = Poly::var(h.f);
        let scaled: Vec<(Sym, Poly)> = (0..5)
            .map(|k| (h.c[k], &f.pow(TRIM_FACTOR_POWERS[k]) * &Poly::var(h.c[k])))
            .collect();
        let power_of_f = |p: &Poly| p.terms().iter().map(|(m, _)| m.exp(h.f)).min().unwrap_or(0);
        let (u, v) = (
            o.omega_sq.den.subs_all(&scaled),
            o.omega_sq.num.subs_all(&scaled),
        );
        let (a, b) = (power_of_f(&u), power_of_f(&v));
        assert!(
            b >= a,
            "omega^2 carries a nonnegative power of the common factor"
        );
        // odd(w) at the scaled coefficients and w = f^(b - a) x, divided by the power of f it
        // carries (the sign of `delta4_groups` kept).
        let signed: Poly =
            o.delta4_groups
                .coefficients()
                .zip([0u32, 1, 2])
                .fold(Poly::zero(), |acc, (g, j)| {
                    &acc + &(&g.subs_all(&scaled) * &(&f.pow(b - a) * &Poly::var(h.w)).pow(j))
                });
        let carried = power_of_f(&signed);
        let reduced = divide_by_power(&signed, h.f, carried);
        let power = 2 * a + carried;
        // The check: f^power u'^2 odd_r(v'/u') is Delta4 at the scaled coefficients.
        let groups = TrimGroups::new(&reduced, &[h.w], 2);
        let c: [Poly; 5] = h.c.map(Poly::var);
        let r = odd_cleared_in(&mut Exact, &groups, &c, Some(&f));
        assert_eq!(
            &f.pow(power) * &r,
            o.delta4.subs_all(&scaled),
            "Delta4(C) = f^power R(c', f)"
        );
        Stripped { power, groups }
    })
}

/// `Delta4(C) / f^power` for `C_k = f^(e_k) c_k` ([`Stripped`]) from the values `c` (the `c'_k`)
/// and `f` in any ring of step 8: [`delta4_in`] with the common factor taken out before any
/// product, so that no division of a high-degree polynomial is needed.
pub fn stripped_delta4_in<C: Clearing>(ring: &mut C, c: &[C::Value; 5], f: &C::Value) -> C::Value {
    odd_cleared_in(ring, &stripped().groups, c, Some(f))
}

/// `p / x^k` for a polynomial every term of which carries `x^k`.
fn divide_by_power(p: &Poly, x: Sym, k: u32) -> Poly {
    Poly::from_terms(p.terms().iter().map(|(m, q)| {
        let mut m = *m;
        assert!(m.exp(x) >= k, "every term carries the power");
        m.set(x, m.exp(x) - k);
        (m, q.clone())
    }))
}

/// A polynomial `f` in `c1..c5` (rational coefficients) at the values `c` of a ring, term by
/// term.
pub fn at_coefficients_in<C: Clearing>(ring: &mut C, f: &Poly, c: &[C::Value; 5]) -> C::Value {
    at_values_in(ring, f, c, None)
}

/// A polynomial in `c1..c5` and the common factor `f` at values of a ring.
fn at_values_in<C: Clearing>(
    ring: &mut C,
    p: &Poly,
    c: &[C::Value; 5],
    f: Option<&C::Value>,
) -> C::Value {
    let h = hopf_symbols();
    let mut acc = ring.lift(&Poly::zero());
    for (m, q) in p.terms() {
        let mut term = ring.lift(&Poly::constant(q.clone()));
        let mut rest = *m;
        for (k, ck) in h.c.iter().enumerate() {
            for _ in 0..m.exp(*ck) {
                term = ring.mul(&term, &c[k]);
            }
            rest.set(*ck, 0);
        }
        if let Some(f) = f {
            for _ in 0..m.exp(h.f) {
                term = ring.mul(&term, f);
            }
            rest.set(h.f, 0);
        }
        assert!(rest.is_one(), "a polynomial in c1..c5 (and f) only");
        acc = ring.add(&acc, &term);
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orlando_delta4_is_the_resultant_of_the_even_and_odd_parts() {
        let o = orlando();
        assert!(o.identity_residual.is_zero());
        let h = hopf_symbols();
        // omega^2 = (c1 c4 - c5) / (c1 c2 - c3), up to a common sign.
        let c = |i: usize| Poly::var(h.c[i - 1]);
        let num = &(&c(1) * &c(4)) - &c(5);
        let den = &(&c(1) * &c(2)) - &c(3);
        let same = (&o.omega_sq.num - &num).is_zero() && (&o.omega_sq.den - &den).is_zero();
        let flipped = (&o.omega_sq.num + &num).is_zero() && (&o.omega_sq.den + &den).is_zero();
        assert!(same || flipped, "{:?}", o.omega_sq);
    }

    /// The evaluation every route uses, `delta4_in`, gives Orlando's determinant itself.
    #[test]
    fn delta4_from_omega_squared_is_the_hurwitz_determinant() {
        let h = hopf_symbols();
        let c = h.c.map(Poly::var);
        assert_eq!(delta4_in(&mut Exact, &c), orlando().delta4);
        // And at the doc example's coefficients (eigenvalues -1, +-2i, -3, -4) it vanishes.
        let at = [8, 23, 44, 76, 48].map(Poly::int);
        assert!(delta4_in(&mut Exact, &at).is_zero());
    }

    /// The stripped form times `f^4` is Delta4 at `C_k = f^(e_k) c_k` (checked inside
    /// `stripped()`), and at f = 1 it is Delta4 itself.
    #[test]
    fn stripped_delta4_times_the_common_factor_is_delta4() {
        let h = hopf_symbols();
        let st = stripped();
        assert_eq!(st.power, 4);
        let c = h.c.map(Poly::var);
        assert_eq!(
            stripped_delta4_in(&mut Exact, &c, &Poly::int(1)),
            orlando().delta4
        );
    }
}
