//! The right-hand sides integrated (the PSS model of Appendix A.2 and the 7th-order model of
//! Appendix A.1 with its gravity terms) with the control inputs as functions of time, and the
//! Dopri5 integration over the segments of a run, sampled from its dense output.

use super::attitude::{euler, gravity_rate};
use super::{Aileron, Model, Rudder, RunStats, SimError, Simulator, Tolerances};
use crate::equations::gravity_and_attitude;
use crate::pss_model::{Controls, PssModel};
use ode_solvers::continuous_output_model::ContinuousOutputModel;
use ode_solvers::{Dopri5, SVector, System};

/// The control inputs as functions of time.
pub(super) struct Inputs<'a> {
    sim: &'a Simulator,
    aileron: Aileron,
    rudder: Rudder,
    /// The rudder when it is constant for t > 0 (fixed, or scheduled with a step aileron).
    rudder_after_step: Option<f64>,
}

impl<'a> Inputs<'a> {
    pub(super) fn new(
        sim: &'a Simulator,
        aileron: Aileron,
        rudder: Rudder,
    ) -> Result<Inputs<'a>, SimError> {
        // Check the schedule covers the final deflection (a ramp stays between 0 and it).
        let last = sim.rudder_at(rudder, aileron.final_value())?;
        let rudder_after_step = match (rudder, aileron) {
            (Rudder::Fixed(v), _) => Some(v),
            (Rudder::ZeroSideslip, Aileron::Step { .. }) => Some(last),
            (Rudder::ZeroSideslip, Aileron::Ramp { .. }) => None,
        };
        Ok(Inputs {
            sim,
            aileron,
            rudder,
            rudder_after_step,
        })
    }

    pub(super) fn controls(&self, t: f64) -> Controls {
        let delta_a = self.aileron.at(t);
        // Inside a ramp the schedule is defined (checked in `new`); NaN would fail the
        // integration loudly rather than silently.
        let delta_r = match self.rudder_after_step {
            Some(v) => v,
            None => self.sim.rudder_at(self.rudder, delta_a).unwrap_or(f64::NAN),
        };
        Controls {
            delta_a,
            delta_e: self.sim.trims.delta_e(),
            delta_r,
        }
    }
}

/// The PSS model (Appendix A.2), state [alpha, beta, p, q, r].
pub(super) struct PssSystem<'a> {
    pub(super) model: &'a PssModel,
    pub(super) inputs: &'a Inputs<'a>,
}

impl System<f64, SVector<f64, 5>> for PssSystem<'_> {
    fn system(&self, t: f64, y: &SVector<f64, 5>, dy: &mut SVector<f64, 5>) {
        let x = [y[0], y[1], y[2], y[3], y[4]];
        let f = self.model.rhs(&x, &self.inputs.controls(t));
        dy.copy_from_slice(&f);
    }
}

/// The 7th-order model (Appendix A.1), state [alpha, beta, p, q, r, gamma_x, gamma_y, gamma_z]
/// with gamma the direction of gravity in body axes.
pub(super) struct FullSystem<'a> {
    pub(super) model: &'a PssModel,
    pub(super) inputs: &'a Inputs<'a>,
    pub(super) speed: f64,
}

impl System<f64, SVector<f64, 8>> for FullSystem<'_> {
    fn system(&self, t: f64, y: &SVector<f64, 8>, dy: &mut SVector<f64, 8>) {
        let x = [y[0], y[1], y[2], y[3], y[4]];
        let f = self.model.rhs(&x, &self.inputs.controls(t));
        let gamma = [y[5], y[6], y[7]];
        let (phi, theta) = euler(&gamma);
        let (d_alpha, d_beta, _, _) =
            gravity_and_attitude(self.speed, x[2], x[3], x[4], phi, theta);
        dy[0] = f[0] + d_alpha;
        dy[1] = f[1] + d_beta;
        dy[2] = f[2];
        dy[3] = f[3];
        dy[4] = f[4];
        let g = gravity_rate(&gamma, x[2], x[3], x[4]);
        dy[5] = g[0];
        dy[6] = g[1];
        dy[7] = g[2];
    }
}

/// The samples as columns, one vector per state component.
pub(super) fn columns<const N: usize>(y: &[SVector<f64, N>]) -> Vec<Vec<f64>> {
    (0..N).map(|i| y.iter().map(|v| v[i]).collect()).collect()
}

/// Integrates over the segments `breaks[0]..breaks[1]..` and samples the continuous output at
/// the times `t`.
pub(super) fn integrate<const N: usize, S>(
    make: impl Fn() -> S,
    y0: SVector<f64, N>,
    breaks: &[f64],
    t: &[f64],
    tol: &Tolerances,
    model: Model,
) -> Result<(Vec<SVector<f64, N>>, RunStats), SimError>
where
    S: System<f64, SVector<f64, N>>,
{
    let mut out = Vec::with_capacity(t.len());
    let mut stats = RunStats::default();
    let mut y = y0;
    let mut k = 0;
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        let mut solver = Dopri5::new(make(), a, b, b - a, y, tol.rtol, tol.atol);
        let mut dense = ContinuousOutputModel::new();
        let fail = |t: f64, message: String| SimError::Integration {
            model: model.name(),
            t,
            message,
        };
        let st = solver
            .integrate_with_continuous_output_model(&mut dense)
            .map_err(|e| {
                // The time the integrator stopped at, not the start of the segment.
                use ode_solvers::dop_shared::IntegrationError as E;
                let at = match e {
                    E::MaxNumStepReached { x, .. }
                    | E::StepSizeUnderflow { x }
                    | E::StiffnessDetected { x } => x,
                };
                fail(at, e.to_string())
            })?;
        stats.evaluations += st.num_eval;
        stats.accepted += st.accepted_steps;
        stats.rejected += st.rejected_steps;
        let last = b == breaks[breaks.len() - 1];
        while k < t.len() && (t[k] < b || (last && t[k] <= b)) {
            let v = dense
                .evaluate(t[k].max(a))
                .ok_or_else(|| fail(t[k], "no dense output".into()))?;
            if v.iter().any(|x| !x.is_finite()) {
                return Err(fail(t[k], "the state is no longer finite".into()));
            }
            out.push(v);
            k += 1;
        }
        y = solver
            .y_out()
            .last()
            .copied()
            .ok_or_else(|| fail(b, "no final state".into()))?;
    }
    Ok((out, stats))
}
