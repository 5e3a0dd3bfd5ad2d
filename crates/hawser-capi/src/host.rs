//! The object a coupling host drives, in safe Rust: a model loaded from a scenario or a
//! MoorDyn deck, then a [`Session`] built at initialisation. The C functions of [`crate::ffi`]
//! and the MoorDyn-compatible library are thin shells over it.

use hawser::Model;
use hawser::math::{Real, Vec3};
use hawser::model::{PointKind, euler_kinematics};
use hawser::session::{Session, SessionOptions};
use std::path::Path;

/// What went wrong, with the status a C caller receives.
#[derive(Clone, Debug, PartialEq)]
pub struct HostError {
    /// The class of error.
    pub kind: ErrorKind,
    /// The message (several lines for an input error: file, line, key, value, hint).
    pub message: String,
}

/// Classes of errors, each a status code of the C ABI.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// A null pointer, an index out of range, an array of the wrong length.
    InvalidArgument,
    /// The scenario or deck could not be read or is invalid.
    Input,
    /// The statics, a step or the coupling failed (divergence, bad kinematics).
    Simulation,
    /// Called out of order (a step before the initialisation, a second initialisation).
    State,
    /// A checkpoint that is not of this model or is damaged.
    Checkpoint,
    /// The caller's buffer is too small (the size needed is returned beside).
    BufferTooSmall,
    /// A panic inside hawser, caught at the boundary.
    Panic,
    /// A file could not be written (a state file).
    Io,
}

impl HostError {
    /// An error of `kind`.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Self {
            kind,
            message: message.into(),
        }
    }
}

fn simulation(e: hawser::SimulationError) -> HostError {
    let kind = if matches!(e, hawser::SimulationError::Checkpoint { .. }) {
        ErrorKind::Checkpoint
    } else {
        ErrorKind::Simulation
    };
    HostError::new(kind, e.to_string())
}

/// A run driven by a coupling host.
pub struct Host {
    /// The model as loaded (coupled objects at their input positions until [`Host::init`]).
    model: Model,
    /// The run, from [`Host::init`] on.
    session: Option<Session>,
    /// Number of coupled degrees of freedom (6 per coupled body, 3 per body on a coupled pin,
    /// then 3 per coupled point).
    dofs: usize,
}

/// How [`Host::step`] reads the host's kinematics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Convention {
    /// hawser's: the kinematics at the end of the interval, a smooth interpolant inside it.
    End,
    /// MoorDyn's: the kinematics at the start of the interval, held at constant velocity.
    Start,
}

impl Host {
    /// Loads a hawser scenario (TOML) or a MoorDyn deck; a deck's `Coupled`/`Vessel` points
    /// become the host's coupled points ([`hawser_io::moordyn::couple_deck_points`]).
    pub fn open(path: &Path) -> Result<Self, HostError> {
        let (mut loaded, _notes) = hawser_io::input::load_input(path, &Default::default())
            .map_err(|e| HostError::new(ErrorKind::Input, e.to_string()))?;
        hawser_io::moordyn::couple_deck_points(&mut loaded);
        Ok(Self::from_model(loaded.model))
    }

    /// A host over a model.
    pub fn from_model(model: Model) -> Self {
        let bodies: usize = model.bodies.iter().map(|b| b.kind.coupled_dofs()).sum();
        let points = model
            .points
            .iter()
            .filter(|p| p.kind == PointKind::Coupled)
            .count();
        Self {
            model,
            session: None,
            dofs: bodies + 3 * points,
        }
    }

    /// Number of coupled degrees of freedom.
    pub fn coupled_dofs(&self) -> usize {
        self.dofs
    }

    /// The model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    fn check_len(&self, what: &str, len: usize) -> Result<(), HostError> {
        if len != self.dofs {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!(
                    "{what} has {len} entries where the model has {} coupled degrees of freedom",
                    self.dofs
                ),
            ));
        }
        Ok(())
    }

    /// The model with its coupled objects placed at `x` (the layout of
    /// [`Session::set_coupled`]): the model [`Host::init`] builds its session of.
    pub fn initialised_model(&self, x: &[Real]) -> Result<Model, HostError> {
        self.check_len("the position array", x.len())?;
        let mut model = self.model.clone();
        let mut k = 0;
        for b in model.bodies.iter_mut() {
            let n = b.kind.coupled_dofs();
            if n == 0 {
                continue;
            }
            let p = &x[k..k + n];
            b.position = Vec3::new(p[0], p[1], p[2]);
            // A coupled pin gives its position only: the body keeps its own orientation.
            if n == 6 {
                b.orientation = euler_kinematics([p[3], p[4], p[5]], [0.0; 3], [0.0; 3]).0;
            }
            k += n;
        }
        for p in model
            .points
            .iter_mut()
            .filter(|p| p.kind == PointKind::Coupled)
        {
            p.position = Vec3::new(x[k], x[k + 1], x[k + 2]);
            k += 3;
        }
        Ok(model)
    }

    /// Places the coupled objects at `x` (the layout of [`Session::set_coupled`]), solves the
    /// static equilibrium there, and sets the initial velocities `xd`.
    pub fn init(&mut self, x: &[Real], xd: &[Real]) -> Result<(), HostError> {
        if self.session.is_some() {
            return Err(HostError::new(
                ErrorKind::State,
                "the session is initialised already",
            ));
        }
        self.check_len("the position array", x.len())?;
        self.check_len("the velocity array", xd.len())?;
        let model = self.initialised_model(x)?;
        let mut session =
            Session::with_options(model, SessionOptions::default()).map_err(simulation)?;
        session.set_coupled(0.0, x, xd, None).map_err(simulation)?;
        self.session = Some(session);
        Ok(())
    }

    /// The session, once initialised.
    pub fn session(&mut self) -> Result<&mut Session, HostError> {
        self.session.as_mut().ok_or_else(|| {
            HostError::new(
                ErrorKind::State,
                "the session is not initialised: call init with the initial kinematics first",
            )
        })
    }

    /// Computes the coupling interval [t, t + dt] [s] from the host's kinematics read by
    /// `convention` (`xdd`: accelerations, hawser's convention only), and writes the loads on
    /// the coupled objects into `forces` (hawser's [`Session::coupled_forces`] for
    /// [`Convention::End`]; MoorDyn's net force of the end nodes, without their inertia, for
    /// [`Convention::Start`]). `t` is the session's time, or the start of the interval just
    /// computed (a repeated interval). Returns the time reached.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        convention: Convention,
        t: Real,
        dt: Real,
        x: &[Real],
        xd: &[Real],
        xdd: Option<&[Real]>,
        forces: &mut [Real],
    ) -> Result<Real, HostError> {
        self.check_len("the position array", x.len())?;
        self.check_len("the velocity array", xd.len())?;
        self.check_len("the force array", forces.len())?;
        let s = self.session()?;
        if !(dt > 0.0 && dt.is_finite() && t.is_finite()) {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!("the interval [{t} s, {t} s + {dt} s] is not finite with dt > 0"),
            ));
        }
        match convention {
            Convention::End => {
                let now = s.time();
                let tolerance = 1e-9 * s.step_size();
                // A new interval starts now; a repeated one ends where the session is.
                if (t - now).abs() > tolerance && (t + dt - now).abs() > tolerance {
                    return Err(HostError::new(
                        ErrorKind::Simulation,
                        format!(
                            "the interval starts at t = {t} s where the session is at {now} s: \
                             a new interval starts at the session's time, a repeated one at the \
                             start of the interval just computed"
                        ),
                    ));
                }
                s.set_coupled(t + dt, x, xd, xdd).map_err(simulation)?;
                s.advance_to(t + dt).map_err(simulation)?;
                s.coupled_forces(forces).map_err(simulation)?;
            }
            Convention::Start => {
                s.set_coupled_constant_velocity(t, dt, x, xd)
                    .map_err(simulation)?;
                s.advance_to(t + dt).map_err(simulation)?;
                end_node_forces(s, forces).map_err(simulation)?;
            }
        }
        Ok(s.time())
    }

    /// The loads on the coupled objects now, in the layout of `convention`'s step.
    pub fn forces(&mut self, convention: Convention, forces: &mut [Real]) -> Result<(), HostError> {
        self.check_len("the force array", forces.len())?;
        let s = self.session()?;
        match convention {
            Convention::End => s.coupled_forces(forces).map_err(simulation),
            Convention::Start => end_node_forces(s, forces).map_err(simulation),
        }
    }

    /// Number of lines.
    pub fn lines(&self) -> usize {
        self.model.lines.len()
    }

    /// Number of points.
    pub fn points(&self) -> usize {
        self.model.points.len()
    }

    fn line_index(&self, line: usize) -> Result<(), HostError> {
        if line >= self.lines() {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!(
                    "line index {line} is out of range: the model has {} lines (indices from 0)",
                    self.lines()
                ),
            ));
        }
        Ok(())
    }

    /// Number of nodes of line `line` (after initialisation: the assembled line's).
    pub fn line_nodes(&mut self, line: usize) -> Result<usize, HostError> {
        self.line_index(line)?;
        Ok(self.session()?.system().lines[line].nodes())
    }

    /// Writes one value per node of line `line` (end A to end B) into `out`: the tension [N],
    /// or, with `positions`, x, y, z [m] per node.
    pub fn line_samples(
        &mut self,
        line: usize,
        positions: bool,
        out: &mut [Real],
    ) -> Result<(), HostError> {
        let nodes = self.line_nodes(line)?;
        let per = if positions { 3 } else { 1 };
        if out.len() != per * nodes {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!(
                    "the array has {} entries where line {line} needs {} ({nodes} nodes)",
                    out.len(),
                    per * nodes
                ),
            ));
        }
        let view = self.session()?.view().map_err(simulation)?;
        for (s, o) in view.line_samples(line).zip(out.chunks_exact_mut(per)) {
            if positions {
                o.copy_from_slice(s.position.as_slice());
            } else {
                o[0] = s.tension;
            }
        }
        Ok(())
    }

    /// Net force [N] of line `line` on its end node `end_b` (false: end A), without the node's
    /// inertia (MoorDyn's `Fnet` of the end node; its norm is the `FairTen` channel).
    pub fn end_node_force(&mut self, line: usize, end_b: bool) -> Result<Vec3, HostError> {
        self.line_index(line)?;
        let view = self.session()?.view().map_err(simulation)?;
        let f = &view.workspace.lines[line].force;
        Ok(if end_b { f[f.len() - 1] } else { f[0] })
    }

    /// Force [N] line `line` exerts on the attachment of an end (hawser's reaction: the end
    /// node's share of the line's forces less its share of the line's inertia).
    pub fn end_force(&mut self, line: usize, end_b: bool) -> Result<Vec3, HostError> {
        self.line_index(line)?;
        Ok(self
            .session()?
            .view()
            .map_err(simulation)?
            .end_force(line, end_b))
    }

    /// Position [m] and the force of the attached lines [N] on point `point`.
    pub fn point(&mut self, point: usize) -> Result<(Vec3, Vec3), HostError> {
        if point >= self.points() {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!(
                    "point index {point} is out of range: the model has {} points (indices \
                     from 0)",
                    self.points()
                ),
            ));
        }
        let s = self.session()?;
        let f = s.point_reaction(point).map_err(simulation)?;
        let x = s.view().map_err(simulation)?.point(point).position;
        Ok((x, f))
    }

    /// The run saved to bytes ([`Session::checkpoint`]).
    pub fn checkpoint(&mut self) -> Result<Vec<u8>, HostError> {
        Ok(self.session()?.checkpoint())
    }

    /// Continues from `bytes` (of a session of the same input, initialised with the same
    /// positions). Before initialisation the model is the one loaded; after it, the
    /// initialised one.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<(), HostError> {
        let model = match &self.session {
            Some(s) => s.model().clone(),
            None => self.model.clone(),
        };
        self.restore_model(model, bytes)
    }

    /// Continues from `bytes`, saved by a session initialised at `x` ([`Host::init`]): what a
    /// new host of the same input restores (the Python package's unpickling).
    pub fn restore_initialised(&mut self, x: &[Real], bytes: &[u8]) -> Result<(), HostError> {
        let model = self.initialised_model(x)?;
        self.restore_model(model, bytes)
    }

    fn restore_model(&mut self, model: Model, bytes: &[u8]) -> Result<(), HostError> {
        let session =
            Session::restore(model, bytes, SessionOptions::default()).map_err(simulation)?;
        self.session = Some(session);
        Ok(())
    }
}

/// MoorDyn's coupled forces: per coupled body the force and moment of the lines' end-node net
/// forces (about the body origin), per coupled point the sum of the net forces of the lines'
/// end nodes on it, without their inertia (MoorDyn-C 2.7 `Point::doRHS`, `getFnet`).
fn end_node_forces(s: &mut Session, forces: &mut [Real]) -> Result<(), hawser::SimulationError> {
    // A coupled pin: the force the body puts on it (MoorDyn's `getFnet` of a `CPLDPIN` body,
    // F6net − M a over the translations, the end masses' inertia included).
    let mut o = 0;
    for k in 0..s.coupled_bodies().len() {
        let b = s.coupled_bodies()[k];
        let n = s.coupled_body_dofs(b);
        if n == 3 {
            let f = s.pin_load(b)?;
            forces[o..o + 3].copy_from_slice(f.as_slice());
        }
        o += n;
    }
    s.view()?;
    let (system, ws, model) = (s.system(), s.workspace(), s.model());
    let node_force = |line: usize, end_b: bool| {
        let f = &ws.lines[line].force;
        if end_b { f[f.len() - 1] } else { f[0] }
    };
    let on_point = |point: usize| {
        let mut f = Vec3::zeros();
        for (li, l) in system.lines.iter().enumerate() {
            if l.end_a == point {
                f += node_force(li, false);
            }
            if l.end_b == point {
                f += node_force(li, true);
            }
        }
        f
    };
    let mut o = 0;
    for &b in s.coupled_bodies() {
        if s.coupled_body_dofs(b) == 3 {
            o += 3;
            continue;
        }
        let origin = ws.bodies[b].position;
        let mut load = [0.0; 6];
        for (p, point) in model.points.iter().enumerate() {
            if matches!(point.kind, PointKind::Body { body, .. } if body == b) {
                let f = on_point(p);
                let m = (ws.points[p].position - origin).cross(&f);
                for i in 0..3 {
                    load[i] += f[i];
                    load[3 + i] += m[i];
                }
            }
        }
        forces[o..o + 6].copy_from_slice(&load);
        o += 6;
    }
    for (k, &p) in s.coupled_points().iter().enumerate() {
        forces[o + 3 * k..o + 3 * k + 3].copy_from_slice(on_point(p).as_slice());
    }
    Ok(())
}
