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

/// Work of one generalized-α Newton iteration, in RK4 force evaluations [-]: an evaluation of
/// the forces and mass, the residual, a block solve and the step's share of the predictor,
/// error estimate and commit. Measured at 1.9 (README example), 2.1 (OC3 in surge) and 2.7
/// (the stiff-seabed chain): CPU per iteration over CPU per RK4 evaluation on the same
/// scenario (docs/implicit.md).
pub const ITERATION_WORK: Real = 2.2;

/// Work of forming generalized-α's Jacobian, in RK4 force evaluations [-]: the coloured finite
/// differences take 2 (2w + 1)·3 + 2 = 20 line evaluations for the tridiagonal blocks (w = 1)
/// of an `fe` line.
pub const JACOBIAN_WORK: Real = 20.0;

/// Generalized-α stays while its work over a window is within this factor of what RK4 at its
/// automatic step would do there [-]: a small preference for the scheme that controls its
/// error, within the spread of the measured work per iteration (1.9 to 2.7). On the
/// stiff-seabed chain 1.0, 1.2 and 1.5 gave 5.2, 5.0 and 5.7 s of CPU (docs/implicit.md).
pub const SWITCH_MARGIN: Real = 1.5;

/// Output intervals in a window over which the two schemes' work is compared [-].
pub const WINDOW_OUTPUTS: u64 = 10;

/// The longest stretch RK4 runs before generalized-α is tried again, in windows [-]: after
/// k windows lost in a row, RK4 runs 2^k windows, at most this many.
pub const LONGEST_EXPLICIT_STRETCH: u64 = 64;

/// `scheme = "auto"` while the run goes: which of generalized-α and RK4 steps now, and the
/// work that decides it. A run that `auto` starts with adaptive generalized-α compares, over
/// windows of [`WINDOW_OUTPUTS`] output intervals, the work its Newton iterations and
/// Jacobians did ([`ITERATION_WORK`], [`JACOBIAN_WORK`]) with the 4 n evaluations per output
/// interval of RK4 at its automatic step (n steps per interval). When generalized-α's exceeds
/// [`SWITCH_MARGIN`] times RK4's (already within a window, or over it), the run goes on with
/// RK4 from that output time; after RK4 has run 2^k windows (k the windows generalized-α lost
/// in a row, the stretch at most [`LONGEST_EXPLICIT_STRETCH`] windows) generalized-α is tried
/// again from the state there. The rule reads counts only, never a clock, so a run makes the
/// same choices, and gives the same bits, every time; a snap, whose ringing holds the
/// adaptive step below RK4's stable step, is stepped by RK4, and the calm between snaps by
/// generalized-α.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SchemeSwitch {
    /// Whether RK4 steps now (generalized-α otherwise).
    pub explicit: bool,
    /// The output index at which the current window (generalized-α) or stretch (RK4) began.
    pub since_output: u64,
    /// Generalized-α's work in the current window [RK4 evaluations].
    pub work: Real,
    /// Windows generalized-α lost in a row.
    pub losses: u32,
    /// Switches so far, either way.
    pub switches: u64,
    /// Output intervals stepped by RK4 so far.
    pub explicit_outputs: u64,
    /// Generalized-α's nominal step when RK4 took over [s]: its first step when it comes back.
    pub implicit_nominal: Real,
}

impl SchemeSwitch {
    /// Adds a generalized-α attempt's work: its Newton `iterations` and `jacobians` formed.
    pub fn add_attempt(&mut self, iterations: u64, jacobians: u64) {
        self.work += ITERATION_WORK * iterations as Real + JACOBIAN_WORK * jacobians as Real;
    }

    /// At the sample of output index `output` (k of t = k Δt_out), with RK4 taking
    /// `explicit_steps` steps per output interval: whether the scheme changes now (true: the
    /// other scheme steps from here).
    pub fn at_output(&mut self, output: u64, explicit_steps: u64) -> bool {
        let elapsed = output.saturating_sub(self.since_output);
        let rk4 = |outputs: u64| 4.0 * (explicit_steps * outputs) as Real;
        if self.explicit {
            self.explicit_outputs += 1;
            let stretch = (1u64 << self.losses.min(63)).min(LONGEST_EXPLICIT_STRETCH);
            if elapsed < stretch * WINDOW_OUTPUTS {
                return false;
            }
            self.explicit = false;
        } else {
            let over = |outputs: u64| self.work > SWITCH_MARGIN * rk4(outputs);
            if over(WINDOW_OUTPUTS) || (elapsed >= WINDOW_OUTPUTS && over(elapsed)) {
                self.losses = self.losses.saturating_add(1);
                self.explicit = true;
            } else if elapsed >= WINDOW_OUTPUTS {
                // Generalized-α won the window: a new one starts.
                self.losses = 0;
                self.since_output = output;
                self.work = 0.0;
                return false;
            } else {
                return false;
            }
        }
        self.since_output = output;
        self.work = 0.0;
        self.switches += 1;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// n(tol) reproduces the calibration (60 steps per period at 1e-4, 279 at 1e-6, within 1 %:
    /// the rounding of K) and scales as tol^(-1/3): a hundredfold tolerance gives
    /// 100^(1/3) = 4.64 times the steps, as the controller's measured 4.1 to 4.6 (round-off
    /// only, 1e-12).
    /// Generalized-α keeps stepping while its work in a window stays within the margin of
    /// RK4's, the window starting again after each; a window whose work passes it hands over
    /// to RK4 at once (here at the third output of a window), for 2, 4, 8, … windows after 1,
    /// 2, 3, … lost in a row, at most 64; a window won resets the count. The work is set in
    /// fractions of the window's budget, so the test holds for any value of the constants.
    #[test]
    fn switches_when_generalized_alpha_does_more_work_than_rk4() {
        let mut w = SchemeSwitch::default();
        w.add_attempt(3, 2);
        assert_eq!(w.work, 3.0 * ITERATION_WORK + 2.0 * JACOBIAN_WORK);
        w.work = 0.0;
        // RK4: 5 steps per output; the window's budget: the margin times its 200 evaluations.
        let steps = 5;
        let budget = SWITCH_MARGIN * 4.0 * (steps * WINDOW_OUTPUTS) as Real;
        let per_output = budget / WINDOW_OUTPUTS as Real;
        for k in 1..=25 {
            w.work += 0.25 * per_output;
            assert!(!w.at_output(k, steps), "output {k}");
        }
        assert_eq!((w.since_output, w.losses, w.switches), (20, 0, 0));
        // Four times the allowance per output: over the budget at the third output.
        let mut k = 25;
        let switched = loop {
            k += 1;
            w.work += 4.0 * per_output;
            if w.at_output(k, steps) {
                break k;
            }
        };
        assert_eq!(
            switched, 28,
            "1.25 + 12 > 10 outputs' allowance at the third output"
        );
        assert!(w.explicit);
        assert_eq!((w.losses, w.switches, w.work), (1, 1, 0.0));
        // RK4 for 2 windows (20 outputs), then generalized-α again.
        for j in 1..=20 {
            let back = w.at_output(switched + j, steps);
            assert_eq!(back, j == 20, "output {}", switched + j);
        }
        assert!(!w.explicit);
        assert_eq!(w.explicit_outputs, 20);
        // It loses again at once (a tenth over the budget), and RK4 runs 4 windows.
        w.work = 1.1 * budget;
        assert!(w.at_output(switched + 21, steps));
        assert_eq!(w.losses, 2);
        let back = (1..=40).find(|j| w.at_output(switched + 21 + j, steps));
        assert_eq!(back, Some(40));
        // Many losses: the stretch stops growing at 64 windows.
        w.losses = 40;
        w.explicit = true;
        w.since_output = 0;
        let back = (1..=1000).find(|&j| w.at_output(j, steps));
        assert_eq!(back, Some(LONGEST_EXPLICIT_STRETCH * WINDOW_OUTPUTS));
        // A window won (work within the margin over all ten outputs) resets the losses.
        let start = w.since_output;
        for j in 1..=10 {
            w.work += 0.95 * per_output;
            assert!(!w.at_output(start + j, steps));
        }
        assert_eq!((w.losses, w.since_output), (0, start + 10));
    }

    #[test]
    fn steps_per_period_scales_as_the_cube_root() {
        let (n4, n6) = (steps_per_period(1e-4), steps_per_period(1e-6));
        assert!((n4 / 60.0 - 1.0).abs() < 0.01, "n(1e-4) = {n4}");
        assert!((n6 / 279.0 - 1.0).abs() < 0.01, "n(1e-6) = {n6}");
        assert!((n6 / n4 - 100f64.cbrt()).abs() < 1e-12, "{}", n6 / n4);
    }
}
