//! The aerodynamic coefficients of a model at one flight state: lift, drag and side force, and
//! the body-axis moments about the centre of gravity, made nondimensional with qbar, S, b and c.
//! Where the aerodynamics read `aero/cl-squared` (JSBSim feeds back the previous step's lift),
//! the lift is iterated to its fixed point, the quasi-steady value. A function that is not
//! finite at the state is refused ([`super::finite`]); the table lookups beyond a table's
//! breakpoints are kept with the coefficients ([`super::clamp`]).

use super::clamp::Clamp;
use super::condition::{Condition, State};
use super::digits::short;
use super::error::JsbsimError;
use super::evaluate::Env;
use super::fixed::{Fixed, CL_SQUARED};
use super::model::Model;
use super::surfaces::Surface;
use std::sync::OnceLock;

/// Coefficients at one state, with each axis function's value.
#[derive(Clone, Debug, PartialEq)]
pub struct Coefficients {
    /// CL, CD, CY (body y), Cl, Cm, Cn (body axes about the CG).
    pub values: [f64; 6],
    /// Each axis function's value (in the model's term order).
    pub terms: Vec<f64>,
    /// The inputs set to zero (clean configuration).
    pub zeroed: Vec<String>,
    /// The table lookups beyond a table's breakpoints, one per table and variable.
    pub clamps: Vec<Clamp>,
}

/// Index of CL in [`Coefficients::values`].
pub const CL: usize = 0;
/// Index of CD.
pub const CD: usize = 1;
/// Index of CY.
pub const CY: usize = 2;
/// Index of Cl (rolling moment).
pub const CROLL: usize = 3;
/// Index of Cm.
pub const CM: usize = 4;
/// Index of Cn.
pub const CN: usize = 5;
/// Their names.
pub const NAMES: [&str; 6] = ["CL", "CD", "CY", "Cl", "Cm", "Cn"];

/// Everything an evaluation needs besides the state.
pub struct Setup<'a> {
    /// The model.
    pub model: &'a Model,
    /// Altitude, speed and air.
    pub condition: Condition,
    /// The surfaces and how they are set.
    pub surfaces: Vec<Surface>,
    /// The user's `--set` values.
    pub settings: Vec<(String, f64)>,
    /// What every evaluation sets the same, made at the first.
    fixed: OnceLock<Fixed<'a>>,
}

impl<'a> Setup<'a> {
    /// The setup of `model` at `condition` with `surfaces` and the user's `settings`.
    pub fn new(
        model: &'a Model,
        condition: Condition,
        surfaces: Vec<Surface>,
        settings: Vec<(String, f64)>,
    ) -> Setup<'a> {
        Setup {
            model,
            condition,
            surfaces,
            settings,
            fixed: OnceLock::new(),
        }
    }

    /// What every evaluation of this setup sets the same, made at the first.
    fn fixed(&self) -> &Fixed<'a> {
        self.fixed
            .get_or_init(|| Fixed::new(self.model, &self.condition, &self.surfaces, &self.settings))
    }

    /// The coefficients at `state`.
    pub fn coefficients(&self, state: &State) -> Result<Coefficients, JsbsimError> {
        let fixed = self.fixed();
        let mut last = None;
        self.fixed_point(|cl2| {
            let mut env = self.env(fixed, state, cl2);
            let zeroed = fixed.zeroed.clone();
            let values = self.evaluate(&mut env, (state, fixed.cg), &zeroed)?;
            let terms = self
                .model
                .aero
                .terms
                .iter()
                .map(|t| env.function(t.function))
                .collect::<Result<Vec<_>, _>>()?;
            last = Some(Coefficients {
                values,
                terms,
                zeroed,
                clamps: env.clamps().to_vec(),
            });
            Ok(values)
        })?;
        Ok(last.expect("at least one evaluation"))
    }

    /// The evaluations of this setup at a sequence of states, each computing again only the
    /// functions that read what changed since the previous one: the trim's.
    pub fn sequence(&self) -> Sequence<'_, 'a> {
        Sequence {
            setup: self,
            previous: None,
            stale: Vec::new(),
        }
    }

    /// The evaluation of `state` with the lift coefficient squared `cl2`.
    fn env(&self, fixed: &Fixed<'a>, state: &State, cl2: f64) -> Env<'a> {
        fixed.env(
            (self.model, &self.condition),
            state,
            (&self.surfaces, &self.settings),
            cl2,
        )
    }

    /// The coefficients `evaluate` gives, with the lift coefficient squared that the model
    /// reads at its fixed point: where the aerodynamics read `aero/cl-squared`, evaluated again
    /// until it is the square of the lift coefficient found (at most 60 times).
    fn fixed_point(
        &self,
        mut evaluate: impl FnMut(f64) -> Result<[f64; 6], JsbsimError>,
    ) -> Result<[f64; 6], JsbsimError> {
        let feedback = self.model.functions.symbols.get(CL_SQUARED).is_some();
        let mut cl2 = 0.0;
        let mut last = None;
        for _ in 0..if feedback { 60 } else { 1 } {
            let values = evaluate(cl2)?;
            let next = values[CL] * values[CL];
            let done = (next - cl2).abs() <= 1e-15 * next.max(1.0);
            cl2 = next;
            last = Some(values);
            if done {
                break;
            }
        }
        Ok(last.expect("at least one evaluation"))
    }

    /// The coefficients of `env` (every input set for `state`), the moments about `cg` (the
    /// model's as loaded), refused when not finite.
    fn evaluate(
        &self,
        env: &mut Env,
        (state, cg): (&State, [f64; 3]),
        zeroed: &[String],
    ) -> Result<[f64; 6], JsbsimError> {
        let metrics = &self.model.metrics;
        let angles = (state.alpha, state.beta);
        let loads = (self.model.aero).loads(env, angles, cg, metrics.aero_rp, metrics.chord)?;
        let values = self.nondimensional(state, loads.force, loads.moment);
        self.refuse_non_finite(env, state, &values, zeroed)?;
        Ok(values)
    }

    /// Refuses an axis function or a coefficient that is not finite at `state`, naming the
    /// function and where its value arose (the coefficients alone are not finite only when the
    /// reference point's shift is not, or the sums overflow).
    fn refuse_non_finite(
        &self,
        env: &mut Env,
        state: &State,
        values: &[f64; 6],
        zeroed: &[String],
    ) -> Result<(), JsbsimError> {
        let place = || place(&self.condition, state);
        let model = self.model;
        for t in &model.aero.terms {
            let v = env.function(t.function)?;
            if !v.is_finite() {
                return Err(super::finite::refusal(env, t.function, v, &place(), zeroed));
            }
        }
        match values.iter().position(|v| !v.is_finite()) {
            None => Ok(()),
            Some(k) => {
                let shift = match &model.aero.rp_shift {
                    Some(e) if !env.eval(e)?.is_finite() => {
                        format!(
                            ": <aero_ref_pt_shift_x>: {}",
                            super::finite::origin(env, e).0
                        )
                    }
                    _ => " (every axis function is finite: their sum overflows)".to_string(),
                };
                Err(JsbsimError::new(
                    &model.file,
                    0,
                    "aerodynamics",
                    format!(
                        "the coefficient {} is {} at {}{shift} (expected a finite value)",
                        NAMES[k],
                        values[k],
                        place()
                    ),
                ))
            }
        }
    }

    /// Body force and moment (lbs, lbs ft) to CL, CD, CY, Cl, Cm, Cn.
    fn nondimensional(&self, state: &State, f: [f64; 3], m: [f64; 3]) -> [f64; 6] {
        let metrics = &self.model.metrics;
        let qs = self.condition.qbar_psf() * metrics.wing_area;
        let (ca, sa, cb, sb) = (
            state.alpha.cos(),
            state.alpha.sin(),
            state.beta.cos(),
            state.beta.sin(),
        );
        // Body to wind axes (the transpose of JSBSim's wind-to-body rotation).
        let wx = ca * cb * f[0] + sb * f[1] + sa * cb * f[2];
        let wz = -sa * f[0] + ca * f[2];
        [
            -wz / qs,
            -wx / qs,
            f[1] / qs,
            m[0] / (qs * metrics.span),
            m[1] / (qs * metrics.chord),
            m[2] / (qs * metrics.span),
        ]
    }
}

/// A setup's evaluations at a sequence of states ([`Setup::sequence`]): the coefficients alone,
/// without the table lookups beyond the breakpoints, each evaluation keeping from the previous
/// one the functions that read nothing it changed ([`Env::keep_from`]).
pub struct Sequence<'s, 'a> {
    setup: &'s Setup<'a>,
    /// The last evaluation that succeeded.
    previous: Option<Env<'a>>,
    stale: Vec<bool>,
}

impl<'s, 'a> Sequence<'s, 'a> {
    /// The setup evaluated.
    pub fn setup(&self) -> &'s Setup<'a> {
        self.setup
    }

    /// [`Coefficients::values`] at `state`, the same numbers and errors as
    /// [`Setup::coefficients`].
    pub fn values(&mut self, state: &State) -> Result<[f64; 6], JsbsimError> {
        let setup = self.setup;
        let fixed = setup.fixed();
        let readers = setup.model.readers();
        setup.fixed_point(|cl2| {
            let mut env = setup.env(fixed, state, cl2);
            env.record_clamps(false);
            if let (Some(previous), Some(readers)) = (self.previous.take(), readers) {
                readers.keep(&mut env, &previous, &mut self.stale);
            }
            let values = setup.evaluate(&mut env, (state, fixed.cg), &fixed.zeroed)?;
            self.previous = Some(env);
            Ok(values)
        })
    }
}

/// Flight state `state` at `condition` in words, for messages: altitude, Mach and alpha, and
/// beta, the rates and the surfaces where they are not zero.
pub fn place(condition: &Condition, state: &State) -> String {
    let mut s = format!(
        "altitude {} m, Mach {}, alpha {} deg",
        short(condition.altitude_m),
        short(condition.mach),
        short(state.alpha.to_degrees())
    );
    if state.beta != 0.0 {
        s += &format!(", beta {} deg", short(state.beta.to_degrees()));
    }
    for (name, v) in ["p", "q", "r"].iter().zip(state.rates) {
        if v != 0.0 {
            s += &format!(", {name} {v:e} rad/s");
        }
    }
    for (name, v) in ["aileron", "elevator", "rudder"].iter().zip(state.surfaces) {
        if v != 0.0 {
            s += &format!(", {name} {v:e}");
        }
    }
    s
}
