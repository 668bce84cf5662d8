//! `model envelope --validate`: the native 6-DOF's verdict at grid points, by the rule of
//! `model validate` ([`mod@crate::six_dof::sweep`], [`crate::six_dof::jump`]). Every point whose
//! criterion predicts a jump within the aileron limit is swept around its critical aileron; a
//! seeded sample of the other analysed points is swept over the top of the stick's travel,
//! where a jump the criterion missed would be met first. The sweeps are short, so that a map of
//! hundreds of points validates in seconds: [`BELOW`] + [`ABOVE`] + 1 steps [`STEP_DEG`] apart,
//! each run [`RUN_S`] s.

use super::map::Envelope;
use super::point::Point;
use crate::jsbsim::condition::{Condition, Speed};
use crate::jsbsim::import::Loaded;
use crate::jsbsim::trim::trim;
use crate::random::Rng;
use crate::six_dof::sweep;
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The seed of the sample: point `k` of the grid is drawn by `Rng::new(SEED + k)`, so the
/// sample is the same whatever the order the points finish in.
pub const SEED: u64 = 45;

/// The steps of a sweep around a predicted jump, below and above the critical aileron (rounded
/// to a step): the jump lies at or past the fold (the step's transient must carry the roll past
/// it; up to 4 deg past in 10-s runs of the F-104), and the rule compares the jump's rise with
/// the sweep's median rise, which the steps below the fold make the primary branch's.
pub const BELOW: usize = 8;
/// See [`BELOW`].
pub const ABOVE: usize = 5;

/// The spacing of the steps, deg: the resolution of the verdict.
pub const STEP_DEG: f64 = 1.0;

/// The length of each run, s (`model validate`'s default).
pub const RUN_S: f64 = 10.0;

/// The top of the sweep of a point without an aileron limit, deg.
const NO_LIMIT_TOP_DEG: f64 = 20.0;

/// The 6-DOF's verdict at a point.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Validation {
    /// Whether the criterion predicts a jump within the aileron limit here (any critical jump
    /// where the model has no limit).
    pub predicted: bool,
    /// The first and last step of the sweep, deg of |delta_a|: around the critical aileron
    /// where a jump is predicted, else up to the aileron limit.
    pub swept_deg: [f64; 2],
    /// Whether the 6-DOF's settled roll rate jumps within the sweep.
    pub jumps: bool,
    /// The two steps the jump lies between, deg; `None` without a jump.
    pub between_deg: Option<[f64; 2]>,
    /// Whether the 6-DOF says what the criterion says: a predicted jump met in the 6-DOF no
    /// earlier than one step before the critical aileron, or no jump where none is predicted.
    pub agrees: bool,
    /// The largest change of Mach over a run of the sweep (the criterion assumes none).
    pub mach_change: f64,
}

/// Whether the criterion predicts a jump within the aileron limit at `p`.
fn predicted(p: &Point) -> bool {
    p.critical.is_some() && p.margin_deg.is_none_or(|m| m >= 0.0)
}

/// The aileron steps of `p`, deg: around the critical aileron where a jump is predicted, else
/// ending at the aileron limit; none below 1 deg.
fn steps(p: &Point) -> Vec<f64> {
    let span = (BELOW + ABOVE) as f64 * STEP_DEG;
    let last = match &p.critical {
        Some(c) if predicted(p) => {
            (c.delta_a_deg.abs() / STEP_DEG).round() * STEP_DEG + ABOVE as f64 * STEP_DEG
        }
        _ => p.aileron_limit_deg.unwrap_or(NO_LIMIT_TOP_DEG),
    };
    let first = (last - span).max(1.0);
    let n = ((last - first) / STEP_DEG + 1e-9).floor() as usize;
    (0..=n).map(|k| first + k as f64 * STEP_DEG).collect()
}

/// Whether point `k` of the grid (`p`) is validated at `sample`: every predicted jump, and the
/// seeded fraction `sample` of the other analysed points.
pub fn chosen(k: usize, p: &Point, sample: f64) -> bool {
    p.route.is_some() && (predicted(p) || Rng::new(SEED + k as u64).unit() < sample)
}

/// The 6-DOF's verdict at `p` of `loaded`, from the trim at its load factor.
pub fn validate_point(loaded: &Loaded, p: &Point) -> Result<Validation, String> {
    let setup = loaded.setup(Condition::new(p.altitude_m, Speed::Mach(p.mach))?);
    let t = trim(&setup, p.load_factor)?;
    let degs = steps(p);
    let s = sweep::sweep(&setup, &t, &degs, RUN_S)?;
    let between = s.jump.map(|j| [j.between_deg.0, j.between_deg.1]);
    let agrees = match (&p.critical, between) {
        (Some(c), Some([_, hi])) if predicted(p) => hi >= c.delta_a_deg.abs() - STEP_DEG,
        (_, None) => !predicted(p),
        _ => false,
    };
    Ok(Validation {
        predicted: predicted(p),
        swept_deg: [degs[0], degs[degs.len() - 1]],
        jumps: between.is_some(),
        between_deg: between,
        agrees,
        mach_change: s.drift[2],
    })
}

/// Validates the chosen points of `env` (of `loaded`) with the seeded fraction `sample` of the
/// others; `progress` gets the fraction done (from any thread).
pub fn validate_envelope(
    env: &mut Envelope,
    loaded: &Loaded,
    sample: f64,
    progress: &(dyn Fn(f64) + Sync),
) {
    let picked: Vec<usize> = (0..env.points.len())
        .filter(|&k| chosen(k, &env.points[k], sample))
        .collect();
    let done = AtomicUsize::new(0);
    let verdicts: Vec<(usize, Result<Validation, String>)> = picked
        .par_iter()
        .map(|&k| {
            let v = validate_point(loaded, &env.points[k]);
            let n = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress(n as f64 / picked.len() as f64);
            (k, v)
        })
        .collect();
    for (k, v) in verdicts {
        match v {
            Ok(v) => env.points[k].validation = Some(v),
            Err(e) => env.points[k].validation_error = Some(e),
        }
    }
    env.validate_sample = Some(sample);
}
