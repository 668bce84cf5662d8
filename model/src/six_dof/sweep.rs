//! A sweep of aileron steps in the 6-DOF from one trim: each step a run of its own from the
//! trim, its settled roll rate the mean |p| over the last [`WINDOW_S`] s (the oracle's
//! `tests/oracle/jsbsim_six_dof.py` measure), and the verdict of the jump rule ([`super::jump`])
//! over the sweep. What `model validate` and `model envelope --validate` judge, and what the
//! tests compare with JSBSim's own sweeps.

use super::history::History;
use super::jump::{find_jump, Jump};
use super::run::{simulate, Settings};
use crate::jsbsim::coefficients::Setup;
use crate::jsbsim::surfaces::Control;
use crate::jsbsim::trim::Trim;
use rayon::prelude::*;

/// The judging window at the end of each run, s.
pub const WINDOW_S: f64 = 2.0;

/// A sweep's settled roll rates and verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The steps, deg of |delta_a| (JSBSim's left aileron stepped to +deg, a roll to the
    /// right; the paper's delta_a is its negative).
    pub aileron_deg: Vec<f64>,
    /// The settled |p| of each step, rad/s.
    pub settled: Vec<f64>,
    /// The jump the rule calls, if any.
    pub jump: Option<Jump>,
    /// The largest change over a run of the sweep of V (m/s), altitude (m) and Mach: how far
    /// the flight state moved from the trim's while the roll was judged.
    pub drift: [f64; 3],
}

/// The mean roll rate over the last `window` s of `h`, rad/s.
pub fn settled(h: &History, window: f64) -> f64 {
    let t_end = h.t.last().copied().unwrap_or(0.0);
    let from = h.t.partition_point(|t| *t < t_end - window - 1e-9);
    let p = &h.p[from..];
    p.iter().sum::<f64>() / p.len().max(1) as f64
}

/// The sweep of `aileron_deg` (ascending, deg of |delta_a|) from `trim` at `setup`'s condition,
/// each run `t_end` s long at 120 Hz with the thrust off; the runs in parallel. Refused for a
/// model that reads its aileron only as normalised travel: its steps have no angle.
pub fn sweep(setup: &Setup, trim: &Trim, aileron_deg: &[f64], t_end: f64) -> Result<Sweep, String> {
    if setup
        .surfaces
        .iter()
        .any(|s| s.control == Control::Aileron && s.per_unit_travel)
    {
        return Err(format!(
            "{}: the aerodynamics read the aileron only as normalised travel, which has no \
             angle to step",
            setup.model.file
        ));
    }
    let runs: Vec<(f64, [f64; 3])> = aileron_deg
        .par_iter()
        .map(|d| {
            let h = simulate(setup, trim, &Settings::step(d.to_radians(), t_end))?;
            let end = h.t.len() - 1;
            let moved = [&h.speed, &h.altitude, &h.mach].map(|v| (v[end] - v[0]).abs());
            Ok((settled(&h, WINDOW_S).abs(), moved))
        })
        .collect::<Result<_, String>>()?;
    let settled: Vec<f64> = runs.iter().map(|r| r.0).collect();
    let drift = runs
        .iter()
        .fold([0.0f64; 3], |acc, r| [0, 1, 2].map(|k| acc[k].max(r.1[k])));
    Ok(Sweep {
        jump: find_jump(aileron_deg, &settled),
        aileron_deg: aileron_deg.to_vec(),
        settled,
        drift,
    })
}
