//! A dynamic run: the system, its state and the integrator, stepped in fixed steps that divide
//! the output interval exactly. The caller observes samples through [`Observer`]; the core
//! writes nothing.

use crate::error::SimulationError;
use crate::integrate::ExplicitRk;
use crate::math::Real;
use crate::model::{Settings, TimeStep};
use crate::system::{Location, System, Workspace};

/// Receives the state at every output time.
pub trait Observer {
    /// Called at t = 0 and after every output interval, with a workspace that holds a
    /// right-hand-side evaluation at this state (tensions, end forces, accelerations).
    fn sample(&mut self, system: &System, time: Real, state: &[Real], ws: &Workspace);
}

/// A dynamic simulation in progress.
pub struct Simulation<'a> {
    system: &'a System,
    ws: Workspace,
    integrator: ExplicitRk,
    derivative: Vec<Real>,
    /// Simulated time [s].
    pub time: Real,
    /// State vector.
    pub state: Vec<Real>,
    /// Time step [s].
    pub step: Real,
    /// Stability limit of the scheme [s] and what sets it.
    pub stable_step: (Real, String),
    steps_per_output: usize,
    steps_done: u64,
}

impl<'a> Simulation<'a> {
    /// Prepares a run from `initial` with the step rule of `settings`. A fixed step above the
    /// stability limit is refused.
    pub fn new(
        system: &'a System,
        settings: &Settings,
        initial: Vec<Real>,
    ) -> Result<Self, SimulationError> {
        Self::build(system, settings, initial, true)
    }

    /// As [`Simulation::new`], but a fixed step above the stability estimate is taken as
    /// given (for experts who know the estimate is conservative for their case; a run that
    /// then diverges stops with [`SimulationError::Diverged`]).
    pub fn new_unchecked(
        system: &'a System,
        settings: &Settings,
        initial: Vec<Real>,
    ) -> Result<Self, SimulationError> {
        Self::build(system, settings, initial, false)
    }

    fn build(
        system: &'a System,
        settings: &Settings,
        initial: Vec<Real>,
        check: bool,
    ) -> Result<Self, SimulationError> {
        let (limit, culprit) = system.stable_step(settings.scheme);
        let wanted = match settings.time_step {
            TimeStep::Auto => settings.safety_factor * limit,
            TimeStep::Fixed(dt) => {
                if check && dt > limit {
                    return Err(SimulationError::StepTooLarge {
                        step: dt,
                        limit,
                        culprit,
                    });
                }
                dt
            }
        };
        // Auto: a whole number of steps per output interval, none longer than wanted. Fixed:
        // the user's step exactly, sampling every round(output_interval / step) steps.
        let (step, per_output) = match settings.time_step {
            TimeStep::Auto => {
                let n = (settings.output_interval / wanted).ceil().max(1.0);
                (settings.output_interval / n, n)
            }
            TimeStep::Fixed(dt) => (dt, (settings.output_interval / dt).round().max(1.0)),
        };
        let ws = system.workspace();
        let n = initial.len();
        Ok(Self {
            system,
            ws,
            integrator: ExplicitRk::new(settings.scheme, n),
            derivative: vec![0.0; n],
            time: 0.0,
            state: initial,
            step,
            stable_step: (limit, culprit),
            steps_per_output: per_output as usize,
            steps_done: 0,
        })
    }

    /// Interval between samples [s] (a whole number of steps).
    pub fn sample_interval(&self) -> Real {
        self.step * self.steps_per_output as Real
    }

    /// Right-hand-side evaluations per step.
    pub fn evaluations_per_step(&self) -> usize {
        self.integrator.stages()
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> u64 {
        self.steps_done
    }

    /// Advances one step. Checks the state for non-finite values.
    pub fn step(&mut self) -> Result<(), SimulationError> {
        let sys = self.system;
        if let Err(loc) =
            self.integrator
                .step(sys, &mut self.ws, self.time, self.step, &mut self.state)
        {
            return Err(divergence(
                self.stable_step.0,
                self.time,
                loc,
                "singular mass matrix",
            ));
        }
        self.steps_done += 1;
        self.time = self.steps_done as Real * self.step;
        if let Some(i) = self.state.iter().position(|x| !x.is_finite()) {
            return Err(divergence(
                self.stable_step.0,
                self.time - self.step,
                sys.locate(i),
                "non-finite position or velocity",
            ));
        }
        Ok(())
    }

    /// Evaluates the right-hand side at the current state (fills tensions and end forces).
    pub fn evaluate(&mut self) -> Result<&Workspace, SimulationError> {
        let sys = self.system;
        sys.rhs(self.time, &self.state, &mut self.derivative, &mut self.ws)
            .map_err(|loc| {
                divergence(self.stable_step.0, self.time, loc, "singular mass matrix")
            })?;
        // Runaway strain: more than 100 % is no cable.
        for (li, lw) in self.ws.lines.iter().enumerate() {
            if let Some(e) = lw.elements.strain.iter().position(|&s| !(s < 1.0)) {
                let loc = Location {
                    object: sys.lines[li].name.clone(),
                    node: e + 1,
                };
                let reason = format!(
                    "runaway strain {:.3} above 100 % in element {e}, between nodes {e} and {}",
                    lw.elements.strain[e],
                    e + 1
                );
                return Err(divergence(self.stable_step.0, self.time, loc, &reason));
            }
        }
        Ok(&self.ws)
    }

    /// Runs to `duration` [s], sampling at t = 0 and every output interval.
    pub fn run(
        &mut self,
        duration: Real,
        observer: &mut impl Observer,
    ) -> Result<(), SimulationError> {
        let outputs = (duration / (self.step * self.steps_per_output as Real) - 1e-9)
            .ceil()
            .max(0.0) as u64;
        self.evaluate()?;
        observer.sample(self.system, self.time, &self.state, &self.ws);
        for _ in 0..outputs {
            for _ in 0..self.steps_per_output {
                self.step()?;
            }
            self.evaluate()?;
            observer.sample(self.system, self.time, &self.state, &self.ws);
        }
        Ok(())
    }
}

/// The error for a non-finite or runaway state at `location`, with the stable step estimate.
fn divergence(stable_step: Real, time: Real, location: Location, reason: &str) -> SimulationError {
    SimulationError::Diverged {
        time,
        object: location.object,
        node: location.node,
        reason: reason.to_string(),
        stable_step,
    }
}
