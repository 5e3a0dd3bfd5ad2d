//! A dynamic run: the system, its state and the integrator, stepped in fixed steps that divide
//! the output interval exactly. The caller observes samples through [`Observer`]; the core
//! writes nothing.

use crate::error::SimulationError;
use crate::integrate::{ExplicitRk, ThreeLevel};
use crate::math::Real;
use crate::model::{Scheme, Settings, TimeStep};
use crate::system::{Location, System, Workspace};

/// Receives the state at every output time.
pub trait Observer {
    /// Called at t = 0 and after every output interval, with a workspace that holds a
    /// right-hand-side evaluation at this state (tensions, end forces, accelerations).
    fn sample(&mut self, system: &System, time: Real, state: &[Real], ws: &Workspace);
}

/// C_k of the elastic-link paper's eq. 48 for the three-level scheme: the highest mode of a
/// lumped element chain has ω = 2c/l, and the predictor–corrector needs ωΔt ≤ 1, so
/// Δt ≤ l/(2c) (the paper allows C_k ≤ 1, which is unstable for this scheme).
const WAVE_COURANT: Real = 0.5;

/// The integrator of a run.
#[derive(Clone, Debug)]
enum Integrator {
    /// An explicit Runge–Kutta scheme at a fixed step.
    Rk(ExplicitRk),
    /// The three-level scheme; `variable`: the step is chosen again from the wave speeds
    /// (eq. 48) at the start of every output interval.
    ThreeLevel { scheme: ThreeLevel, variable: bool },
}

/// A dynamic simulation in progress.
pub struct Simulation<'a> {
    system: &'a System,
    ws: Workspace,
    integrator: Integrator,
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
    /// Interval between samples [s].
    interval: Real,
    /// Samples taken after t = 0, and steps since the last.
    outputs_done: u64,
    substep: usize,
    /// Fraction of the stability limit used by automatic steps.
    safety_factor: Real,
    /// The stiffness-and-damping estimate of the stable step [s] ([`System::stable_step`]).
    stiffness_limit: Real,
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
        if settings.scheme == Scheme::ThreeLevel
            && let Some(l) = system.lines.iter().find(|l| l.dg.is_some())
        {
            return Err(SimulationError::Model(crate::error::ModelError::Invalid {
                what: format!("line {}", l.name),
                why: "uses `dg`, a first-order system in q and v, which the three-level scheme \
                      (for second-order equations in positions) cannot step: use scheme = \
                      \"ssp-rk3\" (the DG paper's) or \"rk4\""
                    .into(),
            }));
        }
        if settings.scheme == Scheme::ThreeLevel && !system.free_bodies.is_empty() {
            return Err(SimulationError::Model(crate::error::ModelError::Invalid {
                what: format!("body {}", system.bodies[system.free_bodies[0]].body.name),
                why: "is free: the three-level scheme does not integrate rigid bodies yet; use \
                      scheme = \"rk4\" or \"ssp-rk3\""
                    .into(),
            }));
        }
        let (mut limit, mut culprit) = system.stable_step(settings.scheme);
        let stiffness_limit = limit;
        let n = initial.len();
        let mut ws = system.workspace();
        system.start_wave_tables(0.0, &initial, &mut ws);
        if settings.scheme == Scheme::ThreeLevel {
            // Eq. 48 at the initial strains, bounded by the stiffness-and-damping estimate.
            let mut derivative = vec![0.0; n];
            system
                .rhs(0.0, &initial, &mut derivative, &mut ws)
                .map_err(|loc| divergence(limit, 0.0, loc, "singular mass matrix"))?;
            let (wave, line, element) = system.wave_step(&ws, WAVE_COURANT);
            if wave < limit {
                limit = wave;
                culprit = format!(
                    "the axial wave in element {element} of line {} (elastic-link paper eq. 48)",
                    system.lines[line].name
                );
            }
        }
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
        let integrator = match settings.scheme.tableau() {
            Some(t) => Integrator::Rk(ExplicitRk::new(t, n)),
            None => Integrator::ThreeLevel {
                scheme: ThreeLevel::new(system, n),
                variable: settings.time_step == TimeStep::Auto,
            },
        };
        Ok(Self {
            system,
            ws,
            integrator,
            derivative: vec![0.0; n],
            time: 0.0,
            state: initial,
            step,
            stable_step: (limit, culprit),
            steps_per_output: per_output as usize,
            steps_done: 0,
            interval: step * per_output,
            outputs_done: 0,
            substep: 0,
            safety_factor: settings.safety_factor,
            stiffness_limit,
        })
    }

    /// Interval between samples [s] (a whole number of steps).
    pub fn sample_interval(&self) -> Real {
        self.interval
    }

    /// Right-hand-side (force) evaluations per step.
    pub fn evaluations_per_step(&self) -> usize {
        match &self.integrator {
            Integrator::Rk(rk) => rk.stages(),
            Integrator::ThreeLevel { scheme, .. } => scheme.evaluations(),
        }
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> u64 {
        self.steps_done
    }

    /// Advances one step. Checks the state for non-finite values.
    pub fn step(&mut self) -> Result<(), SimulationError> {
        let sys = self.system;
        let done = match &mut self.integrator {
            Integrator::Rk(rk) => rk.step(sys, &mut self.ws, self.time, self.step, &mut self.state),
            Integrator::ThreeLevel { scheme, .. } => {
                scheme.step(sys, &mut self.ws, self.time, self.step, &mut self.state)
            }
        };
        if let Err(loc) = done {
            return Err(divergence(
                self.stable_step.0,
                self.time,
                loc,
                "singular mass matrix",
            ));
        }
        self.steps_done += 1;
        self.substep += 1;
        if self.substep == self.steps_per_output {
            self.outputs_done += 1;
            self.substep = 0;
            if let Integrator::ThreeLevel { variable: true, .. } = self.integrator {
                // Variable step (eq. 48): the whole interval in equal steps no longer than
                // the wave limit at the current strains and the stiffness estimate.
                let wave = sys.wave_step(&self.ws, WAVE_COURANT).0;
                let wanted = self.safety_factor * wave.min(self.stiffness_limit);
                let n = (self.interval / wanted).ceil().max(1.0);
                self.step = self.interval / n;
                self.steps_per_output = n as usize;
            }
        }
        self.time = self.outputs_done as Real * self.interval + self.substep as Real * self.step;
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

    /// The run's workspace (scratch of the last evaluation, and the run's wave tables).
    pub fn workspace(&self) -> &Workspace {
        &self.ws
    }

    /// Runs to `duration` [s], sampling at t = 0 and every output interval.
    pub fn run(
        &mut self,
        duration: Real,
        observer: &mut impl Observer,
    ) -> Result<(), SimulationError> {
        let outputs = (duration / self.interval - 1e-9).ceil().max(0.0) as u64;
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
