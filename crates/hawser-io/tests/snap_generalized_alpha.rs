//! An implicit step can be stable and still wrong on a snatch load: the adaptive
//! generalized-α step must resolve the snap. The snapping cable at 1.27 Hz
//! (`examples/snapping_cable_127.toml`, 5 `fe` elements) goes slack each cycle after the ramp
//! and snaps; the top tension's first snap peak of the adaptive run (default tolerance 1e-4,
//! the example's 5 ms output interval, so the steps are the controller's own) must come within
//! 1 % of the converged explicit answer (RK4 at 0.1 ms, checked converged against 0.2 ms).
//! The implicit peak is read at the end of every accepted step, so a step that jumps over the
//! peak shows as a low peak.
//!
//! The cable gets a light axial damping, 2 % of its elements' critical damping: the example as
//! written has none, and then the peak of its first snap is not a converged quantity even for
//! RK4 (the undamped element modes ring through the snap; measured 372.8, 406.3, 411.4, 375.1,
//! 383.5, 376.7 N at RK4 steps of 0.4, 0.2, 0.1, 0.05, 0.025, 0.0125 ms), so no scheme can be
//! held to 1 % of it. With 2 % the RK4 peak is 580.34 / 580.37 / 580.36 / 580.37 N at those
//! steps down to 0.025 ms.
//!
//! Cost: about two seconds in release (`cargo test --release -p hawser-io --test
//! snap_generalized_alpha`).

use hawser::analysis::Channel;
use hawser::math::Real;
use hawser::model::{Model, Scheme, TimeStep};
use hawser::physics::material::AxialDamping;
use hawser::simulation::Simulation;
use hawser::{System, statics};
use std::path::PathBuf;

fn load(file: &str) -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(file);
    hawser_io::scenario::load(&path).unwrap().model
}

/// Times [s] and top tensions [N] at the end of every step to `duration` [s].
fn top_tension(model: &Model, duration: Real) -> (Vec<Real>, Vec<Real>, u64) {
    let system = System::new(model).unwrap();
    let y0 = statics::solve(&system, None, &Default::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let (mut t, mut tension) = (Vec::new(), Vec::new());
    while sim.time() < duration - 1e-9 {
        sim.step().unwrap();
        t.push(sim.time());
        let ws = sim.evaluate().unwrap();
        tension.push(
            Channel::EndTension {
                line: 0,
                end_b: false,
            }
            .value(&system, ws),
        );
    }
    (t, tension, sim.steps_done())
}

/// The first snap: the first time after the slack instant `slack` [s] that the top tension
/// rises through `level` [N], and the largest tension in the 0.1 s after it (a snap rises
/// within 0.06 s, docs/examples.md); its time [s] and value [N].
fn first_snap(t: &[Real], tension: &[Real], slack: Real, level: Real) -> (Real, Real) {
    let start = t
        .iter()
        .zip(tension)
        .find(|&(&ti, &x)| ti >= slack && x > level)
        .map(|(&ti, _)| ti)
        .expect("a snap after the slack");
    let mut best = (0.0, Real::NEG_INFINITY);
    for (&ti, &x) in t.iter().zip(tension) {
        if ti >= start && ti <= start + 0.1 && x > best.1 {
            best = (ti, x);
        }
    }
    best
}

#[test]
fn adaptive_generalized_alpha_resolves_the_first_snap() {
    let duration = 5.0;
    let mut cable = load("snapping_cable_127.toml");
    cable.line_types[0].axial_damping = AxialDamping::Ratio(0.02);
    let mut explicit = cable.clone();
    explicit.settings.scheme = Scheme::Rk4;
    explicit.settings.time_step = TimeStep::Auto;
    explicit.settings.output_interval = 1e-4;
    let (t, rk4, _) = top_tension(&explicit, duration);
    explicit.settings.output_interval = 2e-4;
    let (t_coarse, rk4_coarse, _) = top_tension(&explicit, duration);
    // Slack: the top tension below 5 % of its static value after the ramp's first 4 s (the
    // end element's own weight and drag keep it from reaching zero exactly).
    let static_top = rk4[0];
    let slack = t
        .iter()
        .zip(&rk4)
        .find(|&(&ti, &x)| ti > 4.0 && x < 0.05 * static_top)
        .map(|(&ti, _)| ti)
        .expect("the cable goes slack after the ramp");
    let reference = first_snap(&t, &rk4, slack, 3.0 * static_top);
    let finer = first_snap(&t_coarse, &rk4_coarse, slack, 3.0 * static_top);
    // The reference is converged: doubling RK4's step moves the peak by far less than the 1 %
    // the implicit run is held to (measured 5e-5).
    assert!(
        (finer.1 - reference.1).abs() < 1e-3 * reference.1,
        "RK4 peak not converged: {reference:?} vs {finer:?}"
    );

    let mut implicit = cable;
    implicit.settings.scheme = Scheme::GeneralizedAlpha;
    implicit.settings.time_step = TimeStep::Auto;
    let (ti, ga, steps) = top_tension(&implicit, duration);
    let peak = first_snap(&ti, &ga, slack, 3.0 * static_top);
    let error = (peak.1 - reference.1) / reference.1;
    eprintln!(
        "first snap after the slack at {slack:.4} s: RK4 {:.2} N at {:.4} s (0.2 ms: {:.2} N); \
         generalized-α {:.2} N at {:.4} s ({:+.3} %), {steps} adaptive steps against {} RK4 \
         steps",
        reference.1,
        reference.0,
        finer.1,
        peak.1,
        peak.0,
        100.0 * error,
        t.len()
    );
    assert!(
        error.abs() < 0.01,
        "snap peak off by {:.3} %",
        100.0 * error
    );
    // And the peak is a snap (several times the static tension), not a smooth maximum.
    assert!(
        reference.1 > 3.0 * static_top,
        "{reference:?} vs T0 {static_top}"
    );
}
