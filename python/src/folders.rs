//! The commands whose product is a folder of files, `report`, `plot` and `validate`, and the
//! 6-DOF `simulate --six-dof`: each writes what the command line writes, where it writes it
//! (the same default folder, replaced whole or not at all), and hands back the folder, the
//! files in it and what the command prints.

use crate::aircraft::load;
use crate::run::{detached, raised, to_python};
use model::files::folder::MARKER;
use model::present::commands::figures_of;
use model::present::options::{FiguresArgs, SimulateArgs, ValidateArgs};
use model::present::six_dof::six_dof_of;
use model::present::validate::validation_of;
use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::{Path, PathBuf};

/// The files under `dir`, paths relative to it, sorted (the folder's marker left out).
fn files_in(dir: &Path) -> Vec<String> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let path = e.path();
            if path.is_dir() {
                stack.push(path);
            } else if e.file_name() != MARKER {
                let rel = path.strip_prefix(dir).unwrap_or(&path);
                found.push(rel.to_string_lossy().into_owned());
            }
        }
    }
    found.sort();
    found
}

/// `{"folder": ..., "files": [...]}` of a written folder.
fn written<'py>(py: Python<'py>, folder: &Path) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("folder", folder.display().to_string())?;
    dict.set_item("files", files_in(folder))?;
    Ok(dict)
}

/// `model report AIRCRAFT` (`summary`) or `model plot AIRCRAFT`: the folder, its files and the
/// sections skipped; a file that cannot be written raises `OSError` naming it.
fn figures<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    out: Option<PathBuf>,
    delta_e_deg: Option<f64>,
    summary: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let ac = load(py, aircraft, toml)?;
    // A TOML text names the default folder by the aircraft's name.
    let named = if toml {
        ac.name.clone()
    } else {
        aircraft.to_string()
    };
    let args = FiguresArgs {
        aircraft: named,
        out,
        delta_e_deg,
    };
    let done =
        detached(py, move || figures_of(&ac, &args, summary, &mut |_| {}))?.map_err(raised)?;
    if !done.failed.is_empty() {
        return Err(PyOSError::new_err(done.failed.join("; ")));
    }
    let dict = written(py, &done.folder)?;
    dict.set_item("skipped", done.skipped)?;
    Ok(dict.into_any())
}

/// `model report AIRCRAFT [--out DIR]`: the report's folder (figures, tables, summary.md and
/// summary.json).
#[pyfunction]
#[pyo3(signature = (aircraft, toml=false, out=None, delta_e_deg=None))]
pub fn report<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    out: Option<PathBuf>,
    delta_e_deg: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    figures(py, aircraft, toml, out, delta_e_deg, true)
}

/// `model plot AIRCRAFT [--out DIR]`: the figures alone.
#[pyfunction]
#[pyo3(signature = (aircraft, toml=false, out=None, delta_e_deg=None))]
pub fn plot<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    out: Option<PathBuf>,
    delta_e_deg: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    figures(py, aircraft, toml, out, delta_e_deg, false)
}

/// `model validate SOURCE`: both models' settled roll rates over the aileron steps, the
/// printed lines, and the folder of the plateau figure.
#[pyfunction]
#[pyo3(signature = (source, altitude_m=None, mach=None, load_factor=None, delta_a_deg=None, t_end=10.0, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn validate<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: Option<f64>,
    mach: Option<f64>,
    load_factor: Option<f64>,
    delta_a_deg: Option<String>,
    t_end: f64,
    out: Option<PathBuf>,
) -> PyResult<Bound<'py, PyAny>> {
    let args = ValidateArgs {
        source: source.to_string(),
        altitude_m,
        mach,
        load_factor,
        delta_a_deg,
        t_end,
        out,
    };
    let v = detached(py, move || validation_of(&args))?.map_err(raised)?;
    let result = to_python(py, &v)?;
    result
        .cast::<PyDict>()?
        .set_item("files", files_in(&v.folder))?;
    Ok(result)
}

/// `model simulate SOURCE --six-dof --delta-a-deg D`: the native 6-DOF's time history (the
/// columns of its `--csv`), the trim it started from and the summary line; with `out` the
/// folder of its figure.
#[pyfunction]
#[pyo3(signature = (source, delta_a_deg, t_end=20.0, altitude_m=None, mach=None, load_factor=None, thrust="off".to_string(), dt=None, out=None, delta_e_deg=None, zero_sideslip=false, pss=false))]
#[allow(clippy::too_many_arguments)]
pub fn simulate_six_dof<'py>(
    py: Python<'py>,
    source: &str,
    delta_a_deg: f64,
    t_end: f64,
    altitude_m: Option<f64>,
    mach: Option<f64>,
    load_factor: Option<f64>,
    thrust: String,
    dt: Option<f64>,
    out: Option<PathBuf>,
    delta_e_deg: Option<f64>,
    zero_sideslip: bool,
    pss: bool,
) -> PyResult<Bound<'py, PyAny>> {
    // The 7th-order model's options are passed on so that the 6-DOF refuses them by name.
    let args = SimulateArgs {
        aircraft: source.to_string(),
        delta_a_deg,
        delta_e_deg,
        t_end,
        zero_sideslip,
        pss,
        csv: None,
        six_dof: true,
        altitude_m,
        mach,
        load_factor,
        thrust,
        dt,
        out: out.clone(),
    };
    let run = detached(py, move || six_dof_of(&args))?.map_err(raised)?;
    let h = &run.history;
    let dict = PyDict::new(py);
    for (name, v) in [
        ("t", &h.t),
        ("alpha", &h.alpha),
        ("beta", &h.beta),
        ("p", &h.p),
        ("q", &h.q),
        ("r", &h.r),
        ("speed", &h.speed),
        ("altitude", &h.altitude),
        ("mach", &h.mach),
        ("phi", &h.phi),
        ("theta", &h.theta),
        ("psi", &h.psi),
    ] {
        dict.set_item(name, v.clone())?;
    }
    dict.set_item("model", "6-DOF")?;
    dict.set_item("jsbsim_aileron", h.settings.map_or(0.0, |s| s.aileron))?;
    dict.set_item("thrust_lbs", h.thrust_lbs)?;
    let t = &run.trim;
    let trim = serde_json::json!({
        "load_factor": t.load_factor,
        "alpha_deg": t.alpha.to_degrees(),
        "elevator": t.elevator,
        "elevator_per_unit_travel": t.per_unit_travel,
        "q_rad_s": t.q,
    });
    dict.set_item("trim", to_python(py, &trim)?)?;
    dict.set_item("summary", &run.summary)?;
    if let Some(dir) = out {
        dict.set_item("folder", written(py, &dir)?)?;
    }
    Ok(dict.into_any())
}
