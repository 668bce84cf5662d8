//! `--uncertainty SPEC` of an envelope: the `[uncertainty]` table added to the aircraft file the
//! import writes at every grid point, read by the aircraft loader exactly as `model clear` reads
//! it (one reader of the widths, their checks and their messages).
//!
//! SPEC is one of
//! - a relative width for every coefficient of `[coefficients]`: `10%`;
//! - a list `KEY=WIDTH,...` of coefficient keys, each width relative (`Cl_p=10%`) or an absolute
//!   half-width in the coefficient's units (`Cn_r=0.02`);
//! - the path of a TOML file whose `[uncertainty]` table is taken as written (relative,
//!   half-width or interval `[lo, hi]`; an interval is the same at every point).
//!
//! A relative width follows each point's nominal coefficient, so the box moves with the
//! envelope; an absolute one keeps its size.
//!
//! ```
//! use model::envelope::uncertainty::Uncertainty;
//!
//! let u = Uncertainty::parse("Cl_p=10%, Cn_r=0.02").unwrap();
//! assert_eq!(u.table(), "\n[uncertainty]\nCl_p = \"10%\"\nCn_r = 0.02\n");
//! // A width that is neither relative nor a number is refused naming it.
//! let e = Uncertainty::parse("Cl_p=wide").unwrap_err();
//! assert!(e.contains("Cl_p=wide"), "{e}");
//! ```

use super::grid::Grid;
use crate::aircraft::convert::Coefficient;
use crate::aircraft::{self, Aircraft, AircraftError};
use crate::jsbsim::condition::Condition;
use crate::jsbsim::import::{given_alpha_file, trimmed_file, Loaded};
use crate::jsbsim::trim::trim;
use std::path::Path;

/// The forms SPEC takes, for messages.
const FORMS: &str = "a relative width for every coefficient (`10%`), a list of coefficient keys \
     `KEY=WIDTH,...` (each `10%` or an absolute half-width such as `0.02`), or the path of a \
     readable TOML file with an `[uncertainty]` table";

/// The uncertainty of every grid point, as an `[uncertainty]` table's text.
#[derive(Clone, Debug, PartialEq)]
pub struct Uncertainty {
    /// SPEC as given.
    pub spec: String,
    /// The table's entries, one `key = value` a line.
    entries: String,
}

impl Uncertainty {
    /// Reads `spec` (see the module's documentation); the error names it and the forms.
    pub fn parse(spec: &str) -> Result<Uncertainty, String> {
        let bad = |why: String| format!("--uncertainty {spec}: {why}");
        let path = Path::new(spec);
        let entries = if path.is_file() {
            from_file(path).map_err(bad)?
        } else if spec.contains('=') {
            from_list(spec).map_err(bad)?
        } else if spec.trim().ends_with('%') {
            from_width(spec.trim()).map_err(bad)?
        } else {
            return Err(bad(format!("not a readable file; expected {FORMS}")));
        };
        Ok(Uncertainty {
            spec: spec.to_string(),
            entries,
        })
    }

    /// The `[uncertainty]` table as appended to an aircraft file.
    pub fn table(&self) -> String {
        format!("\n[uncertainty]\n{}", self.entries)
    }

    /// The aircraft of the nondimensional file `text` (named `name`) with this uncertainty; the
    /// error is the loader's, without the position in the composed text.
    pub fn aircraft(&self, text: &str, name: &str) -> Result<Aircraft, String> {
        aircraft::parse(&(text.to_string() + &self.table()), name).map_err(|e| message(&e))
    }

    /// Refuses, before any work, a SPEC the loader refuses at the grid's first point (an unknown
    /// key, a negative width, a width that flips the aileron's sign...): the import's file there,
    /// at its trim at `load_factor` (or alpha 0 without one), read with and without the table. A
    /// point where the import itself fails says nothing about SPEC and passes.
    pub fn check(
        &self,
        loaded: &Loaded,
        name: &str,
        grid: &Grid,
        load_factor: f64,
    ) -> Result<(), String> {
        let Some(&(h, speed)) = grid.points().first() else {
            return Ok(());
        };
        let Ok(condition) = Condition::new(h, speed) else {
            return Ok(());
        };
        let setup = loaded.setup(condition);
        let file = match trim(&setup, load_factor) {
            Ok(t) => trimmed_file(&setup, &t),
            Err(_) => given_alpha_file(&setup, 0.0),
        };
        let Ok(text) = file else {
            return Ok(());
        };
        if aircraft::parse(&text, name).is_err() {
            return Ok(());
        }
        self.aircraft(&text, name)
            .map(|_| ())
            .map_err(|e| format!("--uncertainty {}: {e}", self.spec))
    }
}

/// The loader's message for `e` without its position (which is in the composed text, not in
/// anything the user wrote).
fn message(e: &AircraftError) -> String {
    let s = e.to_string();
    match e.location() {
        Some(at) => s
            .strip_prefix(&format!("{at}: "))
            .map_or(s.clone(), str::to_string),
        None => s,
    }
}

/// `key = "W%"` for every coefficient.
fn from_width(width: &str) -> Result<String, String> {
    let value = relative(width)?;
    Ok(Coefficient::ALL
        .iter()
        .map(|c| format!("{} = {value}\n", c.key()))
        .collect())
}

/// A relative width as a TOML string; the loader checks the number.
fn relative(width: &str) -> Result<String, String> {
    if width.contains(['"', '\\']) || width.chars().any(char::is_control) {
        return Err(format!("`{width}`: expected a relative width such as 10%"));
    }
    Ok(format!("\"{width}\""))
}

/// The entries of `KEY=WIDTH,...`: each key a bare word (the loader checks that it names a
/// coefficient), written once; each width relative or a finite half-width.
fn from_list(list: &str) -> Result<String, String> {
    let mut seen = Vec::new();
    let mut out = String::new();
    for item in list.split(',') {
        let bad = |why: &str| format!("`{}`: {why}", item.trim());
        let (key, width) = item
            .split_once('=')
            .map(|(k, w)| (k.trim(), w.trim()))
            .ok_or_else(|| bad("expected KEY=WIDTH"))?;
        let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
        if key.is_empty() || !key.chars().all(bare) {
            return Err(bad(
                "expected KEY=WIDTH with KEY a coefficient key such as Cl_p",
            ));
        }
        if seen.contains(&key) {
            return Err(bad("the key is given twice"));
        }
        seen.push(key);
        let value = if width.ends_with('%') {
            relative(width)?
        } else {
            match width.parse::<f64>() {
                Ok(x) if x.is_finite() => format!("{x}"),
                _ => {
                    return Err(bad(
                        "expected a relative width such as 10% or a finite absolute half-width",
                    ))
                }
            }
        };
        out += &format!("{key} = {value}\n");
    }
    Ok(out)
}

/// The entries of the `[uncertainty]` table of the file at `path`, each as written there.
fn from_file(path: &Path) -> Result<String, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read it: {e}"))?;
    let doc = toml_edit::ImDocument::parse(text.as_str())
        .map_err(|e| format!("not TOML: {}", e.message()))?;
    let table = doc
        .get("uncertainty")
        .and_then(toml_edit::Item::as_table_like)
        .ok_or("no `[uncertainty]` table in the file")?;
    let mut out = String::new();
    for (name, _) in table.iter() {
        let (key, item) = table.get_key_value(name).ok_or("a key without its value")?;
        let span = |s: Option<std::ops::Range<usize>>| s.and_then(|r| text.get(r));
        match (item.is_value(), span(key.span()), span(item.span())) {
            (true, Some(k), Some(v)) => out += &format!("{k} = {v}\n"),
            _ => {
                return Err(format!(
                    "key `uncertainty.{name}`: expected a width (\"10%\", a half-width or \
                     [lo, hi])"
                ))
            }
        }
    }
    Ok(out)
}
