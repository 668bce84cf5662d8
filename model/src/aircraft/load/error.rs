//! The error of loading an aircraft file, with the location in the file it names.

use super::inertia::INERTIA_TOLERANCE;
use std::fmt;
use std::path::PathBuf;

/// Where in an aircraft file an error was found (1-based line and column, in characters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file name as given to [`parse`](super::parse) (or the path given to
    /// [`load`](super::load)).
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
    /// Inertias (body-axis, or principal moments given directly) the equations of motion
    /// cannot take: a principal moment <= 0, or inertia coefficients beyond f64.
    #[error(
        "{at}: table `[inertia]`: {problem}; expected principal moments > 0 whose inertia \
         coefficients C, D, E are finite in f64 (moments that break a triangle inequality are \
         analysed, with a warning)"
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
