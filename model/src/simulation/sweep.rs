//! Jump detection by simulation (section III, Figs 5 and 6): a sweep of aileron steps from the
//! trim at delta_a = 0, the steady (end-of-run) roll rate of each, and where it jumps.

use super::{parallel_map, Model, Rudder, SimError, SimSettings, Simulator, Steady, Tolerances};
use serde::Serialize;

/// A sweep of aileron steps.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SweepSettings {
    /// Model to integrate.
    pub model: Model,
    /// Rudder during the runs.
    pub rudder: Rudder,
    /// Aileron steps, rad, in sweep order: outward from 0 (e.g. 0, -0.25 deg, -0.5 deg, ...).
    pub delta_a: Vec<f64>,
    /// Length of each run, s.
    pub t_end: f64,
    /// Averaging window at the end of each run, s.
    pub window: f64,
    /// Smallest change of the steady roll rate between neighbouring steps that counts as a
    /// jump, rad/s.
    pub jump_threshold: f64,
    /// Bisection between the two steps around the jump until they are this close, rad
    /// (0: no refinement).
    pub refine_tol: f64,
    /// Integrator tolerances.
    pub tolerances: Tolerances,
}

impl SweepSettings {
    /// Default averaging window, s.
    pub const WINDOW: f64 = 5.0;
    /// Default jump threshold, rad/s.
    pub const JUMP_THRESHOLD: f64 = 0.5;
    /// Default refinement, rad (0.01 deg).
    pub const REFINE_TOL: f64 = 0.01 * std::f64::consts::PI / 180.0;

    /// Steps from 0 to `to` (rad, either sign) every `step` (rad, > 0), rudder fixed at 0, runs
    /// of 20 s averaged over the last 5 s, threshold 0.5 rad/s, refined to 0.01 deg.
    pub fn new(model: Model, to: f64, step: f64) -> SweepSettings {
        let n = if step > 0.0 && to.is_finite() {
            (to.abs() / step).round() as usize
        } else {
            0
        };
        let delta_a = (0..=n)
            .map(|k| (k as f64 * step).min(to.abs()) * to.signum())
            .collect();
        SweepSettings {
            model,
            rudder: Rudder::Fixed(0.0),
            delta_a,
            t_end: SimSettings::T_END,
            window: Self::WINDOW,
            jump_threshold: Self::JUMP_THRESHOLD,
            refine_tol: Self::REFINE_TOL,
            tolerances: Tolerances::default(),
        }
    }
}

/// One run of a sweep.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SweepPoint {
    /// Aileron step, rad.
    pub delta_a: f64,
    /// End-of-run values.
    pub steady: Steady,
}

/// A jump of the steady roll rate between two neighbouring aileron steps.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Jump {
    /// Best estimate of the jump's aileron deflection: the midpoint of `before` and `after`, rad.
    pub delta_a: f64,
    /// The last step that stays on the initial branch.
    pub before: SweepPoint,
    /// The first step that jumps.
    pub after: SweepPoint,
}

/// The result of a sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sweep {
    /// Model integrated.
    pub model: Model,
    /// The runs of the grid in sweep order (refinement runs are not included).
    pub points: Vec<SweepPoint>,
    /// The first jump outward from 0, if any.
    pub jump: Option<Jump>,
    /// Number of runs made (grid and refinement).
    pub runs: usize,
}

/// Runs a sweep of aileron steps for `sim`'s aircraft and elevator and finds the jump: the
/// first pair of neighbouring steps whose steady roll rates differ by more than the threshold,
/// refined by bisection (a run counts as not jumped when its steady roll rate is nearer to that
/// of the last grid step before the jump than to that of the first after it).
pub fn jump_sweep(sim: &Simulator, s: &SweepSettings) -> Result<Sweep, SimError> {
    jump_sweep_with_progress(sim, s, &|_| {})
}

/// As [`jump_sweep`], calling `progress(done)` after each run of the grid (for a progress bar;
/// the few refinement runs that follow are not counted).
pub fn jump_sweep_with_progress(
    sim: &Simulator,
    s: &SweepSettings,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Sweep, SimError> {
    for (name, v) in [("window", s.window), ("jump_threshold", s.jump_threshold)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(SimError::NotPositive {
                name,
                value: v,
                extra: "",
            });
        }
    }
    if s.delta_a.len() > super::MAX_SWEEP_RUNS {
        return Err(SimError::TooManyRuns(s.delta_a.len()));
    }
    if !(s.refine_tol.is_finite() && s.refine_tol >= 0.0) {
        return Err(SimError::NotPositive {
            name: "refine_tol",
            value: s.refine_tol,
            extra: " or 0",
        });
    }
    let base = SimSettings {
        model: s.model,
        delta_e: sim.trims().delta_e(),
        aileron: super::Aileron::Step { delta_a: 0.0 },
        rudder: s.rudder,
        t_end: s.t_end,
        dt: SimSettings::DT,
        tolerances: s.tolerances,
    };
    let point = |delta_a: f64| -> Result<SweepPoint, SimError> {
        let run = sim.run(&SimSettings {
            aileron: super::Aileron::Step { delta_a },
            ..base
        })?;
        Ok(SweepPoint {
            delta_a,
            steady: run.steady(s.window),
        })
    };
    let points = parallel_map(&s.delta_a, |d| point(*d), progress)
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
    let mut runs = points.len();
    let first = points
        .windows(2)
        .find(|w| (w[1].steady.p_mean - w[0].steady.p_mean).abs() > s.jump_threshold);
    let jump = match first {
        None => None,
        Some(w) => {
            let (mut before, mut after) = (w[0], w[1]);
            // Fixed references: the grid neighbours' steady roll rates (refinement runs near
            // the fold may still be in transit at the end of the run).
            let (p_before, p_after) = (before.steady.p_mean, after.steady.p_mean);
            while (after.delta_a - before.delta_a).abs() > s.refine_tol {
                let mid = point(0.5 * (before.delta_a + after.delta_a))?;
                runs += 1;
                let p = mid.steady.p_mean;
                if (p - p_before).abs() <= (p - p_after).abs() {
                    before = mid;
                } else {
                    after = mid;
                }
            }
            Some(Jump {
                delta_a: 0.5 * (before.delta_a + after.delta_a),
                before,
                after,
            })
        }
    };
    Ok(Sweep {
        model: s.model,
        points,
        jump,
        runs,
    })
}
