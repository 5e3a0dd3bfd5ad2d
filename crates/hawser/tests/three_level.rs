//! The elastic-link paper's three-time-level predictor–corrector (eqs. 35–48): stability at
//! its limit, accuracy against RK4, observed order and dissipation.

mod common;
use common::*;
use hawser::math::Real;
use hawser::model::*;
use hawser::simulation::Simulation;
use hawser::system::System;

use common::hanging_mass::*;

/// The hanging mass of tests/mass_spring.rs, displaced 2 mm and released; returns the mass's
/// height every `dt` for `duration`.
fn hanging_mass(scheme: Scheme, mass_matrix: MassMatrix, dt: Real, duration: Real) -> Vec<Real> {
    let model = model(mass_matrix);
    let system = System::new(&model).unwrap();
    let (y, _) = displaced_state(&system, 2e-3);
    let settings = fixed_step_settings(dt, scheme);
    let mut sim = Simulation::new(&system, &settings, y).unwrap();
    let steps = (duration / dt).round() as usize;
    let mut zs = Vec::with_capacity(steps);
    for _ in 0..steps {
        sim.step().unwrap();
        zs.push(node_state(&system, &sim.state(), 0, ELEMENTS).0.z);
    }
    zs
}

/// The scheme converges to the RK4 solution at first order in Δt (the corrector takes the
/// forces at the predicted level n+1, an O(Δt) shift), with lumped and with consistent mass.
/// Errors of the mass's height at t = 0.5 s against RK4 at Δt = 1e-5 s (whose own error,
/// (ωΔt)⁴/120 per period, is below 1e-12 m); four halvings from 1e-4 s. Tolerance: each
/// observed order within 0.1 of 1 (measured 0.98–1.003).
#[test]
fn first_order_convergence_to_rk4() {
    for mm in [MassMatrix::Lumped, MassMatrix::Consistent] {
        let reference = *hanging_mass(Scheme::Rk4, mm, 1e-5, 0.5).last().unwrap();
        let mut prev: Option<Real> = None;
        for dt in [1e-4, 5e-5, 2.5e-5, 1.25e-5] {
            let z = *hanging_mass(Scheme::ThreeLevel, mm, dt, 0.5)
                .last()
                .unwrap();
            let err = (z - reference).abs();
            if let Some(p) = prev {
                let order = (p / err).log2();
                eprintln!("{mm:?} dt {dt:e}: error {err:.3e} m, order {order:.3}");
                assert!((order - 1.0).abs() < 0.1, "{mm:?} dt {dt}: order {order}");
            }
            prev = Some(err);
        }
    }
}

/// The scheme's dissipation: on ẍ = −ω²x the predictor–corrector gives
/// x^{n+1} = (2 − 2h² + h⁴) x^n − (1 − h²) x^{n−1}, h = ωΔt, whose complex roots have
/// |z|² = 1 − h²: the amplitude decays by (1 − h²)^{N/2} over N steps. The hanging mass's
/// fundamental (ω = β c/L, β tan β = γ0 L/m) is measured from its peaks after the faster
/// modes (h up to 0.4, decaying a thousand times faster) have died out. Tolerance: the decay
/// exponent within 10 % (the peaks are sampled every step, 1e-4 of a period; measured
/// within 2 %).
#[test]
fn amplitude_decays_as_derived() {
    let dt = 1e-4;
    let duration = 4.0;
    let z = hanging_mass(Scheme::ThreeLevel, MassMatrix::Lumped, dt, duration);
    let beta = rod_beta(LENGTH / MASS);
    let omega = beta * (EA / 1.0).sqrt() / LENGTH;
    let h = omega * dt;
    let mean = z.iter().sum::<Real>() / z.len() as Real;
    // Peak displacement of each oscillation (between upward crossings of the mean).
    let crossings: Vec<usize> = (1..z.len())
        .filter(|&i| z[i - 1] < mean && z[i] >= mean)
        .collect();
    let peaks: Vec<(usize, Real)> = crossings
        .windows(2)
        .map(|w| {
            let (i, a) = (w[0]..w[1])
                .map(|i| (i, (z[i] - mean).abs()))
                .fold((0, 0.0), |m, x| if x.1 > m.1 { x } else { m });
            (i, a)
        })
        .collect();
    let (i0, a0) = peaks[peaks.len() / 4];
    let (i1, a1) = *peaks.last().unwrap();
    let measured = (a1 / a0).ln() / (i1 - i0) as Real;
    let derived = 0.5 * (1.0 - h * h).ln();
    eprintln!("decay per step: measured {measured:.4e}, derived {derived:.4e} (h = {h:.4e})");
    assert!((measured / derived - 1.0).abs() < 0.1);
}

/// The derived stability limit h = ωΔt ≤ 1: the roots of z² − (2 − 2h² + h⁴) z + (1 − h²)
/// stay in the unit disc up to h = 1 and leave it beyond (the radius 1 that
/// `System::stable_step` uses for this scheme).
#[test]
fn stability_limit_of_the_predictor_corrector() {
    let spectral_radius = |h: Real| {
        let b = 2.0 - 2.0 * h * h + h.powi(4);
        let c = 1.0 - h * h;
        let disc = b * b - 4.0 * c;
        if disc < 0.0 {
            c.sqrt()
        } else {
            ((b.abs() + disc.sqrt()) / 2.0).max(((b.abs() - disc.sqrt()) / 2.0).abs())
        }
    };
    for k in 1..=100 {
        let h = k as Real / 100.0;
        assert!(spectral_radius(h) <= 1.0 + 1e-12, "h = {h}");
    }
    assert!(spectral_radius(1.05) > 1.0);
}
