//! `roll_coupling._core`: the Python extension module (PyO3) over the library the command line
//! uses. Each function takes the options of one command with the CLI's names and defaults,
//! computes through `model` in a thread of its own (the GIL released, Ctrl-C checked while it
//! waits) and hands back the result as the dicts and lists of the command's JSON. The typed
//! classes and numpy arrays are the Python package's (`roll_coupling/`).

mod aircraft;
mod commands;
mod envelope;
mod folders;
mod run;

use pyo3::prelude::*;

/// The module's functions and its exception.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InputError", m.py().get_type::<run::InputError>())?;
    m.add_function(wrap_pyfunction!(commands::analyze, m)?)?;
    m.add_function(wrap_pyfunction!(commands::continue_, m)?)?;
    m.add_function(wrap_pyfunction!(commands::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(commands::clear, m)?)?;
    m.add_function(wrap_pyfunction!(commands::import_jsbsim, m)?)?;
    m.add_function(wrap_pyfunction!(commands::import_jsbsim_list, m)?)?;
    m.add_function(wrap_pyfunction!(commands::convert, m)?)?;
    m.add_function(wrap_pyfunction!(folders::report, m)?)?;
    m.add_function(wrap_pyfunction!(folders::plot, m)?)?;
    m.add_function(wrap_pyfunction!(folders::validate, m)?)?;
    m.add_function(wrap_pyfunction!(folders::simulate_six_dof, m)?)?;
    m.add_function(wrap_pyfunction!(envelope::envelope, m)?)?;
    m.add_function(wrap_pyfunction!(envelope::envelope_plan, m)?)?;
    m.add_function(wrap_pyfunction!(envelope::envelope_point, m)?)?;
    Ok(())
}
