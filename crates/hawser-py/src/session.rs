//! `hawser.Session`: a run a coupling host steps, over hawser-capi's [`Host`] (the object
//! behind the C ABI and the MoorDyn-compatible library), with hawser's convention: the
//! kinematics of the coupled bodies and points are given at the end of each coupling
//! interval (docs/coupling.md).

use crate::convert::{array_n3, vec3};
use crate::errors::{host_error, simulation_error};
use crate::scenario::Scenario;
use hawser::math::{Real, Vec3};
use hawser::model::PointKind;
use hawser_capi::host::{Convention, Host};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyIndexError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyTuple};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// A run stepped by a coupling host: set the coupled bodies' and points' kinematics at the
/// end of each coupling interval, advance to that time, read the forces of the lines on them.
///
/// The flat layout of `x`, `xd` and the forces is MoorDyn's: every coupled body (x, y, z [m],
/// roll, pitch, yaw [rad]; velocities [m/s, rad/s]; a body on a coupled pin, `CoupledPinned`,
/// only its pin's x, y, z, and as force the one it puts on its pin), then every coupled point
/// (x, y, z [m]), each in model order (`dof_names`). A MoorDyn deck's `Coupled`/`Vessel` points are coupled.
///
/// ```python
/// s = hawser.Session(hawser.load("tests/data/moordyn/oc3_lines.txt"))
/// s.init()                        # statics at the input positions
/// for k in range(1, 101):
///     f = s.step(s.time, 0.1, x(k * 0.1), xd(k * 0.1))   # kinematics at t + dt
/// ```
#[pyclass(module = "hawser")]
pub struct Session {
    scenario: Py<Scenario>,
    /// In a mutex only to be `Sync` as Python classes must be; `&mut self` reaches it
    /// without locking.
    host: Mutex<Host>,
    /// The positions the session was initialised at.
    x0: Option<Vec<Real>>,
    stop: Arc<AtomicBool>,
    dof_names: Vec<String>,
    /// The model as loaded (coupled objects at their input positions).
    model: hawser::Model,
}

/// The index of `name` among `names` (of objects of `kind`), or a KeyError listing them.
fn named<'a>(
    kind: &str,
    names: impl Iterator<Item = &'a str> + Clone,
    name: &str,
) -> PyResult<usize> {
    names.clone().position(|n| n == name).ok_or_else(|| {
        PyKeyError::new_err(format!(
            "no {kind} named `{name}` ({kind}s: {})",
            names.collect::<Vec<_>>().join(", ")
        ))
    })
}

fn slice<'a>(a: &'a PyReadonlyArray1<'_, f64>, what: &str) -> PyResult<&'a [f64]> {
    a.as_slice().map_err(|_| {
        pyo3::exceptions::PyValueError::new_err(format!("{what} must be a contiguous array"))
    })
}

impl Session {
    /// A session of `scenario`, not initialised.
    pub fn new(scenario: &Bound<'_, Scenario>) -> PyResult<Self> {
        let mut loaded = scenario.get().loaded.clone();
        hawser_io::moordyn::couple_deck_points(&mut loaded);
        let model = &loaded.model;
        let mut dof_names = Vec::new();
        // 6 per coupled body, 3 (the pin's x, y, z) per body on a coupled pin.
        for b in &model.bodies {
            for d in &hawser::analysis::channels::BODY_MOTION[..b.kind.coupled_dofs()] {
                dof_names.push(format!("{}.{d}", b.name));
            }
        }
        for p in model.points.iter().filter(|p| p.kind == PointKind::Coupled) {
            for d in ["x", "y", "z"] {
                dof_names.push(format!("{}.{d}", p.name));
            }
        }
        Ok(Self {
            scenario: scenario.clone().unbind(),
            host: Mutex::new(Host::from_model(loaded.model.clone())),
            model: loaded.model,
            x0: None,
            stop: Arc::new(AtomicBool::new(false)),
            dof_names,
        })
    }

    fn host(&mut self) -> &mut Host {
        self.host.get_mut().unwrap_or_else(|e| e.into_inner())
    }

    fn session(&mut self, py: Python<'_>) -> PyResult<&mut hawser::session::Session> {
        self.host().session().map_err(|e| host_error(py, e))
    }

    fn line_index(&self, line: &Bound<'_, PyAny>) -> PyResult<usize> {
        let lines = &self.model.lines;
        if let Ok(i) = line.extract::<usize>() {
            return match i < lines.len() {
                true => Ok(i),
                false => Err(PyIndexError::new_err(format!(
                    "line {i}: the model has {} lines",
                    lines.len()
                ))),
            };
        }
        named(
            "line",
            lines.iter().map(|l| l.name.as_str()),
            &line.extract::<String>()?,
        )
    }

    fn point_index(&self, name: &str) -> PyResult<usize> {
        named(
            "point",
            self.model.points.iter().map(|p| p.name.as_str()),
            name,
        )
    }

    /// The positions of the coupled objects in the model: bodies' poses (angles in rad,
    /// R = R_z(yaw) R_y(pitch) R_x(roll)) and points' positions.
    fn model_positions(&self) -> Vec<Real> {
        let model = &self.model;
        let mut x = Vec::with_capacity(self.dof_names.len());
        for b in &model.bodies {
            let (roll, pitch, yaw) = b.orientation.euler_angles();
            let pose = [b.position.x, b.position.y, b.position.z, roll, pitch, yaw];
            x.extend_from_slice(&pose[..b.kind.coupled_dofs()]);
        }
        for p in model.points.iter().filter(|p| p.kind == PointKind::Coupled) {
            x.extend_from_slice(p.position.as_slice());
        }
        x
    }
}

#[pymethods]
impl Session {
    /// A coupling session of `scenario`; call `init` before stepping.
    #[new]
    fn py_new(scenario: &Bound<'_, Scenario>) -> PyResult<Self> {
        Self::new(scenario)
    }

    /// The scenario.
    #[getter]
    fn scenario(&self, py: Python<'_>) -> Py<Scenario> {
        self.scenario.clone_ref(py)
    }

    /// Number of coupled degrees of freedom: 6 per coupled body (3 per body on a coupled pin),
    /// then 3 per coupled point.
    #[getter]
    fn coupled_dofs(&self) -> usize {
        self.dof_names.len()
    }

    /// Names of the coupled degrees of freedom in the layout of `x` and the forces
    /// (`"P4.x"`, `"platform.yaw"`).
    #[getter]
    fn dof_names(&self) -> Vec<String> {
        self.dof_names.clone()
    }

    /// Simulated time [s] (0 before `init`).
    #[getter]
    fn time(&mut self) -> Real {
        self.host().session().map_or(0.0, |s| s.time())
    }

    /// The time step of the scenario's integrator [s] (after `init`).
    #[getter]
    fn time_step(&mut self, py: Python<'_>) -> PyResult<Real> {
        Ok(self.session(py)?.step_size())
    }

    /// What the time integration did so far, as `summary.json`'s `integrator`: the scheme the
    /// run started with and why, steps, the step now [s], generalized-α's counts and
    /// `scheme = "auto"`'s switching to RK4 (after `init`).
    #[getter]
    fn integrator<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let report = self.session(py)?.integrator_report();
        crate::convert::json_to_py(py, &hawser_io::results::integrator_json(&report))
    }

    /// Whether `init` was called.
    #[getter]
    fn initialised(&mut self) -> bool {
        self.host().session().is_ok()
    }

    /// Places the coupled objects at `x` (default: their input positions), solves the static
    /// equilibrium there and sets their velocities `xd` (default: at rest) and, for hosts
    /// that give accelerations at every step (the quintic interpolant), the accelerations
    /// `xdd` at t = 0. Like MoorDyn's `MoorDyn_Init`.
    #[pyo3(signature = (x = None, xd = None, xdd = None))]
    fn init(
        &mut self,
        py: Python<'_>,
        x: Option<PyReadonlyArray1<'_, f64>>,
        xd: Option<PyReadonlyArray1<'_, f64>>,
        xdd: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<()> {
        let x = match &x {
            Some(a) => slice(a, "x")?.to_vec(),
            None => self.model_positions(),
        };
        let xd = match &xd {
            Some(a) => slice(a, "xd")?.to_vec(),
            None => vec![0.0; self.dof_names.len()],
        };
        let xdd = match &xdd {
            Some(a) => Some(slice(a, "xdd")?),
            None => None,
        };
        let host = self.host();
        py.detach(|| {
            host.init(&x, &xd)?;
            if let Some(a) = xdd {
                // The initial kinematics again, with the accelerations.
                let s = host.session()?;
                s.set_coupled(0.0, &x, &xd, Some(a)).map_err(|e| {
                    hawser_capi::host::HostError::new(
                        hawser_capi::host::ErrorKind::Simulation,
                        e.to_string(),
                    )
                })?;
            }
            Ok(())
        })
        .map_err(|e| host_error(py, e))?;
        let stop = self.stop.clone();
        self.session(py)?.set_interrupt(stop);
        self.x0 = Some(x);
        Ok(())
    }

    /// Computes the coupling interval [t, t + dt] [s] with the coupled kinematics `x`, `xd`
    /// (and accelerations `xdd`, for the quintic interpolant) **at its end, t + dt**, and
    /// returns the forces [N] and moments [N·m] of the lines on the coupled objects at t + dt
    /// (global axes, the layout of `x`). `t` is the session's time, or the start of the
    /// interval just computed to compute it again with corrected kinematics (a predictor-
    /// corrector host). The GIL is released while it runs.
    #[pyo3(signature = (t, dt, x, xd, xdd = None))]
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        t: Real,
        dt: Real,
        x: PyReadonlyArray1<'_, f64>,
        xd: PyReadonlyArray1<'_, f64>,
        xdd: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (x, xd) = (slice(&x, "x")?, slice(&xd, "xd")?);
        let xdd = match &xdd {
            Some(a) => Some(slice(a, "xdd")?),
            None => None,
        };
        let mut forces = vec![0.0; self.dof_names.len()];
        let host = self.host();
        py.detach(|| host.step(Convention::End, t, dt, x, xd, xdd, &mut forces))
            .map_err(|e| host_error(py, e))?;
        Ok(PyArray1::from_vec(py, forces))
    }

    /// Sets the coupled kinematics at time `t1` [s], the end of the next coupling interval
    /// (or of the interval just computed, to compute it again). Then `advance_to(t1)`.
    #[pyo3(signature = (t1, x, xd, xdd = None))]
    fn set_coupled(
        &mut self,
        py: Python<'_>,
        t1: Real,
        x: PyReadonlyArray1<'_, f64>,
        xd: PyReadonlyArray1<'_, f64>,
        xdd: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<()> {
        let (x, xd) = (slice(&x, "x")?, slice(&xd, "xd")?);
        let xdd = match &xdd {
            Some(a) => Some(slice(a, "xdd")?),
            None => None,
        };
        self.session(py)?
            .set_coupled(t1, x, xd, xdd)
            .map_err(|e| simulation_error(py, e.to_string()))
    }

    /// Steps to time `t` [s] (the coupled objects follow the kinematics set for it). The GIL
    /// is released; Ctrl-C stops it between two steps and raises `KeyboardInterrupt` with the
    /// session at the last step taken.
    fn advance_to(&mut self, py: Python<'_>, t: Real) -> PyResult<()> {
        let stop = self.stop.clone();
        let session = self.session(py)?;
        let mut signal = None;
        let main = std::thread::current();
        let result = std::thread::scope(|scope| {
            let worker = scope.spawn(|| {
                let r = session.advance_to(t);
                main.unpark();
                r
            });
            while !worker.is_finished() {
                py.detach(|| std::thread::park_timeout(crate::runner::POLL));
                if signal.is_none()
                    && let Err(e) = py.check_signals()
                {
                    stop.store(true, Ordering::Relaxed);
                    signal = Some(e);
                }
            }
            worker.join()
        });
        self.stop.store(false, Ordering::Relaxed);
        if let Some(e) = signal {
            return Err(e);
        }
        match result {
            Ok(r) => r.map_err(|e| simulation_error(py, e.to_string())),
            Err(_) => Err(simulation_error(
                py,
                "internal error in hawser (a bug, please report it): a panic while stepping",
            )),
        }
    }

    /// The forces [N] and moments [N·m] of the lines on the coupled objects now, in the
    /// layout of `x`.
    fn forces<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let mut f = vec![0.0; self.dof_names.len()];
        self.host()
            .forces(Convention::End, &mut f)
            .map_err(|e| host_error(py, e))?;
        Ok(PyArray1::from_vec(py, f))
    }

    /// Releases end `end` (`"A"` or `"B"`) of line `line` (name or index) from its attachment
    /// now, between two steps: the line goes on with that end free (docs/failure.md). The
    /// end must have a failure in the scenario (`[lines.failure]`, with or without a trigger
    /// of its own); releasing it twice does nothing.
    fn release(&mut self, py: Python<'_>, line: &Bound<'_, PyAny>, end: &str) -> PyResult<()> {
        let li = self.line_index(line)?;
        let end = match end {
            "A" | "a" => hawser::model::End::A,
            "B" | "b" => hawser::model::End::B,
            other => {
                return Err(PyKeyError::new_err(format!(
                    "line end `{other}`: give \"A\" or \"B\""
                )));
            }
        };
        let name = self.model.lines[li].name.clone();
        self.session(py)?
            .release(&name, end)
            .map_err(|e| simulation_error(py, e.to_string()))
    }

    /// The line failures so far, in the model's order: per release a dict with `line`, `end`
    /// (`"a"` or `"b"`), `attachment` (the point it released from), `time` [s], `tension`
    /// [N] (the end's tension just before) and `cause` (`"time"`, `"tension"` or `"host"`).
    #[getter]
    fn failures<'py>(&mut self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        let events = self.session(py)?.failure_events();
        events
            .iter()
            .map(|e| {
                let d = PyDict::new(py);
                d.set_item("line", &e.line)?;
                d.set_item("end", e.end.name())?;
                d.set_item("attachment", &e.attachment)?;
                d.set_item("time", e.release.time)?;
                d.set_item("tension", e.release.tension)?;
                d.set_item("cause", e.release.cause.name())?;
                Ok(d)
            })
            .collect()
    }

    /// The force [N] of the lines on point `name` now (any point).
    fn point_force<'py>(&mut self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let p = self.point_index(name)?;
        let f = self
            .session(py)?
            .point_reaction(p)
            .map_err(|e| simulation_error(py, e.to_string()))?;
        Ok(vec3(py, f))
    }

    /// The load of the lines on body `name` now: force [N] and moment about its origin
    /// [N·m], global axes.
    fn body_force<'py>(
        &mut self,
        py: Python<'py>,
        name: &str,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let bodies = &self.model.bodies;
        let b = bodies
            .iter()
            .position(|b| b.name == name)
            .ok_or_else(|| PyKeyError::new_err(format!("no body named `{name}`")))?;
        let load = self
            .session(py)?
            .body_reaction(b)
            .map_err(|e| simulation_error(py, e.to_string()))?;
        Ok(PyArray1::from_slice(py, &load))
    }

    /// Effective tension [N] at the nodes of `line` (a name or an index), end A to end B.
    fn line_tension<'py>(
        &mut self,
        py: Python<'py>,
        line: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let li = self.line_index(line)?;
        let n = self.host().line_nodes(li).map_err(|e| host_error(py, e))?;
        let mut out = vec![0.0; n];
        self.host()
            .line_samples(li, false, &mut out)
            .map_err(|e| host_error(py, e))?;
        Ok(PyArray1::from_vec(py, out))
    }

    /// Positions [m] of the nodes of `line` (a name or an index), n × 3, end A to end B.
    fn line_positions<'py>(
        &mut self,
        py: Python<'py>,
        line: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let li = self.line_index(line)?;
        let view = self
            .session(py)?
            .view()
            .map_err(|e| simulation_error(py, e.to_string()))?;
        let p: Vec<Vec3> = view.line_samples(li).map(|s| s.position).collect();
        array_n3(py, &p)
    }

    /// Names of the output channels (`values()`'s order).
    #[getter]
    fn channels(&mut self, py: Python<'_>) -> PyResult<Vec<String>> {
        let s = self.session(py)?;
        let system = s.system();
        Ok(s.channels().iter().map(|c| c.name(system)).collect())
    }

    /// Units of the output channels.
    #[getter]
    fn units(&mut self, py: Python<'_>) -> PyResult<Vec<&'static str>> {
        Ok(self
            .session(py)?
            .channels()
            .iter()
            .map(|c| c.channel.unit())
            .collect())
    }

    /// The output channels' values now (the order of `channels`).
    fn values<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let view = self
            .session(py)?
            .view()
            .map_err(|e| simulation_error(py, e.to_string()))?;
        let v: Vec<Real> = (0..view.channels.len()).map(|i| view.channel(i)).collect();
        Ok(PyArray1::from_vec(py, v))
    }

    /// The session saved to bytes: state, integrator history, the coupling interval in
    /// progress. `restore` continues from it bit for bit.
    fn checkpoint<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let bytes = self.host().checkpoint().map_err(|e| host_error(py, e))?;
        Ok(PyBytes::new(py, &bytes))
    }

    /// Continues from `data` (`checkpoint()` of a session of the same scenario, initialised at
    /// the same positions).
    fn restore(&mut self, py: Python<'_>, data: &[u8]) -> PyResult<()> {
        let x0 = self.x0.clone().unwrap_or_else(|| self.model_positions());
        let host = self.host();
        py.detach(|| host.restore_initialised(&x0, data))
            .map_err(|e| host_error(py, e))?;
        let stop = self.stop.clone();
        self.session(py)?.set_interrupt(stop);
        self.x0 = Some(x0);
        Ok(())
    }

    /// Pickling: the scenario (its text) ...
    fn __getnewargs__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, [self.scenario.clone_ref(py)])
    }

    /// ... and the initial positions with a checkpoint (None before `init`).
    fn __getstate__<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let state = match &self.x0 {
            Some(x0) => {
                let x0 = x0.clone();
                let bytes = self.checkpoint(py)?;
                (Some(x0), Some(bytes)).into_pyobject(py)?.into_any()
            }
            None => (None::<Vec<Real>>, None::<Vec<u8>>)
                .into_pyobject(py)?
                .into_any(),
        };
        Ok(state)
    }

    fn __setstate__(
        &mut self,
        py: Python<'_>,
        state: (Option<Vec<Real>>, Option<Vec<u8>>),
    ) -> PyResult<()> {
        if let (Some(x0), Some(bytes)) = state {
            self.x0 = Some(x0);
            self.restore(py, &bytes)?;
        }
        Ok(())
    }

    fn __repr__(&mut self) -> String {
        let t = self.time();
        format!(
            "<hawser.Session {} at t = {t} s, {} coupled dofs{}>",
            self.scenario.get().path.display(),
            self.dof_names.len(),
            if self.x0.is_some() {
                ""
            } else {
                ", not initialised"
            }
        )
    }
}
