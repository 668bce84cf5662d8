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
//! back. Without aileron yaw the curve is a graph over P0 and never turns.

use crate::specialise::InAileron;

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
/// Steps keep the change of P0 and of delta_a below 1e-3 where the curve may turn or meet its
/// other trim (aileron yaw); without aileron yaw the curve is the graph of a rational function
/// of P0, and steps of 2e-2 only look for the aileron bound (the jumps and divergence roll rates
/// between two steps are found from their lists).
pub fn follow(
    g: &InAileron,
    det_a: &InAileron,
    divergence: &[f64],
    jumps: &[(f64, f64)],
    max_abs_delta_a: f64,
) -> Outcome {
    let graph = g.0.len() <= 2 && det_a.0.len() <= 1;
    let max_step: f64 = if graph { MAX_STEP } else { TURN_STEP };
    const MAX_STEPS: usize = 2_000_000;
    let nearest = |roots: &[f64], target: f64| -> Option<f64> {
        roots
            .iter()
            .copied()
            .min_by(|a, b| (a - target).abs().total_cmp(&(b - target).abs()))
    };
    let Some(mut da) = nearest(g.aileron_roots(0.0).as_slice(), 0.0) else {
        return Outcome::Lost("no trim at P0 = 0");
    };
    if da.abs() > 1e-9 {
        return Outcome::Lost(
            "the trim at P0 = 0 needs aileron (n_p or delta_r break the symmetry)",
        );
    }
    let (mut p, mut dir, mut slope) = (0.0f64, 1.0f64, 0.0f64);
    let sign_det_a = det_a.eval(0.0, 0.0).signum();
    for _ in 0..MAX_STEPS {
        let h = max_step.min(max_step / slope.abs().max(1e-300)).max(1e-10);
        let p_new = p + dir * h;
        let roots = g.aileron_roots(p_new);
        let Some(da_new) = nearest(roots.as_slice(), da + slope * dir * h) else {
            // The two trims of this roll rate merged and vanished: the curve turns in P0 and
            // continues on the other root, P0 running back.
            dir = -dir;
            let back = g.aileron_roots(p);
            match back
                .into_iter()
                .filter(|r| (r - da).abs() > 0.0)
                .min_by(|a, b| (a - da).abs().total_cmp(&(b - da).abs()))
            {
                Some(other) => {
                    slope = 0.0;
                    da = other;
                    continue;
                }
                None => return Outcome::Lost("the equilibrium curve ends"),
            }
        };
        // A jump root between p and p_new whose aileron is this branch's.
        let (lo, hi) = if p < p_new { (p, p_new) } else { (p_new, p) };
        let diverges = divergence.iter().any(|d| *d > lo && *d <= hi);
        if diverges || det_a.eval(p_new, 0.0).signum() != sign_det_a {
            return Outcome::Divergence(p_new);
        }
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
            return Outcome::Jump(i);
        }
        if da_new.abs() > max_abs_delta_a {
            return Outcome::Unbounded;
        }
        slope = (da_new - da) / (dir * h);
        da = da_new;
        p = p_new;
    }
    Outcome::Lost("the primary branch was followed for 2e6 steps without an end")
}
