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
use model::pss_model::{Controls, PssModel};

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

/// The route's and the exact path's analyses of `ac` (flight state `at`) at elevator increment
/// 0, and the route's bracket width: the route must certify and agree with the exact path
/// ([`same`]).
fn certified_as_exact(ac: &Aircraft, at: &str) -> (Analysis, Analysis, f64) {
    let exact = analyze(ac, 0.0).unwrap();
    let (a, route) = analyze_first_departure(ac, 0.0).unwrap();
    let Route::Certified(w) = route else {
        panic!("{at}: {route:?}");
    };
    if let Err(e) = same(&a, &exact, w) {
        panic!("{at}: {e}");
    }
    (a, exact, w)
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
        certified_as_exact(&ac, &format!("{model} at {altitude_m} m, Mach {mach}"));
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
        let (a, _, w) = certified_as_exact(&ac, &format!("{altitude_m} m, Mach {mach}"));
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
    }
}

/// A point of the PSS equilibrium curve `f(x, delta_a) = 0` (Appendix A.2, at delta_e = 0):
/// the state `[alpha, beta, p, q, r]` and the aileron.
type Y = nalgebra::SVector<f64, 6>;

/// `f` at `y` and its 5x6 Jacobian in `(x, delta_a)` by central differences: the equations of
/// motion themselves, apart from the trim condition the walks follow.
fn pss(m: &PssModel, y: &Y) -> (nalgebra::SVector<f64, 5>, nalgebra::SMatrix<f64, 5, 6>) {
    let f = |y: &Y| {
        let x = [y[0], y[1], y[2], y[3], y[4]];
        let u = Controls {
            delta_a: y[5],
            ..Controls::default()
        };
        nalgebra::SVector::<f64, 5>::from(m.rhs(&x, &u))
    };
    let mut d = nalgebra::SMatrix::<f64, 5, 6>::zeros();
    for j in 0..6 {
        let h = 1e-7 * (1.0 + y[j].abs());
        let (mut a, mut b) = (*y, *y);
        a[j] += h;
        b[j] -= h;
        d.set_column(j, &((f(&a) - f(&b)) / (2.0 * h)));
    }
    (f(y), d)
}

/// Newton's method on `f = 0` with `t . (y - at) = s`, from `at + s t`: the curve's point `s`
/// along the tangent `t` from `at` (pseudo-arclength), or `None` without convergence.
fn corrected(m: &PssModel, at: &Y, t: &Y, s: f64) -> Option<Y> {
    let mut y = at + t * s;
    for _ in 0..12 {
        let (f, d) = pss(m, &y);
        let mut a = nalgebra::SMatrix::<f64, 6, 6>::zeros();
        a.fixed_view_mut::<5, 6>(0, 0).copy_from(&d);
        a.set_row(5, &t.transpose());
        let mut rhs = nalgebra::SVector::<f64, 6>::zeros();
        rhs.fixed_rows_mut::<5>(0).copy_from(&f);
        rhs[5] = t.dot(&(y - at)) - s;
        let dy = a.lu().solve(&rhs)?;
        y -= dy;
        if dy.norm() <= 1e-12 * (1.0 + y.norm()) {
            return Some(y);
        }
    }
    None
}

/// The unit tangent of the curve at `y`, oriented along `prev`.
fn tangent(m: &PssModel, y: &Y, prev: &Y) -> Y {
    let (_, d) = pss(m, y);
    let mut a = nalgebra::SMatrix::<f64, 6, 6>::zeros();
    a.fixed_view_mut::<5, 6>(0, 0).copy_from(&d);
    a.set_row(5, &prev.transpose());
    let mut e = Y::zeros();
    e[5] = 1.0;
    let t = a.lu().solve(&e).unwrap();
    t / t.norm()
}

/// The largest real part of the eigenvalues of the state Jacobian at `y`, and whether that
/// eigenvalue is one of a complex pair (an oscillatory mode).
fn stability(m: &PssModel, y: &Y) -> (f64, bool) {
    let (_, d) = pss(m, y);
    let j: nalgebra::SMatrix<f64, 5, 5> = d.fixed_view::<5, 5>(0, 0).into();
    let l = j.complex_eigenvalues();
    let top = l.iter().max_by(|a, b| a.re.total_cmp(&b.re)).unwrap();
    (top.re, top.im.abs() > 1e-6)
}

/// The PSS equilibrium curve of `ac` continued by pseudo-arclength from the wings-level trim
/// (`P0 = 0, delta_a = 0`) towards `P0 > 0`, up to the first loss of stability (the largest
/// real part of J5's eigenvalues crossing zero, located by bisection along the arc): the
/// largest roll rate reached before it (the turn in P0 if the curve came back), that point
/// `(P0, delta_a)`, whether P0 runs back there (the curve's tangent, oriented along the walk,
/// has dP0/ds < 0: the point lies past the turn) and whether the mode that loses stability is
/// oscillatory (a Hopf point).
fn first_loss_of_stability(ac: &Aircraft) -> (f64, (f64, f64), bool, bool) {
    let m = PssModel::new(ac);
    let mut up = Y::zeros();
    up[2] = 1.0;
    let mut y = corrected(&m, &Y::zeros(), &up, 0.0).expect("the trim at P0 = 0");
    let mut t = tangent(&m, &y, &up);
    let (re0, _) = stability(&m, &y);
    assert!(re0 < 0.0, "the wings-level trim is unstable: {re0}");
    let (mut ds, mut p_max) = (1e-3, 0.0f64);
    for _ in 0..200_000 {
        let Some(next) = corrected(&m, &y, &t, ds) else {
            ds /= 2.0;
            assert!(ds > 1e-12, "the continuation stalls at {y:?}");
            continue;
        };
        let (re, _) = stability(&m, &next);
        if re >= 0.0 {
            let (mut lo, mut hi) = (0.0, ds);
            for _ in 0..60 {
                let mid = (lo + hi) / 2.0;
                let z = corrected(&m, &y, &t, mid).unwrap();
                if stability(&m, &z).0 < 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let z = corrected(&m, &y, &t, lo).unwrap();
            let back = tangent(&m, &z, &t)[2] < 0.0;
            return (p_max.max(z[2]), (z[2], z[5]), back, stability(&m, &z).1);
        }
        p_max = p_max.max(next[2]);
        t = tangent(&m, &next, &t);
        y = next;
        assert!(y[5].abs() <= ac.aileron_range(), "no loss of stability");
        ds = (ds * 1.2).min(2e-3);
    }
    panic!("the continuation did not reach a loss of stability");
}

/// The F-16 at 12,800 m, Mach 0.76 and 13,800 m, Mach 0.77, 1 g: continued from the
/// wings-level trim by pseudo-arclength on the PSS equations of motion (central differences,
/// nalgebra), the equilibrium curve turns in P0 (at the trim condition's turn, by bisection on
/// its discriminant) and, on the arc coming back from the turn, the largest real part of J5's
/// eigenvalues crosses zero at a complex pair: a Hopf point, the branch's first loss of
/// stability (outside the model's validity range, as at 12,500 m, Mach 0.75). Both routes
/// report it as the first departure, at its roll rate and aileron: the walk of the branch
/// steps across the turn, and without walking the arc to the fold and back it misses it.
#[test]
fn the_hopf_point_on_the_arc_back_from_a_turn_is_the_first_departure() {
    if !support::jsbsim_installed() {
        return;
    }
    for (altitude_m, mach) in [(12800.0, 0.76), (13800.0, 0.77)] {
        let ac = jet("f16", altitude_m, mach);
        let (p_max, (p0, da), back, oscillatory) = first_loss_of_stability(&ac);
        let (p_turn, _) = turn(&Values::of(&ac, 0.0, 0.0), p_max - 1e-3, p_max + 1e-3);
        assert!(oscillatory, "{altitude_m} m: not a Hopf point");
        assert!(
            (p_max - p_turn).abs() <= 1e-6,
            "{altitude_m} m: turn {p_max} vs {p_turn}"
        );
        assert!(
            back && p0 < p_turn,
            "{altitude_m} m: {p0} is not past the turn {p_turn}"
        );
        let (a, exact, _) = certified_as_exact(&ac, &format!("{altitude_m} m, Mach {mach}"));
        for (name, b) in [("exact", &exact), ("certified", &a)] {
            let d = b.first_departure.as_ref();
            let d = d.unwrap_or_else(|| panic!("{altitude_m} m, {name}: no first departure"));
            assert_eq!(d.kind, "hopf", "{altitude_m} m, {name}");
            assert!(
                (d.p0 - p0).abs() <= 1e-7,
                "{altitude_m} m, {name}: {} vs {p0}",
                d.p0
            );
            assert!(
                (d.delta_a_rad - da).abs() <= 1e-6,
                "{altitude_m} m, {name}: {d:?} vs {da}"
            );
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
/// Both routes take the fold's aileron as the trim's at their roll rate of the fold, where it is
/// stationary: no landing lies within 1e-5 rad/s of the fold (the exact path, taking the common
/// root of the trim condition and det J5 instead, listed one at the T-38's 4,400 m, Mach 0.61:
/// "lands at P0 = 2.405892 rad/s (jump -0.000004 rad/s)"), and the landings agree to 1e-8
/// (relative).
#[test]
fn landings_next_to_the_fold_are_certified_with_the_exact_answer() {
    if !support::jsbsim_installed() {
        return;
    }
    for (model, altitude_m, mach) in [
        ("f16", 1300.0, 0.85),
        ("f16", 11500.0, 0.94),
        ("T38", 2400.0, 0.48),
        ("T38", 4400.0, 0.61),
        ("T38", 7400.0, 0.91),
    ] {
        let ac = jet(model, altitude_m, mach);
        let (a, exact, _) =
            certified_as_exact(&ac, &format!("{model} at {altitude_m} m, Mach {mach}"));
        let fold = exact.critical.as_ref().expect("a critical jump").p0;
        let lands = |a: &Analysis| -> Vec<f64> {
            let c = a.critical.as_ref().expect("a critical jump");
            c.lands_at.iter().flatten().map(|l| l.p0).collect()
        };
        let (x, y) = (lands(&a), lands(&exact));
        let next_to_the_fold = |p: &f64| (p - fold).abs() < 1e-5;
        assert!(
            !x.iter().chain(&y).any(next_to_the_fold),
            "{model} at {altitude_m} m: {x:?}, {y:?}"
        );
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
