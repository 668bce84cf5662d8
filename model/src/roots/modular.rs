//! The fast square-free certificate of step 2: `gcd(g, g') = 1` checked modulo 31-bit primes.

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
        let bq = BigInt::from(q);
        let red: Vec<u64> = f
            .iter()
            .map(|c| c.mod_floor(&bq).to_u64().unwrap_or(0))
            .collect();
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
