//! `hawser.Scenario`: a validated input (TOML scenario or MoorDyn deck) with its text, and
//! what can be computed from it: statics, modes, a dynamic run, a coupling session.

use crate::convert::{array_n3, array1, dict_to_table, json_to_py, py_to_toml, table_to_py, vec3};
use crate::errors::{scenario_error, simulation_error};
use crate::runner::{self, Failure, Job, Outcome};
use hawser::math::Real;
use hawser::session::View;
use hawser_io::moordyn::ConvertOptions;
use hawser_io::scenario::overrides::Override;
use hawser_io::scenario::{InputFormat, LoadedScenario};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::{PyFileExistsError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::{Path, PathBuf};

/// A scenario: a hawser TOML scenario or a MoorDyn v2 deck, read and validated.
///
/// Build one with `hawser.load(path)`, `Scenario.from_dict(d)`, `Scenario.from_toml(text)`
/// or `Scenario(text, path)`; vary it with `with_overrides`. It is immutable: every
/// variation is a new scenario, validated as a file is (invalid input raises
/// `hawser.ScenarioError`).
#[pyclass(module = "hawser", frozen)]
pub struct Scenario {
    /// The path the input was read from (or the name given to a text or a dict).
    pub origin: PathBuf,
    /// The input's text (TOML or a MoorDyn deck).
    pub source: String,
    /// A deck's host choices (vessel motion, duration).
    pub deck: ConvertOptions,
    /// The dotted-key overrides applied to the input, in order.
    pub overrides: Vec<Override>,
    /// The name the scenario was validated under (`origin`, or `origin (with overrides)`).
    pub path: PathBuf,
    /// The scenario text validated, when overrides made one (the input's text otherwise).
    text: Option<String>,
    /// The validated scenario.
    pub loaded: LoadedScenario,
    notes: Vec<String>,
}

impl Scenario {
    /// Reads and validates `source` as if read from `origin`, with `overrides` applied.
    pub fn parse(
        py: Python<'_>,
        origin: PathBuf,
        source: String,
        deck: ConvertOptions,
        overrides: Vec<Override>,
    ) -> PyResult<Self> {
        let parsed = py.detach(|| {
            if overrides.is_empty() {
                hawser_io::input::parse_input(&origin, &source, &deck)
                    .map(|(loaded, notes)| (origin.clone(), None, loaded, notes))
            } else {
                hawser_io::input::with_overrides(&origin, &source, &deck, &overrides)
                    .map(|(name, text, loaded)| (name, Some(text), loaded, Vec::new()))
            }
        });
        let (path, text, loaded, notes) = parsed.map_err(|e| scenario_error(py, &e))?;
        let notes = notes
            .iter()
            .map(|n| match n.line {
                0 => n.message.clone(),
                l => format!("line {l}: {}", n.message),
            })
            .collect();
        Ok(Self {
            origin,
            source,
            deck,
            overrides,
            path,
            text,
            loaded,
            notes,
        })
    }

    /// The validated text: the input's, or the scenario with its overrides.
    fn validated_text(&self) -> &str {
        self.text.as_deref().unwrap_or(&self.source)
    }

    /// The job of a run of this scenario.
    pub fn job(&self, duration: Option<Real>, out: Option<PathBuf>) -> PyResult<Job> {
        let mut loaded = self.loaded.clone();
        if let Some(d) = duration {
            if !(d > 0.0 && d.is_finite()) {
                return Err(PyValueError::new_err(format!(
                    "duration = {d} s: expected a positive number of seconds"
                )));
            }
            loaded.model.settings.duration = d;
        } else if !loaded.has_simulation {
            return Err(PyValueError::new_err(format!(
                "{} has no [simulation] table: give run(duration=...) [s], or add \
                 `[simulation]` with `duration = ...`",
                self.path.display()
            )));
        }
        Ok(Job {
            loaded,
            source: self.validated_text().to_string(),
            path: self.path.clone(),
            out,
        })
    }
}

fn deck_options(vessel_motion: Option<PathBuf>, duration: Option<Real>) -> ConvertOptions {
    ConvertOptions {
        duration,
        vessel_motion,
    }
}

/// The path a scenario given as text or a dict is validated under: `name` in `base_dir`
/// (files it names are found there; its diagnostics name it).
fn virtual_path(base_dir: Option<PathBuf>, name: &str) -> PathBuf {
    match base_dir {
        Some(d) => d.join(name),
        None => PathBuf::from(name),
    }
}

/// Reads and validates a hawser scenario (TOML) or a MoorDyn v2 input deck (recognised by
/// its content). For a deck, `vessel_motion` moves its coupled points (a file of t, x, y, z,
/// roll, pitch, yaw in s, m, deg) and `duration` [s] sets its simulated time, as the command
/// line's `--vessel-motion` and `--duration` do.
#[pyfunction]
#[pyo3(signature = (path, *, vessel_motion = None, duration = None))]
pub fn load(
    py: Python<'_>,
    path: PathBuf,
    vessel_motion: Option<PathBuf>,
    duration: Option<Real>,
) -> PyResult<Scenario> {
    let source = py
        .detach(|| hawser_io::scenario::tables::read_text_file(&path))
        .map_err(|e| PyOSError::new_err(format!("cannot read {}: {e}", path.display())))?;
    Scenario::parse(
        py,
        path,
        source,
        deck_options(vessel_motion, duration),
        Vec::new(),
    )
}

/// Overrides from a dict of dotted keys and values (`None`: remove the key).
fn override_list(overrides: &Bound<'_, PyDict>) -> PyResult<Vec<Override>> {
    let mut list = Vec::new();
    for (k, v) in overrides.iter() {
        let key: String = k.extract()?;
        let value = match v.is_none() {
            true => None,
            false => Some(py_to_toml(&v, &key)?),
        };
        list.push((key, value));
    }
    Ok(list)
}

#[pymethods]
impl Scenario {
    /// The scenario of the text `source` (TOML or a MoorDyn deck), validated as if read from
    /// `path` (default `"<text>"` in the working directory): files it names are found beside
    /// `path`, and its diagnostics name it. `vessel_motion` and `duration` are a deck's, as
    /// for `load`; `overrides` are set as by `with_overrides`.
    #[new]
    #[pyo3(signature = (source, path = None, *, vessel_motion = None, duration = None, overrides = None))]
    fn py_new(
        py: Python<'_>,
        source: String,
        path: Option<PathBuf>,
        vessel_motion: Option<PathBuf>,
        duration: Option<Real>,
        overrides: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let path = path.unwrap_or_else(|| PathBuf::from("<text>"));
        let overrides = match overrides {
            Some(d) => override_list(d)?,
            None => Vec::new(),
        };
        Self::parse(
            py,
            path,
            source,
            deck_options(vessel_motion, duration),
            overrides,
        )
    }

    /// The scenario of TOML `text`; files it names are looked for in `base_dir` (default: the
    /// working directory).
    #[staticmethod]
    #[pyo3(signature = (text, base_dir = None))]
    fn from_toml(py: Python<'_>, text: String, base_dir: Option<PathBuf>) -> PyResult<Self> {
        Self::parse(
            py,
            virtual_path(base_dir, "<toml>"),
            text,
            ConvertOptions::default(),
            Vec::new(),
        )
    }

    /// The scenario of a dict holding the TOML structure (`{"environment": {"depth": 150.0},
    /// "lines": [{"name": "chain", ...}], ...}`, as `to_dict` gives it); files it names are
    /// looked for in `base_dir` (default: the working directory). Diagnostics give lines and
    /// columns of `to_toml()`'s text.
    #[staticmethod]
    #[pyo3(signature = (d, base_dir = None))]
    fn from_dict(
        py: Python<'_>,
        d: &Bound<'_, PyDict>,
        base_dir: Option<PathBuf>,
    ) -> PyResult<Self> {
        let table = dict_to_table(d, "")?;
        let text = toml::to_string_pretty(&table).map_err(|e| {
            PyValueError::new_err(format!("the dict cannot be written as TOML: {e}"))
        })?;
        Self::parse(
            py,
            virtual_path(base_dir, "<dict>"),
            text,
            ConvertOptions::default(),
            Vec::new(),
        )
    }

    /// A new scenario with dotted keys set: `{"lines.chain.length": 900.0,
    /// "points.fairlead.motion.amplitude": [2.0, 0.0, 0.0], "environment.waves.seed": 7}`.
    /// Arrays of tables are addressed by the `name` of an element (or a 0-based index), arrays
    /// of numbers by index (`points.fairlead.position.2`); `None` removes a key. A key that
    /// names nothing raises `ScenarioError` naming the key; the result is validated as a file
    /// is, under the name `"<path> (with overrides)"` (its lines and columns are those of
    /// `to_toml()`). A MoorDyn deck is overridden in its hawser conversion (`hawser convert`).
    fn with_overrides(&self, py: Python<'_>, overrides: &Bound<'_, PyDict>) -> PyResult<Self> {
        let mut list = self.overrides.clone();
        list.extend(override_list(overrides)?);
        Self::parse(
            py,
            self.origin.clone(),
            self.source.clone(),
            self.deck.clone(),
            list,
        )
    }

    /// The dotted keys set on the input (`with_overrides`, in order; later ones win) and
    /// their values, `None` for a key removed.
    #[getter]
    fn overrides<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in &self.overrides {
            match v {
                Some(v) => d.set_item(k, crate::convert::toml_to_py(py, v)?)?,
                None => d.set_item(k, py.None())?,
            }
        }
        Ok(d)
    }

    /// The scenario's TOML structure as a dict (a deck's hawser conversion).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let text = self.to_toml(py)?;
        let table: toml::Table = toml::from_str(&text)
            .map_err(|e| PyValueError::new_err(format!("the scenario is not a TOML table: {e}")))?;
        table_to_py(py, &table)
    }

    /// The scenario as TOML text (a deck's hawser conversion, as `hawser convert` writes it).
    fn to_toml(&self, py: Python<'_>) -> PyResult<String> {
        match &self.text {
            Some(t) => Ok(t.clone()),
            None => hawser_io::input::scenario_text(&self.path, &self.source, &self.deck)
                .map_err(|e| scenario_error(py, &e)),
        }
    }

    /// The path the scenario was read from, or the name it was validated under.
    #[getter]
    fn path(&self) -> String {
        self.path.display().to_string()
    }

    /// The input's text (TOML, or the MoorDyn deck), before any overrides (`to_toml()` gives
    /// the scenario with them).
    #[getter]
    fn source(&self) -> &str {
        &self.source
    }

    /// `"toml"` or `"moordyn"`.
    #[getter]
    fn format(&self) -> &'static str {
        match self.loaded.format {
            InputFormat::Toml => "toml",
            InputFormat::MoorDyn => "moordyn",
        }
    }

    /// What the reading of a MoorDyn deck converted or ignored (empty for TOML).
    #[getter]
    fn notes(&self) -> Vec<String> {
        self.notes.clone()
    }

    /// Names of the lines, in model order.
    #[getter]
    fn lines(&self) -> Vec<String> {
        self.loaded
            .model
            .lines
            .iter()
            .map(|l| l.name.clone())
            .collect()
    }

    /// Names of the points, in model order.
    #[getter]
    fn points(&self) -> Vec<String> {
        self.loaded
            .model
            .points
            .iter()
            .map(|p| p.name.clone())
            .collect()
    }

    /// Names of the rigid bodies, in model order.
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.loaded
            .model
            .bodies
            .iter()
            .map(|b| b.name.clone())
            .collect()
    }

    /// Simulated duration of a run [s].
    #[getter]
    fn duration(&self) -> Real {
        self.loaded.model.settings.duration
    }

    fn __repr__(&self) -> String {
        let m = &self.loaded.model;
        format!(
            "<hawser.Scenario {} ({}): {} lines, {} points, {} bodies>",
            self.path.display(),
            self.format(),
            m.lines.len(),
            m.points.len(),
            m.bodies.len()
        )
    }

    /// Pickling: a scenario is rebuilt from its text, path, deck choices and overrides.
    fn __getnewargs_ex__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyDict>)> {
        let args = (self.source.clone(), self.origin.clone()).into_pyobject(py)?;
        let kw = PyDict::new(py);
        kw.set_item("vessel_motion", self.deck.vessel_motion.clone())?;
        kw.set_item("duration", self.deck.duration)?;
        kw.set_item("overrides", self.overrides(py)?)?;
        Ok((args.into_any(), kw))
    }

    /// The static equilibrium, as `hawser statics` finds it: a `hawser.Statics` with, per
    /// line, the nodes' arc length [m], positions [m] (n × 3) and effective tensions [N] and
    /// the force [N] each end exerts on its attachment; per point its position [m] and the
    /// force of the lines on it [N]; per body its pose. Raises `SimulationError` when the
    /// solver fails.
    fn statics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let model = &self.loaded.model;
        let computed = py.detach(|| {
            // dg lines are analysed through their hermite twin, as `hawser modes` does.
            let (model, _) = hawser_io::modes::modal_model(model);
            let system = hawser::system::System::new(&model.intact()).map_err(|e| e.to_string())?;
            let sol = hawser::statics::solve(&system, None, &Default::default())
                .map_err(|e| e.to_string())?;
            let mut ws = system.workspace();
            hawser::statics::evaluate(&system, &sol.state, &mut ws);
            Ok::<_, String>((system, sol, ws))
        });
        let (system, sol, ws) = computed.map_err(|e| simulation_error(py, e))?;
        let view = View {
            system: &system,
            workspace: &ws,
            time: 0.0,
            state: &sol.state,
            channels: &[],
            sample: 0,
            releases: &[],
        };
        let raw = PyDict::new(py);
        raw.set_item("method", sol.method.to_string())?;
        raw.set_item("iterations", sol.iterations)?;
        raw.set_item("residual", sol.residual)?;
        raw.set_item("tolerance", sol.tolerance)?;
        raw.set_item("fallback", sol.fallback.clone())?;
        raw.set_item("lines", lines_dict(py, &view)?)?;
        let points = PyDict::new(py);
        for (i, p) in system.points.iter().enumerate() {
            let d = PyDict::new(py);
            d.set_item("position", vec3(py, ws.points[i].position))?;
            d.set_item("force", vec3(py, view.point_line_force(i)))?;
            d.set_item("kind", hawser_io::modes::point_kind(&system, i))?;
            points.set_item(&p.name, d)?;
        }
        raw.set_item("points", points)?;
        let bodies = PyDict::new(py);
        for (b, body) in system.bodies.iter().enumerate() {
            let k = &ws.bodies[b];
            let (roll, pitch, yaw) = k.orientation.euler_angles();
            let d = PyDict::new(py);
            d.set_item("position", vec3(py, k.position))?;
            d.set_item(
                "orientation",
                array1(
                    py,
                    vec![roll.to_degrees(), pitch.to_degrees(), yaw.to_degrees()],
                ),
            )?;
            d.set_item("line_load", array1(py, view.body_line_load(b).to_vec()))?;
            bodies.set_item(&body.body.name, d)?;
        }
        raw.set_item("bodies", bodies)?;
        let tow = system.tow_velocity;
        raw.set_item(
            "tow_velocity",
            (tow != hawser::math::Vec3::zeros()).then(|| vec3(py, tow)),
        )?;
        py.import("hawser._results")?
            .getattr("Statics")?
            .call1((raw,))
    }

    /// Natural frequencies and mode shapes about the static state, the stiffness at the
    /// fixed and prescribed points, and the resonance report against the scenario's periodic
    /// excitations (`margin`: a fraction), as `hawser modes` computes them: a `hawser.Modes`.
    #[pyo3(signature = (count = 10, margin = 0.1))]
    fn modes<'py>(
        &self,
        py: Python<'py>,
        count: usize,
        margin: Real,
    ) -> PyResult<Bound<'py, PyAny>> {
        let model = &self.loaded.model;
        let computed = py.detach(|| {
            // dg lines are analysed through their hermite twin, as `hawser modes` does.
            let (model, _) = hawser_io::modes::modal_model(model);
            let system = hawser::system::System::new(&model.intact()).map_err(|e| e.to_string())?;
            let analysis = hawser_io::modes::ModalAnalysis::compute(&system, count, margin)?;
            Ok::<_, String>((system, analysis))
        });
        let (system, analysis) = computed.map_err(|e| simulation_error(py, e))?;
        let shapes = analysis.shapes(&system);
        let raw = PyDict::new(py);
        raw.set_item("document", json_to_py(py, &analysis.to_json(&system))?)?;
        let lines = PyDict::new(py);
        for (li, l) in system.lines.iter().enumerate() {
            let d = PyDict::new(py);
            d.set_item(
                "arc_length",
                array1(py, (0..l.nodes()).map(|n| l.mesh.arc_length(n)).collect()),
            )?;
            d.set_item("position", array_n3(py, &shapes.line_positions[li])?)?;
            let flat: Vec<_> = shapes
                .line_displacements
                .iter()
                .flat_map(|m| m[li].iter().copied())
                .collect();
            let n = shapes.line_displacements.len();
            d.set_item(
                "shapes",
                array_n3(py, &flat)?.call_method1("reshape", ((n, l.nodes(), 3),))?,
            )?;
            lines.set_item(&l.name, d)?;
        }
        raw.set_item("lines", lines)?;
        let points = PyDict::new(py);
        for (i, &p) in shapes.points.iter().enumerate() {
            let d = PyDict::new(py);
            d.set_item("position", vec3(py, shapes.point_positions[i]))?;
            let per_mode: Vec<_> = shapes.point_displacements.iter().map(|m| m[i]).collect();
            d.set_item("shapes", array_n3(py, &per_mode)?)?;
            points.set_item(&system.points[p].name, d)?;
        }
        raw.set_item("points", points)?;
        let stiffness = PyDict::new(py);
        for (i, &p) in analysis.stiffness.points.iter().enumerate() {
            let k = analysis.stiffness.block(i, i);
            let flat: Vec<Real> = (0..3)
                .flat_map(|r| (0..3).map(move |c| k[(r, c)]))
                .collect();
            stiffness.set_item(
                &system.points[p].name,
                PyArray1::from_vec(py, flat).reshape([3, 3])?,
            )?;
        }
        raw.set_item("stiffness", stiffness)?;
        py.import("hawser._results")?
            .getattr("Modes")?
            .call1((raw,))
    }

    /// Runs the dynamics from the initial condition to `duration` [s] (default: the
    /// scenario's) and returns a `hawser.Results`: the time series (a pandas DataFrame when
    /// pandas is installed), statistics, slack intervals, snap events, line snapshots and the
    /// final state. With `out`, also writes the files of `hawser run` into that folder (a
    /// folder holding another run is refused unless `overwrite`).
    ///
    /// The GIL is released while it runs; a progress bar shows (tqdm when installed) unless
    /// `progress=False`. Ctrl-C stops the run between two steps: `KeyboardInterrupt` is raised
    /// with the results so far as its `results` attribute, and `out` holds the files so far,
    /// flushed and marked interrupted. A run that diverges raises `SimulationError`, likewise
    /// with its results so far.
    #[pyo3(signature = (duration = None, out = None, *, overwrite = false, progress = true))]
    fn run<'py>(
        &self,
        py: Python<'py>,
        duration: Option<Real>,
        out: Option<PathBuf>,
        overwrite: bool,
        progress: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Some(out) = &out {
            check_output_dir(out, overwrite)?;
        }
        let job = self.job(duration, out)?;
        let desc = self
            .path
            .file_name()
            .map_or("hawser".into(), |n| n.to_string_lossy().into_owned());
        let bar = make_bar(py, progress, job.duration(), &desc)?;
        let (mut results, signal) = runner::drive(py, std::slice::from_ref(&job), 1, bar.as_ref())?;
        close_bar(bar.as_ref())?;
        let outcome = results.pop().flatten();
        finish_one(py, outcome, signal, &self.path)
    }

    /// A coupling session of this scenario (`hawser.Session(scenario)`).
    fn session(slf: &Bound<'_, Self>) -> PyResult<crate::session::Session> {
        crate::session::Session::new(slf)
    }
}

/// Per line: arc length, positions, tensions and end forces of the nodes of `view`.
pub fn lines_dict<'py>(py: Python<'py>, view: &View<'_>) -> PyResult<Bound<'py, PyDict>> {
    let lines = PyDict::new(py);
    for (li, l) in view.system.lines.iter().enumerate() {
        let d = PyDict::new(py);
        let samples: Vec<_> = view.line_samples(li).collect();
        d.set_item(
            "arc_length",
            array1(py, samples.iter().map(|s| s.arc_length).collect()),
        )?;
        let positions: Vec<_> = samples.iter().map(|s| s.position).collect();
        d.set_item("position", array_n3(py, &positions)?)?;
        d.set_item(
            "tension",
            array1(py, samples.iter().map(|s| s.tension).collect()),
        )?;
        d.set_item("end_a_force", vec3(py, view.end_force(li, false)))?;
        d.set_item("end_b_force", vec3(py, view.end_force(li, true)))?;
        lines.set_item(&l.name, d)?;
    }
    Ok(lines)
}

/// Refuses an output folder holding another run's files unless `overwrite`.
pub fn check_output_dir(out: &Path, overwrite: bool) -> PyResult<()> {
    let present = hawser_io::results::run_files_in(out);
    if !overwrite && !present.is_empty() {
        return Err(PyFileExistsError::new_err(format!(
            "{} holds the results of another run ({}); pass overwrite=True to replace them, or \
             choose another folder",
            out.display(),
            present.join(", ")
        )));
    }
    Ok(())
}

/// The progress bar of `hawser._progress` for `total` seconds of simulated time, or `None`.
pub fn make_bar<'py>(
    py: Python<'py>,
    enabled: bool,
    total: Real,
    desc: &str,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    if !enabled {
        return Ok(None);
    }
    Ok(Some(
        py.import("hawser._progress")?
            .getattr("make_bar")?
            .call1((total, desc))?,
    ))
}

/// Closes a progress bar.
pub fn close_bar(bar: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
    if let Some(b) = bar {
        b.call_method0("close")?;
    }
    Ok(())
}

/// A run's outcome as `hawser.Results`, or the exception it ends in (with the results so far
/// attached as `results`).
pub fn outcome_to_py<'py>(
    py: Python<'py>,
    outcome: Result<Outcome, Failure>,
) -> Result<Bound<'py, PyAny>, PyErr> {
    let o = match outcome {
        Ok(o) => o,
        Err(Failure::Input(e)) => return Err(scenario_error(py, &e)),
        Err(Failure::Simulation(m)) => return Err(simulation_error(py, m)),
        Err(Failure::Io(e)) => return Err(PyOSError::new_err(e.to_string())),
        Err(Failure::Panic(m)) => {
            return Err(simulation_error(
                py,
                format!("internal error in hawser (a bug, please report it): {m}"),
            ));
        }
    };
    let results = results_to_py(py, &o)?;
    match &o.error {
        Some(message) if !o.interrupted => {
            let err = simulation_error(py, message.clone());
            err.value(py).setattr("results", &results)?;
            Err(err)
        }
        _ => Ok(results),
    }
}

fn finish_one<'py>(
    py: Python<'py>,
    outcome: Option<Result<Outcome, Failure>>,
    signal: Option<PyErr>,
    path: &Path,
) -> PyResult<Bound<'py, PyAny>> {
    let converted = outcome.map(|o| outcome_to_py(py, o));
    match (signal, converted) {
        (Some(sig), Some(Ok(results))) => {
            sig.value(py).setattr("results", results)?;
            Err(sig)
        }
        (Some(sig), _) => Err(sig),
        (None, Some(r)) => r,
        (None, None) => Err(simulation_error(
            py,
            format!("the run of {} did not start", path.display()),
        )),
    }
}

/// The Python dict `hawser._results.Results` is built from.
fn results_to_py<'py>(py: Python<'py>, o: &Outcome) -> PyResult<Bound<'py, PyAny>> {
    let r = &o.recorder;
    let raw = PyDict::new(py);
    let n = r.times.len();
    let c = r.names.len();
    raw.set_item("time", PyArray1::from_slice(py, &r.times))?;
    raw.set_item(
        "values",
        PyArray1::from_slice(py, &r.values).reshape([n, c])?,
    )?;
    raw.set_item("names", PyList::new(py, &r.names)?)?;
    raw.set_item("units", PyList::new(py, &r.units)?)?;
    if let Some(s) = &r.summary_json {
        raw.set_item("summary", json_to_py(py, s)?)?;
    }
    if let Some(s) = &r.line_ranges_json {
        raw.set_item("line_ranges", json_to_py(py, s)?)?;
    }
    if let Some(s) = &r.final_state {
        raw.set_item("final_state", json_to_py(py, s)?)?;
    }
    let snaps = PyDict::new(py);
    for (name, s) in r.lines.iter().zip(&r.snapshots) {
        if s.time.is_empty() {
            continue;
        }
        let d = PyDict::new(py);
        d.set_item("time", PyArray1::from_slice(py, &s.time))?;
        d.set_item("node", PyArray1::from_slice(py, &s.node))?;
        d.set_item("arc_length", PyArray1::from_slice(py, &s.arc_length))?;
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            d.set_item(*axis, PyArray1::from_slice(py, &s.position[k]))?;
        }
        d.set_item("tension", PyArray1::from_slice(py, &s.tension))?;
        snaps.set_item(name, d)?;
    }
    raw.set_item("snapshots", snaps)?;
    raw.set_item("complete", o.error.is_none())?;
    raw.set_item("error", o.error.clone())?;
    raw.set_item("interrupted", o.interrupted)?;
    raw.set_item("out", o.out.as_ref().map(|p| p.display().to_string()))?;
    py.import("hawser._results")?
        .getattr("Results")?
        .call1((raw,))
}
