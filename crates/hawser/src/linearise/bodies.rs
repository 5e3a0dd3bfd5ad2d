//! Rigid bodies in the linearisation: a free body's own 6×6 blocks, and the 6×6 mooring
//! stiffness the lines offer every body.
//!
//! A free body's degrees of freedom are the translation δr of its origin and a small rotation
//! δθ about the global axes, q = [δr; δθ]. Its generalized force is
//! Q = [F; M_o] = own loads (weight, buoyancy, current drag, thrust, members, about the origin;
//! [`crate::model::Body::loads`]) + Σ_p J_pᵀ F_p over the line ends at its points p, with
//! J_p = [1, −[ρ_p]×] (a point moves by δr + δθ × ρ_p) and F_p the lines' force on p. So
//!
//! ```text
//! K = −∂Q/∂q = K_own + Σ_pq J_pᵀ K_pq J_q + K_geo,   K_geo = −Σ_p [F_p]× [ρ_p]× (rotation rows
//!                                                    and columns: J_pᵀ turns with the body)
//! M = M_body (with added mass, about the origin) + Σ J_pᵀ M_pq J_q
//! ```
//!
//! The middle terms are the lines' own blocks at their ends, mapped through J by the block
//! matrix ([`super::DofTarget::Body`]); this module gives K_own + K_geo and M_body. K_own is a
//! central difference of the body's loads over its pose (steps 10⁻⁴ m and 10⁻⁶ rad: round-off
//! ε·|Q|/h is below 10⁻⁸ of the hydrostatic stiffness of a floating body, and the loads are
//! smooth on that scale), and C_own likewise over its velocities (10⁻⁶ m/s, 10⁻⁶ rad/s).

use super::{BlockSolver, Linearisation, Variable, kinematics_at_rest};
use crate::linalg::{BodySlot, Singular};
use crate::math::{Mat3, Mat6, Real, Vec3, Vec6, skew};
use crate::model::{PointKind, RigidKinematics};
use crate::system::System;

/// Finite-difference steps of a body's pose: translation [m], rotation [rad].
const TRANSLATION_STEP: Real = 1e-4;
const ROTATION_STEP: Real = 1e-6;
/// Finite-difference step of a body's velocities [m/s, rad/s].
const VELOCITY_STEP: Real = 1e-6;

/// The body's pose in the static state `state` (at rest).
fn pose(system: &System, state: &[Real], body: usize) -> RigidKinematics {
    match system.layout.body_offset[body] {
        Some(o) => {
            let k = crate::bodies::read_state(&state[o..o + crate::bodies::STATE_LEN]);
            RigidKinematics::at_rest(k.position, k.orientation)
        }
        None => system.bodies[body].initial_kinematics(),
    }
}

/// The slots of the points on free bodies (in the lines' slot order after the free points),
/// with their offsets at the static pose and no centripetal bias.
pub(super) fn slots(system: &System, state: &[Real]) -> Vec<BodySlot> {
    let np = system.free_points.len();
    let mut out = vec![BodySlot::default(); system.point_slot.iter().flatten().count()];
    for (p, slot) in system.point_slot.iter().enumerate() {
        let (Some(s), PointKind::Body { body, offset }) = (slot, &system.points[p].kind) else {
            continue;
        };
        out[s - np] = BodySlot {
            body: system.bodies[*body]
                .free_index
                .expect("a slot is on a free body"),
            offset: pose(system, state, *body).orientation * offset,
            bias: Vec3::zeros(),
        };
    }
    out
}

/// The lines' force on every point [N] at the static state (the end vectors' forces of the
/// lines on it, at rest).
pub(super) fn end_forces(system: &System, state: &[Real]) -> Vec<Vec3> {
    let mut ws = system.workspace();
    super::line_forces_at_rest(system, state, 1.0, false, &mut ws);
    let mut out = vec![Vec3::zeros(); system.points.len()];
    for (li, l) in system.lines.iter().enumerate() {
        let f = &ws.lines[li].force;
        out[l.end_a] += f[0];
        out[l.end_b] += f[l.vectors() - 1];
    }
    out
}

/// [F; M_o] of a body's own loads at kinematics `k`, t = 0.
fn own_load(system: &System, body: usize, k: &RigidKinematics) -> Vec6 {
    system.bodies[body]
        .body
        .loads(k, &system.environment, 0.0)
        .generalized()
}

/// Each free body's own 6×6 block: stiffness K_own + K_geo (`Variable::Position`, `forces`
/// the lines' forces on every point) or damping C_own (`Variable::Velocity`).
pub(super) fn own_blocks(
    system: &System,
    state: &[Real],
    variable: Variable,
    forces: &[Vec3],
) -> Vec<Mat6> {
    system
        .free_bodies
        .iter()
        .map(|&b| {
            let k0 = pose(system, state, b);
            let perturbed = |axis: usize, by: Real| {
                let mut k = k0;
                match (variable, axis < 3) {
                    (Variable::Position, true) => k.position[axis] += by,
                    (Variable::Position, false) => {
                        k.orientation =
                            crate::math::Quat::from_scaled_axis(Vec3::ith(axis - 3, by))
                                * k.orientation;
                    }
                    (Variable::Velocity, true) => k.velocity[axis] += by,
                    (Variable::Velocity, false) => k.angular_velocity[axis - 3] += by,
                }
                own_load(system, b, &k)
            };
            let mut m = Mat6::zeros();
            for axis in 0..6 {
                let h = match (variable, axis < 3) {
                    (Variable::Position, true) => TRANSLATION_STEP,
                    (Variable::Position, false) => ROTATION_STEP,
                    (Variable::Velocity, _) => VELOCITY_STEP,
                };
                let column = -(perturbed(axis, h) - perturbed(axis, -h)) / (2.0 * h);
                m.set_column(axis, &column);
            }
            if variable == Variable::Position {
                let mut geometric = Mat3::zeros();
                for (p, point) in system.points.iter().enumerate() {
                    if let PointKind::Body { body, offset } = &point.kind
                        && *body == b
                    {
                        let rho = k0.orientation * offset;
                        geometric -= skew(&forces[p]) * skew(&rho);
                    }
                }
                let mut block = m.fixed_view_mut::<3, 3>(3, 3);
                block += geometric;
            }
            m
        })
        .collect()
}

/// Each free body's 6×6 mass about its origin with added mass, at the static pose.
pub(super) fn masses(system: &System, state: &[Real]) -> Vec<Mat6> {
    system
        .free_bodies
        .iter()
        .map(|&b| {
            system.bodies[b]
                .body
                .loads(&pose(system, state, b), &system.environment, 0.0)
                .mass
        })
        .collect()
}

/// The 6×6 stiffness the lines offer a body [N/m, N/rad, N·m/m, N·m/rad] over its
/// translation δr and small rotation δθ about global axes at its origin.
#[derive(Clone, Debug)]
pub struct BodyStiffness {
    /// Body index.
    pub body: usize,
    /// K₆ = −∂Q/∂q of the lines' load Q = [F; M_o] on the body, its lines and the free points
    /// relaxed, every body held.
    pub matrix: Mat6,
}

/// The mooring stiffness of every body with lines attached (free or not): each body moved by
/// a unit translation or small rotation with every body held, the lines and free points
/// relaxed to their new equilibrium (static condensation with the block solver), the change of
/// the lines' load on it, plus the geometric term −Σ_p [F_p]× [ρ_p]× of its fairlead forces
/// turning with it:
///
/// ```text
/// K₆ = Σ_pq J_pᵀ K_pq J_q − Σ_p [F_p]× [ρ_p]×,   J_p = [1, −[ρ_p]×]
/// ```
///
/// with K_pq the condensed stiffness between its fairleads ([`super::connection_stiffness`]
/// for points). Without current the matrix is symmetric at equilibrium up to the lines'
/// asymmetry (the geometric term alone is not: the body's own loads balance it).
pub fn body_stiffness(
    system: &System,
    lin: &Linearisation,
) -> Result<Vec<BodyStiffness>, Singular> {
    let mut ws = system.workspace();
    kinematics_at_rest(system, &lin.state, 1.0, &mut ws);
    let forces = end_forces(system, &lin.state);
    let mut solver = BlockSolver::holding_bodies(&lin.stiffness);
    let zero = vec![0.0; lin.dofs.len()];
    let on = |p: usize| match system.points[p].kind {
        PointKind::Body { body, .. } => Some(body),
        _ => None,
    };
    let mut out = Vec::new();
    for b in 0..system.bodies.len() {
        let points: Vec<usize> = (0..system.points.len())
            .filter(|&p| on(p) == Some(b))
            .filter(|&p| system.lines.iter().any(|l| l.end_a == p || l.end_b == p))
            .collect();
        if points.is_empty() {
            continue;
        }
        let origin = ws.bodies[b].position;
        let offset = |p: usize| ws.points[p].position - origin;
        let mut matrix = Mat6::zeros();
        for column in 0..6 {
            let unit = Vec3::ith(column % 3, 1.0);
            let known = |li: usize, vector: usize| {
                let l = &system.lines[li];
                let p = if vector == 0 { l.end_a } else { l.end_b };
                match (on(p) == Some(b), column < 3) {
                    (false, _) => Vec3::zeros(),
                    (true, true) => unit,
                    (true, false) => unit.cross(&offset(p)),
                }
            };
            solver.solve_with_known(&lin.dofs, &zero, known)?;
            let mut q = Vec6::zeros();
            for (li, x) in solver.lines.iter().enumerate() {
                let l = &system.lines[li];
                let n = x.nodes() - 1;
                for (vector, p) in [(0, l.end_a), (n, l.end_b)] {
                    if on(p) != Some(b) {
                        continue;
                    }
                    let f = lin.stiffness.lines[li].row_times(vector, &x.x);
                    let m = offset(p).cross(&f);
                    for i in 0..3 {
                        q[i] += f[i];
                        q[3 + i] += m[i];
                    }
                }
            }
            matrix.set_column(column, &q);
        }
        let mut geometric = Mat3::zeros();
        for &p in &points {
            geometric -= skew(&forces[p]) * skew(&offset(p));
        }
        let mut block = matrix.fixed_view_mut::<3, 3>(3, 3);
        block += geometric;
        out.push(BodyStiffness { body: b, matrix });
    }
    Ok(out)
}
