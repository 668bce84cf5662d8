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

use super::convert::{self, BodyAxisInput, Coefficient, Density};
use super::{
    decimal_to_rational, f64_to_rational, rational_to_f64, Aircraft, Limits, Param, Validity,
};
use super::{DEFAULT_SPEED_M_S, VALIDITY_DEFAULT_DEG};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::ops::Range;
use std::path::Path;
use std::str::FromStr;

mod error;
mod inertia;
mod scale;
mod suggest;
mod uncertainty;

pub use error::{AircraftError, Location};
use suggest::{suggestion, suggestion_among};

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
/// TOML (see [`convert::Converted::to_toml`]); a dimensional file is refused.
pub fn convert_file(path: &Path) -> Result<String, AircraftError> {
    let file = path.display().to_string();
    match read_document(&read(path)?, &file)? {
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

/// The four tables of a nondimensional body-axis file.
struct BodyAxisTables<'t, 'n> {
    flight: &'t Table<'n>,
    geometry: &'t Table<'n>,
    inertia: &'t Table<'n>,
    coefficients: &'t Table<'n>,
}

/// A body-axis file: the aircraft and the conversion it came from (for `convert`).
struct BodyAxis {
    aircraft: Aircraft,
    converted: convert::Converted,
}

enum Parsed {
    Dimensional(Aircraft),
    BodyAxis(Box<BodyAxis>),
}

fn read_document(text: &str, file: &str) -> Result<Parsed, AircraftError> {
    let cx = Cx { text, file };
    if let Some(e) = cx.control_character() {
        return Err(e);
    }
    let doc = toml_edit::ImDocument::parse(text).map_err(|e| cx.syntax_error(&e))?;
    let entries = entries_of(doc.as_table());

    let mut name = None;
    let mut tables: Vec<(&Key, Table<'_>)> = Vec::new();
    for (key, value) in &entries {
        match key.name.as_str() {
            "name" => match &value.kind {
                Kind::String(s) if s.chars().any(char::is_control) => {
                    return Err(AircraftError::InvalidValue {
                        at: cx.at_value(key, value),
                        key: "name".to_string(),
                        expected: "a name without control characters (written or escaped, \
                                   such as `\\t`, `\\n` or `\\u001b`: a name is printed in \
                                   reports and on terminals)"
                            .to_string(),
                        value: shorten(&super::shown(s)),
                    })
                }
                Kind::String(s) if !s.trim().is_empty() => name = Some(s.clone()),
                Kind::String(_) => {
                    return Err(AircraftError::WrongType {
                        at: cx.at_value(key, value),
                        key: "name".to_string(),
                        expected: "a non-empty string",
                        found: "an empty string",
                    })
                }
                other => {
                    return Err(AircraftError::WrongType {
                        at: cx.at_value(key, value),
                        key: "name".to_string(),
                        expected: "a string",
                        found: other.describe(),
                    })
                }
            },
            table => match tables_of_format()
                .iter()
                .find(|(t, _)| !t.is_empty() && *t == table)
            {
                Some((_, keys)) => tables.push((key, cx.table(key, value, keys)?)),
                None => return Err(cx.unknown("", key)),
            },
        }
    }
    let find = |t: &str| tables.iter().find(|(k, _)| k.name == t);
    let body_axis = ["geometry", "coefficients"]
        .iter()
        .find_map(|t| find(t).map(|(k, _)| *k));
    if let (Some(b), Some((d, _))) = (body_axis, find("derivatives").map(|(k, t)| (*k, t))) {
        let (first, second) = if b.start() <= d.start() {
            (b, d)
        } else {
            (d, b)
        };
        return Err(AircraftError::MixedFormats {
            at: cx.at_key(second),
            problem: format!(
                "table `[{}]` given together with `[{}]`",
                second.name, first.name
            ),
        });
    }
    let name = name.unwrap_or_else(|| default_name(file));
    let limits = match find("limits") {
        Some((_, t)) => cx.limits(t)?,
        None => Limits::default(),
    };
    let validity = match find("validity") {
        Some((_, t)) => cx.validity(t)?,
        None => Validity::default(),
    };
    let missing = |table: &str, expected: String| AircraftError::MissingTable {
        at: cx.at(None),
        table: table.to_string(),
        expected,
    };

    if body_axis.is_some() {
        let table = |t: &'static str| {
            find(t)
                .map(|(_, t)| t)
                .ok_or_else(|| missing(t, format!("`[{t}]` with keys {}", list(&keys_of(t)))))
        };
        let tables = BodyAxisTables {
            flight: table("flight")?,
            geometry: table("geometry")?,
            inertia: table("inertia")?,
            coefficients: table("coefficients")?,
        };
        let input = cx.body_axis(&tables)?;
        let converted = convert::convert(&input);
        let aircraft = cx.body_axis_aircraft(name, &input, &converted, &tables)?;
        let uncertainty = match find("uncertainty") {
            Some((_, t)) => cx.body_axis_uncertainty(t, &input, &converted)?,
            None => Vec::new(),
        };
        let aircraft = Aircraft {
            limits,
            validity,
            uncertainty,
            ..aircraft
        };
        return Ok(Parsed::BodyAxis(Box::new(BodyAxis {
            aircraft,
            converted,
        })));
    }

    let inertia = find("inertia").map(|(_, t)| t).ok_or_else(|| {
        missing(
            "inertia",
            "`[inertia]` with either `C`, `D`, `E` or `ix`, `iy`, `iz`".to_string(),
        )
    })?;
    let derivatives = find("derivatives").map(|(_, t)| t).ok_or_else(|| {
        missing(
            "derivatives",
            format!("`[derivatives]` with keys {}", list(&derivative_keys())),
        )
    })?;
    let mut values: Vec<BigRational> = cx.inertia(inertia)?;
    values.extend(cx.derivatives(derivatives)?);
    let speed = match find("flight") {
        Some((_, flight)) => cx.flight(flight)?,
        None => DEFAULT_SPEED_M_S,
    };
    let mut aircraft = Aircraft::new(name, values, speed);
    aircraft.limits = limits;
    aircraft.validity = validity;
    if let Some((_, t)) = find("uncertainty") {
        aircraft.uncertainty = cx.uncertainty(t, &aircraft)?;
    }
    Ok(Parsed::Dimensional(aircraft))
}

// ---------------------------------------------------------------------------------------------
// Validation

const TOP_KEYS: [&str; 9] = [
    "name",
    "inertia",
    "derivatives",
    "flight",
    "geometry",
    "coefficients",
    "limits",
    "validity",
    "uncertainty",
];
const INERTIA_KEYS: [&str; 7] = ["C", "D", "E", "ix", "iy", "iz", "ixz"];
const FLIGHT_KEYS: [&str; 3] = ["speed", "density", "altitude"];
const GEOMETRY_KEYS: [&str; 4] = ["mass", "wing_area", "span", "chord"];
const LIMIT_KEYS: [&str; 3] = ["aileron", "elevator", "rudder"];
const VALIDITY_KEYS: [&str; 2] = ["alpha_max", "beta_max"];
const DEFAULT_N_DELTA_R: i64 = -1;
/// ISA troposphere, m: the altitudes for which `flight.altitude` gives a density.
const ALTITUDE_RANGE_M: (f64, f64) = (0.0, 11_000.0);

fn derivative_keys() -> Vec<&'static str> {
    Param::ALL.iter().skip(3).map(|p| p.key()).collect()
}

fn keys_of(table: &str) -> Vec<&'static str> {
    tables_of_format()
        .into_iter()
        .find(|(t, _)| *t == table)
        .map(|(_, k)| k)
        .unwrap_or_default()
}

/// The valid keys of each table, `""` being the top level.
fn tables_of_format() -> [(&'static str, Vec<&'static str>); 9] {
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
    ]
}

fn list(keys: &[&str]) -> String {
    keys.iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn qualified(table: &str, key: &str) -> String {
    if table.is_empty() {
        key.to_string()
    } else {
        format!("{table}.{key}")
    }
}

fn default_name(file: &str) -> String {
    Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "unnamed aircraft".to_string())
}

fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}

/// At most 40 characters of a value as written, for messages (a 400-digit number stays legible).
fn shorten(s: &str) -> String {
    let s = s.trim().replace('\n', " ");
    if s.chars().count() <= 40 {
        return s;
    }
    let head: String = s.chars().take(24).collect();
    format!("{head}... ({} characters)", s.chars().count())
}

/// A table of the file, checked to hold only valid keys.
struct Table<'n> {
    name: &'static str,
    /// The table's own span or, failing that, its key's.
    span: Option<Range<usize>>,
    entries: &'n [(Key, Node)],
}

impl Table<'_> {
    fn get(&self, key: &str) -> Option<&(Key, Node)> {
        self.entries.iter().find(|(k, _)| k.name == key)
    }
}

/// A number as read: exact, rounded, and as written.
struct Number {
    exact: BigRational,
    float: f64,
    written: String,
}

/// A string `"p/q"` (optional sign, decimal integers, q != 0) as the exact fraction it denotes.
fn fraction_to_rational(s: &str) -> Option<BigRational> {
    let (p, q) = s.trim().split_once('/')?;
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let unsigned = p.strip_prefix(['-', '+']).unwrap_or(p);
    if !digits(unsigned) || !digits(q) || q.len() > 1000 || p.len() > 1000 {
        return None;
    }
    let q = BigInt::from_str(q).ok()?;
    if q.is_zero() {
        return None;
    }
    Some(BigRational::new(BigInt::from_str(p).ok()?, q))
}

struct Cx<'a> {
    text: &'a str,
    file: &'a str,
}

/// What a number key accepts when the literal cannot be read as a finite f64-range number.
const F64_RANGE: &str =
    "a finite number within the range of f64 (magnitude at most 1.7976931348623157e308)";
const I64_RANGE: &str = "an integer within the 64-bit range (-9223372036854775808 to \
     9223372036854775807; write larger magnitudes as decimals, e.g. `1.5e20`)";

impl Cx<'_> {
    fn at(&self, span: Option<&Range<usize>>) -> Location {
        self.at_offset(span.map(|s| s.start))
    }

    fn at_offset(&self, offset: Option<usize>) -> Location {
        let (line, column) = offset.map_or((1, 1), |o| line_col(self.text, o));
        Location {
            file: self.file.to_string(),
            line,
            column,
        }
    }

    fn at_key(&self, key: &Key) -> Location {
        self.at(key.span.as_ref())
    }

    fn at_value(&self, key: &Key, value: &Node) -> Location {
        self.at(value.span.as_ref().or(key.span.as_ref()))
    }

    /// The first control character TOML forbids (all of U+0000-U+001F but tab, LF and CR, and
    /// U+007F), reported with the key on its line; the parser itself says only "invalid basic
    /// string" or, through `toml`, nothing at all.
    fn control_character(&self) -> Option<AircraftError> {
        let (offset, c) = self
            .text
            .char_indices()
            .find(|&(_, c)| (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{7f}')?;
        let mut patched = self.text.to_string();
        patched.replace_range(offset..offset + c.len_utf8(), " ");
        let place = match key_at(&patched, offset) {
            Some(key) => format!("key `{key}`"),
            None => format!("line {}", line_col(self.text, offset).0),
        };
        let name = match c {
            '\0' => " (NUL)",
            '\u{7f}' => " (DEL)",
            '\u{1b}' => " (ESC)",
            _ => "",
        };
        Some(AircraftError::ControlCharacter {
            at: self.at_offset(Some(offset)),
            place,
            found: format!("U+{:04X}{name}", u32::from(c)),
        })
    }

    /// A TOML syntax error; for a number the parser cannot hold (an integer past i64, `1e309`, a
    /// 400-digit literal) the error names the key and the range instead: the literal is replaced
    /// by `0` of the same length, the text parsed again, and the key found by its position.
    fn syntax_error(&self, e: &toml_edit::TomlError) -> AircraftError {
        let message = one_line(e.message());
        let span = e.span();
        let number_message = [
            "number too large",
            "number too small",
            "invalid floating-point number",
        ]
        .iter()
        .any(|m| message.contains(m));
        if let (true, Some(span)) = (number_message, span.as_ref()) {
            let start = span.start.min(self.text.len());
            let rest = self.text.get(start..).unwrap_or("");
            let len = rest
                .find(|c: char| c.is_whitespace() || matches!(c, ',' | ']' | '}' | '#'))
                .unwrap_or(rest.len());
            if len > 0 {
                let literal = &rest[..len];
                let mut patched = self.text.to_string();
                patched.replace_range(start..start + len, &format!("0{}", " ".repeat(len - 1)));
                if let Some(key) = key_at(&patched, start) {
                    let integer = !literal.contains(['.', 'e', 'E']);
                    return AircraftError::InvalidValue {
                        at: self.at_offset(Some(start)),
                        key,
                        expected: if integer { I64_RANGE } else { F64_RANGE }.to_string(),
                        value: shorten(literal),
                    };
                }
            }
        }
        let message = if message.trim().is_empty() {
            self.cut_off(span.as_ref().map_or(self.text.len(), |s| s.start))
        } else {
            message
        };
        AircraftError::Syntax {
            at: self.at(span.as_ref()),
            message,
        }
    }

    /// What to say where the parser stops without a message (a value cut off at the end of
    /// the file): the key of that line, with its table, and what it expects.
    fn cut_off(&self, offset: usize) -> String {
        let offset = offset.min(self.text.len());
        let line_start = self.text[..offset].rfind('\n').map_or(0, |i| i + 1);
        let line = self.text[line_start..].lines().next().unwrap_or("");
        let key = line
            .split_once('=')
            .map(|(k, _)| k.trim())
            .filter(|k| !k.is_empty() && !k.starts_with('#'));
        let table = self.text[..line_start]
            .lines()
            .rev()
            .find_map(|l| {
                let t = l.trim();
                t.strip_prefix('[')
                    .and_then(|t| t.strip_suffix(']'))
                    .map(|t| t.trim().to_string())
            })
            .unwrap_or_default();
        match key {
            Some(k) => format!(
                "key `{}`: the value is missing or cut off here: expected a number",
                qualified(&table, k)
            ),
            None => "the text is cut off here: expected a complete `key = value` line or a \
                     `[table]` header"
                .to_string(),
        }
    }

    fn written(&self, value: &Node) -> String {
        value
            .span
            .as_ref()
            .and_then(|s| self.text.get(s.clone()))
            .map(|s| s.trim().to_string())
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| match &value.kind {
                Kind::Integer(i) => i.to_string(),
                Kind::Float(x) => x.to_string(),
                other => other.describe().to_string(),
            })
            .chars()
            .take(80)
            .collect::<String>()
            .replace('\n', " ")
    }

    fn unknown(&self, table: &str, key: &Key) -> AircraftError {
        AircraftError::UnknownKey {
            at: self.at_key(key),
            key: qualified(table, &key.name),
            hint: suggestion(table, &key.name),
            expected: list(&keys_of(table)),
        }
    }

    /// Checks that `value` (under top-level `key`) is a table holding only `valid` keys.
    fn table<'n>(
        &self,
        key: &Key,
        value: &'n Node,
        valid: &[&str],
    ) -> Result<Table<'n>, AircraftError> {
        let name = TOP_KEYS
            .iter()
            .copied()
            .find(|k| *k == key.name)
            .unwrap_or("");
        let Kind::Table(entries) = &value.kind else {
            return Err(AircraftError::NotATable {
                at: self.at_value(key, value),
                key: key.name.clone(),
                expected: list(valid),
                found: value.kind.describe(),
            });
        };
        // `[uncertainty]` takes the keys of the file's format, known only later: its loaders
        // check them (`uncertainty.rs`).
        if let Some((k, _)) = entries
            .iter()
            .find(|(k, _)| name != "uncertainty" && !valid.contains(&k.name.as_str()))
        {
            return Err(self.unknown(name, k));
        }
        Ok(Table {
            name,
            span: value.span.clone().or_else(|| key.span.clone()),
            entries,
        })
    }

    fn number(&self, table: &str, key: &Key, value: &Node) -> Result<Number, AircraftError> {
        let written = self.written(value);
        let out_of_range = |expected: &str| AircraftError::InvalidValue {
            at: self.at_value(key, value),
            key: qualified(table, &key.name),
            expected: expected.to_string(),
            value: shorten(&written),
        };
        let exact = match &value.kind {
            Kind::Integer(i) => BigRational::from_integer(BigInt::from(*i)),
            Kind::Float(x) if !x.is_finite() => {
                return Err(AircraftError::NotFinite {
                    at: self.at_value(key, value),
                    key: qualified(table, &key.name),
                    value: written,
                })
            }
            // The literal as written (in full: `written` is shortened for messages), never the
            // f64 the parser made of it.
            Kind::Float(x) => match value.span.as_ref().and_then(|s| self.text.get(s.clone())) {
                Some(literal) => decimal_to_rational(&literal.trim().replace('_', ""))
                    .ok_or_else(|| out_of_range(F64_RANGE))?,
                None => f64_to_rational(*x).ok_or_else(|| out_of_range(F64_RANGE))?,
            },
            Kind::String(s) if s.contains('/') => fraction_to_rational(s).ok_or_else(|| {
                out_of_range(
                    "a number, or an exact fraction as a string `\"p/q\"` with decimal \
                     integers p and q, q != 0",
                )
            })?,
            other => {
                return Err(AircraftError::WrongType {
                    at: self.at_value(key, value),
                    key: qualified(table, &key.name),
                    expected: "a number",
                    found: other.describe(),
                })
            }
        };
        let float = rational_to_f64(&exact);
        if !float.is_finite() {
            return Err(out_of_range(F64_RANGE));
        }
        Ok(Number {
            exact,
            float,
            written,
        })
    }

    /// A number that must be > 0 (and, through [`Cx::number`], finite).
    fn positive(
        &self,
        table: &Table<'_>,
        entry: &(Key, Node),
        expected: &str,
    ) -> Result<Number, AircraftError> {
        let (key, value) = entry;
        let n = self.number(table.name, key, value)?;
        if !n.exact.is_positive() {
            return Err(AircraftError::InvalidValue {
                at: self.at_value(key, value),
                key: qualified(table.name, &key.name),
                expected: expected.to_string(),
                value: shorten(&n.written),
            });
        }
        Ok(n)
    }

    fn missing_key(&self, table: &Table<'_>, key: &str, expected: String) -> AircraftError {
        AircraftError::MissingKey {
            at: self.at(table.span.as_ref()),
            table: table.name.to_string(),
            key: qualified(table.name, key),
            expected,
        }
    }

    /// A required key that must be > 0.
    fn required_positive(
        &self,
        table: &Table<'_>,
        key: &str,
        what: &str,
    ) -> Result<Number, AircraftError> {
        let entry = table
            .get(key)
            .ok_or_else(|| self.missing_key(table, key, format!("`{key} = <number>`, {what}")))?;
        self.positive(table, entry, what)
    }

    fn mixed(&self, key: &Key, problem: String) -> AircraftError {
        AircraftError::MixedFormats {
            at: self.at_key(key),
            problem,
        }
    }

    /// C, D, E, given or computed from ix, iy, iz.
    fn inertia(&self, table: &Table<'_>) -> Result<Vec<BigRational>, AircraftError> {
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
        let find = |name: &str| given.iter().find(|(k, _, _)| k.name == name);
        let missing: Vec<&str> = set.iter().copied().filter(|k| find(k).is_none()).collect();
        if !missing.is_empty() {
            let present: Vec<String> = set
                .iter()
                .filter(|k| find(k).is_some())
                .map(|k| format!("`inertia.{k}`"))
                .collect();
            return Err(AircraftError::InertiaSet {
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
            });
        }
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
            [ix, iy, iz] => {
                for (a, b, c, text) in [
                    (ix, iy, iz, "ix + iy < iz"),
                    (ix, iz, iy, "ix + iz < iy"),
                    (iy, iz, ix, "iy + iz < ix"),
                ] {
                    if a + b < *c {
                        return Err(AircraftError::UnphysicalInertia {
                            at: self.at(table.span.as_ref()),
                            problem: text.to_string(),
                        });
                    }
                }
                // Within the triangle inequalities every coefficient lies in [-1, 1].
                Ok(inertia_coefficients(ix, iy, iz).to_vec())
            }
            _ => Err(AircraftError::InertiaSet {
                at: self.at(table.span.as_ref()),
                problem: "incomplete set".to_string(),
            }),
        }
    }

    /// The 15 derivatives in [`Param::ALL`] order.
    fn derivatives(&self, table: &Table<'_>) -> Result<Vec<BigRational>, AircraftError> {
        let mut read = Vec::new();
        for (key, value) in table.entries {
            read.push((key, value, self.number(table.name, key, value)?));
        }
        let mut out = Vec::with_capacity(15);
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
                None if *p == Param::LDeltaR => out.push(BigRational::zero()),
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

    /// The flight speed of a dimensional file, m/s.
    fn flight(&self, table: &Table<'_>) -> Result<f64, AircraftError> {
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
    fn gravity_term(
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

    /// `[limits]`: deflection limits in degrees, each optional and > 0.
    fn limits(&self, table: &Table<'_>) -> Result<Limits, AircraftError> {
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
    fn validity(&self, table: &Table<'_>) -> Result<Validity, AircraftError> {
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

    /// The inputs of a nondimensional body-axis file, each checked where it is written.
    fn body_axis(&self, tables: &BodyAxisTables<'_, '_>) -> Result<BodyAxisInput, AircraftError> {
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
        let density = match (flight.get("density"), flight.get("altitude")) {
            (Some(_), Some((key, value))) => {
                return Err(AircraftError::InvalidValue {
                    at: self.at_key(key),
                    key: "flight.altitude".to_string(),
                    expected: "either `flight.density` or `flight.altitude`, not both".to_string(),
                    value: shorten(&self.written(value)),
                })
            }
            (Some(entry), None) => Density::Given(
                self.positive(flight, entry, "a density in kg/m^3 > 0")?
                    .exact,
            ),
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
                Density::Altitude(n.float)
            }
            (None, None) => {
                return Err(self.missing_key(
                    flight,
                    "density",
                    "`density = <number>` in kg/m^3, or `altitude = <number>` in m (ISA \
                     troposphere, 0 to 11000)"
                        .to_string(),
                ))
            }
        };
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
        })
    }

    /// The aircraft of a converted body-axis file, refused when the principal moments are not
    /// those of a rigid body, a conversion factor or derivative leaves f64 (see `load/scale.rs`),
    /// or the aileron has no roll authority in principal axes.
    fn body_axis_aircraft(
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
            "ix' = {:e}, iy = {:e}, iz' = {:e} kg m^2",
            f(ix),
            f(iy),
            f(iz)
        );
        let unphysical = |problem: String| AircraftError::UnphysicalInertia {
            at: self.at(inertia.span.as_ref()),
            problem: format!("{problem} (principal moments {moments})"),
        };
        for (name, m) in [("ix'", ix), ("iz'", iz)] {
            if !m.is_positive() {
                return Err(unphysical(format!("principal moment {name} <= 0")));
            }
        }
        for (a, b, c, text) in [
            (ix, iy, iz, "ix' + iy < iz'"),
            (ix, iz, iy, "ix' + iz' < iy"),
            (iy, iz, ix, "iy + iz' < ix'"),
        ] {
            if a + b < *c {
                return Err(unphysical(text.to_string()));
            }
        }
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
        // Within the triangle inequalities (checked above) every coefficient lies in [-1, 1].
        let mut values = inertia_coefficients(ix, iy, iz).to_vec();
        values.extend(converted.derivatives.iter().cloned());
        Ok(Aircraft::new(name, values, converted.speed_f64()))
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

/// The qualified key (`derivatives.l_p`) of the entry at byte `offset` of a TOML text that
/// parses: the last key that starts at or before `offset` on the same line, or whose value
/// spans it. `None` when the text does not parse or nothing is there.
fn key_at(text: &str, offset: usize) -> Option<String> {
    let doc = toml_edit::ImDocument::parse(text).ok()?;
    let line = |o: usize| line_col(text, o).0;
    let mut best: Option<(usize, String)> = None;
    let mut stack = vec![(String::new(), entries_of(doc.as_table()))];
    while let Some((prefix, entries)) = stack.pop() {
        for (key, node) in entries {
            let path = if prefix.is_empty() {
                key.name.clone()
            } else {
                format!("{prefix}.{}", key.name)
            };
            let start = key.start();
            // a standard table spans its whole body; only values (and inline tables) count
            let covers = !matches!(node.kind, Kind::Table(_) if node.span.as_ref().is_some_and(|s| text.get(s.start..s.start + 1) == Some("[")))
                && node
                    .span
                    .as_ref()
                    .is_some_and(|s| s.start <= offset && offset < s.end.max(s.start + 1));
            let same_line = start <= offset && line(start) == line(offset);
            if (covers || same_line) && best.as_ref().is_none_or(|(b, _)| start >= *b) {
                best = Some((start, path.clone()));
            }
            if let Kind::Table(inner) = node.kind {
                stack.push((path, inner));
            }
        }
    }
    best.map(|(_, k)| k)
}

/// 1-based line and column (in characters) of a byte offset; never panics.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let mut end = offset.min(text.len());
    while end > 0 && !text.is_char_boundary(end) {
        end -= 1;
    }
    let before = text.get(..end).unwrap_or("");
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before.get(line_start..).unwrap_or("").chars().count() + 1;
    (line, column)
}

// ---------------------------------------------------------------------------------------------
// The document as a small tree with spans, read through toml_edit's public API

/// A key of a TOML table, with its span when the parser has one.
#[derive(Debug)]
struct Key {
    name: String,
    span: Option<Range<usize>>,
}

impl Key {
    /// Byte offset of the key (0 without a span), for ordering keys by position.
    fn start(&self) -> usize {
        self.span.as_ref().map_or(0, |s| s.start)
    }
}

/// A TOML value, with its span when the parser has one.
#[derive(Debug)]
struct Node {
    span: Option<Range<usize>>,
    kind: Kind,
}

#[derive(Debug)]
enum Kind {
    Integer(i64),
    Float(f64),
    String(String),
    Boolean(bool),
    /// An array, with its elements (empty for an array of tables).
    Array(Vec<Node>),
    Datetime,
    Table(Vec<(Key, Node)>),
}

impl Kind {
    fn describe(&self) -> &'static str {
        match self {
            Kind::Integer(_) => "an integer",
            Kind::Float(_) => "a float",
            Kind::String(_) => "a string",
            Kind::Boolean(b) => {
                if *b {
                    "a boolean (`true`)"
                } else {
                    "a boolean (`false`)"
                }
            }
            Kind::Array(_) => "an array",
            Kind::Datetime => "a date-time",
            Kind::Table(_) => "a table",
        }
    }
}

/// The entries of a table (standard, implicit or dotted), in document order.
fn entries_of(table: &toml_edit::Table) -> Vec<(Key, Node)> {
    table
        .iter()
        .filter_map(|(name, item)| {
            let node = item_node(item)?;
            let key = Key {
                name: name.to_string(),
                span: table.key(name).and_then(toml_edit::Key::span),
            };
            Some((key, node))
        })
        .collect()
}

fn item_node(item: &toml_edit::Item) -> Option<Node> {
    use toml_edit::Item;
    match item {
        Item::None => None,
        Item::Value(v) => Some(value_node(v)),
        Item::Table(t) => Some(Node {
            span: t.span(),
            kind: Kind::Table(entries_of(t)),
        }),
        Item::ArrayOfTables(a) => Some(Node {
            span: a.span(),
            kind: Kind::Array(Vec::new()),
        }),
    }
}

fn value_node(value: &toml_edit::Value) -> Node {
    use toml_edit::Value;
    let kind = match value {
        Value::String(s) => Kind::String(s.value().clone()),
        Value::Integer(i) => Kind::Integer(*i.value()),
        Value::Float(x) => Kind::Float(*x.value()),
        Value::Boolean(b) => Kind::Boolean(*b.value()),
        Value::Datetime(_) => Kind::Datetime,
        Value::Array(a) => Kind::Array(a.iter().map(value_node).collect()),
        Value::InlineTable(t) => Kind::Table(
            t.iter()
                .map(|(name, v)| {
                    let key = Key {
                        name: name.to_string(),
                        span: t.key(name).and_then(toml_edit::Key::span),
                    };
                    (key, value_node(v))
                })
                .collect(),
        ),
    };
    Node {
        span: value.span(),
        kind,
    }
}
#[cfg(test)]
mod tests;
