//! Line failures during a run ([`crate::model::LineFailure`]): when a release is due, what it
//! does to the system and the state, and the events a run reports.
//!
//! A release happens between two steps: the stepper stops after the step at which a failure
//! is due ([`Stepper::due_failure`]), the session releases it ([`Stepper::release`]) and then
//! takes the sample due at that time, so the sample at the release time already shows the end
//! free (its attachment's reaction from that line is zero). The release copies the
//! attachment's position and velocity into the reserved free end's state
//! ([`crate::system::SystemFailure::free_end`]), moves the line end onto it, and wakes it.
//! The state keeps its length and nothing is allocated. The Runge–Kutta schemes keep no
//! history, so the next step starts cleanly from the new state; the three-level and
//! generalized-α schemes, whose history (the previous level; the accelerations, the Jacobian
//! and the iteration matrix) belongs to the system before the release, restart it from the
//! state at the release as at the start of a run ([`Stepper::restart`]).

use super::Stepper;
use super::stepper::Integrator;
use crate::error::SimulationError;
use crate::math::{Real, set3};
use crate::model::End;
use crate::system::System;

/// Why a line end released.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReleaseCause {
    /// Its failure time was reached.
    Time,
    /// Its end tension reached the failure's tension.
    Tension,
    /// The host called [`crate::Session::release`].
    Host,
}

impl ReleaseCause {
    /// `"time"`, `"tension"` or `"host"`, as results files spell it.
    pub fn name(self) -> &'static str {
        match self {
            ReleaseCause::Time => "time",
            ReleaseCause::Tension => "tension",
            ReleaseCause::Host => "host",
        }
    }
}

/// A release that happened (one per failure at most), kept in the stepper's state so that
/// checkpoints and a coupling host's repeated intervals carry it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Release {
    /// Time of the release [s] (a step end).
    pub time: Real,
    /// Tension at the end at the release [N]: the magnitude of the force the line exerted on
    /// its attachment at that state, just before it let go.
    pub tension: Real,
    /// What released it.
    pub cause: ReleaseCause,
}

/// A failure due now: its index in [`System::failures`], its cause, and the end's tension [N].
pub(crate) type Due = (usize, ReleaseCause, Real);

/// A line failure that happened, with the names a report needs.
#[derive(Clone, Debug, PartialEq)]
pub struct FailureEvent {
    /// Index of the failure in [`crate::model::Model::failures`].
    pub failure: usize,
    /// Line name.
    pub line: String,
    /// Which end released.
    pub end: End,
    /// Further line ends released with it onto the same free point, (line name, end).
    pub joined: Vec<(String, End)>,
    /// Name of the point it released from.
    pub attachment: String,
    /// Time [s], tension [N] and cause.
    pub release: Release,
}

/// The failures that happened, in the order of the model's failures (not of time).
pub fn failure_events(system: &System, releases: &[Option<Release>]) -> Vec<FailureEvent> {
    system
        .failures
        .iter()
        .zip(releases)
        .enumerate()
        .filter_map(|(k, (f, r))| {
            r.map(|release| FailureEvent {
                failure: k,
                line: system.lines[f.line].name.clone(),
                end: f.end,
                joined: f
                    .joined
                    .iter()
                    .map(|&(l, e)| (system.lines[l].name.clone(), e))
                    .collect(),
                attachment: system.points[f.attachment].name.clone(),
                release,
            })
        })
        .collect()
}

/// Points the line ends of failure `k` at their attachment or, once released, at its free
/// end, and sets the free end's dormancy and the ends' kind in the coupled solve to match.
fn point_end(system: &mut System, ws: &mut crate::system::Workspace, k: usize, released: bool) {
    let f = &system.failures[k];
    let free_end = f.free_end;
    let target = if released { free_end } else { f.attachment };
    system.points[free_end].dormant = !released;
    let kind = system.end_kind(target);
    for j in 0..=system.failures[k].joined.len() {
        let f = &system.failures[k];
        let (line, end) = if j == 0 {
            (f.line, f.end)
        } else {
            f.joined[j - 1]
        };
        let (l, b) = (&mut system.lines[line], &mut ws.blocks[line]);
        match end {
            End::A => {
                l.end_a = target;
                b.end_a = kind;
            }
            End::B => {
                l.end_b = target;
                b.end_b = kind;
            }
        }
    }
}

/// The tension [N] of failure `k` at the evaluation in `ws`: the magnitude of the vector sum
/// of its ends' forces on their attachment, |Σ F_end| (one end: its end tension).
pub(crate) fn failure_tension(system: &System, ws: &crate::system::Workspace, k: usize) -> Real {
    system.failures[k]
        .ends()
        .map(|(line, end)| system.end_force(ws, line, end == End::B))
        .sum::<crate::math::Vec3>()
        .norm()
}

impl Stepper {
    /// Whether a failure has not released yet.
    pub(crate) fn failures_pending(&self) -> bool {
        self.releases.iter().any(Option::is_none)
    }

    /// The releases so far, per failure of the system.
    pub fn releases(&self) -> &[Option<Release>] {
        &self.releases
    }

    /// The first failure not yet released whose trigger is met at the current state: its
    /// time reached (within 1e-9 of a step, the round-off of the clock), or its end tension at
    /// or above its threshold (evaluating the state when a tension trigger is pending: one
    /// evaluation per step, shared with a sample at that time).
    pub(crate) fn due_failure(&mut self, system: &System) -> Result<Option<Due>, SimulationError> {
        let t = self.time();
        let slack = 1e-9 * self.clock.step;
        for (k, f) in system.failures.iter().enumerate() {
            if self.releases[k].is_some() {
                continue;
            }
            let timed = f.time.is_some_and(|at| t >= at - slack);
            if !timed && f.tension.is_none() {
                continue;
            }
            let ws = self.evaluate(system)?;
            let tension = failure_tension(system, ws, k);
            if timed {
                return Ok(Some((k, ReleaseCause::Time, tension)));
            }
            if f.tension.is_some_and(|limit| tension >= limit) {
                return Ok(Some((k, ReleaseCause::Tension, tension)));
            }
        }
        Ok(None)
    }

    /// Releases failure `k` now (module doc): its free end takes the attachment's position
    /// and velocity at the current state, the line end moves onto it, and the release is
    /// recorded with the end's `tension` [N]. Does nothing when it already released.
    pub(crate) fn release(
        &mut self,
        system: &mut System,
        k: usize,
        cause: ReleaseCause,
        tension: Real,
    ) -> Result<(), SimulationError> {
        if self.releases[k].is_some() {
            return Ok(());
        }
        self.evaluate(system)?;
        let f = &system.failures[k];
        let at = self.ws.points[f.attachment];
        let o = system.layout.point_offset[f.free_end].expect("a free end has a state block");
        set3(&mut self.state[o..], 0, &at.position);
        set3(&mut self.state[o..], 1, &at.velocity);
        point_end(system, &mut self.ws, k, true);
        self.restart();
        self.releases[k] = Some(Release {
            time: self.time(),
            tension,
            cause,
        });
        self.invalidate();
        Ok(())
    }

    /// Sets the system's failing line ends to the stepper's releases (after a restore), and
    /// generalized-α's iteration matrix to the line ends' kinds.
    pub(crate) fn apply_releases(&mut self, system: &mut System) {
        for k in 0..system.failures.len() {
            point_end(system, &mut self.ws, k, self.releases[k].is_some());
        }
        if let Integrator::GeneralizedAlpha { scheme, .. } = &mut self.integrator {
            scheme.follow_ends(&self.ws);
        }
        self.invalidate();
    }

    /// Restarts the scheme's history at a release, from the state and time of the release,
    /// as at the start of a run: the three-level scheme's next step is its Taylor start from
    /// the positions and velocities ([`crate::integrate::ThreeLevel::restart`]);
    /// generalized-α's takes the consistent accelerations of the new state and a fresh
    /// Jacobian ([`crate::integrate::GeneralizedAlpha::restart`]), and with adaptive steps its
    /// controller starts again from the run's first step (its a-priori accuracy step) or the
    /// current one, whichever is shorter: the release is a jump in the accelerations, which
    /// the controller's step before it knew nothing of. The Runge–Kutta schemes keep no
    /// history. Allocates nothing.
    fn restart(&mut self) {
        match &mut self.integrator {
            Integrator::Rk(_) => {}
            Integrator::ThreeLevel { scheme, .. } => scheme.restart(),
            Integrator::GeneralizedAlpha { scheme, adaptive } => {
                scheme.restart(&self.ws);
                if *adaptive {
                    self.clock.nominal = self.clock.nominal.min(self.first_step);
                }
            }
        }
    }
}
