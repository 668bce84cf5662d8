//! `model envelope` for Python: the whole grid on the local cores, or its plan (every option
//! checked, the points listed) and its points one at a time, for a scheduler such as Dask that
//! spreads them over workers. A worker reads each model once and keeps it for its later points.

use crate::run::{detached, raised, to_python};
use model::envelope::source::Source;
use model::envelope::uncertainty::Uncertainty;
use model::envelope::{Elevator, Point, SpeedAxis};
use model::jsbsim::import::Loaded;
use model::present::envelope::Plan;
use model::present::failure::Failure;
use model::present::options::EnvelopeArgs;
use pyo3::prelude::*;
use std::collections::BTreeMap;
use std::sync::{Arc, LazyLock, Mutex};

/// The grid's options of `model envelope`: `--altitude-m`, and `--mach` or `--speed` (the
/// plan refuses both or neither, as the command does).
struct Axes {
    altitude_m: String,
    mach: Option<String>,
    speed: Option<String>,
}

/// The options of `model envelope SOURCE --altitude-m H (--mach M | --speed V) ... --json`;
/// `validate_sample` (`--validate-sample`) only with `validate`, as the command requires.
fn args(
    source: &str,
    axes: Axes,
    (load_factor, delta_e_deg): (Option<f64>, Option<f64>),
    uncertainty: Option<String>,
    (validate, validate_sample): (bool, Option<f64>),
) -> Result<EnvelopeArgs, Failure> {
    if validate_sample.is_some() && !validate {
        return Err(Failure::Input(
            "--validate-sample needs --validate (validate=True)".to_string(),
        ));
    }
    Ok(EnvelopeArgs {
        source: source.to_string(),
        altitude_m: axes.altitude_m,
        mach: axes.mach,
        speed: axes.speed,
        load_factor,
        delta_e_deg,
        json: true,
        out: None,
        uncertainty,
        validate,
        validate_sample: validate_sample.unwrap_or(0.1),
    })
}

/// `model envelope SOURCE --json` on every local core, with `--validate` the 6-DOF's verdicts.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, mach=None, speed=None, load_factor=None, delta_e_deg=None, uncertainty=None, validate=false, validate_sample=None))]
#[allow(clippy::too_many_arguments)]
pub fn envelope<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: String,
    mach: Option<String>,
    speed: Option<String>,
    load_factor: Option<f64>,
    delta_e_deg: Option<f64>,
    uncertainty: Option<String>,
    validate: bool,
    validate_sample: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let axes = Axes {
        altitude_m,
        mach,
        speed,
    };
    let source = source.to_string();
    let env = detached(py, move || {
        let a = args(
            &source,
            axes,
            (load_factor, delta_e_deg),
            uncertainty,
            (validate, validate_sample),
        )?;
        Plan::new(&a).map(|p| p.run(&a.source, &|_| {}))
    })?
    .map_err(raised)?;
    to_python(py, &env)
}

/// The plan of an envelope, every option checked as the command checks it: its speed axis
/// (`"mach"` or `"speed_m_s"`), its points (altitude m, value on the speed axis) in the
/// command's order, the trim's load factor, the elevator increment in rad and the elevator as
/// the JSON names it.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, mach=None, speed=None, load_factor=None, delta_e_deg=None, uncertainty=None))]
#[allow(clippy::too_many_arguments)]
pub fn envelope_plan<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: String,
    mach: Option<String>,
    speed: Option<String>,
    load_factor: Option<f64>,
    delta_e_deg: Option<f64>,
    uncertainty: Option<String>,
) -> PyResult<Bound<'py, PyAny>> {
    let axes = Axes {
        altitude_m,
        mach,
        speed,
    };
    let name = source.to_string();
    let plan = detached(py, move || {
        let a = args(
            &name,
            axes,
            (load_factor, delta_e_deg),
            uncertainty,
            (false, None),
        )?;
        Plan::new(&a)
    })?
    .map_err(raised)?;
    let e = plan.elevator;
    to_python(
        py,
        &serde_json::json!({
            "speed_axis": plan.grid.axis,
            "altitudes_m": plan.grid.altitudes_m.values,
            "speeds": plan.grid.speeds.values,
            "points": plan.grid.pairs(),
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

/// The speed axis named as the envelope's JSON names it (`speed_axis`).
fn speed_axis(name: &str) -> Result<SpeedAxis, String> {
    match name {
        "mach" => Ok(SpeedAxis::Mach),
        "speed_m_s" => Ok(SpeedAxis::TrueAirspeed),
        _ => Err(format!(
            "speed_axis {name:?}: expected \"mach\" or \"speed_m_s\""
        )),
    }
}

/// One point of an envelope planned by [`envelope_plan`]: what the envelope's JSON holds for
/// it. `speed` is the point's value on the plan's `speed_axis`.
#[pyfunction]
#[pyo3(signature = (source, altitude_m, speed, load_factor, increment_rad, uncertainty=None, speed_axis="mach"))]
#[allow(clippy::too_many_arguments)]
pub fn envelope_point<'py>(
    py: Python<'py>,
    source: &str,
    altitude_m: f64,
    speed: f64,
    load_factor: f64,
    increment_rad: f64,
    uncertainty: Option<String>,
    speed_axis: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let source = source.to_string();
    let axis = speed_axis.to_string();
    let point = detached(py, move || -> Result<Point, String> {
        let axis = self::speed_axis(&axis)?;
        let l = loaded(&source)?;
        let u = uncertainty.as_deref().map(Uncertainty::parse).transpose()?;
        let elevator = Elevator {
            load_factor,
            increment: increment_rad,
        };
        Ok(Point::cleared_at(
            &l,
            &source,
            (altitude_m, axis.speed(speed)),
            elevator,
            u.as_ref(),
        ))
    })?
    .map_err(|m| raised(m.into()))?;
    to_python(py, &point)
}
