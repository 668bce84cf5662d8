//! The forces and moments of a JSBSim model at a state of the 6-DOF: the import's evaluation
//! ([`crate::jsbsim::condition::set_state`] for what stays fixed over a run, the surfaces, the
//! settings and the zeroed system outputs; [`crate::jsbsim::condition::flight_values`] for the
//! flight state; [`crate::jsbsim::aerodynamics::Aerodynamics::loads`] for the sums and the
//! moment transfer to the CG), with each flight-state property's name resolved once, so that a
//! step looks no name up.

use crate::jsbsim::aerodynamics::Loads;
use crate::jsbsim::coefficients::place;
use crate::jsbsim::condition::{
    flight_values, set_state, Condition, Motion, State as Flight, FLIGHT_VALUES,
};
use crate::jsbsim::error::JsbsimError;
use crate::jsbsim::evaluate::{Env, Functions, Target};
use crate::jsbsim::fixed::CL_SQUARED;
use crate::jsbsim::function::{Expr, PropertyRef};
use crate::jsbsim::model::Model;
use crate::jsbsim::surfaces::Surface;

/// The airframe of a run: the model, what stays fixed, and its evaluation.
pub struct Airframe<'m> {
    model: &'m Model,
    /// The evaluation with the fixed inputs set.
    base: Env<'m>,
    /// The evaluation of the current step.
    env: Env<'m>,
    /// What each of [`flight_values`] sets.
    targets: [Option<Target>; FLIGHT_VALUES],
    /// What `aero/cl-squared` sets, if the model reads it.
    cl_squared: Option<Target>,
    /// The CG, inches, structural frame.
    cg: [f64; 3],
}

impl<'m> Airframe<'m> {
    /// The airframe of `model` with `surfaces` set by `start.surfaces` (held for the run) and the
    /// user's `settings`, at the flight state `start` at `condition` (which names the inputs).
    pub fn new(
        model: &'m Model,
        (condition, start): (&Condition, &Flight),
        surfaces: &[Surface],
        settings: &[(String, f64)],
    ) -> Result<Airframe<'m>, JsbsimError> {
        let mut base = model.environment();
        set_state(&mut base, model, condition, start, surfaces, settings)?;
        let names = flight_values(model, condition, start, &Motion::QUASI_STEADY);
        let targets = names.map(|(name, _)| base.target(name));
        let cl_squared = base.target(CL_SQUARED);
        let varying = varying_functions(&model.functions, targets.iter().chain([&cl_squared]));
        for (f, v) in varying.iter().enumerate() {
            if !v {
                // An error here is met again, and reported, at the first step.
                let _ = base.function(f);
            }
        }
        let mut env = model.environment();
        env.record_clamps(false);
        Ok(Airframe {
            model,
            base,
            env,
            targets,
            cl_squared,
            cg: model.totals().cg,
        })
    }

    /// Forces and moments about the CG (body axes, lbs and lbs ft) at `flight` and `motion` at
    /// `condition`, with the lift coefficient squared `cl2` where the model reads it; a value
    /// that is not finite is an error naming the flight state.
    pub fn loads(
        &mut self,
        condition: &Condition,
        flight: &Flight,
        motion: &Motion,
        cl2: f64,
    ) -> Result<Loads, JsbsimError> {
        self.env.reset_to(&self.base);
        let values = flight_values(self.model, condition, flight, motion);
        for (t, (_, v)) in self.targets.iter().zip(values) {
            if let Some(t) = t {
                self.env.set_target(*t, v);
            }
        }
        if let Some(t) = self.cl_squared {
            self.env.set_target(t, cl2);
        }
        let m = &self.model.metrics;
        let loads = self.model.aero.loads(
            &mut self.env,
            (flight.alpha, flight.beta),
            self.cg,
            m.aero_rp,
            m.chord,
        )?;
        if loads
            .force
            .iter()
            .chain(&loads.moment)
            .all(|v| v.is_finite())
        {
            return Ok(loads);
        }
        Err(JsbsimError::new(
            &self.model.file,
            0,
            "aerodynamics",
            format!(
                "the forces and moments are not finite at {}: force {:?} lbs, moment {:?} lbs ft \
                 (expected finite values)",
                place(condition, flight),
                loads.force,
                loads.moment
            ),
        ))
    }

    /// The model.
    pub fn model(&self) -> &'m Model {
        self.model
    }
}

/// Which of `functions` read, directly or through others, a property that `targets` set at
/// every step (a function set itself counts): the others are evaluated once per run.
fn varying_functions<'a>(
    functions: &Functions,
    targets: impl Iterator<Item = &'a Option<Target>>,
) -> Vec<bool> {
    let mut inputs = vec![false; functions.symbols.len()];
    // None: not yet known; Some(true) also while being visited (a loop counts as varying).
    let mut memo: Vec<Option<bool>> = vec![None; functions.list.len()];
    for t in targets.flatten() {
        match *t {
            Target::Input(s) => inputs[s] = true,
            Target::Function(f) => memo[f] = Some(true),
        }
    }
    for f in 0..functions.list.len() {
        function_varies(functions, &inputs, &mut memo, f);
    }
    memo.into_iter().map(|v| v.unwrap_or(true)).collect()
}

/// Whether function `f` varies (see [`varying_functions`]).
fn function_varies(
    functions: &Functions,
    inputs: &[bool],
    memo: &mut [Option<bool>],
    f: usize,
) -> bool {
    if let Some(v) = memo[f] {
        return v;
    }
    memo[f] = Some(true);
    let v = expr_varies(functions, inputs, memo, &functions.list[f].expr);
    memo[f] = Some(v);
    v
}

/// Whether expression `e` varies (see [`varying_functions`]).
fn expr_varies(
    functions: &Functions,
    inputs: &[bool],
    memo: &mut [Option<bool>],
    e: &Expr,
) -> bool {
    let property = |r: &PropertyRef, memo: &mut [Option<bool>]| match functions.defined_by[r.symbol]
    {
        Some(f) => function_varies(functions, inputs, memo, f),
        None => inputs[r.symbol],
    };
    match e {
        Expr::Value(_) => false,
        Expr::Property(r) => property(r, memo),
        Expr::Table(t) => t.keys.iter().any(|r| property(r, memo)),
        Expr::Apply(_, args) => args.iter().any(|a| expr_varies(functions, inputs, memo, a)),
    }
}

/// The lift coefficient of `loads` at angle of attack `alpha` and dynamic pressure
/// `qbar_area` (psf times the wing area): the lift (wind axes, up) over qbar S.
pub fn lift_coefficient(loads: &Loads, alpha: f64, qbar_area: f64) -> f64 {
    let f = loads.force;
    (alpha.sin() * f[0] - alpha.cos() * f[2]) / qbar_area
}
