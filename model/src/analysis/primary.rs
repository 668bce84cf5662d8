//! The primary branch: which jump a pilot meets first.
//!
//! The primary branch is the equilibrium curve `G(P0, delta_a) = 0` (the trim condition of
//! [`crate::derivation::Derivation::trim_condition`]) through `P0 = 0, delta_a = 0`, the trim of a
//! wings-level aircraft with the ailerons centred. With `delta_r = 0` the PSS model is symmetric
//! under `(P0, beta, r, delta_a) -> -(P0, beta, r, delta_a)`, so following the branch towards
//! `P0 > 0` (negative aileron for `l_delta_a < 0`) also answers the other aileron direction.
//!
//! The curve is followed in f64 only to decide *which* of the exactly isolated jump roots lie on
//! it and in what order: the reported point is always the exact root. Along the curve, P0 is the
//! parameter until the curve turns in P0 (the discriminant of the quadratic in delta_a vanishes:
//! the two trims of a roll rate merge), where it continues on the other root with P0 running
//! back. The turn itself is walked too: the arc up to the fold and back from it to the step's
//! roll rate on the other root holds jump and Hopf points like any other piece of the branch.
//! Without aileron yaw the curve is a graph over P0 and never turns.

use crate::specialise::{InAileron, Roots};
use std::cell::RefCell;

/// How the primary branch ends.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// It reaches the jump root with this index (into the `jumps` slice given to `follow`).
    Jump(usize),
    /// The trims blow up (det A = 0, Eq. 5) at about this roll rate before any jump.
    Divergence(f64),
    /// |delta_a| grows past the bound without a jump.
    Unbounded,
    /// The curve ends (no trim) or cannot be followed; the reason.
    Lost(&'static str),
}

/// The largest step in P0 of [`follow`], rad/s: the aileron bound is checked at steps at most
/// this far apart, so a branch that passes the bound at P0 ends (`Unbounded`, unless a jump or
/// a divergence comes first) by P0 + `MAX_STEP`, and if the f64 value there rounds onto the
/// bound, by the next step (clearance uses this to prove that a branch has no critical jump).
pub const MAX_STEP: f64 = 2e-2;

/// The largest step in P0 of [`follow`] where the curve may turn (aileron yaw), rad/s: the
/// aileron bound is checked at steps at most this far apart there (clearance uses this to
/// prove that a branch coming back on its other trim leaves the range before a jump).
pub const TURN_STEP: f64 = 1e-3;

/// Follows the primary branch from `(0, 0)` and returns how it ends.
///
/// `g` is the trim condition, `det_a` the trim's denominator (scaled for f64 evaluation),
/// `divergence` the positive roots of det A (the divergence roll rates), `jumps` the jump roots
/// as `(p0, delta_a)` (in any order), `max_abs_delta_a` the aileron bound in rad.
///
/// Steps keep the change of P0 below 1e-3, and that of delta_a about as small (the step is set
/// by the slope of the last one), where the curve may turn or meet its other trim (aileron
/// yaw); without aileron yaw the curve is the graph of a rational function of P0, and steps of
/// 2e-2 only look for the aileron bound (the jumps and divergence roll rates between two steps
/// are found from their lists).
pub fn follow(
    g: &InAileron,
    det_a: &InAileron,
    divergence: &[f64],
    jumps: &[(f64, f64)],
    max_abs_delta_a: f64,
) -> Outcome {
    let curve = Curve {
        g,
        det_a,
        divergence,
        bound: max_abs_delta_a,
    };
    let mut walker = match Walker::new(&curve) {
        Ok(w) => w,
        Err((end, _)) => return end,
    };
    loop {
        match walker.advance(&curve) {
            Ok(step) => {
                if let Some((end, _)) = step.meets(jumps) {
                    return end;
                }
            }
            Err((end, _)) => return end,
        }
    }
}

/// The walk of [`follow`] made once and asked many times: the steps taken are kept, and a
/// question about other jump roots reads them, walking on only past the last one kept. The
/// steps do not depend on the jump roots (they only end the walk), so every answer is
/// [`follow`]'s to the bit. A route asks about the branch up to three times at one point (where
/// its certified walks end, the critical jump among the jump roots, the first departure among
/// those and the Hopf points), each time from the same start.
pub struct Walk {
    g: InAileron,
    det_a: InAileron,
    divergence: Vec<f64>,
    bound: f64,
    walked: RefCell<Walked>,
}

/// What a [`Walk`] has walked so far.
struct Walked {
    /// The steps taken, in walk order; the last one ends the walk if it has an end.
    steps: Vec<Step>,
    /// The walk's state after them, or how it ended without a step.
    walker: Result<Walker, (Outcome, f64)>,
}

impl Walk {
    /// The walk of [`follow`] on these arguments (without the jump roots), none of it taken yet.
    pub fn new(g: &InAileron, det_a: &InAileron, divergence: &[f64], max_abs_delta_a: f64) -> Walk {
        let mut walk = Walk {
            g: g.clone(),
            det_a: det_a.clone(),
            divergence: divergence.to_vec(),
            bound: max_abs_delta_a,
            walked: RefCell::new(Walked {
                steps: Vec::new(),
                walker: Err((Outcome::Lost("not started"), 0.0)),
            }),
        };
        walk.walked.get_mut().walker = Walker::new(&walk.curve());
        walk
    }

    fn curve(&self) -> Curve<'_> {
        Curve {
            g: &self.g,
            det_a: &self.det_a,
            divergence: &self.divergence,
            bound: self.bound,
        }
    }

    /// How the branch ends with the jump roots `jumps` ([`follow`]), with the roll rate its
    /// last step started from: the branch up to there holds none of `jumps` and no divergence
    /// roll rate (a jump root between there and the end of a step that meets a divergence roll
    /// rate is not reached). NaN once the curve has turned in P0: the roll rate then no longer
    /// tells how far along the branch the walk is.
    pub fn first(&self, jumps: &[(f64, f64)]) -> (Outcome, f64) {
        let curve = self.curve();
        let mut walked = self.walked.borrow_mut();
        let Walked { steps, walker } = &mut *walked;
        for step in steps.iter() {
            if let Some(end) = step.meets(jumps) {
                return end;
            }
        }
        // The state walks on as a local, whose fields stay in registers between steps.
        let mut w = match walker {
            Ok(w) => w.clone(),
            Err(end) => return end.clone(),
        };
        let (end, state) = loop {
            match w.advance(&curve) {
                Ok(step) => {
                    steps.push(step);
                    if let Some(end) = step.meets(jumps) {
                        break (end, Ok(w));
                    }
                }
                Err(end) => break (end.clone(), Err(end)),
            }
        };
        *walker = state;
        end
    }
}

/// What the walk follows: the trim condition, det A, the divergence roll rates and the aileron
/// bound (as [`follow`]'s arguments).
struct Curve<'a> {
    g: &'a InAileron,
    det_a: &'a InAileron,
    divergence: &'a [f64],
    bound: f64,
}

/// How a step ends the walk, whatever the jump roots.
#[derive(Clone, Copy, Debug, PartialEq)]
enum StepEnd {
    /// It meets a divergence roll rate, or det A changes sign over it.
    Divergence,
    /// Its end lies beyond the aileron bound.
    Unbounded,
}

/// One step of the walk, from `(p, da)` to `(p_new, da_new)`.
#[derive(Clone, Copy, Debug)]
struct Step {
    p: f64,
    p_new: f64,
    da: f64,
    da_new: f64,
    /// The roll rate the step starts from, NaN once the curve has turned in P0.
    since: f64,
    end: Option<StepEnd>,
}

impl Step {
    /// How the walk ends at this step with the jump roots `jumps` (a divergence before a jump
    /// root, a jump root before the aileron bound), and the roll rate the step started from;
    /// `None` when it goes on.
    #[inline(always)]
    fn meets(&self, jumps: &[(f64, f64)]) -> Option<(Outcome, f64)> {
        let Step {
            p,
            p_new,
            da,
            da_new,
            since,
            end,
        } = *self;
        if end == Some(StepEnd::Divergence) {
            return Some((Outcome::Divergence(p_new), since));
        }
        // A jump root between p and p_new whose aileron is this branch's.
        let (lo, hi) = if p < p_new { (p, p_new) } else { (p_new, p) };
        let hit = jumps
            .iter()
            .enumerate()
            .filter(|(_, (jp, _))| *jp > lo && *jp <= hi)
            .filter(|(_, (jp, jda))| {
                let here = da + (da_new - da) * (jp - p) / (p_new - p);
                let tol = 1e-3 * (1.0 + here.abs()) + (da_new - da).abs();
                (jda - here).abs() <= tol
            })
            .min_by(|a, b| ((a.1 .0 - p).abs()).total_cmp(&(b.1 .0 - p).abs()));
        if let Some((i, _)) = hit {
            return Some((Outcome::Jump(i), since));
        }
        (end == Some(StepEnd::Unbounded)).then_some((Outcome::Unbounded, since))
    }
}

/// The state of the walk between two steps.
#[derive(Clone)]
struct Walker {
    max_step: f64,
    p: f64,
    da: f64,
    dir: f64,
    slope: f64,
    /// `p` while the curve has not turned in P0, NaN after.
    since: f64,
    /// Whether the last step's change of delta_a was at most its length: then |slope| <= 1 and
    /// the next step is full, `max_step / |slope| >= max_step` (the division rounds
    /// monotonically), without waiting for the division that gives the slope (its latency was
    /// most of a step's time; the slope itself is only the prediction's, off the chain).
    full: bool,
    /// After a turn: the side of the fold (+1 above, -1 below in delta_a) the curve continues
    /// on.
    turned: Option<f64>,
    /// After a turn: the arc back from the fold to the roll rate the turn was found from, the
    /// next step taken.
    from_fold: Option<Step>,
    sign_det_a: f64,
    ahead: Ahead,
    /// The steps taken so far (a turn counts one, for its step up to the fold).
    rounds: usize,
}

impl Walker {
    /// The walk's start at `(0, 0)`, or how it ends there (with roll rate 0).
    fn new(c: &Curve) -> Result<Walker, (Outcome, f64)> {
        let graph = c.g.0.len() <= 2 && c.det_a.0.len() <= 1;
        let Some(da) = c.g.aileron_roots(0.0).nearest(0.0) else {
            return Err((Outcome::Lost("no trim at P0 = 0"), 0.0));
        };
        if da.abs() > 1e-9 {
            return Err((
                Outcome::Lost(
                    "the trim at P0 = 0 needs aileron (n_p or delta_r break the symmetry)",
                ),
                0.0,
            ));
        }
        Ok(Walker {
            max_step: if graph { MAX_STEP } else { TURN_STEP },
            p: 0.0,
            da,
            dir: 1.0,
            slope: 0.0,
            since: 0.0,
            full: true,
            turned: None,
            from_fold: None,
            sign_det_a: c.det_a.eval(0.0, 0.0).signum(),
            ahead: Ahead::new(),
            rounds: 0,
        })
    }

    /// The next step of the walk (one that ends it is the last), or how the walk ends without
    /// one (the curve ends or cannot be followed), with the roll rate its last step started
    /// from.
    #[inline(always)]
    fn advance(&mut self, c: &Curve) -> Result<Step, (Outcome, f64)> {
        const MAX_STEPS: usize = 2_000_000;
        let max_step = self.max_step;
        if let Some(step) = self.from_fold.take() {
            return Ok(step);
        }
        if self.rounds >= MAX_STEPS {
            return Err((
                Outcome::Lost("the primary branch was followed for 2e6 steps without an end"),
                self.since,
            ));
        }
        self.rounds += 1;
        let h = if self.full {
            max_step
        } else {
            max_step
                .min(max_step / self.slope.abs().max(1e-300))
                .max(1e-10)
        };
        let (p, da, dir) = (self.p, self.da, self.dir);
        let (p_new, roots, det_a_new) = self.ahead.step(c, p, dir * h, h == max_step);
        let back_from_turn = self.turned.take();
        let next = match (back_from_turn, roots.pair()) {
            // The first step back from a turn: the two roots straddle the fold, and the
            // curve goes on with the one on the other root's side of it. The nearest root
            // to a prediction is no guide here (the pair is nearly symmetric about the
            // fold, so a step lands about as close to either): choosing by it could hop
            // back onto the branch just followed and walk it again, back and forth,
            // without end.
            (Some(side), Some([lower, upper])) => Some(if side > 0.0 { upper } else { lower }),
            _ => roots.nearest(da + self.slope * dir * h),
        };
        let Some(da_new) = next else {
            if back_from_turn.is_some() {
                // No trim a step to either side: the curve closes within one step of P0.
                return Err((
                    Outcome::Lost("the equilibrium curve turns twice within one step"),
                    self.since,
                ));
            }
            return self.turn(c, p + dir * h);
        };
        let step = Step {
            p,
            p_new,
            da,
            da_new,
            since: self.since,
            end: self.end_of(c, p, p_new, da_new, det_a_new),
        };
        if step.end.is_none() {
            self.slope = (da_new - da) / (dir * h);
            self.full = (da_new - da).abs() <= h;
            self.da = da_new;
            self.p = p_new;
            if !self.since.is_nan() {
                self.since = p_new;
            }
        }
        Ok(step)
    }

    /// How a step from `p` to `(p_new, da_new)`, det A being `det_a_new` there, ends the walk:
    /// at a divergence roll rate between, or det A's sign changed, or beyond the aileron bound.
    fn end_of(
        &self,
        c: &Curve,
        p: f64,
        p_new: f64,
        da_new: f64,
        det_a_new: f64,
    ) -> Option<StepEnd> {
        let (lo, hi) = if p < p_new { (p, p_new) } else { (p_new, p) };
        let diverges = c.divergence.iter().any(|d| *d > lo && *d <= hi);
        if diverges || det_a_new.signum() != self.sign_det_a {
            Some(StepEnd::Divergence)
        } else if da_new.abs() > c.bound {
            Some(StepEnd::Unbounded)
        } else {
            None
        }
    }

    /// The two trims of this roll rate merge and vanish before `beyond` (where there is none):
    /// the curve turns in P0 and continues on the other root, P0 running back. The step
    /// returned walks the arc up to the fold; the next one ([`Walker::from_fold`]) walks the
    /// arc back from the fold on the other root to this roll rate, and the walk goes on from
    /// there. Both arcs are the branch's: a jump or Hopf point on either is met there, not
    /// stepped over. How the walk ends if there is no other root.
    fn turn(&mut self, c: &Curve, beyond: f64) -> Result<Step, (Outcome, f64)> {
        let (p, da, since) = (self.p, self.da, self.since);
        self.dir = -self.dir;
        self.since = f64::NAN;
        let Some(other) =
            c.g.aileron_roots(p)
                .into_iter()
                .filter(|r| (r - da).abs() > 0.0)
                .min_by(|a, b| (a - da).abs().total_cmp(&(b - da).abs()))
        else {
            return Err((Outcome::Lost("the equilibrium curve ends"), self.since));
        };
        // Near the fold delta_a - delta_a_f ~ -+sqrt(P0_f - P0): the other root leaves it as
        // fast as this one came, the other way in delta_a per P0. Keeping that slope keeps the
        // first steps back as short as the last ones.
        self.turned = Some((other - da).signum());
        self.slope = -self.slope;
        self.da = other;
        let (p_fold, [lower, upper]) = fold(c.g, p, beyond);
        let (near, far) = if da < other {
            (lower, upper)
        } else {
            (upper, lower)
        };
        let det_a_fold = c.det_a.eval(p_fold, 0.0);
        let to_fold = Step {
            p,
            p_new: p_fold,
            da,
            da_new: near,
            since,
            end: self.end_of(c, p, p_fold, near, det_a_fold),
        };
        if to_fold.end.is_none() {
            self.from_fold = Some(Step {
                p: p_fold,
                p_new: p,
                da: far,
                da_new: other,
                since: f64::NAN,
                end: self.end_of(c, p_fold, p, other, c.det_a.eval(p, 0.0)),
            });
        }
        Ok(to_fold)
    }
}

/// The fold of the trim condition `g` between `p`, where it has two roots in delta_a, and
/// `beyond`, where it has none, by bisection on whether the two roots exist: the last roll rate
/// found with them (within rounding of the fold) and the two roots there, ascending.
fn fold(g: &InAileron, mut p: f64, mut beyond: f64) -> (f64, [f64; 2]) {
    let Some(mut pair) = g.aileron_roots(p).pair() else {
        return (p, [f64::NAN; 2]);
    };
    loop {
        let m = p + (beyond - p) / 2.0;
        if m == p || m == beyond {
            return (p, pair);
        }
        match g.aileron_roots(m).pair() {
            Some(r) => (p, pair) = (m, r),
            None => beyond = m,
        }
    }
}

/// How many full steps [`Ahead`] evaluates at once.
const LANES: usize = 4;

/// The walk's evaluations (the roots in delta_a of the trim condition and the value of det A)
/// at the roll rate of each step, made [`LANES`] full steps ahead at a time.
///
/// A step's length follows from the slope of the last one, so the walk is a chain of dependent
/// evaluations, each a Horner scheme whose operations wait on one another: most of the walk's
/// time is that latency. While the steps stay full (|slope| <= 1, the usual case) the roll rates
/// of the next steps are known in advance, `p + h`, `p + h + h`, ..., and their evaluations are
/// independent; made together by the lane forms of the evaluations
/// ([`InAileron::aileron_roots_lanes`], [`InAileron::eval_lanes`]) they overlap, with the same
/// values to the bit, so the walk takes the same steps to the same outcome. Evaluations past a
/// step that is not full are dropped.
#[derive(Clone)]
struct Ahead {
    /// The steps evaluated ahead, in walk order.
    steps: [AheadStep; LANES],
    /// The next unused entry of `steps` (`LANES`: none).
    next: usize,
}

/// One step evaluated by [`Ahead`].
#[derive(Clone, Copy, Default)]
struct AheadStep {
    /// The roll rate it starts from and its signed length.
    from: f64,
    dh: f64,
    /// The roll rate it reaches, the roots in delta_a there and det A there.
    to: f64,
    roots: Roots,
    det_a: f64,
}

impl Ahead {
    fn new() -> Ahead {
        Ahead {
            steps: [AheadStep::default(); LANES],
            next: LANES,
        }
    }

    /// The step of signed length `dh` from `p` along `c`: the roll rate it reaches, the roots
    /// in delta_a there and det A there; `full` says the step has the largest length, so that
    /// the next ones may be evaluated with it.
    #[inline(always)]
    fn step(&mut self, c: &Curve, p: f64, dh: f64, full: bool) -> (f64, Roots, f64) {
        let s = match self.steps.get(self.next) {
            Some(s) if s.from == p && s.dh == dh => *s,
            _ if !full => {
                self.next = LANES;
                let to = p + dh;
                return (to, c.g.aileron_roots(to), c.det_a.eval(to, 0.0));
            }
            _ => {
                let mut from = [p; LANES];
                for l in 1..LANES {
                    from[l] = from[l - 1] + dh;
                }
                let to = from.map(|f| f + dh);
                let roots = c.g.aileron_roots_lanes(to);
                let det_a = c.det_a.eval_lanes(to, 0.0);
                self.steps = std::array::from_fn(|l| AheadStep {
                    from: from[l],
                    dh,
                    to: to[l],
                    roots: roots[l],
                    det_a: det_a[l],
                });
                self.next = 0;
                self.steps[0]
            }
        };
        self.next += 1;
        (s.to, s.roots, s.det_a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::roots::F64Poly;

    /// Trim conditions with aileron yaw (quadratic in delta_a) and without, and a det A with
    /// roots on both sides of P0 = 0: the curves the walk's tests follow.
    fn curves() -> ([InAileron; 2], InAileron) {
        let poly = |c: &[f64]| F64Poly(c.to_vec());
        let yawing = InAileron(vec![
            poly(&[0.0, -0.7, 0.3, 1.1e-3]),
            poly(&[-2.1, 0.05, 0.4]),
            poly(&[0.0, 0.013, 0.0, -0.002]),
        ]);
        let linear = InAileron(vec![poly(&[0.0, -0.7, 0.3]), poly(&[-2.1, 0.05, 0.4])]);
        let det_a = InAileron(vec![poly(&[3.0, 0.0, -1.7, 0.0, 0.21])]);
        ([yawing, linear], det_a)
    }

    /// The evaluations made ahead are those of the one-at-a-time evaluation, to the bit, for
    /// full steps, shorter ones and a change of direction, with aileron yaw (quadratic in
    /// delta_a) and without.
    #[test]
    fn evaluations_made_ahead_are_the_same_to_the_bit() {
        let ([yawing, linear], det_a) = curves();
        for g in [&yawing, &linear] {
            let c = Curve {
                g,
                det_a: &det_a,
                divergence: &[],
                bound: 1.0,
            };
            let mut ahead = Ahead::new();
            let mut p = 0.0f64;
            let full = 2e-2;
            let steps = [
                full, full, 3e-3, full, full, full, full, full, -full, -full, full,
            ];
            for (k, h) in steps.into_iter().cycle().take(60).enumerate() {
                let (p_new, roots, det) = ahead.step(&c, p, h, h.abs() == full);
                assert_eq!(p_new.to_bits(), (p + h).to_bits(), "step {k}");
                let want = g.aileron_roots(p_new);
                assert_eq!(roots.len(), want.len(), "step {k}");
                for (a, b) in roots.as_slice().iter().zip(want.as_slice()) {
                    assert_eq!(a.to_bits(), b.to_bits(), "step {k}");
                }
                assert_eq!(det.to_bits(), det_a.eval(p_new, 0.0).to_bits(), "step {k}");
                p = p_new;
            }
        }
    }

    /// A [`Walk`] asked about several jump lists, in either order (a short walk first, then one
    /// past the steps kept, or the whole walk first), answers as [`follow`] walking afresh for
    /// each, with the same roll rate of the last step whichever order.
    #[test]
    fn a_kept_walk_answers_as_a_fresh_one() {
        let ([yawing, linear], det_a) = curves();
        for g in [&yawing, &linear] {
            let on = |p: f64| (p, g.aileron_roots(p).nearest(0.0).unwrap());
            let lists: Vec<Vec<(f64, f64)>> = vec![
                vec![],
                vec![on(0.05)],
                vec![(0.3, 5.0), on(0.4), on(0.2)],
                vec![(0.3, 5.0)],
            ];
            for divergence in [vec![], vec![0.6]] {
                for bound in [0.1, 1.0] {
                    let fresh: Vec<Outcome> = lists
                        .iter()
                        .map(|j| follow(g, &det_a, &divergence, j, bound))
                        .collect();
                    let forward = Walk::new(g, &det_a, &divergence, bound);
                    let backward = Walk::new(g, &det_a, &divergence, bound);
                    let ahead: Vec<_> = lists.iter().map(|j| forward.first(j)).collect();
                    let mut behind: Vec<_> =
                        lists.iter().rev().map(|j| backward.first(j)).collect();
                    behind.reverse();
                    for (k, want) in fresh.iter().enumerate() {
                        assert_eq!(&ahead[k].0, want, "list {k}, bound {bound}");
                        assert_eq!(&behind[k].0, want, "list {k}, bound {bound}");
                        assert_eq!(ahead[k].1.to_bits(), behind[k].1.to_bits(), "list {k}");
                    }
                }
            }
            assert!(matches!(
                follow(g, &det_a, &[], &[on(0.05)], 1.0),
                Outcome::Jump(0)
            ));
        }
    }

    /// A branch that turns in P0 between two steps: `0.5 delta_a^2 + delta_a + k P0 = 0`
    /// through `(0, 0)` turns at `P0 = 1 / (2k)`, `delta_a = -1`, and comes back on
    /// `delta_a = -1 - sqrt(1 - 2k P0)`. A jump root a hair before the fold, on the arc up to
    /// it or on the arc back from it (its aileron from the formula, apart from the walk), is
    /// met, however close to the fold the walk's last step before it ends.
    #[test]
    fn a_root_on_either_arc_of_a_turn_is_met() {
        let poly = |c: &[f64]| F64Poly(c.to_vec());
        let det_a = InAileron(vec![poly(&[1.0])]);
        for p_fold in [0.50045, 0.3337, 0.7072] {
            let k = 0.5 / p_fold;
            let g = InAileron(vec![poly(&[0.0, k]), poly(&[1.0]), poly(&[0.5])]);
            for below in [1e-9, 1e-7, 1e-5] {
                let p = p_fold - below;
                let s = (1.0 - 2.0 * k * p).sqrt();
                for (arc, da) in [("up", -1.0 + s), ("back", -1.0 - s)] {
                    let end = follow(&g, &det_a, &[], &[(p, da)], 10.0);
                    assert_eq!(end, Outcome::Jump(0), "fold {p_fold}, {below} below, {arc}");
                }
            }
        }
    }
}
