//! The fast certificates of the exact steps, modulo 31-bit primes: square-freeness (step 2,
//! `gcd(g, g') = 1`) and coprimality (`gcd(a, b) = 1`, before a pseudo-remainder sequence whose
//! coefficients grow with every step).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::ToPrimitive;

/// The three largest primes below 2³¹ (so products of residues fit in a `u64`).
const SQUARE_FREE_PRIMES: [u64; 3] = [2_147_483_647, 2_147_483_629, 2_147_483_587];

fn mul_mod(a: u64, b: u64, q: u64) -> u64 {
    (a * b) % q
}

fn inv_mod(a: u64, q: u64) -> u64 {
    // Fermat: a^(q−2), q prime.
    let (mut base, mut e, mut acc) = (a, q - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, base, q);
        }
        base = mul_mod(base, base, q);
        e >>= 1;
    }
    acc
}

/// Degree of `gcd(a, b)` over 𝔽_q (inputs reduced, trailing zeros trimmed, `a` non-zero).
fn gcd_degree_mod(mut a: Vec<u64>, mut b: Vec<u64>, q: u64) -> usize {
    while !b.is_empty() {
        let n = b.len() - 1;
        let inv = inv_mod(b[n], q);
        while a.len() > n {
            let m = a.len() - 1;
            let c = mul_mod(a[m], inv, q);
            for (j, &bc) in b.iter().enumerate() {
                let t = mul_mod(c, bc, q);
                let x = &mut a[m - n + j];
                *x = if *x >= t { *x - t } else { *x + (q - t) };
            }
            while a.last() == Some(&0) {
                a.pop();
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len() - 1
}

/// Certifies that `f` (degree ≥ 1) is square-free: if for a prime `q` not dividing `lc(f)`
/// `gcd(f mod q, (f mod q)')` is constant, then so is `gcd(f, f')` over ℚ (being primitive, it
/// divides `f` and `f'` in `ℤ[x]`, and its reduction keeps its degree and divides both).
/// `false` means "not certified", after which the exact decomposition decides.
pub(super) fn certainly_square_free(f: &[BigInt]) -> bool {
    SQUARE_FREE_PRIMES.iter().any(|&q| {
        let red = reduced(f, q);
        if red.last() == Some(&0) {
            return false;
        }
        let mut der: Vec<u64> = red
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, &c)| mul_mod(c, i as u64 % q, q))
            .collect();
        while der.last() == Some(&0) {
            der.pop();
        }
        gcd_degree_mod(red, der, q) == 0
    })
}

/// Certifies that `a` and `b` (integer, `a` non-zero) have a constant gcd over ℚ: if for a
/// prime `q` not dividing `lc(a)` `gcd(a mod q, b mod q)` is constant, so is the primitive gcd
/// `g` over ℤ (`lc(g)` divides `lc(a)`, so `g mod q` keeps its degree, and it divides both
/// reductions). `false` means "not certified", after which the exact gcd decides.
pub(super) fn certainly_coprime(a: &[BigInt], b: &[BigInt]) -> bool {
    if a.is_empty() {
        return false;
    }
    SQUARE_FREE_PRIMES.iter().any(|&q| {
        let ra = reduced(a, q);
        if ra.last() == Some(&0) {
            return false;
        }
        let mut rb = reduced(b, q);
        while rb.last() == Some(&0) {
            rb.pop();
        }
        gcd_degree_mod(ra, rb, q) == 0
    })
}

/// The coefficients of `f` modulo `q`, in [0, q).
fn reduced(f: &[BigInt], q: u64) -> Vec<u64> {
    let bq = BigInt::from(q);
    f.iter()
        .map(|c| c.mod_floor(&bq).to_u64().unwrap_or(0))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn z(v: &[i64]) -> Vec<BigInt> {
        v.iter().map(|&c| BigInt::from(c)).collect()
    }

    #[test]
    fn coprimality_is_certified_only_for_coprime_polynomials() {
        // (x - 1)(x - 2) and (x - 3): coprime; (x - 1)(x - 2) and (x - 2)(x + 5): share x - 2.
        assert!(certainly_coprime(&z(&[2, -3, 1]), &z(&[-3, 1])));
        assert!(!certainly_coprime(&z(&[2, -3, 1]), &z(&[-10, 3, 1])));
        // A constant divides everything; zero shares every root.
        assert!(certainly_coprime(&z(&[2, -3, 1]), &z(&[7])));
        assert!(!certainly_coprime(&z(&[2, -3, 1]), &[]));
        // x - 2^31 + 1 and x: coprime over ℚ, and the first prime divides the difference, so
        // the certificate must try another.
        assert!(certainly_coprime(&z(&[-2_147_483_647, 1]), &z(&[0, 1])));
        // A leading coefficient every prime divides is never trusted: lc x + 1 and x + 1 are
        // coprime, but modulo each prime the first is the constant 1.
        let lc: BigInt = SQUARE_FREE_PRIMES
            .iter()
            .map(|&q| BigInt::from(q))
            .product();
        let a = vec![BigInt::from(1), lc];
        assert!(!certainly_coprime(&a, &z(&[1, 1])));
    }
}
