//! `model envelope` for Python: the whole grid on the local cores, or its plan (every option
//! checked, the points listed) and its points one at a time, for a scheduler such as Dask that
//! spreads them over workers. A worker reads each model once and keeps it for its later points.

use crate::run::{detached, raised, to_python};
use model::envelope::source::Source;
use model::envelope::uncertainty::Uncertainty;
use model::envelope::{Elevator, Point};
use model::jsbsim::import::Loaded;
use model::present::envelope::Plan;
use model::present::options::EnvelopeArgs;
use pyo3::prelude::*;
use std::collections::BTreeMap;
use std::sync::{Arc, LazyLock, Mutex};

/// The options of `model envelope SOURCE --altitude-m H --mach M ...`.
fn args(
    source: &str,
    altitude_m: &str,
    mach: &str,
    load_factor: Option<f64>,
    delta_e_deg: Option<f64>,
    uncertainty: Option<String>,
) -> EnvelopeArgs {
    EnvelopeArgs {
        source: source.to_string(),
        altitude_m: altitude_m.to_string(),
        mach: mach.to_string(),
        load_factor,
        delta_e_deg,
        json: true,
        out: None,
        uncertainty,
        validate: false,
        validate_sample: 0.1,
    }
}

/// `model envelope SOURCE --json` on every local core.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, mach, load_factor=None, delta_e_deg=None, uncertainty=None))]
pub fn envelope<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: &str,
    mach: &str,
    load_factor: Option<f64>,
    delta_e_deg: Option<f64>,
    uncertainty: Option<String>,
) -> PyResult<Bound<'py, PyAny>> {
    let a = args(
        source,
        altitude_m,
        mach,
        load_factor,
        delta_e_deg,
        uncertainty,
    );
    let env =
        detached(py, move || Plan::new(&a).map(|p| p.run(&a.source, &|_| {})))?.map_err(raised)?;
    to_python(py, &env)
}

/// The plan of an envelope, every option checked as the command checks it: its points
/// (altitude m, Mach) in the command's order, the trim's load factor, the elevator increment in
/// rad and the elevator as the JSON names it.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, mach, load_factor=None, delta_e_deg=None, uncertainty=None))]
pub fn envelope_plan<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: &str,
    mach: &str,
    load_factor: Option<f64>,
    delta_e_deg: Option<f64>,
    uncertainty: Option<String>,
) -> PyResult<Bound<'py, PyAny>> {
    let a = args(
        source,
        altitude_m,
        mach,
        load_factor,
        delta_e_deg,
        uncertainty,
    );
    let plan = detached(py, move || Plan::new(&a))?.map_err(raised)?;
    let e = plan.elevator;
    to_python(
        py,
        &serde_json::json!({
            "altitudes_m": plan.grid.altitudes_m.values,
            "machs": plan.grid.machs.values,
            "points": plan.grid.points(),
            "load_factor": e.load_factor,
            "increment_rad": e.increment,
            "elevator": e.to_string(),
            "aircraft": model::envelope::map::aircraft_name(&plan.loaded, source),
        }),
    )
}

/// The models this process has read, by source.
static LOADED: LazyLock<Mutex<BTreeMap<String, Arc<Loaded>>>> = LazyLock::new(Mutex::default);

/// The model of `source`, read on its first use in this process.
fn loaded(source: &str) -> Result<Arc<Loaded>, String> {
    if let Some(l) = LOADED.lock().map_err(|e| e.to_string())?.get(source) {
        return Ok(Arc::clone(l));
    }
    let l = Arc::new(Source::parse(source)?.load()?);
    LOADED
        .lock()
        .map_err(|e| e.to_string())?
        .insert(source.to_string(), Arc::clone(&l));
    Ok(l)
}

/// One point of an envelope planned by [`envelope_plan`]: what the envelope's JSON holds for
/// it.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, mach, load_factor, increment_rad, uncertainty=None))]
pub fn envelope_point<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: f64,
    mach: f64,
    load_factor: f64,
    increment_rad: f64,
    uncertainty: Option<String>,
) -> PyResult<Bound<'py, PyAny>> {
    let source = source.to_string();
    let point = detached(py, move || -> Result<Point, String> {
        let l = loaded(&source)?;
        let u = uncertainty.as_deref().map(Uncertainty::parse).transpose()?;
        let elevator = Elevator {
            load_factor,
            increment: increment_rad,
        };
        Ok(Point::cleared_at(
            &l,
            &source,
            (altitude_m, mach),
            elevator,
            u.as_ref(),
        ))
    })?
    .map_err(|m| raised(m.into()))?;
    to_python(py, &point)
}
