//! The dimensional principal-axis format of Table A.1: `[inertia]` (C, D, E, or ix, iy, iz from
//! which they are computed exactly) and `[derivatives]`, the 15 dimensional derivatives.

use super::super::{Aircraft, Param, DEFAULT_SPEED_M_S};
use super::{
    derivative_keys, list, qualified, AircraftError, Common, Cx, Key, Node, Number, Table, Tables,
};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// `n_delta_r` when a file does not give it.
const DEFAULT_N_DELTA_R: i64 = -1;

impl Cx<'_> {
    /// The aircraft of a dimensional file: `[inertia]`, `[derivatives]`, the speed of the
    /// optional `[flight]` and the optional `[uncertainty]`.
    pub(super) fn dimensional_document(
        &self,
        tables: &Tables<'_, '_>,
        common: Common,
    ) -> Result<Aircraft, AircraftError> {
        let inertia = tables.required(
            self,
            "inertia",
            "`[inertia]` with either `C`, `D`, `E` or `ix`, `iy`, `iz`".to_string(),
        )?;
        let derivatives = tables.required(
            self,
            "derivatives",
            format!("`[derivatives]` with keys {}", list(&derivative_keys())),
        )?;
        let mut values: Vec<BigRational> = self.inertia(inertia)?;
        values.extend(self.derivatives(derivatives)?);
        let speed = match tables.get("flight") {
            Some(flight) => self.flight(flight)?,
            None => DEFAULT_SPEED_M_S,
        };
        let mut aircraft = Aircraft::new(common.name, values, speed);
        aircraft.trimmed = ["z_0", "alpha_t"]
            .iter()
            .any(|k| derivatives.get(k).is_some());
        aircraft.limits = common.limits;
        aircraft.validity = common.validity;
        aircraft.warnings = self.moment_warnings(inertia);
        if let Some(t) = tables.get("uncertainty") {
            aircraft.uncertainty = self.uncertainty(t, &aircraft)?;
        }
        Ok(aircraft)
    }

    /// C, D, E, given or computed from ix, iy, iz.
    pub(super) fn inertia(&self, table: &Table<'_>) -> Result<Vec<BigRational>, AircraftError> {
        if let Some((key, _)) = table.get("ixz") {
            return Err(self.mixed(
                key,
                "`inertia.ixz` (a body-axis product of inertia) in a file with `[derivatives]` \
                 (principal axes)"
                    .to_string(),
            ));
        }
        let mut coeffs = Vec::new();
        let mut moments = Vec::new();
        for (key, value) in table.entries {
            let n = self.number(table.name, key, value)?;
            if ["C", "D", "E"].contains(&key.name.as_str()) {
                coeffs.push((key, value, n));
            } else {
                moments.push((key, value, n));
            }
        }
        if let (Some((c, _, _)), Some((m, _, _))) = (coeffs.first(), moments.first()) {
            let (first, second) = if c.start() <= m.start() {
                (c, m)
            } else {
                (m, c)
            };
            return Err(AircraftError::InertiaSet {
                at: self.at_key(second),
                problem: format!(
                    "`inertia.{}` given together with `inertia.{}`",
                    second.name, first.name
                ),
            });
        }
        if coeffs.is_empty() && moments.is_empty() {
            return Err(AircraftError::InertiaSet {
                at: self.at(table.span.as_ref()),
                problem: "no inertia given (`inertia` is empty)".to_string(),
            });
        }
        let (set, given): (&[&str], _) = if moments.is_empty() {
            (&["C", "D", "E"], &coeffs)
        } else {
            (&["ix", "iy", "iz"], &moments)
        };
        if let Some(e) = self.incomplete_set(table, set, given) {
            return Err(e);
        }
        let find = |name: &str| given.iter().find(|(k, _, _)| k.name == name);
        let mut out = Vec::with_capacity(3);
        for k in set {
            let Some((key, value, n)) = find(k) else {
                continue;
            };
            if !moments.is_empty() && !n.exact.is_positive() {
                return Err(AircraftError::NonPositiveInertia {
                    at: self.at_value(key, value),
                    key: qualified(table.name, &key.name),
                    value: n.written.clone(),
                });
            }
            // |C|, |D|, |E| <= 1 are the triangle inequalities of the principal moments
            // (C = (Iz - Ix)/Iy <= 1 is Iz <= Ix + Iy, and so on).
            if moments.is_empty() && n.exact.abs() > BigRational::from_integer(1.into()) {
                return Err(AircraftError::InvalidValue {
                    at: self.at_value(key, value),
                    key: qualified(table.name, &key.name),
                    expected: "an inertia coefficient within [-1, 1] (the triangle inequalities \
                               of the principal moments; outside, the inertia is unphysical)"
                        .to_string(),
                    value: n.written.clone(),
                });
            }
            out.push(n.exact.clone());
        }
        match out.as_slice() {
            [c, d, e] if moments.is_empty() => {
                self.one_rigid_body(table, given)?;
                Ok(vec![c.clone(), d.clone(), e.clone()])
            }
            // Moments that break a triangle inequality give a coefficient outside [-1, 1] and a
            // warning (`load/triangle.rs`).
            [ix, iy, iz] => self.coefficients_in_f64(table, [ix, iy, iz]),
            _ => Err(AircraftError::InertiaSet {
                at: self.at(table.span.as_ref()),
                problem: "incomplete set".to_string(),
            }),
        }
    }

    /// The error for a set (`C`, `D`, `E` or `ix`, `iy`, `iz`) of which only some are given.
    fn incomplete_set(
        &self,
        table: &Table<'_>,
        set: &[&str],
        given: &[(&Key, &Node, Number)],
    ) -> Option<AircraftError> {
        let find = |name: &str| given.iter().find(|(k, _, _)| k.name == name);
        let missing: Vec<&str> = set.iter().copied().filter(|k| find(k).is_none()).collect();
        if missing.is_empty() {
            return None;
        }
        let present: Vec<String> = set
            .iter()
            .filter(|k| find(k).is_some())
            .map(|k| format!("`inertia.{k}`"))
            .collect();
        Some(AircraftError::InertiaSet {
            at: self.at(table.span.as_ref()),
            problem: format!(
                "missing {} (only {} given)",
                missing
                    .iter()
                    .map(|k| format!("`inertia.{k}`"))
                    .collect::<Vec<_>>()
                    .join(", "),
                present.join(", ")
            ),
        })
    }

    /// The derivatives in [`Param::ALL`] order after C, D, E (the trim's `z_0` and `alpha_t`, as
    /// `l_delta_r`, default to 0: the paper's aircraft).
    pub(super) fn derivatives(&self, table: &Table<'_>) -> Result<Vec<BigRational>, AircraftError> {
        let mut read = Vec::new();
        for (key, value) in table.entries {
            read.push((key, value, self.number(table.name, key, value)?));
        }
        let mut out = Vec::with_capacity(Param::COUNT - 3);
        for p in Param::ALL.iter().skip(3) {
            let found = read.iter().find(|(k, _, _)| k.name == p.key());
            match found {
                Some((key, value, n)) => {
                    if *p == Param::LDeltaA && n.exact.is_zero() {
                        return Err(AircraftError::ZeroAileronAuthority {
                            at: self.at_value(key, value),
                            key: qualified(table.name, &key.name),
                            value: n.written.clone(),
                        });
                    }
                    out.push(n.exact.clone());
                }
                None if *p == Param::NDeltaR => {
                    out.push(BigRational::from_integer(BigInt::from(DEFAULT_N_DELTA_R)));
                }
                None if matches!(p, Param::LDeltaR | Param::Z0 | Param::AlphaT) => {
                    out.push(BigRational::zero())
                }
                None => {
                    return Err(self.missing_key(
                        table,
                        p.key(),
                        format!("`{} = <number>` in {}", p.key(), p.unit()),
                    ))
                }
            }
        }
        Ok(out)
    }
}

/// C = (iz - ix)/iy, D = (iy - ix)/iz, E = (iz - iy)/ix, exactly (principal moments).
pub(super) fn inertia_coefficients(
    ix: &BigRational,
    iy: &BigRational,
    iz: &BigRational,
) -> [BigRational; 3] {
    [(iz - ix) / iy, (iy - ix) / iz, (iz - iy) / ix]
}
