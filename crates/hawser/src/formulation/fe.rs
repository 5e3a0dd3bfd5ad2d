//! Position-vector finite elements (position-vector paper, §2).
//!
//! Two-node straight elements with nodal positions as unknowns (eq. 4). Strain is computed
//! from the current and original element lengths, ε = L/L0 − 1 (eqs. 7–8 with the lost
//! equation restored from the text: the element's unit vector t = (r2 − r1)/L gives the
//! direction cosines of eq. 9), so a rigid rotation produces no strain. The elastic and damping
//! nodal forces are F1 = T t, F2 = −T t with T = T(ε, ε̇) (eqs. 13–15, our derivation:
//! δU = ∫ T δε ds = T t·(δr2 − δr1)); ε̇ = t·(v2 − v1)/L0 (eq. 14).
//! The consistent mass matrix is γ0 L0/6 [2I I; I 2I] (eq. 12, restored: ∫ NᵀN γ0 ds for
//! linear shape functions N = [(1−ξ)I, ξI]); the added mass (eqs. 17–18) is orientation
//! dependent, ρ A (C_an (I − t tᵀ) + C_at t tᵀ), integrated with the same shape functions.
//! Drag (eqs. 16, 19–23) and added mass are integrated with two-point Gauss quadrature of the
//! linearly interpolated velocities (eq. 20); weight and buoyancy (eqs. 24–25) exactly,
//! including the part of an element below the water surface; seabed and obstacle contact at
//! the nodes ([`obstacle_contacts`]).

use super::{ElementState, LoadOptions, Mesh};
use crate::formulation::fluid_load;
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3};
use crate::model::MassMatrix;
use crate::physics::environment::Environment;
use crate::physics::hydrodynamics::added_mass_matrix;
use crate::physics::obstacles::{LineBall, Obstacle};

/// Gauss points on [0, 1] for two-point quadrature (weight ½ each).
const GAUSS: [Real; 2] = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];

/// Evaluates the nodal forces [N] of an `fe` line at positions `r` [m] and velocities `v`
/// [m/s] (nodes 0..=N, ends included) and, if asked, its mass blocks [kg] into `blocks`.
///
/// `forces[i]` is the total force the line's physics puts on node i: tension, weight,
/// buoyancy, drag, fluid inertia, seabed and obstacle contact. End forces on attachments
/// follow from it.
#[allow(clippy::too_many_arguments)]
pub fn line_forces(
    line: &Mesh,
    mass_matrix: MassMatrix,
    env: &Environment,
    time: Real,
    r: &[Vec3],
    v: &[Vec3],
    forces: &mut [Vec3],
    elements: &mut ElementState,
    blocks: Option<&mut LineBlocks>,
    options: LoadOptions,
) {
    let n = line.elements();
    forces[..=n].iter_mut().for_each(|f| *f = Vec3::zeros());
    let g = env.gravity;
    let rho_w = env.water_density;
    // Nothing above the bed's highest point touches it (−depth for a flat bed).
    let bed_top = env.seabed_top();
    let consistent = mass_matrix == MassMatrix::Consistent;
    // No current and no waves: the fluid is at rest everywhere.
    let still_water = env.is_still_water();
    let mut blocks = blocks;
    if let Some(b) = blocks.as_deref_mut() {
        b.clear();
    }
    for e in 0..n {
        let sec = &line.sections[line.element_section[e]];
        let lt = &sec.line_type;
        let l0 = sec.element_length;
        let (ra, rb) = (r[e], r[e + 1]);
        let (va, vb) = (v[e], v[e + 1]);
        let delta = rb - ra;
        let length = delta.norm();
        let t = delta * (1.0 / length);
        let strain = length * sec.inverse_length - 1.0;
        // ε̇ = t·(v_b − v_a)/L0 (eq. 14), less σ(1 + ε) on a winch (Mesh::length_rate).
        let strain_rate =
            t.dot(&(vb - va)) * sec.inverse_length - line.length_rate * (1.0 + strain);
        let tension = sec.law.tension(strain, strain_rate);
        elements.tension[e] = tension;
        elements.strain[e] = strain;
        let stretch = 1.0 + strain;
        let ft = t * tension;
        forces[e] += ft;
        forces[e + 1] -= ft;

        // Weight and buoyancy (eqs. 24–25), buoyancy on the submerged part only.
        let weight = lt.mass_per_length * g * l0 * 0.5;
        let (sub_a, sub_b) = submerged_shape_integrals(ra.z, rb.z);
        let buoy = rho_w * sec.area * g * l0;
        forces[e].z += buoy * sub_a - weight;
        forces[e + 1].z += buoy * sub_b - weight;

        // Drag and fluid inertia at two Gauss points (eqs. 16, 19–23).
        let root_stretch = stretch.max(0.0).sqrt();
        let w = 0.5 * l0;
        for (g, &xi) in GAUSS.iter().enumerate() {
            let (na, nb) = (1.0 - xi, xi);
            let f = fluid_load(
                env,
                &options.fluid,
                2 * e + g,
                lt,
                sec.area,
                time,
                &(ra * na + rb * nb),
                &(va * na + vb * nb),
                &t,
                root_stretch,
                options.current_factor,
                still_water,
            );
            forces[e] += f * (w * na);
            forces[e + 1] += f * (w * nb);
        }

        // Structural and added mass (eqs. 12, 17–18): per unit length
        // γ0 I + ρ A (C_an (I − t tᵀ) + C_at t tᵀ) = (γ0 + ρ A C_an) I + ρ A (C_at − C_an) t tᵀ,
        // integrated with the linear shape functions; exact with one evaluation unless the
        // element crosses the surface, where each Gauss point takes its own density.
        if let Some(b) = blocks.as_deref_mut() {
            // Element mass over `length` at density `rho`: (γ0 I + added mass) · length.
            let element_mass = |rho: Real, length: Real| -> Mat3 {
                let mut m = added_mass_matrix(
                    rho,
                    sec.area,
                    lt.normal_added_mass,
                    lt.tangential_added_mass,
                    &t,
                );
                for k in 0..3 {
                    m[(k, k)] += lt.mass_per_length;
                }
                m * length
            };
            if (ra.z < 0.0) == (rb.z < 0.0) {
                // Uniform density: exact shape-function integrals, ∫NaNa = ∫NbNb = 1/3 and
                // ∫NaNb = 1/6 (consistent), ∫Na = ∫Nb = 1/2 (lumped).
                let rho = env.fluid_density(ra.z);
                if consistent {
                    let third = element_mass(rho, l0 / 3.0);
                    b.diag[e] += third;
                    b.diag[e + 1] += third;
                    let sixth = third * 0.5;
                    b.lower[e] += sixth;
                    b.upper[e] += sixth;
                } else {
                    let half = element_mass(rho, 0.5 * l0);
                    b.diag[e] += half;
                    b.diag[e + 1] += half;
                }
            } else {
                // Crossing the surface: each Gauss point takes its own density.
                for &xi in &GAUSS {
                    let (na, nb) = (1.0 - xi, xi);
                    let m = element_mass(env.fluid_density(ra.z * na + rb.z * nb), w);
                    if consistent {
                        b.diag[e] += m * (na * na);
                        b.diag[e + 1] += m * (nb * nb);
                        b.lower[e] += m * (na * nb);
                        b.upper[e] += m * (na * nb);
                    } else {
                        b.diag[e] += m * na;
                        b.diag[e + 1] += m * nb;
                    }
                }
            }
        }

        // Seabed contact (DG paper eqs. 15–16) by nodal quadrature over the element.
        if ra.z < bed_top || rb.z < bed_top {
            let net_weight = (rho_w * sec.area - lt.mass_per_length) * g;
            for (node, rn, vn) in [(e, ra, va), (e + 1, rb, vb)] {
                let f = env.seabed_contact_force(
                    &rn,
                    &vn,
                    lt.diameter,
                    lt.mass_per_length,
                    stretch,
                    net_weight,
                    line.node_length(node),
                );
                forces[node] += f * (0.5 * l0);
            }
        }
    }

    // Obstacle contact by the same nodal quadrature.
    if !env.obstacles.is_empty() {
        obstacle_contacts(line, &env.obstacles, time, r, v, |_, node, f, w| {
            forces[node] += f * w
        });
    }
}

/// Contact of an `fe` line with `obstacles` at time `time` [s], by the nodal quadrature of the
/// seabed contact: each element contributes, at each of its two nodes, the contact force per
/// unit unstretched length there ([`Obstacle::contact_force`], with the element's stretch
/// L/L0) times half its unstretched length L0/2. Calls `visit(obstacle, node, f, w)` for each
/// such contribution in contact: f [N/m] the force per unit length on the line, w [m] the
/// weight, so that node `node` receives f·w [N]. Obstacles whose quick test
/// ([`Obstacle::may_touch`] on a ball holding the line) fails are skipped with O(1) work.
/// The dynamics ([`line_forces`]) and the obstacle channels ([`crate::analysis::obstacles`])
/// both go through this function, so the channels are exactly the forces the nodes receive.
pub fn obstacle_contacts(
    line: &Mesh,
    obstacles: &[Obstacle],
    time: Real,
    r: &[Vec3],
    v: &[Vec3],
    mut visit: impl FnMut(usize, usize, Vec3, Real),
) {
    let n = line.elements();
    let mut bounds = LineBall::new();
    r[..=n].iter().for_each(|p| bounds.add(p));
    let (centre, radius) = bounds.ball();
    let cable_radius = line
        .sections
        .iter()
        .fold(0.0, |m: Real, s| m.max(0.5 * s.line_type.diameter));
    for (k, obstacle) in obstacles.iter().enumerate() {
        let kin = obstacle.kinematics(time);
        if !obstacle.may_touch(&kin, &centre, radius + cable_radius) {
            continue;
        }
        for e in 0..n {
            let sec = line.section(e);
            let lt = &sec.line_type;
            let contact = [
                obstacle.penetration(&kin, &r[e], lt.diameter),
                obstacle.penetration(&kin, &r[e + 1], lt.diameter),
            ];
            if contact.iter().all(Option::is_none) {
                continue;
            }
            let stretch = (r[e + 1] - r[e]).norm() * sec.inverse_length;
            for (j, p) in contact.iter().enumerate() {
                if let Some(p) = p {
                    let node = e + j;
                    let f = obstacle.contact_force(&kin, p, &v[node], lt.mass_per_length, stretch);
                    visit(k, node, f, 0.5 * sec.element_length);
                }
            }
        }
    }
}

/// Mechanical energy of element e [J]: kinetic ½ vᵀ M v with the element's structural mass
/// (consistent, ½ (m/6)[2 1; 1 2] (eq. 12), or lumped), weight γ0 L0 g z̄ and strain energy
/// L0 W(ε), ε = L/L0 − 1: the potential whose gradient [`line_forces`] evaluates in air.
pub fn element_energy(
    mesh: &Mesh,
    mass_matrix: MassMatrix,
    gravity: Real,
    q: &[Vec3],
    qdot: &[Vec3],
    e: usize,
) -> super::Energy {
    let s = mesh.section(e);
    let l0 = s.element_length;
    let m = s.line_type.mass_per_length * l0;
    let (va, vb) = (qdot[e], qdot[e + 1]);
    super::Energy {
        kinetic: match mass_matrix {
            MassMatrix::Lumped => 0.25 * m * (va.norm_squared() + vb.norm_squared()),
            MassMatrix::Consistent => {
                m / 6.0 * (va.norm_squared() + va.dot(&vb) + vb.norm_squared())
            }
        },
        gravity: m * gravity * 0.5 * (q[e].z + q[e + 1].z),
        elastic: l0
            * s.law
                .strain_energy_density((q[e + 1] - q[e]).norm() / l0 - 1.0),
    }
}

/// ∫ N_a and ∫ N_b over the submerged (z < 0) part of a straight element from height `za` to
/// `zb`, as fractions of the element length (each is ½ when fully submerged).
#[inline]
pub fn submerged_shape_integrals(za: Real, zb: Real) -> (Real, Real) {
    if za <= 0.0 && zb <= 0.0 {
        return (0.5, 0.5);
    }
    if za >= 0.0 && zb >= 0.0 {
        return (0.0, 0.0);
    }
    // Crossing at ξ* = za / (za − zb).
    let xs = za / (za - zb);
    if za < 0.0 {
        // Submerged on [0, ξ*]: ∫(1−ξ) = ξ* − ξ*²/2, ∫ξ = ξ*²/2.
        (xs - 0.5 * xs * xs, 0.5 * xs * xs)
    } else {
        // Submerged on [ξ*, 1].
        let a = 0.5 - (xs - 0.5 * xs * xs);
        let b = 0.5 - 0.5 * xs * xs;
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn submerged_integrals_sum_to_submerged_fraction() {
        for (za, zb, frac) in [
            (-1.0, 1.0, 0.5),
            (1.0, -3.0, 0.75),
            (-2.0, -1.0, 1.0),
            (2.0, 1.0, 0.0),
        ] {
            let (a, b) = submerged_shape_integrals(za, zb);
            assert!((a + b - frac).abs() < 1e-15, "{za} {zb}");
        }
        // Upper end dry: the wet lower node carries more of the buoyancy.
        let (a, b) = submerged_shape_integrals(-1.0, 1.0);
        assert!((a - 0.375).abs() < 1e-15 && (b - 0.125).abs() < 1e-15);
    }
}
