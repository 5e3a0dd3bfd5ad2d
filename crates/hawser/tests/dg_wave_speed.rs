//! `dg` axial wave speed c = √(EA/γ0) (SPEC §7 analytic checks).
//!
//! A 100 m line, N = 20, P = 4, pre-stretched 0.1 % between a fixed end A and a prescribed
//! end B, no gravity and no fluid. B is pulled 1 mm further by a raised-cosine ramp of 10 ms;
//! the time at which the axial displacement at 75, 50 and 25 m from B reaches half the ramp
//! gives the speed over 50 m in material coordinates.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use std::f64::consts::PI;

#[test]
fn axial_pulse_travels_at_sqrt_ea_over_gamma() {
    for order in [2, 4, 6] {
        let c = measure(order);
        let exact = 1000.0;
        let err = (c - exact) / exact;
        println!(
            "P = {order}: measured c = {c:.3} m/s vs {exact} ({:+.4} %)",
            100.0 * err
        );
        assert!(err.abs() < 0.01, "P {order}: {c}");
    }
}

fn measure(order: usize) -> Real {
    let (length, gamma, ea) = (100.0, 10.0, 1.0e7);
    let line = single(
        beam_type(gamma, ea, 0.0),
        length,
        20,
        order,
        [EndCondition::PINNED_JOINT, EndCondition::PRESCRIBED_PINNED],
    );
    let env = vacuum();
    let pre = 1.0e-3;
    let (delta, ramp) = (1.0e-3, 0.01);
    let mut state = vec![0.0; line.state_len()];
    line.straight(
        &mut state,
        Vec3::zeros(),
        Vec3::new(length * (1.0 + pre), 0.0, 0.0),
    );
    let mut ws = DgWorkspace::new(&line);
    let mut stepper = DgStepper::new(&line);
    let dt = stable_step(&line, 0.8);
    let b0 = Vec3::new(length * (1.0 + pre), 0.0, 0.0);
    let ends = |t: Real| {
        let mut e = fixed_ends(Vec3::zeros(), b0);
        if t < ramp {
            let w = 0.5 * (1.0 - (PI * t / ramp).cos());
            e[1].position.x += delta * w;
            e[1].velocity.x = delta * 0.5 * PI / ramp * (PI * t / ramp).sin();
        } else {
            e[1].position.x += delta;
        }
        e
    };
    let stations = [75.0, 50.0, 25.0];
    let mut times = vec![0.0];
    let mut disp: Vec<Vec<Real>> = vec![vec![0.0]; 3];
    let mut t = 0.0;
    while t < 0.1 {
        stepper.step(&line, &env, t, dt, &mut state, &mut ws, ends);
        t += dt;
        times.push(t);
        for (k, s) in stations.iter().enumerate() {
            disp[k].push(line.position(&state, &ends(t), *s).x - s * (1.0 + pre));
        }
    }
    let t75 = crossing(&times, &disp[0], 0.5 * delta).unwrap();
    let t50 = crossing(&times, &disp[1], 0.5 * delta).unwrap();
    let t25 = crossing(&times, &disp[2], 0.5 * delta).unwrap();
    println!("P {order}: dt {dt:.3e}, arrivals {t75:.5} {t50:.5} {t25:.5}");
    50.0 / (t25 - t75)
}
