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
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::str::FromStr;

mod inertia;
mod scale;
mod uncertainty;

use inertia::INERTIA_TOLERANCE;

/// Where in an aircraft file an error was found (1-based line and column, in characters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file name as given to [`parse`] (or the path given to [`load`]).
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, counted in characters.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// What the two formats consist of, for messages about mixing them.
const FORMATS: &str = "either the dimensional principal-axis format (`[inertia]` C, D, E or ix, \
     iy, iz, and `[derivatives]`) or the nondimensional body-axis format (`[flight]` speed and \
     density or altitude, `[geometry]`, `[inertia]` ix, iy, iz, ixz, and `[coefficients]`)";

/// Why an aircraft file could not be loaded. Every message names the file, the line and column,
/// the key (with its table, e.g. `derivatives.l_p`) and what was expected.
#[derive(Debug, thiserror::Error)]
pub enum AircraftError {
    /// The file could not be read (missing, unreadable, not UTF-8).
    #[error("{}: cannot read the aircraft file: {source} (expected a readable UTF-8 TOML file)", path.display())]
    Io {
        /// The path that was given.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The text is not valid TOML.
    #[error("{at}: TOML syntax error: {message}")]
    Syntax {
        /// Where the parser located the error.
        at: Location,
        /// The parser's message, on one line.
        message: String,
    },
    /// A control character (NUL, ...) that TOML allows nowhere.
    #[error(
        "{at}: {place}: expected printable text (TOML allows no control character but tab in \
         keys, strings and comments), found {found}"
    )]
    ControlCharacter {
        /// Where the character is.
        at: Location,
        /// The key whose line or value holds it (`key `name``), or `line N`.
        place: String,
        /// The character, e.g. `U+0000 (NUL)`.
        found: String,
    },
    /// A required table (`[inertia]`, `[derivatives]`, ...) is absent.
    #[error("{at}: missing table `[{table}]`: expected {expected}")]
    MissingTable {
        /// Line 1 of the file.
        at: Location,
        /// The table's name.
        table: String,
        /// What the table must contain.
        expected: String,
    },
    /// A key that must hold a table (`inertia`, `derivatives`, `flight`, ...) holds something else.
    #[error("{at}: key `{key}`: expected a table `[{key}]` with keys {expected}, found {found}")]
    NotATable {
        /// Where the value is.
        at: Location,
        /// The key.
        key: String,
        /// The keys the table takes.
        expected: String,
        /// What was found instead.
        found: &'static str,
    },
    /// A required key is absent from its table.
    #[error("{at}: missing required key `{key}` in table `[{table}]`: expected {expected}")]
    MissingKey {
        /// The header of the table.
        at: Location,
        /// The table.
        table: String,
        /// The missing key, with its table (`derivatives.l_p`).
        key: String,
        /// What the key must hold.
        expected: String,
    },
    /// A key the format does not know.
    #[error("{at}: unknown key `{key}`{}; expected one of {expected}", hint_suffix(.hint))]
    UnknownKey {
        /// Where the key is.
        at: Location,
        /// The key, with its table.
        key: String,
        /// A suggestion: the closest valid key, or the table the key belongs in.
        hint: Option<String>,
        /// The valid keys of the table.
        expected: String,
    },
    /// A value of the wrong type (a string where a number is expected, ...).
    #[error("{at}: key `{key}`: expected {expected}, found {found}")]
    WrongType {
        /// Where the value is.
        at: Location,
        /// The key, with its table.
        key: String,
        /// The expected type, e.g. "a number".
        expected: &'static str,
        /// What was found, e.g. "a string".
        found: &'static str,
    },
    /// `nan`, `inf` or `-inf` where a finite number is expected.
    #[error("{at}: key `{key}`: expected a finite number, found `{value}`")]
    NotFinite {
        /// Where the value is.
        at: Location,
        /// The key, with its table.
        key: String,
        /// The value as written.
        value: String,
    },
    /// A number outside the range this key accepts (out of range of f64 or i64, not positive,
    /// an altitude outside the ISA troposphere, ...).
    #[error("{at}: key `{key}`: expected {expected}, found `{value}`")]
    InvalidValue {
        /// Where the value is.
        at: Location,
        /// The key, with its table.
        key: String,
        /// What the key accepts.
        expected: String,
        /// The value as written (shortened when long).
        value: String,
    },
    /// `l_delta_a = 0`: the aileron has no roll authority.
    #[error(
        "{at}: key `{key}`: expected a nonzero aileron derivative, found `{value}` (with no roll \
         authority the trim aileron deflection delta_a = -(...)/l_delta_a is undefined)"
    )]
    ZeroAileronAuthority {
        /// Where the value is.
        at: Location,
        /// `derivatives.l_delta_a` (or `coefficients.Cl_delta_a`).
        key: String,
        /// The value as written.
        value: String,
    },
    /// `[inertia]` does not hold exactly one complete set: `C`, `D`, `E` or `ix`, `iy`, `iz`.
    #[error(
        "{at}: table `[inertia]`: {problem}; expected either `C`, `D`, `E` (inertia coefficients) \
         or `ix`, `iy`, `iz` (moments of inertia), all three of one set and none of the other"
    )]
    InertiaSet {
        /// The offending key, or the table header.
        at: Location,
        /// What is wrong, naming the keys.
        problem: String,
    },
    /// A moment of inertia that is zero or negative.
    #[error("{at}: key `{key}`: expected a moment of inertia > 0, found `{value}`")]
    NonPositiveInertia {
        /// Where the value is.
        at: Location,
        /// The key, with its table.
        key: String,
        /// The value as written.
        value: String,
    },
    /// Inertias (body-axis, or principal moments given directly) that are not those of a
    /// rigid body.
    #[error(
        "{at}: table `[inertia]`: {problem}; expected principal moments > 0 that satisfy the \
         triangle inequalities (each at most the sum of the other two)"
    )]
    UnphysicalInertia {
        /// The `[inertia]` header.
        at: Location,
        /// Which condition fails, with the principal moments.
        problem: String,
    },
    /// Inertia coefficients `C`, `D`, `E` that no rigid body has, not even to within the
    /// rounding of tabled data (see `load/inertia.rs`).
    #[error(
        "{at}: table `[inertia]`: {problem}; expected `C`, `D`, `E` each within \
         {INERTIA_TOLERANCE} of those of one rigid body (C = (iz - ix)/iy and D = (iy - ix)/iz \
         fix iy/ix = (1 + D)/(1 - C D) and iz/ix = (1 + C)/(1 - C D), and so E; data rounded to \
         three decimals, as in Table A.1, are within it), or the moments `ix`, `iy`, `iz`"
    )]
    InconsistentInertia {
        /// The key of the coefficient that does not fit (`E`, or `D` for C = D = 1).
        at: Location,
        /// The coefficients as written and what C and D imply.
        problem: String,
    },
    /// A flight speed that is zero or negative.
    #[error("{at}: key `{key}`: expected a speed in m/s > 0, found `{value}`")]
    InvalidSpeed {
        /// Where the value is.
        at: Location,
        /// `flight.speed`.
        key: String,
        /// The value as written.
        value: String,
    },
    /// Tables or keys of the two formats in one file.
    #[error("{at}: {problem}; expected {FORMATS}, not a mix")]
    MixedFormats {
        /// The key that mixes the formats.
        at: Location,
        /// What is mixed, naming the keys.
        problem: String,
    },
    /// `convert` was given a file that is already dimensional.
    #[error(
        "{at}: expected a nondimensional body-axis file (with `[geometry]` and \
         `[coefficients]`) to convert; this file is already in the dimensional principal-axis \
         format"
    )]
    AlreadyDimensional {
        /// Line 1 of the file.
        at: Location,
    },
}

impl AircraftError {
    /// Where the error is, for every error but [`AircraftError::Io`].
    pub fn location(&self) -> Option<&Location> {
        match self {
            AircraftError::Io { .. } => None,
            AircraftError::Syntax { at, .. }
            | AircraftError::ControlCharacter { at, .. }
            | AircraftError::MissingTable { at, .. }
            | AircraftError::NotATable { at, .. }
            | AircraftError::MissingKey { at, .. }
            | AircraftError::UnknownKey { at, .. }
            | AircraftError::WrongType { at, .. }
            | AircraftError::NotFinite { at, .. }
            | AircraftError::InvalidValue { at, .. }
            | AircraftError::ZeroAileronAuthority { at, .. }
            | AircraftError::InertiaSet { at, .. }
            | AircraftError::NonPositiveInertia { at, .. }
            | AircraftError::UnphysicalInertia { at, .. }
            | AircraftError::InconsistentInertia { at, .. }
            | AircraftError::InvalidSpeed { at, .. }
            | AircraftError::MixedFormats { at, .. }
            | AircraftError::AlreadyDimensional { at } => Some(at),
        }
    }
}

fn hint_suffix(hint: &Option<String>) -> String {
    match hint {
        Some(h) => format!(" ({h})"),
        None => String::new(),
    }
}

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

/// Levenshtein distance over characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = Vec::with_capacity(b.len() + 1);
        cur.push(i + 1);
        for (j, cb) in b.iter().enumerate() {
            let substitute =
                prev.get(j).copied().unwrap_or(usize::MAX - 1) + usize::from(ca != *cb);
            let delete = prev.get(j + 1).copied().unwrap_or(usize::MAX - 1) + 1;
            let insert = cur.last().copied().unwrap_or(usize::MAX - 1) + 1;
            cur.push(substitute.min(delete).min(insert));
        }
        prev = cur;
    }
    prev.last().copied().unwrap_or(0)
}

/// A hint for an unknown key in `table`: the same key in another case, the table it belongs in,
/// or the closest valid key within edit distance 2.
fn suggestion(table: &str, key: &str) -> Option<String> {
    let lower = key.to_lowercase();
    let all = tables_of_format();
    let own: &[&str] = all
        .iter()
        .find(|(t, _)| *t == table)
        .map_or(&[], |(_, keys)| keys.as_slice());
    if let Some(k) = own.iter().find(|k| k.to_lowercase() == lower) {
        return Some(format!("did you mean `{k}`?"));
    }
    for (other, keys) in &all {
        if *other == table {
            continue;
        }
        if let Some(k) = keys.iter().find(|k| k.to_lowercase() == lower) {
            return Some(if other.is_empty() {
                format!("`{k}` belongs at the top level, before any table")
            } else {
                format!("`{k}` belongs in the `[{other}]` table")
            });
        }
    }
    suggestion_among(own, key)
}

/// The closest of `own` to `key` within edit distance 2 (ignoring case), as a hint.
fn suggestion_among(own: &[&str], key: &str) -> Option<String> {
    let lower = key.to_lowercase();
    own.iter()
        .map(|k| (edit_distance(&lower, &k.to_lowercase()), *k))
        .filter(|(d, _)| *d <= 2)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| format!("did you mean `{k}`?"))
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
mod tests {
    use super::*;

    const GOOD: &str = r#"name = "T"
[inertia]
C = 0.959
D = 0.786
E = 0.705
[derivatives]
z_alpha = -3.0076
y_beta = -0.0558
l_p = -21.7529
l_r = 1.5207
l_beta = -110.45
l_delta_a = -327.28
m_q = -1.815
m_alpha = -13.52504
m_delta_e = -33.268
n_p = 0
n_r = -0.2608
n_beta = 3.716
n_delta_a = 0.0
[flight]
speed = 150.0
"#;

    const FILE: &str = "test_plane.toml";

    /// Parses `text`, expects an error, and checks the message holds the file, the line, and
    /// every one of `needles`.
    fn err(text: &str, line: usize, needles: &[&str]) -> AircraftError {
        let e = match parse(text, FILE) {
            Ok(a) => panic!("expected an error, got {a:?}"),
            Err(e) => e,
        };
        let msg = e.to_string();
        assert!(msg.contains(FILE), "no file name in: {msg}");
        assert!(
            msg.contains(&format!("{FILE}:{line}:")),
            "no line {line} in: {msg}"
        );
        for n in needles {
            assert!(msg.contains(n), "no `{n}` in: {msg}");
        }
        assert_eq!(e.location().map(|l| l.line), Some(line), "{msg}");
        e
    }

    fn replace(from: &str, to: &str) -> String {
        assert!(GOOD.contains(from), "{from}");
        GOOD.replacen(from, to, 1)
    }

    #[test]
    fn good_file_parses() {
        let a = parse(GOOD, FILE).unwrap();
        assert_eq!(a.name, "T");
        assert_eq!(a.speed, 150.0);
        for p in Param::ALL {
            assert_eq!(a.exact(p), Aircraft::a().exact(p), "{p:?}");
        }
    }

    #[test]
    fn paper_files_are_table_a1_exactly() {
        for (text, builtin) in [
            (
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml")),
                Aircraft::a(),
            ),
            (
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/b.toml")),
                Aircraft::b(),
            ),
        ] {
            let a = parse(text, "x.toml").unwrap();
            assert_eq!(a.name, builtin.name);
            assert_eq!(a.speed, builtin.speed);
            for p in Param::ALL {
                assert!(a.exact(p) == builtin.exact(p), "{} {p:?}", builtin.name);
            }
        }
        let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml"));
        let a = load(path).unwrap();
        assert!(Param::ALL
            .iter()
            .all(|&p| a.exact(p) == Aircraft::a().exact(p)));
    }

    #[test]
    fn aircraft_c_parses_with_computed_inertia() {
        let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/c.toml"));
        let c = load(path).unwrap();
        assert_eq!(c.name, "Aircraft C (non-paper test case)");
        assert_eq!(c.speed, 200.0);
        let q = |s: &str| decimal_to_rational(s).unwrap();
        // (6.1 - 1)/5.5, (5.5 - 1)/6.1, (6.1 - 5.5)/1
        assert_eq!(*c.exact(Param::C), q("5.1") / q("5.5"));
        assert_eq!(*c.exact(Param::D), q("4.5") / q("6.1"));
        assert_eq!(*c.exact(Param::E), q("0.6"));
        assert_eq!(*c.exact(Param::Np), q("-0.05"));
        assert_eq!(*c.exact(Param::Lr), q("0.3"));
        assert_eq!(*c.exact(Param::NDeltaR), q("-4"));
    }

    #[test]
    fn moments_of_inertia_give_exact_coefficients() {
        let text = replace(
            "C = 0.959\nD = 0.786\nE = 0.705\n",
            "ix = 0.4\niy = 0.5\niz = 0.7\n",
        );
        let a = parse(&text, FILE).unwrap();
        let q = |s: &str| decimal_to_rational(s).unwrap();
        // C = (iz - ix)/iy = 0.3/0.5 = 3/5; D = (iy - ix)/iz = 0.1/0.7 = 1/7; E = (iz - iy)/ix = 1/2
        assert_eq!(*a.exact(Param::C), q("0.6"));
        assert_eq!(*a.exact(Param::D), BigRational::new(1.into(), 7.into()));
        assert_eq!(*a.exact(Param::E), q("0.5"));
        // 0.1 + 0.2 style binary rounding never enters
        assert_ne!(a.value(Param::D), 0.0);
    }

    #[test]
    fn defaults_name_speed_and_rudder() {
        let text =
            GOOD.replacen("name = \"T\"\n", "", 1)
                .replacen("[flight]\nspeed = 150.0\n", "", 1);
        let a = parse(&text, "dir/my_jet.toml").unwrap();
        assert_eq!(a.name, "my_jet");
        assert_eq!(a.speed, DEFAULT_SPEED_M_S);
        assert_eq!(
            *a.exact(Param::NDeltaR),
            BigRational::from_integer((-1).into())
        );
        let a = parse(&GOOD.replacen("speed = 150.0", "speed = 210", 1), FILE).unwrap();
        assert_eq!(a.speed, 210.0);
        let a = parse(
            &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nn_delta_r = -2.5\n"),
            FILE,
        )
        .unwrap();
        assert_eq!(a.value(Param::NDeltaR), -2.5);
    }

    #[test]
    fn unreadable_file_names_the_path() {
        let e = load(Path::new("/nonexistent/dir/plane.toml")).unwrap_err();
        assert!(matches!(e, AircraftError::Io { .. }));
        let msg = e.to_string();
        assert!(msg.contains("/nonexistent/dir/plane.toml"), "{msg}");
        assert!(msg.contains("expected a readable"), "{msg}");
    }

    #[test]
    fn a_value_cut_off_at_the_end_of_the_file_names_its_key() {
        // The parser stops there without a message of its own.
        let cut = "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\nE = ";
        let e = err(cut, 5, &["inertia.E", "expected a number"]);
        assert!(matches!(e, AircraftError::Syntax { .. }));
        // A cut-off header has the parser's own message.
        let e = err(
            "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\n[deriv",
            5,
            &["table header"],
        );
        assert!(matches!(e, AircraftError::Syntax { .. }));
    }

    #[test]
    fn syntax_error_passes_line_and_column_through() {
        let e = err(
            &replace("l_p = -21.7529", "l_p = -21.75.29"),
            9,
            &["TOML syntax error"],
        );
        assert!(matches!(e, AircraftError::Syntax { .. }));
        // an unclosed array is found where the next line starts
        let e = err(
            &replace("l_r = 1.5207", "l_r = [1.5207"),
            11,
            &["syntax", "expected"],
        );
        assert!(matches!(e, AircraftError::Syntax { .. }));
        // a duplicate key is a syntax error too
        let e = err(&replace("l_r = 1.5207", "l_p = 1.5207"), 10, &["l_p"]);
        assert!(matches!(e, AircraftError::Syntax { .. }));
    }

    #[test]
    fn missing_key_names_table_header_line() {
        let e = err(
            &replace("m_alpha = -13.52504\n", ""),
            6,
            &[
                "derivatives.m_alpha",
                "missing required key",
                "expected `m_alpha = <number>`",
            ],
        );
        assert!(matches!(e, AircraftError::MissingKey { .. }));
        assert_eq!(e.location().map(|l| l.column), Some(1));
    }

    #[test]
    fn unknown_key_suggests_the_closest() {
        let e = err(
            &replace("l_p = -21.7529", "l_pp = -21.7529"),
            9,
            &[
                "unknown key `derivatives.l_pp`",
                "did you mean `l_p`?",
                "expected one of",
            ],
        );
        assert!(matches!(e, AircraftError::UnknownKey { .. }));
        let e = err(
            &replace("name = \"T\"", "nmae = \"T\""),
            1,
            &["`nmae`", "did you mean `name`?"],
        );
        assert!(matches!(e, AircraftError::UnknownKey { .. }));
        let e = err(
            &replace("C = 0.959", "c = 0.959"),
            3,
            &["`inertia.c`", "did you mean `C`?"],
        );
        assert!(matches!(e, AircraftError::UnknownKey { .. }));
        err(
            &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nspeed = 3\n"),
            20,
            &["`derivatives.speed`", "belongs in the `[flight]` table"],
        );
        err(
            &replace("speed = 150.0", "sped = 150.0"),
            21,
            &["`flight.sped`", "did you mean `speed`?"],
        );
        let e = err(
            &replace("l_p = -21.7529", "roll_damping = -21.7529"),
            9,
            &["`derivatives.roll_damping`", "expected one of `z_alpha`"],
        );
        assert!(!e.to_string().contains("did you mean"), "{e}");
        err(
            &format!("{GOOD}[extra]\nx = 1\n"),
            22,
            &["unknown key `extra`"],
        );
    }

    #[test]
    fn non_number_is_rejected() {
        let e = err(
            &replace("l_beta = -110.45", "l_beta = \"-110.45\""),
            11,
            &["derivatives.l_beta", "expected a number, found a string"],
        );
        assert!(matches!(e, AircraftError::WrongType { .. }));
        err(
            &replace("m_q = -1.815", "m_q = true"),
            13,
            &["derivatives.m_q", "expected a number", "boolean"],
        );
        err(
            &replace("m_q = -1.815", "m_q = [-1.815]"),
            13,
            &["derivatives.m_q", "found an array"],
        );
        err(
            &replace("m_q = -1.815", "m_q = 1979-05-27"),
            13,
            &["derivatives.m_q", "found a date-time"],
        );
        err(
            &replace("m_q = -1.815", "m_q = { v = 1 }"),
            13,
            &["derivatives.m_q", "found a table"],
        );
        err(
            &replace("D = 0.786", "D = \"x\""),
            4,
            &["inertia.D", "expected a number"],
        );
        err(
            &replace("speed = 150.0", "speed = \"fast\""),
            21,
            &["flight.speed", "expected a number"],
        );
        err(
            &replace("name = \"T\"", "name = 3"),
            1,
            &["`name`", "expected a string, found an integer"],
        );
    }

    #[test]
    fn nan_is_rejected() {
        let e = err(
            &replace("n_r = -0.2608", "n_r = nan"),
            17,
            &["derivatives.n_r", "expected a finite number", "`nan`"],
        );
        assert!(matches!(e, AircraftError::NotFinite { .. }));
        assert_eq!(e.location().map(|l| l.column), Some(7));
    }

    #[test]
    fn infinity_is_rejected() {
        let e = err(
            &replace("E = 0.705", "E = -inf"),
            5,
            &["inertia.E", "expected a finite number", "`-inf`"],
        );
        assert!(matches!(e, AircraftError::NotFinite { .. }));
        err(
            &replace("speed = 150.0", "speed = +inf"),
            21,
            &["flight.speed", "finite"],
        );
    }

    #[test]
    fn zero_aileron_authority_is_rejected() {
        for zero in ["0", "0.0", "-0.0"] {
            let e = err(
                &replace("l_delta_a = -327.28", &format!("l_delta_a = {zero}")),
                12,
                &[
                    "derivatives.l_delta_a",
                    "expected a nonzero",
                    "roll authority",
                ],
            );
            assert!(matches!(e, AircraftError::ZeroAileronAuthority { .. }));
        }
    }

    #[test]
    fn inertia_sets_must_be_exactly_one_complete_set() {
        let both = replace("E = 0.705\n", "E = 0.705\nix = 1.0\niy = 2\niz = 3\n");
        let e = err(
            &both,
            6,
            &[
                "`inertia.ix` given together with `inertia.C`",
                "expected either",
            ],
        );
        assert!(matches!(e, AircraftError::InertiaSet { .. }));

        let neither = replace("C = 0.959\nD = 0.786\nE = 0.705\n", "");
        let e = err(
            &neither,
            2,
            &["`inertia`", "no inertia given", "expected either"],
        );
        assert!(matches!(e, AircraftError::InertiaSet { .. }));

        let partial = replace("E = 0.705\n", "");
        let e = err(
            &partial,
            2,
            &[
                "missing `inertia.E`",
                "`inertia.C`, `inertia.D`",
                "expected either",
            ],
        );
        assert!(matches!(e, AircraftError::InertiaSet { .. }));

        let partial = replace("C = 0.959\nD = 0.786\nE = 0.705\n", "iz = 2\n");
        err(
            &partial,
            2,
            &["missing `inertia.ix`, `inertia.iy`", "expected either"],
        );
    }

    #[test]
    fn inertias_must_be_positive() {
        for bad in ["0", "-1.5", "0.0"] {
            let text = replace(
                "C = 0.959\nD = 0.786\nE = 0.705\n",
                &format!("ix = 1\niy = {bad}\niz = 3\n"),
            );
            let e = err(
                &text,
                4,
                &["inertia.iy", "expected a moment of inertia > 0", bad],
            );
            assert!(matches!(e, AircraftError::NonPositiveInertia { .. }));
        }
    }

    #[test]
    fn inertias_must_be_those_of_a_rigid_body() {
        // ix + iy < iz (and ratios beyond f64 without the check: E = 0.6 / 1e-309).
        let text = replace(
            "C = 0.959\nD = 0.786\nE = 0.705\n",
            "ix = 1e-309\niy = 5.5\niz = 6.1\n",
        );
        let e = err(
            &text,
            2,
            &["[inertia]", "ix + iy < iz", "triangle inequalities"],
        );
        assert!(matches!(e, AircraftError::UnphysicalInertia { .. }));
        for (bad, key) in [("C = 1.5", "inertia.C"), ("E = -1.01", "inertia.E")] {
            let line = if key == "inertia.C" {
                "C = 0.959"
            } else {
                "E = 0.705"
            };
            err(
                &replace(line, bad),
                if key == "inertia.C" { 3 } else { 5 },
                &[key, "within [-1, 1]", "unphysical"],
            );
        }
    }

    #[test]
    fn inertia_coefficients_no_rigid_body_has_are_refused() {
        // C = D = 0 is ix = iy = iz, so E = 0.
        let e = err(
            &replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 0\nD = 0\nE = 0.9"),
            5,
            &[
                "`inertia.E` = 0.9",
                "C and D imply E = (C - D)/(1 - C D) = 0",
                "within 0.001 of those of one rigid body",
            ],
        );
        assert!(matches!(e, AircraftError::InconsistentInertia { .. }));
        // C = D = 1: iz = ix + iy and iy = ix + iz, so ix = 0 and E = (iz - iy)/ix is undefined.
        let e = err(
            &replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 1\nD = 1\nE = 0.5"),
            4,
            &[
                "`inertia.C` = 1 and `inertia.D` = 1",
                "ix = 0",
                "rigid body",
            ],
        );
        assert!(matches!(e, AircraftError::InconsistentInertia { .. }));
    }

    #[test]
    fn inertia_coefficients_within_rounding_of_a_rigid_body_are_accepted() {
        // Table A.1's A: C and D imply E = 0.7026, E = 0.705 is within its three decimals.
        assert!(parse(GOOD, FILE).is_ok());
        // C = D = 0.5 imply E = 0; C, D within 0.001 reach E = 0.002/0.750001 = 0.00267, so E
        // within 0.001 of that passes and beyond it does not.
        let with_e = |e: &str| {
            replace(
                "C = 0.959\nD = 0.786\nE = 0.705",
                &format!("C = 0.5\nD = 0.5\nE = {e}"),
            )
        };
        assert!(parse(&with_e("0.0036"), FILE).is_ok());
        assert!(parse(&with_e("-0.0036"), FILE).is_ok());
        err(
            &with_e("0.0037"),
            5,
            &["C and D imply E = (C - D)/(1 - C D) = 0"],
        );
        // C = D = -1 is a lamina in the y-z plane (ix = iy + iz): every E in [-1, 1] is one.
        let lamina = replace("C = 0.959\nD = 0.786\nE = 0.705", "C = -1\nD = -1\nE = 0.3");
        assert!(parse(&lamina, FILE).is_ok());
    }

    #[test]
    fn a_speed_whose_g_over_v_leaves_f64_names_flight_speed() {
        for tiny in ["1e-320", "1e-400"] {
            err(
                &replace("speed = 150.0", &format!("speed = {tiny}")),
                21,
                &["key `flight.speed`", "g/V", tiny],
            );
        }
    }

    #[test]
    fn speed_must_be_positive() {
        let e = err(
            &replace("speed = 150.0", "speed = 0"),
            21,
            &["flight.speed", "expected a speed in m/s > 0", "`0`"],
        );
        assert!(matches!(e, AircraftError::InvalidSpeed { .. }));
        err(
            &replace("speed = 150.0", "speed = -3.5"),
            21,
            &["flight.speed", "> 0"],
        );
    }

    #[test]
    fn missing_tables_are_reported_at_line_1() {
        let no_derivatives = GOOD.split("[derivatives]").next().unwrap().to_string();
        let e = err(
            &no_derivatives,
            1,
            &[
                "missing table `[derivatives]`",
                "expected `[derivatives]` with keys `z_alpha`",
            ],
        );
        assert!(matches!(e, AircraftError::MissingTable { .. }));
        let no_inertia = replace("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", "");
        let e = err(
            &no_inertia,
            1,
            &["missing table `[inertia]`", "expected `[inertia]` with"],
        );
        assert!(matches!(e, AircraftError::MissingTable { .. }));
    }

    #[test]
    fn a_table_that_is_not_a_table_is_rejected() {
        let text = format!(
            "inertia = 3\n{}",
            GOOD.replacen("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", "", 1)
        );
        let e = err(
            &text,
            1,
            &[
                "key `inertia`",
                "expected a table `[inertia]`",
                "found an integer",
            ],
        );
        assert!(matches!(e, AircraftError::NotATable { .. }));
        let text = replace("[flight]\nspeed = 150.0\n", "[[flight]]\nspeed = 150.0\n");
        let e = err(
            &text,
            20,
            &["key `flight`", "expected a table", "found an array"],
        );
        assert!(matches!(e, AircraftError::NotATable { .. }));
    }

    #[test]
    fn dotted_and_inline_tables_work_and_keep_lines() {
        let text = "inertia = { ix = 1, iy = 2, iz = 3 }\n\
                    derivatives.z_alpha = -1\nderivatives.y_beta = -1\nderivatives.l_p = -1\n\
                    derivatives.l_r = 0\nderivatives.l_beta = -1\nderivatives.l_delta_a = -1\n\
                    derivatives.m_q = -1\nderivatives.m_alpha = -1\nderivatives.m_delta_e = -1\n\
                    derivatives.n_p = 0\nderivatives.n_r = -1\nderivatives.n_beta = 1\n\
                    derivatives.n_delta_a = 0\n";
        let a = parse(text, FILE).unwrap();
        assert_eq!(*a.exact(Param::E), BigRational::from_integer(1.into()));
        err(
            &text.replace("derivatives.m_q = -1", "derivatives.m_qq = -1"),
            8,
            &["`derivatives.m_qq`", "did you mean `m_q`?"],
        );
        err(
            &text.replace("derivatives.n_p = 0\n", ""),
            2,
            &["missing required key `derivatives.n_p`"],
        );
    }

    #[test]
    fn garbage_never_panics() {
        let inputs = [
            "",
            "\u{feff}",
            "[",
            "= 1",
            "a.b.c.d = 1",
            "[derivatives.l_p.x]\ny = 1",
            "inertia = []\n",
            "derivatives = {}\ninertia = {}",
            "name = \"\"",
            "\"$__serde_spanned_private_start\" = 1",
            "[inertia]\n\"$__toml_private_datetime\" = 1",
            "x = 9223372036854775807\ny = 1e308\nz = 5e-324",
            "[inertia]\nix = 1e308\niy = 5e-324\niz = 1e-300\n",
            "é = 1\nñ = \"ü\"",
        ];
        for text in inputs {
            let r = parse(text, "g.toml");
            if let Err(e) = r {
                assert!(e.to_string().contains("g.toml"), "{e}");
            }
        }
        for (i, _) in GOOD.char_indices() {
            let _ = parse(GOOD.get(..i).unwrap_or(""), "g.toml");
        }
    }

    #[test]
    fn numbers_enter_as_the_literal_written_not_as_an_f64() {
        // 22 significant digits: an f64 cannot hold them, the literal text can.
        let a = parse(
            &replace("l_p = -21.7529", "l_p = -0.1000000000000000000001"),
            FILE,
        )
        .unwrap();
        let q = |s: &str| decimal_to_rational(s).unwrap();
        assert_eq!(*a.exact(Param::Lp), q("-0.1000000000000000000001"));
        assert_ne!(*a.exact(Param::Lp), q("-0.1"));
        // longer than any message shows: every digit counts
        let long = format!("-21.7529{}1", "0".repeat(100));
        let a = parse(&replace("l_p = -21.7529", &format!("l_p = {long}")), FILE).unwrap();
        assert_eq!(*a.exact(Param::Lp), q(&long));
        assert_ne!(*a.exact(Param::Lp), q("-21.7529"));
        // an empty quoted key is unknown, not a table
        err(&format!("\"\" = 1\n{GOOD}"), 1, &["unknown key ``"]);
        // underscores, a plus sign and an exponent
        let a = parse(&replace("l_r = 1.5207", "l_r = +1_5.207e-1"), FILE).unwrap();
        assert_eq!(*a.exact(Param::Lr), q("1.5207"));
        // an exact fraction as a string
        let a = parse(&replace("l_r = 1.5207", "l_r = \"-1/3\""), FILE).unwrap();
        assert_eq!(*a.exact(Param::Lr), BigRational::new((-1).into(), 3.into()));
        for bad in ["\"1/0\"", "\"1.5/2\"", "\"/3\""] {
            err(
                &replace("l_r = 1.5207", &format!("l_r = {bad}")),
                10,
                &["derivatives.l_r", "exact fraction"],
            );
        }
    }

    #[test]
    fn numbers_the_parser_cannot_hold_name_their_key() {
        let e = err(
            &replace("l_p = -21.7529", "l_p = 99999999999999999999"),
            9,
            &[
                "key `derivatives.l_p`",
                "expected an integer within the 64-bit range",
            ],
        );
        assert!(matches!(e, AircraftError::InvalidValue { .. }));
        assert_eq!(e.location().map(|l| l.column), Some(7));
        err(
            &replace("m_q = -1.815", "m_q = 1e309"),
            13,
            &["key `derivatives.m_q`", "range of f64", "`1e309`"],
        );
        let digits = "7".repeat(400);
        let e = err(
            &replace("m_q = -1.815", &format!("m_q = {digits}")),
            13,
            &["key `derivatives.m_q`", "64-bit range", "(400 characters)"],
        );
        assert!(e.to_string().len() < 400, "{e}");
        err(
            &replace("m_q = -1.815", &format!("m_q = {digits}.5")),
            13,
            &["key `derivatives.m_q`", "range of f64"],
        );
        err(
            &replace("speed = 150.0", "speed = -1e400"),
            21,
            &["flight.speed", "finite"],
        );
        // accepted by the parser as 0.0, but the literal is beyond exact reading
        err(
            &replace("m_q = -1.815", "m_q = 1e-100000"),
            13,
            &["derivatives.m_q", "range of f64"],
        );
        // inside an inline table the key is still found
        let text = replace("C = 0.959\nD = 0.786\nE = 0.705\n", "").replacen(
            "[inertia]\n",
            "inertia = { ix = 1, iy = 1e999, iz = 3 }\n",
            1,
        );
        err(&text, 2, &["key `inertia.iy`", "range of f64"]);
    }

    #[test]
    fn control_characters_name_their_key() {
        let e = err(
            &replace("name = \"T\"", "name = \"T\0\""),
            1,
            &["key `name`", "U+0000 (NUL)", "expected printable text"],
        );
        assert!(matches!(e, AircraftError::ControlCharacter { .. }));
        assert_eq!(e.location().map(|l| l.column), Some(10));
        err(
            &replace("l_p = -21.7529", "l_p = -21.7529 # \0"),
            9,
            &["key `derivatives.l_p`", "U+0000"],
        );
        err(
            &replace("[derivatives]\n", "[derivatives]\n# \u{1b}[31m\n"),
            7,
            &["line 7", "U+001B (ESC)"],
        );
    }

    #[test]
    fn an_integer_below_i64_names_its_key_and_range_as_one_above_does() {
        let below = err(
            &replace("l_beta = -110.45", "l_beta = -9223372036854775809"),
            11,
            &[
                "key `derivatives.l_beta`",
                "expected an integer within the 64-bit range (-9223372036854775808 to \
                 9223372036854775807",
                "found `-9223372036854775809`",
            ],
        );
        let above = err(
            &replace("l_beta = -110.45", "l_beta = 9223372036854775808"),
            11,
            &["key `derivatives.l_beta`"],
        );
        let parts = |e: &AircraftError| match e {
            AircraftError::InvalidValue {
                at, key, expected, ..
            } => Some((at.clone(), key.clone(), expected.clone())),
            _ => None,
        };
        assert!(parts(&below).is_some(), "{below}");
        assert_eq!(parts(&below), parts(&above));
    }

    #[test]
    fn a_name_with_escaped_control_characters_is_refused() {
        for (escaped, found) in [
            ("Air\\u0007craft", "Air\\u{7}craft"),
            ("Evil\\u001b[31m", "Evil\\u{1b}[31m"),
            ("two\\nlines", "two\\nlines"),
            ("tab\\there", "tab\\there"),
        ] {
            let e = err(
                &replace("name = \"T\"", &format!("name = \"{escaped}\"")),
                1,
                &[
                    "key `name`",
                    "expected a name without control characters",
                    &format!("found `{found}`"),
                ],
            );
            assert!(matches!(e, AircraftError::InvalidValue { .. }));
        }
    }

    #[test]
    fn a_percentage_is_one_number_and_one_percent_sign() {
        let with = |entry: &str| format!("{GOOD}[uncertainty]\nl_p = {entry}\n");
        let five = parse(&with("\"5%\""), FILE).unwrap().uncertainty;
        for same in ["\" 5 % \"", "\"5 %\"", "\"+5%\""] {
            assert_eq!(
                parse(&with(same), FILE).unwrap().uncertainty,
                five,
                "{same}"
            );
        }
        for bad in ["5%%", "5% junk", "%5", "5%5", "%", "5 % %"] {
            let e = err(
                &with(&format!("\"{bad}\"")),
                23,
                &[
                    "key `uncertainty.l_p`",
                    "one number followed by exactly one `%`",
                    &format!("found `\"{bad}\"`"),
                ],
            );
            assert!(matches!(e, AircraftError::InvalidValue { .. }));
        }
    }

    #[test]
    fn roll_due_to_rudder_is_optional() {
        assert!(parse(GOOD, FILE).unwrap().exact(Param::LDeltaR).is_zero());
        let a = parse(
            &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nl_delta_r = 2.25\n"),
            FILE,
        )
        .unwrap();
        assert_eq!(a.value(Param::LDeltaR), 2.25);
        err(
            &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nl_delta_r = \"x\"\n"),
            20,
            &["derivatives.l_delta_r", "expected a number"],
        );
    }

    #[test]
    fn limits_and_validity_tables() {
        let a = parse(GOOD, FILE).unwrap();
        assert_eq!(a.limits, Limits::default());
        assert_eq!(a.validity, Validity::default());
        assert_eq!(a.validity.alpha_max_deg, 30.0);
        let text =
            format!("{GOOD}[limits]\naileron = 21.5\nrudder = 30\n[validity]\nbeta_max = 12.5\n");
        let a = parse(&text, FILE).unwrap();
        assert_eq!(
            a.limits,
            Limits {
                aileron_deg: Some(21.5),
                elevator_deg: None,
                rudder_deg: Some(30.0),
            }
        );
        assert_eq!(a.validity.alpha_max_deg, 30.0);
        assert_eq!(a.validity.beta_max_deg, 12.5);
        for (bad, needle) in [
            ("0", "> 0"),
            ("-3", "> 0"),
            ("nan", "finite"),
            ("\"x\"", "number"),
        ] {
            err(
                &text.replacen("aileron = 21.5", &format!("aileron = {bad}"), 1),
                23,
                &["limits.aileron", needle],
            );
        }
        err(
            &text.replacen("rudder = 30", "rudder = 0.0", 1),
            24,
            &["limits.rudder", "a deflection limit in degrees > 0"],
        );
        err(
            &text.replacen("beta_max = 12.5", "beta_max = -1", 1),
            26,
            &["validity.beta_max", "an angle in degrees > 0"],
        );
        err(
            &text.replacen("rudder = 30", "flap = 30", 1),
            24,
            &[
                "unknown key `limits.flap`",
                "`aileron`, `elevator`, `rudder`",
            ],
        );
        err(
            &text.replacen("beta_max", "alpha_mx", 1),
            26,
            &[
                "unknown key `validity.alpha_mx`",
                "did you mean `alpha_max`?",
            ],
        );
        err(
            &format!("limits = 3\n{GOOD}"),
            1,
            &["key `limits`", "expected a table"],
        );
    }

    #[test]
    fn dimensional_files_refuse_body_axis_keys() {
        let e = err(
            &replace("E = 0.705\n", "E = 0.705\nixz = 3\n"),
            6,
            &["`inertia.ixz`", "expected either the dimensional"],
        );
        assert!(matches!(e, AircraftError::MixedFormats { .. }));
        err(
            &replace("speed = 150.0", "speed = 150.0\naltitude = 3000"),
            22,
            &["`flight.altitude`", "not a mix"],
        );
        err(
            &format!("{GOOD}[geometry]\nmass = 1\n"),
            22,
            &[
                "table `[geometry]` given together with `[derivatives]`",
                "not a mix",
            ],
        );
    }

    #[test]
    fn helpers() {
        assert_eq!(edit_distance("l_pp", "l_p"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(line_col("ab\ncé\nx", 0), (1, 1));
        assert_eq!(line_col("ab\ncé\nx", 3), (2, 1));
        assert_eq!(line_col("ab\ncé\nx", 5), (2, 2));
        assert_eq!(line_col("ab\ncé\nx", 7), (3, 1));
        assert_eq!(line_col("ab", 99), (1, 3));
    }
}
