//! Modes of models with pinned bodies: a pinned body turns about its pin, whose motion is
//! given, so its three rotations are degrees of freedom of the modal analysis and its
//! translations are held (`DofMap::held`).

use hawser::analysis::modes::{EigenMethod, ModalOptions, Modes, natural_modes};
use hawser::linearise::{Linearisation, LinearisationOptions, linearise};
use hawser::math::{Mat3, Quat, Real, Vec3};
use hawser::model::*;
use hawser::simulation::Simulation;
use hawser::statics::{StaticOptions, solve};
use hawser::system::System;
use hawser::verification::vacuum_environment;
use hawser::verification::{dry_line_type, fixed, fixed_step_settings, single_line};
use std::f64::consts::TAU;

const G: Real = 9.81;

/// Statics, linearisation and the lowest `count` modes with `method`.
fn modes_of(model: &Model, count: usize, method: EigenMethod) -> (System, Linearisation, Modes) {
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics converges");
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let options = ModalOptions {
        count,
        method,
        ..Default::default()
    };
    let modes = natural_modes(&system, &lin, &options).expect("modes");
    (system, lin, modes)
}

/// A compound pendulum in a vacuum on a fixed pin: mass m = 100 kg, centre of gravity
/// d = 2 m below the pin, inertia about the centre of gravity (10, 20, 30) kg·m². Its small
/// swings about x and y have ω² = m g d / (I_G + m d²), which are the modal analysis's two
/// nonzero eigenvalues exactly (the linearisation of gravity's moment about the pin is
/// m g d for both tilts, the mass about the pin I_G + m d²): 1e-9 relative is the round-off of
/// the 6×6 dense solve. Turning about the vertical through the pin meets no stiffness: one
/// eigenvalue is 0 (within 1e-9 of the others). A modal analysis that let the origin move
/// would give 6 modes with the translation and the swing coupled (the free-flying body's
/// swing frequency is zero: nothing holds it), so the count and the values both fail.
#[test]
fn pinned_pendulum_modes_are_the_compound_pendulum_frequencies() {
    let (mass, d) = (100.0, 2.0);
    let inertia = Vec3::new(10.0, 20.0, 30.0);
    let model = Model {
        environment: vacuum_environment(G),
        bodies: vec![Body {
            position: Vec3::new(1.0, -2.0, 10.0),
            centre_of_gravity: Vec3::new(0.0, 0.0, -d),
            kind: BodyKind::Pinned(Pin::Fixed),
            ..Body::new("pendulum", mass, Mat3::from_diagonal(&inertia))
        }],
        ..Default::default()
    };
    let (_, lin, modes) = modes_of(&model, 10, EigenMethod::Dense);
    assert_eq!(
        modes.degrees_of_freedom, 6,
        "the linearisation keeps 6 rows"
    );
    assert_eq!(lin.dofs.held(), vec![0, 1, 2]);
    assert_eq!(modes.modes.len(), 3, "three rotations are free");
    let swing = |i: Real| mass * G * d / (i + mass * d * d);
    let mut expected = [0.0, swing(inertia.x), swing(inertia.y)];
    expected.sort_by(Real::total_cmp);
    let scale = expected[2];
    for (mode, want) in modes.modes.iter().zip(expected) {
        eprintln!(
            "pendulum mode: λ = {:.9e} rad²/s² (closed form {want:.9e}), {}",
            mode.eigenvalue, mode.label.text
        );
        assert!(
            (mode.eigenvalue - want).abs() < 1e-9 * scale,
            "λ {} vs {want}",
            mode.eigenvalue
        );
        // The pin holds the origin: no translation in any shape.
        let (translation, rotation) = mode.body_motion(&lin.dofs, 0).unwrap();
        assert_eq!(translation, Vec3::zeros());
        assert!(rotation.norm() > 0.0);
    }
}

/// A pinned arm in a vacuum (pin at 10 m, 120 kg, centre of gravity (0.1, 0, −2) m) held
/// sideways by one taut elastic line (11.5 m, EA 20 kN, about 2 % strain) of `elements`
/// elements from a lug at (0.5, 0, −3) m on the arm to an anchor: the line's stiffness and
/// mass join the arm's rotations.
fn tethered_arm(elements: usize) -> Model {
    let mut model = single_line(
        dry_line_type(0.02, 0.5, 2.0e4),
        11.5,
        elements,
        (
            Point {
                name: "lug".into(),
                position: Vec3::zeros(),
                kind: PointKind::Body {
                    body: 0,
                    offset: Vec3::new(0.5, 0.0, -3.0),
                },
            },
            fixed("anchor", Vec3::new(12.0, 1.0, 5.0)),
        ),
        Formulation::Fe,
        MassMatrix::Consistent,
    );
    model.environment = vacuum_environment(G);
    model.bodies.push(Body {
        position: Vec3::new(0.0, 0.0, 10.0),
        centre_of_gravity: Vec3::new(0.1, 0.0, -2.0),
        kind: BodyKind::Pinned(Pin::Fixed),
        ..Body::new(
            "arm",
            120.0,
            Mat3::from_diagonal(&Vec3::new(30.0, 40.0, 10.0)),
        )
    });
    model
}

/// The shift-invert solver (the pinned translations held by the block solver, K and M
/// projected onto the free degrees of freedom) finds the dense solution's eigenvalues within
/// 1e-9 relative (the subspace iteration's default backward-error tolerance is 1e-10) on the
/// tethered arm with 20 line elements (63 degrees of freedom, 60 free).
#[test]
fn shift_invert_holds_the_pin_as_the_dense_solve_does() {
    let model = tethered_arm(20);
    let (_, lin, sparse) = modes_of(&model, 8, EigenMethod::ShiftInvert);
    let (_, _, dense) = modes_of(&model, 8, EigenMethod::Dense);
    assert_eq!(sparse.method, EigenMethod::ShiftInvert);
    for (j, (s, d)) in sparse.modes.iter().zip(&dense.modes).enumerate() {
        let err = (s.eigenvalue - d.eigenvalue).abs() / d.eigenvalue.abs().max(1e-12);
        eprintln!(
            "mode {j}: {:.6} Hz (dense {:.6} Hz), {}",
            s.frequency, d.frequency, s.label.text
        );
        assert!(err < 1e-9, "mode {j}: {} vs {}", s.eigenvalue, d.eigenvalue);
        // The held rows solve δr = 0 up to the round-off of the dense Schur solve.
        let (translation, rotation) = s.body_motion(&lin.dofs, 0).unwrap();
        assert!(
            translation.norm() < 1e-12 * rotation.norm().max(1.0),
            "mode {j} moves the pin by {translation}"
        );
    }
}

/// The lowest mode of the arm on a one-element line (its only degrees of freedom are the
/// arm's three rotations; the line adds its stiffness and its end mass at the lug) against the
/// dynamics: the arm turned from equilibrium by 1e-4 of the mode's rotation and let go swings
/// in that mode alone, and its zero crossings over 6 periods give the modal period within
/// 1e-4 (RK4 at T/2000 shifts it by ~1e-12; the amplitude's nonlinearity by ~1e-8; the
/// crossings are read from a linear interpolation). A period from a linearisation that let the
/// pin move, or dropped the line's end mass or its geometric stiffness, misses by percents.
#[test]
fn lowest_mode_of_a_tethered_arm_is_its_free_swing() {
    let model = tethered_arm(1);
    let (system, lin, modes) = modes_of(&model, 3, EigenMethod::Dense);
    let first = &modes.modes[0];
    assert!(first.eigenvalue > 0.0);
    let (_, rotation) = first.body_motion(&lin.dofs, 0).unwrap();
    let axis = rotation.normalize();
    let dt = first.period / 2000.0;
    let o = system.layout.body_offset[0].unwrap();
    let mut y = lin.state.clone();
    let mut k = hawser::bodies::read_state(&y[o..o + hawser::bodies::STATE_LEN]);
    let rest = k.orientation;
    k.orientation = Quat::from_scaled_axis(axis * 1e-4) * rest;
    hawser::bodies::write_state(&k, &mut y[o..o + hawser::bodies::STATE_LEN]);
    let turn = |y: &[Real]| {
        let k = hawser::bodies::read_state(&y[o..o + hawser::bodies::STATE_LEN]);
        (k.orientation * rest.inverse()).scaled_axis().dot(&axis)
    };
    let mut sim = Simulation::new(&system, &fixed_step_settings(dt, Scheme::Rk4), y).unwrap();
    let (mut last, mut crossings) = (turn(sim.state()), Vec::new());
    while crossings.len() < 7 {
        sim.step().unwrap();
        let now = turn(sim.state());
        if last > 0.0 && now <= 0.0 {
            crossings.push(sim.time() - dt * now / (now - last));
        }
        last = now;
        assert!(sim.time() < 10.0 * first.period, "no swing");
    }
    let period = (crossings[6] - crossings[0]) / 6.0;
    eprintln!(
        "tethered arm: modal period {:.7} s ({}), free swing {period:.7} s, error {:.2e}",
        first.period,
        first.label.text,
        period / first.period - 1.0
    );
    assert!((period / first.period - 1.0).abs() < 1e-4);
    assert!((TAU / first.period - first.eigenvalue.sqrt()).abs() < 1e-12 * first.eigenvalue);
}
