//! High-order discontinuous Galerkin lines with bending (DG paper: Palm & Eskilsson 2020,
//! eqs. 4–33; the method is described with its derivations in `docs/dg.md`).
//!
//! # Method
//!
//! The state of a line is u = [q, v] with q = ∂r/∂s and v = γ0 ν (eqs. 4–11), in the
//! conservative form du/dt = dF/ds + G with F = [v/γ0, T î + T_s]. Each element of a section
//! carries Legendre modal coefficients of order P (1..=[`basis::MAX_ORDER`], per section).
//! The fluxes are Lax–Friedrichs with λ = √(T'(ε)/γ0) (eqs. 23–25); bending enters through the
//! shear force T_s computed by the nested LDG chain κ = ∂î/∂s, κ̇ = ∂î̇/∂s,
//! M* = î × (EI κ + ζb κ̇)/l_ε², τ = ∂M*/∂s, T_s = î × τ/l_ε with the β fluxes of
//! eqs. 29–30 ([`rhs`]). External loads are the shared physics of
//! [`crate::physics`]: the axial law [`crate::physics::material::AxialLaw`] (eq. 22), Morison
//! drag and added mass [`crate::physics::hydrodynamics`] (eqs. 13, 17), weight and buoyancy
//! (eq. 14) and seabed contact [`crate::physics::seabed`] (eqs. 15–16), evaluated at the Gauss
//! points.
//!
//! # Positions
//!
//! Besides q and v, each element carries the modes of its position r, evolved with ṙ = v/γ0
//! (the third block of the element state). External loads read positions from it. It stays
//! consistent with q to discretisation error: d/dt(∂r/∂s − q) is the Lax–Friedrichs jump
//! term of the q equation only. [`DgLine::position_from_tangent`] gives the other route,
//! r(s) = r_A + ∫q ds, and [`DgLine::positions_from_tangent`] resets the field from it;
//! `tests/dg_positions.rs` checks that the two agree.
//!
//! # Coupling to points and bodies
//!
//! The ends of a line belong to its attachments (ARCHITECTURE.md); a DG line end has no
//! lumped mass. At each Runge–Kutta stage a host does:
//!
//! ```ignore
//! let ends: [EndState; 2] = [attachment_a.kinematics(t), attachment_b.kinematics(t)];
//! let loads: [EndLoad; 2] = line.rhs(&env, t, &state, &ends, &mut dstate, &mut ws);
//! // loads[0].force, loads[0].moment: what the line puts on attachment A (likewise B);
//! // add them to the attachment's equation of motion for the same stage.
//! ```
//!
//! - [`DgLine::rhs`]`(&self, env: &Environment, time: Real, state: &[Real],
//!   ends: &[EndState; 2], dstate: &mut [Real], ws: &mut DgWorkspace) -> [EndLoad; 2]`
//! - [`EndState`] `{ position, velocity, acceleration, force, moment, direction,
//!   direction_rate }`: what the attachment supplies; the end's [`EndCondition`] (Table 1)
//!   says which fields are used. Velocity ends (anchors, prescribed motion, free points,
//!   bodies) impose v̂ = γ0 ν_BC and receive T̂ = T⁺ + Z(ν_BC − ν⁺)·n, the traction of the
//!   Lax–Friedrichs flux with a mirrored ghost state (Z = λγ0, the axial impedance);
//!   force ends (free end, point force) impose T̂.
//! - [`EndLoad`] `{ force, moment }`: force [N] and moment [N·m] on the attachment.
//! - [`DgStepper::step`] runs SSP-RK3 for a line alone with a closure for the end states
//!   and returns the step-averaged end loads; [`stable_step`] is the CFL estimate.
//!
//! The whole right-hand side is allocation-free; [`DgWorkspace`] is sized once.

pub mod basis;
pub mod line;
pub mod rhs;
pub mod statics;
pub mod step;

pub use line::{
    DgLine, DgSection, DgSectionSpec, EndCondition, EndLoad, EndState, Rotation, Translation,
};
pub use rhs::DgWorkspace;
pub use statics::{SteadyState, steady_state};
pub use step::{DgStepper, stable_step};

use crate::math::{Real, Vec3};

/// Line fields at one arc length, from a state and its last right-hand-side evaluation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Channels {
    /// Position r [m]: r_A + ∫q ds from the base of the last right-hand side.
    pub position: Vec3,
    /// Strain ε = |q| − 1 [-].
    pub strain: Real,
    /// Axial tension T(ε, ε̇) [N] (eq. 22).
    pub tension: Real,
    /// Curvature vector κ = ∂î/∂s [1/m] (its norm is the curvature).
    pub curvature: Vec3,
    /// Bending moment vector M = î × (EI κ + ζb κ̇) [N·m] (eq. 19).
    pub moment: Vec3,
    /// Shear force vector T_s = î × ∂M*/∂s / l_ε [N] (eq. 20).
    pub shear: Vec3,
}

impl DgLine {
    /// The fields at arc length s [m] for `state`, after `rhs` was evaluated at that state
    /// into `rate` (its output) with workspace `ws` (the LDG modes κ, κ̇, τ are read from it).
    pub fn channels(&self, state: &[Real], rate: &[Real], ws: &DgWorkspace, s: Real) -> Channels {
        let (e, xi) = self.locate(s);
        let sec = self.section(e);
        let el = &self.elements[e];
        let m3 = 3 * sec.basis.modes();
        let (q, _, _) = self.fields(state, e);
        let q = self.eval_modes(e, q, xi);
        let qdot = self.eval_modes(e, &rate[el.state..el.state + m3], xi);
        let l = q.norm().max(1e-12);
        let i = q / l;
        let tension = sec.properties.law.tension(l - 1.0, i.dot(&qdot));
        let (mut curvature, mut moment, mut shear) = (Vec3::zeros(), Vec3::zeros(), Vec3::zeros());
        if self.bending {
            let modes = 3 * el.mode..3 * el.mode + m3;
            curvature = self.eval_modes(e, &ws.modes_kappa[modes.clone()], xi);
            let lt = &sec.properties.line_type;
            let mut k = curvature * lt.bending_stiffness;
            if lt.bending_damping != 0.0 {
                k += self.eval_modes(e, &ws.modes_kdot[modes.clone()], xi) * lt.bending_damping;
            }
            moment = i.cross(&k);
            shear = i.cross(&self.eval_modes(e, &ws.modes_tau[modes], xi)) / l;
        }
        Channels {
            position: self.position_from_tangent(state, ws.base, s),
            strain: l - 1.0,
            tension,
            curvature,
            moment,
            shear,
        }
    }
}

impl DgLine {
    /// Mechanical energy of the line [J] at `state`, positions integrated from end A at
    /// `r_a` (see [`DgLine::position_from_tangent`]): kinetic ½∫|v|²/γ0 ds, the potential of
    /// weight in air ∫γ0 g z ds, and the strain energy ∫W(ε) ds + ½∫EI|∂î/∂s|² ds, by Gauss
    /// quadrature with P + 3 points per element. Allocates (diagnostics, not the time loop).
    pub fn energy(&self, state: &[Real], r_a: Vec3, gravity: Real) -> crate::formulation::Energy {
        let mut energy = crate::formulation::Energy::default();
        let mut base = r_a;
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            let lt = &sec.properties.line_type;
            let m = sec.basis.modes();
            let quad = basis::Basis::new(m - 1, m + 2);
            let (q, v, _) = self.fields(state, e);
            let half = 0.5 * el.length;
            for k in 0..quad.points {
                let row = k * m..(k + 1) * m;
                let (mut qs, mut dq, mut vs, mut rs) =
                    (Vec3::zeros(), Vec3::zeros(), Vec3::zeros(), Vec3::zeros());
                for (j, ((p, dp), int)) in quad.phi[row.clone()]
                    .iter()
                    .zip(&quad.dphi[row.clone()])
                    .zip(&quad.integral[row])
                    .enumerate()
                {
                    let (qj, vj) = (crate::math::get3(q, j), crate::math::get3(v, j));
                    qs += qj * *p;
                    dq += qj * (*dp / half);
                    vs += vj * *p;
                    rs += qj * (*int * half);
                }
                let ds = quad.weight[k] * half;
                let l = qs.norm().max(1e-12);
                let i = qs / l;
                let kappa = (dq - i * i.dot(&dq)) / l;
                energy.kinetic += 0.5 * vs.norm_squared() / lt.mass_per_length * ds;
                energy.gravity += lt.mass_per_length * gravity * (base + rs).z * ds;
                energy.elastic += (sec.properties.law.strain_energy_density(l - 1.0)
                    + 0.5 * lt.bending_stiffness * kappa.norm_squared())
                    * ds;
            }
            base += crate::math::get3(q, 0) * el.length;
        }
        energy
    }

    /// Fills the line's node outputs after [`DgLine::rhs`] evaluated `state` with `ws`:
    /// positions at the N + 1 element ends (r_A + ∫q, the positions the loads saw), velocities
    /// there (the mean of the two sides' ν at an interface), the tension at each node (the
    /// mean of the two sides, the end loads' magnitudes at the ends), and per element the
    /// mean of its two end values of tension, strain, curvature |κ|, bending moment
    /// |M| = l_ε² |M*| and shear force |T_s|. Allocation-free, O(N).
    pub fn sample(
        &self,
        state: &[Real],
        ws: &DgWorkspace,
        loads: &[EndLoad; 2],
        positions: &mut [Vec3],
        velocities: &mut [Vec3],
        node_tension: &mut [Real],
        elements: &mut crate::formulation::ElementState,
    ) {
        let n = self.elements.len();
        let mut r = ws.base;
        positions[0] = r;
        for (e, el) in self.elements.iter().enumerate() {
            r += crate::math::get3(&state[el.state..], 0) * el.length;
            positions[e + 1] = r;
        }
        velocities[0] = ws.end_nu[0];
        velocities[n] = ws.end_nu[2 * n - 1];
        node_tension[0] = loads[0].force.norm();
        node_tension[n] = loads[1].force.norm();
        for i in 1..n {
            velocities[i] = (ws.end_nu[2 * i - 1] + ws.end_nu[2 * i]) * 0.5;
            node_tension[i] = 0.5 * (ws.end_tension[2 * i - 1] + ws.end_tension[2 * i]);
        }
        for e in 0..n {
            let (a, b) = (2 * e, 2 * e + 1);
            elements.tension[e] = 0.5 * (ws.end_tension[a] + ws.end_tension[b]);
            elements.strain[e] = 0.5 * (ws.end_stretch[a] + ws.end_stretch[b]) - 1.0;
            if self.bending {
                let moment = |p: usize| ws.end_mstar[p].norm() * ws.end_stretch[p].powi(2);
                elements.curvature[e] = 0.5 * (ws.end_kappa[a].norm() + ws.end_kappa[b].norm());
                elements.bending_moment[e] = 0.5 * (moment(a) + moment(b));
                elements.shear_force[e] = 0.5 * (ws.end_shear[a].norm() + ws.end_shear[b].norm());
            }
        }
    }
}
