//! What an evaluation of one setup (a model at one flight condition, its surfaces and the
//! user's settings) sets the same at every flight state: the model's metrics and weight, the
//! system outputs zeroed (the clean power-off configuration), and each property name resolved
//! to what it sets. A trim evaluates the coefficients hundreds of times at one condition; each
//! evaluation then starts from a copy of this one and looks no name up.

use super::condition::{flight_values, set_state, Condition, Motion, State, FLIGHT_VALUES};
use super::evaluate::{Env, Target};
use super::model::Model;
use super::surfaces::Surface;

/// JSBSim's name of the previous step's lift coefficient squared, which some models read.
pub const CL_SQUARED: &str = "aero/cl-squared";

/// The fixed part of a setup's evaluations.
pub struct Fixed<'m> {
    /// The evaluation with the metrics, the weight and the zeroed system outputs set.
    base: Env<'m>,
    /// The names of the zeroed system outputs, as [`set_state`] gives them.
    pub zeroed: Vec<String>,
    /// What each of [`flight_values`] sets.
    flight: [Option<Target>; FLIGHT_VALUES],
    /// What each form of each surface sets, in the order of [`Surface::values`].
    surfaces: Vec<Vec<Option<Target>>>,
    /// What each setting sets.
    settings: Vec<Option<Target>>,
    /// What [`CL_SQUARED`] sets, if the model reads it.
    pub cl_squared: Option<Target>,
    /// The centre of gravity as loaded (inches, structural frame), about which the moments are
    /// taken.
    pub cg: [f64; 3],
}

impl<'m> Fixed<'m> {
    /// The fixed part of the evaluations of `model` at `condition` with `surfaces` and
    /// `settings`. Which names a state sets does not depend on the state (every flight-state
    /// property, every form of a surface the model gives, every setting), so neither do the
    /// system outputs left unset, which [`set_state`] zeroes.
    pub fn new(
        model: &'m Model,
        condition: &Condition,
        surfaces: &[Surface],
        settings: &[(String, f64)],
    ) -> Fixed<'m> {
        let mut base = model.environment();
        let state = State {
            alpha: 0.0,
            beta: 0.0,
            rates: [0.0; 3],
            surfaces: [0.0; 3],
        };
        let mut probe = model.environment();
        let zeroed =
            set_state(&mut probe, model, condition, &state, surfaces, settings).unwrap_or_default();
        for name in &zeroed {
            base.set(name, 0.0);
        }
        let names = flight_values(model, condition, &state, &Motion::QUASI_STEADY);
        Fixed {
            flight: names.map(|(name, _)| base.target(name)),
            surfaces: surfaces
                .iter()
                .map(|s| s.values(0.0).iter().map(|(n, _)| base.target(n)).collect())
                .collect(),
            settings: settings.iter().map(|(n, _)| base.target(n)).collect(),
            cl_squared: base.target(CL_SQUARED),
            cg: model.totals().cg,
            zeroed,
            base,
        }
    }

    /// The evaluation of `state` at `condition` with `surfaces` and `settings` (those this was
    /// made with) and the lift coefficient squared `cl2`: every input set as [`set_state`]
    /// sets it, in the same order.
    pub fn env(
        &self,
        (model, condition): (&Model, &Condition),
        state: &State,
        (surfaces, settings): (&[Surface], &[(String, f64)]),
        cl2: f64,
    ) -> Env<'m> {
        let mut env = self.base.clone();
        let values = flight_values(model, condition, state, &Motion::QUASI_STEADY);
        for (t, (_, v)) in self.flight.iter().zip(values) {
            if let Some(t) = t {
                env.set_target(*t, v);
            }
        }
        for ((s, x), targets) in surfaces.iter().zip(state.surfaces).zip(&self.surfaces) {
            for ((_, value), t) in s.values(x).into_iter().zip(targets) {
                if let (Some(v), Some(t)) = (value, t) {
                    env.set_target(*t, v);
                }
            }
        }
        for ((_, v), t) in settings.iter().zip(&self.settings) {
            if let Some(t) = t {
                env.set_target(*t, *v);
            }
        }
        if let Some(t) = self.cl_squared {
            env.set_target(t, cl2);
        }
        env
    }
}
