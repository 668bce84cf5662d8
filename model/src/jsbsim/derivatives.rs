//! The nondimensional body-axis derivatives of the aircraft file from a model at a flight
//! condition, by central differences of the evaluated coefficients: per rad, rates made
//! nondimensional as p b/(2V), q c/(2V), r b/(2V). A central difference is the mean of the two
//! one-sided slopes, which is the derivative where the coefficient is smooth and the mean slope
//! where it has a kink at the point (an |beta| term, a table breakpoint); the kinks are detected
//! by comparing the one-sided slopes and reported. The step, 1e-6 in each variable, is small
//! enough that no breakpoint of the catalogue's tables (spaced 1e-3 and more) other than one at
//! the point itself falls within it, and large enough that rounding stays near 1e-10.

use super::aerodynamics::Axis;
use super::coefficients::{Coefficients, Setup, CL, CM, CN, CROLL, CY};
use super::condition::State;
use super::error::JsbsimError;

/// The step of the differences.
pub const STEP: f64 = 1e-6;

/// A state variable the derivatives are taken in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variable {
    /// Angle of attack, rad.
    Alpha,
    /// Sideslip, rad.
    Beta,
    /// p b/(2V).
    P,
    /// q c/(2V).
    Q,
    /// r b/(2V).
    R,
    /// Aileron (JSBSim's sign).
    Aileron,
    /// Elevator.
    Elevator,
    /// Rudder.
    Rudder,
}

/// The derivatives of the file: key, coefficient index, variable, and the sign that converts
/// JSBSim's convention to this crate's (positive aileron rolls left here, right in JSBSim).
pub const DERIVATIVES: [(&str, usize, Variable, f64); 15] = [
    ("CL_alpha", CL, Variable::Alpha, 1.0),
    ("CY_beta", CY, Variable::Beta, 1.0),
    ("Cl_beta", CROLL, Variable::Beta, 1.0),
    ("Cl_p", CROLL, Variable::P, 1.0),
    ("Cl_r", CROLL, Variable::R, 1.0),
    ("Cl_delta_a", CROLL, Variable::Aileron, -1.0),
    ("Cl_delta_r", CROLL, Variable::Rudder, 1.0),
    ("Cm_alpha", CM, Variable::Alpha, 1.0),
    ("Cm_q", CM, Variable::Q, 1.0),
    ("Cm_delta_e", CM, Variable::Elevator, 1.0),
    ("Cn_beta", CN, Variable::Beta, 1.0),
    ("Cn_p", CN, Variable::P, 1.0),
    ("Cn_r", CN, Variable::R, 1.0),
    ("Cn_delta_a", CN, Variable::Aileron, -1.0),
    ("Cn_delta_r", CN, Variable::Rudder, 1.0),
];

/// One derivative with where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Derivative {
    /// The file's key.
    pub key: &'static str,
    /// Its value in this crate's convention.
    pub value: f64,
    /// Whether the coefficient has a kink at the point (the one-sided slopes differ).
    pub kink: Option<(f64, f64)>,
    /// The axis functions that change with the variable.
    pub functions: Vec<String>,
}

/// `state` moved by `h` in `variable`.
pub fn moved(setup: &Setup, state: &State, variable: Variable, h: f64) -> State {
    let mut s = *state;
    let v = setup.condition.speed * super::units::FT_PER_M;
    let m = &setup.model.metrics;
    match variable {
        Variable::Alpha => s.alpha += h,
        Variable::Beta => s.beta += h,
        Variable::P => s.rates[0] += h * 2.0 * v / m.span,
        Variable::Q => s.rates[1] += h * 2.0 * v / m.chord,
        Variable::R => s.rates[2] += h * 2.0 * v / m.span,
        Variable::Aileron => s.surfaces[0] += h,
        Variable::Elevator => s.surfaces[1] += h,
        Variable::Rudder => s.surfaces[2] += h,
    }
    s
}

/// Every derivative of [`DERIVATIVES`] at `state`, with the coefficients there.
pub fn derivatives(
    setup: &Setup,
    state: &State,
) -> Result<(Coefficients, Vec<Derivative>), JsbsimError> {
    let base = setup.coefficients(state)?;
    let mut out = Vec::new();
    let mut cache: Vec<(Variable, Coefficients, Coefficients)> = Vec::new();
    for (key, c, variable, sign) in DERIVATIVES {
        if !cache.iter().any(|(v, _, _)| *v == variable) {
            let plus = setup.coefficients(&moved(setup, state, variable, STEP))?;
            let minus = setup.coefficients(&moved(setup, state, variable, -STEP))?;
            cache.push((variable, plus, minus));
        }
        let (_, plus, minus) = cache
            .iter()
            .find(|(v, _, _)| *v == variable)
            .expect("cached");
        let forward = (plus.values[c] - base.values[c]) / STEP;
        let backward = (base.values[c] - minus.values[c]) / STEP;
        let scale = forward.abs().max(backward.abs()).max(1e-3);
        let kink = ((forward - backward).abs() > 1e-4 * scale)
            .then_some((sign * backward, sign * forward));
        let functions = setup
            .model
            .aero
            .terms
            .iter()
            .zip(plus.terms.iter().zip(&minus.terms))
            .filter(|(t, (a, b))| a != b && t.axis == axis_of(c))
            .map(|(t, _)| setup.model.functions.list[t.function].name.clone())
            .collect();
        let value = sign * (forward + backward) / 2.0;
        if !value.is_finite() {
            return Err(JsbsimError::new(
                &setup.model.file,
                0,
                key,
                format!(
                    "the derivative is {value} at {}: the coefficient {} is {:e} there and \
                     {:e} / {:e} a step of {STEP} away (expected finite differences)",
                    super::coefficients::place(&setup.condition, state),
                    super::coefficients::NAMES[c],
                    base.values[c],
                    minus.values[c],
                    plus.values[c]
                ),
            ));
        }
        out.push(Derivative {
            key,
            value,
            kink,
            functions,
        });
    }
    Ok((base, out))
}

/// The axis whose functions make coefficient `c`.
fn axis_of(c: usize) -> Axis {
    match c {
        CL => Axis::Lift,
        CY => Axis::Side,
        CROLL => Axis::Roll,
        CM => Axis::Pitch,
        CN => Axis::Yaw,
        _ => Axis::Drag,
    }
}
