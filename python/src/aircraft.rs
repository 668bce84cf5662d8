//! The aircraft argument of the module's functions: `A`/`B`, a file path or a `jsbsim:` source
//! as the command line reads them, or the text of an aircraft TOML file (the Python package
//! turns a dict of the file's keys into that text).

use model::aircraft::{self, Aircraft};
use model::present::options::read_aircraft;
use pyo3::exceptions::PyUserWarning;
use pyo3::prelude::*;

/// The name the loader's messages give a TOML text passed in from Python.
pub const TEXT: &str = "<aircraft TOML>";

/// The aircraft of `arg` (a name, path or source when `toml` is false, else the text of an
/// aircraft file), its warnings raised as Python `UserWarning`s, or the CLI's message.
pub fn load(py: Python<'_>, arg: &str, toml: bool) -> PyResult<Aircraft> {
    let loaded = if toml {
        aircraft::parse(arg, TEXT).map_err(|e| e.to_string())
    } else {
        let arg = arg.to_string();
        super::run::detached(py, move || read_aircraft(&arg))?
    };
    let ac = loaded.map_err(|m| super::run::raised(m.into()))?;
    let category = py.get_type::<PyUserWarning>();
    for w in &ac.warnings {
        PyErr::warn(py, &category, &std::ffi::CString::new(w.as_str())?, 1)?;
    }
    Ok(ac)
}
