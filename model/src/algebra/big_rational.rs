//! Big rationals kept in lowest terms by Lehmer's gcd.
//!
//! num-rational reduces every sum and product with num-bigint's binary gcd, which is quadratic
//! in the length with a large constant (one full-length shift per step): on the thousand-bit
//! coefficients of an aircraft's exact Hopf and aileron-yaw polynomials it took most of the
//! exact path's time. Here the gcd is Lehmer's, and sums and products reduce as Knuth
//! describes (TAOCP 4.5.1): a product cancels each numerator against the other denominator
//! before multiplying, a sum divides out the gcd of the denominators first (Henrici), so every
//! gcd is taken of the shorter operands, never of the unreduced result.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Non-negative gcd of two integers by Lehmer's algorithm (Knuth, TAOCP 4.5.2, Algorithm L):
/// Euclid's quotients are simulated on 63-bit leading parts and applied to the full numbers as
/// one unimodular 2×2 step (a real division only when the simulation makes no progress), and
/// the tail runs in `u128`.
pub fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut u, mut v) = (a.magnitude().clone(), b.magnitude().clone());
    if u < v {
        std::mem::swap(&mut u, &mut v);
    }
    while !v.is_zero() {
        if let (Some(x), Some(y)) = (u.to_u128(), v.to_u128()) {
            return BigInt::from(x.gcd(&y));
        }
        // u ≥ v and u > 2^128, so the shift is positive and both leading parts fit in 63 bits.
        let s = u.bits() - 63;
        let mut uh = i128::from((&u >> s).to_u64().unwrap_or(0));
        let mut vh = i128::from((&v >> s).to_u64().unwrap_or(0));
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        while vh + cc > 0 && vh + cd > 0 && uh + ca >= 0 && uh + cb >= 0 {
            let q = (uh + ca) / (vh + cc);
            if q != (uh + cb) / (vh + cd) {
                break;
            }
            (ca, cc) = (cc, ca - q * cc);
            (cb, cd) = (cd, cb - q * cd);
            (uh, vh) = (vh, uh - q * vh);
        }
        if cb == 0 {
            let r = &u % &v;
            u = std::mem::replace(&mut v, r);
        } else {
            // The step matrix is unimodular, so the gcd is preserved whatever happens.
            let (bu, bv) = (BigInt::from(u), BigInt::from(v));
            let nu = &bu * BigInt::from(ca) + &bv * BigInt::from(cb);
            let nv = &bu * BigInt::from(cc) + &bv * BigInt::from(cd);
            (u, v) = (nu.magnitude().clone(), nv.magnitude().clone());
            if u < v {
                std::mem::swap(&mut u, &mut v);
            }
        }
    }
    BigInt::from(u)
}

/// The least common multiple of two positive integers.
pub fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    if b.is_one() || a == b {
        a.clone()
    } else {
        a / gcd(a, b) * b
    }
}

/// The reduced rational `n / d` (`d ≠ 0`).
pub fn reduced(mut n: BigInt, mut d: BigInt) -> BigRational {
    if n.is_zero() {
        return BigRational::zero();
    }
    if d.is_negative() {
        n = -n;
        d = -d;
    }
    if d.is_one() {
        return BigRational::new_raw(n, d);
    }
    let g = gcd(&n, &d);
    if !g.is_one() {
        n /= &g;
        d /= &g;
    }
    BigRational::new_raw(n, d)
}

/// `x / g`, without a division when `g` is one.
fn divided(x: &BigInt, g: &BigInt) -> BigInt {
    if g.is_one() {
        x.clone()
    } else {
        x / g
    }
}

/// `a + b` in lowest terms (Henrici: with `g = gcd(b₁, b₂)`, only `gcd(t, g)` of the new
/// numerator `t` remains to divide out).
pub fn add(a: &BigRational, b: &BigRational) -> BigRational {
    let (an, ad, bn, bd) = (a.numer(), a.denom(), b.numer(), b.denom());
    if ad.is_one() && bd.is_one() {
        return BigRational::new_raw(an + bn, BigInt::one());
    }
    if ad == bd {
        return reduced(an + bn, ad.clone());
    }
    let g = gcd(ad, bd);
    if g.is_one() {
        return BigRational::new_raw(an * bd + bn * ad, ad * bd);
    }
    let (ad_g, bd_g) = (ad / &g, bd / &g);
    let t = an * &bd_g + bn * &ad_g;
    if t.is_zero() {
        return BigRational::zero();
    }
    let h = gcd(&t, &g);
    BigRational::new_raw(divided(&t, &h), ad_g * divided(bd, &h))
}

/// `a * b` in lowest terms: each numerator is cancelled against the other denominator first.
pub fn mul(a: &BigRational, b: &BigRational) -> BigRational {
    let (an, ad, bn, bd) = (a.numer(), a.denom(), b.numer(), b.denom());
    if ad.is_one() && bd.is_one() {
        return BigRational::new_raw(an * bn, BigInt::one());
    }
    if an.is_zero() || bn.is_zero() {
        return BigRational::zero();
    }
    let (g1, g2) = (gcd(an, bd), gcd(bn, ad));
    BigRational::new_raw(
        divided(an, &g1) * divided(bn, &g2),
        divided(ad, &g2) * divided(bd, &g1),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::collection::vec;
    use proptest::prelude::*;

    /// An integer of up to `limbs` 64-bit limbs, either sign.
    fn big(limbs: usize) -> impl Strategy<Value = BigInt> {
        (vec(any::<u64>(), 1..=limbs), any::<bool>()).prop_map(|(l, negative)| {
            let m = l.iter().fold(BigInt::zero(), |acc, &x| (acc << 64u32) + x);
            if negative {
                -m
            } else {
                m
            }
        })
    }

    /// A rational `n c / d` with a common factor `c` shared with another operand.
    fn rational(n: BigInt, d: BigInt, c: &BigInt) -> BigRational {
        BigRational::new(n * c, d.abs() + 1)
    }

    proptest! {
        #[test]
        fn lehmer_gcd_agrees_with_binary_gcd(a in big(13), b in big(7), c in big(5)) {
            let (a, b) = (a * &c, b * &c);
            prop_assert_eq!(gcd(&a, &b), a.gcd(&b));
            prop_assert_eq!(gcd(&b, &BigInt::zero()), b.abs());
        }

        /// Sums and products equal num-rational's (which reduces by its own gcd), whatever the
        /// signs, common factors and lengths, in lowest terms with a positive denominator
        /// (`new_raw` results compare equal to num-rational's only then).
        #[test]
        fn sums_and_products_equal_num_rationals(
            (n1, d1, n2, d2, n3) in (big(7), big(4), big(5), big(6), big(3)),
            c in big(3),
        ) {
            let x = rational(n1, d1, &c);
            let y = BigRational::new(n2, d2.abs() * &c + 1);
            let z = BigRational::new(n3, x.denom().clone());
            let cases = [(&x, &y), (&y, &x), (&x, &z), (&x, &-x.clone()), (&x, &BigRational::zero())];
            for (a, b) in cases {
                for (got, want) in [(add(a, b), a + b), (mul(a, b), a * b)] {
                    prop_assert!(got.denom().is_positive());
                    prop_assert!(got.is_zero() || gcd(got.numer(), got.denom()).is_one());
                    prop_assert_eq!(got, want);
                }
            }
        }
    }
}
