//! The valid keys of each table of an aircraft file (`""` being the top level), and how
//! messages write them.

use super::super::convert::Coefficient;
use super::super::Param;

pub(super) const TOP_KEYS: [&str; 10] = [
    "name",
    "inertia",
    "derivatives",
    "flight",
    "geometry",
    "coefficients",
    "limits",
    "validity",
    "uncertainty",
    "import",
];
pub(super) const INERTIA_KEYS: [&str; 7] = ["C", "D", "E", "ix", "iy", "iz", "ixz"];
pub(super) const FLIGHT_KEYS: [&str; 5] = ["speed", "density", "altitude", "alpha", "load_factor"];
pub(super) const GEOMETRY_KEYS: [&str; 4] = ["mass", "wing_area", "span", "chord"];
pub(super) const LIMIT_KEYS: [&str; 3] = ["aileron", "elevator", "rudder"];
pub(super) const VALIDITY_KEYS: [&str; 2] = ["alpha_max", "beta_max"];
pub(super) const IMPORT_KEYS: [&str; 1] = ["warnings"];

pub(super) fn derivative_keys() -> Vec<&'static str> {
    Param::ALL.iter().skip(3).map(|p| p.key()).collect()
}

pub(super) fn keys_of(table: &str) -> Vec<&'static str> {
    tables_of_format()
        .into_iter()
        .find(|(t, _)| *t == table)
        .map(|(_, k)| k)
        .unwrap_or_default()
}

/// The valid keys of each table, `""` being the top level.
pub(super) fn tables_of_format() -> [(&'static str, Vec<&'static str>); 10] {
    [
        ("", TOP_KEYS.to_vec()),
        ("inertia", INERTIA_KEYS.to_vec()),
        ("derivatives", derivative_keys()),
        ("flight", FLIGHT_KEYS.to_vec()),
        ("geometry", GEOMETRY_KEYS.to_vec()),
        (
            "coefficients",
            Coefficient::ALL.iter().map(|c| c.key()).collect(),
        ),
        ("limits", LIMIT_KEYS.to_vec()),
        ("validity", VALIDITY_KEYS.to_vec()),
        // Either format's keys here; each format's loader then takes only its own.
        (
            "uncertainty",
            Param::ALL
                .iter()
                .map(|p| p.key())
                .chain(Coefficient::ALL.iter().map(|c| c.key()))
                .collect(),
        ),
        ("import", IMPORT_KEYS.to_vec()),
    ]
}

pub(super) fn list(keys: &[&str]) -> String {
    keys.iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn qualified(table: &str, key: &str) -> String {
    if table.is_empty() {
        key.to_string()
    } else {
        format!("{table}.{key}")
    }
}
