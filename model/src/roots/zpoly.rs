//! Primitive integer polynomials (`ℤ[x]`, ascending coefficients): the integer form every
//! exact step works on, the contents, pseudo-remainder gcds and Yun's
//! square-free decomposition (step 2 of the method, the exact fallback).

use super::*;
use crate::algebra::big_rational;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

pub(super) type ZPoly = Vec<BigInt>;

/// `(z, l)` with `p = z / l`: integer coefficients over `l = lcm` of the denominators.
pub(super) fn common_denominator(p: &UPoly) -> (ZPoly, BigInt) {
    let l = p
        .coeffs()
        .iter()
        .fold(BigInt::one(), |l, c| big_rational::lcm(&l, c.denom()));
    let z = p
        .coeffs()
        .iter()
        .map(|c| {
            if c.denom() == &l {
                c.numer().clone()
            } else {
                c.numer() * (&l / c.denom())
            }
        })
        .collect();
    (z, l)
}

fn trim_z(v: &mut ZPoly) {
    while v.last().is_some_and(Zero::is_zero) {
        v.pop();
    }
}

/// Positive gcd of the coefficients (zero for the zero polynomial). Starts from the smallest
/// coefficient so that every further gcd begins with a cheap remainder.
fn content(v: &[BigInt]) -> BigInt {
    let Some(smallest) = v.iter().filter(|c| !c.is_zero()).min_by_key(|c| c.bits()) else {
        return BigInt::zero();
    };
    let mut g = smallest.abs();
    for c in v {
        if g.is_one() {
            break;
        }
        if !c.is_zero() {
            g = big_rational::gcd(c, &g);
        }
    }
    g
}

/// Divides by the positive content (the sign is kept).
fn make_primitive(v: &mut ZPoly) {
    let g = content(v);
    if !g.is_zero() && !g.is_one() {
        for c in v.iter_mut() {
            *c = &*c / &g;
        }
    }
}

fn make_lc_positive(v: &mut ZPoly) {
    if v.last().is_some_and(Signed::is_negative) {
        for c in v.iter_mut() {
            *c = -&*c;
        }
    }
}

/// Primitive integer polynomial with positive leading coefficient, a positive multiple of `p`.
///
/// With reduced fractions `nᵢ/dᵢ` and `L = lcm(dᵢ)`, the content of `L·p` is `gcd(nᵢ)`, so only
/// gcds of the (small) input numerators and denominators are needed, never of the products.
pub(super) fn to_primitive_z(p: &UPoly) -> ZPoly {
    let (mut v, _) = common_denominator(p);
    let mut g = BigInt::zero();
    for c in p.coeffs().iter().filter(|c| !c.is_zero()) {
        g = if g.is_zero() {
            c.numer().abs()
        } else {
            big_rational::gcd(&g, c.numer())
        };
        if g.is_one() {
            break;
        }
    }
    if !g.is_zero() && !g.is_one() {
        for c in v.iter_mut() {
            *c = &*c / &g;
        }
    }
    make_lc_positive(&mut v);
    v
}

pub(super) fn z_to_upoly(v: &[BigInt]) -> UPoly {
    UPoly::new(v.iter().cloned().map(BigRational::from_integer).collect())
}

fn z_derivative(v: &[BigInt]) -> ZPoly {
    v.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * BigInt::from(i))
        .collect()
}

fn z_sub(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let mut out: ZPoly = (0..a.len().max(b.len()))
        .map(|i| match (a.get(i), b.get(i)) {
            (Some(x), Some(y)) => x - y,
            (Some(x), None) => x.clone(),
            (None, Some(y)) => -y,
            (None, None) => BigInt::zero(),
        })
        .collect();
    trim_z(&mut out);
    out
}

/// Pseudo-remainder of `a` by non-zero `b`: `lc(b)^s · a = q·b + r` with `deg r < deg b`.
fn prem(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let n = b.len() - 1;
    let lb = &b[n];
    let mut r = a.to_vec();
    while r.len() > n {
        let m = r.len() - 1;
        let lr = r[m].clone();
        let shift = m - n;
        if !lb.is_one() {
            for c in r.iter_mut() {
                *c *= lb;
            }
        }
        for (j, bc) in b.iter().enumerate().take(n) {
            r[j + shift] -= &lr * bc;
        }
        r.pop();
        trim_z(&mut r);
    }
    r
}

/// Primitive gcd with positive leading coefficient (primitive pseudo-remainder sequence).
/// Zero only if both inputs are zero.
pub(super) fn z_gcd(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    // Most pairs are coprime: a certificate modulo a prime answers without the sequence.
    if certainly_coprime(a, b) || certainly_coprime(b, a) {
        return vec![BigInt::one()];
    }
    let (mut r0, mut r1) = if a.len() >= b.len() {
        (a.to_vec(), b.to_vec())
    } else {
        (b.to_vec(), a.to_vec())
    };
    make_primitive(&mut r0);
    make_primitive(&mut r1);
    loop {
        if r1.is_empty() {
            make_lc_positive(&mut r0);
            return r0;
        }
        if r1.len() == 1 {
            return vec![BigInt::one()];
        }
        let mut r = prem(&r0, &r1);
        make_primitive(&mut r);
        r0 = std::mem::replace(&mut r1, r);
    }
}

/// The quotient `a / b` in `ℤ[x]` if `b` (non-zero) divides `a` there, `None` otherwise: every
/// step's leading division must be exact and nothing may remain.
pub(super) fn z_checked_div(a: &[BigInt], b: &[BigInt]) -> Option<ZPoly> {
    let n = b.len().checked_sub(1)?;
    if a.len() <= n {
        return a.iter().all(Zero::is_zero).then(Vec::new);
    }
    let mut r = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len() - n];
    for s in (0..q.len()).rev() {
        let (c, rest) = r[s + n].div_rem(&b[n]);
        if !rest.is_zero() {
            return None;
        }
        if !c.is_zero() {
            for (j, bc) in b.iter().enumerate() {
                r[s + j] -= &c * bc;
            }
        }
        q[s] = c;
    }
    r[..n].iter().all(Zero::is_zero).then_some(q)
}

/// Exact quotient `a / b` in `ℤ[x]` where `b` is known to divide `a` (e.g. `b` primitive and a
/// divisor of `a` in `ℚ[x]`, by Gauss's lemma).
fn z_exact_div(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    z_checked_div(a, b).expect("the divisor divides in Z[x]")
}

/// Yun's square-free decomposition of a primitive `f` (degree ≥ 1), entirely in `ℤ[x]`: every gcd
/// is primitive, so all quotients are integral. Returns the non-constant factors (primitive,
/// positive leading coefficient) with their multiplicities, in increasing multiplicity.
pub(super) fn z_yun(f: &[BigInt]) -> Vec<(ZPoly, u32)> {
    let df = z_derivative(f);
    let a0 = z_gcd(f, &df);
    if a0.len() == 1 {
        let mut g = f.to_vec();
        make_lc_positive(&mut g);
        return vec![(g, 1)];
    }
    let mut b = z_exact_div(f, &a0);
    let c = z_exact_div(&df, &a0);
    let mut d = z_sub(&c, &z_derivative(&b));
    let mut out = Vec::new();
    let mut i = 1u32;
    while b.len() > 1 {
        let a = z_gcd(&b, &d);
        b = z_exact_div(&b, &a);
        let c = z_exact_div(&d, &a);
        d = z_sub(&c, &z_derivative(&b));
        if a.len() > 1 {
            out.push((a, i));
        }
        i += 1;
    }
    out
}
