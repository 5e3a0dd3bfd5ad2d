//! Steady states of a `dg` line by Newton's method on its semi-discrete equations.
//!
//! The steady state of the DG dynamics is du/dt = 0 for u = [q, v]: the same discrete
//! equations the paper reaches by running the dynamics to rest (its ring beam, §4.1, ramps
//! the end moment over 500 s), found directly. The Jacobian is by forward differences and
//! solved densely ([`crate::linalg::DenseLu`]): meant for verification-sized lines (a few
//! thousand unknowns), not for the time loop.
//!
//! When both ends impose velocities (anchored lines), Σ_e h_e q̇_0^e = ν_B − ν_A makes the
//! mean-mode rows of the q equation dependent: the span ∫q ds is conserved by the dynamics
//! and must be given. The rows of the last element's mean mode are then replaced by the span
//! condition Σ_e h_e q_0^e = r_B − r_A from the end positions.
//! The position field is reset to r_A + ∫q after every update.

use super::line::{DgLine, EndState, Translation};
use super::rhs::DgWorkspace;
use crate::linalg::DenseLu;
use crate::math::{Real, Vec3, get3};
use crate::physics::environment::Environment;

/// Outcome of [`steady_state`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyState {
    /// Newton iterations taken.
    pub iterations: usize,
    /// Largest |du/dt| component at the end (span rows in m, scaled).
    pub residual: Real,
    /// Largest update of the last iteration.
    pub step: Real,
}

/// Solves du/dt = 0 for the q and v modes of `state` (the initial guess), with the end
/// states `ends` at time `time` [s]. Stops when the largest update is below `tolerance`
/// (in the units of q, i.e. relative) or after `max_iterations`; `Err` when the Jacobian is
/// singular or the iteration diverges. Allocates.
pub fn steady_state(
    line: &DgLine,
    env: &Environment,
    time: Real,
    state: &mut [Real],
    ends: &[EndState; 2],
    tolerance: Real,
    max_iterations: usize,
) -> Result<SteadyState, SteadyState> {
    let mut ws = DgWorkspace::new(line);
    let mut rate = vec![0.0; line.state_len()];
    let mut unknowns = Vec::new();
    for (e, el) in line.elements.iter().enumerate() {
        let m3 = 3 * line.section(e).basis.modes();
        unknowns.extend(el.state..el.state + 2 * m3);
    }
    let n = unknowns.len();
    let span = line.ends[0].translation == Translation::Velocity
        && line.ends[1].translation == Translation::Velocity;
    let last = line.elements.len() - 1;
    // Rows (positions in `unknowns`) of the last element's mean-mode q equations.
    let span_rows: Vec<usize> = (0..3)
        .map(|c| {
            let idx = line.elements[last].state + c;
            unknowns.iter().position(|&u| u == idx).unwrap()
        })
        .collect();
    let span_scale = line.sections[0].wave_speed.max(1.0) / line.length();
    let residual =
        |state: &mut [Real], rate: &mut [Real], ws: &mut DgWorkspace, out: &mut [Real]| {
            line.positions_from_tangent(state, ends[0].position);
            line.rhs(env, time, state, ends, rate, ws);
            for (o, &u) in out.iter_mut().zip(&unknowns) {
                *o = rate[u];
            }
            if span {
                let mut integral = Vec3::zeros();
                for (e, el) in line.elements.iter().enumerate() {
                    let _ = e;
                    integral += get3(&state[el.state..], 0) * el.length;
                }
                let d = (integral - (ends[1].position - ends[0].position)) * span_scale;
                for c in 0..3 {
                    out[span_rows[c]] = d[c];
                }
            }
        };
    let mut r0 = vec![0.0; n];
    let mut r1 = vec![0.0; n];
    let mut lu = DenseLu::new(n);
    let mut dx = vec![0.0; n];
    let mut tmp = vec![0.0; n];
    let mut backup = vec![0.0; n];
    let norm = |v: &[Real]| v.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
    let mut out = SteadyState {
        iterations: 0,
        residual: Real::INFINITY,
        step: Real::INFINITY,
    };
    residual(state, &mut rate, &mut ws, &mut r0);
    for it in 1..=max_iterations {
        out.iterations = it;
        lu.clear();
        for (j, &u) in unknowns.iter().enumerate() {
            let x = state[u];
            let h = 1e-7 * (1.0 + x.abs());
            state[u] = x + h;
            residual(state, &mut rate, &mut ws, &mut r1);
            state[u] = x;
            for i in 0..n {
                let d = (r1[i] - r0[i]) / h;
                if d != 0.0 {
                    lu.add(i, j, d);
                }
            }
        }
        if lu.factor().is_err() {
            return Err(out);
        }
        dx.copy_from_slice(&r0);
        lu.solve(&mut dx, &mut tmp);
        for (b, &u) in backup.iter_mut().zip(&unknowns) {
            *b = state[u];
        }
        let r_norm = norm(&r0);
        // Backtracking on the residual norm.
        let mut alpha = 1.0;
        loop {
            for ((&u, b), d) in unknowns.iter().zip(&backup).zip(&dx) {
                state[u] = b - alpha * d;
            }
            residual(state, &mut rate, &mut ws, &mut r1);
            let r_new = norm(&r1);
            if r_new.is_finite() && (r_new < r_norm || alpha < 1e-3 || r_norm < 1e-300) {
                break;
            }
            alpha *= 0.5;
        }
        std::mem::swap(&mut r0, &mut r1);
        out.step = alpha * norm(&dx);
        out.residual = norm(&r0);
        if !out.residual.is_finite() {
            return Err(out);
        }
        if out.step < tolerance {
            residual(state, &mut rate, &mut ws, &mut r0);
            return Ok(out);
        }
    }
    Err(out)
}
