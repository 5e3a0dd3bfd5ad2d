//! How a run starts: the initial-condition policy of a model (static equilibrium with the
//! released points held, the steady tow, or the shape as defined) and the rule for an input
//! step above the stability limit.

use crate::error::StaticsError;
use crate::math::Real;
use crate::model::{InitialCondition, Model, Settings, StepAboveLimit, TimeStep};
use crate::statics::{StaticOptions, StaticSolution};
use crate::system::System;

/// The initial state of `model` (assembled as `system`) by its
/// [`Settings::initial_condition`](crate::model::Settings): the static equilibrium with the
/// points of `settings.release` held and then free ([`crate::statics::solve_with_release`]),
/// the steady tow (the system carries the tow velocity, so its statics are the steady tow), or
/// the lines as defined ([`crate::statics::as_defined_shape`]: straight where taut, else
/// elastic catenaries under their weight in air or water, everything at rest). Returns
/// the state and the static solution when one was solved.
pub fn initial_state(
    system: &System,
    model: &Model,
    options: &StaticOptions,
) -> Result<(Vec<Real>, Option<StaticSolution>), StaticsError> {
    match model.settings.initial_condition {
        InitialCondition::Statics => {
            let sol = crate::statics::solve_with_release(model, system, options)?;
            Ok((sol.state.clone(), Some(sol)))
        }
        InitialCondition::SteadyTow => {
            let sol = crate::statics::solve(system, None, options)?;
            Ok((sol.state.clone(), Some(sol)))
        }
        InitialCondition::AsDefined => {
            let mut ws = system.workspace();
            let mut y = system.straight_state();
            crate::statics::as_defined_shape(system, &mut y, &mut ws);
            Ok((y, None))
        }
    }
}

/// The step [s] a run of `system` with `settings` will take at most, and what sets it: a fixed
/// step as given (unless [`step_fallback`] replaces it), else `safety_factor` times the
/// stability limit (the automatic step is then lowered to divide the output interval). For a
/// check of the run's length before anything is solved ([`super::check_run_length`]).
pub fn planned_step(system: &System, settings: &Settings) -> (Real, String) {
    let scheme = crate::integrate::choose_scheme(system, settings).scheme;
    if scheme == crate::model::Scheme::GeneralizedAlpha && settings.time_step == TimeStep::Auto {
        // Adaptive generalized-α has no stability limit: its first step is the accuracy step
        // (as the stepper takes it), no longer than the output interval.
        let (step, culprit) = crate::integrate::choice::accuracy_step(system, settings);
        return (step.min(settings.output_interval), culprit);
    }
    let (limit, culprit) = system.stable_step(scheme);
    match settings.time_step {
        TimeStep::Fixed(dt) if step_fallback(system, settings).is_none() => {
            (dt, "the scenario's time_step".to_string())
        }
        _ => (settings.safety_factor * limit, culprit),
    }
}

/// Nodes a run steps: every line node, free point and free body (for the length of a run).
pub fn stepped_nodes(system: &System) -> usize {
    system.lines.iter().map(|l| l.nodes()).sum::<usize>()
        + system.free_points.len()
        + system.free_bodies.len()
}

/// A fixed step that [`StepAboveLimit::UseAuto`] replaced by the automatic step.
#[derive(Clone, Debug, PartialEq)]
pub struct StepFallback {
    /// The input's step [s].
    pub requested: Real,
    /// The stability limit [s].
    pub limit: Real,
    /// What sets the limit.
    pub culprit: String,
}

/// The fixed step of `settings` when it is above the stability limit of `system` and the
/// settings say to take the automatic step instead ([`StepAboveLimit::UseAuto`], MoorDyn
/// decks, whose `dtM` was chosen for MoorDyn's integrator).
pub fn step_fallback(system: &System, settings: &Settings) -> Option<StepFallback> {
    let TimeStep::Fixed(dt) = settings.time_step else {
        return None;
    };
    if settings.step_above_limit != StepAboveLimit::UseAuto {
        return None;
    }
    let (limit, culprit) = system.stable_step(settings.scheme);
    (dt > limit).then_some(StepFallback {
        requested: dt,
        limit,
        culprit,
    })
}
