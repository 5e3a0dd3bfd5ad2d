//! The loads and added mass of a body's cylindrical members: MoorDyn's rods (`Rod::doRHS` of
//! MoorDyn-C 2.7), lumped at N + 1 nodes along each member and summed about the body origin.
//!
//! A member of diameter d from end A to end B (length L, unit axis q, N segments of length
//! h = L/N) has nodes i = 0 … N at ρ_i = a + (i/N)(b − a) from the body origin (global axes),
//! each standing for the length ℓ_i (h, or h/2 at an end) and the volume v_i = π d²/4 ℓ_i.
//! With u_i the water's velocity minus the node's, a_w the water's acceleration, p and q parts
//! normal to and along the axis, and W_i the node's wet fraction (below):
//!
//! ```text
//! side drag      ½ ρ C_dn d ℓ_i W_i |u_p| u_p
//! side inertia   ρ v_i W_i (1 + C_an) a_w,p + ρ v_i W_i a_w,q      (Froude–Krylov along q)
//! added mass     ρ v_i W_i C_an (1 − q qᵀ)
//! end i = 0, N   ½ ρ C_dEnd (π d²/4) W_i |u_q| u_q,   ρ C_aEnd V_e W_i (a_w,q, and q qᵀ
//!                in the mass),  V_e = (2/3) π (d/2)³,  when the end is wet
//! seabed         ((−depth − z_i) K_g − c ż_i) d ℓ_i ẑ below the bed (MoorDyn's rods)
//! ```
//!
//! The wet fraction W_i is MoorDyn's: W = W_0 cos²φ + (A_w/A) sin²φ, φ the inclination of the
//! axis from the vertical, W_0 the part of the node's length below the surface along the axis
//! and A_w/A the wet part of the cross-section at the node. The buoyancy is not lumped: it is
//! ρ g V_w at the centroid of the member's wet volume, the cylinder clipped exactly by the
//! surface plane ([`super::wetted_prism`]), where MoorDyn adds nodal side and end pressures
//! (the same for a member under water, and for an upright one cut by the surface).
//!
//! The added mass resists each node's absolute acceleration; its velocity-dependent part
//! −M_i ω × (ω × ρ_i) is in the force. The member's own mass is the body's.

use super::hydrostatics::{Section, wetted_prism};
use super::loads::BodyLoads;
use crate::math::{Mat3, Real, Vec3, skew};
use crate::model::{Member, RigidKinematics};
use crate::physics::environment::Environment;
use std::f64::consts::PI;

/// A 3×3 node mass `m` at offset `rho` from the body origin as its 6×6 block about the
/// origin: Jᵀ m J with J = [1, −[ρ]×].
fn add_point_mass(out: &mut BodyLoads, m: &Mat3, rho: &Vec3) {
    let rx = skew(rho);
    let m_rx = m * rx;
    let mut block = out.mass.fixed_view_mut::<3, 3>(0, 0);
    block += m;
    let mut block = out.mass.fixed_view_mut::<3, 3>(0, 3);
    block -= m_rx;
    let mut block = out.mass.fixed_view_mut::<3, 3>(3, 0);
    block += rx * m;
    let mut block = out.mass.fixed_view_mut::<3, 3>(3, 3);
    block -= rx * m_rx;
}

/// Unit vectors e₁, e₂ normal to the unit vector `q`, with e₁ × e₂ = q.
fn normals(q: &Vec3) -> (Vec3, Vec3) {
    let helper = if q.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    let e1 = helper.cross(q).normalize();
    (e1, q.cross(&e1))
}

/// Adds `member`'s loads and added mass, at the body kinematics `k` (rotation matrix `r`), to
/// `out` (global axes, moments about the body origin). Allocates nothing.
pub fn member_loads(
    member: &Member,
    k: &RigidKinematics,
    r: &Mat3,
    env: &Environment,
    t: Real,
    out: &mut BodyLoads,
) {
    let rho = env.water_density;
    let (a, b) = (r * member.end_a, r * member.end_b);
    let axis = b - a;
    let length = axis.norm();
    let q = axis / length;
    let d = member.diameter;
    let area = 0.25 * PI * d * d;
    let n = member.segments;
    let h = length / n as Real;
    let w = k.angular_velocity;
    let centre = 0.5 * (a + b);
    let still = env.is_still_at(t);
    let zeta = if env.waves.is_none() {
        0.0
    } else {
        let c = k.position + centre;
        env.surface_elevation(c.x, c.y, t)
    };

    // Buoyancy of the wet part, at its centroid.
    let (e1, e2) = normals(&q);
    let axes = Mat3::from_columns(&[e1, e2, q]);
    let wet = wetted_prism(
        &Section::Circle { radius: 0.5 * d },
        0.5 * length,
        &axes.transpose().column(2).into_owned(),
        k.position.z + centre.z - zeta,
    );
    let buoyancy = Vec3::new(0.0, 0.0, rho * env.gravity * wet.volume);
    out.force += buoyancy;
    out.moment += (centre + axes * wet.centroid).cross(&buoyancy);

    // MoorDyn's wet fraction: h0, the length along the axis from A to the surface (negative
    // when A is the end above it).
    let (za, zb) = (k.position.z + a.z, k.position.z + b.z);
    let h0 = if za < zeta && zb < zeta {
        length
    } else if za < zeta && zb > zeta {
        (zeta - za) / q.z
    } else if zb < zeta && za > zeta {
        -(zeta - za) / q.z
    } else {
        0.0
    };
    let (cos2, sin2) = (q.z * q.z, 1.0 - q.z * q.z);
    let sin_phi = sin2.sqrt();
    let end_volume = 2.0 / 3.0 * PI * (0.5 * d).powi(3);
    let seabed = env.depth.is_finite().then(|| {
        (
            env.seabed.stiffness,
            env.seabed.damping_per_length(d, rho * area),
        )
    });
    let qq = q * q.transpose();
    let mut along = 0.0;
    for i in 0..=n {
        let end = i == 0 || i == n;
        let dl = if end { 0.5 * h } else { h };
        let offset = a + axis * (i as Real / n as Real);
        let x = k.position + offset;
        let v = k.velocity + w.cross(&offset);
        // Along-axis wet part of the node's length, then of its cross-section.
        let w0 = if h0 < 0.0 {
            if along >= -h0 {
                1.0
            } else if along + dl > -h0 {
                (along + dl + h0) / dl
            } else {
                0.0
            }
        } else if along + dl <= h0 {
            1.0
        } else if along < h0 {
            (h0 - along) / dl
        } else {
            0.0
        };
        along += dl;
        let (hi, lo) = (x.z + 0.5 * d * sin_phi, x.z - 0.5 * d * sin_phi);
        let section = if lo > zeta {
            0.0
        } else if hi < zeta {
            1.0
        } else if sin_phi < 1e-3 {
            0.5
        } else {
            let g = ((x.z - zeta) / sin_phi).clamp(-0.5 * d, 0.5 * d);
            let al = (2.0 * g / d).acos();
            d * d / 8.0 * (2.0 * al - (2.0 * al).sin()) / area
        };
        let wet_fraction = w0 * cos2 + section * sin2;
        let volume = area * dl;

        let mut force = Vec3::zeros();
        let mut mass =
            rho * volume * wet_fraction * member.normal_added_mass * (Mat3::identity() - qq);
        let end_wet = end && lo < zeta;
        if end_wet {
            mass += rho * member.end_added_mass * end_volume * wet_fraction * qq;
        }
        let (u_w, a_w) = if still {
            (Vec3::zeros(), Vec3::zeros())
        } else {
            env.fluid_kinematics(&x, t)
        };
        let u = u_w - v;
        let u_q = q * u.dot(&q);
        let u_p = u - u_q;
        force += 0.5 * rho * member.normal_drag * d * dl * wet_fraction * u_p.norm() * u_p;
        let a_q = q * a_w.dot(&q);
        let a_p = a_w - a_q;
        force += rho * volume * wet_fraction * ((1.0 + member.normal_added_mass) * a_p + a_q);
        if end_wet {
            force += 0.5 * rho * member.end_drag * area * wet_fraction * u_q.norm() * u_q;
            force += rho * member.end_added_mass * end_volume * wet_fraction * a_q;
        }
        if let Some((stiffness, damping)) = seabed {
            let depth = -env.depth - x.z;
            if depth > 0.0 {
                force.z += (depth * stiffness - v.z * damping) * d * dl;
            }
        }
        // The added mass resists the node's absolute acceleration, whose velocity-dependent
        // part ω × (ω × ρ_i) is not in the mass matrix.
        force -= mass * w.cross(&w.cross(&offset));
        add_point_mass(out, &mass, &offset);
        out.force += force;
        out.moment += offset.cross(&force);
    }
}
