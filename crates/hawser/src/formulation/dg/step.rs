//! SSP-RK3 time stepping (DG paper eqs. 31–33) and the CFL-based stable step.

use super::line::{DgLine, EndLoad, EndState};
use super::rhs::DgWorkspace;
use crate::math::Real;
use crate::physics::environment::Environment;

/// Courant numbers C_a(P) of the axial limit Δt ≤ C_a(P) h/λ for P = 1..=8: 0.9 times the
/// limits of SSP-RK3 with the Lax–Friedrichs flux measured in `tests/dg_stable_step.rs`
/// (0.412, 0.210, 0.126, 0.084, 0.060, 0.045, –, 0.028: the RKDG values of Cockburn and Shu).
/// Beyond P = 8, 2/(P + 1)² (the measured limits are ≈ 2.2/(P + 1)² there).
pub const AXIAL_COURANT: [Real; 8] = [0.37, 0.19, 0.113, 0.075, 0.054, 0.040, 0.031, 0.025];

/// Axial Courant number C_a(P) (see [`AXIAL_COURANT`]).
pub fn axial_courant(order: usize) -> Real {
    match order {
        0 => 1.0,
        1..=8 => AXIAL_COURANT[order - 1],
        p => 2.0 / ((p + 1) * (p + 1)) as Real,
    }
}
/// Constant C_b of the flexural limit Δt ≤ C_b (h/(P + 1)²)² √(γ0/EI): the measured limits
/// of `tests/dg_stable_step.rs` give C_b = 2.6 (P = 1) to 3.7 (P = 8) with centred LDG
/// fluxes; 2.3 keeps a margin.
pub const FLEXURAL_COURANT: Real = 2.3;

/// Constant C_c of the axial-damping limit Δt ≤ C_c h² γ0 / (c (P + 1)^3.25), fitted to the
/// measured limits of `tests/dg_stable_step.rs` (their exponent is 3.2 ± 0.05).
pub const AXIAL_DAMPING_COURANT: Real = 0.9;
/// Constant C_ζ of the bending-damping limit Δt ≤ C_ζ h⁴ γ0 / (ζb (P + 1)⁷) (measured
/// constants 1.3–1.4 for P = 2..6 with exponent 7).
pub const BENDING_DAMPING_COURANT: Real = 1.0;

/// The largest stable SSP-RK3 step [s] of a line, times `safety` (≤ 1; 0.8 is a good
/// default): the minimum over elements of the axial limit C_a(P) h/λ with λ the largest
/// axial wave speed √(max T'/γ0) (eq. 25), and, where EI > 0, the flexural limit
/// C_b (h/(P + 1)²)² √(γ0/EI) of the fourth-order bending operator, whose spectral radius
/// grows like (EI/γ0)^½ ((P + 1)²/h)², the two combined as 1/Δt² = 1/Δt_a² + 1/Δt_b²; with
/// axial damping c the diffusive limit [`AXIAL_DAMPING_COURANT`] h² γ0 / (c (P + 1)^3.25) and
/// with bending damping ζb the limit [`BENDING_DAMPING_COURANT`] h⁴ γ0 / (ζb (P + 1)⁷), whose
/// rates 1/Δt add to the first. Bending damping is by far the most restrictive: the fourth
/// derivative of ν it carries makes its limit fall like h⁴/P⁷.
pub fn stable_step(line: &DgLine, safety: Real) -> Real {
    let mut dt = Real::INFINITY;
    for el in &line.elements {
        let sec = &line.sections[el.section];
        let p = sec.basis.order as Real;
        let h = el.length;
        let lt = &sec.properties.line_type;
        let gamma = lt.mass_per_length;
        let hp = h / ((p + 1.0) * (p + 1.0));
        // Axial and flexural limits combined in quadrature (1/Δt² adds): both act on the
        // imaginary axis and their spectra add where they are of similar size.
        let mut inv2 = 0.0;
        if sec.wave_speed > 0.0 {
            inv2 += (sec.wave_speed / (axial_courant(sec.basis.order) * h)).powi(2);
        }
        if lt.bending_stiffness > 0.0 {
            inv2 += (lt.bending_stiffness / gamma) / (FLEXURAL_COURANT * hp * hp).powi(2);
        }
        // Damping: real-axis limits, whose rates add to the oscillatory one.
        let mut rate = if inv2 > 0.0 { inv2.sqrt() } else { 0.0 };
        if line.modal_filter + line.shock_filter > 0.0 && p >= 2.0 {
            // The filter's fastest decay, σ = c_f λ (2P + 1)/h, a real-axis rate.
            rate += (line.modal_filter + line.shock_filter) * sec.wave_speed * (2.0 * p + 1.0) / h;
        }
        if sec.properties.law.damping > 0.0 {
            rate += sec.properties.law.damping * (p + 1.0).powf(3.25)
                / (AXIAL_DAMPING_COURANT * h * h * gamma);
        }
        if lt.bending_damping > 0.0 {
            rate += lt.bending_damping * (p + 1.0).powi(7)
                / (BENDING_DAMPING_COURANT * h.powi(4) * gamma);
        }
        if rate > 0.0 {
            dt = dt.min(1.0 / rate);
        }
    }
    dt * safety
}

/// SSP-RK3 of Shu and Osher in the paper's form (eqs. 31–33), the same scheme as
/// [`crate::integrate::SSP_RK3`] in Butcher form (nodes 0, 1, ½, weights ⅙, ⅙, ⅔), with its
/// two stage buffers sized once.
#[derive(Clone, Debug)]
pub struct DgStepper {
    stage: Vec<Real>,
    rate: Vec<Real>,
}

impl DgStepper {
    /// Stepper for `line`.
    pub fn new(line: &DgLine) -> Self {
        Self {
            stage: vec![0.0; line.state_len()],
            rate: vec![0.0; line.state_len()],
        }
    }

    /// Advances `state` from `t` to `t + dt`. `ends(t)` gives the attachments' states at a
    /// stage time. Returns the end loads averaged with the scheme's weights (⅙, ⅙, ⅔): the
    /// impulse over the step divided by dt, which is what a coupled point should receive.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        line: &DgLine,
        env: &Environment,
        t: Real,
        dt: Real,
        state: &mut [Real],
        ws: &mut DgWorkspace,
        mut ends: impl FnMut(Real) -> [EndState; 2],
    ) -> [EndLoad; 2] {
        let mut avg = [EndLoad::default(); 2];
        let mut accumulate = |loads: [EndLoad; 2], w: Real| {
            for (a, l) in avg.iter_mut().zip(loads) {
                a.force += l.force * w;
                a.moment += l.moment * w;
            }
        };
        // u(1) = u + dt L(u, t)
        let loads = line.rhs(env, t, state, &ends(t), &mut self.rate, ws);
        accumulate(loads, 1.0 / 6.0);
        for ((s, u), k) in self.stage.iter_mut().zip(state.iter()).zip(&self.rate) {
            *s = u + dt * k;
        }
        // u(2) = ¾ u + ¼ (u(1) + dt L(u(1), t + dt))
        let loads = line.rhs(env, t + dt, &self.stage, &ends(t + dt), &mut self.rate, ws);
        accumulate(loads, 1.0 / 6.0);
        for ((s, u), k) in self.stage.iter_mut().zip(state.iter()).zip(&self.rate) {
            *s = 0.75 * u + 0.25 * (*s + dt * k);
        }
        // u(n+1) = ⅓ u + ⅔ (u(2) + dt L(u(2), t + dt/2))
        let th = t + 0.5 * dt;
        let loads = line.rhs(env, th, &self.stage, &ends(th), &mut self.rate, ws);
        accumulate(loads, 2.0 / 3.0);
        for ((u, s), k) in state.iter_mut().zip(&self.stage).zip(&self.rate) {
            *u = (*u + 2.0 * (s + dt * k)) / 3.0;
        }
        avg
    }
}
