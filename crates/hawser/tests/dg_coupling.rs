//! Coupling a `dg` line to a free point through the end interface: a point mass M hanging in
//! air on a vertical line (top anchored) is integrated together with the line by SSP-RK3, the
//! point receiving the line's end force of every stage ([`DgLine::rhs`]'s [`EndLoad`]) and the
//! line receiving the point's velocity ([`EndState`]).
//!
//! Checks: the mean force at the anchor equals the total weight (M + γ0 L) g, and the period
//! of the fundamental axial mode equals that of a rod with a tip mass,
//! β tan β = γ0 L / M, ω = β c / L (c = √(EA/γ0)), within 0.5 %.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use hawser::physics::environment::Environment;

#[test]
fn hanging_mass_oscillates_at_the_rod_with_tip_mass_frequency() {
    let (length, gamma, ea, mass) = (100.0, 10.0, 1.0e6, 1000.0);
    let line = single(
        beam_type(gamma, ea, 0.0),
        length,
        10,
        4,
        [EndCondition::PINNED_JOINT, EndCondition::RIGID_BODY],
    );
    let env = Environment {
        gravity: 9.80665,
        ..Default::default()
    };
    let g = env.gravity;
    // Top anchor A at z = 300 m (in air), the line hanging down to the mass at z = 200 m.
    let top = Vec3::new(0.0, 0.0, 300.0);
    let n = line.state_len();
    let mut y = vec![0.0; n + 6];
    line.straight(&mut y[..n], top, top - Vec3::new(0.0, 0.0, length));
    y[n + 2] = top.z - length;
    let mut ws = DgWorkspace::new(&line);
    let mut anchor_force = Vec3::zeros();
    // dy/dt of the coupled system; returns the loads on the anchor and on the point.
    let mut f = |t: Real, y: &[Real], dy: &mut [Real]| -> [EndLoad; 2] {
        let xp = Vec3::new(y[n], y[n + 1], y[n + 2]);
        let vp = Vec3::new(y[n + 3], y[n + 4], y[n + 5]);
        let ends = [
            EndState::fixed(top, Vec3::x()),
            EndState {
                velocity: vp,
                ..EndState::fixed(xp, Vec3::x())
            },
        ];
        let loads = line.rhs(&env, t, &y[..n], &ends, &mut dy[..n], &mut ws);
        let a = (loads[1].force + Vec3::new(0.0, 0.0, -mass * g)) / mass;
        dy[n..n + 3].copy_from_slice(vp.as_slice());
        dy[n + 3..n + 6].copy_from_slice(a.as_slice());
        loads
    };
    let dt = stable_step(&line, 0.8);
    let (mut k, mut s) = (vec![0.0; n + 6], vec![0.0; n + 6]);
    let mut t = 0.0;
    let mut crossings = Vec::new();
    let mut prev_v = 0.0;
    let (mut sum, mut count) = (0.0, 0);
    while crossings.len() < 9 {
        // SSP-RK3 (DG paper eqs. 31–33) on the coupled state.
        let l0 = f(t, &y, &mut k);
        for i in 0..y.len() {
            s[i] = y[i] + dt * k[i];
        }
        let l1 = f(t + dt, &s, &mut k);
        for i in 0..y.len() {
            s[i] = 0.75 * y[i] + 0.25 * (s[i] + dt * k[i]);
        }
        let l2 = f(t + 0.5 * dt, &s, &mut k);
        for i in 0..y.len() {
            y[i] = (y[i] + 2.0 * (s[i] + dt * k[i])) / 3.0;
        }
        anchor_force = (l0[0].force + l1[0].force) / 6.0 + l2[0].force * (2.0 / 3.0);
        t += dt;
        let v = y[n + 5];
        if prev_v < 0.0 && v >= 0.0 {
            crossings.push(t - dt * v / (v - prev_v));
        }
        if !crossings.is_empty() {
            sum += anchor_force.z;
            count += 1;
        }
        prev_v = v;
        assert!(t < 100.0);
    }
    let period = (crossings[8] - crossings[0]) / 8.0;
    // β tan β = γ0 L / M by Newton.
    let ratio = gamma * length / mass;
    let mut beta: Real = 0.8;
    for _ in 0..50 {
        let fb = beta * beta.tan() - ratio;
        let dfb = beta.tan() + beta / beta.cos().powi(2);
        beta -= fb / dfb;
    }
    let c = (ea / gamma).sqrt();
    let exact = 2.0 * std::f64::consts::PI * length / (beta * c);
    let mean = sum / count as Real;
    let weight = (mass + gamma * length) * g;
    println!(
        "period {period:.5} s vs {exact:.5} ({:+.4} %); mean anchor force {mean:.2} N (on the \
         anchor, downward) vs weight {weight:.2} N ({:+.2e}); last {anchor_force:?}",
        100.0 * (period / exact - 1.0),
        -mean / weight - 1.0
    );
    assert!((period / exact - 1.0).abs() < 0.005);
    assert!((-mean / weight - 1.0).abs() < 0.01);
}
