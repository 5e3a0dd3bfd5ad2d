//! The low-level form of a run, on a system it borrows: for tests and tools that compose an
//! assembled [`System`], a hand-made initial state and their own settings. Hosts use the owning
//! [`crate::Session`], which also applies the model's initial-condition policy; both step with
//! the same [`Stepper`].

use crate::error::SimulationError;
use crate::math::Real;
use crate::model::Settings;
pub use crate::session::{Observer, ObserverError};
use crate::session::{Stepper, View};
use crate::system::{System, Workspace};

/// A dynamic simulation in progress on a borrowed system.
pub struct Simulation<'a> {
    system: &'a System,
    stepper: Stepper,
}

impl<'a> Simulation<'a> {
    /// Prepares a run from `initial` with the step rule of `settings`. A fixed step above the
    /// stability limit is refused.
    pub fn new(
        system: &'a System,
        settings: &Settings,
        initial: Vec<Real>,
    ) -> Result<Self, SimulationError> {
        Ok(Self {
            system,
            stepper: Stepper::new(system, settings, initial, true)?,
        })
    }

    /// As [`Simulation::new`], but a fixed step above the stability estimate is taken as
    /// given (for experts who know the estimate is conservative for their case; a run that
    /// then diverges stops with [`SimulationError::Diverged`]).
    pub fn new_unchecked(
        system: &'a System,
        settings: &Settings,
        initial: Vec<Real>,
    ) -> Result<Self, SimulationError> {
        Ok(Self {
            system,
            stepper: Stepper::new(system, settings, initial, false)?,
        })
    }

    /// Simulated time [s].
    pub fn time(&self) -> Real {
        self.stepper.time()
    }

    /// The state vector.
    pub fn state(&self) -> &[Real] {
        self.stepper.state()
    }

    /// Time step [s].
    pub fn step_size(&self) -> Real {
        self.stepper.step_size()
    }

    /// Stability limit of the scheme [s] and what sets it.
    pub fn stable_step(&self) -> (Real, &str) {
        self.stepper.stable_step()
    }

    /// Interval between samples [s] (a whole number of steps).
    pub fn sample_interval(&self) -> Real {
        self.stepper.sample_interval()
    }

    /// Right-hand-side (force) evaluations per step.
    pub fn evaluations_per_step(&self) -> usize {
        self.stepper.evaluations_per_step()
    }

    /// The scheme the run uses and why (`scheme = "auto"` resolved,
    /// [`crate::integrate::choose_scheme`]).
    pub fn scheme(&self) -> &crate::integrate::SchemeChoice {
        self.stepper.scheme()
    }

    /// What the generalized-α scheme did so far: steps, refused steps, Newton iterations,
    /// Jacobians (`None` for the other schemes).
    pub fn implicit_statistics(&self) -> Option<crate::integrate::generalized_alpha::Statistics> {
        self.stepper.implicit_statistics()
    }

    /// `scheme = "auto"`'s switching between generalized-α and RK4 so far
    /// ([`crate::integrate::choice::SchemeSwitch`]; `None` unless `auto` started the run with
    /// adaptive generalized-α).
    pub fn scheme_switch(&self) -> Option<crate::integrate::choice::SchemeSwitch> {
        self.stepper.scheme_switch()
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> u64 {
        self.stepper.steps_done()
    }

    /// Advances one step. Checks the state for non-finite values.
    pub fn step(&mut self) -> Result<(), SimulationError> {
        self.stepper.step(self.system)
    }

    /// The run's workspace (scratch of the last evaluation, and the run's wave tables).
    pub fn workspace(&self) -> &Workspace {
        self.stepper.workspace()
    }

    /// Evaluates the right-hand side at the current state (fills tensions and end forces).
    pub fn evaluate(&mut self) -> Result<&Workspace, SimulationError> {
        self.stepper.evaluate(self.system)
    }

    /// Runs to `duration` [s], sampling at t = 0 and every output interval (the default
    /// channels; observers that need others read them from the view's system and workspace).
    pub fn run(
        &mut self,
        duration: Real,
        observer: &mut impl Observer,
    ) -> Result<(), SimulationError> {
        let interval = self.stepper.sample_interval();
        let end = (duration / interval - 1e-9).ceil().max(0.0) * interval;
        let system = self.system;
        let mut sample = |s: &Stepper| {
            let view = View {
                system,
                workspace: s.workspace(),
                time: s.time(),
                state: s.state(),
                channels: &[],
                sample: 0,
                releases: s.releases(),
            };
            observer
                .sample(&view)
                .map_err(|e| SimulationError::Observer { message: e.0 })
        };
        self.stepper.sample_start(system, &mut sample)?;
        self.stepper.advance(system, end, sample, false).map(|_| ())
    }
}

/// An observer that keeps nothing (benchmarks, runs read only at their end).
impl Observer for () {
    fn sample(&mut self, _: &View<'_>) -> Result<(), ObserverError> {
        Ok(())
    }
}
