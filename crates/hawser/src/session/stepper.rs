//! The time-stepping engine of a run: the integrator, its clock, the state and the scratch, on a
//! system it borrows at each call. [`crate::Session`] owns one together with its system; the
//! low-level [`crate::simulation::Simulation`] borrows a system for tests that compose parts.

use crate::error::{ModelError, SimulationError};
use crate::integrate::choice::SchemeSwitch;
use crate::integrate::generalized_alpha::{Attempt, Statistics};
use crate::integrate::{
    ExplicitRk, GeneralizedAlpha, RK4, SchemeChoice, ThreeLevel, choose_scheme,
};
use crate::math::Real;
use crate::model::{Scheme, Settings, TimeStep};
use crate::system::{Location, System, Workspace};
use crate::warning::Warning;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// C_k of the elastic-link paper's eq. 48 for the three-level scheme: the highest mode of a
/// lumped element chain has ω = 2c/l, and the predictor–corrector needs ωΔt ≤ 1, so
/// Δt ≤ l/(2c) (the paper allows C_k ≤ 1, which is unstable for this scheme).
const WAVE_COURANT: Real = 0.5;

/// The integrator of a run.
#[derive(Clone, Debug)]
pub(crate) enum Integrator {
    /// An explicit Runge–Kutta scheme.
    Rk(ExplicitRk),
    /// The three-level scheme; `variable`: the step is chosen again from the wave speeds
    /// (eq. 48) at the start of every output interval.
    ThreeLevel { scheme: ThreeLevel, variable: bool },
    /// The implicit generalized-α scheme; `adaptive`: each step is chosen by its error
    /// estimate ([`TimeStep::Auto`]), landing on every output time.
    GeneralizedAlpha {
        scheme: Box<GeneralizedAlpha>,
        adaptive: bool,
    },
}

/// The shortest adaptive step relative to the output interval [-]: a step that must be
/// shorter to meet the tolerance stops the run (a discontinuity the model cannot step over).
const MIN_ADAPTIVE_STEP: Real = 1e-9;

/// Simulated time kept without accumulating round-off: t = anchor + n·Δt, with the anchor
/// moved to the exact output time k·Δt_out whenever a step lands on one, so that in a run
/// whose steps divide the output interval every time is k·Δt_out + j·Δt.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Clock {
    /// Current step [s].
    pub step: Real,
    /// The run's own step [s] (set at the start, or by the three-level scheme's variable
    /// step); [`Stepper::advance`] shortens steps below it to land on a host's time.
    pub nominal: Real,
    /// Time the step count starts from [s].
    pub anchor: Real,
    /// Steps since the anchor.
    pub since_anchor: u64,
    /// Steps taken in all.
    pub steps_done: u64,
    /// Interval between samples [s] (a whole number of steps of the initial step).
    pub interval: Real,
    /// Index k of the next sample time k·Δt_out (the sample at t = 0 is index 0).
    pub next_output: u64,
}

impl Clock {
    /// Current time [s].
    #[inline]
    pub fn time(&self) -> Real {
        self.anchor + self.since_anchor as Real * self.step
    }

    /// Whether the time has reached the next sample time, within half a step.
    #[inline]
    pub fn output_due(&self) -> bool {
        self.time() >= self.next_output as Real * self.interval - 0.5 * self.step
    }

    /// Marks the next sample as taken, moving the anchor onto its exact time when the clock
    /// sits on it.
    pub fn take_output(&mut self) {
        let boundary = self.next_output as Real * self.interval;
        if (self.time() - boundary).abs() <= 1e-6 * self.step {
            self.anchor = boundary;
            self.since_anchor = 0;
        }
        self.next_output += 1;
    }

    /// Changes the step from now on.
    pub fn set_step(&mut self, step: Real) {
        if step != self.step {
            self.anchor = self.time();
            self.since_anchor = 0;
            self.step = step;
        }
    }
}

/// Everything the next step of a [`Stepper`] needs, saved in memory (a coupling host's
/// repeated interval) or in a checkpoint.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Saved {
    /// The state vector.
    pub state: Vec<Real>,
    /// The clock.
    pub clock: Clock,
    /// The scheme's history: the three-level scheme's previous level; generalized-α's
    /// accelerations and Jacobian ([`GeneralizedAlpha::history`]); empty for Runge–Kutta.
    pub history: Vec<Real>,
    /// The three-level scheme's last step [s] (0 for the others).
    pub last_step: Real,
    /// Per failure of the system: its release, if it happened ([`Stepper::releases`]).
    pub releases: Vec<Option<super::Release>>,
    /// `scheme = "auto"`'s switching between generalized-α and RK4 (default when the run
    /// does not switch).
    pub switch: SchemeSwitch,
}

/// What a run that `scheme = "auto"` started with adaptive generalized-α needs to go on with
/// RK4 and back ([`SchemeSwitch`]): the scheme not stepping now, sized at the start so that a
/// switch allocates nothing, and each scheme's step and stability limit.
#[derive(Clone, Debug)]
pub(crate) struct AutoSwitch {
    /// Which scheme steps, and the work that decides it.
    pub state: SchemeSwitch,
    /// The integrator not stepping now.
    standby: Integrator,
    /// The stability limit [s] and what sets it of the scheme not stepping now.
    standby_limit: (Real, String),
    /// RK4's steps per output interval: its automatic step is the interval in that many
    /// equal steps.
    explicit_steps: u64,
}

/// A run in progress on some system: integrator, clock, state and scratch, sized once.
#[derive(Clone, Debug)]
pub struct Stepper {
    pub(crate) ws: Workspace,
    pub(crate) integrator: Integrator,
    derivative: Vec<Real>,
    pub(crate) state: Vec<Real>,
    pub(crate) clock: Clock,
    /// Stability limit of the scheme [s] and what sets it.
    pub(crate) stable_step: (Real, String),
    /// Fraction of the stability limit used by automatic steps.
    safety_factor: Real,
    /// The stiffness-and-damping estimate of the stable step [s] ([`System::stable_step`]).
    stiffness_limit: Real,
    /// The state and clock before the last step, restored when that step diverged.
    last_good: (Vec<Real>, Clock),
    /// Stops the run between two steps when set.
    pub(crate) interrupt: Option<Arc<AtomicBool>>,
    /// Steps done when the workspace was last evaluated (`None`: never).
    evaluated_at: Option<u64>,
    /// Steps done when generalized-α last accepted a step whose accelerations still belong to
    /// the state (`None`: none, or the state or its inputs changed since): an evaluation there
    /// takes them instead of solving the mass system ([`System::rhs_with_accelerations`]).
    accelerations_at: Option<u64>,
    /// The scheme the run uses and why.
    scheme: SchemeChoice,
    /// Whether the next adaptive step was planned by [`Stepper::advance`].
    planned: bool,
    /// Per failure of the system ([`System::failures`]): its release, once it happened.
    pub(crate) releases: Vec<Option<super::Release>>,
    /// The run's first step [s]: an adaptive generalized-α run restarts its controller from
    /// it (or from its current step, when shorter) after a release ([`Stepper::restart`]).
    pub(crate) first_step: Real,
    /// `scheme = "auto"` started with adaptive generalized-α: the switching to RK4 and back
    /// ([`SchemeSwitch`]); `None` for every other run.
    pub(crate) auto: Option<Box<AutoSwitch>>,
}

/// What a step size rule found wrong.
pub(crate) fn scheme_error(system: &System, scheme: Scheme) -> Option<SimulationError> {
    if matches!(scheme, Scheme::ThreeLevel | Scheme::GeneralizedAlpha)
        && let Some(l) = system.lines.iter().find(|l| l.dg().is_some())
    {
        return Some(SimulationError::Model(ModelError::SchemeCannotStepDg {
            scheme: scheme.name(),
            line: l.name.clone(),
        }));
    }
    if scheme == Scheme::GeneralizedAlpha
        && let Some((b, parent)) = system.bodies.iter().find_map(|b| {
            let (parent, _) = b.body.kind.pin()?.parent()?;
            Some((b, parent))
        })
    {
        return Some(SimulationError::Model(
            ModelError::SchemeCannotStepPinOnBody {
                body: b.body.name.clone(),
                parent: system.bodies[parent].body.name.clone(),
            },
        ));
    }
    if scheme == Scheme::ThreeLevel && !system.free_bodies.is_empty() {
        return Some(SimulationError::Model(ModelError::SchemeCannotStepBodies {
            scheme: "three-level",
            body: system.bodies[system.free_bodies[0]].body.name.clone(),
        }));
    }
    None
}

impl Stepper {
    /// Prepares a run of `system` from `initial` with the step rule of `settings`. With
    /// `check`, a fixed step above the stability limit is refused; without, it is taken as
    /// given (a run that then diverges stops with [`SimulationError::Diverged`]).
    pub fn new(
        system: &System,
        settings: &Settings,
        initial: Vec<Real>,
        check: bool,
    ) -> Result<Self, SimulationError> {
        let choice = choose_scheme(system, settings);
        let scheme = choice.scheme;
        if let Some(e) = scheme_error(system, scheme) {
            return Err(e);
        }
        let (mut limit, mut culprit) = system.stable_step(scheme);
        if scheme == Scheme::GeneralizedAlpha {
            culprit = "nothing: generalized-α is unconditionally stable".into();
        }
        let stiffness_limit = limit;
        let n = initial.len();
        let mut ws = system.workspace();
        system.start_wave_tables(0.0, &initial, &mut ws);
        if scheme == Scheme::ThreeLevel {
            // Eq. 48 at the initial strains, bounded by the stiffness-and-damping estimate.
            let mut derivative = vec![0.0; n];
            system
                .rhs(0.0, &initial, &mut derivative, &mut ws)
                .map_err(|loc| divergence(limit, 0.0, loc, failed_solve(&ws)))?;
            let (wave, line, element) = system.wave_step(&ws, WAVE_COURANT);
            if wave < limit {
                limit = wave;
                culprit = format!(
                    "the axial wave in element {element} of line {} (elastic-link paper eq. 48)",
                    system.lines[line].name
                );
            }
        }
        let adaptive = scheme == Scheme::GeneralizedAlpha && settings.time_step == TimeStep::Auto;
        let wanted = match settings.time_step {
            // The first adaptive step: the a-priori accuracy step of the automatic choice.
            TimeStep::Auto if adaptive => {
                crate::integrate::choice::accuracy_step(system, settings).0
            }
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
            TimeStep::Auto if adaptive => (wanted.min(settings.output_interval), 1.0),
            TimeStep::Auto => {
                let n = (settings.output_interval / wanted).ceil().max(1.0);
                (settings.output_interval / n, n)
            }
            TimeStep::Fixed(dt) => (dt, (settings.output_interval / dt).round().max(1.0)),
        };
        let integrator = match (scheme, scheme.tableau()) {
            (_, Some(t)) => Integrator::Rk(ExplicitRk::new(t, n)),
            (Scheme::GeneralizedAlpha, None) => Integrator::GeneralizedAlpha {
                scheme: Box::new(GeneralizedAlpha::new(
                    system,
                    n,
                    settings.spectral_radius,
                    settings.tolerance,
                )),
                adaptive,
            },
            _ => Integrator::ThreeLevel {
                scheme: ThreeLevel::new(system, n),
                variable: settings.time_step == TimeStep::Auto,
            },
        };
        let interval = if adaptive {
            settings.output_interval
        } else {
            step * per_output
        };
        // `auto` chose adaptive generalized-α: RK4 at its automatic step stands by for the
        // stretches where it is the cheaper ([`SchemeSwitch`]).
        let auto = if adaptive
            && settings.scheme == Scheme::Auto
            && scheme_error(system, Scheme::Rk4).is_none()
        {
            let (limit, culprit) = system.stable_step(Scheme::Rk4);
            let steps = (interval / (settings.safety_factor * limit))
                .ceil()
                .max(1.0);
            // A degenerate RK4 step (zero, not finite, or beyond any run's length) never wins.
            (steps.is_finite() && steps <= MAX_STEPS).then(|| {
                Box::new(AutoSwitch {
                    state: SchemeSwitch::default(),
                    standby: Integrator::Rk(ExplicitRk::new(&RK4, n)),
                    standby_limit: (limit, culprit),
                    explicit_steps: steps as u64,
                })
            })
        } else {
            None
        };
        Ok(Self {
            ws,
            integrator,
            derivative: vec![0.0; n],
            last_good: (initial.clone(), Clock::default()),
            interrupt: None,
            evaluated_at: None,
            accelerations_at: None,
            state: initial,
            clock: Clock {
                step,
                nominal: step,
                anchor: 0.0,
                since_anchor: 0,
                steps_done: 0,
                interval,
                next_output: 0,
            },
            stable_step: (limit, culprit),
            safety_factor: settings.safety_factor,
            stiffness_limit,
            scheme: choice,
            planned: false,
            releases: vec![None; system.failures.len()],
            first_step: step,
            auto,
        })
    }

    /// `scheme = "auto"`'s switching so far (`None` unless `auto` started the run with
    /// adaptive generalized-α): switches made and output intervals stepped by RK4.
    pub fn scheme_switch(&self) -> Option<SchemeSwitch> {
        self.auto.as_ref().map(|a| a.state)
    }

    /// Puts the standby scheme in place of the stepping one ([`SchemeSwitch`]), at an output
    /// time: RK4 takes its automatic step; generalized-α starts again from the state as at
    /// the start of a run (its reference tensions kept), from the step it had when it left.
    /// Allocates nothing.
    fn swap_scheme(&mut self) {
        let Some(auto) = self.auto.as_deref_mut() else {
            return;
        };
        std::mem::swap(&mut self.integrator, &mut auto.standby);
        std::mem::swap(&mut self.stable_step, &mut auto.standby_limit);
        match &mut self.integrator {
            Integrator::GeneralizedAlpha { scheme, .. } => {
                scheme.restart(&self.ws);
                self.clock.nominal = auto.state.implicit_nominal;
            }
            _ => {
                auto.state.implicit_nominal = self.clock.nominal;
                let step = self.clock.interval / auto.explicit_steps as Real;
                self.clock.set_step(step);
                self.clock.nominal = step;
            }
        }
        self.accelerations_at = None;
    }

    /// The generalized-α integrator of the run, stepping or standing by for `auto`.
    fn implicit(&self) -> Option<&GeneralizedAlpha> {
        let standby = self.auto.as_deref().map(|a| &a.standby);
        [Some(&self.integrator), standby]
            .into_iter()
            .flatten()
            .find_map(|i| match i {
                Integrator::GeneralizedAlpha { scheme, .. } => Some(&**scheme),
                _ => None,
            })
    }

    /// The scheme the run uses and why ([`choose_scheme`]).
    pub fn scheme(&self) -> &SchemeChoice {
        &self.scheme
    }

    /// What the generalized-α scheme did so far (`None` for the other schemes).
    pub fn implicit_statistics(&self) -> Option<Statistics> {
        self.implicit().map(|s| s.statistics)
    }

    /// Whether each step is chosen by an error estimate (generalized-α with automatic steps).
    fn adaptive(&self) -> bool {
        matches!(
            self.integrator,
            Integrator::GeneralizedAlpha { adaptive: true, .. }
        )
    }

    /// The earliest time trigger [s] of a failure not released yet that is after now
    /// (infinite when there is none): adaptive steps land on it, so that a release due at a
    /// time happens at that time rather than up to a long step after it.
    fn next_failure_time(&self, system: &System) -> Real {
        let now = self.clock.time();
        system
            .failures
            .iter()
            .zip(&self.releases)
            .filter(|(_, r)| r.is_none())
            .filter_map(|(f, _)| f.time)
            .filter(|&at| at > now + 1e-9 * self.clock.interval)
            .fold(Real::INFINITY, Real::min)
    }

    /// The time [s] of the first output after now.
    fn next_output_time(&self) -> Real {
        let now = self.clock.time();
        let mut k = self.clock.next_output;
        while (k as Real) * self.clock.interval <= now + 1e-9 * self.clock.interval {
            k += 1;
        }
        k as Real * self.clock.interval
    }

    /// An adaptive step of about `wanted` [s] that lands on `boundary` [s]: the distance to it
    /// in ⌈distance / wanted⌉ equal steps.
    fn landing_step(&self, boundary: Real, wanted: Real) -> Real {
        let distance = boundary - self.clock.time();
        distance / (distance / wanted - 1e-9).ceil().max(1.0)
    }

    /// Simulated time [s].
    #[inline]
    pub fn time(&self) -> Real {
        self.clock.time()
    }

    /// Saves what the next step needs into `saved` (no allocation once `saved` has the sizes).
    pub(crate) fn save(&self, saved: &mut Saved) {
        // The sample's part (state, clock, releases, switching), then the scheme's history:
        // generalized-α's also while RK4 steps for `auto` (its reference tensions are the
        // run's, from the start).
        self.save_sample(saved);
        if let Integrator::ThreeLevel { scheme, .. } = &self.integrator {
            let (previous, last_step) = scheme.history();
            saved.history.clear();
            saved.history.extend_from_slice(previous);
            saved.last_step = last_step;
        } else if let Some(scheme) = self.implicit() {
            scheme.history(&mut saved.history);
        }
        // Otherwise (RK4 alone) no history: save_sample left it empty, with no last step.
    }

    /// Saves the state, clock and releases into `saved`, not the scheme's history (cleared):
    /// what a run's report of its last sample needs ([`Stepper::restore_sample`]). A sample is
    /// saved at every output time, and generalized-α's history (its Jacobian) is some thousand
    /// numbers, which took a third of an adaptive run's CPU time when it was saved there.
    /// Allocates nothing once `saved` has the sizes.
    pub(crate) fn save_sample(&self, saved: &mut Saved) {
        saved.state.clear();
        saved.state.extend_from_slice(&self.state);
        saved.clock = self.clock;
        saved.releases.clear();
        saved.releases.extend_from_slice(&self.releases);
        saved.switch = self.scheme_switch().unwrap_or_default();
        saved.history.clear();
        saved.last_step = 0.0;
    }

    /// Goes back to a sample saved by [`Stepper::save_sample`] to report it: the state, clock
    /// and releases; the scheme's history is left as it is, so the run must not step on from
    /// here (a diverged run's report of its last sample).
    pub(crate) fn restore_sample(&mut self, saved: &Saved) {
        self.state.copy_from_slice(&saved.state);
        self.clock = saved.clock;
        self.evaluated_at = None;
        self.accelerations_at = None;
        if saved.releases.len() == self.releases.len() {
            self.releases.copy_from_slice(&saved.releases);
        }
    }

    /// Marks the workspace stale (the inputs of the next evaluation changed).
    pub(crate) fn invalidate(&mut self) {
        self.evaluated_at = None;
        self.accelerations_at = None;
    }

    /// Goes back to a saved point of this run (or of a run of the same model); false when the
    /// saved history does not fit this run's scheme. The releases of line failures are taken
    /// back as saved; the system's line ends must then follow them
    /// ([`Stepper::apply_releases`]).
    pub(crate) fn restore(&mut self, saved: &Saved) -> bool {
        self.state.copy_from_slice(&saved.state);
        self.clock = saved.clock;
        self.evaluated_at = None;
        self.accelerations_at = None;
        if saved.releases.len() != self.releases.len() {
            return false;
        }
        self.releases.copy_from_slice(&saved.releases);
        if let Some(auto) = self.auto.as_deref_mut() {
            // The saved run's scheme steps; its generalized-α history is set below.
            if auto.state.explicit != saved.switch.explicit {
                std::mem::swap(&mut self.integrator, &mut auto.standby);
                std::mem::swap(&mut self.stable_step, &mut auto.standby_limit);
            }
            auto.state = saved.switch;
        } else if saved.switch != SchemeSwitch::default() {
            return false;
        }
        match &mut self.integrator {
            Integrator::ThreeLevel { scheme, .. } => {
                if saved.history.len() != self.state.len() {
                    return false;
                }
                scheme.set_history(&saved.history, saved.last_step);
                true
            }
            Integrator::GeneralizedAlpha { scheme, .. } => {
                // The saved accelerations are those of the saved step, as in the saved run.
                let fits = scheme.set_history(&saved.history);
                if fits && !saved.history.is_empty() {
                    self.accelerations_at = Some(self.clock.steps_done);
                }
                fits
            }
            // No history of its own; for `auto`, its standby generalized-α's.
            Integrator::Rk(_) => {
                saved.history.is_empty()
                    || match self.auto.as_deref_mut().map(|a| &mut a.standby) {
                        Some(Integrator::GeneralizedAlpha { scheme, .. }) => {
                            scheme.set_history(&saved.history)
                        }
                        _ => false,
                    }
            }
        }
    }

    /// The state vector.
    #[inline]
    pub fn state(&self) -> &[Real] {
        &self.state
    }

    /// The workspace, holding the last evaluation.
    #[inline]
    pub fn workspace(&self) -> &Workspace {
        &self.ws
    }

    /// Current time step [s].
    #[inline]
    pub fn step_size(&self) -> Real {
        self.clock.step
    }

    /// Stability limit of the scheme [s] and what sets it.
    pub fn stable_step(&self) -> (Real, &str) {
        (self.stable_step.0, &self.stable_step.1)
    }

    /// Interval between samples [s] (a whole number of steps).
    pub fn sample_interval(&self) -> Real {
        self.clock.interval
    }

    /// Right-hand-side (force) evaluations per step (generalized-α: per Newton iteration;
    /// [`Stepper::implicit_statistics`] counts them).
    pub fn evaluations_per_step(&self) -> usize {
        match &self.integrator {
            Integrator::Rk(rk) => rk.stages(),
            Integrator::ThreeLevel { scheme, .. } => scheme.evaluations(),
            Integrator::GeneralizedAlpha { scheme, .. } => scheme.evaluations(),
        }
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> u64 {
        self.clock.steps_done
    }

    /// Advances one step. Checks the interrupt flag before and the state for non-finite
    /// values after; a step that diverged leaves the state and time of the last good step
    /// (what a run's final state reports).
    pub fn step(&mut self, system: &System) -> Result<(), SimulationError> {
        if self.adaptive() && !std::mem::take(&mut self.planned) {
            // A step not planned by `advance` (a bare `step`): land on the next output or
            // failure time.
            let boundary = self.next_output_time().min(self.next_failure_time(system));
            let step = self.landing_step(boundary, self.clock.nominal);
            self.clock.set_step(step);
        }
        let (t, dt) = (self.clock.time(), self.clock.step);
        if let Some(flag) = &self.interrupt
            && flag.load(Ordering::Relaxed)
        {
            return Err(SimulationError::Interrupted { time: t });
        }
        self.last_good.0.copy_from_slice(&self.state);
        self.last_good.1 = self.clock;
        let done = match &mut self.integrator {
            Integrator::Rk(rk) => rk
                .step(system, &mut self.ws, t, dt, &mut self.state)
                .map_err(|loc| (loc, failed_solve(&self.ws).to_string())),
            Integrator::ThreeLevel { scheme, .. } => scheme
                .step(system, &mut self.ws, t, dt, &mut self.state)
                .map_err(|loc| (loc, failed_solve(&self.ws).to_string())),
            Integrator::GeneralizedAlpha { .. } => self.implicit_step(system, t, dt),
        };
        self.clock.steps_done += 1;
        self.clock.since_anchor += 1;
        let failed = match done {
            Err((loc, reason)) => Some(divergence(self.stable_step.0, t, loc, &reason)),
            // A test of every entry without early exit (it packs into registers), and the
            // search for the first only when one is not finite.
            Ok(()) if self.state.iter().fold(true, |all, x| all & x.is_finite()) => None,
            Ok(()) => self.state.iter().position(|x| !x.is_finite()).map(|i| {
                divergence(
                    self.stable_step.0,
                    t,
                    system.locate(i),
                    "non-finite position or velocity",
                )
            }),
        };
        if let Some(e) = failed {
            self.state.copy_from_slice(&self.last_good.0);
            self.clock = self.last_good.1;
            self.evaluated_at = None;
            self.accelerations_at = None;
            return Err(e);
        }
        self.accelerations_at = matches!(self.integrator, Integrator::GeneralizedAlpha { .. })
            .then_some(self.clock.steps_done);
        system.hold_pins(self.clock.time(), &mut self.state, &self.ws);
        Ok(())
    }

    /// A generalized-α step from t, of `dt` [s] or, adaptive, of what its error estimate
    /// allows: refused attempts are tried again shorter, landing on the same boundary; the
    /// clock takes the step done and the controller's next step as its nominal one.
    fn implicit_step(
        &mut self,
        system: &System,
        t: Real,
        dt: Real,
    ) -> Result<(), (Location, String)> {
        let adaptive = self.adaptive();
        let boundary = t + dt;
        let mut dt = dt;
        loop {
            let Integrator::GeneralizedAlpha { scheme, .. } = &mut self.integrator else {
                unreachable!("an implicit step of the generalized-α scheme")
            };
            let before = scheme.statistics;
            let attempt = scheme
                .step(system, &mut self.ws, t, dt, &mut self.state, adaptive)
                .map_err(|f| (f.location, f.reason))?;
            if let Some(auto) = self.auto.as_deref_mut() {
                let after = scheme.statistics;
                auto.state.add_attempt(
                    after.iterations - before.iterations,
                    after.jacobians - before.jacobians,
                );
            }
            match attempt {
                Attempt::Accepted { error } => {
                    if adaptive {
                        self.clock.nominal = scheme.next_step(self.clock.nominal, dt, error);
                    }
                    return Ok(());
                }
                Attempt::Rejected { error } => {
                    let wanted = scheme.retry_step(dt, error);
                    self.clock.nominal = wanted;
                    dt = self.landing_step(boundary, wanted);
                    if dt < MIN_ADAPTIVE_STEP * self.clock.interval {
                        return Err((
                            system.locate(0),
                            format!(
                                "the adaptive generalized-α step fell below {:.1e} s: the error \
                                 estimate or the Newton iterations fail at every step",
                                MIN_ADAPTIVE_STEP * self.clock.interval
                            ),
                        ));
                    }
                    self.clock.set_step(dt);
                }
            }
        }
    }

    /// One step; at an output time, marks the output taken, evaluates and calls `sample`.
    /// With `watch`, a line failure due after the step stops before the sample and is
    /// returned (its index, cause and the end's tension [N]): the caller releases it and then
    /// takes the sample ([`Stepper::sample_due`]).
    pub(crate) fn step_sampled<F>(
        &mut self,
        system: &System,
        sample: F,
        watch: bool,
    ) -> Result<Option<super::Due>, SimulationError>
    where
        F: FnOnce(&Stepper) -> Result<(), SimulationError>,
    {
        self.step(system)?;
        if watch && let Some(due) = self.due_failure(system)? {
            return Ok(Some(due));
        }
        self.sample_due(system, sample)?;
        Ok(None)
    }

    /// At an output time, marks the output taken, evaluates and calls `sample`.
    pub(crate) fn sample_due<F>(
        &mut self,
        system: &System,
        sample: F,
    ) -> Result<(), SimulationError>
    where
        F: FnOnce(&Stepper) -> Result<(), SimulationError>,
    {
        if self.clock.output_due() {
            self.take_output(system);
            self.evaluate(system)?;
            sample(self)?;
        }
        Ok(())
    }

    /// Steps to time `t` [s] exactly, sampling at every output time. When t − now is a whole
    /// number of steps (within 1e-9 of one) the run's own step is kept, so that runs whose
    /// hosts advance by whole steps are the same whatever the interval; otherwise the steps
    /// of this advance are shortened equally so that the last ends at t (none is longer than
    /// the run's step, so the stability limit holds).
    ///
    /// With `watch`, stops after the step at which a line failure is due and returns it
    /// ([`Stepper::step_sampled`]); the caller releases it and calls again.
    pub(crate) fn advance<F>(
        &mut self,
        system: &System,
        t: Real,
        mut sample: F,
        watch: bool,
    ) -> Result<Option<super::Due>, SimulationError>
    where
        F: FnMut(&Stepper) -> Result<(), SimulationError>,
    {
        loop {
            let nominal = self.clock.nominal;
            let remaining = t - self.clock.time();
            if !(remaining > 1e-9 * nominal) {
                break;
            }
            if self.adaptive() {
                let boundary = t
                    .min(self.next_output_time())
                    .min(self.next_failure_time(system));
                let step = self.landing_step(boundary, nominal);
                self.clock.set_step(step);
                self.planned = true;
                if let Some(due) = self.step_sampled(system, &mut sample, watch)? {
                    return Ok(Some(due));
                }
                continue;
            }
            let k = remaining / nominal;
            let whole = k.round();
            let step = if whole >= 1.0 && (k - whole).abs() <= 1e-9 * whole {
                nominal
            } else {
                remaining / k.ceil().max(1.0)
            };
            self.clock.set_step(step);
            if let Some(due) = self.step_sampled(system, &mut sample, watch)? {
                return Ok(Some(due));
            }
        }
        // Land on t itself (the steps sum to it within round-off).
        let off = (self.clock.time() - t).abs();
        if off != 0.0 && off <= 1e-6 * self.clock.step {
            self.clock.anchor = t;
            self.clock.since_anchor = 0;
        }
        Ok(None)
    }

    /// Takes the sample at t = 0 once: marks it taken, evaluates and calls `sample`.
    pub(crate) fn sample_start<F>(
        &mut self,
        system: &System,
        sample: F,
    ) -> Result<(), SimulationError>
    where
        F: FnOnce(&Stepper) -> Result<(), SimulationError>,
    {
        if self.clock.next_output == 0 {
            self.take_output(system);
            self.evaluate(system)?;
            sample(self)?;
        }
        Ok(())
    }

    /// Whether the clock has reached the next sample time.
    #[inline]
    pub fn output_due(&self) -> bool {
        self.clock.output_due()
    }

    /// Marks the sample due now as taken; the three-level scheme with automatic steps then
    /// chooses the step of the next output interval (eq. 48): the whole interval in equal
    /// steps no longer than the wave limit at the current strains and the stiffness estimate.
    pub fn take_output(&mut self, system: &System) {
        let first = self.clock.next_output == 0;
        let output = self.clock.next_output;
        self.clock.take_output();
        if !first
            && let Some(auto) = self.auto.as_deref_mut()
            && auto.state.at_output(output, auto.explicit_steps)
        {
            self.swap_scheme();
        }
        if !first && let Integrator::ThreeLevel { variable: true, .. } = self.integrator {
            let wave = system.wave_step(&self.ws, WAVE_COURANT).0;
            let wanted = self.safety_factor * wave.min(self.stiffness_limit);
            let n = (self.clock.interval / wanted).ceil().max(1.0);
            self.clock.set_step(self.clock.interval / n);
            self.clock.nominal = self.clock.step;
        }
    }

    /// Evaluates the right-hand side at the current state (fills tensions and end forces) and
    /// checks for runaway strain; does nothing when the state has not changed since the last
    /// evaluation.
    pub fn evaluate(&mut self, system: &System) -> Result<&Workspace, SimulationError> {
        if self.evaluated_at != Some(self.clock.steps_done) {
            self.evaluate_anew(system)?;
        }
        Ok(&self.ws)
    }

    /// [`Stepper::evaluate`], always.
    fn evaluate_anew(&mut self, system: &System) -> Result<(), SimulationError> {
        let t = self.clock.time();
        self.evaluated_at = None;
        // After a generalized-α step, its accelerations where they are all a solve would give.
        let given = match &self.integrator {
            Integrator::GeneralizedAlpha { scheme, .. }
                if self.accelerations_at == Some(self.clock.steps_done) =>
            {
                system.rhs_with_accelerations(
                    t,
                    &self.state,
                    scheme.accelerations(),
                    &mut self.derivative,
                    &mut self.ws,
                )
            }
            _ => false,
        };
        if !given {
            system
                .rhs(t, &self.state, &mut self.derivative, &mut self.ws)
                .map_err(|loc| divergence(self.stable_step.0, t, loc, failed_solve(&self.ws)))?;
        }
        // Runaway strain: more than 100 % is no cable.
        for (li, lw) in self.ws.lines.iter().enumerate() {
            if let Some(e) = lw.elements.strain.iter().position(|&s| !(s < 1.0)) {
                let loc = Location {
                    object: system.lines[li].name.clone(),
                    node: e + 1,
                };
                let reason = format!(
                    "runaway strain {:.3} above 100 % in element {e}, between nodes {e} and {}",
                    lw.elements.strain[e],
                    e + 1
                );
                return Err(divergence(self.stable_step.0, t, loc, &reason));
            }
        }
        self.evaluated_at = Some(self.clock.steps_done);
        Ok(())
    }
}

/// Steps beyond which a run is refused ([`SimulationError::StepUnusable`]): 1e12 steps take a
/// year at the 3e4 steps/s of a 137-node line (catenary_mooring at 4.3e6 node-steps/s), and a
/// step below 1e-12 of the duration is a property far outside the physical range.
pub const MAX_STEPS: Real = 1e12;

/// Whether a run of `duration` [s] with time step `step` [s] (set by `culprit`) on `nodes`
/// nodes can end: refused when the step is zero, not finite or needs more than [`MAX_STEPS`]
/// steps; a [`Warning::LongRun`] when it needs more than
/// [`LONG_RUN_NODE_STEPS`](crate::warning::LONG_RUN_NODE_STEPS) node-steps. Used by
/// [`crate::Session`] and by hosts that check a model without running it (`hawser check`).
pub fn check_run_length(
    step: Real,
    culprit: &str,
    duration: Real,
    nodes: usize,
) -> Result<Option<Warning>, SimulationError> {
    let steps = if step > 0.0 {
        (duration / step).ceil()
    } else {
        Real::INFINITY
    };
    if !(step > 0.0 && step.is_finite() && steps <= MAX_STEPS) {
        return Err(SimulationError::StepUnusable {
            step,
            culprit: culprit.to_string(),
            duration,
            steps,
        });
    }
    Ok(
        (steps * nodes as Real > crate::warning::LONG_RUN_NODE_STEPS).then(|| Warning::LongRun {
            step,
            steps,
            nodes,
            culprit: culprit.to_string(),
        }),
    )
}

/// Why the mass solve of an evaluation failed: a state that blew up within the step (its
/// stages met non-finite positions, velocities or forces), or a mass matrix that is singular
/// for a finite state.
fn failed_solve(ws: &Workspace) -> &'static str {
    if ws.holds_non_finite() {
        "non-finite position, velocity or force within the step: the state blew up"
    } else {
        "singular mass matrix"
    }
}

/// The error for a non-finite or runaway state at `location`, with the stable step estimate.
pub(crate) fn divergence(
    stable_step: Real,
    time: Real,
    location: Location,
    reason: &str,
) -> SimulationError {
    SimulationError::Diverged {
        time,
        object: location.object,
        node: location.node,
        reason: reason.to_string(),
        stable_step,
    }
}
