//! Tests of the certified root isolation: every claim checked against exact rational
//! arithmetic on corners of the coefficient boxes.

use super::bernstein::Node;
use super::local::{keeps_bits, split_point};
use super::*;

/// Enclosures of relative half-width `rel` around `m 10^e 10^scale` for each `(m, e)`.
fn enclosures(coefficients: &[(f64, i32)], rel: f64, scale: i32) -> Vec<I> {
    coefficients
        .iter()
        .map(|(m, e)| {
            let m = m * 10f64.powi(*e) * 10f64.powi(scale);
            I::new(m - m.abs() * rel, m + m.abs() * rel)
        })
        .collect()
}

/// Coefficient vectors of the box `b` to check exactly: every lower end, every upper end
/// (the extremes of any combination with nonnegative weights), the corner `corner` and an
/// interior point.
fn corners(b: &[I], corner: &[bool]) -> [Vec<f64>; 4] {
    [
        b.iter().map(|c| c.lo).collect(),
        b.iter().map(|c| c.hi).collect(),
        b.iter()
            .zip(corner)
            .map(|(c, k)| if *k { c.hi } else { c.lo })
            .collect(),
        b.iter().map(|c| c.lo + 0.75 * (c.hi - c.lo)).collect(),
    ]
}

/// The exact value `e` lies in the node's coefficient `(m, r)`, or the node claims nothing
/// about it (an infinite radius, no sign).
fn holds(node: &Node, j: usize, e: &num_rational::BigRational) -> bool {
    let (m, r) = node.c[j];
    if !r.is_finite() {
        return node.sign(j).is_none();
    }
    let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
    q(m) - q(r) <= *e && *e <= q(m) + q(r)
}

/// De Casteljau's subdivision at `t` in exact rationals: (left, right).
fn exact_split(
    mut w: Vec<num_rational::BigRational>,
    t: &num_rational::BigRational,
) -> (
    Vec<num_rational::BigRational>,
    Vec<num_rational::BigRational>,
) {
    let n = w.len() - 1;
    let a = num_rational::BigRational::from_integer(1.into()) - t;
    let mut l = vec![w[0].clone()];
    let mut r = vec![w[n].clone()];
    for level in 1..=n {
        for j in 0..=n - level {
            w[j] = &a * &w[j] + t * &w[j + 1];
        }
        l.push(w[0].clone());
        r.push(w[n - level].clone());
    }
    r.reverse();
    (l, r)
}

/// Magnitudes the property tests scale their coefficients by: ordinary, tiny (down to
/// subnormal, where the underflow floors matter) and huge (sums overflow).
const SCALES: [i32; 4] = [0, -300, -315, 296];

proptest::proptest! {
    /// The Bernstein coefficients in f64 with their radii (`Node::bernstein`) enclose the
    /// exact ones, in rationals, of every polynomial with coefficients in the enclosures
    /// (all lower ends, all upper ends, a corner and an interior point), for magnitudes
    /// that differ by many orders, tiny and huge ones, and wide or point enclosures, up to
    /// the degree where the conversion is in f64 and beyond.
    #[test]
    fn bernstein_coefficients_in_f64_enclose_the_exact_ones(
        coefficients in proptest::collection::vec((-1.0f64..1.0, -12i32..12), 2..60),
        rel in proptest::sample::select(vec![0.0, 1e-15, 1e-9, 1e-3]),
        scale in proptest::sample::select(SCALES.to_vec()),
        corner in proptest::collection::vec(proptest::bool::ANY, 60),
    ) {
        use num_rational::BigRational;
        let q = |v: f64| BigRational::from_float(v).expect("finite");
        let a = enclosures(&coefficients, rel, scale);
        let n = a.len() - 1;
        let node = Node::bernstein(&a).expect("within the degree limit");
        let binomial = |n: usize, k: usize| -> BigRational {
            let mut c = num_bigint::BigInt::from(1);
            for i in 0..k {
                c = c * (n - i) / (i + 1);
            }
            BigRational::from_integer(c)
        };
        for chosen in corners(&a, &corner) {
            for j in 0..=n {
                let exact = (0..=j).fold(BigRational::from_integer(0.into()), |acc, i| {
                    acc + binomial(j, i) / binomial(n, i) * q(chosen[i])
                });
                proptest::prop_assert!(
                    holds(&node, j, &exact),
                    "b_{j} of degree {n}: {:?} misses {exact}",
                    node.c[j]
                );
            }
        }
    }

    /// De Casteljau's subdivision in f64 with its radii (`Node::split`), applied twice,
    /// encloses the exact subdivision, in rationals, of every coefficient vector in the
    /// node's enclosures (all lower ends, all upper ends, a corner and an interior point),
    /// at every split point the isolation uses, for magnitudes that differ by many orders,
    /// tiny and huge ones, and wide or point enclosures.
    #[test]
    fn subdivision_in_f64_encloses_the_exact_subdivision(
        coefficients in proptest::collection::vec((-1.0f64..1.0, -12i32..12), 2..24),
        rel in proptest::sample::select(vec![0.0, 1e-15, 1e-9, 1e-3]),
        scale in proptest::sample::select(SCALES.to_vec()),
        corner in proptest::collection::vec(proptest::bool::ANY, 24),
        which in 0usize..15,
    ) {
        use num_rational::BigRational;
        let q = |v: f64| BigRational::from_float(v).expect("finite");
        let b = enclosures(&coefficients, rel, scale);
        // The guided splits' sixteenths (which include the fixed weights 0.4375 ... 0.625).
        let t = (which + 1) as f64 / 16.0;
        let (left, right) = Node::of(&b).split(t, &mut Vec::new());
        let (left_right, _) = right.split(t, &mut Vec::new());
        for chosen in corners(&b, &corner) {
            let w: Vec<BigRational> = chosen.iter().map(|v| q(*v)).collect();
            let (l, r) = exact_split(w, &q(t));
            let (rl, _) = exact_split(r.clone(), &q(t));
            for (node, exact) in [(&left, &l), (&right, &r), (&left_right, &rl)] {
                for (j, e) in exact.iter().enumerate() {
                    proptest::prop_assert!(
                        holds(node, j, e),
                        "coefficient {j}: {:?} misses {e} for t = {t}",
                        node.c[j]
                    );
                }
            }
        }
    }
}

proptest::proptest! {
    /// Degrees 1 and 2 in closed form: every answer counts the exact positive roots (in
    /// rationals: Descartes' count and the discriminant's sign) of the polynomial at the
    /// enclosures' lower ends, upper ends and midpoints, and each bracket holds a sign
    /// change of each; the brackets are finite, positive, sorted and disjoint. A refusal
    /// (`None`) is always allowed: the bisection takes the polynomial.
    #[test]
    fn closed_forms_isolate_the_exact_positive_roots(
        c in proptest::collection::vec((-1.0f64..1.0, -40i32..40, 0u8..4), 2..4),
        rel in proptest::sample::select(vec![0.0, 1e-15, 1e-6]),
    ) {
        use num_rational::BigRational;
        let q = |v: f64| BigRational::from_float(v).expect("finite");
        let zero = || BigRational::from_integer(0.into());
        let last = c.len() - 1;
        let box_: Vec<I> = c
            .iter()
            .enumerate()
            .map(|(i, (m, e, kind))| {
                let m = m * 10f64.powi(*e);
                // The middle coefficient of a quadratic may be an exact zero.
                if *kind == 0 && i != 0 && i != last {
                    return I::point(0.0);
                }
                I::new(m - m.abs() * rel, m + m.abs() * rel)
            })
            .collect();
        proptest::prop_assume!(!box_[0].contains_zero() && !box_[last].contains_zero());
        let Some(found) = low_degree(&IPoly::new(box_.clone())) else {
            return Ok(());
        };
        for (k, (lo, hi, _)) in found.iter().enumerate() {
            proptest::prop_assert!(0.0 < *lo && lo < hi && hi.is_finite(), "{:?}", found);
            if k > 0 {
                proptest::prop_assert!(found[k - 1].1 < *lo, "overlap in {:?}", found);
            }
        }
        for pick in 0..3 {
            let e: Vec<BigRational> = box_
                .iter()
                .map(|x| match pick {
                    0 => q(x.lo),
                    1 => q(x.hi),
                    _ => (q(x.lo) + q(x.hi)) / BigRational::from_integer(2.into()),
                })
                .collect();
            let value = |x: f64| e.iter().rev().fold(zero(), |acc, c| acc * q(x) + c);
            let positive = if e.len() == 2 {
                usize::from(e[0].clone() * &e[1] < zero())
            } else {
                let d = e[1].clone() * &e[1] - BigRational::from_integer(4.into()) * &e[0] * &e[2];
                let changes = super::sign_changes(
                    e.iter().filter(|x| **x != zero()).map(|x| Some(if *x > zero() { 1.0 } else { -1.0 })),
                )
                .expect("exact signs");
                if changes == 2 && d < zero() { 0 } else { changes }
            };
            proptest::prop_assert_eq!(found.len(), positive, "{:?} at {:?}", found, e);
            for (lo, hi, _) in &found {
                proptest::prop_assert!(value(*lo) * value(*hi) < zero(), "no sign change on [{lo}, {hi}]");
            }
        }
    }
}

/// Guided splits keep 20 bits of the ends for bisection: a sixteenth of [0, 1] does; a
/// node of width 2^-10 whose end has a bit at 2^-45 (finer than its grid 2^-30) does not;
/// ends of every sign and zero are read by their lowest set bit.
#[test]
fn guided_splits_keep_bits_for_bisection() {
    assert!(keeps_bits(0.0, 0.4375, 1.0));
    assert!(keeps_bits(-1.0, -0.125, 1.0));
    let tl = 0.5 + 2f64.powi(-45);
    let tr = tl + 2f64.powi(-10);
    assert!(!keeps_bits(tl, tl + 7.0 * 2f64.powi(-14), tr));
    let tl = 0.5 + 2f64.powi(-30);
    assert!(keeps_bits(
        tl,
        tl + 7.0 * 2f64.powi(-14),
        tl + 2f64.powi(-10)
    ));
    // Width 2^-40: the grid is 2^-60, and ends that are multiples of 2^-60 pass.
    let a = 2f64.powi(-20) + 2f64.powi(-60);
    let b = a + 2f64.powi(-40);
    assert!(keeps_bits(a, a + 2f64.powi(-41), b));
    assert!(!keeps_bits(a, a + 2f64.powi(-61), b));
    // A subnormal width: no guided split.
    assert!(!keeps_bits(0.0, f64::from_bits(1), f64::from_bits(2)));
}

/// A split point is exact or there is no split: 7/16 of an interval whose width needs all
/// 53 bits is not a double.
#[test]
fn split_points_are_exact_or_refused() {
    assert_eq!(split_point(0.0, 1.0, 0.4375), Some(0.4375));
    assert_eq!(split_point(0.25, 0.5, 0.5), Some(0.375));
    assert_eq!(split_point(0.0, 1.0 - f64::EPSILON, 0.4375), None);
    // The middle of an interval one ulp wide is not a double.
    assert_eq!(split_point(1.0, 1.0 + f64::EPSILON, 0.5), None);
}

/// A sum that overflows is no sign: the Bernstein coefficients of this
/// polynomial of degree 10 with coefficients near `f64::MAX` overflow to +inf while two of
/// the exact ones are negative, and a node that read +inf as positive proved "no roots". It
/// has two positive roots, near 0.82 and 0.9 (exact values of opposite signs at 0.8, 0.85
/// and 0.95; Descartes' rule on the signs + + - - + allows at most two): the isolation
/// must find them or give up, never answer that there are none.
#[test]
fn an_overflowing_sum_is_no_sign() {
    let m = f64::MAX;
    let c = [
        0.6 * m,
        0.6 * m,
        -m,
        -0.99 * m,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        m,
    ];
    let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
    let value = |x: f64| c.iter().rev().fold(q(0.0), |acc, a| acc * q(x) + q(*a));
    let zero = q(0.0);
    assert!(value(0.8) > zero && value(0.85) < zero && value(0.95) > zero);
    match positive_roots(&p(&c)) {
        Ok(r) => {
            assert_eq!(r.len(), 2, "{r:?}");
            assert!(r[0].lo < 0.85 && r[0].hi > 0.8 && r[1].lo > 0.85 && r[1].hi < 0.95);
        }
        // Giving up (the exact path then answers) is allowed; a wrong count is not.
        Err(Uncertified::Budget | Uncertified::Sign | Uncertified::Degenerate) => {}
        Err(why) => panic!("{why:?}"),
    }
}

fn p(c: &[f64]) -> IPoly {
    IPoly::new(c.iter().map(|x| I::point(*x)).collect())
}

#[test]
fn well_conditioned_roots_are_bracketed_to_a_few_ulps() {
    // (x - 1/3)(x - 2)(x - 1000)(x + 5): positive roots 1/3, 2, 1000.
    let f = p(&[-1.0 / 3.0, 1.0]);
    let q = f
        .mul(&p(&[-2.0, 1.0]))
        .mul(&p(&[-1000.0, 1.0]))
        .mul(&p(&[5.0, 1.0]));
    let r = positive_roots(&q).expect("simple, well separated roots");
    assert_eq!(r.len(), 3);
    for (b, want) in r.iter().zip([1.0 / 3.0, 2.0, 1000.0]) {
        assert!(b.lo <= want && want <= b.hi, "{b:?} vs {want}");
        // The running error bound of Horner's scheme widens each step by an ulp or two of
        // the partial sum, and the bracket is within a factor two of what that enclosure
        // can certify.
        assert!(b.hi - b.lo <= 64.0 * f64::EPSILON * want, "{b:?}");
    }
}

#[test]
fn even_polynomials_are_isolated_in_the_square_with_the_same_brackets() {
    // q(u) = (u - 1/10)(u - 3)(u - 9)(u + 1), p(x) = q(x^2): positive roots of p at
    // sqrt(1/10), sqrt(3) and 3, and p is given only through its local expansions.
    let q = p(&[-0.1, 1.0])
        .mul(&p(&[-3.0, 1.0]))
        .mul(&p(&[-9.0, 1.0]))
        .mul(&p(&[1.0, 1.0]));
    let px = IPoly::new(
        q.coeffs()
            .iter()
            .flat_map(|c| [*c, I::point(0.0)])
            .take(2 * q.coeffs().len() - 1)
            .collect(),
    );
    assert_eq!(px.in_square().as_ref(), Some(&q));
    let value = |x: f64| px.eval(I::point(x));
    let (local, local_u) = (
        |x0: f64| px.shift(I::point(x0)),
        |u0: f64| q.shift(I::point(u0)),
    );
    let even = positive_roots_windowed_even(&q, &local_u, &local, &value, 1e-12).unwrap();
    let direct = positive_roots_windowed(&px, &local, &value, 1e-12).unwrap();
    assert_eq!(even.len(), 3);
    for ((b, d), want) in even
        .iter()
        .zip(&direct)
        .zip([0.1f64.sqrt(), 3f64.sqrt(), 3.0])
    {
        assert!(b.lo <= want && want <= b.hi, "{b:?} vs {want}");
        assert!(b.relative_width() <= 1e-12, "{b:?}");
        assert!(d.lo <= b.hi && b.lo <= d.hi, "{b:?} vs {d:?}");
    }
    // A root on a window end in u (u = 2) cannot be decided there: an error, not an answer
    // (the caller then isolates in x).
    let on_end = p(&[-2.0, 1.0]).mul(&p(&[1.0, 1.0]));
    let local_u = |u0: f64| on_end.shift(I::point(u0));
    let r = positive_roots_windowed_even(&on_end, &local_u, &local, &value, 1e-12);
    assert_eq!(r, Err(Uncertified::Sign));
    // An odd coefficient that cannot vanish: not even, refused.
    assert_eq!(p(&[1.0, 1e-300, 1.0]).in_square(), None);
}

#[test]
fn undecidable_cases_are_errors_not_answers() {
    // A double root: the Bernstein signs never separate it.
    let d = p(&[-1.0, 1.0]).mul(&p(&[-1.0, 1.0])).mul(&p(&[3.0, 1.0]));
    assert!(positive_roots(&d).is_err());
    // A constant term that may vanish.
    let z = IPoly::new(vec![I::new(-1e-20, 1e-20), I::point(1.0), I::point(1.0)]);
    assert_eq!(positive_roots(&z), Err(Uncertified::Degenerate));
    // No positive roots: x^2 + 1.
    assert_eq!(positive_roots(&p(&[1.0, 0.0, 1.0])), Ok(Vec::new()));
}

/// Two roots 1.8e-7 apart (0.62795908, 0.62795926) and a third at 1.8933: guided splits at
/// sixteenths alone would use up the bits of the nodes' ends near the pair (no exact split
/// point after 15 levels); yielding to bisection isolates all three.
#[test]
fn guided_splits_leave_clustered_roots_isolable() {
    let c = [
        -0.7465876718488366,
        2.7721550534404242,
        -3.149212077114739,
        1.0,
    ];
    let found = positive_roots(&p(&c)).expect("bisection certifies these roots");
    assert_eq!(found.len(), 3, "{found:?}");
    for (b, (root, tolerance)) in
        found
            .iter()
            .zip([(0.62795908, 5e-8), (0.62795926, 5e-8), (1.8932937, 1e-7)])
    {
        assert!((b.value - root).abs() < tolerance, "{b:?} against {root}");
    }
}

/// A root beyond the range of doubles' bound: -1e10 + 1e-300 x^3 has its root near
/// 2.2e103, but the root bound overflows; a bracket is finite or the answer is an error.
#[test]
fn brackets_are_finite_or_refused() {
    let c = p(&[-1e10, 0.0, 0.0, 1e-300]);
    match positive_roots(&c) {
        Ok(found) => {
            for b in &found {
                assert!(
                    b.lo.is_finite() && b.hi.is_finite() && b.value.is_finite(),
                    "{b:?}"
                );
            }
        }
        Err(e) => assert_eq!(e, Uncertified::Wide),
    }
}
