//! The commands `analyze`, `continue`, `simulate`, `clear`, `convert` and `import jsbsim` (with
//! its `--list`) for Python: the options filled in as the command line's parser fills them (the same defaults, checked by the
//! same functions, refused with the same messages), the result as its JSON's objects.

use crate::aircraft::load;
use crate::run::{detached, raised, to_python};
use model::present::commands::{
    diagram_of, history_of, routed_analysis_of, runs_of, steady_window, Routed,
};
use model::present::options::{AnalyzeArgs, ClearArgs, ContinueArgs, SimulateArgs};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `model analyze AIRCRAFT --json`: the exact path's numbers (the certified route's with
/// `certified`).
#[pyfunction]
#[pyo3(signature = (aircraft, toml=false, delta_e_deg=None, certified=false))]
pub fn analyze<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    delta_e_deg: Option<f64>,
    certified: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let ac = load(py, aircraft, toml)?;
    let args = AnalyzeArgs {
        aircraft: aircraft.to_string(),
        delta_e_deg,
        json: true,
        exact: false,
        certified,
        all: false,
    };
    let (result, route) = detached(py, move || routed_analysis_of(&ac, &args))?.map_err(raised)?;
    to_python(py, &Routed::new(&result, route))
}

/// `model continue AIRCRAFT --json`.
#[pyfunction]
#[pyo3(signature = (aircraft, toml=false, param="delta_a".to_string(), min_deg=-45.8366, max_deg=45.8366, delta_e_deg=None, zero_sideslip=false))]
#[allow(clippy::too_many_arguments)]
pub fn continue_<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    param: String,
    min_deg: f64,
    max_deg: f64,
    delta_e_deg: Option<f64>,
    zero_sideslip: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let ac = load(py, aircraft, toml)?;
    let args = ContinueArgs {
        aircraft: aircraft.to_string(),
        param,
        min_deg,
        max_deg,
        delta_e_deg,
        zero_sideslip,
        json: true,
        csv: None,
    };
    let result = detached(py, move || diagram_of(&ac, &args, &mut |_| {}))?.map_err(raised)?;
    to_python(py, &result)
}

/// `model simulate AIRCRAFT --delta-a-deg D`: the time history (the CSV's columns), the model
/// integrated and the steady values the command prints.
#[pyfunction]
#[pyo3(signature = (aircraft, delta_a_deg, toml=false, delta_e_deg=None, t_end=20.0, zero_sideslip=false, pss=false))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    aircraft: &str,
    delta_a_deg: f64,
    toml: bool,
    delta_e_deg: Option<f64>,
    t_end: f64,
    zero_sideslip: bool,
    pss: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let ac = load(py, aircraft, toml)?;
    let name = ac.name.clone();
    let args = SimulateArgs {
        aircraft: aircraft.to_string(),
        delta_a_deg,
        delta_e_deg,
        t_end,
        zero_sideslip,
        pss,
        csv: None,
        six_dof: false,
        altitude_m: None,
        mach: None,
        load_factor: None,
        thrust: "off".to_string(),
        dt: None,
        out: None,
    };
    let (history, model) = detached(py, move || history_of(&ac, &args))?.map_err(raised)?;
    let steady = history.steady(steady_window(t_end));
    let out = to_python(py, &history)?;
    let dict = out.cast::<PyDict>()?;
    dict.set_item("aircraft", name)?;
    dict.set_item("model", model.name())?;
    dict.set_item("steady", to_python(py, &steady)?)?;
    Ok(out)
}

/// `model clear AIRCRAFT --json`: one run, or a list of runs with `delta_e_range`.
#[pyfunction]
#[pyo3(signature = (aircraft, toml=false, delta_e_deg=None, delta_e_range=None, samples=1000, tolerance=1e-3, seed=1))]
#[allow(clippy::too_many_arguments)]
pub fn clear<'py>(
    py: Python<'py>,
    aircraft: &str,
    toml: bool,
    delta_e_deg: Option<f64>,
    delta_e_range: Option<String>,
    samples: usize,
    tolerance: f64,
    seed: u64,
) -> PyResult<Bound<'py, PyAny>> {
    let ac = load(py, aircraft, toml)?;
    let args = ClearArgs {
        aircraft: aircraft.to_string(),
        delta_e_deg,
        delta_e_range,
        samples,
        tolerance,
        seed,
        json: true,
        out: None,
    };
    let runs = detached(py, move || runs_of(&ac, &args, &mut |_| {}))?.map_err(raised)?;
    if runs.len() == 1 {
        to_python(py, &runs[0])
    } else {
        to_python(py, &runs)
    }
}

/// `model import jsbsim` of the `jsbsim:` source `spec`: the aircraft file's text (what the
/// command prints) and the trim it was linearised at (`None` for an angle of attack given).
#[pyfunction]
pub fn import_jsbsim<'py>(py: Python<'py>, spec: &str) -> PyResult<Bound<'py, PyAny>> {
    let request = model::jsbsim::cli::request(spec).map_err(|m| raised(m.into()))?;
    let (text, trim) = detached(py, move || model::jsbsim::import::import_trimmed(&request))?
        .map_err(|m| raised(m.into()))?;
    let trim = trim.map(|t| {
        serde_json::json!({
            "load_factor": t.load_factor,
            "alpha_deg": t.alpha.to_degrees(),
            "elevator": t.elevator,
            "elevator_per_unit_travel": t.per_unit_travel,
            "q_rad_s": t.q,
        })
    });
    to_python(py, &(text, trim))
}

/// `model import jsbsim --list [--analyze] ...` with the words after `jsbsim` in `args`: the
/// catalogue (every model and whether it reads), or with `--analyze` the table of every model
/// analysed at the flight condition in `args`; the text the command prints.
#[pyfunction]
pub fn import_jsbsim_list(py: Python<'_>, args: Vec<String>) -> PyResult<String> {
    let mut all = vec!["jsbsim".to_string()];
    all.extend(args);
    let text = detached(py, move || {
        if all.iter().any(|a| a == "--analyze") {
            model::present::catalogue::table(&all)
        } else {
            model::jsbsim::cli::listing_of(&all)
        }
    })?;
    text.map_err(|m| raised(m.into()))
}

/// `model convert FILE`: the dimensional principal-axis TOML of a nondimensional body-axis
/// file, the text the command prints.
#[pyfunction]
pub fn convert(py: Python<'_>, file: std::path::PathBuf) -> PyResult<String> {
    let text = detached(py, move || model::aircraft::convert_file(&file))?;
    text.map_err(|e| raised(e.to_string().into()))
}
