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
/// the lines as defined (elastic catenaries between their ends, everything at rest). Returns
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
            crate::statics::catenary_seed(system, &mut y, &mut ws);
            Ok((y, None))
        }
    }
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
