//! How the module runs the library: the work in a thread of its own while the caller's thread
//! waits without the GIL and checks for Ctrl-C, and the library's failures as Python exceptions
//! carrying the command line's messages.

use model::present::failure::Failure;
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::sync::mpsc::{channel, RecvTimeoutError};
use std::time::Duration;

pyo3::create_exception!(
    _core,
    InputError,
    PyValueError,
    "Bad input (a file, key or value): the command line's message, which exits 2."
);

/// How often the waiting thread looks for Ctrl-C.
const POLL: Duration = Duration::from_millis(50);

/// The stack of the worker thread: the exact path recurses over large polynomials, as on the
/// command line's main thread.
const STACK: usize = 64 << 20;

/// `work` run in a thread of its own while this thread waits with the GIL released, so that
/// other Python threads (a Dask worker's) go on. Ctrl-C raises `KeyboardInterrupt` at once;
/// the abandoned work finishes in the background and its result is dropped.
pub fn detached<T: Send + 'static>(
    py: Python<'_>,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = channel();
    std::thread::Builder::new()
        .name("roll-coupling".into())
        .stack_size(STACK)
        .spawn(move || {
            let _ = tx.send(work());
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start a thread: {e}")))?;
    let mut rx = rx;
    loop {
        let (received, back) = py.detach(move || (rx.recv_timeout(POLL), rx));
        rx = back;
        match received {
            Ok(v) => return Ok(v),
            Err(RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "the computation stopped without a result (a panic: please report it)",
                ))
            }
        }
    }
}

/// A failure of a command as the exception Python raises: bad input as [`InputError`], an
/// output not written as `OSError`.
pub fn raised(f: Failure) -> PyErr {
    match f {
        Failure::Input(msg) => InputError::new_err(msg),
        Failure::Output(msg) => PyOSError::new_err(msg),
        Failure::Closed => PyOSError::new_err("output closed"),
    }
}

/// `value` as the Python objects of its JSON (dicts, lists, floats bit for bit; a non-finite
/// number, which JSON cannot carry, as `None`, as the command line prints it).
pub fn to_python<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let json = serde_json::to_value(value).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    pythonize::pythonize(py, &json).map_err(|e| PyRuntimeError::new_err(e.to_string()))
}
