//! Coupling with a host program: the host sets the kinematics of the coupled points and bodies
//! at the end of each coupling interval, advances the session to that time, and reads back the
//! loads of the lines on them. A repeated call for the same interval (a host that corrects its
//! prediction) goes back to the interval's start and computes it again.
//!
//! The kinematics inside an interval are interpolated ([`crate::model::PointTrack`],
//! [`crate::model::BodyTrack`]); docs/coupling.md states the semantics.

use super::Session;
use super::stepper::Saved;
use crate::error::SimulationError;
use crate::math::{Real, Vec3};
use crate::model::{PointKind, RigidKinematics, euler_kinematics};

/// The coupled objects and the interval in progress.
#[derive(Clone, Debug, Default)]
pub(crate) struct Coupling {
    /// Indices of the coupled bodies, in model order.
    pub bodies: Vec<usize>,
    /// Indices of the coupled points, in model order.
    pub points: Vec<usize>,
    /// The interval [t₀, t₁] being set or computed.
    pub interval: Option<(Real, Real)>,
    /// The run at t₀, for a repeated interval.
    pub start: Saved,
    /// Samples given to the observers by t₀, and the time of the last of them [s].
    pub start_samples: (u64, Real),
}

impl Coupling {
    pub(crate) fn of(model: &crate::Model) -> Self {
        Self {
            bodies: (0..model.bodies.len())
                .filter(|&b| model.bodies[b].kind.coupled_dofs() > 0)
                .collect(),
            points: (0..model.points.len())
                .filter(|&p| model.points[p].kind == PointKind::Coupled)
                .collect(),
            ..Default::default()
        }
    }
}

fn coupling_error(what: String) -> SimulationError {
    SimulationError::Coupling { what }
}

impl Session {
    /// Indices of the coupled points ([`PointKind::Coupled`]), in model order.
    pub fn coupled_points(&self) -> &[usize] {
        &self.coupling.points
    }

    /// Indices of the coupled bodies ([`crate::model::BodyKind::Coupled`], and the pinned bodies whose pin
    /// is coupled, [`crate::model::Pin::Coupled`]), in model order.
    pub fn coupled_bodies(&self) -> &[usize] {
        &self.coupling.bodies
    }

    /// Coupled degrees of freedom of body `body`: 6 for a coupled body, 3 (the pin's
    /// translations) for a body on a coupled pin ([`crate::model::BodyKind::coupled_dofs`]).
    pub fn coupled_body_dofs(&self, body: usize) -> usize {
        self.system.bodies[body].body.kind.coupled_dofs()
    }

    /// Number of coupled degrees of freedom in the layout of [`Session::set_coupled`]: 6 per
    /// coupled body or 3 per body on a coupled pin, in model order, then 3 per coupled point
    /// (MoorDyn's order: a `CoupledPinned` body takes 3 entries).
    pub fn coupled_dofs(&self) -> usize {
        let bodies: usize = self
            .coupling
            .bodies
            .iter()
            .map(|&b| self.coupled_body_dofs(b))
            .sum();
        bodies + 3 * self.coupling.points.len()
    }

    /// Opens the coupling interval that ends at `t1` [s], or reopens it: a first call for a
    /// new end time starts an interval at the session's time; a call for the end time of the
    /// interval just computed goes back to its start (a repeated interval). At t = 0 before
    /// the first step, a call for t1 = 0 sets the initial kinematics (returns true).
    fn begin_interval(&mut self, t1: Real) -> Result<bool, SimulationError> {
        let now = self.stepper.time();
        if !t1.is_finite() {
            return Err(coupling_error(format!(
                "the coupling time {t1} s is not a finite number"
            )));
        }
        let tolerance = 1e-9 * self.stepper.clock.nominal;
        if self.coupling.interval.is_none()
            && self.stepper.steps_done() == 0
            && (t1 - now).abs() <= tolerance
        {
            return Ok(true);
        }
        if let Some((t0, end)) = self.coupling.interval
            && (t1 - end).abs() <= tolerance
        {
            if now > t0 + tolerance {
                // The interval was computed: go back to its start.
                // Saved by this run: its history fits.
                let _ = self.stepper.restore(&self.coupling.start);
                self.stepper.apply_releases(&mut self.system);
                let (samples, last) = self.coupling.start_samples;
                if self.samples > samples {
                    for o in self.observers.iter_mut().flatten() {
                        o.rewind(t0)
                            .map_err(|e| SimulationError::Observer { message: e.0 })?;
                    }
                }
                self.samples = samples;
                self.last_sample = last;
                // The last accepted state is now the interval's start.
                self.stepper.save(&mut self.sampled);
            }
            return Ok(false);
        }
        if !(t1 > now + tolerance) {
            return Err(coupling_error(format!(
                "the coupling time t = {t1} s is not after the session's time {now} s: a new \
                 interval must end later, and a repeated one at the same time as the interval \
                 it repeats"
            )));
        }
        // The t = 0 sample belongs before any interval.
        self.advance_to(now)?;
        let tracks = &mut self.stepper.ws.coupling;
        for t in tracks.points.iter_mut().flatten() {
            t.start_at(now);
        }
        for t in tracks.bodies.iter_mut().flatten() {
            t.start_at(now);
        }
        self.stepper.save(&mut self.coupling.start);
        self.coupling.start_samples = (self.samples, self.last_sample);
        self.coupling.interval = Some((now, t1));
        Ok(false)
    }

    /// Sets the position [m] and velocity [m/s] of coupled point `point` at time `t1` [s], the
    /// end of the coupling interval that [`Session::advance_to`]`(t1)` then computes. At
    /// t1 = 0 before the first step it sets the initial kinematics (the initial statics were
    /// solved at the point's model position: set that position in the model before building
    /// the session, and give it here with the initial velocity).
    pub fn set_point_kinematics(
        &mut self,
        point: usize,
        t1: Real,
        position: Vec3,
        velocity: Vec3,
        acceleration: Option<Vec3>,
    ) -> Result<(), SimulationError> {
        if !self.coupling.points.contains(&point) {
            return Err(coupling_error(format!(
                "point #{point} is not a coupled point (coupled points: {})",
                index_list(&self.coupling.points)
            )));
        }
        if !position
            .iter()
            .chain(velocity.iter())
            .all(|x| x.is_finite())
        {
            return Err(coupling_error(format!(
                "the kinematics of point {} at t = {t1} s are not finite",
                self.system.points[point].name
            )));
        }
        let initial = self.begin_interval(t1)?;
        let track = self.stepper.ws.coupling.points[point]
            .as_mut()
            .expect("a coupled point has a track");
        track.set_end(t1, position, velocity, acceleration);
        if initial {
            track.start_at(t1);
            self.stepper.invalidate();
        }
        Ok(())
    }

    /// Sets the pose and velocities of coupled body `body` at time `t1` [s], and its
    /// accelerations when `accelerations` (otherwise they follow from the interpolation).
    /// For a body on a coupled pin, only the translation (position, velocity, acceleration of
    /// the pin) is used: its rotations are its own.
    pub fn set_body_kinematics(
        &mut self,
        body: usize,
        t1: Real,
        kinematics: &RigidKinematics,
        accelerations: bool,
    ) -> Result<(), SimulationError> {
        if !self.coupling.bodies.contains(&body) {
            return Err(coupling_error(format!(
                "body #{body} is not a coupled body (coupled bodies: {})",
                index_list(&self.coupling.bodies)
            )));
        }
        let k = kinematics;
        let finite = k
            .position
            .iter()
            .chain(k.velocity.iter())
            .chain(k.angular_velocity.iter())
            .chain(k.acceleration.iter())
            .chain(k.angular_acceleration.iter())
            .chain(k.orientation.coords.iter())
            .all(|x| x.is_finite());
        if !finite {
            return Err(coupling_error(format!(
                "the kinematics of body {} at t = {t1} s are not finite",
                self.system.bodies[body].body.name
            )));
        }
        let initial = self.begin_interval(t1)?;
        let track = self.stepper.ws.coupling.bodies[body]
            .as_mut()
            .expect("a coupled body has a track");
        track.set_end(t1, kinematics, accelerations);
        if initial {
            track.start_at(t1);
            self.stepper.invalidate();
        }
        Ok(())
    }

    /// Sets every coupled object's kinematics at `t1` [s] from flat arrays in the layout of
    /// [`Session::coupled_dofs`]: per coupled body x, y, z [m], roll, pitch, yaw [rad]
    /// (R = R_z(yaw) R_y(pitch) R_x(roll)) in `x` and the velocity [m/s] and angular velocity
    /// [rad/s, global axes] in `xd` (per body on a coupled pin, the pin's x, y, z and its
    /// velocity only); then per coupled point x, y, z [m] and its velocity.
    /// `xdd`, if given, holds the accelerations in the layout of `xd` (the interpolants are
    /// then quintic, exact for the motions hosts usually prescribe).
    pub fn set_coupled(
        &mut self,
        t1: Real,
        x: &[Real],
        xd: &[Real],
        xdd: Option<&[Real]>,
    ) -> Result<(), SimulationError> {
        let n = self.coupled_dofs();
        if x.len() != n || xd.len() != n || xdd.is_some_and(|a| a.len() != n) {
            return Err(coupling_error(format!(
                "the coupled kinematics have {} positions, {} velocities and {} accelerations \
                 where the model has {n} coupled degrees of freedom",
                x.len(),
                xd.len(),
                xdd.map_or(n, |a| a.len())
            )));
        }
        let mut o = 0;
        for k in 0..self.coupling.bodies.len() {
            let b = self.coupling.bodies[k];
            let n = self.coupled_body_dofs(b);
            let mut p = [0.0; 6];
            let mut v = [0.0; 6];
            let mut a = [0.0; 6];
            p[..n].copy_from_slice(&x[o..o + n]);
            v[..n].copy_from_slice(&xd[o..o + n]);
            if let Some(xdd) = xdd {
                a[..n].copy_from_slice(&xdd[o..o + n]);
            }
            o += n;
            let (orientation, _, _) = euler_kinematics([p[3], p[4], p[5]], [0.0; 3], [0.0; 3]);
            let kinematics = RigidKinematics {
                position: Vec3::new(p[0], p[1], p[2]),
                orientation,
                velocity: Vec3::new(v[0], v[1], v[2]),
                angular_velocity: Vec3::new(v[3], v[4], v[5]),
                acceleration: Vec3::new(a[0], a[1], a[2]),
                angular_acceleration: Vec3::new(a[3], a[4], a[5]),
            };
            self.set_body_kinematics(b, t1, &kinematics, xdd.is_some())?;
        }
        for k in 0..self.coupling.points.len() {
            let p = self.coupling.points[k];
            let o = o + 3 * k;
            self.set_point_kinematics(
                p,
                t1,
                Vec3::new(x[o], x[o + 1], x[o + 2]),
                Vec3::new(xd[o], xd[o + 1], xd[o + 2]),
                xdd.map(|a| Vec3::new(a[o], a[o + 1], a[o + 2])),
            )?;
        }
        Ok(())
    }

    /// The force [N] the lines exert on coupled (or any) point `point` at the session's time:
    /// the sum of the end forces of the lines attached to it (each the end node's share of
    /// the line's forces less its share of the line's inertia, [`crate::System::end_force`]).
    pub fn point_reaction(&mut self, point: usize) -> Result<Vec3, SimulationError> {
        if point >= self.system.points.len() {
            return Err(coupling_error(format!(
                "there is no point #{point} (the model has {})",
                self.system.points.len()
            )));
        }
        self.stepper.evaluate(&self.system)?;
        let ws = self.stepper.workspace();
        let mut f = Vec3::zeros();
        for (li, l) in self.system.lines.iter().enumerate() {
            if l.end_a == point {
                f += self.system.end_force(ws, li, false);
            }
            if l.end_b == point {
                f += self.system.end_force(ws, li, true);
            }
        }
        Ok(f)
    }

    /// The load the lines put on body `body` through the points on it at the session's time:
    /// force [N] and moment about the body origin [N·m], global axes.
    pub fn body_reaction(&mut self, body: usize) -> Result<[Real; 6], SimulationError> {
        if body >= self.system.bodies.len() {
            return Err(coupling_error(format!(
                "there is no body #{body} (the model has {})",
                self.system.bodies.len()
            )));
        }
        Ok(self.view()?.body_line_load(body))
    }

    /// The force [N] pinned body `body` exerts on its pin at the session's time, global axes
    /// ([`crate::View::pin_load`]): its weight, buoyancy, hydrodynamic and line loads less its
    /// inertia, over the translations.
    pub fn pin_load(&mut self, body: usize) -> Result<Vec3, SimulationError> {
        if body >= self.system.bodies.len() {
            return Err(coupling_error(format!(
                "there is no body #{body} (the model has {})",
                self.system.bodies.len()
            )));
        }
        let name = self.system.bodies[body].body.name.clone();
        self.view()?.pin_load(body).ok_or_else(|| {
            coupling_error(format!(
                "body {name} (#{body}) is not pinned: it has no pin load"
            ))
        })
    }

    /// The loads on every coupled object in the layout of [`Session::coupled_dofs`]: per
    /// coupled body its force [N] and moment about its origin [N·m] (per body on a coupled
    /// pin, the force it exerts on its pin, [`Session::pin_load`]), per coupled point its
    /// force [N], all in global axes.
    pub fn coupled_forces(&mut self, forces: &mut [Real]) -> Result<(), SimulationError> {
        let n = self.coupled_dofs();
        if forces.len() != n {
            return Err(coupling_error(format!(
                "the force array has {} entries where the model has {n} coupled degrees of \
                 freedom",
                forces.len()
            )));
        }
        let mut o = 0;
        for k in 0..self.coupling.bodies.len() {
            let b = self.coupling.bodies[k];
            if self.coupled_body_dofs(b) == 3 {
                let f = self.pin_load(b)?;
                forces[o..o + 3].copy_from_slice(f.as_slice());
                o += 3;
            } else {
                let load = self.body_reaction(b)?;
                forces[o..o + 6].copy_from_slice(&load);
                o += 6;
            }
        }
        for k in 0..self.coupling.points.len() {
            let f = self.point_reaction(self.coupling.points[k])?;
            let o = o + 3 * k;
            forces[o..o + 3].copy_from_slice(f.as_slice());
        }
        Ok(())
    }
}

/// `#0, #2, #5`, or `none`.
fn index_list(indices: &[usize]) -> String {
    if indices.is_empty() {
        return "none".into();
    }
    indices
        .iter()
        .map(|i| format!("#{i}"))
        .collect::<Vec<_>>()
        .join(", ")
}
