//! The stiff-seabed chain (`tests/data/stiff_seabed_chain.toml`: a studless chain on a seabed of
//! 1.8e9 Pa/m, critically damped, its top end on a vertical circle of radius 0.2 m and period
//! 1.25 s): the scheme `scheme = "auto"` picks must give the top tension's cycle maxima within
//! 0.5 % of the converged explicit run, the target of docs/implicit.md.
//!
//! Reduced to stay cheap: 33 segments of 1 m instead of 165 of 0.2 m (the seabed contact is as
//! stiff per unit length, 1.8e9 Pa/m × d, and still sets a contact frequency of ≈ 8500 rad/s
//! at the resting nodes), 5 s simulated (the 2.5 s build-up and two cycles), and the maxima of
//! the two cycles after the build-up compared. The explicit reference is RK4 at 0.4 of its
//! automatic step (safety factor 0.2; its maxima change by less than 0.05 % from safety 0.4,
//! checked when this test was written: the test also checks it, so that a reference that is
//! not converged fails here instead of hiding an error). 0.5 % is the target's own bound.
//!
//! Cost: about six seconds of CPU in release (`cargo test --release -p hawser-io --test
//! stiff_seabed_chain`).

#[path = "../../hawser/tests/alloc_count/mod.rs"]
mod alloc_count;

use hawser::analysis::Channel;
use hawser::math::Real;
use hawser::model::{Model, Scheme, TimeStep};
use hawser::session::{Observer, ObserverError, View};
use hawser::simulation::Simulation;
use hawser::{System, statics};
use std::path::PathBuf;

const PERIOD: Real = 1.25;
const RAMP: Real = 2.5;
const DURATION: Real = 5.0;

fn model() -> Model {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/stiff_seabed_chain.toml");
    let mut model = hawser_io::scenario::load(&path).unwrap().model;
    model.lines[0].sections[0].elements = 33;
    model.settings.duration = DURATION;
    model
}

/// Samples of the top node force (MoorDyn's `FairTen`) [N] at the output times.
struct Top(Vec<(Real, Real)>);

impl Observer for Top {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let channel = Channel::EndNodeForce {
            line: 0,
            end_b: true,
        };
        self.0
            .push((view.time, channel.value(view.system, view.workspace)));
        Ok(())
    }
}

/// The largest sample in each period after the build-up [N], and the scheme used.
fn cycle_maxima(model: &Model) -> (Vec<Real>, Scheme) {
    let system = System::new(model).unwrap();
    let y0 = statics::solve(&system, None, &Default::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let scheme = sim.scheme().scheme;
    let mut top = Top(Vec::new());
    sim.run(DURATION, &mut top).unwrap();
    let cycles = ((DURATION - RAMP) / PERIOD).round() as usize;
    let maxima = (0..cycles)
        .map(|k| {
            let (a, b) = (RAMP + k as Real * PERIOD, RAMP + (k + 1) as Real * PERIOD);
            top.0
                .iter()
                .filter(|(t, _)| *t >= a - 1e-9 && *t < b - 1e-9)
                .map(|s| s.1)
                .fold(Real::NEG_INFINITY, Real::max)
        })
        .collect();
    (maxima, scheme)
}

fn explicit(safety_factor: Real) -> Vec<Real> {
    let mut m = model();
    m.settings.scheme = Scheme::Rk4;
    m.settings.time_step = TimeStep::Auto;
    m.settings.safety_factor = safety_factor;
    cycle_maxima(&m).0
}

fn worst(a: &[Real], b: &[Real]) -> Real {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y)
        .fold(0.0, Real::max)
}

#[test]
fn auto_scheme_keeps_cycle_maxima_within_half_a_percent_of_explicit() {
    let reference = explicit(0.2);
    let coarser = explicit(0.4);
    assert!(
        worst(&coarser, &reference) < 5e-4,
        "the explicit reference is not converged: {coarser:?} against {reference:?}"
    );
    let (auto, scheme) = cycle_maxima(&model());
    assert_eq!(
        scheme,
        Scheme::GeneralizedAlpha,
        "auto should step this stiff case implicitly"
    );
    let e = worst(&auto, &reference);
    assert!(
        e <= 5e-3,
        "auto ({scheme:?}) maxima {auto:?} against RK4 {reference:?}: worst {:.3} %",
        e * 100.0
    );
}

/// The work of a run in RK4 force evaluations, by `auto`'s own measure
/// ([`hawser::integrate::choice::ITERATION_WORK`], [`hawser::integrate::choice::JACOBIAN_WORK`]):
/// generalized-α's Newton iterations and Jacobians, and four evaluations per RK4 step.
fn work(session: &hawser::Session) -> Real {
    use hawser::integrate::choice::{ITERATION_WORK, JACOBIAN_WORK};
    let s = session.implicit_statistics().unwrap();
    let explicit_steps = session.steps_done() - s.steps;
    ITERATION_WORK * s.iterations as Real
        + JACOBIAN_WORK * s.jacobians as Real
        + 4.0 * explicit_steps as Real
}

/// The snap rings at the chain's axial modes and holds generalized-α's adaptive step below
/// RK4's stable step: `auto` hands those stretches to RK4 (switching at output times, by the
/// work each scheme does), and so does less work than generalized-α alone, by its own
/// measure: at most 0.9 of it (0.863 when this test was written: 146 400 against 169 629
/// evaluations; `hawser bench` 0.19 against 0.22 s of CPU; at 165 segments and 12.5 s the gain
/// is 2.5×). The counts are exact, so the bound does not flake. The maxima it gives are the
/// first test's.
#[test]
fn auto_hands_the_snaps_to_rk4_and_does_less_work() {
    let mut m = model();
    let mut auto = hawser::Session::new(m.clone()).unwrap();
    auto.run().unwrap();
    let switch = auto
        .scheme_switch()
        .expect("auto started with generalized-α");
    assert!(
        switch.switches >= 2 && switch.explicit_outputs > 0,
        "no switch to RK4 and back: {switch:?}"
    );
    assert!(
        switch.explicit_outputs < (DURATION / m.settings.output_interval) as u64,
        "RK4 throughout: {switch:?}"
    );
    // The results' record of it (`summary.json`'s `integrator`): the same switches, RK4's
    // time on the output grid, RK4's steps beside generalized-α's.
    let report = auto.integrator_report();
    let w = report.switching.expect("switching recorded");
    assert_eq!(w.switches, switch.switches);
    let rk4_time = switch.explicit_outputs as Real * m.settings.output_interval;
    assert!((w.rk4_time - rk4_time).abs() <= 1e-12 * DURATION, "{w:?}");
    let ga = report.generalized_alpha.expect("generalized-α stepped");
    assert!(ga.steps > 0 && ga.steps < report.steps, "{report:?}");
    assert_eq!(report.choice.scheme, Scheme::GeneralizedAlpha);
    m.settings.scheme = Scheme::GeneralizedAlpha;
    let mut implicit = hawser::Session::new(m).unwrap();
    implicit.run().unwrap();
    assert!(implicit.scheme_switch().is_none());
    let (a, g) = (work(&auto), work(&implicit));
    assert!(
        a < 0.9 * g,
        "auto's work {a:.0} against generalized-α's {g:.0}"
    );
}

/// A run saved while RK4 steps for `auto`, or while generalized-α does, resumes bit for bit:
/// the checkpoint carries which scheme steps, the window's work and generalized-α's history
/// (its reference tensions from the start of the run).
#[test]
fn auto_switching_resumes_bit_for_bit() {
    let mut m = model();
    m.settings.duration = 4.0;
    let mut whole = hawser::Session::new(m.clone()).unwrap();
    whole.run().unwrap();
    // Where to save: RK4's spells last a few tenths of a second, so every 0.5 s and every
    // 0.125 s at which a run advanced by 0.125 s finds RK4 stepping (its adaptive steps land
    // on each advance, so it is not the whole run to the bit, but its spells are the same).
    let mut probe = hawser::Session::new(m.clone()).unwrap();
    let mut stops = Vec::new();
    for k in 1..32 {
        let stop = 0.125 * k as Real;
        probe.advance_to(stop).unwrap();
        if probe.scheme_switch().unwrap().explicit || k % 4 == 0 {
            stops.push(stop);
        }
    }
    let mut seen = [false; 2];
    for stop in stops {
        let mut first = hawser::Session::new(m.clone()).unwrap();
        first.advance_to(stop).unwrap();
        let explicit = first.scheme_switch().unwrap().explicit;
        seen[explicit as usize] = true;
        let bytes = first.checkpoint();
        let mut resumed = hawser::Session::restore(m.clone(), &bytes, Default::default()).unwrap();
        resumed.run().unwrap();
        assert_eq!(resumed.state(), whole.state(), "saved at {stop} s");
        assert_eq!(
            resumed.scheme_switch(),
            whole.scheme_switch(),
            "saved at {stop} s"
        );
    }
    assert_eq!(seen, [true, true], "saved only under one scheme");
}

/// Switching allocates nothing: both integrators are sized when the run starts, and a switch
/// swaps them and restarts generalized-α from the state (its start's evaluation and Jacobian
/// take the scratch it already has). Counted from 0.5 s to the end, over switches both ways.
#[test]
fn auto_switching_does_not_allocate() {
    let mut session = hawser::Session::new(model()).unwrap();
    session.advance_to(0.5).unwrap();
    let before = session.scheme_switch().unwrap().switches;
    let count = alloc_count::allocations_in(|| session.advance_to(DURATION).unwrap());
    let switches = session.scheme_switch().unwrap().switches - before;
    assert!(switches >= 2, "{switches} switches to count over");
    assert_eq!(count, 0, "{count} allocations over {switches} switches");
}
