//! Python bindings of hawser: the extension module `hawser._hawser` of the Python package
//! `hawser` (distribution `hawser-cable`; the Python half is in `python/hawser`).
//!
//! Everything is computed by the core (`hawser::session::Session`, statics, modes) and
//! hawser-io (inputs, overrides, result summaries and writers, the modal analysis); this
//! crate converts between them and Python, releases the GIL while they work, and turns
//! Ctrl-C into the session's stop flag.
#![warn(missing_docs)]
// `!(x > 0.0)` rejects NaN, which `x <= 0.0` would let through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod convert;
mod errors;
mod runner;
mod scenario;
mod session;

use hawser::math::Real;
use pyo3::prelude::*;
use pyo3::types::PyList;
use scenario::{Scenario, close_bar, make_bar, outcome_to_py};
use std::path::PathBuf;

/// Runs `scenarios` (each a `Scenario`) as independent runs on `workers` threads of this
/// process (default: one per core), the GIL released; returns their `Results` in order. Each
/// run is sequential on one thread, so every result is identical bit for bit to the same run
/// done alone. `duration` [s] overrides every scenario's; `out`, a list of folders (one per
/// scenario), writes each run's files. A failed run raises its exception once all have
/// ended, with the list of results (None for the failed) as its `results` attribute; Ctrl-C
/// stops every run and raises `KeyboardInterrupt` likewise.
#[pyfunction]
#[pyo3(signature = (scenarios, workers = None, *, duration = None, out = None, overwrite = false, progress = true))]
fn run_many<'py>(
    py: Python<'py>,
    scenarios: Vec<Bound<'py, Scenario>>,
    workers: Option<usize>,
    duration: Option<Real>,
    out: Option<Vec<PathBuf>>,
    overwrite: bool,
    progress: bool,
) -> PyResult<Bound<'py, PyList>> {
    if let Some(o) = &out
        && o.len() != scenarios.len()
    {
        return Err(pyo3::exceptions::PyValueError::new_err(format!(
            "out has {} folders for {} scenarios",
            o.len(),
            scenarios.len()
        )));
    }
    let mut jobs = Vec::with_capacity(scenarios.len());
    for (i, s) in scenarios.iter().enumerate() {
        let dir = out.as_ref().map(|o| o[i].clone());
        if let Some(d) = &dir {
            scenario::check_output_dir(d, overwrite)?;
        }
        jobs.push(s.get().job(duration, dir)?);
    }
    let workers = workers
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let total: Real = jobs.iter().map(|j| j.duration()).sum();
    let bar = make_bar(py, progress, total, &format!("{} runs", jobs.len()))?;
    let (outcomes, signal) = runner::drive(py, &jobs, workers, bar.as_ref())?;
    close_bar(bar.as_ref())?;
    let results = PyList::empty(py);
    let mut first_error: Option<PyErr> = None;
    for o in outcomes {
        match o.map(|o| outcome_to_py(py, o)) {
            Some(Ok(r)) => results.append(r)?,
            Some(Err(e)) => {
                // A run that stopped with results (a divergence) keeps them in the list.
                let partial = e.value(py).getattr("results").ok();
                results.append(partial)?;
                first_error.get_or_insert(e);
            }
            None => results.append(py.None())?,
        }
    }
    if let Some(e) = signal.or(first_error) {
        e.value(py).setattr("results", &results)?;
        return Err(e);
    }
    Ok(results)
}

/// The extension module.
#[pymodule]
fn _hawser(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Scenario>()?;
    m.add_class::<session::Session>()?;
    m.add_function(wrap_pyfunction!(scenario::load, m)?)?;
    m.add_function(wrap_pyfunction!(run_many, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
