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

use super::{ElementState, LoadOptions, Mesh, SectionProperties};
use crate::formulation::fluid_load;
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3};
use crate::model::MassMatrix;
use crate::physics::environment::Environment;
use crate::physics::hydrodynamics::{DragModel, added_mass_of, drag_force_with_factor};
use crate::physics::obstacles::{LineBall, Obstacle};

/// Gauss points on [0, 1] for two-point quadrature (weight ½ each).
const GAUSS: [Real; 2] = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];

/// Evaluates the nodal forces [N] of an `fe` line at positions `r` [m] and velocities `v`
/// [m/s] (nodes 0..=N, ends included) and, if asked, its mass blocks [kg] into `blocks`.
///
/// `forces[i]` is the total force the line's physics puts on node i: tension, weight,
/// buoyancy, drag, fluid inertia, seabed and obstacle contact. End forces on attachments
/// follow from it.
///
/// The element loop walks the line once, section by section, with everything that does not
/// change along a section computed once (`SectionConstants`); each node's force is summed
/// in a register while its two elements are evaluated (the contributions of element e − 1,
/// then those of element e, in the order of the equations above: tension, weight and
/// buoyancy, the two Gauss points, seabed contact), so that every node receives the same
/// sums in the same order whatever the section boundaries.
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
    let (r, v, forces) = (&r[..=n], &v[..=n], &mut forces[..=n]);
    let (tension_out, strain_out) = (&mut elements.tension[..n], &mut elements.strain[..n]);
    // Nothing above the bed's highest point touches it (−depth for a flat bed).
    let bed_top = env.seabed_top();
    let consistent = mass_matrix == MassMatrix::Consistent;
    // No current and no waves: the fluid is at rest everywhere.
    let still_water = env.is_still_water();
    let mut blocks = blocks;
    if let Some(b) = blocks.as_deref_mut() {
        // A lumped line's diagonal blocks are all written below, from its `LumpedMass`.
        if consistent || b.coupled {
            b.clear();
        }
    }
    // The isotropic mass c [kg] of node e summed so far (element e − 1's share).
    let mut node_isotropic = 0.0;
    // The force on node e summed so far (the contributions of element e − 1), and half the
    // unstretched length of element e − 1 (node e's share of it, 0 at node 0).
    let mut node_force = Vec3::zeros();
    let mut previous_half = 0.0;
    let (mut ra, mut va) = (r[0], v[0]);
    let mut first = 0;
    while first < n {
        let section = line.element_section[first];
        let end = first
            + line.element_section[first..]
                .iter()
                .position(|&s| s != section)
                .unwrap_or(n - first);
        let sec = &line.sections[section];
        let k = SectionConstants::new(sec, env);
        let lt = &sec.line_type;
        let per_element = r[first + 1..=end]
            .iter()
            .zip(&v[first + 1..=end])
            .zip(tension_out[first..end].iter_mut())
            .zip(strain_out[first..end].iter_mut())
            .zip(forces[first..end].iter_mut());
        for (e, ((((&rb, &vb), tension_out), strain_out), force_out)) in
            (first..end).zip(per_element)
        {
            let delta = rb - ra;
            let length = delta.norm();
            let t = delta * (1.0 / length);
            let strain = length * sec.inverse_length - 1.0;
            // ε̇ = t·(v_b − v_a)/L0 (eq. 14), less σ(1 + ε) on a winch (Mesh::length_rate).
            let strain_rate =
                t.dot(&(vb - va)) * sec.inverse_length - line.length_rate * (1.0 + strain);
            let tension = sec.law.tension(strain, strain_rate);
            *tension_out = tension;
            *strain_out = strain;
            let stretch = 1.0 + strain;
            let ft = t * tension;
            let mut fa = node_force;
            let mut fb = Vec3::zeros();
            fa += ft;
            fb -= ft;

            // Weight and buoyancy (eqs. 24–25), buoyancy on the submerged part only.
            let (sub_a, sub_b) = submerged_shape_integrals(ra.z, rb.z);
            fa.z += k.buoyancy * sub_a - k.weight;
            fb.z += k.buoyancy * sub_b - k.weight;

            // Drag and fluid inertia at two Gauss points (eqs. 16, 19–23).
            let root_stretch = stretch.max(0.0).sqrt();
            if still_water {
                // Both Gauss points at once (lane g holds point g): the same operations as
                // `fluid_load` in fluid at rest, which the compiler packs two by two.
                let f = k.still_water_drag_pair(&ra, &rb, &va, &vb, root_stretch, &t);
                for (f, xi) in f.iter().zip(GAUSS) {
                    fa += f * (k.half_length * (1.0 - xi));
                    fb += f * (k.half_length * xi);
                }
            } else {
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
                    fa += f * (k.half_length * na);
                    fb += f * (k.half_length * nb);
                }
            }

            // Structural and added mass (eqs. 12, 17–18): per unit length
            // γ0 I + ρ A (C_an (I − t tᵀ) + C_at t tᵀ) = (γ0 + ρ A C_an) I + ρ A (C_at − C_an) t tᵀ,
            // integrated with the linear shape functions; exact with one evaluation unless
            // the element crosses the surface, where each Gauss point takes its own density.
            if let Some(b) = blocks.as_deref_mut() {
                if consistent {
                    add_element_mass(b, e, &k, &t, ra.z, rb.z);
                } else {
                    let ([ca, cb], rank_one) = lumped_element_mass(&k, ra.z, rb.z);
                    b.lumped.isotropic[e] = node_isotropic + ca;
                    b.lumped.rank_one[e] = rank_one;
                    b.lumped.tangent[e] = t;
                    node_isotropic = cb;
                }
            }

            // Seabed contact (DG paper eqs. 15–16) by nodal quadrature over the element.
            if ra.z < bed_top || rb.z < bed_top {
                let contact = |position: &Vec3, velocity: &Vec3, node_length: Real| {
                    env.seabed.contact_force_with(
                        &env.seabed_at(position.x, position.y),
                        position,
                        velocity,
                        lt.diameter,
                        root_stretch,
                        k.seabed_damping,
                        k.net_weight,
                        node_length,
                    ) * k.half_length
                };
                // Each node carries half of each adjacent element.
                fa += contact(&ra, &va, previous_half + k.half_length);
                let next_half = if e + 1 < n {
                    0.5 * line.section(e + 1).element_length
                } else {
                    0.0
                };
                fb += contact(&rb, &vb, k.half_length + next_half);
            }
            *force_out = fa;
            node_force = fb;
            previous_half = k.half_length;
            (ra, va) = (rb, vb);
        }
        first = end;
    }
    forces[n] = node_force;
    if let Some(b) = blocks.filter(|_| !consistent) {
        b.lumped.isotropic[n] = node_isotropic;
        b.lumped.current = true;
        if b.lumped.ends_only && !b.coupled {
            b.diag[0] = b.lumped.block(0);
            b.diag[n] = b.lumped.block(n);
        } else {
            b.form_lumped_diagonal();
        }
    }

    // Obstacle contact by the same nodal quadrature.
    if !env.obstacles.is_empty() {
        obstacle_contacts(line, &env.obstacles, time, r, v, |_, node, f, w| {
            forces[node] += f * w
        });
    }
}

/// What [`line_forces`] needs of a section that does not change along it, each computed by
/// the expression the per-element code would use (so the results are the same bits).
struct SectionConstants<'a> {
    /// Half the weight of an element, γ0 g L0 / 2 [N].
    weight: Real,
    /// Buoyancy of a submerged element, ρ_w A g L0 [N].
    buoyancy: Real,
    /// L0 / 2 [m]: the Gauss weight, and each node's share of the element.
    half_length: Real,
    /// ½ ρ d in water and in air [kg/m²]: the drag's dynamic-pressure factor before √(1+ε).
    drag_factor: [Real; 2],
    /// Morison's C_dn and C_dt, `None` for drag loading functions.
    morison: Option<(Real, Real)>,
    /// The drag model (for loading functions).
    drag: &'a DragModel,
    /// Added mass per unit length in water and in air: ρ A C_an and ρ A (C_at − C_an) [kg/m].
    added_mass: [(Real, Real); 2],
    /// Mass per unit length γ0 [kg/m].
    mass_per_length: Real,
    /// Unstretched element length L0 [m].
    element_length: Real,
    /// Vertical seabed damping per unit length [N·s/m²].
    seabed_damping: Real,
    /// Net weight per unit length (ρ_w A − γ0) g [N/m] (negative when the cable sinks).
    net_weight: Real,
}

impl<'a> SectionConstants<'a> {
    #[inline]
    fn new(sec: &'a SectionProperties, env: &Environment) -> Self {
        let lt = &sec.line_type;
        let (g, rho_w, l0) = (env.gravity, env.water_density, sec.element_length);
        let added = |rho: Real| {
            (
                rho * sec.area * lt.normal_added_mass,
                rho * sec.area * (lt.tangential_added_mass - lt.normal_added_mass),
            )
        };
        Self {
            weight: lt.mass_per_length * g * l0 * 0.5,
            buoyancy: rho_w * sec.area * g * l0,
            half_length: 0.5 * l0,
            drag_factor: [
                0.5 * rho_w * lt.diameter,
                0.5 * env.air_density * lt.diameter,
            ],
            morison: match lt.drag {
                DragModel::Morison { normal, tangential } => Some((normal, tangential)),
                DragModel::LoadingFunctions { .. } => None,
            },
            drag: &lt.drag,
            added_mass: [added(rho_w), added(env.air_density)],
            mass_per_length: lt.mass_per_length,
            element_length: l0,
            seabed_damping: env
                .seabed
                .damping_per_length(lt.diameter, lt.mass_per_length),
            net_weight: (rho_w * sec.area - lt.mass_per_length) * g,
        }
    }

    /// Drag per unit unstretched length [N/m] in fluid at rest at the two Gauss points of the
    /// element from `ra` to `rb` [m] moving at `va`, `vb` [m/s], with unit tangent `t` and
    /// √(1+ε) `root_stretch`: `drag_force` of the relative velocity −v at each point, in
    /// water or in air by the point's height, Morison's drag written lane by lane (lane g is
    /// Gauss point g) so that the two points are computed together.
    #[inline(always)]
    fn still_water_drag_pair(
        &self,
        ra: &Vec3,
        rb: &Vec3,
        va: &Vec3,
        vb: &Vec3,
        root_stretch: Real,
        t: &Vec3,
    ) -> [Vec3; 2] {
        let (na, nb) = ([1.0 - GAUSS[0], 1.0 - GAUSS[1]], GAUSS);
        let Some((normal, tangential)) = self.morison else {
            let point = |g: usize| {
                let z = ra.z * na[g] + rb.z * nb[g];
                let factor = if z < 0.0 {
                    self.drag_factor[0]
                } else {
                    self.drag_factor[1]
                };
                let relative = -(va * na[g] + vb * nb[g]);
                drag_force_with_factor(self.drag, factor, root_stretch, t, &relative)
            };
            return [point(0), point(1)];
        };
        let z = lanes(|g| ra.z * na[g] + rb.z * nb[g]);
        // The relative velocity −(va na + vb nb), component by component.
        let rx = lanes(|g| -(va.x * na[g] + vb.x * nb[g]));
        let ry = lanes(|g| -(va.y * na[g] + vb.y * nb[g]));
        let rz = lanes(|g| -(va.z * na[g] + vb.z * nb[g]));
        let vt = lanes(|g| rx[g] * t.x + ry[g] * t.y + rz[g] * t.z);
        let nx = lanes(|g| rx[g] - t.x * vt[g]);
        let ny = lanes(|g| ry[g] - t.y * vt[g]);
        let nz = lanes(|g| rz[g] - t.z * vt[g]);
        let vn = lanes(|g| (nx[g] * nx[g] + ny[g] * ny[g] + nz[g] * nz[g]).sqrt());
        let q = lanes(|g| {
            let factor = if z[g] < 0.0 {
                self.drag_factor[0]
            } else {
                self.drag_factor[1]
            };
            factor * root_stretch
        });
        let cn = lanes(|g| normal * vn[g]);
        let ct = lanes(|g| tangential * vt[g].abs());
        // Written out rather than `[0, 1].map(..)`, which the compiler left as a call.
        let point = |g: usize| {
            Vec3::new(
                q[g] * (cn[g] * nx[g] + ct[g] * (t.x * vt[g])),
                q[g] * (cn[g] * ny[g] + ct[g] * (t.y * vt[g])),
                q[g] * (cn[g] * nz[g] + ct[g] * (t.z * vt[g])),
            )
        };
        [point(0), point(1)]
    }

    /// The element's mass per unit length γ0 I + added mass at density index `fluid` (0
    /// water, 1 air), times `length` [m] ([`added_mass_of`]).
    #[inline(always)]
    fn element_mass(&self, fluid: usize, tangent: &Vec3, length: Real) -> Mat3 {
        let (alpha, beta) = self.added_mass[fluid];
        let mut m = added_mass_of(alpha, beta, tangent);
        for k in 0..3 {
            m[(k, k)] += self.mass_per_length;
        }
        m * length
    }
}

/// [f(0), f(1)]: a quantity at both Gauss points.
#[inline(always)]
fn lanes(f: impl Fn(usize) -> Real) -> [Real; 2] {
    [f(0), f(1)]
}

/// The index of the fluid at height z [m] in [`SectionConstants`]' pairs: 0 in water (z < 0),
/// 1 in air.
#[inline(always)]
fn fluid(z: Real) -> usize {
    usize::from(!(z < 0.0))
}

/// Adds element e's consistent mass blocks [kg] into `b` (see [`line_forces`]).
#[inline(always)]
fn add_element_mass(
    b: &mut LineBlocks,
    e: usize,
    k: &SectionConstants,
    t: &Vec3,
    za: Real,
    zb: Real,
) {
    let l0 = k.element_length;
    if (za < 0.0) == (zb < 0.0) {
        // Uniform density: exact shape-function integrals, ∫NaNa = ∫NbNb = 1/3 and
        // ∫NaNb = 1/6.
        let third = k.element_mass(fluid(za), t, l0 / 3.0);
        b.diag[e] += third;
        b.diag[e + 1] += third;
        let sixth = third * 0.5;
        b.lower[e] += sixth;
        b.upper[e] += sixth;
    } else {
        // Crossing the surface: each Gauss point takes its own density.
        for &xi in &GAUSS {
            let (na, nb) = (1.0 - xi, xi);
            let m = k.element_mass(fluid(za * na + zb * nb), t, k.half_length);
            b.diag[e] += m * (na * na);
            b.diag[e + 1] += m * (nb * nb);
            b.lower[e] += m * (na * nb);
            b.upper[e] += m * (na * nb);
        }
    }
}

/// The lumped mass of an element from height `za` to `zb` [m] as its two nodes' shares of
/// the isotropic part, [c_a, c_b] = ∫ N (γ0 + ρ A C_an) ds [kg], and of the weight of t tᵀ,
/// [b_a, b_b] = ∫ N ρ A (C_at − C_an) ds [kg] ([`crate::linalg::LumpedMass`]): ∫ N = L0/2 for each node at
/// uniform density; crossing the surface, each Gauss point takes its own density.
#[inline(always)]
fn lumped_element_mass(k: &SectionConstants, za: Real, zb: Real) -> ([Real; 2], [Real; 2]) {
    if (za < 0.0) == (zb < 0.0) {
        let (alpha, beta) = k.added_mass[fluid(za)];
        let c = (k.mass_per_length + alpha) * k.half_length;
        let b = beta * k.half_length;
        ([c, c], [b, b])
    } else {
        let (mut c, mut b) = ([0.0; 2], [0.0; 2]);
        for &xi in &GAUSS {
            let (alpha, beta) = k.added_mass[fluid(za * (1.0 - xi) + zb * xi)];
            for (j, n) in [1.0 - xi, xi].into_iter().enumerate() {
                c[j] += (k.mass_per_length + alpha) * (k.half_length * n);
                b[j] += beta * (k.half_length * n);
            }
        }
        (c, b)
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
