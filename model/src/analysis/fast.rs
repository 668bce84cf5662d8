//! The jump analysis in certified floating point ([`crate::certified`]), with the exact path
//! as the fallback whenever a certificate fails.
//!
//! Same answer as [`super::analyze_with`] without departures (the critical jump, divergence roll
//! rates, jump points, poles of det K, zero-sideslip departures), found from the enclosed
//! criterion polynomials instead of the exact ones: each root is the value of a certified
//! bracket of one or two ulps around the exact root, and everything evaluated at the roots (the
//! trim, the aileron, the primary branch) is the same f64 evaluation as on the exact path, of
//! polynomials whose coefficients differ from the exact path's by their enclosures' widths.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::analysis::fast::{analyze_routed, Route};
//!
//! let (a, route) = analyze_routed(&Aircraft::a(), 2f64.to_radians()).unwrap();
//! assert!(matches!(route, Route::Certified(w) if w <= 1e-10));
//! // The paper's first jump of aircraft A, Fig. 7: P0 = 1.70 rad/s.
//! assert!((a.critical.unwrap().p0 - 1.706288).abs() < 1e-6);
//! ```

use super::departure::{self, fold_window};
use super::primary::Walk;
use super::{
    analyze_with, check, exact_jump_part, parametric, withhold_zero_sideslip, Analysis,
    AnalysisError, AtTrim, Departures, ExactJumpPart, Found, InAileron, JumpPoint, LocalPolys,
};
use crate::aircraft::{Aircraft, Param};
use crate::algebra::{PolyF64, Sym, MAX_SYMS};
use crate::certified::dense::{IPoly, IPoly2};
use crate::certified::{
    first_hopf_on_branch, fold_intervals, positive_roots_by, real_roots_outside, trim_condition_at,
    trim_condition_of_states, value_at, Bracket, BranchEnd, Criterion, EnclosedHopf, EnclosedPolys,
    JumpPolys, Uncertified, Values,
};
use crate::equations::symbols;
use crate::interval::I;
use std::sync::OnceLock;

mod on_branch;

/// Which route gave the answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Route {
    /// Every root certified in floating point: each reported roll rate lies in a bracket that
    /// holds the exact root, the widest of relative width `.0` (at most [`MAX_WIDTH`]).
    Certified(f64),
    /// The certified route did not answer (why: a case it does not cover, such as the Hopf
    /// points of an aircraft whose aileron yaws, or a failed certificate), and the exact path
    /// did.
    Exact(Uncertified),
}

impl Route {
    /// `"certified"` or `"exact"`: the route's name, as `analyze --json` and the envelope
    /// report it.
    pub fn name(self) -> &'static str {
        match self {
            Route::Certified(_) => "certified",
            Route::Exact(_) => "exact",
        }
    }

    /// Why the certified route did not answer (`None` when it did), in words.
    pub fn fallback(self) -> Option<&'static str> {
        let Route::Exact(why) = self else {
            return None;
        };
        Some(match why {
            Uncertified::Uncovered => {
                "a case the certified route does not cover (the Hopf points of an aircraft \
                 whose aileron yaws)"
            }
            Uncertified::Degenerate => "a polynomial that may vanish or drop in degree",
            Uncertified::Sign => "a sign the enclosures could not decide",
            Uncertified::Budget => "roots closer than the enclosures resolve",
            Uncertified::Wide => "a root double precision cannot pin down",
        })
    }
}

/// The widest relative bracket the certified route reports; a root that double precision
/// cannot pin down closer (an ill-conditioned root, e.g. next to a divergence roll rate) sends
/// the aircraft to the exact path.
pub const MAX_WIDTH: f64 = 1e-9;

/// [`super::analyze_with`] without departures, by the certified route where it succeeds.
pub fn analyze_fast(aircraft: &Aircraft, delta_e_rad: f64) -> Result<Analysis, AnalysisError> {
    analyze_routed(aircraft, delta_e_rad).map(|(a, _)| a)
}

/// [`analyze_fast`], saying which route answered.
pub fn analyze_routed(
    aircraft: &Aircraft,
    delta_e_rad: f64,
) -> Result<(Analysis, Route), AnalysisError> {
    analyze_routed_with(aircraft, delta_e_rad, false)
}

/// [`super::analyze_with`] by the certified route where it succeeds, saying which route
/// answered: with `departures`, the full answer of [`super::analyze`] (Hopf points with omega
/// and l1, landings, first departure, zero-sideslip Hopf roll rates).
///
/// The departure part is certified the same way as the jump part: the Hopf polynomials
/// ([`EnclosedHopf`], the factor `det(A)^4` the exact path strips taken out before any product)
/// and the trim condition at each fold's aileron are enclosed, and their roots isolated and
/// refined ([`crate::certified::positive_roots_windowed`],
/// [`crate::certified::real_roots_outside`]); everything evaluated at the roots (omega^2,
/// omega, l1, stability) is the exact path's f64 evaluation ([`super::AtTrim`]), of the
/// parametric polynomials at the aircraft's data instead of the specialised ones. Any
/// certificate that fails sends the whole analysis to the exact path, and so does aileron yaw
/// (`n_delta_a != 0`) for the departure part: the trim then depends on delta_a and the exact
/// path eliminates it from the Hopf polynomial by a resultant, which is not enclosed here
/// ([`Uncertified::Uncovered`]).
pub fn analyze_routed_with(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    departures: bool,
) -> Result<(Analysis, Route), AnalysisError> {
    if !delta_e_rad.is_finite() || delta_e_rad.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(AnalysisError::DeltaE(delta_e_rad));
    }
    let part = if departures { Part::All } else { Part::Jump };
    routed(aircraft, delta_e_rad, part)
}

/// The jump part of [`super::analyze`] and its first departure (no other Hopf points, no
/// landings but the critical jump's, no zero-sideslip Hopf roll rates: what the envelope and
/// the clearance report), by the certified route where it succeeds, saying which route
/// answered; otherwise the exact path's (reported as [`Route::Exact`]).
///
/// With aileron yaw both are certified along the primary branch alone
/// ([`crate::certified::first_root_on_branch`], the route of `on_branch`): the critical jump is
/// the first sign change of the jump determinant on the branch (up to the first divergence
/// roll rate or the aileron range), and the first departure the first sign change of the Hopf
/// determinant before it, which the exact path finds among the roots of its resultants. The
/// analysis of that route holds the critical jump as the only entry of `jump`, no poles of
/// det K, and the zero-sideslip section withheld (not computed); callers read the critical
/// jump, its note and margin, and the first departure. Where a certificate of that route
/// fails, the certified jump part (every root of the enclosed resultants isolated) and the
/// same walk for the first departure are tried; where that fails, the exact path's jump part
/// answers and the walk starts from its critical jump; where a piece of the branch cannot be
/// decided (in P0, or in delta_a past a turn in P0), the whole exact path answers.
pub fn analyze_first_departure(
    aircraft: &Aircraft,
    delta_e_rad: f64,
) -> Result<(Analysis, Route), AnalysisError> {
    if !delta_e_rad.is_finite() || delta_e_rad.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(AnalysisError::DeltaE(delta_e_rad));
    }
    routed(aircraft, delta_e_rad, Part::First)
}

/// How much of the analysis a route computes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Part {
    /// The jump part alone.
    Jump,
    /// The jump part and the first departure.
    First,
    /// Everything [`super::analyze`] gives.
    All,
}

/// [`analyze_routed_with`] for `part` of the analysis (the exact path's fallback answers
/// with departures unless `part` is [`Part::Jump`]).
fn routed(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    part: Part,
) -> Result<(Analysis, Route), AnalysisError> {
    let departures = part != Part::Jump;
    if part == Part::First {
        if let Ok((a, width)) = on_branch::on_branch(aircraft, delta_e_rad) {
            if check(&a).is_ok() {
                return Ok((a, Route::Certified(width)));
            }
        }
    }
    let why = match certified(aircraft, delta_e_rad, part) {
        Ok((mut a, width)) => {
            withhold_zero_sideslip(&mut a);
            match check(&a) {
                // A withheld section, and values the checks refuse (not finite, indistinct in
                // f64), are the exact path's to withhold or refuse, with its own message.
                Ok(()) if a.zero_sideslip.withheld.is_some() => Uncertified::Sign,
                Ok(()) => return Ok((a, Route::Certified(width))),
                Err(_) => Uncertified::Sign,
            }
        }
        Err(why) => why,
    };
    if part == Part::First {
        if let Some(a) = exact_jumps_then_branch(aircraft, delta_e_rad) {
            return Ok((a, Route::Exact(why)));
        }
    }
    analyze_with(aircraft, delta_e_rad, departures).map(|a| (a, Route::Exact(why)))
}

/// The fallback of [`analyze_first_departure`] for an aircraft whose aileron yaws: the exact
/// path's jump part (its exact roots, a few milliseconds) and the first departure certified
/// along the primary branch from its critical jump ([`Branch::first_departure`]), instead of
/// the exact path's Hopf resultant (about 60 of its 100 ms on the F-104). `None` where the
/// exact path refuses the data, the aileron does not yaw, or a certificate of the walk fails:
/// the whole exact path answers then.
fn exact_jumps_then_branch(aircraft: &Aircraft, delta_e_rad: f64) -> Option<Analysis> {
    if num_traits::Zero::is_zero(aircraft.exact(Param::NDeltaA)) {
        return None;
    }
    let ExactJumpPart {
        found,
        walk,
        mut analysis,
        critical,
        ..
    } = exact_jump_part(aircraft, delta_e_rad).ok()?;
    let v = Values::of(aircraft, delta_e_rad, 0.0);
    let e = EnclosedPolys::new(&v).ok()?;
    let divergence = positive_roots_by(
        &e.det_a,
        Some(&|x| value_at(&v, Criterion::DetA, x)),
        MAX_WIDTH,
    )
    .ok()?;
    // The certified divergence roll rates must be the exact path's (the walk proves its roots
    // apart from the former, the f64 walk of the branch stops at the latter).
    let same = divergence.len() == found.divergence.len()
        && divergence
            .iter()
            .zip(&found.divergence)
            .all(|(b, x)| b.lo <= *x && *x <= b.hi);
    if !same {
        return None;
    }
    let at = at_trim_values(aircraft, delta_e_rad);
    let on = Branch {
        v: &v,
        trim_condition: &e.trim_condition,
        found: &found,
        walk: &walk,
        divergence: &divergence,
        marks: (aircraft, delta_e_rad),
        fold: None,
    };
    on.first_departure(&mut analysis, critical, &LocalPolys::parametric().at(&at))
        .ok()?;
    withhold_zero_sideslip(&mut analysis);
    check(&analysis).ok()?;
    Some(analysis)
}

/// Every parameter's f64 value of `aircraft`, the elevator `delta_e_rad` and `delta_r = 0`:
/// what [`LocalPolys::at`] evaluates the f64 trims at.
fn at_trim_values(aircraft: &Aircraft, delta_e_rad: f64) -> Vec<(Sym, f64)> {
    let s = symbols();
    let mut values: Vec<(Sym, f64)> = s
        .params
        .iter()
        .copied()
        .zip(aircraft.values_f64())
        .collect();
    values.extend([(s.delta_e, delta_e_rad), (s.delta_r, 0.0)]);
    values
}

/// The certified route and its widest relative bracket, or why it cannot certify.
///
/// The criterion polynomials come from the tape ([`EnclosedPolys::by_tape`]) where it applies,
/// and the whole data are lifted ([`Values::of`]) only when something needs them: a root whose
/// bracket the coefficients' enclosures cannot narrow enough (refined on the values at a point,
/// [`value_at`]), the departures, or a tape whose enclosures fail to certify, when the general
/// route ([`EnclosedPolys::new`]) is tried before the exact path.
fn certified(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    departures: Part,
) -> Result<(Analysis, f64), Uncertified> {
    let lifted = std::cell::OnceCell::new();
    let v = || lifted.get_or_init(|| Values::of(aircraft, delta_e_rad, 0.0));
    if let Some(Ok(e)) = EnclosedPolys::by_tape(&Values::data(aircraft), delta_e_rad) {
        if let Ok(answer) = certified_with(aircraft, delta_e_rad, departures, &e, &v) {
            return Ok(answer);
        }
    }
    certified_with(
        aircraft,
        delta_e_rad,
        departures,
        &EnclosedPolys::new(v())?,
        &v,
    )
}

/// [`certified`] on the criterion polynomials `e` of the data `v` (lifted on first use).
fn certified_with<'v>(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    departures: Part,
    e: &EnclosedPolys,
    v: &dyn Fn() -> &'v Values,
) -> Result<(Analysis, f64), Uncertified> {
    let roots = |p: &IPoly, which: Criterion| {
        positive_roots_by(p, Some(&|x| value_at(v(), which, x)), MAX_WIDTH)
    };
    let divergence = roots(&e.det_a, Criterion::DetA)?;
    let jump = roots(&e.jump, Criterion::Jump)?;
    let poles = roots(&e.poles, Criterion::Poles)?;
    // The exact path cancels common roots of the jump and pole polynomials and removes those of
    // det A; here they must be provably distinct instead.
    apart(&jump, &poles)?;
    apart(&jump, &divergence)?;
    apart(&poles, &divergence)?;

    let lateral_authority = if e.lateral.is_exact_zero() {
        false
    } else if e.lateral.contains_zero() {
        return Err(Uncertified::Degenerate);
    } else {
        true
    };
    let zs_roots = if lateral_authority {
        let zs = roots(&e.zs_jump, Criterion::ZsJump)?;
        apart(&zs, &roots(&e.zs_d_det, Criterion::ZsDDet)?)?;
        apart(&zs, &roots(&e.zs_det, Criterion::ZsDet)?)?;
        zs
    } else {
        Vec::new()
    };

    let f64s = |p: &IPoly2| InAileron(p.0.iter().map(|c| c.mid()).collect());
    let univariate = |p: &IPoly| f64s(&IPoly2::new(vec![p.clone()]));
    let width = [&divergence, &jump, &poles, &zs_roots]
        .iter()
        .flat_map(|b| b.iter().map(Bracket::relative_width))
        .fold(0.0, f64::max);
    if width > MAX_WIDTH {
        return Err(Uncertified::Wide);
    }
    let value = |b: Vec<Bracket>| b.iter().map(|r| r.value).collect::<Vec<f64>>();
    let found = Found {
        divergence: value(divergence.clone()),
        jump_roots: value(jump),
        pole_roots: value(poles),
        zs_roots: value(zs_roots),
        g: f64s(&e.trim_condition),
        trims: std::iter::once(univariate(&e.det_a))
            .chain(e.trim.iter().map(f64s))
            .collect(),
        jump_at: f64s(&e.jump_at),
        d_at: f64s(&e.d_at),
        zs_trims: std::iter::once(&e.zs_det)
            .chain(&e.zs_trim)
            .map(univariate)
            .collect(),
        lateral_authority,
    };
    let data = aircraft.values_f64();
    let s = symbols();
    // Every symbol's value, NaN for those a zero-sideslip point sets (and any other).
    let mut known = [f64::NAN; MAX_SYMS];
    for (p, v) in s.params.iter().zip(&data) {
        known[p.index()] = *v;
    }
    known[s.delta_e.index()] = delta_e_rad;
    known[s.delta_r.index()] = 0.0;
    let zs_controls = |at: &[(Sym, f64)]| {
        let mut values = known;
        for (t, v) in at {
            values[t.index()] = *v;
        }
        let look = |x: Sym| values[x.index()];
        let [a_num, a_den, r_num, r_den] = zs_control_forms();
        (
            a_num.eval(&look) / a_den.eval(&look),
            r_num.eval(&look) / r_den.eval(&look),
        )
    };
    let walk = found.walk(aircraft);
    let (mut analysis, critical) = found.assemble(aircraft, delta_e_rad, &zs_controls, &walk);
    if departures == Part::Jump {
        return Ok((analysis, width));
    }
    let local = LocalPolys::parametric();
    let values = at_trim_values(aircraft, delta_e_rad);
    let at = || local.at(&values);
    let input = match certified_departures(v(), e, &divergence, &analysis.jump, at()) {
        Err(Uncertified::Uncovered) if departures == Part::First => {
            let marks = (aircraft, delta_e_rad);
            let on = Branch {
                v: v(),
                trim_condition: &e.trim_condition,
                found: &found,
                walk: &walk,
                divergence: &divergence,
                marks,
                fold: None,
            };
            let w = on.first_departure(&mut analysis, critical, &at())?;
            return Ok((analysis, width.max(w)));
        }
        input => input?,
    };
    let marks = (aircraft, delta_e_rad);
    found.add_departures(&mut analysis, critical, &input.0, marks, &walk);
    Ok((analysis, width.max(input.1)))
}

/// What the first departure along the primary branch reads (aileron yaw).
struct Branch<'a> {
    v: &'a Values,
    trim_condition: &'a IPoly2,
    found: &'a Found,
    /// The f64 walk of the primary branch on `found` ([`Found::walk`]).
    walk: &'a Walk,
    divergence: &'a [Bracket],
    marks: (&'a Aircraft, f64),
    /// The critical jump's certified bracket and an enclosure of the branch's aileron at one
    /// of its roll rates, where the walk along the branch found it: its landings are then
    /// sought outside an interval proven to hold no root of the trim condition but the fold
    /// itself ([`fold_intervals`]), not only outside [`fold_window`].
    fold: Option<(Bracket, I)>,
}

impl Branch<'_> {
    /// Sets the first departure of `analysis` (whose critical jump is `critical`) and the
    /// critical jump's landings, from the first Hopf root on the primary branch up to the
    /// critical jump, or without one up to the aileron range's end ([`first_hopf_on_branch`]);
    /// the widest relative bracket used.
    fn first_departure(
        &self,
        analysis: &mut Analysis,
        critical: Option<usize>,
        at: &AtTrim<'_>,
    ) -> Result<f64, Uncertified> {
        let bound = self.marks.0.aileron_range();
        self.first_departure_before(analysis, critical, at, BranchEnd::Bound(bound))
    }

    /// [`Branch::first_departure`], the walk without a critical jump ending at `end` (where
    /// the f64 walk of the branch ends: the aileron range, or a divergence roll rate).
    fn first_departure_before(
        &self,
        analysis: &mut Analysis,
        critical: Option<usize>,
        at: &AtTrim<'_>,
        end: BranchEnd,
    ) -> Result<f64, Uncertified> {
        let (g, trims) = (&self.found.g, &self.found.trims);
        let bound = self.marks.0.aileron_range();
        let start = departure::start(at, trims);
        let end = match critical {
            Some(i) => BranchEnd::Fold {
                p0: analysis.jump[i].p0,
                delta_a: analysis.jump[i].delta_a_rad,
            },
            None => end,
        };
        // An unstable trim at the branch's start is the first departure: no Hopf root to seek.
        let root = match start {
            super::unstable_trim::Start::Unstable(_) => None,
            _ => first_hopf_on_branch(self.v, end, MAX_WIDTH)?,
        };
        // A first root whose aileron is proven beyond the range is where the branch has left
        // the range before: no departure within it (as the f64 walk, which ends there).
        let root = root.filter(|(_, da)| da.lo <= bound && da.hi >= -bound);
        let mut width = 0.0_f64;
        if let Some(i) = critical {
            let fold = analysis.jump[i].clone();
            let landing = landing_roots(
                self.v,
                self.trim_condition,
                &fold,
                &det_a_roots(self.divergence),
                self.fold,
            )?;
            let value = |b: &[Bracket]| b.iter().map(|r| r.value).collect::<Vec<f64>>();
            analysis.jump[i].lands_at =
                Some(departure::landings(at, trims, &fold, &value(&landing)));
            analysis.critical = Some(analysis.jump[i].clone());
            width = landing
                .iter()
                .map(Bracket::relative_width)
                .fold(0.0, f64::max);
        }
        let hopf = match root {
            Some((b, da)) => {
                apart(&[b], self.divergence)?;
                width = width.max(b.relative_width());
                // The trim of the root's roll rate on the branch, as the f64 roots of the trim
                // condition give it (the exact path's choice among them).
                let da = g
                    .aileron_roots(b.value)
                    .to_vec()
                    .into_iter()
                    .min_by(|x, y| (x - da.mid()).abs().total_cmp(&(y - da.mid()).abs()))
                    .unwrap_or(da.mid());
                let p = departure::hopf_point(at, b.value, da, trims, self.marks);
                vec![p.ok_or(Uncertified::Sign)?]
            }
            None => Vec::new(),
        };
        let first = departure::first_departure(start, &analysis.jump, &hopf, self.walk);
        // The f64 walk of the branch must agree with the certified one on which comes first
        // (without a critical jump, on the branch leaving the aileron range first).
        let kind = first.as_ref().map(|f| f.kind);
        let agrees = match (hopf.is_empty(), kind) {
            (_, Some(k)) if k != "jump" && k != "hopf" => true,
            (true, Some("jump")) | (false, Some("hopf")) => true,
            (true, None) => critical.is_none(),
            _ => false,
        };
        if !agrees || width > MAX_WIDTH {
            return Err(Uncertified::Sign);
        }
        analysis.first_departure = first;
        Ok(width)
    }
}

/// det A's real roots from its positive ones `divergence` (det A is even in P0).
fn det_a_roots(divergence: &[Bracket]) -> Vec<Bracket> {
    divergence
        .iter()
        .map(|b| Bracket {
            lo: -b.hi,
            hi: -b.lo,
            value: -b.value,
        })
        .chain(divergence.iter().copied())
        .collect()
}

/// The certified real roots of the trim condition at the aileron of the fold `j` (where it can
/// land), proven apart from det A's roots `det_a_roots`: those outside [`fold_window`], or,
/// with the fold's bracket and aileron enclosure `fold`, outside the first interval of
/// [`fold_intervals`] (wider than the window, proven to hold no root at the fold's exact
/// aileron but the fold) in which the roots outside can be certified.
fn landing_roots(
    v: &Values,
    trim_condition: &IPoly2,
    j: &JumpPoint,
    det_a_roots: &[Bracket],
    fold: Option<(Bracket, I)>,
) -> Result<Vec<Bracket>, Uncertified> {
    let g = trim_condition.at_aileron(I::point(j.delta_a_rad));
    let at = |x: f64, da: f64| {
        let cleared = trim_condition_at(v, x, da);
        trim_condition_of_states(v, x, da)
            .and_then(|s| s.intersect(cleared))
            .unwrap_or(cleared)
    };
    let value = |x: f64| at(x, j.delta_a_rad);
    let window = fold_window(j);
    let own = fold.map_or_else(Vec::new, |(b, near)| {
        let half = (window.1 - window.0) / 2.0;
        fold_intervals(trim_condition, &at, b, near, j.delta_a_rad, half)
    });
    let mut roots = Err(Uncertified::Sign);
    for x in own.into_iter().chain([window]) {
        roots = real_roots_outside(&g, x, Some(&value), MAX_WIDTH);
        if roots.is_ok() {
            break;
        }
    }
    let roots = roots?;
    apart(&roots, det_a_roots)?;
    Ok(roots)
}

/// The zero-sideslip controls of the parametric derivation (numerator and denominator of
/// delta_a, then of delta_r; Eq. 35), prepared once per process for f64 evaluation: the same
/// operations as [`crate::algebra::Poly::eval_f64`] in the same order, so the same values to
/// the bit.
fn zs_control_forms() -> &'static [PolyF64; 4] {
    static FORMS: OnceLock<[PolyF64; 4]> = OnceLock::new();
    FORMS.get_or_init(|| {
        let par = parametric();
        [
            &par.zs_delta_a.num,
            &par.zs_delta_a.den,
            &par.zs_delta_r.num,
            &par.zs_delta_r.den,
        ]
        .map(|p| p.to_f64_form())
    })
}

/// The departure part's roots by the certified route (the Hopf polynomials' positive roots,
/// proven distinct from det A's, the trim condition's real roots at each fold's aileron) and
/// their widest relative bracket.
fn certified_departures<'a>(
    v: &Values,
    e: &EnclosedPolys,
    divergence: &[Bracket],
    jump: &[JumpPoint],
    at: AtTrim<'a>,
) -> Result<(Departures<'a>, f64), Uncertified> {
    let h = EnclosedHopf::new(v)?;
    let hopf = h.positive_roots(v, false, MAX_WIDTH)?;
    apart(&hopf, divergence)?;
    let zs_hopf = h.positive_roots(v, true, MAX_WIDTH)?;
    let zs_det = positive_roots_by(
        &e.zs_det,
        Some(&|x| value_at(v, Criterion::ZsDet, x)),
        MAX_WIDTH,
    )?;
    apart(&zs_hopf, &zs_det)?;
    // det A is even in P0: its real roots are the divergence roll rates and their mirrors.
    let det_a_roots = det_a_roots(divergence);
    let landing = jump
        .iter()
        .map(|j| landing_roots(v, &e.trim_condition, j, &det_a_roots, None))
        .collect::<Result<Vec<_>, _>>()?;
    let width = [&hopf, &zs_hopf]
        .into_iter()
        .chain(&landing)
        .flat_map(|b| b.iter().map(Bracket::relative_width))
        .fold(0.0, f64::max);
    if width > MAX_WIDTH {
        return Err(Uncertified::Wide);
    }
    let value = |b: &[Bracket]| b.iter().map(|r| r.value).collect::<Vec<f64>>();
    Ok((
        Departures {
            at,
            hopf_roots: value(&hopf),
            hopf_at: InAileron(vec![h.hopf.mid()]),
            zs_hopf_roots: value(&zs_hopf),
            landing_roots: landing.iter().map(|b| value(b)).collect(),
        },
        width,
    ))
}

/// Proves that no bracket of `a` meets one of `b` (their roots are distinct).
fn apart(a: &[Bracket], b: &[Bracket]) -> Result<(), Uncertified> {
    let meet = a
        .iter()
        .any(|x| b.iter().any(|y| x.lo <= y.hi && y.lo <= x.hi));
    if meet {
        Err(Uncertified::Sign)
    } else {
        Ok(())
    }
}

/// The critical jump alone (the first jump on the primary branch, as [`super::analyze`] defines
/// it) by the certified route without fallback: its roll rate and aileron (rad), `Ok(None)`
/// when the primary branch diverges or reaches |delta_a| = `bound` first, or why it cannot be
/// certified. The lean route of the Monte Carlo: only the jump polynomial and det A are
/// isolated, each root refined towards relative width `width` (the critical one must reach it;
/// the value reported is the Newton root in its bracket), and the critical root's bracket is
/// proven free of poles of det K.
pub fn critical(v: &Values, bound: f64, width: f64) -> Result<Option<(f64, f64)>, Uncertified> {
    let e = JumpPolys::new(v)?;
    let lean = Lean {
        det_a: &e.det_a,
        det_a_value: e.trim().0,
        trim_condition: &e.trim_condition,
        jump_at: &e.jump_at,
        jump: &e.jump,
    };
    lean.critical(&|| v, &|| e.poles(v), bound, width)
}

/// [`critical`] of the data `data` (in [`crate::aircraft::Param::ALL`] order) at elevator
/// `delta_e_rad` and `delta_r = 0`, from the criterion program's tape
/// ([`EnclosedPolys::by_tape`]) where it applies; `lift` gives the data's [`Values`] (lifted on
/// first need: a root the tape's enclosures cannot pin down, or data the tape does not cover,
/// or a certificate that fails on the tape's enclosures, when [`critical`] answers on them).
pub fn critical_of(
    data: &[I; crate::aircraft::Param::COUNT],
    delta_e_rad: f64,
    lift: &dyn Fn() -> Values,
    bound: f64,
    width: f64,
) -> Result<Option<(f64, f64)>, Uncertified> {
    let lifted = std::cell::OnceCell::new();
    let v = || lifted.get_or_init(lift);
    if let Some(Ok(e)) = EnclosedPolys::by_tape(data, delta_e_rad) {
        let det_a_value = IPoly2::new(vec![e.det_a.clone()]);
        let lean = Lean {
            det_a: &e.det_a,
            det_a_value: &det_a_value,
            trim_condition: &e.trim_condition,
            jump_at: &e.jump_at,
            jump: &e.jump,
        };
        if let Ok(answer) = lean.critical(&v, &|| Ok(e.poles.clone()), bound, width) {
            return Ok(answer);
        }
    }
    critical(v(), bound, width)
}

/// What [`critical`] reads of the criterion polynomials, from either route.
struct Lean<'a> {
    det_a: &'a IPoly,
    /// det A as the walk evaluates it (a polynomial in P0 and delta_a).
    det_a_value: &'a IPoly2,
    trim_condition: &'a IPoly2,
    jump_at: &'a IPoly2,
    jump: &'a IPoly,
}

impl Lean<'_> {
    /// [`critical`] on these polynomials of the data `v` (asked for only to refine a root the
    /// enclosures cannot pin down), with `poles` the pole polynomial.
    fn critical<'v>(
        &self,
        v: &dyn Fn() -> &'v Values,
        poles: &dyn Fn() -> Result<IPoly, Uncertified>,
        bound: f64,
        width: f64,
    ) -> Result<Option<(f64, f64)>, Uncertified> {
        let divergence = positive_roots_by(
            self.det_a,
            Some(&|x| value_at(v(), Criterion::DetA, x)),
            width,
        )?;
        let jump = positive_roots_by(
            self.jump,
            Some(&|x| value_at(v(), Criterion::Jump, x)),
            width,
        )?;
        apart(&jump, &divergence)?;
        let f64s = |p: &IPoly2| InAileron(p.0.iter().map(|c| c.mid()).collect());
        let g = f64s(self.trim_condition);
        let jump_at = f64s(self.jump_at);
        let det_a = f64s(self.det_a_value);
        let points: Vec<(f64, f64, Bracket)> = jump
            .iter()
            .map(|b| (b.value, super::aileron_of_root(&g, &jump_at, b.value), *b))
            .filter(|(_, da, _)| da.is_finite())
            .collect();
        let roots: Vec<(f64, f64)> = points.iter().map(|(p, da, _)| (*p, *da)).collect();
        let divergence: Vec<f64> = divergence.iter().map(|b| b.value).collect();
        match super::primary::follow(&g, &det_a, &divergence, &roots, bound) {
            super::Outcome::Jump(i) => {
                let (p0, da, b) = points[i];
                if b.relative_width() > width {
                    return Err(Uncertified::Wide);
                }
                // A common root of the jump and pole polynomials is no jump (the exact path
                // cancels it): the pole polynomial must keep its sign over the critical bracket.
                if poles()?.eval(I::new(b.lo, b.hi)).contains_zero() {
                    return Err(Uncertified::Sign);
                }
                Ok(Some((p0, da)))
            }
            super::Outcome::Lost(_) => Err(Uncertified::Degenerate),
            _ => Ok(None),
        }
    }
}
