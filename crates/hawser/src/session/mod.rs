//! A run as a library object: [`Session`] owns everything a dynamic run needs (the model, the
//! assembled system, the state, the integrator and its scratch) and is driven by its host:
//! the command line, a Python notebook, a coupling host such as OpenFAST or WEC-Sim.
//!
//! ```text
//! Model ──Session::new──▶ System (assembled) + initial state (statics / release / steady tow /
//!                         as defined) + Stepper (integrator, clock, workspace)
//! host:  set coupled kinematics ─▶ advance_to(t) ─▶ read channels, line samples, reactions
//!                                      │ every output interval
//!                                      ▼
//!                                  Observer::sample(&View)   (writers, recorders, progress)
//! ```
//!
//! Stepping allocates nothing: the state, the workspace, the integrator's stages and the
//! coupling buffers are sized when the session is built.

mod checkpoint;
mod constant_velocity;
mod coupling;
mod failure;
mod initial;
mod stepper;
mod view;

pub use checkpoint::{CHECKPOINT_VERSION, Decoder, Encoder, fnv1a, model_hash};
pub(crate) use failure::Due;
pub use failure::{FailureEvent, Release, ReleaseCause, failure_events};
pub use initial::{StepFallback, initial_state, planned_step, step_fallback, stepped_nodes};
pub use stepper::{MAX_STEPS, Stepper, check_run_length};
pub use view::{Attached, LineSample, LineSamples, Observer, ObserverError, RunEnd, View};

use crate::analysis::OutputChannel;
use crate::error::SimulationError;
use crate::math::Real;
use crate::model::{Model, TimeStep};
use crate::statics::{StaticOptions, StaticSolution};
use crate::system::{System, Workspace};
use crate::warning::Warning;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// Choices of the host that are not part of the model.
#[derive(Clone, Debug, Default)]
pub struct SessionOptions {
    /// Accept a fixed `time_step` above the stability estimate (expert use: a run that then
    /// diverges stops with the time, line and node).
    pub allow_unstable_step: bool,
    /// Options of the initial statics.
    pub statics: StaticOptions,
}

/// Identifies an attached observer ([`Session::attach`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ObserverId(usize);

/// An owning dynamic run: built from a [`Model`], stepped by its host, observed by writers.
pub struct Session {
    model: Model,
    system: System,
    stepper: Stepper,
    channels: Vec<OutputChannel>,
    observers: Vec<Option<Box<dyn Attached>>>,
    statics: Option<StaticSolution>,
    fallback: Option<StepFallback>,
    /// The warnings of the initial statics and of the run's length.
    warnings: Vec<Warning>,
    /// Samples given to the observers so far (0: not even the one at t = 0).
    samples: u64,
    /// Time of the last sample [s].
    last_sample: Real,
    /// The end time of the model's duration on the output grid [s].
    end_time: Real,
    /// The coupled objects and the coupling interval in progress.
    coupling: coupling::Coupling,
    /// The run at its last sample: what a diverged run reports as its final state (the
    /// state of the failed step, or of the step before it, may already be blown up).
    sampled: stepper::Saved,
}

impl Session {
    /// A run of `model` from its initial condition, with the default options.
    pub fn new(model: Model) -> Result<Self, SimulationError> {
        Self::with_options(model, SessionOptions::default())
    }

    /// A run of `model` from its initial condition ([`initial_state`]): the static
    /// equilibrium (with released points held), the steady tow, or the lines as defined.
    pub fn with_options(model: Model, options: SessionOptions) -> Result<Self, SimulationError> {
        let system = System::new(&model)?;
        // A run that cannot end is refused before its statics are solved.
        let (step, culprit) = planned_step(&system, &model.settings);
        check_run_length(
            step,
            &culprit,
            model.settings.duration,
            stepped_nodes(&system),
        )?;
        let (state, statics) = if system.failures.is_empty() {
            initial_state(&system, &model, &options.statics)?
        } else {
            // The intact system's state is a prefix of this one's: the failures' reserved
            // free ends come last and rest until released.
            let intact = model.intact();
            let twin = System::new(&intact)?;
            let (mut state, mut statics) = initial_state(&twin, &intact, &options.statics)?;
            state.resize(system.layout.len, 0.0);
            // A dormant free end rests where its attachment starts (what a points file shows).
            for f in &system.failures {
                let o =
                    system.layout.point_offset[f.free_end].expect("a free end has a state block");
                crate::math::set3(&mut state[o..], 0, &system.points[f.free_end].position);
            }
            if let Some(s) = statics.as_mut() {
                s.state.resize(system.layout.len, 0.0);
            }
            (state, statics)
        };
        Self::assemble(model, system, state, statics, &options)
    }

    /// A run of `model` from a given `state` (of the layout of `System::new(&model)`), with no
    /// initial statics: verification cases that start from a known shape, restarts.
    pub fn from_state(
        model: Model,
        state: Vec<Real>,
        options: SessionOptions,
    ) -> Result<Self, SimulationError> {
        let system = System::new(&model)?;
        if state.len() != system.layout.len {
            return Err(SimulationError::Model(
                crate::error::ModelError::StateLength {
                    given: state.len(),
                    expected: system.layout.len,
                },
            ));
        }
        Self::assemble(model, system, state, None, &options)
    }

    fn assemble(
        mut model: Model,
        system: System,
        state: Vec<Real>,
        statics: Option<StaticSolution>,
        options: &SessionOptions,
    ) -> Result<Self, SimulationError> {
        let fallback = step_fallback(&system, &model.settings);
        if fallback.is_some() && !options.allow_unstable_step {
            model.settings.time_step = TimeStep::Auto;
        }
        let stepper = Stepper::new(
            &system,
            &model.settings,
            state,
            !options.allow_unstable_step,
        )?;
        let channels = if model.outputs.is_empty() {
            crate::analysis::channels::default_channels(&model)
        } else {
            model.outputs.clone()
        };
        let mut coupling = coupling::Coupling::of(&model);
        // Sized now: saving the start of an interval allocates nothing.
        stepper.save(&mut coupling.start);
        let mut sampled = stepper::Saved::default();
        stepper.save_sample(&mut sampled);
        let interval = stepper.sample_interval();
        let duration = model.settings.duration;
        let (_, culprit) = stepper.stable_step();
        let long = check_run_length(
            stepper.step_size(),
            culprit,
            duration,
            stepped_nodes(&system),
        )?;
        let mut warnings = statics.as_ref().map_or(Vec::new(), |s| s.warnings.clone());
        warnings.extend(long);
        let outputs = (duration / interval - 1e-9).ceil().max(0.0);
        Ok(Self {
            warnings,
            end_time: outputs * interval,
            model,
            system,
            stepper,
            channels,
            observers: Vec::new(),
            statics,
            fallback: fallback.filter(|_| !options.allow_unstable_step),
            samples: 0,
            last_sample: 0.0,
            coupling,
            sampled,
        })
    }

    /// The model.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The assembled system.
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The initial static solution, when the run started from one.
    pub fn initial_statics(&self) -> Option<&StaticSolution> {
        self.statics.as_ref()
    }

    /// What the engineer must know about this run: the warnings of its initial statics
    /// ([`StaticSolution::warnings`]) and of its length ([`Warning::LongRun`]).
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings
    }

    /// The input's fixed step, when it was above the stability limit and replaced by the
    /// automatic step ([`crate::model::StepAboveLimit::UseAuto`]).
    pub fn step_fallback(&self) -> Option<&StepFallback> {
        self.fallback.as_ref()
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

    /// Right-hand-side evaluations per step.
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

    /// What the time integration did so far: the scheme and why, steps, the step now,
    /// generalized-α's counts and `auto`'s switching ([`crate::integrate::IntegratorReport`]).
    pub fn integrator_report(&self) -> crate::integrate::IntegratorReport {
        let interval = self.stepper.sample_interval();
        crate::integrate::IntegratorReport {
            choice: self.stepper.scheme().clone(),
            steps: self.stepper.steps_done(),
            time_step: self.stepper.step_size(),
            generalized_alpha: self.stepper.implicit_statistics(),
            switching: self
                .stepper
                .scheme_switch()
                .map(|w| crate::integrate::SwitchingReport {
                    switches: w.switches,
                    rk4_time: w.explicit_outputs as Real * interval,
                    rk4_now: w.explicit,
                }),
        }
    }

    /// Steps taken so far.
    pub fn steps_done(&self) -> u64 {
        self.stepper.steps_done()
    }

    /// End of the model's duration on the output grid [s]: the first sample time at or after
    /// `settings.duration`.
    pub fn end_time(&self) -> Real {
        self.end_time
    }

    /// Time of the last sample given to the observers [s].
    pub fn last_sample_time(&self) -> Real {
        self.last_sample
    }

    /// The run's output channels, in column order.
    pub fn channels(&self) -> &[OutputChannel] {
        &self.channels
    }

    /// A flag that stops the run between two steps when set (by a signal handler, a GUI, a
    /// Python KeyboardInterrupt): [`Session::advance_to`] then returns
    /// [`SimulationError::Interrupted`] with the state of the last step.
    pub fn set_interrupt(&mut self, flag: Arc<AtomicBool>) {
        self.stepper.interrupt = Some(flag);
    }

    /// Attaches an observer; it receives every sample from now on.
    pub fn attach(&mut self, observer: impl Attached) -> ObserverId {
        self.observers.push(Some(Box::new(observer)));
        ObserverId(self.observers.len() - 1)
    }

    /// The attached observer `id`, if it is a `T`.
    pub fn observer<T: Attached>(&self, id: ObserverId) -> Option<&T> {
        let o: &dyn std::any::Any = self.observers.get(id.0)?.as_deref()?;
        o.downcast_ref()
    }

    /// The attached observer `id`, mutably, if it is a `T`.
    pub fn observer_mut<T: Attached>(&mut self, id: ObserverId) -> Option<&mut T> {
        let o: &mut dyn std::any::Any = self.observers.get_mut(id.0)?.as_deref_mut()?;
        o.downcast_mut()
    }

    /// Detaches observer `id` and gives it back, if it is a `T`.
    pub fn detach<T: Attached>(&mut self, id: ObserverId) -> Option<T> {
        let slot = self.observers.get_mut(id.0)?;
        if !slot.as_deref().is_some_and(|o| {
            let o: &dyn std::any::Any = o;
            o.is::<T>()
        }) {
            return None;
        }
        let o: Box<dyn std::any::Any> = slot.take()?;
        o.downcast().ok().map(|b| *b)
    }

    /// The current state with its evaluation (channels, line samples, body loads). Evaluates
    /// the right-hand side first when the state changed since the last evaluation.
    pub fn view(&mut self) -> Result<View<'_>, SimulationError> {
        self.stepper.evaluate(&self.system)?;
        Ok(self.current_view())
    }

    fn current_view(&self) -> View<'_> {
        view_of(
            &self.system,
            &self.stepper,
            &self.channels,
            self.samples.saturating_sub(1),
        )
    }

    /// The workspace of the last evaluation (for low-level readers; [`Session::view`] is the
    /// checked way).
    pub fn workspace(&self) -> &Workspace {
        self.stepper.workspace()
    }

    /// Advances one step, sampling if an output time is reached.
    pub fn step(&mut self) -> Result<(), SimulationError> {
        self.advance(None)
    }

    /// Steps to time `t` [s], sampling at every output time. When t − now is a whole number
    /// of steps the run's own step is kept; otherwise the steps to t are shortened equally so
    /// that the last ends at t (a coupling host's interval that the step does not divide).
    pub fn advance_to(&mut self, t: Real) -> Result<(), SimulationError> {
        self.advance(Some(t))
    }

    /// [`Session::advance_to`] `t`, or one step. A line failure due after a step is released
    /// before the sample at that time ([`failure`]); the run then goes on.
    fn advance(&mut self, t: Option<Real>) -> Result<(), SimulationError> {
        // Failures due before the first step (a time of 0, a tension already above its limit).
        self.release_due()?;
        loop {
            let Self {
                system,
                stepper,
                channels,
                observers,
                samples,
                last_sample,
                sampled,
                ..
            } = self;
            let mut notify = |s: &Stepper| {
                notify_observers(
                    system,
                    s,
                    channels,
                    observers,
                    samples,
                    last_sample,
                    sampled,
                )
            };
            stepper.sample_start(system, &mut notify)?;
            let watch = stepper.failures_pending();
            let due = match t {
                Some(t) => stepper.advance(system, t, &mut notify, watch)?,
                None => stepper.step_sampled(system, &mut notify, watch)?,
            };
            let Some((k, cause, tension)) = due else {
                return Ok(());
            };
            self.stepper.release(&mut self.system, k, cause, tension)?;
            self.release_due()?;
            let Self {
                system,
                stepper,
                channels,
                observers,
                samples,
                last_sample,
                sampled,
                ..
            } = self;
            stepper.sample_due(system, |s: &Stepper| {
                notify_observers(
                    system,
                    s,
                    channels,
                    observers,
                    samples,
                    last_sample,
                    sampled,
                )
            })?;
            if t.is_none() {
                return Ok(());
            }
        }
    }

    /// Releases every failure due at the current state.
    fn release_due(&mut self) -> Result<(), SimulationError> {
        if !self.stepper.failures_pending() {
            return Ok(());
        }
        while let Some((k, cause, tension)) = self.stepper.due_failure(&self.system)? {
            self.stepper.release(&mut self.system, k, cause, tension)?;
        }
        Ok(())
    }

    /// Releases end `end` of line `line` from its attachment now, between two steps (a host's
    /// call: a line cut on purpose, a failure decided outside hawser). The end must have a
    /// failure in the model ([`crate::model::Model::failures`], with or without a trigger of
    /// its own), which reserves its free end's state; releasing an end twice does nothing.
    /// The release is recorded with the end's tension at this state and
    /// [`ReleaseCause::Host`].
    pub fn release(&mut self, line: &str, end: crate::model::End) -> Result<(), SimulationError> {
        let Some(k) = self.system.failures.iter().position(|f| {
            f.ends()
                .any(|(l, e)| self.system.lines[l].name == line && e == end)
        }) else {
            let known: Vec<String> = self
                .system
                .failures
                .iter()
                .flat_map(|f| f.ends())
                .map(|(l, e)| format!("{}.end_{}", self.system.lines[l].name, e.name()))
                .collect();
            return Err(SimulationError::Model(crate::error::ModelError::Invalid {
                what: format!("release of line {line}, end {}", end.name()),
                why: format!(
                    "that line end has no failure in the model, so no free end is reserved \
                     for it: add one (a `[lines.NAME.failure]` table, or a MoorDyn FAILURE \
                     row); the ends that can release are: {}",
                    if known.is_empty() {
                        "none".to_string()
                    } else {
                        known.join(", ")
                    }
                ),
            }));
        };
        let ws = self.stepper.evaluate(&self.system)?;
        let tension = failure::failure_tension(&self.system, ws, k);
        self.stepper
            .release(&mut self.system, k, ReleaseCause::Host, tension)
    }

    /// The line failures that happened so far, in the model's order.
    pub fn failure_events(&self) -> Vec<FailureEvent> {
        failure_events(&self.system, self.stepper.releases())
    }

    /// Runs to the end of the model's duration ([`Session::end_time`]).
    pub fn run(&mut self) -> Result<(), SimulationError> {
        self.advance_to(self.end_time)
    }

    /// Ends the run: every observer's [`Observer::finish`] with the last state (evaluated
    /// when it can be) and how the run ended (`error`: the error that stopped it). Returns the
    /// first observer error.
    pub fn finish(&mut self, error: Option<&SimulationError>) -> Result<(), SimulationError> {
        if error.is_none() {
            self.advance_to(self.stepper.time())?;
        }
        // A diverged run reports the state of its last sample, which passed the checks.
        if matches!(error, Some(SimulationError::Diverged { .. })) && self.samples > 0 {
            self.stepper.restore_sample(&self.sampled);
            self.stepper.apply_releases(&mut self.system);
        }
        // A state that cannot be evaluated (a singular mass matrix) reports the workspace of
        // its last evaluation.
        let _ = self.stepper.evaluate(&self.system);
        let end = RunEnd {
            last_sample: self.last_sample,
            error: error.map(|e| e.to_string()),
            interrupted: matches!(error, Some(SimulationError::Interrupted { .. })),
            warnings: self.warnings.clone(),
            integrator: self.integrator_report(),
        };
        let mut observers = std::mem::take(&mut self.observers);
        let view = self.current_view();
        let mut first = None;
        for o in observers.iter_mut().flatten() {
            if let Err(e) = o.finish(&view, &end)
                && first.is_none()
            {
                first = Some(SimulationError::Observer { message: e.0 });
            }
        }
        self.observers = observers;
        first.map_or(Ok(()), Err)
    }
}

/// Gives the observers the sample of `s`'s current state.
fn notify_observers(
    system: &System,
    s: &Stepper,
    channels: &[OutputChannel],
    observers: &mut [Option<Box<dyn Attached>>],
    samples: &mut u64,
    last_sample: &mut Real,
    sampled: &mut stepper::Saved,
) -> Result<(), SimulationError> {
    *samples += 1;
    *last_sample = s.time();
    s.save_sample(sampled);
    let view = view_of(system, s, channels, *samples - 1);
    for o in observers.iter_mut().flatten() {
        o.sample(&view)
            .map_err(|e| SimulationError::Observer { message: e.0 })?;
    }
    Ok(())
}

/// The view of a stepper's current state.
fn view_of<'a>(
    system: &'a System,
    stepper: &'a Stepper,
    channels: &'a [OutputChannel],
    sample: u64,
) -> View<'a> {
    View {
        system,
        workspace: stepper.workspace(),
        time: stepper.time(),
        state: stepper.state(),
        channels,
        sample,
        releases: stepper.releases(),
    }
}
