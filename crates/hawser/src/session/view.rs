//! Read access to an evaluated state: output channels, line samples along the arc length, body
//! poses and loads, point kinematics and end forces. Every writer and binding reads a run
//! through a [`View`]; [`Observer`]s receive one at every sample.

use crate::analysis::{Channel, OutputChannel};
use crate::math::{Real, Vec3};
use crate::model::RigidKinematics;
use crate::system::{PointKinematics, System, Workspace};

/// A state of a run with an evaluation of its right-hand side: what every output is read from.
#[derive(Clone, Copy)]
pub struct View<'a> {
    /// The assembled system.
    pub system: &'a System,
    /// The workspace holding the evaluation at this state.
    pub workspace: &'a Workspace,
    /// Simulated time [s].
    pub time: Real,
    /// The state vector.
    pub state: &'a [Real],
    /// The run's output channels, in column order.
    pub channels: &'a [OutputChannel],
    /// Index of this sample (0 at t = 0).
    pub sample: u64,
    /// Per failure of the system ([`System::failures`]): its release so far, if any (empty
    /// outside a run).
    pub releases: &'a [Option<super::Release>],
}

/// One node of a line as writers report it ([`View::line_samples`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineSample {
    /// Node index (0 at end A).
    pub node: usize,
    /// Unstretched arc length from end A [m] (the current length of a line on a winch).
    pub arc_length: Real,
    /// Position [m].
    pub position: Vec3,
    /// Velocity [m/s].
    pub velocity: Vec3,
    /// Effective tension [N] ([`System::node_tension`]).
    pub tension: Real,
    /// Axial strain [-]: the mean of the adjacent elements' strains (an end element's at an
    /// end node).
    pub strain: Real,
    /// Curvature [1/m]: as the strain, from the elements' midpoint curvatures (0 for `fe`,
    /// which has no bending).
    pub curvature: Real,
    /// Bending moment [N·m], as the curvature (0 for `fe`).
    pub bending_moment: Real,
}

/// The nodes of one line, end A to end B.
pub struct LineSamples<'a> {
    view: View<'a>,
    line: usize,
    node: usize,
    nodes: usize,
}

impl Iterator for LineSamples<'_> {
    type Item = LineSample;

    fn next(&mut self) -> Option<LineSample> {
        if self.node >= self.nodes {
            return None;
        }
        let i = self.node;
        self.node += 1;
        let (system, ws, li) = (self.view.system, self.view.workspace, self.line);
        let l = &system.lines[li];
        let lw = &ws.lines[li];
        let n = self.nodes - 1;
        let el = &lw.elements;
        // The elements on either side of node i (one at an end).
        let (a, b) = (i.saturating_sub(1), i.min(n - 1));
        let mean = |v: &[Real]| 0.5 * (v[a] + v[b]);
        let v = l.node_vector(i);
        Some(LineSample {
            node: i,
            arc_length: system.line_mesh(ws, li).arc_length(i) + 0.0,
            position: lw.position[v],
            velocity: lw.velocity[v],
            tension: system.node_tension(ws, li, i),
            strain: mean(&el.strain),
            curvature: mean(&el.curvature),
            bending_moment: mean(&el.bending_moment),
        })
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.nodes - self.node;
        (left, Some(left))
    }
}

impl ExactSizeIterator for LineSamples<'_> {}

impl<'a> View<'a> {
    /// Value of output channel `index` (of [`View::channels`]).
    #[inline]
    pub fn channel(&self, index: usize) -> Real {
        self.value(&self.channels[index].channel)
    }

    /// Value of any channel at this state.
    #[inline]
    pub fn value(&self, channel: &Channel) -> Real {
        channel.value_at(self.system, self.workspace, self.time)
    }

    /// Column name of output channel `index`.
    pub fn channel_name(&self, index: usize) -> String {
        self.channels[index].name(self.system)
    }

    /// The nodes of line `line` from end A to end B: arc length, position, velocity, tension,
    /// strain, curvature, bending moment.
    pub fn line_samples(&self, line: usize) -> LineSamples<'a> {
        LineSamples {
            view: *self,
            line,
            node: 0,
            nodes: self.system.lines[line].nodes(),
        }
    }

    /// Force [N] line `line` exerts on the attachment of an end (`end_b` false: end A).
    #[inline]
    pub fn end_force(&self, line: usize, end_b: bool) -> Vec3 {
        self.system.end_force(self.workspace, line, end_b)
    }

    /// Kinematics of point `point`.
    #[inline]
    pub fn point(&self, point: usize) -> &'a PointKinematics {
        &self.workspace.points[point]
    }

    /// Pose, velocities and accelerations of body `body`.
    #[inline]
    pub fn body(&self, body: usize) -> &'a RigidKinematics {
        &self.workspace.bodies[body]
    }

    /// The load the lines put on body `body` through the points on it: force [N] and moment
    /// about the body origin [N·m], global axes ([`Channel::BodyLineLoad`]).
    pub fn body_line_load(&self, body: usize) -> [Real; 6] {
        let mut load = [0.0; 6];
        for (dof, l) in load.iter_mut().enumerate() {
            *l = self.value(&Channel::BodyLineLoad { body, dof });
        }
        load
    }

    /// The force [N] pinned body `body` exerts on its pin, global axes: −R with R the pin's
    /// force on the body, R = M_tt a_pin + M_tr α − F over the body's own loads and the
    /// lines' load on it ([`crate::bodies::pin_force`]); what a coupling host holding the pin
    /// feels (MoorDyn's forces of a `CoupledPinned` body). `None` unless the body is pinned.
    pub fn pin_load(&self, body: usize) -> Option<Vec3> {
        let b = &self.system.bodies[body].body;
        b.kind.pin()?;
        let k = &self.workspace.bodies[body];
        let own = b.loads(k, &self.system.environment, self.time);
        let lines = crate::math::Vec6::from_column_slice(&self.body_line_load(body));
        Some(-crate::bodies::pin_force(
            &own.mass,
            &own.generalized(),
            &lines,
            k,
        ))
    }

    /// Net force [N] the attached lines exert on point `point` (the sum of their end-node
    /// forces, [`Channel::PointForce`]).
    pub fn point_line_force(&self, point: usize) -> Vec3 {
        Vec3::from_fn(|axis, _| self.value(&Channel::PointForce { point, axis }))
    }
}

/// Receives a run's samples: at t = 0 and after every output interval, then once at its end.
/// Writers (CSV, Parquet, VTK), in-memory recorders and progress displays are observers.
pub trait Observer {
    /// One sample. An error stops the run ([`crate::SimulationError::Observer`]) with the
    /// results so far kept.
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError>;

    /// The run ended (`end.error` is `None` when it reached its end time), with the last
    /// evaluated state.
    fn finish(&mut self, view: &View<'_>, end: &RunEnd) -> Result<(), ObserverError> {
        let _ = (view, end);
        Ok(())
    }

    /// A coupling host computes the interval that started at `time` [s] again (it corrected
    /// its kinematics): forget the samples after `time`. Observers that cannot say so.
    fn rewind(&mut self, time: Real) -> Result<(), ObserverError> {
        Err(ObserverError(format!(
            "this observer cannot forget its samples after t = {time} s, which a coupling \
             host's repeated interval needs"
        )))
    }
}

/// An observer a [`crate::Session`] owns ([`crate::Session::attach`]): any `Observer` that is
/// `Send` and `'static`, so that the session can move between threads and give it back.
pub trait Attached: Observer + std::any::Any + Send {}

impl<T: Observer + std::any::Any + Send> Attached for T {}

/// Why an observer could not take a sample (a write failure, with the file it concerns).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct ObserverError(pub String);

impl From<std::io::Error> for ObserverError {
    fn from(e: std::io::Error) -> Self {
        Self(e.to_string())
    }
}

/// How a run ended, for [`Observer::finish`].
#[derive(Clone, Debug, PartialEq)]
pub struct RunEnd {
    /// Time of the last sample [s].
    pub last_sample: Real,
    /// Why it stopped early, if it did.
    pub error: Option<String>,
    /// Whether it stopped because it was interrupted (SIGINT, SIGTERM, KeyboardInterrupt).
    pub interrupted: bool,
    /// The run's warnings ([`crate::Session::warnings`]).
    pub warnings: Vec<crate::warning::Warning>,
    /// What the time integration did ([`crate::Session::integrator_report`]).
    pub integrator: crate::integrate::IntegratorReport,
}
