//! `scheme = "auto"`: the cheaper of RK4 at its stable step and adaptive generalized-α at the
//! accuracy the settings ask for (docs/implicit.md states the rule and checks it).
//!
//! RK4 costs four evaluations of the forces per step and must step within its stability
//! limit h_e (axial waves, seabed contact, damping: [`System::stable_step`]) whatever the
//! motion. Generalized-α costs one evaluation and one block solve per Newton iteration (1.25
//! to 1.29 per attempt measured at tolerance 1e-4, with the Jacobian reused; docs/implicit.md)
//! and steps as far as the accuracy allows. Its step is not known before the run (the error
//! estimate chooses it), so the rule estimates it from what the scenario shows of its time
//! scales: the accuracy step
//!
//!   h_a = min(Δt_out, T_min / n(tol)),   n(tol) = 2π / (K · tol)^(1/3),
//!
//! where Δt_out is the output interval (steps land on the output times), T_min the shortest
//! period of the excitation (prescribed sinusoids and orbits, wave components, RAO motions),
//! and n(tol) the steps per period the adaptive controller takes on a motion of that period.
//! Generalized-α is second-order accurate, so its local error per step on a mode of angular
//! frequency ω grows as (ωh)³; the controller holds it to the tolerance, so its step scales as
//! tol^(1/3) (ωh = (K · tol)^(1/3)). The constant K = [`ERROR_PER_TOLERANCE`] is calibrated
//! against the steps the controller takes on the bundled wave-driven examples at tolerances
//! 1e-4 and 1e-6 (docs/implicit.md). The run goes implicit when h_a ≥ [`SPEEDUP`] · h_e: the
//! implicit step is then long enough to pay for its iterations. A run with a fixed
//! `time_step` keeps RK4 (the step was chosen for an explicit scheme), and a run with `dg`
//! lines steps explicitly (generalized-α cannot step them).

use crate::math::Real;
use crate::model::{Motion, PointKind, Scheme, Settings, TimeStep};
use crate::system::System;

/// The ratio of the accuracy step to RK4's stable step above which generalized-α is chosen
/// [-]. A generalized-α step at tolerance 1e-6 costs 0.24 to 0.78 of an RK4 step on the
/// bundled examples (Newton iterations with a block solve each, 1.25 to 1.29 per attempt
/// measured at 1e-4, and the amortised Jacobian, against RK4's four evaluations), so the
/// factor is a margin for the error of the a-priori step h_a, not the cost ratio
/// (docs/implicit.md measures both).
pub const SPEEDUP: Real = 3.0;

/// K of n(tol) = 2π / (K · tol)^(1/3), the steps per excitation period of adaptive
/// generalized-α [-]: (ωh)³ = K · tol. Calibrated on examples/rao_crane.toml and
/// examples/wave_buoy.toml, whose steps the wave excitation sets: the controller's mean step
/// was 1/74 and 1/54 of the shortest wave period at tolerance 1e-4, 1/327 and 1/220 at 1e-6
/// (ratios 4.4 and 4.1 against 100^(1/3) = 4.6); K = 11.5 gives 1/60 and 1/279
/// (docs/implicit.md).
pub const ERROR_PER_TOLERANCE: Real = 11.5;

/// The scheme a run uses and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SchemeChoice {
    /// The scheme (never [`Scheme::Auto`]).
    pub scheme: Scheme,
    /// Why, in words with the numbers.
    pub reason: String,
}

/// The scheme of a run of `system` with `settings`: the settings' own, or for
/// [`Scheme::Auto`] the rule of the module doc.
pub fn choose_scheme(system: &System, settings: &Settings) -> SchemeChoice {
    let given = |scheme: Scheme, reason: String| SchemeChoice { scheme, reason };
    if settings.scheme != Scheme::Auto {
        return given(settings.scheme, "set by the scenario".into());
    }
    if let Some(l) = system.lines.iter().find(|l| l.dg().is_some()) {
        return given(
            Scheme::Rk4,
            format!("line {} uses dg, which steps explicitly", l.name),
        );
    }
    if let Some(b) = system
        .bodies
        .iter()
        .find(|b| b.body.kind.pin().is_some_and(|p| p.parent().is_some()))
    {
        return given(
            Scheme::Rk4,
            format!(
                "body {} is pinned to another body, which generalized-α steps at first order",
                b.body.name
            ),
        );
    }
    if let TimeStep::Fixed(dt) = settings.time_step {
        return given(
            Scheme::Rk4,
            format!("the fixed time_step {dt:.3e} s is kept with RK4"),
        );
    }
    let (limit, culprit) = system.stable_step(Scheme::Rk4);
    let explicit = settings.safety_factor * limit;
    let (accuracy, what) = accuracy_step(system, settings);
    if accuracy >= SPEEDUP * explicit {
        given(
            Scheme::GeneralizedAlpha,
            format!(
                "the accuracy step {accuracy:.3e} s ({what}) is {} RK4's automatic step \
                 {explicit:.3e} s (set by {culprit})",
                times(accuracy / explicit)
            ),
        )
    } else {
        given(
            Scheme::Rk4,
            format!(
                "RK4's automatic step {explicit:.3e} s (set by {culprit}) is within {SPEEDUP}× the \
                 accuracy step {accuracy:.3e} s ({what})"
            ),
        )
    }
}

/// A ratio as "130×", or "7.95e302×" when it has more than four digits.
fn times(ratio: Real) -> String {
    if ratio < 1e4 {
        format!("{ratio:.0}×")
    } else {
        format!("{ratio:.2e}×")
    }
}

/// The a-priori accuracy step h_a [s] of the module doc and what sets it.
pub fn accuracy_step(system: &System, settings: &Settings) -> (Real, String) {
    let interval = settings.output_interval;
    let Some(period) = shortest_period(system) else {
        return (interval, "the output interval".into());
    };
    let steps = steps_per_period(settings.tolerance);
    let step = period / steps;
    if step < interval {
        (
            step,
            format!(
                "{steps:.0} steps per {period:.3} s period of the excitation at tolerance {:.0e}",
                settings.tolerance
            ),
        )
    } else {
        (interval, "the output interval".into())
    }
}

/// n(tol) = 2π / (K · tol)^(1/3) of the module doc: the steps per period of the excitation
/// adaptive generalized-α takes at tolerance `tolerance` [-].
pub fn steps_per_period(tolerance: Real) -> Real {
    2.0 * std::f64::consts::PI / (ERROR_PER_TOLERANCE * tolerance).cbrt()
}

/// The shortest period [s] of the excitation the model shows: prescribed sinusoids and orbits
/// of points, the wave components (their highest frequency; they also drive RAO motions of
/// prescribed bodies and vessels). `None` when nothing periodic drives the system.
pub fn shortest_period(system: &System) -> Option<Real> {
    let mut shortest = Real::INFINITY;
    let mut frequency = |f: Real| {
        if f > 0.0 && f.is_finite() {
            shortest = shortest.min(1.0 / f);
        }
    };
    let mut motion = |m: &Motion| match m {
        Motion::Sinusoid {
            amplitude,
            frequency: f,
            ..
        } => {
            for k in 0..3 {
                if amplitude[k] != 0.0 {
                    frequency(f[k]);
                }
            }
        }
        Motion::CircularOrbit {
            radius,
            frequency: f,
            ..
        } if *radius != 0.0 => frequency(*f),
        _ => {}
    };
    for p in &system.points {
        if let PointKind::Prescribed(m) = &p.kind {
            motion(m);
        }
    }
    // RAO motions of vessels and bodies move at the wave components' frequencies.
    if let Some(field) = system.environment.waves.field() {
        let omega = field.highest_frequency();
        if omega > 0.0 {
            shortest = shortest.min(2.0 * std::f64::consts::PI / omega);
        }
    }
    shortest.is_finite().then_some(shortest)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// n(tol) reproduces the calibration (60 steps per period at 1e-4, 279 at 1e-6, within 1 %:
    /// the rounding of K) and scales as tol^(-1/3): a hundredfold tolerance gives
    /// 100^(1/3) = 4.64 times the steps, as the controller's measured 4.1 to 4.6 (round-off
    /// only, 1e-12).
    #[test]
    fn steps_per_period_scales_as_the_cube_root() {
        let (n4, n6) = (steps_per_period(1e-4), steps_per_period(1e-6));
        assert!((n4 / 60.0 - 1.0).abs() < 0.01, "n(1e-4) = {n4}");
        assert!((n6 / 279.0 - 1.0).abs() < 0.01, "n(1e-6) = {n6}");
        assert!((n6 / n4 - 100f64.cbrt()).abs() < 1e-12, "{}", n6 / n4);
    }
}
