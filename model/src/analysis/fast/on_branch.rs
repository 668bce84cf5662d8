//! The critical jump and the first departure of an aircraft whose aileron yaws, certified by
//! walking the primary branch alone ([`on_branch`]).
//!
//! With aileron yaw the jump and pole polynomials are resultants in delta_a whose enclosures
//! are wide, and the certified route of the jump part must isolate every one of their positive
//! roots, on every branch, or fall back to the exact path. The envelope needs only the critical
//! jump, the first fold on the primary branch: here the jump determinant `det J5 det(A)^2` is
//! followed along the branch from `P0 = 0` by mean-value forms ([`first_root_on_branch`] with
//! [`Det::Jump`]) up to the first divergence roll rate or to where the branch's aileron is
//! proven beyond the aileron range, and its first sign change, narrowed to [`MAX_WIDTH`], is the
//! critical jump; the pole polynomial is proven nonzero over its bracket (the exact path
//! cancels common roots of the two). The first departure is then the first Hopf root on the
//! same branch before it ([`Branch::first_departure`]).

use super::{apart, at_trim_values, Branch, MAX_WIDTH};
use crate::aircraft::{Aircraft, Param};
use crate::analysis::primary::{Outcome, Walk};
use crate::analysis::{Analysis, Found, InAileron, LocalPolys};
use crate::certified::dense::{IPoly, IPoly2};
use crate::certified::{
    first_root_on_branch, positive_roots_by, value_at, value_over, Bracket, BranchEnd, Criterion,
    Det, TrimPolys, Uncertified, Values,
};
use crate::interval::I;

/// What the zero-sideslip section says on this route, which does not compute it.
pub(super) const ZERO_SIDESLIP_WITHHELD: &str = "not computed: the first departure's route \
     follows the primary branch alone (analyze gives this section)";

/// The critical jump, its landings and the first departure of `aircraft` at elevator
/// `delta_e_rad`, all certified along the primary branch, and the widest relative bracket;
/// [`Uncertified::Uncovered`] without aileron yaw (the jump part's certified route answers
/// those), or why a certificate fails.
///
/// The analysis holds what is true on this route: the divergence roll rates (every positive
/// root of det A, certified), the critical jump as the only entry of `jump` (the other roots
/// of the jump polynomial are not sought), no poles of det K, no Hopf points but through the
/// first departure, and the zero-sideslip section withheld with [`ZERO_SIDESLIP_WITHHELD`].
/// `critical_note` is the f64 walk's ([`crate::analysis::primary::follow`]) as on every
/// route, which must agree with the certified walk on whether the branch reaches the jump.
pub(super) fn on_branch(
    aircraft: &Aircraft,
    delta_e_rad: f64,
) -> Result<(Analysis, f64), Uncertified> {
    if num_traits::Zero::is_zero(aircraft.exact(Param::NDeltaA)) {
        return Err(Uncertified::Uncovered);
    }
    let v = Values::of(aircraft, delta_e_rad, 0.0);
    let t = TrimPolys::new(&v)?;
    let divergence = positive_roots_by(
        &t.det_a,
        Some(&|x| value_at(&v, Criterion::DetA, x)),
        MAX_WIDTH,
    )?;
    let mut found = found(&t, &divergence);
    let walk = found.walk(aircraft);
    let end = end(aircraft, &walk, &divergence)?;
    let jump = first_root_on_branch(&v, Det::Jump, end, MAX_WIDTH)?;
    if let Some((b, _)) = &jump {
        apart(&[*b], &divergence)?;
        if value_over(&v, Criterion::Poles, I::new(b.lo, b.hi)).contains_zero() {
            return Err(Uncertified::Sign);
        }
    }
    found.jump_roots = jump.iter().map(|(b, _)| b.value).collect();
    let no_zs = |_: &[_]| (f64::NAN, f64::NAN);
    let (mut analysis, critical) = found.assemble(aircraft, delta_e_rad, &no_zs, &walk);
    // The f64 walk must reach the certified jump, at its aileron, and find none without it.
    let agrees = match (&jump, critical) {
        (Some((_, e)), Some(0)) => {
            let da = analysis.jump[0].delta_a_rad;
            (da - e.mid()).abs() <= 1e-6 * (1.0 + da.abs())
        }
        (None, None) => true,
        _ => false,
    };
    if !agrees {
        return Err(Uncertified::Sign);
    }
    let on = Branch {
        v: &v,
        trim_condition: &t.trim_condition,
        found: &found,
        walk: &walk,
        divergence: &divergence,
        marks: (aircraft, delta_e_rad),
        fold: jump,
    };
    let values = at_trim_values(aircraft, delta_e_rad);
    let at = LocalPolys::parametric().at(&values);
    let w = on.first_departure_before(&mut analysis, critical, &at, end)?;
    analysis.zero_sideslip.withheld = Some(ZERO_SIDESLIP_WITHHELD.to_string());
    let width = divergence
        .iter()
        .chain(jump.iter().map(|(b, _)| b))
        .map(Bracket::relative_width)
        .fold(w, f64::max);
    Ok((analysis, width))
}

/// Where the walks along the branch end: at the aileron range, or where the f64 walk of the
/// branch (`walk`, without jump roots) starts the step that meets the first divergence roll
/// rate (the exact path reports the divergence there, and no jump root between there and the
/// divergence: the jump determinant, which holds the factor `det(A)^2`, need not be decided up
/// to it). Where the f64 walk meets it after the branch turned in P0, the walks end at the
/// first divergence roll rate: the certified walk past the turn (in delta_a) does not cover a
/// branch that comes back to it, and a root before the turn is one the f64 walk must reach
/// too.
fn end(aircraft: &Aircraft, walk: &Walk, divergence: &[Bracket]) -> Result<BranchEnd, Uncertified> {
    let bound = aircraft.aileron_range();
    let first = divergence.first().map_or(f64::INFINITY, |b| b.lo);
    let p0 = match walk.first(&[]) {
        (Outcome::Divergence(_), p) if p < first => p,
        (Outcome::Divergence(_), p) if p.is_nan() => first,
        (Outcome::Divergence(_), _) => return Err(Uncertified::Sign),
        _ => first,
    };
    Ok(BranchEnd::Before { p0, bound })
}

/// What the walk reads, as the routes' [`Found`]: the certified divergence roll rates and the
/// f64 polynomials of `t`, without jump roots (the walk sets the critical jump's, the only one).
fn found(t: &TrimPolys, divergence: &[Bracket]) -> Found {
    let f64s = |p: &IPoly2| InAileron(p.0.iter().map(|c| c.mid()).collect());
    let univariate = |p: &IPoly| f64s(&IPoly2::new(vec![p.clone()]));
    Found {
        divergence: divergence.iter().map(|b| b.value).collect(),
        jump_roots: Vec::new(),
        pole_roots: Vec::new(),
        zs_roots: Vec::new(),
        g: f64s(&t.trim_condition),
        trims: std::iter::once(univariate(&t.det_a))
            .chain(t.trim.iter().map(f64s))
            .collect(),
        jump_at: f64s(&t.jump_at),
        d_at: InAileron(Vec::new()),
        zs_trims: Vec::new(),
        lateral_authority: false,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{analyze_first_departure, Route};
    use super::*;
    use crate::analysis::analyze;
    use num_rational::BigRational;

    /// Aircraft B with aileron yaw (n_delta_a = -1.5): at delta_e = 2 deg its branch reaches a
    /// jump, at -4 deg it diverges first. Either way the branch route answers alone, with the
    /// exact path's critical jump (within the bracket), note and first departure, and says
    /// what it leaves out.
    #[test]
    fn the_branch_route_gives_the_exact_paths_critical_jump_and_first_departure() {
        let ac = Aircraft::b().with(Param::NDeltaA, BigRational::new((-3).into(), 2.into()));
        for de in [2f64.to_radians(), (-4f64).to_radians()] {
            let exact = analyze(&ac, de).unwrap();
            let (a, route) = analyze_first_departure(&ac, de).unwrap();
            let Route::Certified(w) = route else {
                panic!("delta_e {de}: {route:?}");
            };
            assert!(w <= MAX_WIDTH);
            let p0 = |a: &Analysis| a.critical.as_ref().map(|c| c.p0);
            match (p0(&exact), p0(&a)) {
                (Some(x), Some(y)) => assert!((x - y).abs() <= 2.0 * w * x, "{x} vs {y}"),
                (x, y) => assert_eq!(x, y, "delta_e {de}"),
            }
            assert_eq!(a.critical_note, exact.critical_note);
            assert_eq!(
                a.divergence_roll_rates.len(),
                exact.divergence_roll_rates.len()
            );
            let first = |a: &Analysis| a.first_departure.as_ref().map(|f| (f.kind, f.p0));
            match (first(&exact), first(&a)) {
                (Some((k, x)), Some((l, y))) => {
                    assert_eq!(k, l);
                    assert!((x - y).abs() <= 2.0 * w * x, "{x} vs {y}");
                }
                (x, y) => assert_eq!(x, y, "delta_e {de}"),
            }
            assert_eq!(a.jump.len(), usize::from(a.critical.is_some()));
            assert!(a.det_k_poles.is_empty());
            let withheld = a.zero_sideslip.withheld.as_deref();
            assert_eq!(withheld, Some(ZERO_SIDESLIP_WITHHELD));
        }
    }
}

#[cfg(test)]
mod walk_tests {
    //! The walk of the jump determinant along the branch (`certified::branch`), against the
    //! exact path.
    use crate::aircraft::{Aircraft, Param};
    use crate::analysis::analyze_with;
    use crate::certified::{first_root_on_branch, BranchEnd, Det, Values};
    use num_rational::BigRational;

    /// The paper's aircraft with aileron yaw `n_delta_a` (a ratio), at elevator `de_deg`.
    fn yawing(ac: Aircraft, n_delta_a: (i64, i64), de_deg: f64) -> (Aircraft, f64) {
        let n = BigRational::new(n_delta_a.0.into(), n_delta_a.1.into());
        (ac.with(Param::NDeltaA, n), de_deg.to_radians())
    }

    fn cases() -> Vec<(Aircraft, f64)> {
        vec![
            yawing(Aircraft::b(), (-3, 2), 2.0),
            yawing(Aircraft::b(), (30, 1), -4.0),
            yawing(Aircraft::a(), (-5, 1), 2.0),
        ]
    }

    /// Where the exact path finds no critical jump (aircraft B with n_delta_a = -1.5 at
    /// delta_e = -4 deg diverges first; aircraft A with n_delta_a = 30 there reaches
    /// |delta_a| = 90 deg first), the walk up to the aileron range, or to the largest step of
    /// the exact path's walk before the first divergence roll rate, finds no root.
    #[test]
    fn no_jump_root_where_the_branch_diverges_or_leaves_the_range_first() {
        for (i, (ac, de)) in [
            yawing(Aircraft::b(), (-3, 2), -4.0),
            yawing(Aircraft::a(), (30, 1), -4.0),
        ]
        .into_iter()
        .enumerate()
        {
            let exact = analyze_with(&ac, de, false).unwrap();
            assert!(exact.critical.is_none(), "case {i}");
            let divergence = exact.divergence_roll_rates.first().copied();
            let end = BranchEnd::Before {
                p0: divergence.map_or(f64::INFINITY, |d| d - crate::analysis::primary::TURN_STEP),
                bound: ac.aileron_range(),
            };
            let root = first_root_on_branch(&Values::of(&ac, de, 0.0), Det::Jump, end, 1e-9);
            assert!(matches!(root, Ok(None)), "case {i}: {root:?}");
        }
    }

    /// The first root of the jump determinant on the branch is the exact path's critical jump
    /// (the first root of its jump resultant that its f64 walk of the branch meets): the
    /// exact root lies in the certified bracket, and its aileron in the branch's enclosure.
    #[test]
    fn the_first_jump_root_on_the_branch_brackets_the_exact_critical_jump() {
        for (i, (ac, de)) in cases().into_iter().enumerate() {
            let exact = analyze_with(&ac, de, false).unwrap();
            let c = exact.critical.expect("a critical jump");
            let v = Values::of(&ac, de, 0.0);
            let end = BranchEnd::Before {
                p0: f64::INFINITY,
                bound: ac.aileron_range(),
            };
            let (b, da) = first_root_on_branch(&v, Det::Jump, end, 1e-9)
                .unwrap()
                .expect("a root");
            let slack = 4.0 * f64::EPSILON * c.p0;
            assert!(b.hi - b.lo <= 1e-9 * b.hi, "case {i}: {b:?}");
            assert!(
                b.lo - slack <= c.p0 && c.p0 <= b.hi + slack,
                "case {i}: {b:?} vs {}",
                c.p0
            );
            assert!(
                (da.mid() - c.delta_a_rad).abs() <= 1e-6,
                "case {i}: {da:?} vs {}",
                c.delta_a_rad
            );
        }
    }

    /// The walk ends without a root where the branch's aileron passes a bound below the exact
    /// critical jump's |delta_a|, and at a roll rate below the jump's.
    #[test]
    fn the_walk_ends_before_the_jump_at_a_smaller_bound_or_roll_rate() {
        for (i, (ac, de)) in cases().into_iter().enumerate() {
            let c = analyze_with(&ac, de, false).unwrap().critical.unwrap();
            let v = Values::of(&ac, de, 0.0);
            for end in [
                BranchEnd::Before {
                    p0: f64::INFINITY,
                    bound: c.delta_a_rad.abs() / 2.0,
                },
                BranchEnd::Before {
                    p0: c.p0 / 2.0,
                    bound: ac.aileron_range(),
                },
            ] {
                let root = first_root_on_branch(&v, Det::Jump, end, 1e-9);
                assert!(matches!(root, Ok(None)), "case {i}, {end:?}: {root:?}");
            }
        }
    }
}
