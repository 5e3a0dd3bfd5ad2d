//! `[simulation]`: duration, step, scheme and initial condition, the release of held points,
//! and the checks of a steady tow.

use super::{Builder, Check, NON_NEGATIVE, POSITIVE};
use crate::scenario::diagnostics::closest;
use crate::scenario::schema::*;
use hawser::model::*;
use std::ops::Range;

/// The result formats a run writes besides CSV and JSON (`simulation.formats`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutputFormats {
    /// `timeseries.parquet` (needs this crate's `parquet` feature).
    pub parquet: bool,
    /// ParaView files at each snapshot (`vtk/run.pvd`).
    pub vtk: bool,
}

impl Default for OutputFormats {
    /// Every format this build can write: Parquet when built with it, and VTK.
    fn default() -> Self {
        Self {
            parquet: cfg!(feature = "parquet"),
            vtk: true,
        }
    }
}

/// `simulation.formats`: the defaults when absent; Parquet refused when this build has not
/// got it; VTK without `snapshot_interval` refused (it would write nothing).
pub(super) fn build_formats(b: &mut Builder, spec: Option<&SimulationSpec>) -> OutputFormats {
    let Some(formats) = spec.and_then(|s| s.formats.as_ref()) else {
        return OutputFormats::default();
    };
    let chosen = |f| formats.get_ref().contains(&f);
    let out = OutputFormats {
        parquet: chosen(FormatSpec::Parquet),
        vtk: chosen(FormatSpec::Vtk),
    };
    if out.parquet && !cfg!(feature = "parquet") {
        let d = b
            .diag(
                Some(formats.span()),
                "simulation.formats",
                "this hawser was built without Parquet",
            )
            .expected("\"vtk\" in this build")
            .hint(
                "remove \"parquet\", or build hawser with the cargo feature `parquet` (the \
                 command-line tool has it by default)",
            );
        b.push(d);
    }
    if out.vtk && spec.is_some_and(|s| s.snapshot_interval.is_none()) {
        let d = b
            .diag(
                Some(formats.span()),
                "simulation.formats",
                "\"vtk\" writes the snapshots for ParaView, and there are none",
            )
            .expected("`snapshot_interval` with \"vtk\"")
            .hint("add `snapshot_interval = ...` (s) to [simulation], or remove \"vtk\"");
        b.push(d);
    }
    out
}

pub(super) fn build_settings(
    b: &mut Builder,
    spec: Option<&SimulationSpec>,
) -> (Settings, Option<Range<usize>>) {
    // `scheme = "auto"` unless the scenario sets one (docs/implicit.md).
    let mut s = Settings::default();
    let Some(sim) = spec else { return (s, None) };
    s.duration = b.num(
        &sim.duration,
        "simulation.duration",
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "the simulated time span",
    );
    s.output_interval = b.opt(
        &sim.output_interval,
        "simulation.output_interval",
        0.1,
        Check {
            ok: POSITIVE,
            expected: "s, > 0",
        },
        "e.g. 0.1 s",
    );
    s.safety_factor = b.opt(
        &sim.safety_factor,
        "simulation.safety_factor",
        0.8,
        Check {
            ok: |x| x > 0.0 && x <= 1.0,
            expected: "-, in (0, 1]",
        },
        "0.8 leaves a margin below the stability limit",
    );
    if let Some(si) = &sim.snapshot_interval {
        s.snapshot_interval = Some(b.num(
            si,
            "simulation.snapshot_interval",
            Check {
                ok: POSITIVE,
                expected: "s, > 0",
            },
            "e.g. 1 s",
        ));
    }
    s.scheme = match sim.scheme {
        Some(SchemeSpec::Rk4) => Scheme::Rk4,
        Some(SchemeSpec::SspRk3) => Scheme::SspRk3,
        Some(SchemeSpec::ThreeLevel) => Scheme::ThreeLevel,
        Some(SchemeSpec::GeneralizedAlpha) => Scheme::GeneralizedAlpha,
        Some(SchemeSpec::Auto) | None => Scheme::Auto,
    };
    s.spectral_radius = b.opt(
        &sim.spectral_radius,
        "simulation.spectral_radius",
        DEFAULT_SPECTRAL_RADIUS,
        Check {
            ok: |x| (0.0..=1.0).contains(&x),
            expected: "-, in [0, 1]",
        },
        "ρ∞ of generalized-α: 1 keeps every mode's amplitude, 0 damps unresolved modes in one \
         step; 0.8 is the default",
    );
    s.tolerance = b.opt(
        &sim.tolerance,
        "simulation.tolerance",
        DEFAULT_TOLERANCE,
        Check {
            ok: |x| x > 0.0 && x < 1.0,
            expected: "-, in (0, 1)",
        },
        "the local tension error per step relative to the line's reference tension; 1e-6 is \
         the default",
    );
    s.step_above_limit = match sim.step_above_limit {
        Some(StepAboveLimitSpec::Auto) => StepAboveLimit::UseAuto,
        Some(StepAboveLimitSpec::Refuse) | None => StepAboveLimit::Refuse,
    };
    s.initial_condition = match sim.initial_condition.as_ref().map(|c| *c.get_ref()) {
        Some(InitialConditionSpec::AsDefined) => InitialCondition::AsDefined,
        Some(InitialConditionSpec::SteadyTow) => InitialCondition::SteadyTow,
        _ => InitialCondition::Statics,
    };
    let mut span = None;
    if let Some(ts) = &sim.time_step {
        span = Some(ts.span());
        match ts.get_ref() {
            TimeStepSpec::Value(dt) if dt.is_finite() && *dt > 0.0 => {
                if b.physical(Some(ts.span()), "simulation.time_step", &[*dt]) {
                    s.time_step = TimeStep::Fixed(*dt)
                }
            }
            TimeStepSpec::Keyword(k) if k == "auto" => s.time_step = TimeStep::Auto,
            _ => {
                let d = b
                    .diag(
                        Some(ts.span()),
                        "simulation.time_step",
                        "`time_step` must be \"auto\" or a positive number of seconds",
                    )
                    .expected("\"auto\" or s, > 0")
                    .hint("\"auto\" picks the largest stable step");
                b.push(d);
            }
        }
    }
    (s, span)
}

/// `simulation.initial_condition = "steady-tow"`: every prescribed motion one constant
/// horizontal velocity, calm water, no dg lines, no release ([`hawser::model::tow_velocity`]).
pub(super) fn check_steady_tow(b: &mut Builder, spec: Option<&SimulationSpec>, model: &Model) {
    let Some(ic) = spec.and_then(|s| s.initial_condition.as_ref()) else {
        return;
    };
    if *ic.get_ref() != InitialConditionSpec::SteadyTow || !b.errors.is_empty() {
        return;
    }
    if let Err(hawser::error::ModelError::Invalid { what, why }) =
        hawser::model::tow_velocity(model)
    {
        let d = b
            .diag(
                Some(ic.span()),
                "simulation.initial_condition",
                format!("\"steady-tow\": {what} {why}"),
            )
            .expected(
                "a towing vessel: prescribed points and bodies (and obstacles) that all move at \
                 one constant horizontal velocity [m/s], in calm water",
            )
            .hint(
                "give the vessel a `constant-velocity` motion (or a manoeuvre with \
                 build_up_time = 0), or start from \"statics\" or \"as-defined\"",
            );
        b.push(d);
    }
}

/// `simulation.release`: names of free points held in the initial statics, as point indices.
pub(super) fn build_release(
    b: &mut Builder,
    spec: Option<&SimulationSpec>,
    model: &Model,
) -> Vec<usize> {
    let mut out = Vec::new();
    let Some(sim) = spec else { return out };
    for (k, name) in sim.release.iter().enumerate() {
        let key = format!("simulation.release[{k}]");
        let n = name.get_ref();
        let Some(p) = model.point_index(n) else {
            let hint = match closest(n, model.points.iter().map(|p| p.name.as_str())) {
                Some(c) => format!("did you mean `{c}`?"),
                None => "list the names of free points ([[points]] with type = \"free\")".into(),
            };
            let d = b
                .diag(Some(name.span()), &key, format!("no point is named `{n}`"))
                .expected("the name of a free point")
                .hint(hint);
            b.push(d);
            continue;
        };
        if !matches!(model.points[p].kind, PointKind::Free { .. }) {
            let d = b
                .diag(
                    Some(name.span()),
                    &key,
                    format!("point `{n}` is not a free point: only free points can be released"),
                )
                .expected("the name of a free point")
                .hint(
                    "make it `type = \"free\"` (mass 0 at the end of a single dg line makes a \
                     free cable end); the statics hold it at its `position`",
                );
            b.push(d);
            continue;
        }
        if out.contains(&p) {
            let d = b
                .diag(
                    Some(name.span()),
                    &key,
                    format!("point `{n}` is released twice"),
                )
                .expected("each point once")
                .hint("remove the repeated name");
            b.push(d);
            continue;
        }
        out.push(p);
    }
    out
}
