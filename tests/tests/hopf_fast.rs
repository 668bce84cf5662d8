//! The full analysis (Hopf points with omega and l1, landings, first departure,
//! zero-sideslip Hopf roll rates) on the certified route (`analyze_routed_with(.., true)`)
//! gives the exact path's answer (`analyze_with(.., true)`, big rationals), and the structural
//! factors of det A it divides by hold.
//!
//! Random aircraft around A and B as in `certified.rs`. Aircraft with aileron yaw are sent to
//! the exact path by design (their Hopf polynomial is a resultant in delta_a, not enclosed), so
//! the share the certified route must answer is counted on those without.

mod support;

use model::aircraft::{Aircraft, Param};
use model::analysis::fast::{analyze_routed_with, Route};
use model::analysis::{
    analyze_with, parametric, parametric_characteristic, univariate, Analysis, CriterionPolys,
};
use model::certified::Uncertified;
use model::derivation::hopf::{cleared_coefficients, TRIM_FACTOR_POWERS};
use model::equations::symbols;
use model::specialise::specialisation;
use num_rational::BigRational;
use support::{close, close_roots, random_aircraft, same_analysis, size, Rng};

/// Aircraft in the random sample (the full-size run: `ROLL_FULL_SIZE=1`).
fn n() -> usize {
    size(300, 1000)
}

/// The aircraft without aileron yaw (n_delta_a = 0), the certified route's whole domain.
fn without_aileron_yaw(ac: Aircraft) -> Aircraft {
    ac.with(Param::NDeltaA, BigRational::from_integer(0.into()))
}

/// The departure part of two analyses agrees: same Hopf points (P0 within the certified width,
/// omega and l1 to 1e-6 relative where the trim is within the validity range, kind and marks),
/// same landings, same first departure, same zero-sideslip Hopf roll rates.
fn same_departures(e: &Analysis, f: &Analysis, w: f64) -> Result<(), String> {
    if e.hopf.len() != f.hopf.len() {
        return Err(format!("{} vs {} Hopf points", e.hopf.len(), f.hopf.len()));
    }
    for (x, y) in e.hopf.iter().zip(&f.hopf) {
        let (p, q) = (&x.point, &y.point);
        if !close_roots(p.p0, q.p0, w)
            || p.within_validity != q.within_validity
            || p.within_limits != q.within_limits
        {
            return Err(format!("Hopf point {p:?} vs {q:?}"));
        }
        // Outside the validity range the trim is a badly conditioned f64 evaluation on both
        // routes (see `certified.rs`): only the roll rate and the marks are compared there.
        if p.within_validity && !(close(x.omega, y.omega) && close(x.l1, y.l1) && x.kind == y.kind)
        {
            return Err(format!(
                "Hopf point at P0 = {}: omega {} vs {}, l1 {} vs {}",
                p.p0, x.omega, y.omega, x.l1, y.l1
            ));
        }
    }
    for (x, y) in e.jump.iter().zip(&f.jump) {
        let (a, b) = (x.lands_at.as_ref(), y.lands_at.as_ref());
        let (a, b) = (a.ok_or("exact landings")?, b.ok_or("certified landings")?);
        if a.len() != b.len() {
            return Err(format!("landings of P0 = {}: {a:?} vs {b:?}", x.p0));
        }
        // A landing is a root of the trim condition at the fold's aileron, and that aileron is
        // itself an f64 evaluation at the fold (its last digits differ between the routes): far
        // out (P0 ~ 90 rad/s was met) the root moves by 1e-9 relative with it. So landings
        // agree to the printed precision, not to the certified width.
        for (l, m) in a.iter().zip(b) {
            let valid = l.alpha.abs() < 0.5 && l.beta.abs() < 0.5;
            if !close(l.p0, m.p0) || valid && !(close(l.alpha, m.alpha) && close(l.beta, m.beta)) {
                return Err(format!("landing {l:?} vs {m:?}"));
            }
        }
    }
    match (&e.first_departure, &f.first_departure) {
        (None, None) => {}
        (Some(x), Some(y)) => {
            if x.kind != y.kind
                || !close_roots(x.p0, y.p0, w)
                || x.hopf_kind != y.hopf_kind
                || x.lands_at.as_ref().map(Vec::len) != y.lands_at.as_ref().map(Vec::len)
            {
                return Err(format!("first departure {x:?} vs {y:?}"));
            }
        }
        (x, y) => return Err(format!("first departure {x:?} vs {y:?}")),
    }
    let (a, b) = (
        &e.zero_sideslip.hopf_roll_rates,
        &f.zero_sideslip.hopf_roll_rates,
    );
    if a.len() != b.len() || a.iter().zip(b).any(|(x, y)| !close_roots(*x, *y, w)) {
        return Err(format!("zero-sideslip Hopf roll rates {a:?} vs {b:?}"));
    }
    Ok(())
}

#[test]
fn certified_full_analysis_agrees_with_the_exact_path_on_random_aircraft() {
    let n = n();
    let mut rng = Rng::new(1010);
    let (mut certified, mut total, mut fallbacks) = (0usize, 0usize, Vec::new());
    let (mut hopf_points, mut uncovered) = (0usize, 0usize);
    for i in 0..n {
        let ac = random_aircraft(&mut rng, i);
        // Three in four without aileron yaw (the certified route's domain), the rest with it
        // (which must fall back, and then equal the exact path trivially).
        let yaw = rng.unit() < 0.25 && ac.value(Param::NDeltaA) != 0.0;
        let ac = if yaw { ac } else { without_aileron_yaw(ac) };
        let de = rng.uniform(-5.0, 5.0).to_radians();
        let exact = analyze_with(&ac, de, true);
        let fast = analyze_routed_with(&ac, de, true);
        match (&exact, &fast) {
            (Ok(e), Ok((f, route))) => {
                let w = match route {
                    Route::Certified(w) => {
                        assert!(!yaw, "aircraft {i}: aileron yaw is not certified");
                        certified += 1;
                        hopf_points += f.hopf.len();
                        *w
                    }
                    Route::Exact(why) => {
                        // With aileron yaw the departure part is not covered (or the jump
                        // part's certificate failed first, as in `certified.rs`).
                        if yaw {
                            uncovered += usize::from(*why == Uncertified::Uncovered);
                        } else {
                            fallbacks.push(*why);
                        }
                        0.0
                    }
                };
                if !yaw {
                    total += 1;
                }
                let same = same_analysis(e, f, w).and_then(|()| same_departures(e, f, w));
                if let Err(why) = same {
                    panic!("aircraft {i} ({ac:?}, delta_e {de}): {why}");
                }
            }
            (Err(a), Err(b)) => assert_eq!(a, b, "aircraft {i}: both refuse alike"),
            _ => panic!(
                "aircraft {i}: exact {:?} vs certified {:?}",
                exact.as_ref().err(),
                fast.as_ref().err()
            ),
        }
    }
    println!(
        "{n} aircraft, {total} without aileron yaw: {certified} certified ({hopf_points} Hopf \
         points among them), fallbacks {fallbacks:?}; {uncovered} with aileron yaw uncovered"
    );
    assert!(uncovered > 0, "aileron yaw goes to the exact path");
    assert!(
        certified as f64 >= 0.9 * total as f64,
        "only {certified} of {total} certified"
    );
    assert!(
        hopf_points > 0,
        "the sample must hold Hopf points to compare"
    );
}

/// The powers of det A (det A1) the certified route divides the cleared characteristic
/// coefficients by ([`TRIM_FACTOR_POWERS`]) divide them exactly, on A, B and random aircraft
/// without aileron yaw: checked on the exact polynomials, independently of the enclosures.
#[test]
fn trim_factor_powers_divide_the_cleared_characteristic_coefficients() {
    let s = symbols();
    let mut rng = Rng::new(99);
    let mut sample = vec![Aircraft::a(), Aircraft::b()];
    sample.extend((0..size(6, 40)).map(|i| without_aileron_yaw(random_aircraft(&mut rng, i))));
    let de = 2f64.to_radians();
    for (i, ac) in sample.iter().enumerate() {
        let cp = CriterionPolys::new(parametric(), ac, de);
        let values = specialisation(ac, de);
        let c = parametric_characteristic()
            .clone()
            .map(|ck| ck.subs_values(&values));
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        let t3 = [s.alpha0, s.q0, s.r0];
        let zero = [(s.beta0, model::algebra::Q::ZERO)];
        let czs = c.clone().map(|ck| ck.subs_values(&zero));
        for (cleared, den) in [
            (
                cleared_coefficients(&c, &t4, &cp.trim, &cp.det_a),
                &cp.det_a,
            ),
            (
                cleared_coefficients(&czs, &t3, &cp.zs_trim, &cp.zs_det),
                &cp.zs_det,
            ),
        ] {
            let den = univariate(den, s.p0);
            for (k, ck) in cleared.iter().enumerate() {
                let mut rest = univariate(ck, s.p0);
                for _ in 0..TRIM_FACTOR_POWERS[k] {
                    let (q, r) = rest.div_rem(&den);
                    assert!(
                        r.is_zero(),
                        "aircraft {i}: C{} / den^{}",
                        k + 1,
                        TRIM_FACTOR_POWERS[k]
                    );
                    rest = q;
                }
            }
        }
    }
}

/// At `delta_e = 0` in the paper's case (no trim lift `z_0`, the principal axis on the path,
/// `alpha_t = 0`) the zero-sideslip trim is the origin: every numerator of Eq. 35 is then a
/// multiple of `delta_e`, so step 8 makes the zero-sideslip jump and pole polynomials
/// `det(A1)^2 f(0)` and each cleared characteristic coefficient `C_k = det(A1)^k c_k(0)`. The
/// certified route divides those whole powers out (their double roots cannot be isolated);
/// checked here on the parametric derivation and on the exact polynomials of A, B and random
/// aircraft, independently of the enclosures.
#[test]
fn at_zero_elevator_the_zero_sideslip_factors_divide_exactly() {
    let s = symbols();
    let papers_case = [
        (s.param(Param::Z0), model::algebra::Q::ZERO),
        (s.param(Param::AlphaT), model::algebra::Q::ZERO),
    ];
    for (i, num) in parametric().zs_trim.iter().enumerate() {
        // With a trim lift or an inclined principal axis the origin is no trim: the numerators
        // are not multiples of delta_e, and the certified route takes its general path.
        assert!(
            num.div_var_pow(s.delta_e, 1).is_none(),
            "numerator {i} with the trim terms"
        );
        assert!(
            num.subs_values(&papers_case)
                .div_var_pow(s.delta_e, 1)
                .is_some(),
            "zero-sideslip trim numerator {i} is a multiple of delta_e"
        );
    }
    let mut rng = Rng::new(98);
    let mut sample = vec![Aircraft::a(), Aircraft::b()];
    sample.extend((0..size(6, 40)).map(|i| random_aircraft(&mut rng, i)));
    let zero = [(s.beta0, model::algebra::Q::ZERO)];
    for (i, ac) in sample.iter().enumerate() {
        let cp = CriterionPolys::new(parametric(), ac, 0.0);
        let values = specialisation(ac, 0.0);
        let c = parametric_characteristic()
            .clone()
            .map(|ck| ck.subs_values(&values).subs_values(&zero));
        let cleared = cleared_coefficients(&c, &[s.alpha0, s.q0, s.r0], &cp.zs_trim, &cp.zs_det);
        let den = univariate(&cp.zs_det, s.p0);
        let divides = |p: &model::roots::UPoly, k: usize| {
            (0..k).try_fold(p.clone(), |rest, _| {
                let (q, r) = rest.div_rem(&den);
                r.is_zero().then_some(q)
            })
        };
        for (k, ck) in cleared.iter().enumerate() {
            let ck = univariate(ck, s.p0);
            assert!(divides(&ck, k + 1).is_some(), "aircraft {i}: C{}", k + 1);
        }
        for (name, p) in [("zs_jump", &cp.zs_jump), ("zs_d_det", &cp.zs_d_det)] {
            let p = univariate(p, s.p0);
            assert!(divides(&p, 2).is_some(), "aircraft {i}: {name}");
        }
    }
}

/// At `delta_e = 0` (an envelope's level flight) the certified route answers without the
/// exact path for aircraft A, and for random aircraft it gives the exact path's full answer
/// wherever it certifies.
#[test]
fn certified_full_analysis_at_zero_elevator_agrees_with_the_exact_path() {
    let (_, route) = analyze_routed_with(&Aircraft::a(), 0.0, true).unwrap();
    assert!(matches!(route, Route::Certified(_)), "{route:?}");
    let mut rng = Rng::new(1011);
    let (mut certified, mut fallbacks) = (0usize, Vec::new());
    let n = size(100, 1000);
    for i in 0..n {
        let ac = without_aileron_yaw(random_aircraft(&mut rng, i));
        let (Ok(e), Ok((f, route))) = (
            analyze_with(&ac, 0.0, true),
            analyze_routed_with(&ac, 0.0, true),
        ) else {
            continue;
        };
        let w = match route {
            Route::Certified(w) => {
                certified += 1;
                w
            }
            Route::Exact(why) => {
                fallbacks.push(why);
                0.0
            }
        };
        let same = same_analysis(&e, &f, w).and_then(|()| same_departures(&e, &f, w));
        if let Err(why) = same {
            panic!("aircraft {i} ({ac:?}): {why}");
        }
    }
    println!("{n} aircraft at delta_e = 0: {certified} certified, fallbacks {fallbacks:?}");
    assert!(certified > 0, "the comparison must not be empty");
}
