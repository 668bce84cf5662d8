//! The optional `[limits]` (control deflection limits) and `[validity]` (the angles within which
//! the model holds) tables, the same in either format.

use super::super::{Limits, Validity, VALIDITY_DEFAULT_DEG};
use super::{AircraftError, Cx, Table};

impl Cx<'_> {
    /// `[limits]`: deflection limits in degrees, each optional and > 0.
    pub(super) fn limits(&self, table: &Table<'_>) -> Result<Limits, AircraftError> {
        let limit = |k: &str| -> Result<Option<f64>, AircraftError> {
            table
                .get(k)
                .map(|entry| {
                    self.positive(table, entry, "a deflection limit in degrees > 0")
                        .map(|n| n.float)
                })
                .transpose()
        };
        Ok(Limits {
            aileron_deg: limit("aileron")?,
            elevator_deg: limit("elevator")?,
            rudder_deg: limit("rudder")?,
        })
    }

    /// `[validity]`: |alpha| and |beta| limits in degrees, each optional (default 30) and > 0.
    pub(super) fn validity(&self, table: &Table<'_>) -> Result<Validity, AircraftError> {
        let angle = |k: &str| -> Result<f64, AircraftError> {
            match table.get(k) {
                Some(entry) => self
                    .positive(table, entry, "an angle in degrees > 0")
                    .map(|n| n.float),
                None => Ok(VALIDITY_DEFAULT_DEG),
            }
        };
        Ok(Validity {
            alpha_max_deg: angle("alpha_max")?,
            beta_max_deg: angle("beta_max")?,
        })
    }
}
