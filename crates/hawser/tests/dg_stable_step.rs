//! The stable step of `dg` lines: [`stable_step`] is below the measured SSP-RK3 limit for
//! every order, axially and with bending, and not far below it.
//!
//! The measured limit is found by bisection on Δt: a fixed–fixed (axial) or clamped–free
//! (bending) line with a random perturbation of every mode is stepped 3000 times; it is
//! stable when the state stays bounded.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};

fn bounded(line: &DgLine, dt: Real, steps: usize) -> bool {
    let env = vacuum();
    let mut state = vec![0.0; line.state_len()];
    let l = line.length();
    let b = Vec3::new(l * 1.001, 0.0, 0.0);
    line.straight(&mut state, Vec3::zeros(), b);
    let mut rng = rand_like(12345);
    for x in state.iter_mut() {
        *x += 1e-6 * rng();
    }
    let norm0: Real = state.iter().map(|x| x * x).sum::<Real>().sqrt();
    let mut ws = DgWorkspace::new(line);
    let mut st = DgStepper::new(line);
    let ends = fixed_ends(Vec3::zeros(), b);
    let mut t = 0.0;
    for _ in 0..steps {
        st.step(line, &env, t, dt, &mut state, &mut ws, |_| ends);
        t += dt;
    }
    let norm: Real = state.iter().map(|x| x * x).sum::<Real>().sqrt();
    norm.is_finite() && norm < 2.0 * norm0
}

fn rand_like(seed: u64) -> impl FnMut() -> Real {
    let mut s = seed;
    move || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 11) as Real / (1u64 << 53) as Real) * 2.0 - 1.0
    }
}

/// Largest stable step by bisection between 0.05 and 20 times `guess`.
fn measured_limit(line: &DgLine, guess: Real, steps: usize) -> Real {
    let (mut lo, mut hi) = (0.05 * guess, 20.0 * guess);
    for _ in 0..16 {
        let mid = (lo * hi).sqrt();
        if bounded(line, mid, steps) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

fn ratios(ei: Real, orders: &[usize], steps: usize) -> Vec<(usize, Real)> {
    ratios_damped(ei, 0.0, 0.0, orders, steps)
}

/// Ratios estimate / measured limit for a 10 m line of 6 elements, γ0 = 10 kg/m, EA = 0.1 MN,
/// bending stiffness `ei`, bending damping `zb` and axial damping `c`.
fn ratios_damped(
    ei: Real,
    zb: Real,
    c: Real,
    orders: &[usize],
    steps: usize,
) -> Vec<(usize, Real)> {
    orders
        .iter()
        .map(|&p| {
            let ends = if ei > 0.0 || zb > 0.0 {
                [EndCondition::CLAMPED, EndCondition::CLAMPED]
            } else {
                [EndCondition::PINNED_JOINT, EndCondition::PINNED_JOINT]
            };
            let mut lt = beam_type(10.0, 1.0e5, ei);
            lt.bending_damping = zb;
            lt.axial_damping = hawser::physics::material::AxialDamping::Coefficient(c);
            let line = single(lt, 10.0, 6, p, ends);
            let estimate = stable_step(&line, 1.0);
            let limit = measured_limit(&line, estimate, steps);
            println!(
                "EI {ei:e} ζb {zb:e} c {c:e} P {p}: estimate {estimate:.4e} s, measured limit {limit:.4e} s, ratio {:.3}",
                estimate / limit
            );
            (p, estimate / limit)
        })
        .collect()
}

#[test]
fn stable_step_is_safe_and_not_too_cautious() {
    let mut all = Vec::new();
    for ei in [0.0, 1.0e3, 1.0e5] {
        for (p, r) in ratios(ei, &[1, 2, 3, 4, 5, 6, 8], 1500) {
            all.push((ei, p, r));
        }
    }
    for (zb, c) in [(1.0e2, 0.0), (0.0, 1.0e3)] {
        for (p, r) in ratios_damped(1.0e3, zb, c, &[1, 2, 4, 6], 1500) {
            all.push((zb + c, p, r));
        }
    }
    for (ei, p, r) in all {
        assert!(r < 1.0 && r > 0.3, "EI {ei} P {p}: estimate / limit = {r}");
    }
}
