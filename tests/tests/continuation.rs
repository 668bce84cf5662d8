//! The continuation (`model::continuation`) against the paper's continuation results
//! (Figs 1, 2 and 9 of AIAA 2006-6267, computed there with AUTO2000; sections II.B and V.B) and
//! against the analytical criterion of section IV (`model::analysis`): every fold must be a root
//! of the jump polynomial, every zero-sideslip branch point a departure root, for the paper's
//! aircraft and for aircraft that are neither A nor B. Points, stability and Hopf frequencies
//! are re-checked with the independent oracle of `paper_tests` (hand-written model,
//! finite-difference Jacobian, LU trims).

use model::aircraft::{f64_to_rational, Aircraft, Param};
use model::analysis::{analyze, Analysis};
use model::continuation::{
    continue_equilibria, ContinuationError, ContinuationParam, Diagram, Settings, SpecialKind,
    SpecialPoint,
};
use model::plot::Shape;
use paper_tests::{fd_jacobian, pss_rhs, reference, zero_sideslip_trim, Lcg, Params};
use std::path::Path;
use std::sync::OnceLock;

/// The paper's elevator setting, 2 deg (as in `Settings::default`).
fn de() -> f64 {
    2f64.to_radians()
}

fn diagram(ac: &Aircraft, settings: &Settings) -> Diagram {
    continue_equilibria(ac, settings, &mut |_| {}).expect("continuation runs")
}

fn b_default() -> &'static Diagram {
    static D: OnceLock<Diagram> = OnceLock::new();
    D.get_or_init(|| diagram(&Aircraft::b(), &Settings::default()))
}

fn a_default() -> &'static Diagram {
    static D: OnceLock<Diagram> = OnceLock::new();
    D.get_or_init(|| diagram(&Aircraft::a(), &Settings::default()))
}

/// Aircraft A in delta_e over [-0.5, 0.5] rad with delta_a = 0: the symmetric case.
fn a_delta_e() -> &'static Diagram {
    static D: OnceLock<Diagram> = OnceLock::new();
    D.get_or_init(|| diagram(&Aircraft::a(), &delta_e_settings(0.0)))
}

fn delta_e_settings(delta_a: f64) -> Settings {
    Settings {
        param: ContinuationParam::DeltaE,
        min: -0.5,
        max: 0.5,
        delta_a,
        ..Settings::default()
    }
}

fn a_zero_sideslip() -> &'static Diagram {
    static D: OnceLock<Diagram> = OnceLock::new();
    D.get_or_init(|| {
        let s = Settings {
            zero_sideslip: true,
            ..Settings::default()
        };
        diagram(&Aircraft::a(), &s)
    })
}

fn folds(d: &Diagram) -> Vec<&SpecialPoint> {
    d.special(SpecialKind::Fold).collect()
}

fn state(p: &SpecialPoint) -> [f64; 5] {
    [p.alpha, p.beta, p.p, p.q, p.r]
}

/// The controls at a point of a diagram in delta_a with fixed delta_e, delta_r.
fn controls(s: &Settings, mu: f64) -> [f64; 3] {
    match s.param {
        ContinuationParam::DeltaA => [mu, s.delta_e, s.delta_r],
        ContinuationParam::DeltaE => [s.delta_a, mu, s.delta_r],
        ContinuationParam::DeltaR => [s.delta_a, s.delta_e, mu],
    }
}

/// Every fold's |P0| equals a positive jump root of `analyze` to 1e-6 (the PSS equations are
/// symmetric under p, beta, r, delta_a -> -p, -beta, -r, -delta_a with delta_r = 0, so folds at
/// negative roll rates mirror the roots), and every jump root whose trim lies in the range is
/// found at both signs of P0.
fn assert_folds_are_the_jump_roots(ac: &Aircraft, d: &Diagram, a: &Analysis, s: &Settings) {
    let folds = folds(d);
    for f in &folds {
        let nearest = a
            .jump
            .iter()
            .map(|j| (f.p.abs() - j.p0).abs())
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest < 1e-6,
            "{}: fold at P0 = {} is no jump root ({:?})",
            ac.name,
            f.p,
            a.jump
        );
    }
    let margin = 1e-3;
    for j in &a.jump {
        let states = [j.alpha, j.beta, j.p0, j.q, j.r];
        let inside = j.delta_a_rad.abs() < s.max.min(-s.min) - margin
            && states.iter().all(|v| v.abs() < s.max_state - margin);
        if !inside {
            continue;
        }
        for sign in [1.0, -1.0] {
            let hit = folds.iter().find(|f| (f.p - sign * j.p0).abs() < 1e-6);
            let f = hit.unwrap_or_else(|| {
                panic!(
                    "{}: jump root {} (sign {sign}) not found as a fold",
                    ac.name, j.p0
                )
            });
            assert!(
                (f.param - sign * j.delta_a_rad).abs() < 1e-6,
                "{f:?} vs {j:?}"
            );
        }
    }
}

/// Every point is an equilibrium (oracle residual), and its stability flag agrees with the
/// oracle's eigenvalues wherever they are not marginal.
fn assert_points_are_equilibria_with_right_stability(k: &Params, d: &Diagram, s: &Settings) {
    for (bi, b) in d.branches.iter().enumerate() {
        assert!(
            b.points.len() >= 2,
            "branch {bi} has {} points",
            b.points.len()
        );
        // Every third point and the ends (debug builds are slow).
        let n = b.points.len();
        for (i, pt) in b
            .points
            .iter()
            .enumerate()
            .filter(|(i, _)| i % 3 == 0 || *i == n - 1)
        {
            let x = [pt.alpha, pt.beta, pt.p, pt.q, pt.r];
            let u = controls(s, pt.param);
            let scale = 1.0 + x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let res = pss_rhs(k, &x, &u);
            assert!(
                res.iter().all(|v| v.abs() < 1e-8 * scale * scale * 100.0),
                "branch {bi} point {i}: residual {res:?}"
            );
            let eig = fd_jacobian(k, &x, &u).complex_eigenvalues();
            let max_re = eig.iter().map(|z| z.re).fold(f64::MIN, f64::max);
            if max_re.abs() > 1e-5 * scale {
                assert_eq!(
                    pt.stable,
                    max_re < 0.0,
                    "branch {bi} point {i}: eigenvalues {eig:?}"
                );
            }
        }
    }
}

/// Each branch ends on the parameter range, on the state bound, or closes on itself.
fn assert_branches_end_on_a_bound(d: &Diagram, s: &Settings) {
    for (bi, b) in d.branches.iter().enumerate() {
        let (first, last) = (&b.points[0], &b.points[b.points.len() - 1]);
        for end in [first, last] {
            let on_range = (end.param - s.min).abs() < 1e-9 || (end.param - s.max).abs() < 1e-9;
            let big = [end.alpha, end.beta, end.p, end.q, end.r]
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            let on_state = (big - s.max_state).abs() < 1e-9;
            let dist = ((first.param - last.param).powi(2)
                + (first.p - last.p).powi(2)
                + (first.alpha - last.alpha).powi(2)
                + (first.beta - last.beta).powi(2))
            .sqrt();
            let closed = dist < 2.0 * s.ds_max;
            assert!(
                on_range || on_state || closed,
                "branch {bi} ends at {end:?}, not on a bound"
            );
        }
    }
}

#[test]
fn fig_1_folds_aircraft_a_near_minus_4_and_plus_8_deg() {
    let ac = Aircraft::a();
    let s = Settings::default();
    let d = a_default();
    let a = analyze(&ac, de()).unwrap();
    assert_folds_are_the_jump_roots(&ac, d, &a, &s);
    // One primary branch through the level trim, four folds: P0 = +-1.706288, +-3.033180.
    assert_eq!(
        d.branches.len(),
        1,
        "A's equilibria form one branch (Fig. 1)"
    );
    let f = folds(d);
    assert_eq!(f.len(), 4, "{f:?}");
    let at = |p0: f64| f.iter().find(|x| (x.p - p0).abs() < 1e-6).copied().unwrap();
    assert!(
        (at(reference::A_JUMP_P0[0]).param.to_degrees() - reference::A_FOLD_DELTA_A_DEG).abs()
            < 1e-3,
        "Fig. 1: about -4 deg"
    );
    assert!(
        (at(reference::A_JUMP_P0[1]).param.to_degrees() - 7.80).abs() < 1e-2,
        "Fig. 1: about +8 deg"
    );
    // The level trim is stable; the middle part between the folds is not (a saddle).
    let b = &d.branches[0];
    let level = b
        .points
        .iter()
        .min_by(|x, y| x.p.abs().total_cmp(&y.p.abs()))
        .unwrap();
    assert!(level.stable && level.p.abs() < 0.1);
    let mid = b.points.iter().find(|x| x.p > 2.0 && x.p < 2.8).unwrap();
    assert!(!mid.stable, "unstable between the folds: {mid:?}");
    let beyond = b.points.iter().find(|x| x.p > 3.2 && x.p < 6.0).unwrap();
    assert!(
        beyond.stable,
        "A regains stability after the second fold: {beyond:?}"
    );
    assert_points_are_equilibria_with_right_stability(&ac.values_f64(), d, &s);
    assert_branches_end_on_a_bound(d, &s);
}

#[test]
fn fig_2_folds_aircraft_b_are_the_jump_roots_first_near_minus_12_deg() {
    let ac = Aircraft::b();
    let s = Settings::default();
    let d = b_default();
    let a = analyze(&ac, de()).unwrap();
    assert_folds_are_the_jump_roots(&ac, d, &a, &s);
    // All four roots have delta_a within +-0.8 rad: eight folds (both signs of P0).
    assert!(a.jump.iter().all(|j| j.delta_a_rad.abs() < 0.8));
    assert_eq!(folds(d).len(), 8);
    // The primary branch (through the level trim) loses stability at the fold a, about -12 deg.
    let fa = folds(d)
        .into_iter()
        .find(|f| (f.p - reference::B_JUMP_P0[0]).abs() < 1e-6)
        .unwrap();
    assert!(
        (fa.param.to_degrees() - reference::B_FOLD_DELTA_A_DEG).abs() < 1e-3,
        "{fa:?}"
    );
}

#[test]
fn fig_2_all_branches_of_b_found_without_hand_picked_starts_ending_at_divergence() {
    let ac = Aircraft::b();
    let s = Settings::default();
    let d = b_default();
    // Table 1: divergence at 2.986460 and 4.783697. The equilibria form pieces separated by
    // them: |P0| < 2.986, between the two (each sign), and beyond 4.784 (each sign).
    let div = analyze(&ac, de()).unwrap().divergence_roll_rates;
    assert_eq!(d.branches.len(), 5, "{} branches", d.branches.len());
    for b in &d.branches {
        let (lo, hi) = b
            .points
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.p), h.max(p.p)));
        let crosses = div
            .iter()
            .any(|r| (lo < *r && *r < hi) || (lo < -r && -r < hi));
        assert!(
            !crosses,
            "a branch crosses a divergence roll rate: [{lo}, {hi}]"
        );
    }
    let primary = d
        .branches
        .iter()
        .filter(|b| b.points.windows(2).any(|w| w[0].p * w[1].p <= 0.0));
    assert_eq!(primary.count(), 1, "one branch through P0 = 0");
    // Branches running into a divergence roll rate end on the state bound, close to it.
    let mut ends_at_divergence = 0;
    for b in &d.branches {
        for end in [&b.points[0], &b.points[b.points.len() - 1]] {
            let big = [end.alpha, end.beta, end.q, end.r]
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            if (big - s.max_state).abs() < 1e-9 {
                let gap = div
                    .iter()
                    .map(|r| (end.p.abs() - r).abs())
                    .fold(f64::MAX, f64::min);
                assert!(
                    gap < 0.05,
                    "state bound reached away from divergence: {end:?}"
                );
                ends_at_divergence += 1;
            }
        }
    }
    assert!(ends_at_divergence >= 4, "{ends_at_divergence}");
    assert_points_are_equilibria_with_right_stability(&ac.values_f64(), d, &s);
    assert_branches_end_on_a_bound(d, &s);
}

#[test]
fn fig_2_hopf_points_of_aircraft_b_with_their_frequencies() {
    let k = Aircraft::b().values_f64();
    let d = b_default();
    let hopf: Vec<&SpecialPoint> = d.special(SpecialKind::Hopf).collect();
    assert!(
        !hopf.is_empty(),
        "Fig. 2 shows Hopf points (filled squares)"
    );
    for h in &hopf {
        let w = h.frequency.expect("a Hopf point has a frequency");
        let x = state(h);
        let u = [h.param, de(), 0.0];
        let res = pss_rhs(&k, &x, &u);
        assert!(res.iter().all(|v| v.abs() < 1e-8), "{res:?}");
        // The oracle's eigenvalues: a pair +-i w on the imaginary axis, all others off it.
        let eig = fd_jacobian(&k, &x, &u).complex_eigenvalues();
        let pair = eig
            .iter()
            .find(|z| (z.im - w).abs() < 1e-5)
            .expect("the critical pair");
        assert!(pair.re.abs() < 1e-5, "{eig:?}");
        assert!(w > 0.0);
    }
    // Symmetric pairs: (P0, delta_a) and (-P0, -delta_a).
    for h in &hopf {
        assert!(hopf
            .iter()
            .any(|g| (g.p + h.p).abs() < 1e-7 && (g.param + h.param).abs() < 1e-7));
    }
}

/// The closed-form Hopf points as the report's Figs 1-4 mark them: the figure data
/// of `model report`, drawn and written as the CSV beside the figure, holds them as their own
/// series, apart from the continuation's; each row is `(delta_a deg, p rad/s)`.
fn closed_form_hopf_rows(ac: &Aircraft, d: &Diagram) -> Vec<(f64, f64)> {
    let a = analyze(ac, de()).unwrap();
    let data = model::present::report::bifurcation_data(d, &a, &ac.name);
    // Figs 3, 4 mark them in each state panel too: those in the figures' aileron range, each
    // with its mirror image.
    let (lo, hi) = data.delta_a_range_deg.unwrap();
    let inside = a
        .hopf
        .iter()
        .filter(|h| (lo..=hi).contains(&h.point.delta_a_deg))
        .count();
    let states = model::plot::figures::trim_states_figure(&data).unwrap();
    for panel in &states.panels {
        let marked = panel.markers.iter().filter(|m| m.shape == Shape::Diamond);
        assert_eq!(marked.count(), 2 * inside, "{}: {}", ac.name, panel.title);
    }
    let csv = model::plot::figures::bifurcation_figure(&data)
        .unwrap()
        .to_csv();
    csv.lines()
        .filter(|row| row.contains(",marker,closed-form Hopf point"))
        .map(|row| {
            let f: Vec<&str> = row.rsplitn(3, ',').collect();
            (f[1].parse().unwrap(), f[0].parse().unwrap())
        })
        .collect()
}

#[test]
fn report_figures_mark_the_closed_form_hopf_points_of_b_and_none_of_a() {
    let b = closed_form_hopf_rows(&Aircraft::b(), b_default());
    // AUTO-07p's Hopf points and their mirror images (-P0 at -delta_a); B's third, at +75.7 deg
    // of aileron, lies beyond the figure's +-0.8 rad.
    assert_eq!(b.len(), 2 * reference::B_HOPF.len(), "{b:?}");
    for (p0, da_deg, _) in reference::B_HOPF {
        for sign in [1.0, -1.0] {
            assert!(
                b.iter()
                    .any(|(da, p)| (p - sign * p0).abs() < 1e-6
                        && (da - sign * da_deg).abs() < 0.005),
                "{}: {b:?}",
                sign * p0
            );
        }
    }
    let a = closed_form_hopf_rows(&Aircraft::a(), a_default());
    assert!(a.is_empty(), "{a:?}");
}

#[test]
fn fig_9_zero_sideslip_departure_of_a_is_a_branch_point_at_the_criterion_root() {
    let ac = Aircraft::a();
    let d = a_zero_sideslip();
    let a = analyze(&ac, de()).unwrap();
    let dep = &a.zero_sideslip.departure[0];
    assert!((dep.p0 - reference::A_ZERO_SIDESLIP_P0[0]).abs() < 1e-6);
    let bps: Vec<&SpecialPoint> = d.special(SpecialKind::Branch).collect();
    let bp = bps
        .iter()
        .find(|b| b.p > 0.0)
        .expect("the transcritical point of Fig. 9");
    assert!(
        (bp.p - dep.p0).abs() < 1e-6,
        "branch point at P0 = {}, criterion {}",
        bp.p,
        dep.p0
    );
    assert!(
        (bp.param - dep.delta_a_rad).abs() < 1e-6,
        "{} vs {}",
        bp.param,
        dep.delta_a_rad
    );
    assert!(
        (bp.param - -0.15).abs() < 0.01,
        "Fig. 9: about delta_a = -0.15 rad"
    );
    assert!(bp.beta.abs() < 1e-9, "on the zero-sideslip branch");
    // Its mirror image, and nothing else in range (the second root needs |delta_a| > 0.8).
    assert_eq!(bps.len(), 2, "{bps:?}");
    // The zero-sideslip branch is branch 0: beta = 0 all along, stable up to the departure and
    // unstable beyond it (exchange of stability with the crossing branch, found by switching).
    assert!(d.branches.len() >= 2, "the crossing branch is traced too");
    let zs = &d.branches[0];
    assert!(zs.points.iter().all(|p| p.beta.abs() < 1e-9));
    for p in &zs.points {
        if (p.p.abs() - dep.p0).abs() > 1e-3 {
            assert_eq!(p.stable, p.p.abs() < dep.p0, "{p:?}");
        }
    }
    let crossing = &d.branches[bp.branch.max(1)];
    assert!(crossing.points.iter().any(|p| p.beta.abs() > 1e-3));
}

#[test]
fn fig_9_eba_step_1_rudder_schedule_is_the_closed_form_zero_sideslip_trim() {
    let k = Aircraft::a().values_f64();
    let d = a_zero_sideslip();
    assert!(d.rudder_schedule.len() > 10);
    for s in &d.rudder_schedule {
        let (_, da, dr) = zero_sideslip_trim(&k, s.p, de()).unwrap();
        assert!(
            (s.delta_a - da).abs() < 1e-9 * (1.0 + da.abs()),
            "{s:?} vs {da}"
        );
        assert!(
            (s.delta_r - dr).abs() < 1e-9 * (1.0 + dr.abs()),
            "{s:?} vs {dr}"
        );
    }
    // It spans the whole aileron range (the schedule has no turning point for A).
    let (lo, hi) = d
        .rudder_schedule
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), s| {
            (l.min(s.delta_a), h.max(s.delta_a))
        });
    assert!(
        (lo - -0.8).abs() < 1e-9 && (hi - 0.8).abs() < 1e-9,
        "[{lo}, {hi}]"
    );
    // Step 2's points follow the schedule: the zero-sideslip branch has the schedule's P0.
    let zs = &d.branches[0];
    for p in zs.points.iter().step_by(7) {
        let (x, da, _) = zero_sideslip_trim(&k, p.p, de()).unwrap();
        assert!((p.param - da).abs() < 1e-8 * (1.0 + da.abs()));
        assert!((p.alpha - x[0]).abs() < 1e-8 * (1.0 + x[0].abs()));
    }
}

#[test]
fn zero_sideslip_departure_of_b_and_c_at_the_criterion_root() {
    for ac in [Aircraft::b(), aircraft_c()] {
        // States bounded at 5: the departures are at small states; shorter crossing branches.
        let s = Settings {
            zero_sideslip: true,
            max_state: 5.0,
            ..Settings::default()
        };
        let d = diagram(&ac, &s);
        let a = analyze(&ac, de()).unwrap();
        let bps: Vec<&SpecialPoint> = d.special(SpecialKind::Branch).collect();
        for bp in &bps {
            let hit = a
                .zero_sideslip
                .departure
                .iter()
                .any(|r| (bp.p.abs() - r.p0).abs() < 1e-6);
            assert!(hit, "{}: branch point {bp:?} is no departure root", ac.name);
        }
        let first = &a.zero_sideslip.departure[0];
        assert!(first.delta_a_rad.abs() < 0.8);
        assert!(
            bps.iter().any(|b| (b.p - first.p0).abs() < 1e-6),
            "{}: {bps:?}",
            ac.name
        );
    }
}

fn aircraft_c() -> Aircraft {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../aircraft/c.toml");
    model::aircraft::load(&path).expect("aircraft/c.toml")
}

/// A random, plausible aircraft (as in the derivation tests; nothing tuned to A or B).
fn random_aircraft(rng: &mut Lcg, i: usize) -> Aircraft {
    let k = paper_tests::random_params(rng);
    let values = k.iter().map(|v| f64_to_rational(*v).unwrap()).collect();
    Aircraft::new(format!("random {i}"), values, 150.0)
}

#[test]
fn folds_equal_the_jump_roots_for_non_paper_aircraft() {
    let s = Settings::default();
    let mut rng = Lcg(2024);
    let mut aircraft = vec![aircraft_c()];
    aircraft.extend((0..3).map(|i| random_aircraft(&mut rng, i)));
    let mut folds_seen = 0;
    for ac in &aircraft {
        let d = diagram(ac, &s);
        let a = analyze(ac, de()).unwrap();
        assert_folds_are_the_jump_roots(ac, &d, &a, &s);
        assert_branches_end_on_a_bound(&d, &s);
        folds_seen += folds(&d).len();
    }
    assert!(
        folds_seen >= 4,
        "the random aircraft exercise the check: {folds_seen} folds"
    );
}

#[test]
fn folds_in_delta_e_and_delta_r_have_a_zero_eigenvalue_and_hopf_points_an_imaginary_pair() {
    // No criterion in these parameters; the oracle's Jacobian is singular at each fold.
    let ac = Aircraft::a();
    let k = ac.values_f64();
    let mut seen = [0usize; 3];
    for (param, da) in [
        (ContinuationParam::DeltaE, 0.0),
        (ContinuationParam::DeltaE, -0.05),
        (ContinuationParam::DeltaR, -0.05),
    ] {
        let s = Settings {
            param,
            min: -0.5,
            max: 0.5,
            delta_a: da,
            ..Settings::default()
        };
        let computed;
        let d = if param == ContinuationParam::DeltaE && da == 0.0 {
            a_delta_e()
        } else {
            computed = diagram(&ac, &s);
            &computed
        };
        assert_eq!(d.parameter, param.name());
        assert_branches_end_on_a_bound(d, &s);
        for sp in &d.special_points {
            let u = controls(&s, sp.param);
            let eig = fd_jacobian(&k, &state(sp), &u).complex_eigenvalues();
            let res = pss_rhs(&k, &state(sp), &u);
            assert!(res.iter().all(|v| v.abs() < 1e-8), "{sp:?}: {res:?}");
            match sp.kind {
                SpecialKind::Fold | SpecialKind::Branch => {
                    let smallest = eig.iter().map(|z| z.norm()).fold(f64::MAX, f64::min);
                    assert!(smallest < 1e-5, "{sp:?}: {eig:?}");
                }
                SpecialKind::Hopf => {
                    let w = sp.frequency.unwrap();
                    assert!(eig
                        .iter()
                        .any(|z| (z.im - w).abs() < 1e-5 && z.re.abs() < 1e-5));
                }
            }
            seen[sp.kind as usize] += 1;
        }
    }
    // With delta_a = 0 the symmetric branch p = 0 exists in delta_e, and the rolling branches
    // leave it at a pitchfork: a branch point.
    assert!(
        seen[0] > 0 && seen[1] > 0 && seen[2] > 0,
        "folds, Hopf, branch points: {seen:?}"
    );
}

#[test]
fn symmetric_branch_in_delta_e_is_found_once_with_its_pitchfork() {
    let d = a_delta_e();
    let symmetric: Vec<_> = d
        .branches
        .iter()
        .filter(|b| b.points.iter().all(|p| p.p.abs() < 1e-9))
        .collect();
    assert_eq!(symmetric.len(), 1, "the p = 0 branch, once");
    let bp = d.special(SpecialKind::Branch).next().expect("a pitchfork");
    assert!(bp.p.abs() < 1e-6);
    // No saddle-node reported at the pitchfork itself.
    assert!(d
        .special(SpecialKind::Fold)
        .all(|f| (f.param - bp.param).abs() > 1e-4 || f.p.abs() > 1e-3));
}

/// An aircraft A with aileron yaw `n_delta_a` (1/s^2).
fn a_with_aileron_yaw(n_delta_a: f64) -> Aircraft {
    let mut values: Vec<_> = Param::ALL
        .iter()
        .map(|p| Aircraft::a().exact(*p).clone())
        .collect();
    values[Param::NDeltaA.index()] = f64_to_rational(n_delta_a).unwrap();
    Aircraft::new(format!("A with n_delta_a = {n_delta_a}"), values, 150.0)
}

#[test]
fn folds_of_aileron_yaw_aircraft_are_the_closed_form_jump_roots_to_1e_8() {
    // With n_delta_a != 0 the closed form eliminates delta_a by a resultant; the
    // continuation knows nothing of it and must find the same folds, state and aileron.
    let s = Settings::default();
    let mut checked = 0;
    for nda in [8.0, -8.0, -3.0] {
        let ac = a_with_aileron_yaw(nda);
        let a = analyze(&ac, de()).unwrap();
        let d = diagram(&ac, &s);
        let k = ac.values_f64();
        assert!(!folds(&d).is_empty(), "{}", ac.name);
        for f in folds(&d) {
            let eig = fd_jacobian(&k, &state(f), &[f.param, de(), 0.0]).complex_eigenvalues();
            assert!(eig.iter().any(|z| z.norm() < 1e-5), "{f:?}: {eig:?}");
            let sign = f.p.signum();
            let j = a
                .jump
                .iter()
                .find(|j| (f.p.abs() - j.p0).abs() < 1e-8)
                .unwrap_or_else(|| panic!("{}: fold {f:?} is no jump root {:?}", ac.name, a.jump));
            assert!(
                (sign * j.delta_a_rad - f.param).abs() < 1e-8,
                "{f:?} vs {j:?}"
            );
            for (x, y) in [(sign * j.beta, f.beta), (j.alpha, f.alpha), (j.q, f.q)] {
                assert!((x - y).abs() < 1e-8 * (1.0 + x.abs()), "{f:?} vs {j:?}");
            }
            checked += 1;
        }
        assert_points_are_equilibria_with_right_stability(&k, &d, &s);
    }
    assert!(checked >= 8, "{checked} folds compared");
}

#[test]
fn json_has_the_parameter_as_key_and_csv_one_row_per_point() {
    let d = b_default();
    let v = serde_json::to_value(d).unwrap();
    assert_eq!(v["aircraft"], "Aircraft B");
    assert_eq!(v["parameter"], "delta_a");
    let p0 = &v["branches"][0]["points"][0];
    for key in ["delta_a", "alpha", "beta", "p", "q", "r", "stable"] {
        assert!(p0.get(key).is_some(), "point lacks {key}: {p0}");
    }
    let sp = v["special_points"].as_array().unwrap();
    assert_eq!(sp.len(), d.special_points.len());
    assert!(sp
        .iter()
        .any(|s| s["kind"] == "fold" && s.get("delta_a").is_some()));
    assert!(sp
        .iter()
        .any(|s| s["kind"] == "hopf" && s["frequency"].as_f64().unwrap() > 0.0));
    assert!(v.get("rudder_schedule").is_none());
    let csv = d.to_csv();
    let n: usize = d.branches.iter().map(|b| b.points.len()).sum();
    assert_eq!(csv.lines().count(), n + 1);
    assert_eq!(
        csv.lines().next().unwrap(),
        "branch,delta_a_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable"
    );
    // delta_e diagrams use their own key.
    let s = Settings {
        param: ContinuationParam::DeltaE,
        min: -0.2,
        max: 0.2,
        ..Settings::default()
    };
    let v = serde_json::to_value(diagram(&Aircraft::a(), &s)).unwrap();
    assert!(v["branches"][0]["points"][0].get("delta_e").is_some());
    let zs = serde_json::to_value(a_zero_sideslip()).unwrap();
    assert!(zs["rudder_schedule"][0].get("delta_r").is_some());
}

#[test]
fn output_is_deterministic_and_progress_runs_from_0_to_1() {
    let mut last = -1.0;
    let mut monotone = true;
    let again = continue_equilibria(&Aircraft::a(), &Settings::default(), &mut |f| {
        monotone &= f >= last && (0.0..=1.0).contains(&f);
        last = f;
    })
    .unwrap();
    assert_eq!(&again, a_default());
    assert!(monotone && last == 1.0, "progress runs from 0 to 1");
}

#[test]
fn bad_settings_are_errors_not_panics() {
    let ac = Aircraft::a();
    let bad = [
        Settings {
            min: 0.5,
            max: -0.5,
            ..Settings::default()
        },
        Settings {
            min: f64::NAN,
            ..Settings::default()
        },
        Settings {
            max_state: 0.0,
            ..Settings::default()
        },
        Settings {
            seed_spacing: 0.0,
            ..Settings::default()
        },
        Settings {
            ds_min: 1.0,
            ..Settings::default()
        },
        Settings {
            delta_e: f64::INFINITY,
            ..Settings::default()
        },
        Settings {
            max_newton: 0,
            ..Settings::default()
        },
    ];
    for s in &bad {
        assert!(
            matches!(
                continue_equilibria(&ac, s, &mut |_| {}),
                Err(ContinuationError::Settings(_))
            ),
            "{s:?}"
        );
    }
    let zs_e = Settings {
        zero_sideslip: true,
        param: ContinuationParam::DeltaE,
        ..Settings::default()
    };
    assert!(matches!(
        continue_equilibria(&ac, &zs_e, &mut |_| {}),
        Err(ContinuationError::ZeroSideslip(_))
    ));
    // A range without any equilibrium is an empty diagram, not an error.
    let s = Settings {
        param: ContinuationParam::DeltaE,
        min: 5.0,
        max: 5.1,
        max_state: 1.0,
        ..Settings::default()
    };
    let d = diagram(&ac, &s);
    assert!(d.branches.is_empty() && d.special_points.is_empty());
    assert!(
        "delta_r".parse::<ContinuationParam>().is_ok() && "x".parse::<ContinuationParam>().is_err()
    );
}
