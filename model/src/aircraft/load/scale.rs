//! The conversion factors of a nondimensional body-axis file, checked before the derivatives.
//!
//! Each derivative is a coefficient times a factor of the flight condition, geometry and
//! inertia (docs/nondimensional.md): rho V S / (2 m) for z_alpha and y_beta,
//! rho V^2 S b / (2 ix') for the static roll derivatives, and so on. A factor outside the normal
//! range of f64 makes every derivative it scales vanish, lose its digits or overflow whatever
//! the coefficients are (a speed of 1e-160 m/s takes l_delta_a to 0), so it is refused naming
//! the input that pushes it out of range (the one whose power contributes most in that
//! direction), not a coefficient. A coefficient that takes its derivative beyond f64 with its
//! factor in range is refused naming the coefficient.

use super::{qualified, shorten, AircraftError, BodyAxisTables, Cx, Table};
use crate::aircraft::convert::{BodyAxisInput, Coefficient, Converted, Density};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

/// An input of the conversion factors.
#[derive(Clone, Copy)]
enum Input {
    Speed,
    /// The air density, given or of the ISA altitude.
    Rho,
    WingArea,
    Span,
    Chord,
    Mass,
    /// The principal moment ix'.
    Ix,
    Iy,
    /// The principal moment iz'.
    Iz,
}

/// One conversion factor, per unit coefficient: the product of `powers` over `divisor`.
struct Factor {
    formula: &'static str,
    divisor: f64,
    powers: &'static [(Input, i32)],
}

use Input::{Chord, Ix, Iy, Iz, Mass, Rho, Span, Speed, WingArea};

static FORCE: Factor = Factor {
    formula: "rho V S / (2 m)",
    divisor: 2.0,
    powers: &[(Rho, 1), (Speed, 1), (WingArea, 1), (Mass, -1)],
};
static ROLL: Factor = Factor {
    formula: "rho V^2 S b / (2 ix')",
    divisor: 2.0,
    powers: &[(Rho, 1), (Speed, 2), (WingArea, 1), (Span, 1), (Ix, -1)],
};
static ROLL_RATE: Factor = Factor {
    formula: "rho V S b^2 / (4 ix')",
    divisor: 4.0,
    powers: &[(Rho, 1), (Speed, 1), (WingArea, 1), (Span, 2), (Ix, -1)],
};
static PITCH: Factor = Factor {
    formula: "rho V^2 S c / (2 iy)",
    divisor: 2.0,
    powers: &[(Rho, 1), (Speed, 2), (WingArea, 1), (Chord, 1), (Iy, -1)],
};
static PITCH_RATE: Factor = Factor {
    formula: "rho V S c^2 / (4 iy)",
    divisor: 4.0,
    powers: &[(Rho, 1), (Speed, 1), (WingArea, 1), (Chord, 2), (Iy, -1)],
};
static YAW: Factor = Factor {
    formula: "rho V^2 S b / (2 iz')",
    divisor: 2.0,
    powers: &[(Rho, 1), (Speed, 2), (WingArea, 1), (Span, 1), (Iz, -1)],
};
static YAW_RATE: Factor = Factor {
    formula: "rho V S b^2 / (4 iz')",
    divisor: 4.0,
    powers: &[(Rho, 1), (Speed, 1), (WingArea, 1), (Span, 2), (Iz, -1)],
};

/// The factor that scales coefficient `c` into its derivative (in body axes; the rotation to
/// principal axes mixes factors of one size).
fn factor(c: Coefficient) -> &'static Factor {
    use Coefficient::*;
    match c {
        CLAlpha | CYBeta => &FORCE,
        ClBeta | ClDeltaA | ClDeltaR => &ROLL,
        ClP | ClR => &ROLL_RATE,
        CmAlpha | CmDeltaE => &PITCH,
        CmQ => &PITCH_RATE,
        CnBeta | CnDeltaA | CnDeltaR => &YAW,
        CnP | CnR => &YAW_RATE,
    }
}

/// Which way a factor or derivative leaves the normal range of f64.
#[derive(Clone, Copy, PartialEq)]
enum Out {
    Under,
    Over,
}

fn out_of_range(log10: f64) -> Option<Out> {
    if log10 < f64::MIN_POSITIVE.log10() {
        Some(Out::Under)
    } else if log10 > f64::MAX.log10() {
        Some(Out::Over)
    } else {
        None
    }
}

impl Cx<'_> {
    /// Refuses a conversion factor outside the normal range of f64, naming the input that
    /// pushes it out, and a coefficient whose derivative its factor takes beyond f64.
    pub(super) fn conversion_factors(
        &self,
        body: &BodyAxisInput,
        converted: &Converted,
        tables: &BodyAxisTables<'_, '_>,
    ) -> Result<(), AircraftError> {
        for c in Coefficient::ALL {
            let f = factor(c);
            let terms: Vec<(Input, f64)> = f
                .powers
                .iter()
                .map(|&(input, power)| (input, f64::from(power) * log10(input, body, converted)))
                .collect();
            let total = terms.iter().map(|(_, t)| t).sum::<f64>() - f.divisor.log10();
            if let Some(out) = out_of_range(total) {
                let by = |a: &&(Input, f64), b: &&(Input, f64)| a.1.total_cmp(&b.1);
                let culprit = match out {
                    Out::Under => terms.iter().min_by(by),
                    Out::Over => terms.iter().max_by(by),
                };
                if let Some(&(input, _)) = culprit {
                    return Err(self.factor_error(input, f, total, out, body, tables));
                }
            }
            let coefficient = body.coefficient(c);
            if !coefficient.is_zero()
                && out_of_range(total + log10_positive(&coefficient.abs())) == Some(Out::Over)
            {
                return Err(self.coefficient_error(c, f, total, tables.coefficients));
            }
        }
        Ok(())
    }

    fn factor_error(
        &self,
        input: Input,
        f: &Factor,
        log10: f64,
        out: Out,
        body: &BodyAxisInput,
        tables: &BodyAxisTables<'_, '_>,
    ) -> AircraftError {
        let (table, key, what) = place(input, body, tables);
        let direction = match out {
            Out::Under => "underflows (the smallest normal double is 2.2e-308)",
            Out::Over => "overflows (the largest double is 1.8e308)",
        };
        let (at, value) = match table.get(key) {
            Some((k, v)) => (self.at_value(k, v), self.written(v)),
            None => (self.at(table.span.as_ref()), String::new()),
        };
        AircraftError::InvalidValue {
            at,
            key: qualified(table.name, key),
            expected: format!(
                "{what} at which the conversion to dimensional derivatives stays within the \
                 normal range of f64: here {} = {} per unit coefficient {direction}; check the \
                 units of `[flight]`, `[geometry]` and `[inertia]`",
                f.formula,
                scientific(log10)
            ),
            value: shorten(&value),
        }
    }

    fn coefficient_error(
        &self,
        c: Coefficient,
        f: &Factor,
        log10: f64,
        coefficients: &Table<'_>,
    ) -> AircraftError {
        let (at, value) = match coefficients.get(c.key()) {
            Some((k, v)) => (self.at_value(k, v), self.written(v)),
            None => (self.at(coefficients.span.as_ref()), String::new()),
        };
        let derivative = c.derivative().key();
        AircraftError::InvalidValue {
            at,
            key: qualified(coefficients.name, c.key()),
            expected: format!(
                "a coefficient per rad whose derivative {derivative} stays within the range of \
                 f64 (magnitude at most 1.8e308): {} = {} per unit coefficient",
                f.formula,
                scientific(log10)
            ),
            value: shorten(&value),
        }
    }
}

/// The table, key and description of an input, for messages.
fn place<'t, 'n>(
    input: Input,
    body: &BodyAxisInput,
    tables: &BodyAxisTables<'t, 'n>,
) -> (&'t Table<'n>, &'static str, &'static str) {
    let moment = "a body-axis moment of inertia in kg m^2 > 0";
    match input {
        Speed => (tables.flight, "speed", "a speed in m/s > 0"),
        Rho => match body.density {
            Density::Given(_) => (tables.flight, "density", "a density in kg/m^3 > 0"),
            Density::Altitude(_) => (tables.flight, "altitude", "an ISA altitude in m"),
        },
        WingArea => (tables.geometry, "wing_area", "a wing area in m^2 > 0"),
        Span => (tables.geometry, "span", "a wing span in m > 0"),
        Chord => (
            tables.geometry,
            "chord",
            "a mean aerodynamic chord in m > 0",
        ),
        Mass => (tables.geometry, "mass", "a mass in kg > 0"),
        Ix => (tables.inertia, "ix", moment),
        Iy => (tables.inertia, "iy", moment),
        Iz => (tables.inertia, "iz", moment),
    }
}

/// log10 of an input (every input is > 0 once loaded), exact beyond the range of f64.
fn log10(input: Input, body: &BodyAxisInput, converted: &Converted) -> f64 {
    let value = match input {
        Speed => &body.speed,
        Rho => match &body.density {
            Density::Given(rho) => rho,
            Density::Altitude(_) => return converted.density.log10(),
        },
        WingArea => &body.wing_area,
        Span => &body.span,
        Chord => &body.chord,
        Mass => &body.mass,
        Ix => &converted.principal[0],
        Iy => &converted.principal[1],
        Iz => &converted.principal[2],
    };
    log10_positive(value)
}

/// log10 of a rational > 0, from its numerator and denominator (each may lie beyond f64).
fn log10_positive(q: &BigRational) -> f64 {
    log10_integer(q.numer()) - log10_integer(q.denom())
}

fn log10_integer(n: &BigInt) -> f64 {
    let shift = n.bits().saturating_sub(64);
    let top = (n.abs() >> shift).to_f64().unwrap_or(f64::NAN);
    top.log10() + shift as f64 * std::f64::consts::LOG10_2
}

/// `10^log10` as `m.me±e`, also beyond the range of f64.
fn scientific(log10: f64) -> String {
    let mut exponent = log10.floor();
    let mut mantissa = (10f64.powf(log10 - exponent) * 10.0).round() / 10.0;
    if mantissa >= 10.0 {
        mantissa /= 10.0;
        exponent += 1.0;
    }
    format!("{mantissa}e{exponent}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn logarithms_and_scientific_notation_reach_beyond_f64() {
        let q = |s: &str| crate::aircraft::decimal_to_rational(s).unwrap();
        assert!((log10_positive(&q("1e-320")) + 320.0).abs() < 1e-9);
        assert!((log10_positive(&q("6e400")) - 400.778_151_250_383_6).abs() < 1e-9);
        assert_eq!(scientific(log10_positive(&q("6e-321"))), "6e-321");
        let huge = q("1.26e300") * q("1e300");
        assert_eq!(scientific(log10_positive(&huge)), "1.3e600");
        assert_eq!(scientific(2.0_f64.log10()), "2e0");
    }
}
