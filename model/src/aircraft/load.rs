//! Loading an aircraft from a hand-written TOML file, exactly, with errors that point at the line.
//!
//! The format is
//!
//! ```toml
//! name = "Aircraft A"   # optional, default: the file stem
//! [inertia]             # either C, D, E ...
//! C = 0.959
//! D = 0.786
//! E = 0.705
//! # ... or ix, iy, iz (any one unit), from which C, D, E are computed exactly
//! [derivatives]         # dimensional, 1/s or 1/s^2, angles in rad
//! z_alpha = -3.0076
//! # ... every key of Param::ALL after C, D, E; n_delta_r is optional (default -1)
//! [flight]              # optional
//! speed = 150.0         # m/s, optional, default DEFAULT_SPEED_M_S
//! ```
//!
//! Every number enters as the exact rational of the decimal the user wrote (through
//! [`f64_to_rational`]); `C = (iz - ix)/iy`, `D = (iy - ix)/iz` and `E = (iz - iy)/ix` are computed
//! in exact rational arithmetic. Every error names the file, the line and column, the key with its
//! table, and what was expected.
//!
//! Line numbers come from the spans of the `toml` crate. Tables created implicitly (by dotted keys
//! such as `derivatives.l_p = 1`) carry no span of their own in `toml` 0.8, which makes
//! `toml::Spanned<T>` fail on them; this module therefore reads the document into its own `Node`
//! tree, which speaks the `Spanned` protocol of `serde_spanned` 0.6 and accepts values without a
//! span as well.

use super::{f64_to_rational, Aircraft, Param, DEFAULT_SPEED_M_S};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};

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
        /// Where the `toml` crate located the error.
        at: Location,
        /// The `toml` crate's message, on one line.
        message: String,
    },
    /// A required table (`[inertia]` or `[derivatives]`) is absent.
    #[error("{at}: missing table `[{table}]`: expected {expected}")]
    MissingTable {
        /// Line 1 of the file.
        at: Location,
        /// The table's name.
        table: String,
        /// What the table must contain.
        expected: String,
    },
    /// A key that must hold a table (`inertia`, `derivatives`, `flight`) holds something else.
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
    /// `l_delta_a = 0`: the aileron has no roll authority.
    #[error(
        "{at}: key `{key}`: expected a nonzero aileron derivative, found `{value}` (with no roll \
         authority the trim aileron deflection delta_a = -(...)/l_delta_a is undefined)"
    )]
    ZeroAileronAuthority {
        /// Where the value is.
        at: Location,
        /// `derivatives.l_delta_a`.
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
}

impl AircraftError {
    /// Where the error is, for every error but [`AircraftError::Io`].
    pub fn location(&self) -> Option<&Location> {
        match self {
            AircraftError::Io { .. } => None,
            AircraftError::Syntax { at, .. }
            | AircraftError::MissingTable { at, .. }
            | AircraftError::NotATable { at, .. }
            | AircraftError::MissingKey { at, .. }
            | AircraftError::UnknownKey { at, .. }
            | AircraftError::WrongType { at, .. }
            | AircraftError::NotFinite { at, .. }
            | AircraftError::ZeroAileronAuthority { at, .. }
            | AircraftError::InertiaSet { at, .. }
            | AircraftError::NonPositiveInertia { at, .. }
            | AircraftError::InvalidSpeed { at, .. } => Some(at),
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
    let text = std::fs::read_to_string(path).map_err(|source| AircraftError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse(&text, &path.display().to_string())
}

/// Parses the TOML text of an aircraft; `file` is the name used in error messages and, without a
/// `name` key, its stem is the aircraft's name.
pub fn parse(text: &str, file: &str) -> Result<Aircraft, AircraftError> {
    let cx = Cx { text, file };
    let root: Node = toml::from_str(text).map_err(|e| AircraftError::Syntax {
        at: cx.at(e.span().as_ref()),
        message: one_line(e.message()),
    })?;
    let Kind::Table(entries) = &root.kind else {
        return Err(AircraftError::Syntax {
            at: cx.at(None),
            message: "the document is not a table".to_string(),
        });
    };

    let mut name = None;
    let mut inertia = None;
    let mut derivatives = None;
    let mut flight = None;
    for (key, value) in entries {
        match key.name.as_str() {
            "name" => match &value.kind {
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
            "inertia" => inertia = Some(cx.table(key, value, &INERTIA_KEYS)?),
            "derivatives" => derivatives = Some(cx.table(key, value, &derivative_keys())?),
            "flight" => flight = Some(cx.table(key, value, &FLIGHT_KEYS)?),
            _ => return Err(cx.unknown("", key)),
        }
    }

    let inertia = inertia.ok_or_else(|| AircraftError::MissingTable {
        at: cx.at(None),
        table: "inertia".to_string(),
        expected: "`[inertia]` with either `C`, `D`, `E` or `ix`, `iy`, `iz`".to_string(),
    })?;
    let derivatives = derivatives.ok_or_else(|| AircraftError::MissingTable {
        at: cx.at(None),
        table: "derivatives".to_string(),
        expected: format!("`[derivatives]` with keys {}", list(&derivative_keys())),
    })?;

    let mut values: Vec<BigRational> = cx.inertia(&inertia)?;
    values.extend(cx.derivatives(&derivatives)?);
    let speed = match flight {
        Some(flight) => cx.flight(&flight)?,
        None => DEFAULT_SPEED_M_S,
    };
    let name = name.unwrap_or_else(|| default_name(file));
    Ok(Aircraft::new(name, values, speed))
}

// ---------------------------------------------------------------------------------------------
// Validation

const TOP_KEYS: [&str; 4] = ["name", "inertia", "derivatives", "flight"];
const INERTIA_KEYS: [&str; 6] = ["C", "D", "E", "ix", "iy", "iz"];
const FLIGHT_KEYS: [&str; 1] = ["speed"];
const OPTIONAL_DERIVATIVE: Param = Param::NDeltaR;
const DEFAULT_N_DELTA_R: i64 = -1;

fn derivative_keys() -> Vec<&'static str> {
    Param::ALL.iter().skip(3).map(|p| p.key()).collect()
}

/// The valid keys of each table, `""` being the top level.
fn tables() -> [(&'static str, Vec<&'static str>); 4] {
    [
        ("", TOP_KEYS.to_vec()),
        ("inertia", INERTIA_KEYS.to_vec()),
        ("derivatives", derivative_keys()),
        ("flight", FLIGHT_KEYS.to_vec()),
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
    let all = tables();
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

struct Cx<'a> {
    text: &'a str,
    file: &'a str,
}

impl Cx<'_> {
    fn at(&self, span: Option<&Range<usize>>) -> Location {
        let (line, column) = span.map_or((1, 1), |s| line_col(self.text, s.start));
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
        let expected = tables()
            .iter()
            .find(|(t, _)| *t == table)
            .map(|(_, keys)| list(keys))
            .unwrap_or_default();
        AircraftError::UnknownKey {
            at: self.at_key(key),
            key: qualified(table, &key.name),
            hint: suggestion(table, &key.name),
            expected,
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
        if let Some((k, _)) = entries
            .iter()
            .find(|(k, _)| !valid.contains(&k.name.as_str()))
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
        match &value.kind {
            Kind::Integer(i) => Ok(Number {
                exact: BigRational::from_integer(BigInt::from(*i)),
                float: *i as f64,
                written,
            }),
            Kind::Float(x) => match f64_to_rational(*x) {
                Some(exact) => Ok(Number {
                    exact,
                    float: *x,
                    written,
                }),
                None => Err(AircraftError::NotFinite {
                    at: self.at_value(key, value),
                    key: qualified(table, &key.name),
                    value: written,
                }),
            },
            other => Err(AircraftError::WrongType {
                at: self.at_value(key, value),
                key: qualified(table, &key.name),
                expected: "a number",
                found: other.describe(),
            }),
        }
    }

    /// C, D, E, given or computed from ix, iy, iz.
    fn inertia(&self, table: &Table<'_>) -> Result<Vec<BigRational>, AircraftError> {
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
            let (first, second) =
                if c.span.as_ref().map(|s| s.start) <= m.span.as_ref().map(|s| s.start) {
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
            out.push(n.exact.clone());
        }
        match out.as_slice() {
            [c, d, e] if moments.is_empty() => Ok(vec![c.clone(), d.clone(), e.clone()]),
            [ix, iy, iz] => Ok(vec![(iz - ix) / iy, (iy - ix) / iz, (iz - iy) / ix]),
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
                None if *p == OPTIONAL_DERIVATIVE => {
                    out.push(BigRational::from_integer(BigInt::from(DEFAULT_N_DELTA_R)));
                }
                None if *p == Param::LDeltaR => out.push(BigRational::zero()),
                None => {
                    return Err(AircraftError::MissingKey {
                        at: self.at(table.span.as_ref()),
                        table: table.name.to_string(),
                        key: qualified(table.name, p.key()),
                        expected: format!("`{} = <number>` in {}", p.key(), p.unit()),
                    })
                }
            }
        }
        Ok(out)
    }

    /// The flight speed, m/s.
    fn flight(&self, table: &Table<'_>) -> Result<f64, AircraftError> {
        let Some((key, value)) = table.get("speed") else {
            return Ok(DEFAULT_SPEED_M_S);
        };
        let n = self.number(table.name, key, value)?;
        if !(n.float > 0.0 && n.float.is_finite()) {
            return Err(AircraftError::InvalidSpeed {
                at: self.at_value(key, value),
                key: qualified(table.name, &key.name),
                value: n.written,
            });
        }
        Ok(n.float)
    }
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
// A TOML tree with spans

// The private protocol by which `toml` 0.8 (through `serde_spanned` 0.6 and `toml_datetime` 0.6)
// hands out spans and date-times. If it ever changes, values merely lose their spans (errors then
// point at line 1) and the tests on line numbers fail.
const SPANNED_NAME: &str = "$__serde_spanned_private_Spanned";
const SPANNED_START: &str = "$__serde_spanned_private_start";
const SPANNED_END: &str = "$__serde_spanned_private_end";
const SPANNED_VALUE: &str = "$__serde_spanned_private_value";
const SPANNED_FIELDS: &[&str] = &[SPANNED_START, SPANNED_END, SPANNED_VALUE];
const DATETIME_FIELD: &str = "$__toml_private_datetime";

/// A key of a TOML table, with its span when the parser has one.
#[derive(Debug)]
struct Key {
    name: String,
    span: Option<Range<usize>>,
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
    Array,
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
            Kind::Array => "an array",
            Kind::Datetime => "a date-time",
            Kind::Table(_) => "a table",
        }
    }
}

impl<'de> Deserialize<'de> for Key {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_struct(SPANNED_NAME, SPANNED_FIELDS, KeyVisitor)
    }
}

struct KeyVisitor;

impl<'de> Visitor<'de> for KeyVisitor {
    type Value = Key;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a key")
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Key, E> {
        Ok(Key {
            name: v.to_string(),
            span: None,
        })
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Key, A::Error> {
        let (mut start, mut end, mut name) = (None, None, None);
        while let Some(field) = map.next_key::<Key>()? {
            match field.name.as_str() {
                SPANNED_START => start = Some(map.next_value::<usize>()?),
                SPANNED_END => end = Some(map.next_value::<usize>()?),
                SPANNED_VALUE => name = Some(map.next_value::<String>()?),
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        let name = name.ok_or_else(|| de::Error::custom("a key without a name"))?;
        let span = match (start, end) {
            (Some(s), Some(e)) => Some(s..e.max(s)),
            (Some(s), None) => Some(s..s),
            _ => None,
        };
        Ok(Key { name, span })
    }
}

impl<'de> Deserialize<'de> for Node {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_struct(SPANNED_NAME, SPANNED_FIELDS, NodeVisitor)
    }
}

/// A value read without asking for its span (the inside of a spanned value).
struct Bare(Node);

impl<'de> Deserialize<'de> for Bare {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(NodeVisitor).map(Bare)
    }
}

struct NodeVisitor;

fn bare(kind: Kind) -> Node {
    Node { span: None, kind }
}

impl<'de> Visitor<'de> for NodeVisitor {
    type Value = Node;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a TOML value")
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Node, E> {
        Ok(bare(Kind::Boolean(v)))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Node, E> {
        Ok(bare(Kind::Integer(v)))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Node, E> {
        match i64::try_from(v) {
            Ok(i) => Ok(bare(Kind::Integer(i))),
            Err(_) => Ok(bare(Kind::Float(v as f64))),
        }
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Node, E> {
        Ok(bare(Kind::Float(v)))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Node, E> {
        Ok(bare(Kind::String(v.to_string())))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Node, A::Error> {
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        Ok(bare(Kind::Array))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Node, A::Error> {
        let Some(first) = map.next_key::<Key>()? else {
            return Ok(bare(Kind::Table(Vec::new())));
        };
        match first.name.as_str() {
            SPANNED_START => {
                let start = map.next_value::<usize>()?;
                let mut end = start;
                let mut value = None;
                while let Some(field) = map.next_key::<Key>()? {
                    match field.name.as_str() {
                        SPANNED_END => end = map.next_value::<usize>()?,
                        SPANNED_VALUE => value = Some(map.next_value::<Bare>()?.0),
                        _ => {
                            map.next_value::<IgnoredAny>()?;
                        }
                    }
                }
                let mut node = value.ok_or_else(|| de::Error::custom("a value without a value"))?;
                node.span = Some(start..end.max(start));
                Ok(node)
            }
            DATETIME_FIELD => {
                map.next_value::<IgnoredAny>()?;
                while map.next_key::<IgnoredAny>()?.is_some() {
                    map.next_value::<IgnoredAny>()?;
                }
                Ok(bare(Kind::Datetime))
            }
            _ => {
                let mut entries = vec![(first, map.next_value::<Node>()?)];
                while let Some(key) = map.next_key::<Key>()? {
                    entries.push((key, map.next_value::<Node>()?));
                }
                Ok(bare(Kind::Table(entries)))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::decimal_to_rational;

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
            "ix = 0.1\niy = 3\niz = 0.7\n",
        );
        let a = parse(&text, FILE).unwrap();
        let q = |s: &str| decimal_to_rational(s).unwrap();
        // C = (iz - ix)/iy = 0.6/3 = 1/5; D = (iy - ix)/iz = 2.9/0.7 = 29/7; E = (iz - iy)/ix = -23
        assert_eq!(*a.exact(Param::C), q("0.2"));
        assert_eq!(*a.exact(Param::D), BigRational::new(29.into(), 7.into()));
        assert_eq!(*a.exact(Param::E), q("-23"));
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
