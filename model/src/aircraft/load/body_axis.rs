//! The nondimensional body-axis format: `[flight]` speed with density or altitude, `[geometry]`,
//! `[inertia]` ix, iy, iz, ixz and `[coefficients]`, read into the input of
//! [`convert`](crate::aircraft::convert), and the aircraft of its conversion checked.

use super::super::convert::{self, BodyAxisInput, Coefficient};
use super::super::{rational_to_f64, Aircraft, Param};
use super::triangle::{moment_text, triangle_violation};
use super::{
    inertia_coefficients, keys_of, list, qualified, AircraftError, Common, Cx, Table, Tables,
    F64_RANGE,
};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// A body-axis file: the aircraft and the conversion it came from (for `convert`).
pub(super) struct BodyAxis {
    pub(super) aircraft: Aircraft,
    pub(super) converted: convert::Converted,
}

/// The four tables of a nondimensional body-axis file.
pub(super) struct BodyAxisTables<'t, 'n> {
    pub(super) flight: &'t Table<'n>,
    pub(super) geometry: &'t Table<'n>,
    pub(super) inertia: &'t Table<'n>,
    pub(super) coefficients: &'t Table<'n>,
}

impl Cx<'_> {
    /// The aircraft of a body-axis file and its conversion: the four tables of the format,
    /// converted and checked, and the optional `[uncertainty]`.
    pub(super) fn body_axis_document(
        &self,
        tables: &Tables<'_, '_>,
        common: Common,
    ) -> Result<BodyAxis, AircraftError> {
        let table = |t: &'static str| {
            tables.required(self, t, format!("`[{t}]` with keys {}", list(&keys_of(t))))
        };
        let format = BodyAxisTables {
            flight: table("flight")?,
            geometry: table("geometry")?,
            inertia: table("inertia")?,
            coefficients: table("coefficients")?,
        };
        let input = self.body_axis(&format)?;
        let converted = convert::convert(&input);
        let aircraft = self.body_axis_aircraft(common.name, &input, &converted, &format)?;
        let uncertainty = match tables.get("uncertainty") {
            Some(t) => self.body_axis_uncertainty(t, &input, &converted)?,
            None => Vec::new(),
        };
        let aircraft = Aircraft {
            limits: common.limits,
            validity: common.validity,
            uncertainty,
            ..aircraft
        };
        Ok(BodyAxis {
            aircraft,
            converted,
        })
    }

    /// The inputs of a nondimensional body-axis file, each checked where it is written.
    pub(super) fn body_axis(
        &self,
        tables: &BodyAxisTables<'_, '_>,
    ) -> Result<BodyAxisInput, AircraftError> {
        let BodyAxisTables {
            flight,
            geometry,
            inertia,
            coefficients,
        } = *tables;
        for k in ["C", "D", "E"] {
            if let Some((key, _)) = inertia.get(k) {
                return Err(self.mixed(
                    key,
                    format!(
                        "`inertia.{k}` (an inertia coefficient of the dimensional format) in a \
                         file with `[geometry]` and `[coefficients]`"
                    ),
                ));
            }
        }
        let speed = self.required_positive(flight, "speed", "a speed in m/s > 0")?;
        if let Some((key, value)) = flight.get("speed") {
            self.gravity_term(flight, &(key, value), &speed)?;
        }
        let density = self.density(flight)?;
        let length = |k: &str, what: &str| self.required_positive(geometry, k, what);
        let moment = |k: &str| {
            self.required_positive(inertia, k, "a body-axis moment of inertia in kg m^2 > 0")
                .map(|n| n.exact)
        };
        let ixz = match inertia.get("ixz") {
            Some((key, value)) => self.number(inertia.name, key, value)?.exact,
            None => {
                return Err(self.missing_key(
                    inertia,
                    "ixz",
                    "`ixz = <number>`, the body-axis product of inertia in kg m^2 (0 when the \
                     body axes are principal)"
                        .to_string(),
                ))
            }
        };
        let mut coeffs = Vec::with_capacity(Coefficient::ALL.len());
        for c in Coefficient::ALL {
            let (key, value) = coefficients.get(c.key()).ok_or_else(|| {
                self.missing_key(
                    coefficients,
                    c.key(),
                    format!("`{} = <number>`, per rad", c.key()),
                )
            })?;
            coeffs.push(self.number(coefficients.name, key, value)?.exact);
        }
        Ok(BodyAxisInput {
            speed: speed.exact,
            density,
            mass: length("mass", "a mass in kg > 0")?.exact,
            wing_area: length("wing_area", "a wing area in m^2 > 0")?.exact,
            span: length("span", "a wing span in m > 0")?.exact,
            chord: length("chord", "a mean aerodynamic chord in m > 0")?.exact,
            ix: moment("ix")?,
            iy: moment("iy")?,
            iz: moment("iz")?,
            ixz,
            coefficients: coeffs,
            trim_alpha: self.trim_alpha(flight)?,
            load_factor: self
                .optional_number(flight, "load_factor")?
                .unwrap_or_else(BigRational::zero),
        })
    }

    /// The exact value of an optional key of `table`.
    fn optional_number(
        &self,
        table: &Table<'_>,
        k: &str,
    ) -> Result<Option<BigRational>, AircraftError> {
        match table.get(k) {
            Some((key, value)) => Ok(Some(self.number(table.name, key, value)?.exact)),
            None => Ok(None),
        }
    }

    /// `flight.alpha`, the body-axis angle of attack of the trim: a small-angle model holds it
    /// only well inside a right angle.
    fn trim_alpha(&self, flight: &Table<'_>) -> Result<Option<BigRational>, AircraftError> {
        let Some((key, value)) = flight.get("alpha") else {
            return Ok(None);
        };
        let n = self.number(flight.name, key, value)?;
        if n.float.abs() < std::f64::consts::FRAC_PI_2 {
            return Ok(Some(n.exact));
        }
        Err(AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(flight.name, &key.name),
            expected: "the body-axis angle of attack of the trim in rad, between -pi/2 and pi/2"
                .to_string(),
            value: n.written,
        })
    }

    /// The aircraft of a converted body-axis file, refused when a principal moment is not
    /// positive, a conversion factor or derivative leaves f64 (see `load/scale.rs`),
    /// or the aileron has no roll authority in principal axes; principal moments that break a
    /// triangle inequality give a warning (see `load/triangle.rs`).
    pub(super) fn body_axis_aircraft(
        &self,
        name: String,
        input: &BodyAxisInput,
        converted: &convert::Converted,
        tables: &BodyAxisTables<'_, '_>,
    ) -> Result<Aircraft, AircraftError> {
        let (inertia, coefficients) = (tables.inertia, tables.coefficients);
        let [ix, iy, iz] = &converted.principal;
        let f = rational_to_f64;
        let moments = format!(
            "ix' = {}, iy = {}, iz' = {} kg m^2",
            moment_text(f(ix)),
            moment_text(f(iy)),
            moment_text(f(iz))
        );
        // The x-z block [[ix, -ixz], [-ixz, iz]] has the principal moments ix', iz' as its
        // eigenvalues: both are positive iff ix iz - ixz^2 > 0 (ix, iz > 0 read before).
        for (name, m) in [("ix'", ix), ("iz'", iz)] {
            if !m.is_positive() {
                return Err(AircraftError::UnphysicalInertia {
                    at: self.at(inertia.span.as_ref()),
                    problem: format!(
                        "principal moment {name} <= 0 (principal moments {moments}): ix iz - ixz^2 <= 0 \
                         makes the x-z inertia matrix singular or indefinite, and the \
                         equations of motion divide by the principal moments"
                    ),
                });
            }
        }
        let warnings: Vec<String> = triangle_violation(["ix'", "iy", "iz'"], [ix, iy, iz])
            .into_iter()
            .map(|w| format!("{}: table `[inertia]`: {w}", self.at(inertia.span.as_ref())))
            .collect();
        self.conversion_factors(input, converted, tables)?;
        let l_delta_a = &converted.derivatives[Param::LDeltaA.index() - 3];
        if l_delta_a.is_zero() {
            let at = coefficients.get(Coefficient::ClDeltaA.key()).map_or_else(
                || self.at(coefficients.span.as_ref()),
                |(k, v)| self.at_value(k, v),
            );
            return Err(AircraftError::ZeroAileronAuthority {
                at,
                key: qualified(coefficients.name, Coefficient::ClDeltaA.key()),
                value: "0 (l_delta_a in principal axes)".to_string(),
            });
        }
        for (p, v) in Param::ALL.iter().skip(3).zip(&converted.derivatives) {
            let x = rational_to_f64(v);
            if !x.is_finite() {
                return Err(AircraftError::InvalidValue {
                    at: self.at(coefficients.span.as_ref()),
                    key: format!("derivatives.{} (converted)", p.key()),
                    expected: format!(
                        "{F64_RANGE}: check the units of `[flight]`, `[geometry]` and `[inertia]`"
                    ),
                    value: format!("{x:e}"),
                });
            }
        }
        // Within the triangle inequalities every coefficient lies in [-1, 1]; a file that
        // breaks one has a coefficient outside and its warning.
        let mut values = inertia_coefficients(ix, iy, iz).to_vec();
        values.extend(converted.derivatives.iter().cloned());
        let mut aircraft = Aircraft::new(name, values, converted.speed_f64());
        aircraft.warnings = warnings;
        aircraft.trimmed = input.trim_alpha.is_some() || tables.flight.get("load_factor").is_some();
        Ok(aircraft)
    }
}
