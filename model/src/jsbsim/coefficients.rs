//! The aerodynamic coefficients of a model at one flight state: lift, drag and side force, and
//! the body-axis moments about the centre of gravity, made nondimensional with qbar, S, b and c.
//! Where the aerodynamics read `aero/cl-squared` (JSBSim feeds back the previous step's lift),
//! the lift is iterated to its fixed point, the quasi-steady value.

use super::condition::{set_state, Condition, State};
use super::error::JsbsimError;
use super::model::Model;
use super::surfaces::Surface;

/// Coefficients at one state, with each axis function's value.
#[derive(Clone, Debug, PartialEq)]
pub struct Coefficients {
    /// CL, CD, CY (body y), Cl, Cm, Cn (body axes about the CG).
    pub values: [f64; 6],
    /// Each axis function's value (in the model's term order).
    pub terms: Vec<f64>,
    /// The inputs set to zero (clean configuration).
    pub zeroed: Vec<String>,
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
}

impl Setup<'_> {
    /// The coefficients at `state`.
    pub fn coefficients(&self, state: &State) -> Result<Coefficients, JsbsimError> {
        let model = self.model;
        let feedback = model.functions.symbols.get("aero/cl-squared").is_some();
        let mut cl2 = 0.0;
        let mut last = None;
        for _ in 0..if feedback { 60 } else { 1 } {
            let mut env = model.environment();
            let zeroed = set_state(
                &mut env,
                model,
                &self.condition,
                state,
                &self.surfaces,
                &self.settings,
            )?;
            env.set("aero/cl-squared", cl2);
            let loads = model.loads(&mut env, state.alpha, state.beta)?;
            let terms = model
                .aero
                .terms
                .iter()
                .map(|t| env.function(t.function))
                .collect::<Result<Vec<_>, _>>()?;
            let values = self.nondimensional(state, loads.force, loads.moment);
            let next = values[CL] * values[CL];
            let done = (next - cl2).abs() <= 1e-15 * next.max(1.0);
            cl2 = next;
            last = Some(Coefficients {
                values,
                terms,
                zeroed,
            });
            if done {
                break;
            }
        }
        Ok(last.expect("at least one evaluation"))
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
