//! Aileron yaw (`n_delta_a != 0`) and roll due to rudder (`l_delta_r`) in the closed form
//! (beyond the paper), checked against an independent numeric computation written here: trim
//! branches from nalgebra LU solves ([`paper_tests::trim_branches`]), det J5 from
//! finite-difference Jacobians, sign changes refined by bisection. Nothing here calls the
//! symbolic layer except the code under test.

use model::aircraft::{f64_to_rational, Aircraft, Param};
use model::algebra::{Poly, Q};
use model::analysis::{analyze, specialisation, univariate};
use model::derivation::Derivation;
use model::equations::symbols;
use paper_tests::{fd_jacobian, ix, pss_rhs, random_params, trim_branches, Lcg, Params};

fn de() -> f64 {
    2f64.to_radians()
}

fn aircraft(k: &Params, name: &str) -> Aircraft {
    let values = k.iter().map(|v| f64_to_rational(*v).unwrap()).collect();
    Aircraft::new(name, values, 150.0)
}

/// A random aircraft with aileron yaw of either sign (1-6 % of l_delta_a) and roll due to
/// rudder.
fn random_yawing(rng: &mut Lcg) -> Params {
    let mut k = random_params(rng);
    let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
    k[ix::NDA] = sign * rng.range(0.01, 0.06) * k[ix::LDA].abs();
    k[ix::LDR] = rng.range(-3.0, 3.0);
    k
}

fn det_j5(k: &Params, x: &[f64; 5], da: f64) -> f64 {
    fd_jacobian(k, x, &[da, de(), 0.0]).determinant()
}

/// The jump points by brute force: every trim branch on a fine P0 grid, det J5 sign changes
/// along each branch (branches paired in ascending delta_a between grid points with the same
/// number of trims), refined by bisection in P0. Only trims with |delta_a| <= 1 rad and
/// moderate states are kept (elsewhere finite differences lose their digits).
fn numeric_jumps(k: &Params, p_max: f64) -> Vec<(f64, f64)> {
    let branches = |p: f64| trim_branches(k, p, de(), 0.0);
    let det_on = |p: f64, i: usize, n: usize| -> Option<(f64, f64)> {
        let b = branches(p);
        (b.len() == n).then(|| (det_j5(k, &b[i].0, b[i].1), b[i].1))
    };
    let mut out = Vec::new();
    let n_grid = 6000;
    let mut prev = branches(1e-6);
    for s in 1..=n_grid {
        let p = p_max * s as f64 / n_grid as f64;
        let cur = branches(p);
        if cur.len() == prev.len() {
            for i in 0..cur.len() {
                let (x0, x1) = (&prev[i], &cur[i]);
                let big = |x: &[f64; 5]| x.iter().any(|v| v.abs() > 5.0);
                if x0.1.abs() > 1.0 || x1.1.abs() > 1.0 || big(&x0.0) || big(&x1.0) {
                    continue;
                }
                let (d0, d1) = (det_j5(k, &x0.0, x0.1), det_j5(k, &x1.0, x1.1));
                if d0 * d1 >= 0.0 {
                    continue;
                }
                let n = cur.len();
                let (mut lo, mut hi, mut dlo) = (p - p_max / n_grid as f64, p, d0);
                let mut da = x1.1;
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let Some((dm, dam)) = det_on(mid, i, n) else {
                        break;
                    };
                    da = dam;
                    if dm * dlo > 0.0 {
                        lo = mid;
                        dlo = dm;
                    } else {
                        hi = mid;
                    }
                }
                out.push((0.5 * (lo + hi), da));
            }
        }
        prev = cur;
    }
    out
}

#[test]
fn jump_points_with_aileron_yaw_equal_an_independent_numeric_scan() {
    let mut rng = Lcg(808);
    let mut compared = 0;
    let mut signs = [0, 0];
    for i in 0..6 {
        let k = random_yawing(&mut rng);
        signs[usize::from(k[ix::NDA] > 0.0)] += 1;
        let ac = aircraft(&k, &format!("random yawing {i}"));
        let a = analyze(&ac, de()).unwrap();
        let p_max = 6.0;
        let numeric = numeric_jumps(&k, p_max);
        // Every numeric fold is a reported jump point, with its aileron.
        for (p, da) in &numeric {
            let j = a
                .jump
                .iter()
                .find(|j| (j.p0 - p).abs() < 1e-6)
                .unwrap_or_else(|| {
                    panic!(
                        "{}: numeric fold at P0 = {p} missing: {:?}",
                        ac.name, a.jump
                    )
                });
            assert!(
                (j.delta_a_rad - da).abs() < 1e-6 * (1.0 + da.abs()),
                "{j:?} vs {da}"
            );
            compared += 1;
        }
        // Every reported jump point inside the scanned region is a numeric fold: a trim with
        // all five PSS equations satisfied and det J5 = 0 (nothing spurious).
        for j in &a.jump {
            let x = [j.alpha, j.beta, j.p0, j.q, j.r];
            if j.p0 >= p_max - 1e-3 || j.delta_a_rad.abs() > 1.0 || x.iter().any(|v| v.abs() > 5.0)
            {
                continue;
            }
            let res = pss_rhs(&k, &x, &[j.delta_a_rad, de(), 0.0]);
            let scale = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            assert!(
                res.iter().all(|r| r.abs() < 1e-8 * scale * 100.0),
                "{j:?}: {res:?}"
            );
            assert!(
                numeric.iter().any(|(p, _)| (p - j.p0).abs() < 1e-6),
                "{}: reported jump {j:?} is no numeric fold ({numeric:?})",
                ac.name
            );
        }
    }
    assert!(
        signs[0] > 0 && signs[1] > 0,
        "both signs of n_delta_a: {signs:?}"
    );
    assert!(compared >= 6, "{compared} folds compared");
}

#[test]
fn without_aileron_yaw_the_eliminated_jump_polynomial_is_the_papers() {
    // With n_delta_a = 0 the trim condition is linear in delta_a and the resultant on the
    // actual degrees is det J5 det(A)^2 itself, exactly.
    for ac in [Aircraft::a(), Aircraft::b()] {
        let d = Derivation::derive(&specialisation(&ac, de()));
        assert_eq!(d.jump(), d.jump_at(), "{}", ac.name);
        assert_eq!(d.poles(), d.d_at(), "{}", ac.name);
    }
}

#[test]
fn eliminated_jump_polynomial_is_continuous_in_n_delta_a_with_only_pole_factors_at_zero() {
    // Aircraft A's data with n_delta_a left symbolic: the resultant divided by n_delta_a^2 is
    // continuous in n_delta_a; at n_delta_a = 0 it is g1^2 e J, where J is the paper's jump
    // polynomial, g1 = l_delta_a det(A)^2 marks the trim poles and e the trim branch that leaves
    // to infinite aileron. So it has exactly the paper's jump roots once those are removed.
    let s = symbols();
    let nda = s.param(Param::NDeltaA);
    let values: Vec<_> = specialisation(&Aircraft::a(), de())
        .into_iter()
        .filter(|(x, _)| *x != nda)
        .collect();
    let d = Derivation::derive(&values);
    let zero = Poly::zero();
    let at0 = |p: &Poly| p.subs(nda, &zero);
    let g1 = at0(&d.trim_condition().coeff(s.delta_a, 1));
    let e = d.jump_at().coeff(s.delta_a, 2).div_var_pow(nda, 2).unwrap();
    let paper = at0(d.jump_at());
    assert!(!paper.contains(s.delta_a));
    let lhs = at0(d.jump());
    let rhs = &(&(&g1 * &g1) * &at0(&e)) * &paper;
    assert_eq!(lhs, rhs);
    // g1 = l_delta_a det(A)^2 exactly.
    let det_a = at0(&d.det_a);
    let l_da = Poly::constant(Q::from_big(Aircraft::a().exact(Param::LDeltaA).clone()));
    assert_eq!(g1, &l_da * &(&det_a * &det_a));
    // The roots of the paper's polynomial are roots of the eliminated one, and e adds no
    // positive root that has a finite trim: analyze reports exactly the paper's jump points.
    let u = |p: &Poly| univariate(p, s.p0);
    let (j, jp) = (u(&lhs), u(&paper));
    assert!(j.div_rem(&jp).1.is_zero());
    let a = analyze(&Aircraft::a(), de()).unwrap();
    assert_eq!(a.jump.len(), 2);
}

#[test]
fn generated_trim_returns_both_branches_and_each_satisfies_all_five_pss_equations() {
    let mut rng = Lcg(77);
    let (mut checked, mut two) = (0, 0);
    for _ in 0..20 {
        let k = random_yawing(&mut rng);
        let g = paper_tests::generated_derivatives(&k);
        for p0 in [0.3, 1.1, 2.0, 3.3] {
            let dr = 0.01;
            let branches = roll_criterion::trim(&g, p0, de(), dr);
            let mut found: Vec<f64> = Vec::new();
            for t in &branches {
                let x = [t.alpha, t.beta, p0, t.q, t.r];
                if !(t.delta_a.is_finite() && x.iter().all(|v| v.is_finite())) {
                    continue;
                }
                let res = pss_rhs(&k, &x, &[t.delta_a, de(), dr]);
                let scale = x
                    .iter()
                    .chain([&t.delta_a])
                    .fold(1.0f64, |m, v| m.max(v.abs()));
                assert!(
                    res.iter().all(|r| r.abs() < 1e-9 * scale * scale * 300.0),
                    "{res:?}"
                );
                found.push(t.delta_a);
            }
            // The same trims as the oracle's (LU solves and the roll quadratic), no more, no
            // fewer, where the oracle's are moderate.
            let oracle: Vec<f64> = trim_branches(&k, p0, de(), dr)
                .iter()
                .map(|b| b.1)
                .filter(|da| da.abs() < 1e6)
                .collect();
            for da in &oracle {
                assert!(
                    found
                        .iter()
                        .any(|f| (f - da).abs() < 1e-8 * (1.0 + da.abs())),
                    "oracle trim {da} missing from {branches:?}"
                );
            }
            two += usize::from(oracle.len() == 2);
            checked += 1;
        }
    }
    assert!(
        checked >= 60 && two >= 20,
        "{checked} roll rates, {two} with two trims"
    );
    // Without aileron yaw there is one trim: the second element is not a number.
    let k = paper_tests::random_params(&mut rng);
    let t = roll_criterion::trim(&paper_tests::generated_derivatives(&k), 1.0, de(), 0.0);
    assert!(
        t[0].delta_a.is_finite() && !t[1].delta_a.is_finite(),
        "{t:?}"
    );
}

#[test]
fn generated_zero_sideslip_trim_holds_with_aileron_yaw_and_roll_due_to_rudder() {
    // Both lateral controls enter both lateral equations: the aileron and rudder of the
    // generated zero-sideslip trim must be the oracle's 2x2 solve, and hold all five equations.
    let mut rng = Lcg(99);
    let mut checked = 0;
    for _ in 0..20 {
        let k = random_yawing(&mut rng);
        let g = paper_tests::generated_derivatives(&k);
        for p0 in [0.4, 1.3, 2.6] {
            let t = roll_criterion::zero_sideslip_trim(&g, p0, de());
            let (x, da, dr) = paper_tests::zero_sideslip_trim(&k, p0, de()).unwrap();
            let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * (1.0 + b.abs());
            assert!(
                close(t.delta_a, da) && close(t.delta_r, dr),
                "{t:?} vs {da} {dr}"
            );
            assert!(
                close(t.alpha, x[0]) && close(t.q, x[3]) && close(t.r, x[4]),
                "{t:?}"
            );
            let res = pss_rhs(
                &k,
                &[t.alpha, 0.0, p0, t.q, t.r],
                &[t.delta_a, de(), t.delta_r],
            );
            assert!(res.iter().all(|r| r.abs() < 1e-9), "{res:?}");
            checked += 1;
        }
    }
    assert_eq!(checked, 60);
}

/// How the primary branch ends, traced by the oracle: `Some(p0)` for a jump (a sign change of
/// det J5 along the branch), `None` when |delta_a| passes `bound` first; and the roll rate of
/// the first turn, if any. The curve is followed on a uniform grid of P0 through the oracle's
/// trims ([`trim_branches`], ascending in delta_a), from one grid point to the next by the
/// nearest trim. Where the two trims of a roll rate merge (none at the next grid point) the
/// curve turns and goes on with the other one, P0 running back: at the first point back it is
/// the trim on the other one's side in the ascending order (the two straddle the fold, and the
/// order holds over one step), then the nearest again.
fn oracle_primary(k: &Params, de: f64, bound: f64, p_max: f64) -> (Option<f64>, Option<f64>) {
    let step = 1e-4;
    let at = |p: f64| trim_branches(k, p, de, 0.0);
    let nearest = |t: &[([f64; 5], f64)], da: f64| {
        (0..t.len()).min_by(|a, b| (t[*a].1 - da).abs().total_cmp(&(t[*b].1 - da).abs()))
    };
    let (mut p, mut dir, mut turn) = (0.0f64, 1.0, None);
    let (mut da, mut det, mut turned) = (0.0, None, None);
    while p.abs() < p_max {
        let next = at(p + dir * step);
        let i = match turned.take() {
            Some(side) if next.len() == 2 => Some(side),
            _ => nearest(&next, da),
        };
        let Some(i) = i else {
            // The fold: continue on the other trim of the last roll rate, running back.
            assert!(turn.is_none(), "a second turn within the bound");
            let last = at(p);
            assert_eq!(last.len(), 2, "two trims next to the fold at {p}");
            let mine = nearest(&last, da).unwrap();
            turn = Some(p);
            dir = -dir;
            turned = Some(1 - mine);
            da = last[1 - mine].1;
            continue;
        };
        p += dir * step;
        let (x, next_da) = next[i];
        da = next_da;
        if da.abs() > bound {
            return (None, turn);
        }
        let d = det_j5_at(k, &x, da, de);
        if det.is_some_and(|e: f64| d * e < 0.0) {
            return (Some(p), turn);
        }
        det = Some(d);
    }
    panic!("the oracle's primary branch has no end below P0 = {p_max}");
}

fn det_j5_at(k: &Params, x: &[f64; 5], da: f64, de: f64) -> f64 {
    fd_jacobian(k, x, &[da, de, 0.0]).determinant()
}

/// A branch that turns in P0 goes on along its other trim, not back along itself. Aircraft A
/// with n_delta_a = 40 /s^2 at delta_e = -4 deg: the primary branch turns near P0 = 3.88 rad/s
/// at delta_a = 72.5 deg, and its other trim reaches the aileron range (90 deg) before any jump.
/// Both routes of `analyze` must say so; following the nearest trim at the first step back
/// (the two straddle the fold almost symmetrically) walked back down the primary branch, to the
/// mirror fold at -3.88 and up again, until the walk gave up after 2e6 steps ("not defined").
#[test]
fn a_branch_that_turns_goes_on_along_its_other_trim() {
    let mut k = Aircraft::a().values_f64();
    k[ix::NDA] = 40.0;
    let a = aircraft(&k, "A, n_delta_a = 40");
    let de = (-4f64).to_radians();
    let bound = a.aileron_range();
    let (jump, turn) = oracle_primary(&k, de, bound, 8.0);
    let turn = turn.expect("the oracle's branch turns");
    assert!((3.8..3.95).contains(&turn), "turn at {turn}");
    assert_eq!(jump, None, "the oracle meets a jump first");
    for (route, r) in [
        ("exact", analyze(&a, de).unwrap()),
        (
            "certified",
            model::analysis::fast::analyze_fast(&a, de).unwrap(),
        ),
    ] {
        assert!(r.critical.is_none(), "{route}: {:?}", r.critical);
        let note = r.critical_note.unwrap_or_default();
        assert!(
            note.contains("reaches |delta_a| = 90.0 deg"),
            "{route}: {note}"
        );
    }
}
