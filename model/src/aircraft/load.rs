//! Loading an aircraft from a hand-written TOML file, exactly, with errors that point at the line.
//!
//! Two formats are accepted. The dimensional principal-axis format of Table A.1:
//!
//! ```toml
//! name = "Aircraft A"   # optional, default: the file stem
//! [inertia]             # either C, D, E ...
//! C = 0.959
//! D = 0.786
//! E = 0.705
//! # ... or ix, iy, iz (principal axes, any one unit), from which C, D, E are computed exactly
//! [derivatives]         # dimensional, 1/s or 1/s^2, angles in rad
//! z_alpha = -3.0076
//! # ... every key of Param::ALL after C, D, E; n_delta_r (default -1) and l_delta_r (default 0)
//! # are optional
//! [flight]              # optional
//! speed = 150.0         # m/s, optional, default DEFAULT_SPEED_M_S
//! ```
//!
//! and the nondimensional body-axis format (`[flight]` speed with density or altitude,
//! `[geometry]`, `[inertia]` ix, iy, iz, ixz, `[coefficients]`), which
//! [`crate::aircraft::convert`] turns into the first. Both take the optional `[limits]` and
//! `[validity]` tables. The tables of one format may not be mixed with those of the other.
//!
//! Every number enters as the exact rational of the decimal literal the user wrote (the literal
//! text comes from `toml_edit`'s spans, never from an f64); a string `"p/q"` is the exact fraction
//! p/q (what `convert` writes where a value is not a terminating decimal). `C = (iz - ix)/iy`,
//! `D = (iy - ix)/iz` and `E = (iz - iy)/ix` are computed in exact rational arithmetic; given
//! C, D, E must be those of one rigid body to within the rounding of tabled data (`inertia.rs`).
//! A nondimensional file's flight condition, geometry and inertia must keep every conversion
//! factor within the normal range of f64 (`scale.rs`). Every error names the file, the line and
//! column, the key with its table, and what was expected.
//!
//! The reading is in files of one concept each: the document as a tree with spans
//! (`toml_tree.rs`), the valid keys (`keys.rs`), the reader every error takes its place from
//! (`reader.rs`), text the parser refuses (`syntax.rs`), exact numbers (`number.rs`), the two
//! formats (`principal_axis.rs`, `body_axis.rs`) and the tables they share (`flight.rs`,
//! `limits.rs`, `uncertainty.rs`) and the warnings an import wrote (`import.rs`).

use super::{Aircraft, Limits, Validity};
use std::path::Path;

mod body_axis;
mod error;
mod flight;
mod import;
mod inertia;
mod keys;
mod limits;
mod number;
mod principal_axis;
mod reader;
mod scale;
mod suggest;
mod syntax;
mod toml_tree;
mod triangle;
mod uncertainty;

use body_axis::{BodyAxis, BodyAxisTables};
pub use error::{AircraftError, Location};
use keys::{derivative_keys, keys_of, list, qualified, tables_of_format, TOP_KEYS};
use number::{Number, F64_RANGE, I64_RANGE};
use principal_axis::inertia_coefficients;
use reader::{shorten, Cx, Table};
use suggest::suggestion_among;
use toml_tree::{entries_of, key_at, line_col, Key, Kind, Node};

/// Reads an aircraft file and parses it with [`parse`]; messages name the file by its path.
pub fn load(path: &Path) -> Result<Aircraft, AircraftError> {
    parse(&read(path)?, &path.display().to_string())
}

/// Parses the TOML text of an aircraft; `file` is the name used in error messages and, without a
/// `name` key, its stem is the aircraft's name.
pub fn parse(text: &str, file: &str) -> Result<Aircraft, AircraftError> {
    match read_document(text, file)? {
        Parsed::Dimensional(a) => Ok(a),
        Parsed::BodyAxis(c) => Ok(c.aircraft),
    }
}

/// Reads a nondimensional body-axis file and writes the equivalent dimensional principal-axis
/// TOML (see [`Converted::to_toml`](super::convert::Converted::to_toml)); a dimensional file is refused.
pub fn convert_file(path: &Path) -> Result<String, AircraftError> {
    convert_text(&read(path)?, &path.display().to_string())
}

/// [`convert_file`] of the file text `text`, named `file` in messages (a path, or the
/// `jsbsim:` source that made the text).
pub fn convert_text(text: &str, file: &str) -> Result<String, AircraftError> {
    let file = file.to_string();
    match read_document(text, &file)? {
        Parsed::BodyAxis(c) => Ok(c.converted.to_toml(&c.aircraft, &file)),
        Parsed::Dimensional(_) => Err(AircraftError::AlreadyDimensional {
            at: Location {
                file,
                line: 1,
                column: 1,
            },
        }),
    }
}

fn read(path: &Path) -> Result<String, AircraftError> {
    std::fs::read_to_string(path).map_err(|source| AircraftError::Io {
        path: path.to_path_buf(),
        source,
    })
}

enum Parsed {
    Dimensional(Aircraft),
    BodyAxis(Box<BodyAxis>),
}

/// The top-level tables of a file, each checked to hold only its valid keys, in document order.
struct Tables<'k, 'n> {
    tables: Vec<(&'k Key, Table<'n>)>,
}

impl<'k, 'n> Tables<'k, 'n> {
    /// The table `name` with its key, if the file has it.
    fn find(&self, name: &str) -> Option<&(&'k Key, Table<'n>)> {
        self.tables.iter().find(|(k, _)| k.name == name)
    }

    /// The table `name`, if the file has it.
    fn get(&self, name: &str) -> Option<&Table<'n>> {
        self.find(name).map(|(_, t)| t)
    }

    /// The table `name`, which the file's format requires: `expected` says what it holds.
    fn required(
        &self,
        cx: &Cx<'_>,
        name: &str,
        expected: String,
    ) -> Result<&Table<'n>, AircraftError> {
        self.get(name).ok_or_else(|| AircraftError::MissingTable {
            at: cx.at(None),
            table: name.to_string(),
            expected,
        })
    }
}

/// What a file says besides its format's own tables: its name and the optional `[limits]` and
/// `[validity]`.
struct Common {
    name: String,
    limits: Limits,
    validity: Validity,
}

fn read_document(text: &str, file: &str) -> Result<Parsed, AircraftError> {
    let cx = Cx { text, file };
    if let Some(e) = cx.control_character() {
        return Err(e);
    }
    let doc = toml_edit::ImDocument::parse(text).map_err(|e| cx.syntax_error(&e))?;
    let entries = entries_of(doc.as_table());

    let mut name = None;
    let mut tables = Tables { tables: Vec::new() };
    for (key, value) in &entries {
        match key.name.as_str() {
            "name" => name = Some(cx.aircraft_name(key, value)?),
            table => match tables_of_format()
                .iter()
                .find(|(t, _)| !t.is_empty() && *t == table)
            {
                Some((_, keys)) => tables.tables.push((key, cx.table(key, value, keys)?)),
                None => return Err(cx.unknown("", key)),
            },
        }
    }
    let body_axis = cx.one_format(&tables)?;
    let common = Common {
        name: name.unwrap_or_else(|| default_name(file)),
        limits: match tables.get("limits") {
            Some(t) => cx.limits(t)?,
            None => Limits::default(),
        },
        validity: match tables.get("validity") {
            Some(t) => cx.validity(t)?,
            None => Validity::default(),
        },
    };
    let imported = match tables.get("import") {
        Some(t) => cx.import_warnings(t)?,
        None => Vec::new(),
    };
    if body_axis {
        let mut body_axis = cx.body_axis_document(&tables, common)?;
        body_axis.aircraft.warnings.extend(imported);
        return Ok(Parsed::BodyAxis(Box::new(body_axis)));
    }
    let mut aircraft = cx.dimensional_document(&tables, common)?;
    aircraft.warnings.extend(imported);
    Ok(Parsed::Dimensional(aircraft))
}

impl Cx<'_> {
    /// The `name` key: a non-empty string without control characters.
    fn aircraft_name(&self, key: &Key, value: &Node) -> Result<String, AircraftError> {
        match &value.kind {
            Kind::String(s) if s.chars().any(char::is_control) => {
                Err(AircraftError::InvalidValue {
                    at: self.at_value(key, value),
                    key: "name".to_string(),
                    expected: "a name without control characters (written or escaped, \
                               such as `\\t`, `\\n` or `\\u001b`: a name is printed in \
                               reports and on terminals)"
                        .to_string(),
                    value: shorten(&super::shown(s)),
                })
            }
            Kind::String(s) if !s.trim().is_empty() => Ok(s.clone()),
            Kind::String(_) => Err(AircraftError::WrongType {
                at: self.at_value(key, value),
                key: "name".to_string(),
                expected: "a non-empty string",
                found: "an empty string",
            }),
            other => Err(AircraftError::WrongType {
                at: self.at_value(key, value),
                key: "name".to_string(),
                expected: "a string",
                found: other.describe(),
            }),
        }
    }

    /// Whether the file is in the body-axis format (it has `[geometry]` or `[coefficients]`);
    /// refused when it also has the dimensional `[derivatives]`, naming the later of the two.
    fn one_format(&self, tables: &Tables<'_, '_>) -> Result<bool, AircraftError> {
        let body_axis = ["geometry", "coefficients"]
            .iter()
            .find_map(|t| tables.find(t).map(|(k, _)| *k));
        if let (Some(b), Some((d, _))) = (body_axis, tables.find("derivatives")) {
            let (first, second) = if b.start() <= d.start() {
                (b, *d)
            } else {
                (*d, b)
            };
            return Err(AircraftError::MixedFormats {
                at: self.at_key(second),
                problem: format!(
                    "table `[{}]` given together with `[{}]`",
                    second.name, first.name
                ),
            });
        }
        Ok(body_axis.is_some())
    }
}

/// The name of an aircraft whose file has no `name` key: the file's stem.
fn default_name(file: &str) -> String {
    Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "unnamed aircraft".to_string())
}

#[cfg(test)]
mod tests;
