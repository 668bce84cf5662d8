//! The certified walk along the primary branch past a turn in P0 (the walk in delta_a of
//! `model::certified`), against the exact path, at the JSBSim jets whose 1-g branches turn:
//! the F-16 (just before a divergence roll rate) and the T-38. Skipped with a message when the
//! JSBSim models are not installed.

mod support;

use model::aircraft::{self, Aircraft};
use model::analysis::fast::{analyze_first_departure, Route, MAX_WIDTH};
use model::analysis::{analyze, Analysis};
use model::certified::{first_root_on_branch, BranchEnd, Det, TrimPolys, Values};
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};

/// `model` imported at `altitude_m`, `mach`, trimmed at 1 g.
fn jet(model: &str, altitude_m: f64, mach: f64) -> Aircraft {
    let request = Request {
        model: model.to_string(),
        root: None,
        altitude_m,
        speed: Speed::Mach(mach),
        alpha: Alpha::Trim(1.0),
        settings: Vec::new(),
    };
    aircraft::parse(&import(&request).unwrap(), model).unwrap()
}

/// The roll rate where the branch turns in P0 (the trim condition's discriminant in delta_a
/// changes sign: its two trims merge) and the trims' aileron there, found by bisection in f64
/// on the midpoint polynomials between `lo` (two trims) and `hi` (none): a computation of the
/// turn apart from the walk.
fn turn(v: &Values, mut lo: f64, mut hi: f64) -> (f64, f64) {
    let t = TrimPolys::new(v).unwrap();
    let c = |p: f64| -> Vec<f64> {
        let at =
            |k: &model::certified::dense::IPoly| k.0.iter().rev().fold(0.0, |a, x| a * p + x.mid());
        t.trim_condition.0.iter().map(at).collect()
    };
    let disc = |p: f64| {
        let k = c(p);
        k[1] * k[1] - 4.0 * k[0] * k[2]
    };
    assert!(disc(lo) > 0.0 && disc(hi) < 0.0, "no turn in [{lo}, {hi}]");
    for _ in 0..60 {
        let m = lo + (hi - lo) / 2.0;
        if disc(m) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    let k = c(lo);
    (lo, -k[1] / (2.0 * k[2]))
}

/// The critical jump, its note and the first departure of `a` and of the exact path `e` are
/// the same (roll rates within their certified brackets of relative width `w`).
fn same(a: &Analysis, e: &Analysis, w: f64) -> Result<(), String> {
    let jump = |a: &Analysis| a.critical.as_ref().map(|c| (c.p0, c.delta_a_rad));
    let first = |a: &Analysis| {
        a.first_departure
            .as_ref()
            .map(|d| (d.kind, d.p0, d.delta_a_rad))
    };
    let close = |x: f64, y: f64| support::close_roots(x, y, w.max(MAX_WIDTH));
    match (jump(a), jump(e)) {
        (Some((p, d)), Some((q, f))) if close(p, q) && (d - f).abs() <= 1e-6 => {}
        (None, None) => {}
        (x, y) => return Err(format!("critical jump {x:?} vs {y:?}")),
    }
    if a.critical_note != e.critical_note {
        return Err(format!(
            "note {:?} vs {:?}",
            a.critical_note, e.critical_note
        ));
    }
    match (first(a), first(e)) {
        (Some((k, p, d)), Some((l, q, f))) if k == l && close(p, q) && (d - f).abs() <= 1e-6 => {}
        (None, None) => {}
        (x, y) => return Err(format!("first departure {x:?} vs {y:?}")),
    }
    Ok(())
}

/// Where the 1-g maps of the F-16 and the T-38 (`envelope --altitude-m 0:14500:500 --mach
/// 0.3:0.95:0.05`) fell back to the exact path, and the F-16 at 8,600 m, Mach 0.87 (its
/// critical jump after a turn of the f64 walk), the route of the envelope certifies the exact
/// path's critical jump, note and first departure: branches that turn in P0 and reach 90 deg of
/// aileron (F-16, 1,500 m, Mach 0.4), that meet a Hopf point past the turn (12,500 m, Mach
/// 0.75), and the T-38's, whose first Hopf root lies past the critical jump (7,500 m, Mach
/// 0.45; 14,500 m, Mach 0.9) or past 90 deg of aileron (11,500 m, Mach 0.6).
#[test]
fn branches_that_turn_or_end_before_a_hopf_root_are_certified_with_the_exact_answer() {
    if !support::jsbsim_installed() {
        return;
    }
    for (model, altitude_m, mach) in [
        ("f16", 1500.0, 0.4),
        ("f16", 12500.0, 0.75),
        ("f16", 8600.0, 0.87),
        ("T38", 7500.0, 0.45),
        ("T38", 11500.0, 0.6),
        ("T38", 14500.0, 0.9),
    ] {
        let ac = jet(model, altitude_m, mach);
        let exact = analyze(&ac, 0.0).unwrap();
        let (a, route) = analyze_first_departure(&ac, 0.0).unwrap();
        let Route::Certified(w) = route else {
            panic!("{model} at {altitude_m} m, Mach {mach}: {route:?}");
        };
        if let Err(e) = same(&a, &exact, w) {
            panic!("{model} at {altitude_m} m, Mach {mach}: {e}");
        }
    }
}

/// The F-16 at 12,500 m, Mach 0.75, 1 g: its branch turns in P0 (at about 0.510 rad/s, -11 deg
/// of aileron, by the discriminant) and comes back to the exact path's first Hopf point
/// (0.5095 rad/s, -25.7 deg). The walk of the Hopf determinant brackets that root and the
/// branch's aileron there; the jump determinant keeps its sign on the branch up to 90 deg, as
/// the exact path finds no critical jump. At 1,500 m, Mach 0.4 (the turn at 1.2027 rad/s,
/// -20 deg, just before the divergence roll rate 1.2177 rad/s) neither has a root.
#[test]
fn the_walk_past_the_turn_brackets_the_exact_hopf_root() {
    if !support::jsbsim_installed() {
        return;
    }
    let ac = jet("f16", 12500.0, 0.75);
    let exact = analyze(&ac, 0.0).unwrap();
    let v = Values::of(&ac, 0.0, 0.0);
    let (p_turn, da_turn) = turn(&v, 0.4, 0.5134);
    let hopf = exact.first_departure.as_ref().unwrap();
    assert_eq!(hopf.kind, "hopf");
    assert!(
        hopf.p0 < p_turn && hopf.delta_a_rad < da_turn,
        "{hopf:?} vs {p_turn}, {da_turn}"
    );
    let end = BranchEnd::Before {
        p0: exact.divergence_roll_rates[0] - 1e-3,
        bound: ac.aileron_range(),
    };
    let (b, da) = first_root_on_branch(&v, Det::Hopf, end, MAX_WIDTH)
        .unwrap()
        .unwrap();
    let slack = 4.0 * f64::EPSILON * hopf.p0;
    assert!(
        b.lo - slack <= hopf.p0 && hopf.p0 <= b.hi + slack,
        "{b:?} vs {}",
        hopf.p0
    );
    assert!(b.hi - b.lo <= MAX_WIDTH * b.hi, "{b:?}");
    assert!(
        (da.mid() - hopf.delta_a_rad).abs() <= 1e-6,
        "{da:?} vs {}",
        hopf.delta_a_rad
    );
    assert!(exact.critical.is_none());
    assert!(matches!(
        first_root_on_branch(&v, Det::Jump, end, MAX_WIDTH),
        Ok(None)
    ));

    let ac = jet("f16", 1500.0, 0.4);
    let exact = analyze(&ac, 0.0).unwrap();
    let v = Values::of(&ac, 0.0, 0.0);
    let divergence = exact.divergence_roll_rates[0];
    let (p_turn, _) = turn(&v, 1.0, 1.2035);
    assert!(p_turn < divergence);
    assert!(exact.critical.is_none() && exact.first_departure.is_none());
    let end = BranchEnd::Before {
        p0: divergence - 1e-3,
        bound: ac.aileron_range(),
    };
    for det in [Det::Hopf, Det::Jump] {
        let root = first_root_on_branch(&v, det, end, MAX_WIDTH);
        assert!(matches!(root, Ok(None)), "{det:?}: {root:?}");
    }
}

/// Where the fine 1-g map of the F-16 (`envelope --altitude-m 0:14500:100 --mach
/// 0.3:0.95:0.01`) fell back to the exact path next to the first divergence roll rate, the
/// route certifies the exact path's answer with the jump determinant of the trim states
/// (`det J5`, not `det J5 det(A)^2`, whose cancellation kept its bracket from narrowing). At
/// 2,600 m, Mach 0.86 and 4,100 m, Mach 0.87 the critical jump lies within 0.006 rad/s of det
/// A's root; at 900 m, Mach 0.83 the branch turns a few millionths of a rad/s below it, without
/// a jump. The exact path's answers (`model analyze "jsbsim:f16 --altitude-m A --mach M" --exact
/// --json`): critical jump roll rate (rad/s) and aileron (rad), the first departure that jump.
#[test]
fn fine_map_points_next_to_a_divergence_roll_rate_are_certified_with_the_exact_answer() {
    if !support::jsbsim_installed() {
        return;
    }
    for (altitude_m, mach, jump) in [
        (900.0, 0.83, None),
        (2600.0, 0.86, Some((3.135257236463953, -0.499058561832254))),
        (4100.0, 0.87, Some((3.154000371287608, -0.5084207439946957))),
    ] {
        let ac = jet("f16", altitude_m, mach);
        let (a, route) = analyze_first_departure(&ac, 0.0).unwrap();
        let Route::Certified(w) = route else {
            panic!("{altitude_m} m, Mach {mach}: {route:?}");
        };
        let at = |a: &Analysis| a.critical.as_ref().map(|c| (c.p0, c.delta_a_rad));
        let first = |a: &Analysis| a.first_departure.as_ref().map(|d| (d.kind, d.p0));
        match (at(&a), jump) {
            (Some((p, d)), Some((q, f))) => {
                assert!(support::close_roots(p, q, w), "{altitude_m} m: {p} vs {q}");
                assert!((d - f).abs() <= 1e-6, "{altitude_m} m: {d} vs {f}");
                let (kind, p) = first(&a).expect("a first departure");
                assert!(kind == "jump" && support::close_roots(p, q, w));
            }
            (None, None) => assert_eq!(first(&a), None, "{altitude_m} m"),
            (x, y) => panic!("{altitude_m} m, Mach {mach}: {x:?} vs {y:?}"),
        }
        if let Err(e) = same(&a, &analyze(&ac, 0.0).unwrap(), w) {
            panic!("{altitude_m} m, Mach {mach}: {e}");
        }
    }
}

/// Where the fine 1-g maps of the F-16 and the T-38 (`envelope --altitude-m 0:14500:100 --mach
/// 0.3:0.95:0.01`) fell back for the critical jump's landings, the route certifies the exact
/// path's critical jump, first departure and landings. At the route's aileron, 1e-13 to 2e-11
/// rad off the fold's, the fold's double root splits into two roots a few millionths of a
/// rad/s either side of it (T-38 at 2,400 m, Mach 0.48, 4,400 m, Mach 0.61, 7,400 m, Mach 0.91;
/// F-16 at 11,500 m, Mach 0.94), which only the proof that the trim condition has no other
/// root around the fold leaves out; the landings themselves (a slope of 7e-3 at the T-38's
/// 2.2547 rad/s; the F-16's at 1,300 m, Mach 0.85, next to det A's root) need the trim
/// condition evaluated through the trim states to be bracketed within 1e-9.
///
/// The exact path's own aileron (1.3e-12 rad off the fold's at the T-38's 4,400 m, Mach 0.61,
/// and at 7,400 m, Mach 0.91) splits the fold too, and it lists one root of the pair as a
/// landing (`model analyze --exact`: "lands at P0 = 2.405892 rad/s (jump -0.000004 rad/s)"):
/// such a root, within 1e-5 rad/s of the fold, is the fold's own, and the route rightly has
/// none. The other landings agree to 1e-8 (relative): both routes take them at their own f64
/// aileron of the fold.
#[test]
fn landings_next_to_the_fold_are_certified_with_the_exact_answer() {
    if !support::jsbsim_installed() {
        return;
    }
    for (model, altitude_m, mach, split) in [
        ("f16", 1300.0, 0.85, 0),
        ("f16", 11500.0, 0.94, 0),
        ("T38", 2400.0, 0.48, 0),
        ("T38", 4400.0, 0.61, 1),
        ("T38", 7400.0, 0.91, 1),
    ] {
        let ac = jet(model, altitude_m, mach);
        let exact = analyze(&ac, 0.0).unwrap();
        let (a, route) = analyze_first_departure(&ac, 0.0).unwrap();
        let Route::Certified(w) = route else {
            panic!("{model} at {altitude_m} m, Mach {mach}: {route:?}");
        };
        if let Err(e) = same(&a, &exact, w) {
            panic!("{model} at {altitude_m} m, Mach {mach}: {e}");
        }
        let fold = exact.critical.as_ref().expect("a critical jump").p0;
        let lands = |a: &Analysis| -> Vec<f64> {
            let c = a.critical.as_ref().expect("a critical jump");
            c.lands_at.iter().flatten().map(|l| l.p0).collect()
        };
        let (x, all) = (lands(&a), lands(&exact));
        let (own, y): (Vec<f64>, Vec<f64>) = all.iter().partition(|p| (*p - fold).abs() < 1e-5);
        assert_eq!(own.len(), split, "{model} at {altitude_m} m: {all:?}");
        assert!(!y.is_empty(), "{model} at {altitude_m} m: no landing");
        assert_eq!(
            x.len(),
            y.len(),
            "{model} at {altitude_m} m: {x:?} vs {y:?}"
        );
        for (p, q) in x.iter().zip(&y) {
            assert!(
                support::close_roots(*p, *q, 1e-8),
                "{model} at {altitude_m} m, Mach {mach}: landing {p} vs {q}"
            );
        }
    }
}
