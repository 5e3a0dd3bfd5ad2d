//! Rust errors as the package's Python exceptions (defined in `hawser/_errors.py`):
//! `ScenarioError` carries every diagnostic (file, line, column, key, value, expected unit
//! and range, hint) as the command line prints them; `SimulationError` the reason a statics,
//! a run or a coupling step failed.

use hawser_io::scenario::{Diagnostic, ScenarioError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

fn class<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("hawser._errors")?.getattr(name)
}

fn diagnostic<'py>(py: Python<'py>, d: &Diagnostic) -> PyResult<Bound<'py, PyAny>> {
    let kw = PyDict::new(py);
    kw.set_item("message", &d.message)?;
    kw.set_item("file", d.file.display().to_string())?;
    kw.set_item("line", d.line)?;
    kw.set_item("column", d.column)?;
    kw.set_item("key", &d.key)?;
    kw.set_item("value", &d.value)?;
    kw.set_item("expected", &d.expected)?;
    kw.set_item("hint", &d.hint)?;
    kw.set_item("text", d.to_string())?;
    class(py, "Diagnostic")?.call((), Some(&kw))
}

/// `hawser.ScenarioError` of `e`, its text the command line's.
pub fn scenario_error(py: Python<'_>, e: &ScenarioError) -> PyErr {
    let build = || -> PyResult<PyErr> {
        let diagnostics = e
            .diagnostics
            .iter()
            .map(|d| diagnostic(py, d))
            .collect::<PyResult<Vec<_>>>()?;
        let err = class(py, "ScenarioError")?.call1((e.to_string(), diagnostics))?;
        Ok(PyErr::from_value(err))
    };
    build().unwrap_or_else(|e| e)
}

/// `hawser.SimulationError` with `message`.
pub fn simulation_error(py: Python<'_>, message: impl Into<String>) -> PyErr {
    let message = message.into();
    match class(py, "SimulationError").and_then(|c| c.call1((message,))) {
        Ok(err) => PyErr::from_value(err),
        Err(e) => e,
    }
}

/// A coupling host's error ([`hawser_capi::host::HostError`]) as the Python exception of its
/// class: bad arguments as `ValueError`, calls out of order as `RuntimeError`, the rest as
/// `SimulationError`.
pub fn host_error(py: Python<'_>, e: hawser_capi::host::HostError) -> PyErr {
    use hawser_capi::host::ErrorKind;
    match e.kind {
        ErrorKind::InvalidArgument | ErrorKind::BufferTooSmall => {
            pyo3::exceptions::PyValueError::new_err(e.message)
        }
        ErrorKind::State => pyo3::exceptions::PyRuntimeError::new_err(e.message),
        ErrorKind::Io => pyo3::exceptions::PyOSError::new_err(e.message),
        _ => simulation_error(py, e.message),
    }
}
