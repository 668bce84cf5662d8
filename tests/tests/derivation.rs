//! The derivation checked against independent numerics, for symbolic parameters and for
//! random aircraft that are neither A nor B (n_p != 0, other inertias): nothing is tuned.

use model::aircraft::{Aircraft, Param};
use model::algebra::{Poly, Sym, Q};
use model::analysis::analyze;
use model::derivation::Derivation;
use model::equations::symbols;
use paper_tests::{
    fd_jacobian, pss_rhs, random_trimmed_params, residual_denominator, trim, Lcg, Params,
};
use std::sync::OnceLock;

fn parametric() -> &'static Derivation {
    static D: OnceLock<Derivation> = OnceLock::new();
    D.get_or_init(Derivation::parametric)
}

/// Symbol values for evaluating parametric results in f64.
fn lookup(k: &Params, extra: &[(Sym, f64)]) -> impl Fn(Sym) -> f64 {
    let s = symbols();
    let mut table: Vec<(Sym, f64)> = Param::ALL
        .iter()
        .map(|p| (s.param(*p), k[p.index()]))
        .collect();
    table.extend_from_slice(extra);
    move |x| {
        table
            .iter()
            .find(|(t, _)| *t == x)
            .map_or(f64::NAN, |(_, v)| *v)
    }
}

/// [`lookup`] with the trim symbols at the state `x` = [alpha, beta, p, q, r].
fn lookup_state(k: &Params, x: &[f64; 5]) -> impl Fn(Sym) -> f64 {
    let s = symbols();
    let state = [s.alpha0, s.beta0, s.p0, s.q0, s.r0];
    let extra: Vec<(Sym, f64)> = state.into_iter().zip(x.iter().copied()).collect();
    lookup(k, &extra)
}

fn eval(p: &Poly, f: &impl Fn(Sym) -> f64) -> f64 {
    p.eval_f64(f)
}

#[test]
fn identity_det_j5_equals_d_det_k_symbolically() {
    // Step 7: the difference normalizes to exactly zero for symbolic parameters.
    let d = parametric();
    assert!(
        d.identity_residual.is_zero(),
        "det J5 - d det K = {:?}",
        d.identity_residual
    );
    // and the matrix-determinant-lemma form agrees with the entrywise d K: det(dK) = d (d det K).
    let kd = &d.k_times_d;
    let det_dk = &(&kd[0][0] * &kd[1][1]) - &(&kd[0][1] * &kd[1][0]);
    assert!((&det_dk - &(&d.d * &d.d_det_k)).is_zero());
}

#[test]
fn symbolic_linearization_equals_central_difference_jacobian() {
    let d = parametric();
    let mut rng = Lcg(7);
    for _ in 0..200 {
        let k = random_trimmed_params(&mut rng);
        let x: [f64; 5] = std::array::from_fn(|_| rng.range(-1.0, 1.0));
        let u = [
            rng.range(-0.2, 0.2),
            rng.range(-0.1, 0.1),
            rng.range(-0.1, 0.1),
        ];
        let f = lookup_state(&k, &x);
        let num = fd_jacobian(&k, &x, &u);
        for i in 0..5 {
            for j in 0..5 {
                let sym = eval(d.jacobian.get(i, j), &f);
                // Central differences of a quadratic model are exact up to rounding:
                // |error| <~ eps * |f| / h ~ 1e-16 * 1e3 / 1e-6.
                assert!(
                    (sym - num[(i, j)]).abs() < 1e-6 * (1.0 + sym.abs()),
                    "J[{i}][{j}]: symbolic {sym}, numeric {}",
                    num[(i, j)]
                );
            }
        }
    }
}

#[test]
fn identity_holds_numerically_at_random_points() {
    let d = parametric();
    let mut rng = Lcg(11);
    for _ in 0..200 {
        let k = random_trimmed_params(&mut rng);
        let x: [f64; 5] = std::array::from_fn(|_| rng.range(-1.0, 1.0));
        let f = lookup_state(&k, &x);
        let j = fd_jacobian(&k, &x, &[0.0; 3]);
        let det_j5 = j.determinant();
        let dd = residual_denominator(&j);
        assert!((eval(&d.d, &f) - dd).abs() < 1e-6 * (1.0 + dd.abs()));
        let kd = &d.k_times_d;
        let det_k = (eval(&kd[0][0], &f) * eval(&kd[1][1], &f)
            - eval(&kd[0][1], &f) * eval(&kd[1][0], &f))
            / (dd * dd);
        let scale = 1.0 + det_j5.abs() + (dd * det_k).abs();
        assert!(
            (det_j5 - dd * det_k).abs() < 1e-6 * scale,
            "det J5 {det_j5}, d det K {}",
            dd * det_k
        );
    }
}

#[test]
fn trim_formulas_solve_the_pss_equations() {
    let s = symbols();
    let d = parametric();
    let mut rng = Lcg(3);
    for _ in 0..200 {
        let k = random_trimmed_params(&mut rng);
        let (p0, de, dr) = (
            rng.range(0.0, 6.0),
            rng.range(-0.1, 0.1),
            rng.range(-0.1, 0.1),
        );
        // random_trimmed_params has no aileron yaw, so the trim's delta_a term vanishes whatever
        // delta_a is (tests/tests/aileron_yaw.rs checks the trims with aileron yaw).
        let f = lookup(
            &k,
            &[
                (s.p0, p0),
                (s.delta_e, de),
                (s.delta_r, dr),
                (s.delta_a, 0.0),
            ],
        );
        let den = eval(&d.det_a, &f);
        let t: Vec<f64> = d.trim.iter().map(|n| eval(n, &f) / den).collect();
        let g = lookup(
            &k,
            &[
                (s.alpha0, t[0]),
                (s.beta0, t[1]),
                (s.p0, p0),
                (s.q0, t[2]),
                (s.r0, t[3]),
                (s.delta_r, dr),
            ],
        );
        let da = eval(&d.delta_a.num, &g) / eval(&d.delta_a.den, &g);
        let (x, da_lu) = trim(&k, p0, de, dr).unwrap();
        let scale = 1.0 + x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, (a, b)) in [x[0], x[1], x[3], x[4]].iter().zip(&t).enumerate() {
            assert!(
                (a - b).abs() < 1e-8 * scale,
                "state {i}: LU {a}, formula {b}"
            );
        }
        assert!((da - da_lu).abs() < 1e-8 * (1.0 + da.abs()));
        let res = pss_rhs(&k, &[t[0], t[1], p0, t[2], t[3]], &[da, de, dr]);
        assert!(
            res.iter().all(|v| v.abs() < 1e-8 * scale * 100.0),
            "{res:?}"
        );
    }
}

#[test]
fn jump_polynomial_is_even_in_p0_with_delta_r_zero() {
    // The symmetry A(-P) = S A(P) S with S = diag(1,-1,1,-1) makes the jump
    // polynomial even when delta_r = 0; degree 12, 7 nonzero coefficients.
    let s = symbols();
    let d = Derivation::derive(&[(s.delta_r, Q::ZERO)]);
    // Without aileron yaw (the paper's aircraft) det J5 det(A)^2 is a polynomial in P0 alone.
    let jump = d.jump_at().subs(s.param(Param::NDeltaA), &Poly::zero());
    let c = jump.coeffs(s.p0);
    assert_eq!(c.len(), 13, "degree 12 in P0");
    assert!(
        c.iter().skip(1).step_by(2).all(Poly::is_zero),
        "odd coefficients vanish"
    );
    assert_eq!(c.iter().filter(|p| !p.is_zero()).count(), 7);
    // Its parameters: every derivative that enters J5 or the trim, and nothing else.
    assert!(!jump.contains(s.param(Param::LDeltaA)) && !jump.contains(s.delta_a));
}

#[test]
fn eq_5_odd_powers_of_det_a_vanish_and_leading_coefficient_is_cd() {
    let s = symbols();
    let d = parametric();
    let cd = &Poly::var(s.param(Param::C)) * &Poly::var(s.param(Param::D));
    assert_eq!(d.biquadratic[2], cd);
}

/// Zeros of det J5 along the trim curve by an independent numeric scan (LU trims,
/// nalgebra determinant); those with d != 0 are the jump points (det J5 = d det K).
fn numeric_jump_points(k: &Params, de: f64, p_max: f64) -> Vec<f64> {
    let det =
        |p0: f64| trim(k, p0, de, 0.0).map(|(x, _)| fd_jacobian(k, &x, &[0.0; 3]).determinant());
    let dd = |p0: f64| {
        trim(k, p0, de, 0.0).map(|(x, _)| residual_denominator(&fd_jacobian(k, &x, &[0.0; 3])))
    };
    let n = 20000;
    let mut out = Vec::new();
    let mut prev = (1e-4, det(1e-4));
    for i in 1..=n {
        let p = 1e-4 + p_max * i as f64 / n as f64;
        let cur = (p, det(p));
        if let (Some(a), Some(b)) = (prev.1, cur.1) {
            if a.signum() != b.signum() {
                let (mut lo, mut hi) = (prev.0, cur.0);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    match det(mid) {
                        Some(m) if m.signum() == a.signum() => lo = mid,
                        _ => hi = mid,
                    }
                }
                let root = 0.5 * (lo + hi);
                // Discard sign changes at poles of the trim (det A = 0) and at d = 0.
                let finite =
                    det(root).is_some_and(|v| v.abs() < 1e-3 * (1.0 + a.abs().max(b.abs())));
                if finite && dd(root).is_some_and(|v| v.abs() > 1e-6) {
                    out.push(root);
                }
            }
        }
        prev = cur;
    }
    out
}

#[test]
fn analyze_matches_an_independent_numeric_scan_on_random_aircraft() {
    let mut rng = Lcg(2024);
    let mut total = 0;
    for case in 0..40 {
        let k = random_trimmed_params(&mut rng);
        let values = k
            .iter()
            .map(|v| model::aircraft::f64_to_rational(*v).unwrap())
            .collect();
        let ac = Aircraft::new(format!("random {case}"), values, 150.0);
        let de = rng.range(-0.05, 0.05);
        let a = analyze(&ac, de).unwrap();
        let p_max = 6.0;
        let want = numeric_jump_points(&k, de, p_max);
        let got: Vec<f64> = a.jump.iter().map(|j| j.p0).filter(|p| *p < p_max).collect();
        // Roots of even multiplicity do not change sign and escape the scan; the random data
        // make them non-generic, so the sets must agree.
        assert_eq!(
            got.len(),
            want.len(),
            "case {case}: analyze {got:?}, scan {want:?}"
        );
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-6 * (1.0 + w), "case {case}: {g} vs {w}");
        }
        total += got.len();
    }
    assert!(
        total > 10,
        "the random aircraft must exercise the criterion ({total} roots)"
    );
}

/// `x` and `y` differ by a nonzero constant factor, exactly: `x * lc(y) == y * lc(x)`.
fn proportional(x: &Poly, y: &Poly) -> bool {
    let s = symbols();
    let lead = |p: &Poly| p.coeff(s.p0, p.degree(s.p0)).as_constant().unwrap();
    !x.is_zero() && (&x.scale(&lead(y)) - &y.scale(&lead(x))).is_zero()
}

#[test]
fn analysis_polynomials_are_proportional_to_the_specialised_derivation() {
    // `analyze` substitutes the data into trim-level parametric results and clears
    // denominators with integer scales; the full derivation specialised before its first step
    // must give the same polynomials up to constants.
    let mut rng = Lcg(77);
    let mut aircraft = vec![Aircraft::a(), Aircraft::b()];
    for i in 0..3 {
        let k = random_trimmed_params(&mut rng);
        let values = k
            .iter()
            .map(|v| model::aircraft::f64_to_rational(*v).unwrap())
            .collect();
        aircraft.push(Aircraft::new(format!("random {i}"), values, 150.0));
    }
    // Degenerate inertias: E = 0 makes d linear in the trim states (step 8 must still clear
    // d and det J5 with the same power of det A), D = 0 makes det A quadratic in P0.
    for (label, param) in [("E = 0", Param::E), ("D = 0", Param::D)] {
        let a = Aircraft::a();
        let values = Param::ALL
            .iter()
            .map(|p| {
                if *p == param {
                    Default::default()
                } else {
                    a.exact(*p).clone()
                }
            })
            .collect();
        aircraft.push(Aircraft::new(format!("A with {label}"), values, 150.0));
    }
    // Aileron yaw and roll due to rudder: the trim gains delta_a, the trim condition turns
    // quadratic.
    let mut values: Vec<_> = Param::ALL
        .iter()
        .map(|p| Aircraft::a().exact(*p).clone())
        .collect();
    values[Param::NDeltaA.index()] = model::aircraft::f64_to_rational(8.0).unwrap();
    values[Param::LDeltaR.index()] = model::aircraft::f64_to_rational(-2.5).unwrap();
    aircraft.push(Aircraft::new("A with aileron yaw", values, 150.0));
    for ac in aircraft {
        let de = 2f64.to_radians();
        // Emitting the specialised functions must not panic either (proc-macro input).
        assert!(!model::emit::specialised_functions(&ac).is_empty());
        let fast = model::analysis::CriterionPolys::new(parametric(), &ac, de);
        let full = Derivation::derive(&model::analysis::specialisation(&ac, de));
        for (f, g, what) in [
            (&fast.det_a, &full.det_a, "det A"),
            (&fast.jump_at, full.jump_at(), "jump"),
            (&fast.d_at, full.d_at(), "d det A"),
            (&fast.zs_jump, full.zs_jump(), "zs jump"),
            (&fast.zs_d_det, full.zs_d_det(), "zs d"),
        ] {
            assert!(proportional(f, g), "{}: {what}", ac.name);
        }
        let u = |p: &Poly| model::analysis::univariate(p, symbols().p0);
        for (f, g, what) in [
            (&fast.jump, u(full.jump()), "jump resultant"),
            (&fast.poles, u(full.poles()), "pole resultant"),
        ] {
            let (lf, lg) = (f.leading_coeff().unwrap(), g.leading_coeff().unwrap());
            assert_eq!(f.scale(lg), g.scale(lf), "{}: {what}", ac.name);
        }
        // det K = det J5 / d = jump / d_det_a exactly, at a rational roll rate (this fails if
        // the two are cleared with different powers of det A, e.g. when E = 0).
        let s = symbols();
        let p0 = Q::ratio(7, 5);
        // At a rational aileron too: with aileron yaw the trim of P0 depends on it (the
        // identity holds at every (P0, delta_a), on the equilibrium curve or off it).
        let at_p0 = |p: &Poly| {
            p.subs_values(&[(s.p0, p0.clone()), (s.delta_a, Q::ratio(1, 10))])
                .as_constant()
                .unwrap()
        };
        let den = at_p0(&full.det_a);
        let mut trims: Vec<(model::algebra::Sym, Q)> = [s.alpha0, s.beta0, s.q0, s.r0]
            .iter()
            .zip(&full.trim)
            .map(|(sym, n)| (*sym, at_p0(n).div(&den)))
            .collect();
        trims.push((s.p0, p0.clone()));
        trims.push((s.delta_a, Q::ratio(1, 10)));
        let exact = |p: &Poly| p.subs_values(&trims).as_constant().unwrap();
        let det_k = exact(&full.det_j5).div(&exact(&full.d));
        assert_eq!(
            det_k,
            at_p0(full.jump_at()).div(&at_p0(full.d_at())),
            "{}",
            ac.name
        );
        // The trims are the same ratios.
        for (n_fast, n_full) in fast.trim.iter().zip(&full.trim) {
            let lhs = n_fast * &full.det_a;
            let rhs = n_full * &fast.det_a;
            assert!((&lhs - &rhs).is_zero(), "{}: trim ratio", ac.name);
        }
    }
}
