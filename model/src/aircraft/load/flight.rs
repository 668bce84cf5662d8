//! The `[flight]` table: the speed of either format (with the gravity term g/V it must keep
//! finite), and the density or ISA altitude of a nondimensional body-axis file.

use super::super::DEFAULT_SPEED_M_S;
use super::{qualified, shorten, AircraftError, Cx, Key, Node, Number, Table};
use num_traits::Signed;

/// ISA troposphere, m: the altitudes for which `flight.altitude` gives a density.
pub(super) const ALTITUDE_RANGE_M: (f64, f64) = (0.0, 11_000.0);

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
        if (crate::equations::G / n.float).is_finite() {
            return Ok(());
        }
        let (key, value) = entry;
        Err(AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table.name, &key.name),
            expected: format!(
                "a speed in m/s at which the gravity term g/V of the 7th-order model is a \
                 finite double (about {:.1e} m/s or more)",
                crate::equations::G / f64::MAX
            ),
            value: shorten(&n.written),
        })
    }
}
