//! Observed mesh-convergence order of the `fe` formulation in the element length h.
//!
//! 1. Statics: a suspended elastic catenary (the case of `tests/catenary.rs`) solved by Newton
//!    at N = 8, 16, 32, 64 elements against the closed form (`hawser::statics::catenary`):
//!    end tensions and the mid-span node position. Linear elements with the weight lumped at
//!    the nodes make the chain a polygon whose nodes are O(h²) off the catenary, and the end
//!    force (end element tension plus half an element's weight) is O(h²) too.
//! 2. Dynamics: the fundamental transverse frequency of a taut string, f1 = 1/(2 L) √(T/μ)
//!    with L the stretched length and μ = γ0/(1 + ε) the mass per stretched length, i.e.
//!    f1 = 1/(2 L0) √(T/(γ0 (1 + ε))), at N = 4, 8, 16, 32. The discrete sine shape is an exact
//!    mode of the uniform chain, with frequency error −π²/(24 N²) for lumped mass and
//!    +π²/(24 N²) for consistent mass: order 2 with opposite signs.

mod common;
use common::*;
use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::simulation::Simulation;
use hawser::statics::{StaticOptions, catenary, solve};
use hawser::system::System;
use std::f64::consts::PI;

/// Observed orders log2(e_N / e_2N) of a sequence of errors at N, 2N, 4N, ...
fn orders(errors: &[Real]) -> Vec<Real> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

#[test]
fn static_catenary_converges_at_second_order() {
    let (d, gamma, ea, length) = (0.05, 20.0, 5.0e7, 110.0);
    let w = (gamma - 1025.0 * PI * d * d / 4.0) * 9.80665;
    let a = Vec3::new(0.0, 0.0, -500.0);
    let b = Vec3::new(80.0, 0.0, -440.0);
    let exact = catenary::solve(80.0, 60.0, length, w, ea, false).unwrap();
    let (mx, mz) = exact.position(0.5 * length);
    let mid_exact = a + Vec3::new(mx, 0.0, mz);
    let options = StaticOptions {
        // Residual 1e-9 of the line weight (the default): its effect on the results (≈ 1e-9
        // relative) is far below the smallest discretisation error measured (2.3e-5 at
        // N = 64), and it stays above the rounding floor of the force evaluation (positions
        // ≈ 500 m carry ≈ 1e-13 m, times EA/L0 ≈ 4e6–3e7 N/m: ~1e-6 N, 5e-11 of the weight).
        relative_tolerance: 1e-9,
        ..Default::default()
    };
    let mut err_a = Vec::new();
    let mut err_b = Vec::new();
    let mut err_mid = Vec::new();
    for n in [8, 16, 32, 64] {
        let model = single_line(
            line_type(d, gamma, ea),
            length,
            n,
            fixed("A", a),
            fixed("B", b),
            MassMatrix::Consistent,
        );
        let system = System::new(&model).unwrap();
        let sol = solve(&system, None, &options).expect("statics converges");
        let mut ws = system.workspace();
        let mut dy = vec![0.0; sol.state.len()];
        system.rhs(0.0, &sol.state, &mut dy, &mut ws).unwrap();
        let ta = system.end_force(&ws, 0, false).norm();
        let tb = system.end_force(&ws, 0, true).norm();
        let mid = node_state(&system, &sol.state, 0, n / 2).0;
        err_a.push((ta / exact.tension_a() - 1.0).abs());
        err_b.push((tb / exact.tension_b() - 1.0).abs());
        err_mid.push((mid - mid_exact).norm() / length);
        eprintln!(
            "N = {n:3}: end A {:.3e}, end B {:.3e}, mid node {:.3e} (relative; residual {:.1e} N, {})",
            err_a.last().unwrap(),
            err_b.last().unwrap(),
            err_mid.last().unwrap(),
            sol.residual,
            sol.method
        );
    }
    for (what, errors) in [
        ("end A tension", &err_a),
        ("end B tension", &err_b),
        ("mid-span node", &err_mid),
    ] {
        let p = orders(errors);
        eprintln!("{what}: observed orders {p:.3?}");
        // Linear elements: O(h²) for a smooth solution. 1.8–2.2 is the band of a clean
        // asymptotic regime (higher-order terms at N = 8 are ~(8/N)² smaller than at N = 64
        // as relative perturbations of the ratio: a few %); order 1 or 3 is a different scheme.
        for &o in &p {
            assert!(
                (1.8..2.2).contains(&o),
                "{what}: observed orders {p:?} (errors {errors:?})"
            );
        }
    }
}

/// Measured fundamental transverse frequency [Hz] of a taut string of `n` elements.
fn string_frequency(n: usize, mass_matrix: MassMatrix, l0: Real, gamma: Real, ea: Real) -> Real {
    let strain = 0.01;
    let model = taut_string(l0, gamma, ea, strain, n, mass_matrix);
    let system = System::new(&model).unwrap();
    // Transverse sine of amplitude 1e-5 L0: the tension change it causes, ~EA (π A/L)²/4,
    // shifts the frequency by ~1e-8 relative, far below the O(1e-4) mesh errors measured.
    let amplitude = 1.0e-5 * l0;
    let mut y = system.straight_state();
    for i in 1..n {
        let (p, _) = node_state(&system, &y, 0, i);
        let s = i as Real / n as Real;
        let shape = Vec3::new(0.0, amplitude * (PI * s).sin(), 0.0);
        set_node_state(&system, &mut y, 0, i, p + shape, Vec3::zeros());
    }
    // Stability limit 1.3 ms (N = 32, lumped), 0.74 ms (consistent); the RK4 phase error at the
    // 10 rad/s fundamental is (ω dt)⁴/120 ≈ 5e-11 for dt = 2.5e-4 s.
    let dt = 2.5e-4;
    let settings = fixed_step_settings(dt, Scheme::Rk4);
    let mut sim = Simulation::new(&system, &settings, y).unwrap();
    let mut ys = Vec::new();
    // About four periods of ≈ 0.64 s.
    for _ in 0..10_400 {
        sim.step().unwrap();
        ys.push(node_state(&system, &sim.state, 0, n / 2).0.y);
    }
    1.0 / mean_period(&upward_crossings(&ys, 0.0, dt))
}

#[test]
fn taut_string_frequency_converges_at_second_order() {
    let (l0, gamma, ea): (Real, Real, Real) = (10.0, 1.0, 1.0e5);
    let strain: Real = 0.01;
    let tension = ea * strain;
    let f1 = 1.0 / (2.0 * l0) * (tension / (gamma * (1.0 + strain))).sqrt();
    for (mass_matrix, sign) in [(MassMatrix::Lumped, -1.0), (MassMatrix::Consistent, 1.0)] {
        let mut errors = Vec::new();
        for n in [4, 8, 16, 32] {
            let f = string_frequency(n, mass_matrix, l0, gamma, ea);
            let e = f / f1 - 1.0;
            let predicted = sign * PI * PI / (24.0 * (n * n) as Real);
            eprintln!(
                "{mass_matrix:?} N = {n:2}: f = {f:.8} Hz vs f1 = {f1:.8} Hz: {e:+.4e} (leading term {predicted:+.4e})"
            );
            // The error has the sign of the mass matrix's dispersion and the size of the
            // leading term π²/(24 N²) up to its next term, O(N⁻⁴): within 5 % of it for N ≥ 4.
            assert!(
                e * sign > 0.0 && (e / predicted - 1.0).abs() < 0.05,
                "{mass_matrix:?} N = {n}: error {e:+.4e}, leading term {predicted:+.4e}"
            );
            errors.push(e.abs());
        }
        let p = orders(&errors);
        eprintln!("{mass_matrix:?}: observed orders {p:.3?}");
        // Same band as the statics: clean second order.
        for &o in &p {
            assert!(
                (1.8..2.2).contains(&o),
                "{mass_matrix:?}: observed orders {p:?} (errors {errors:?})"
            );
        }
    }
}
