//! Tests of exact root isolation: known roots, clustered and multiple roots, poles, timing.

use super::*;
use num_bigint::{BigInt, Sign};
use num_traits::ToPrimitive;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn int(n: i64) -> BigRational {
    q(n, 1)
}

/// Parses a decimal such as `-1.25e-3` exactly.
fn dec(s: &str) -> BigRational {
    let (mant, exp) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i64>().unwrap()),
        None => (s, 0),
    };
    let (ip, fp) = mant.split_once('.').unwrap_or((mant, ""));
    let digits: BigInt = format!("{ip}{fp}").parse().unwrap();
    let e = exp - fp.len() as i64;
    let ten = BigInt::from(10);
    if e >= 0 {
        BigRational::from_integer(digits * num_traits::pow(ten, e as usize))
    } else {
        BigRational::new(digits, num_traits::pow(ten, (-e) as usize))
    }
}

fn poly_with_roots(roots: &[(BigRational, u32)]) -> UPoly {
    let mut p = UPoly::constant(int(1));
    for (r, m) in roots {
        for _ in 0..*m {
            p = p.mul(&UPoly::from_roots(std::slice::from_ref(r)));
        }
    }
    p
}

/// Checks that the reported interval brackets the exact root and `value` is its nearest f64.
fn assert_root(found: &RealRoot, exact: &BigRational, mult: u32) {
    assert!(
        (found.lo < *exact && *exact <= found.hi) || (found.lo == found.hi && found.lo == *exact),
        "root {exact} not in ({}, {}]",
        found.lo,
        found.hi
    );
    assert_eq!(found.multiplicity, mult, "multiplicity of {exact}");
    assert_eq!(found.value, exact.to_f64().unwrap(), "value of {exact}");
}

fn values(r: &[RealRoot]) -> Vec<f64> {
    r.iter().map(|r| r.value).collect()
}

#[test]
fn simple_cubic() {
    let p = UPoly::from_roots(&[int(1), int(2), int(3)]);
    let r = real_roots(&p);
    assert_eq!(values(&r), [1.0, 2.0, 3.0]);
    for (x, k) in r.iter().zip(1..) {
        assert_root(x, &int(k), 1);
    }
}

#[test]
fn double_root_is_reported_once_with_multiplicity_two() {
    let p = poly_with_roots(&[(int(1), 2), (int(-2), 1)]);
    let r = real_roots(&p);
    assert_eq!(r.len(), 2);
    assert_root(&r[0], &int(-2), 1);
    assert_root(&r[1], &int(1), 2);
}

#[test]
fn roots_1e_minus_9_apart_are_both_found() {
    let a = int(1);
    let b = int(1) + q(1, 1_000_000_000);
    let p = UPoly::from_roots(&[a.clone(), b.clone()]).scale(&q(-7, 3));
    let r = positive_roots(&p);
    assert_eq!(r.len(), 2);
    assert_root(&r[0], &a, 1);
    assert_root(&r[1], &b, 1);
    assert!(r[0].value < r[1].value);
}

#[test]
fn roots_of_different_factors_closer_than_f64_resolution_are_ordered_exactly() {
    let a = q(1, 3);
    let b = q(1, 3) + BigRational::new(1.into(), num_traits::pow(BigInt::from(10), 30));
    let p = poly_with_roots(&[(a.clone(), 2), (b.clone(), 1)]);
    let r = real_roots(&p);
    assert_eq!(r.len(), 2);
    assert!(r[0].lo < a && a <= r[0].hi && r[0].multiplicity == 2);
    assert!(r[1].lo < b && b <= r[1].hi && r[1].multiplicity == 1);
    assert!(r[0].hi <= r[1].lo);
}

#[test]
fn gcd_cancels_a_pole_exactly_but_keeps_a_nearby_root() {
    // N/D with N = (x−2)(x−2.0001)(x²+1), D = (x−2)(x+3): the common root 2 is a removable
    // singularity, 2.0001 is a genuine root 10⁻⁴ away from it.
    let close = dec("2.0001");
    let n = UPoly::from_roots(&[int(2), close.clone()]).mul(&UPoly::from_i64s(&[1, 0, 1]));
    let d = UPoly::from_roots(&[int(2), int(-3)]);
    let g = n.gcd(&d);
    assert_eq!(g, UPoly::from_roots(&[int(2)]));
    let (nq, rem) = n.div_rem(&g);
    assert!(rem.is_zero());
    let r = positive_roots(&nq);
    assert_eq!(r.len(), 1);
    assert_root(&r[0], &close, 1);
}

#[test]
fn wilkinson_twelve() {
    let roots: Vec<_> = (1..=12).map(int).collect();
    let p = UPoly::from_roots(&roots);
    let r = positive_roots(&p);
    assert_eq!(r.len(), 12);
    for (x, k) in r.iter().zip(1..) {
        assert!((x.value - k as f64).abs() <= 1e-12 * k as f64);
        assert_root(x, &int(k), 1);
    }
}

#[test]
fn big_decimal_coefficients() {
    // Three roots given with 30 decimals (two of them 10⁻³⁰ apart), a negative root, and a
    // quadratic with 30-digit data and no real roots: denominators reach 10^120.
    let r1 = dec("0.123456789012345678901234567891");
    let r2 = dec("3.141592653589793238462643383279");
    let r3 = dec("3.141592653589793238462643383280");
    let quad = UPoly::new(vec![
        dec("2.718281828459045235360287471352"),
        dec("-1.000000000000000000000000000001"),
        dec("1.5"),
    ]);
    let c = quad.coeffs();
    assert!(&c[1] * &c[1] - int(4) * &c[0] * &c[2] < int(0)); // discriminant < 0
    assert!(real_roots(&quad).is_empty());
    let p = UPoly::from_roots(&[r1.clone(), r2.clone(), r3.clone(), int(-5)]).mul(&quad);
    let found = positive_roots(&p);
    assert_eq!(found.len(), 3);
    assert_root(&found[0], &r1, 1);
    // r2 and r3 share their f64 value but have disjoint exact enclosures.
    assert!(found[1].lo < r2 && r2 <= found[1].hi);
    assert!(found[2].lo < r3 && r3 <= found[2].hi);
    assert!(found[1].hi <= found[2].lo);
    assert_eq!(found[1].value, r2.to_f64().unwrap());
    assert_eq!(found[2].value, r3.to_f64().unwrap());
    // Every reported enclosure is a genuine sign change of the exact polynomial.
    for x in found.iter().filter(|x| x.lo != x.hi) {
        assert_ne!(p.eval(&x.lo).signum(), p.eval(&x.hi).signum());
    }
}

#[test]
fn no_positive_roots() {
    assert!(positive_roots(&UPoly::from_i64s(&[1, 0, 1])).is_empty());
    assert!(positive_roots(&UPoly::from_roots(&[int(-1), int(-2), q(-1, 7)])).is_empty());
    assert!(real_roots(&UPoly::from_i64s(&[1, 0, 1])).is_empty());
}

#[test]
fn roots_at_zero_are_excluded_from_positive_roots() {
    // x³ (x − 1)
    let p = UPoly::from_i64s(&[0, 0, 0, -1, 1]);
    let pos = positive_roots(&p);
    assert_eq!(pos.len(), 1);
    assert_root(&pos[0], &int(1), 1);
    let all = real_roots(&p);
    assert_eq!(all.len(), 2);
    assert_root(&all[0], &int(0), 3);
    assert_root(&all[1], &int(1), 1);
}

#[test]
fn biquadratic() {
    let p = UPoly::from_i64s(&[4, 0, -5, 0, 1]);
    let pos = positive_roots(&p);
    assert_eq!(values(&pos), [1.0, 2.0]);
    assert_eq!(values(&real_roots(&p)), [-2.0, -1.0, 1.0, 2.0]);
}

#[test]
fn roots_in_is_half_open() {
    let p = UPoly::from_roots(&[int(1), int(2), int(3)]);
    assert_eq!(values(&roots_in(&p, &int(1), &int(3))), [2.0, 3.0]);
    assert_eq!(values(&roots_in(&p, &q(1, 2), &q(5, 2))), [1.0, 2.0]);
    assert!(roots_in(&p, &int(3), &int(1)).is_empty());
    // Bounds closer to a root than any isolating interval is wide.
    let eps = BigRational::new(1.into(), num_traits::pow(BigInt::from(10), 40));
    let r = roots_in(&p, &(int(2) - &eps), &(int(3) - &eps));
    assert_eq!(values(&r), [2.0]);
    let r = roots_in(&p, &(int(2) + &eps), &(int(3) + &eps));
    assert_eq!(values(&r), [3.0]);
    // Irrational root √2 against tight rational bounds on either side.
    let s = UPoly::from_i64s(&[-2, 0, 1]);
    let below = dec("1.41421356237309504880168872420969807");
    let above = dec("1.41421356237309504880168872420969808");
    assert_eq!(roots_in(&s, &below, &above).len(), 1);
    assert!(roots_in(&s, &above, &int(2)).is_empty());
    assert!(roots_in(&s, &int(0), &below).is_empty());
    // Zero root counted only when 0 ∈ (lo, hi].
    let z = UPoly::from_i64s(&[0, 1]);
    assert_eq!(roots_in(&z, &int(-1), &int(0)).len(), 1);
    assert!(roots_in(&z, &int(0), &int(1)).is_empty());
}

#[test]
fn zero_and_constant_polynomials_have_no_roots() {
    assert!(real_roots(&UPoly::zero()).is_empty());
    assert!(positive_roots(&UPoly::zero()).is_empty());
    assert!(real_roots(&UPoly::from_i64s(&[5])).is_empty());
    assert_eq!(UPoly::from_i64s(&[0, 0]), UPoly::zero());
    assert_eq!(UPoly::zero().degree(), None);
}

#[test]
fn irrational_roots_are_correctly_rounded() {
    let p = UPoly::from_i64s(&[-2, 0, 1]);
    let r = real_roots(&p);
    assert_eq!(
        values(&r),
        [-std::f64::consts::SQRT_2, std::f64::consts::SQRT_2]
    );
    // x³ − 2
    let r = real_roots(&UPoly::from_i64s(&[-2, 0, 0, 1]));
    assert_eq!(r.len(), 1);
    assert!((r[0].value - 2f64.cbrt()).abs() <= f64::EPSILON * 2.0);
    let lo3 = &r[0].lo * &r[0].lo * &r[0].lo;
    let hi3 = &r[0].hi * &r[0].hi * &r[0].hi;
    assert!(lo3 < int(2) && int(2) < hi3);
}

#[test]
fn tiny_and_huge_roots() {
    let tiny = dec("1.5e-300");
    let huge = dec("2.5e300");
    let p = UPoly::from_roots(&[tiny.clone(), huge.clone(), dec("7e-5")]);
    let r = positive_roots(&p);
    assert_eq!(r.len(), 3);
    assert_root(&r[0], &tiny, 1);
    assert_root(&r[1], &dec("7e-5"), 1);
    assert_root(&r[2], &huge, 1);
}

#[test]
fn cluster_of_sixteen_roots_within_a_thousandth() {
    let roots: Vec<_> = (0..16).map(|i| q(1, 1) + q(i, 16_000)).collect();
    let p = UPoly::from_roots(&roots);
    let r = positive_roots(&p);
    assert_eq!(r.len(), 16);
    for (x, e) in r.iter().zip(&roots) {
        assert_root(x, e, 1);
    }
}

#[test]
fn square_free_factorisation() {
    let p = poly_with_roots(&[(int(1), 3), (int(-2), 2), (int(5), 1)]).scale(&q(3, 4));
    let f = p.square_free_factors();
    let expect = vec![
        (UPoly::from_roots(&[int(5)]), 1),
        (UPoly::from_roots(&[int(-2)]), 2),
        (UPoly::from_roots(&[int(1)]), 3),
    ];
    assert_eq!(f, expect);
    let back = f.iter().fold(UPoly::constant(q(3, 4)), |acc, (g, i)| {
        (0..*i).fold(acc, |acc, _| acc.mul(g))
    });
    assert_eq!(back, p);
    assert!(UPoly::from_i64s(&[7]).square_free_factors().is_empty());
}

#[test]
fn arithmetic() {
    let a = UPoly::from_i64s(&[1, 2, 3]);
    let b = UPoly::from_i64s(&[-1, 1]);
    let (qq, r) = a.div_rem(&b);
    assert_eq!(qq.mul(&b).add(&r), a);
    assert_eq!(r.degree(), Some(0));
    assert_eq!(r.coeffs()[0], a.eval(&int(1)));
    assert_eq!(a.sub(&a), UPoly::zero());
    assert_eq!(a.derivative(), UPoly::from_i64s(&[2, 6]));
    assert_eq!(a.eval_f64(2.0), 17.0);
    assert_eq!(a.gcd(&UPoly::zero()), a.monic());
    assert_eq!(UPoly::zero().gcd(&UPoly::zero()), UPoly::zero());
    assert_eq!(a.gcd(&b), UPoly::from_i64s(&[1]));
}

#[test]
fn fallback_refinement_alone_is_correct_too() {
    // The exact quadratic-interval-refinement fallback, without the Newton fast path.
    let sqrt2 = UPoly::from_i64s(&[-2, 0, 1]);
    let cluster: Vec<_> = (0..6).map(|i| int(1) + q(i, 1_000_000_000)).collect();
    for (p, expect) in [
        (
            sqrt2,
            vec![-std::f64::consts::SQRT_2, std::f64::consts::SQRT_2],
        ),
        (
            UPoly::from_roots(&cluster),
            cluster.iter().map(|r| r.to_f64().unwrap()).collect(),
        ),
    ] {
        let f = to_primitive_z(&p);
        let k = root_bound_log2(&f);
        let bound = BigInt::one() << k.max(0) as u64;
        let (mut iso, mut exact) = (Vec::new(), Vec::new());
        isolate(&f, &-bound.clone(), &bound, 0, &mut iso, &mut exact);
        let mut got: Vec<f64> = exact.iter().map(|(m, k)| dyadic_to_f64(m, *k)).collect();
        for iv in iso {
            let r = qir(&f, iv);
            assert!(r.exact || refined_enough(&r.a, &r.b, r.k));
            got.push(if r.exact {
                dyadic_to_f64(&r.a, r.k)
            } else {
                dyadic_to_f64(&(&r.a + &r.b), r.k + 1)
            });
        }
        got.sort_by(f64::total_cmp);
        assert_eq!(got, expect);
    }
}

#[test]
fn certified_cell_walks_to_the_right_neighbour() {
    // A deliberately wrong guess a few ulps off is corrected by exact signs.
    let f = to_primitive_z(&UPoly::from_i64s(&[-2, 0, 1]));
    for off in [-3i64, -1, 0, 2, 3] {
        let mut iv = Isolated {
            a: BigInt::one(),
            b: BigInt::from(2),
            k: 0,
            sb: Sign::Plus,
        };
        let x = f64::from_bits((std::f64::consts::SQRT_2.to_bits() as i64 + off) as u64);
        let r = certify_cell(&f, &mut iv, x).expect("within four cells");
        let v = dyadic_to_f64(&(&r.a + &r.b), r.k + 1);
        assert_eq!(v, std::f64::consts::SQRT_2);
    }
}

#[test]
#[should_panic(expected = "division by the zero polynomial")]
fn division_by_zero_panics() {
    let _ = UPoly::from_i64s(&[1, 1]).div_rem(&UPoly::zero());
}

#[test]
fn dyadic_rounding() {
    for x in [
        1.0,
        0.1,
        3.5e-310,
        5e-324,
        1.7976931348623157e308,
        -2.5,
        1e-300,
    ] {
        let r = BigRational::from_float(x).unwrap();
        let (n, d) = (r.numer().clone(), r.denom().clone());
        let k = d.bits() - 1;
        assert_eq!(dyadic_to_f64(&n, k), x);
    }
    // Ties to even: 1 + 2^-53 rounds to 1, 1 + 3·2^-53 rounds to 1 + 2^-51.
    assert_eq!(dyadic_to_f64(&((BigInt::one() << 53u32) + 1), 53), 1.0);
    assert_eq!(
        dyadic_to_f64(&((BigInt::one() << 53u32) + 3), 53),
        1.0 + 2f64.powi(-51)
    );
    assert_eq!(dyadic_to_f64(&(BigInt::one() << 1100u32), 0), f64::INFINITY);
}

/// Tiny deterministic linear congruential generator (no extra dependencies).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

#[test]
fn random_polynomials_from_known_roots() {
    let mut rng = Lcg(0x5eed);
    for case in 0..300 {
        let mut roots: Vec<(BigRational, u32)> = Vec::new();
        let count = 1 + rng.below(6);
        while roots.len() < count as usize {
            let r = match rng.below(4) {
                // a small rational
                0 | 1 => q(rng.below(401) as i64 - 200, 1 + rng.below(60) as i64),
                // a near-twin of an existing root
                2 if !roots.is_empty() => {
                    let i = rng.below(roots.len() as u64) as usize;
                    let d = 1 + rng.below(9) as i64;
                    &roots[i].0 + q(d, 10i64.pow(1 + rng.below(12) as u32))
                }
                // a decimal with many digits
                _ => dec(&format!(
                    "{}.{:09}{:09}",
                    rng.below(50) as i64 - 25,
                    rng.below(1_000_000_000),
                    rng.below(1_000_000_000)
                )),
            };
            if roots.iter().all(|(x, _)| *x != r) {
                roots.push((r, 1 + rng.below(3) as u32));
            }
        }
        let mut p = poly_with_roots(&roots).scale(&q(rng.below(1000) as i64 + 1, 37));
        if rng.below(2) == 0 {
            // times an irreducible quadratic x² + c, c > 0
            p = p.mul(&UPoly::new(vec![
                q(1 + rng.below(100) as i64, 7),
                int(0),
                int(1),
            ]));
        }
        roots.sort_by(|a, b| a.0.cmp(&b.0));
        let found = real_roots(&p);
        assert_eq!(found.len(), roots.len(), "case {case}: {roots:?}");
        for (f, (r, m)) in found.iter().zip(&roots) {
            assert_root(f, r, *m);
        }
        let pos: Vec<_> = roots.iter().filter(|(r, _)| r.is_positive()).collect();
        let fpos = positive_roots(&p);
        assert_eq!(fpos.len(), pos.len(), "case {case}");
        for (f, (r, m)) in fpos.iter().zip(pos) {
            assert_root(f, r, *m);
        }
    }
}

#[test]
fn rational_arithmetic_is_exact() {
    let mut rng = Lcg(11);
    let mut rat = || q(rng.below(2001) as i64 - 1000, 1 + rng.below(97) as i64);
    for _ in 0..50 {
        let a = UPoly::new((0..7).map(|_| rat()).collect());
        let d = UPoly::new((0..4).map(|_| rat()).collect());
        let x = rat();
        let naive = a.coeffs().iter().rev().fold(int(0), |acc, c| acc * &x + c);
        assert_eq!(a.eval(&x), naive);
        if d.is_zero() {
            continue;
        }
        let (qq, r) = a.div_rem(&d);
        assert_eq!(qq.mul(&d).add(&r), a);
        assert!(r.degree().is_none_or(|e| e < d.degree().unwrap()));
        // exact division leaves no remainder
        let (q2, r2) = a.mul(&d).div_rem(&d);
        assert_eq!((q2, r2), (a.clone(), UPoly::zero()));
    }
}

/// Degree-12 polynomial with twelve real rational roots (coefficients up to ~126 digits).
fn timing_poly(rng: &mut Lcg) -> UPoly {
    let roots: Vec<_> = (0..12)
        .map(|_| {
            let n = rng.below(1_000_000) as i64 - 300_000;
            let d = 1 + rng.below(999) as i64;
            q(n, d * 1000)
        })
        .collect();
    UPoly::from_roots(&roots).scale(&q(rng.below(1_000_000) as i64 + 1, 999_983))
}

/// Prints the mean time of `positive_roots` over `polys` (20 repetitions) and the mean number of
/// roots found.
fn time_positive_roots(what: &str, polys: &[UPoly]) {
    const REPS: usize = 20;
    let start = std::time::Instant::now();
    let mut n = 0;
    for _ in 0..REPS {
        for p in polys {
            n += positive_roots(p).len();
        }
    }
    n /= REPS;
    let per = start.elapsed() / (REPS * polys.len()) as u32;
    println!("{what}: {per:?} per positive_roots ({n} roots)");
}

#[test]
#[ignore = "timing; run with --release -- --ignored --nocapture"]
fn timing() {
    let mut rng = Lcg(42);
    let polys: Vec<_> = (0..200).map(|_| timing_poly(&mut rng)).collect();
    let digits: usize = polys[0]
        .coeffs()
        .iter()
        .map(|c| c.numer().to_string().len() + c.denom().to_string().len())
        .max()
        .unwrap();
    time_positive_roots(
        &format!("degree 12, up to {digits} digits per coefficient"),
        &polys,
    );
    // random dense polynomials, coefficients p/q with 28-digit p and q
    let polys: Vec<_> = (0..200)
        .map(|_| {
            UPoly::new(
                (0..13)
                    .map(|_| {
                        let n: BigInt = format!("{}{:018}", rng.below(1 << 30), rng.next())
                            .parse()
                            .unwrap();
                        let d: BigInt = format!("{}{:018}", 1 + rng.below(1 << 30), rng.next())
                            .parse()
                            .unwrap();
                        let s = if rng.below(2) == 0 { -1 } else { 1 };
                        BigRational::new(n * s, d)
                    })
                    .collect(),
            )
        })
        .collect();
    time_positive_roots(
        "random dense degree 12, 28-digit numerators and denominators",
        &polys,
    );
    // degree 16, coefficients with 30 decimals (denominators 10^30), as after substitution
    let polys: Vec<_> = (0..200)
        .map(|_| {
            UPoly::new(
                (0..17)
                    .map(|_| {
                        let s = if rng.below(2) == 0 { "-" } else { "" };
                        dec(&format!(
                            "{s}{}.{:015}{:015}e{}",
                            rng.below(1000),
                            rng.below(1_000_000_000_000_000),
                            rng.below(1_000_000_000_000_000),
                            rng.below(9) as i64 - 4
                        ))
                    })
                    .collect(),
            )
        })
        .collect();
    time_positive_roots("random dense degree 16, 30-decimal coefficients", &polys);
}

/// A random polynomial of degree `deg` with rational coefficients of up to six digits.
fn random_upoly(rng: &mut Lcg, deg: usize) -> UPoly {
    let mut c: Vec<BigRational> = (0..=deg)
        .map(|_| {
            q(
                rng.below(2_000_001) as i64 - 1_000_000,
                1 + rng.below(999) as i64,
            )
        })
        .collect();
    if c[deg].is_zero() {
        c[deg] = int(1);
    }
    UPoly::new(c)
}

/// `div_exact` gives the quotient of every exact division (the same as `div_rem`'s, with no
/// remainder) and refuses every inexact one, including a divisor that is a rational multiple
/// of a factor and a remainder of one unit in the constant term.
#[test]
fn exact_division_returns_the_quotient_or_refuses() {
    let mut rng = Lcg(31);
    for case in 0..200 {
        let (da, db) = (rng.below(7) as usize, 1 + rng.below(5) as usize);
        let (a, b) = (random_upoly(&mut rng, da), random_upoly(&mut rng, db));
        let product = a.mul(&b);
        assert_eq!(product.div_exact(&b), Some(a.clone()), "case {case}");
        assert_eq!(
            product.div_rem(&b),
            (a.clone(), UPoly::zero()),
            "case {case}"
        );
        let scaled = b.scale(&q(-7, 3));
        assert_eq!(
            product.div_exact(&scaled),
            Some(a.scale(&q(-3, 7))),
            "case {case}"
        );
        let off = product.add(&UPoly::constant(int(1)));
        assert_eq!(off.div_exact(&b), None, "case {case}");
    }
    assert_eq!(UPoly::from_i64s(&[1, 1]).div_exact(&UPoly::zero()), None);
    assert_eq!(
        UPoly::zero().div_exact(&UPoly::from_i64s(&[1, 1])),
        Some(UPoly::zero())
    );
}
