//! The `[flight]` table: the speed of either format (with the gravity term g/V it must keep
//! finite), and the density or ISA altitude of a nondimensional body-axis file.

use super::super::convert::Density;
use super::super::DEFAULT_SPEED_M_S;
use super::{qualified, shorten, AircraftError, Cx, Key, Node, Number, Table};
use num_traits::Signed;

/// ISA troposphere, m: the altitudes for which `flight.altitude` gives a density.
const ALTITUDE_RANGE_M: (f64, f64) = (0.0, 11_000.0);

impl Cx<'_> {
    /// The flight speed of a dimensional file, m/s.
    pub(super) fn flight(&self, table: &Table<'_>) -> Result<f64, AircraftError> {
        for k in ["density", "altitude"] {
            if let Some((key, _)) = table.get(k) {
                return Err(self.mixed(
                    key,
                    format!(
                        "`flight.{k}` (used only to convert nondimensional coefficients) in a \
                         file with `[derivatives]`"
                    ),
                ));
            }
        }
        for (k, instead) in [("alpha", "alpha_t"), ("load_factor", "z_0")] {
            if let Some((key, _)) = table.get(k) {
                return Err(self.mixed(
                    key,
                    format!(
                        "`flight.{k}` (the trim of nondimensional coefficients) in a file with \
                         `[derivatives]`, whose trim is `derivatives.{instead}`"
                    ),
                ));
            }
        }
        let Some((key, value)) = table.get("speed") else {
            return Ok(DEFAULT_SPEED_M_S);
        };
        let n = self.number(table.name, key, value)?;
        if !n.exact.is_positive() {
            return Err(AircraftError::InvalidSpeed {
                at: self.at_value(key, value),
                key: qualified(table.name, &key.name),
                value: n.written,
            });
        }
        self.gravity_term(table, &(key, value), &n)?;
        Ok(n.float)
    }

    /// The speed `n` of `entry`, refused when the gravity term g/V of the 7th-order model is
    /// not a finite double (a speed below 5.5e-308 m/s, or one that rounds to 0).
    pub(super) fn gravity_term(
        &self,
        table: &Table<'_>,
        entry: &(&Key, &Node),
        n: &Number,
    ) -> Result<(), AircraftError> {
        if (crate::aircraft::G / n.float).is_finite() {
            return Ok(());
        }
        let (key, value) = entry;
        Err(AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table.name, &key.name),
            expected: format!(
                "a speed in m/s at which the gravity term g/V of the 7th-order model is a \
                 finite double (about {:.1e} m/s or more)",
                crate::aircraft::G / f64::MAX
            ),
            value: shorten(&n.written),
        })
    }

    /// The air density of a body-axis file: `flight.density`, or the ISA density at
    /// `flight.altitude` (one of the two, not both).
    pub(super) fn density(&self, flight: &Table<'_>) -> Result<Density, AircraftError> {
        match (flight.get("density"), flight.get("altitude")) {
            (Some(_), Some((key, value))) => Err(AircraftError::InvalidValue {
                at: self.at_key(key),
                key: "flight.altitude".to_string(),
                expected: "either `flight.density` or `flight.altitude`, not both".to_string(),
                value: shorten(&self.written(value)),
            }),
            (Some(entry), None) => Ok(Density::Given(
                self.positive(flight, entry, "a density in kg/m^3 > 0")?
                    .exact,
            )),
            (None, Some((key, value))) => {
                let n = self.number(flight.name, key, value)?;
                let (low, high) = ALTITUDE_RANGE_M;
                if !(n.float >= low && n.float <= high) {
                    return Err(AircraftError::InvalidValue {
                        at: self.at_value(key, value),
                        key: qualified(flight.name, &key.name),
                        expected: format!(
                            "an altitude in m within the ISA troposphere, {low} to {high}"
                        ),
                        value: shorten(&n.written),
                    });
                }
                Ok(Density::Altitude(n.float))
            }
            (None, None) => Err(self.missing_key(
                flight,
                "density",
                "`density = <number>` in kg/m^3, or `altitude = <number>` in m (ISA \
                 troposphere, 0 to 11000)"
                    .to_string(),
            )),
        }
    }
}
