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

pub mod jacobian;

use super::{ElementState, LoadOptions, Mesh, SectionProperties};
use crate::formulation::fluid_load;
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3};
use crate::model::MassMatrix;
use crate::physics::environment::{Current, Environment, profile_at};
use crate::physics::hydrodynamics::{
    DragModel, added_mass_coefficients, added_mass_of, drag_force_with_factor,
};
use crate::physics::material::AxialStiffness;
use crate::physics::obstacles::{LineBall, Obstacle};
use crate::physics::static_kinematics::FluidPoints;

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
/// change along a section computed once (`SectionConstants`), several elements at a time
/// (`ElementBatch`): what depends on one element only (tangent, strain, tension, weight and
/// buoyancy, Morison's fluid load with the fluid's kinematics taken point by point) is
/// computed lane by lane, then each node's force is summed from the contributions of
/// element e − 1, then those of element e, in the order of the equations above (tension,
/// weight and buoyancy, the two Gauss points, seabed contact), so that every node receives
/// the same sums in the same order whatever the section boundaries and the lanes. Where a
/// batch is clear of the seabed and its fluid load is in the lanes, the node sums go lane by
/// lane too.
///
/// The loop runs in batches of four elements, compiled for AVX2 and SSE2, and on a processor
/// with AVX-512 in batches of eight for lines of at least [`WIDE_LINE`] elements (the lanes
/// past a section's last element computed and dropped), compiled for AVX-512
/// (`crate::math::wide_simd_fn`), with the same bits from all.
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
    let wide = crate::math::simd_level() == crate::math::SimdLevel::Avx512;
    let in_batches = if wide && line.elements() >= WIDE_LINE {
        line_forces_wide
    } else {
        line_forces_narrow
    };
    in_batches(
        line,
        mass_matrix,
        env,
        time,
        r,
        v,
        forces,
        elements,
        blocks,
        options,
    )
}

crate::math::wide_simd_fn! {
    /// [`line_forces`] in batches of four elements.
    #[allow(clippy::too_many_arguments)]
    fn line_forces_narrow(
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
        line_forces_in_lanes::<4>(
            line, mass_matrix, env, time, r, v, forces, elements, blocks, options,
        )
    }
}

crate::math::wide_simd_fn! {
    avx512;
    /// [`line_forces`] in batches of eight elements.
    #[allow(clippy::too_many_arguments)]
    fn line_forces_wide(
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
        line_forces_in_lanes::<8>(
            line, mass_matrix, env, time, r, v, forces, elements, blocks, options,
        )
    }
}

/// The lines of at least this many elements that [`line_forces`] evaluates in batches of
/// eight with AVX-512, whose registers hold eight: at most seven lanes a section are computed
/// and dropped. Measured against batches of four (`hawser bench`, RK4, lumped mass): the OC3
/// deck's lines of 20 elements 1.01×, a 1000 m chain of 40 elements 1.09×, of 320 1.18×.
const WIDE_LINE: usize = 16;

/// [`line_forces`] in batches of `L` elements.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn line_forces_in_lanes<const L: usize>(
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
        if consistent {
            // Every block of a consistent line is started from zero by the element that
            // first adds to it (`add_element_mass`): no pass clearing them first.
            b.lumped.current = false;
        } else if b.coupled {
            // A lumped line's diagonal blocks are all written below, from its `LumpedMass`.
            b.clear();
        }
    }
    // The isotropic mass c [kg] of node e summed so far (element e − 1's share).
    let mut node_isotropic = 0.0;
    // The force on node e summed so far (the contributions of element e − 1), and half the
    // unstretched length of element e − 1 (node e's share of it, 0 at node 0).
    let mut node_force = Vec3::zeros();
    let mut previous_half = 0.0;
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
        // Morison's fluid load (drag, and in moving water Froude–Krylov and added-mass
        // force): the batches compute it with the elements.
        let batch_drag = k.morison.is_some();
        let mut batch = ElementBatch::<L>::new();
        for e0 in (first..end).step_by(L) {
            let count = L.min(end - e0);
            batch.evaluate(
                &k,
                sec,
                line.length_rate,
                &r[e0..=end],
                &v[e0..=end],
                still_water,
            );
            if batch_drag && !still_water {
                batch.fluid_drag(
                    &k,
                    env,
                    &options.fluid,
                    2 * e0,
                    sec.area,
                    (lt.normal_added_mass, lt.tangential_added_mass),
                    time,
                    options.current_factor,
                );
            }
            if count == L {
                // A whole batch: a copy of fixed length, inlined (a call to memcpy else).
                tension_out[e0..e0 + L].copy_from_slice(&batch.tension);
                strain_out[e0..e0 + L].copy_from_slice(&batch.strain);
            } else {
                tension_out[e0..e0 + count].copy_from_slice(&batch.tension[..count]);
                strain_out[e0..e0 + count].copy_from_slice(&batch.strain[..count]);
            }
            // Structural and added mass (eqs. 12, 17–18): per unit length
            // γ0 I + ρ A (C_an (I − t tᵀ) + C_at t tᵀ) = (γ0 + ρ A C_an) I + ρ A (C_at − C_an) t tᵀ,
            // integrated with the linear shape functions; exact with one evaluation unless
            // the element crosses the surface, where each Gauss point takes its own density.
            if let Some(b) = blocks.as_deref_mut() {
                if consistent {
                    for (lane, e) in (e0..e0 + count).enumerate() {
                        let t = Vec3::new(batch.tx[lane], batch.ty[lane], batch.tz[lane]);
                        add_element_mass(b, e, &k, &t, r[e].z, r[e + 1].z);
                    }
                } else {
                    let lumped = &mut b.lumped;
                    let elements = e0..e0 + count;
                    let isotropic = &mut lumped.isotropic[elements.clone()];
                    let [rank_a, rank_b] = &mut lumped.rank_one;
                    let (rank_a, rank_b) =
                        (&mut rank_a[elements.clone()], &mut rank_b[elements.clone()]);
                    let [tx, ty, tz] = &mut lumped.tangent;
                    let (tx, ty, tz) = (
                        &mut tx[elements.clone()],
                        &mut ty[elements.clone()],
                        &mut tz[elements.clone()],
                    );
                    for lane in 0..count {
                        let (za, zb) = (r[e0 + lane].z, r[e0 + lane + 1].z);
                        let ([ca, cb], [ba, bb]) = lumped_element_mass(&k, za, zb);
                        isotropic[lane] = node_isotropic + ca;
                        (rank_a[lane], rank_b[lane]) = (ba, bb);
                        (tx[lane], ty[lane], tz[lane]) =
                            (batch.tx[lane], batch.ty[lane], batch.tz[lane]);
                        node_isotropic = cb;
                    }
                }
            }
            if batch_drag && r[e0..=e0 + count].iter().all(|p| !(p.z < bed_top)) {
                // Clear of the bed, the fluid load in the lanes: nothing but the batch's own
                // terms, so the nodes' sums lane by lane too.
                node_force = batch.sum_nodes(node_force, &mut forces[e0..e0 + count], count);
                previous_half = k.half_length;
                continue;
            }
            for (lane, e) in (e0..e0 + count).enumerate() {
                let (ra, rb, va, vb) = (r[e], r[e + 1], v[e], v[e + 1]);
                let t = Vec3::new(batch.tx[lane], batch.ty[lane], batch.tz[lane]);
                let ft = Vec3::new(batch.ftx[lane], batch.fty[lane], batch.ftz[lane]);
                let mut fa = node_force;
                let mut fb = Vec3::zeros();
                fa += ft;
                fb -= ft;

                // Weight and buoyancy (eqs. 24–25), buoyancy on the submerged part only.
                fa.z += batch.weight_a[lane];
                fb.z += batch.weight_b[lane];

                // Drag and fluid inertia at two Gauss points (eqs. 16, 19–23).
                let root_stretch = batch.root_stretch[lane];
                if batch_drag {
                    for g in 0..2 {
                        let [ax, ay, az] = &batch.drag_a[g];
                        let [bx, by, bz] = &batch.drag_b[g];
                        fa += Vec3::new(ax[lane], ay[lane], az[lane]);
                        fb += Vec3::new(bx[lane], by[lane], bz[lane]);
                    }
                } else if still_water {
                    // Drag loading functions in fluid at rest.
                    for xi in GAUSS {
                        let (na, nb) = (1.0 - xi, xi);
                        let z = ra.z * na + rb.z * nb;
                        let relative = -(va * na + vb * nb);
                        let f = drag_force_with_factor(
                            k.drag,
                            k.drag_factor[fluid_index(z)],
                            root_stretch,
                            &t,
                            &relative,
                        );
                        fa += f * (k.half_length * na);
                        fb += f * (k.half_length * nb);
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
                forces[e] = fa;
                node_force = fb;
                previous_half = k.half_length;
            }
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
            added_mass_coefficients(
                rho,
                sec.area,
                lt.normal_added_mass,
                lt.tangential_added_mass,
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

/// The quantities of up to `L` consecutive elements (lane l: the batch's element l; the compiler
/// packs the lanes into SIMD registers, two a register with SSE2, four with AVX2, eight with
/// AVX-512) of one section that depend on
/// nothing but the element: unit tangent t, strain ε, tension T and its nodal force T t
/// (eqs. 7–9, 13–15), √(1+ε), weight and buoyancy, and with Morison drag the fluid load
/// (eqs. 16, 19–23; in moving water with the fluid's inertia) at both Gauss points times each
/// node's share of
/// the Gauss weight, (L0/2) N_a(ξ_g) and
/// (L0/2) N_b(ξ_g). [`line_forces`] adds them node by node in its own order. Each lane runs
/// the expressions a per-element loop would, so the results are the same bits whatever the
/// lane count or the instruction set.
struct ElementBatch<const L: usize> {
    /// Unit tangent components [-].
    tx: [Real; L],
    ty: [Real; L],
    tz: [Real; L],
    /// Axial strain ε = L/L0 − 1 [-].
    strain: [Real; L],
    /// Tension T(ε, ε̇) [N].
    tension: [Real; L],
    /// √(max(1 + ε, 0)) [-]: the drag's diameter and length factor.
    root_stretch: [Real; L],
    /// T t, the force on the element's first node [N] (its second node takes −T t).
    ftx: [Real; L],
    fty: [Real; L],
    ftz: [Real; L],
    /// Weight and buoyancy on the first and second node, ρ_w A g L0 ∫N_a − γ0 g L0/2 and
    /// the same with N_b (the integrals over the submerged part, eqs. 24–25) [N], upward.
    weight_a: [Real; L],
    weight_b: [Real; L],
    /// Drag at Gauss point g times (L0/2) N_a(ξ_g), components x, y, z [N].
    drag_a: [[[Real; L]; 3]; 2],
    /// Drag at Gauss point g times (L0/2) N_b(ξ_g) [N].
    drag_b: [[[Real; L]; 3]; 2],
    /// The nodes, [r_a, r_b, v_a, v_b][component][lane] [m, m/s], kept for the fluid load in
    /// moving water (by `evaluate`).
    node: [[[Real; L]; 3]; 4],
    /// The last lane holding an element of its own (the lanes after it repeat it).
    last: usize,
}

// Lanes are indexed: the lane loops are what the compiler packs into registers.
#[allow(clippy::needless_range_loop)]
impl<const L: usize> ElementBatch<L> {
    /// A batch with every quantity zero.
    fn new() -> Self {
        let lanes = [0.0; L];
        Self {
            tx: lanes,
            ty: lanes,
            tz: lanes,
            strain: lanes,
            tension: lanes,
            root_stretch: lanes,
            ftx: lanes,
            fty: lanes,
            ftz: lanes,
            weight_a: lanes,
            weight_b: lanes,
            drag_a: [[lanes; 3]; 2],
            drag_b: [[lanes; 3]; 2],
            node: [[lanes; 3]; 4],
            last: 0,
        }
    }

    /// Evaluates the elements whose nodes are `r` [m] moving at `v` [m/s] (element l from
    /// node l to node l + 1, at most `L` of them; lanes past the last element repeat
    /// it), of section `sec` with constants `k`, on a line paid out at `length_rate` [1/s]
    /// (ε̇ = t·(v_b − v_a)/L0 − σ(1 + ε), [`Mesh::length_rate`]). With Morison drag, in
    /// `still_water` its drag too, else the node lanes kept in the batch for
    /// [`ElementBatch::fluid_drag`].
    #[inline(always)]
    fn evaluate(
        &mut self,
        k: &SectionConstants,
        sec: &SectionProperties,
        length_rate: Real,
        r: &[Vec3],
        v: &[Vec3],
        still_water: bool,
    ) {
        let last = r.len() - 2;
        self.last = last.min(L - 1);
        // Each lane's two nodes, component by component, built from the nodes straight into
        // locals (element l.min(last) in lane l): written into the batch first and read back
        // as whole registers, the narrow stores stall the wide loads (store forwarding).
        let lane = |p: &[Vec3], node: usize, c: usize| -> [Real; L] {
            std::array::from_fn(|l| p[l.min(last) + node][c])
        };
        let (xa, ya, za) = (lane(r, 0, 0), lane(r, 0, 1), lane(r, 0, 2));
        let (xb, yb, zb) = (lane(r, 1, 0), lane(r, 1, 1), lane(r, 1, 2));
        let (vxa, vya, vza) = (lane(v, 0, 0), lane(v, 0, 1), lane(v, 0, 2));
        let (vxb, vyb, vzb) = (lane(v, 1, 0), lane(v, 1, 1), lane(v, 1, 2));
        if k.morison.is_some() && !still_water {
            self.node = [[xa, ya, za], [xb, yb, zb], [vxa, vya, vza], [vxb, vyb, vzb]];
        }
        let il = sec.inverse_length;
        let mut rate = [0.0; L];
        for l in 0..L {
            let (dx, dy, dz) = (xb[l] - xa[l], yb[l] - ya[l], zb[l] - za[l]);
            let length = (dx * dx + dy * dy + dz * dz).sqrt();
            let inverse = 1.0 / length;
            let (tx, ty, tz) = (dx * inverse, dy * inverse, dz * inverse);
            let strain = length * il - 1.0;
            let (dvx, dvy, dvz) = (vxb[l] - vxa[l], vyb[l] - vya[l], vzb[l] - vza[l]);
            rate[l] = (tx * dvx + ty * dvy + tz * dvz) * il - length_rate * (1.0 + strain);
            (self.tx[l], self.ty[l], self.tz[l]) = (tx, ty, tz);
            self.strain[l] = strain;
            self.root_stretch[l] = (1.0 + strain).max(0.0).sqrt();
        }
        let law = &sec.law;
        match law.stiffness {
            // AxialLaw::tension for a linear law, without its branches.
            AxialStiffness::Linear(ea) => {
                for l in 0..L {
                    let strain = self.strain[l];
                    let elastic = if strain > 0.0 || law.compression {
                        ea * strain
                    } else {
                        0.0
                    };
                    self.tension[l] = elastic + law.damping * rate[l];
                }
            }
            AxialStiffness::Table { .. } => {
                for l in 0..L {
                    self.tension[l] = law.tension(self.strain[l], rate[l]);
                }
            }
        }
        for l in 0..L {
            let (sub_a, sub_b) = submerged_shape_integrals(za[l], zb[l]);
            self.weight_a[l] = k.buoyancy * sub_a - k.weight;
            self.weight_b[l] = k.buoyancy * sub_b - k.weight;
        }
        for l in 0..L {
            let tension = self.tension[l];
            self.ftx[l] = self.tx[l] * tension;
            self.fty[l] = self.ty[l] * tension;
            self.ftz[l] = self.tz[l] * tension;
        }
        let Some((normal, tangential)) = k.morison.filter(|_| still_water) else {
            return;
        };
        for (g, xi) in GAUSS.into_iter().enumerate() {
            let (na, nb) = (1.0 - xi, xi);
            let (wa, wb) = (k.half_length * na, k.half_length * nb);
            for l in 0..L {
                let (tx, ty, tz) = (self.tx[l], self.ty[l], self.tz[l]);
                let z = za[l] * na + zb[l] * nb;
                // The relative velocity −(v_a N_a + v_b N_b) of the fluid at rest.
                let rx = -(vxa[l] * na + vxb[l] * nb);
                let ry = -(vya[l] * na + vyb[l] * nb);
                let rz = -(vza[l] * na + vzb[l] * nb);
                let factor = k.drag_factor[fluid_index(z)];
                let q = factor * self.root_stretch[l];
                let f = morison_lane((normal, tangential), q, [tx, ty, tz], [rx, ry, rz]);
                for c in 0..3 {
                    self.drag_a[g][c][l] = f[c] * wa;
                    self.drag_b[g][c][l] = f[c] * wb;
                }
            }
        }
    }

    /// The fluid load in moving water at both Gauss points, times each node's share of the
    /// Gauss weight, into `drag_a` and `drag_b`: what [`fluid_load`] computes there, lane by
    /// lane but for the fluid's kinematics (one call a point, `fluid` at the line's point
    /// `first_point` + 2 l + g for lane l and Gauss point g, as [`fluid_load`] is called):
    /// Morison drag on the relative velocity u c_f − v (c_f `current_factor`) with the
    /// point's fluid density, plus the Froude–Krylov and added-mass force of the fluid's
    /// acceleration a_w, ρ A ((1 + C_an) a_w,n + C_at a_w,t) (DG paper eq. 13), in the
    /// operations of [`fluid_inertia_force`] (zero, and kept for the same bits, in a steady
    /// current). A depth-profile current without waves, taken at the points themselves, is
    /// looked up here ([`profile_at`]).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn fluid_drag(
        &mut self,
        k: &SectionConstants,
        env: &Environment,
        fluid: &FluidPoints,
        first_point: usize,
        area: Real,
        added_mass: (Real, Real),
        time: Real,
        current_factor: Real,
    ) {
        let Some((normal, tangential)) = k.morison else {
            return;
        };
        let [[xa, ya, za], [xb, yb, zb], [vxa, vya, vza], [vxb, vyb, vzb]] = &self.node;
        let (can, cat) = added_mass;
        // The lanes past the batch's last element repeat it (`evaluate`).
        let last = self.last;
        for (g, xi) in GAUSS.into_iter().enumerate() {
            let (na, nb) = (1.0 - xi, xi);
            let (wa, wb) = (k.half_length * na, k.half_length * nb);
            let mut u = [[0.0; L]; 3];
            let mut acceleration = [[0.0; L]; 3];
            match &env.current {
                Current::Profile { z: zs, velocity }
                    if env.waves.is_none() && matches!(fluid, FluidPoints::Direct) =>
                {
                    // [`Environment::fluid_kinematics`] of a depth profile without waves, its
                    // profile lookup inlined here: the current's velocity plus the waves' zero
                    // under water, nothing in the air; no acceleration.
                    for l in 0..L {
                        let z = za[l] * na + zb[l] * nb;
                        let profile = profile_at(zs, velocity, z);
                        for c in 0..3 {
                            u[c][l] = if z < 0.0 { profile[c] + 0.0 } else { 0.0 };
                        }
                    }
                }
                _ => {
                    for l in 0..L {
                        let z = za[l] * na + zb[l] * nb;
                        let point = Vec3::new(xa[l] * na + xb[l] * nb, ya[l] * na + yb[l] * nb, z);
                        let index = first_point + 2 * l.min(last) + g;
                        let (velocity, a) = fluid.kinematics(env, index, &point, time);
                        for c in 0..3 {
                            u[c][l] = velocity[c];
                            acceleration[c][l] = a[c];
                        }
                    }
                }
            }
            for l in 0..L {
                let (tx, ty, tz) = (self.tx[l], self.ty[l], self.tz[l]);
                let z = za[l] * na + zb[l] * nb;
                let rx = u[0][l] * current_factor - (vxa[l] * na + vxb[l] * nb);
                let ry = u[1][l] * current_factor - (vya[l] * na + vyb[l] * nb);
                let rz = u[2][l] * current_factor - (vza[l] * na + vzb[l] * nb);
                let density = env.fluid_density(z);
                let q = k.drag_factor[fluid_index(z)] * self.root_stretch[l];
                let drag = morison_lane((normal, tangential), q, [tx, ty, tz], [rx, ry, rz]);
                // `fluid_inertia_force`: a_t = t (a·t), a_n = a − a_t.
                let [ax, ay, az] = [acceleration[0][l], acceleration[1][l], acceleration[2][l]];
                let along = ax * tx + ay * ty + az * tz;
                let inertia = |t: Real, a: Real| {
                    let at = t * along;
                    density * area * ((1.0 + can) * (a - at) + cat * at)
                };
                let f = [
                    drag[0] + inertia(tx, ax),
                    drag[1] + inertia(ty, ay),
                    drag[2] + inertia(tz, az),
                ];
                for c in 0..3 {
                    self.drag_a[g][c][l] = f[c] * wa;
                    self.drag_b[g][c][l] = f[c] * wb;
                }
            }
        }
    }

    /// The forces on the first `count` elements' first nodes into `forces` [N], from
    /// `carried`, the sum on the first node of the earlier elements' contributions; returns
    /// that sum for the node after the last element. The terms of tension, weight and
    /// buoyancy and drag (with Morison drag in the batch) are added in the order of
    /// [`line_forces`]' element loop, lane l summing node l's: first element l − 1's
    /// contributions (−T t, its weight, its two Gauss points), then element l's.
    #[inline(always)]
    fn sum_nodes(&self, carried: Vec3, forces: &mut [Vec3], count: usize) -> Vec3 {
        // Each element's contributions to its second node, from zero.
        let mut second = [[0.0; L]; 3];
        let ft = [&self.ftx, &self.fty, &self.ftz];
        for c in 0..3 {
            for l in 0..L {
                let mut f = 0.0 - ft[c][l];
                if c == 2 {
                    f += self.weight_b[l];
                }
                f += self.drag_b[0][c][l];
                f += self.drag_b[1][c][l];
                second[c][l] = f;
            }
        }
        // Node l starts from element l − 1's (the carried sum for l = 0).
        let mut node = [[0.0; L]; 3];
        for c in 0..3 {
            node[c][0] = carried[c];
            node[c][1..].copy_from_slice(&second[c][..L - 1]);
            for l in 0..L {
                let mut f = node[c][l] + ft[c][l];
                if c == 2 {
                    f += self.weight_a[l];
                }
                f += self.drag_a[0][c][l];
                f += self.drag_a[1][c][l];
                node[c][l] = f;
            }
        }
        for (l, f) in forces[..count].iter_mut().enumerate() {
            *f = Vec3::new(node[0][l], node[1][l], node[2][l]);
        }
        let last = count - 1;
        Vec3::new(second[0][last], second[1][last], second[2][last])
    }
}

/// Morison's drag per unit unstretched length [N/m] (DG paper eq. 17) at one point of one
/// lane: q (C_dn |v_n| v_n + C_dt |v_t| v_t) for the relative velocity `r` [m/s] split along
/// the unit tangent `t`, q = ½ ρ d √(1+ε) [kg/m²] and (C_dn, C_dt) `coefficients`; the
/// operations of [`drag_force_with_factor`], written out so that the lanes pack.
#[inline(always)]
fn morison_lane(coefficients: (Real, Real), q: Real, t: [Real; 3], r: [Real; 3]) -> [Real; 3] {
    let (normal, tangential) = coefficients;
    let [tx, ty, tz] = t;
    let [rx, ry, rz] = r;
    let vt = rx * tx + ry * ty + rz * tz;
    let (nx, ny, nz) = (rx - tx * vt, ry - ty * vt, rz - tz * vt);
    let vn = (nx * nx + ny * ny + nz * nz).sqrt();
    let (cn, ct) = (normal * vn, tangential * vt.abs());
    [
        q * (cn * nx + ct * (tx * vt)),
        q * (cn * ny + ct * (ty * vt)),
        q * (cn * nz + ct * (tz * vt)),
    ]
}

/// The index of the fluid at height z [m] in [`SectionConstants`]' pairs: 0 in water (z < 0),
/// 1 in air.
#[inline(always)]
fn fluid_index(z: Real) -> usize {
    usize::from(!(z < 0.0))
}

/// Adds element e's consistent mass blocks [kg] into `b` (see [`line_forces`]), starting
/// from zero each block it is the first element to add to.
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
    // Element e is the first to add to node e + 1's block and to the pair between its
    // nodes, element 0 to node 0's too: each starts from zero here, as a clear pass would.
    if e == 0 {
        b.diag[0] = Mat3::zeros();
    }
    b.diag[e + 1] = Mat3::zeros();
    b.lower[e] = Mat3::zeros();
    b.upper[e] = Mat3::zeros();
    if (za < 0.0) == (zb < 0.0) {
        // Uniform density: exact shape-function integrals, ∫NaNa = ∫NbNb = 1/3 and
        // ∫NaNb = 1/6.
        let third = k.element_mass(fluid_index(za), t, l0 / 3.0);
        b.diag[e] += third;
        b.diag[e + 1] += third;
        let sixth = third * 0.5;
        b.lower[e] += sixth;
        b.upper[e] += sixth;
    } else {
        // Crossing the surface: each Gauss point takes its own density.
        for &xi in &GAUSS {
            let (na, nb) = (1.0 - xi, xi);
            let m = k.element_mass(fluid_index(za * na + zb * nb), t, k.half_length);
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
        let (alpha, beta) = k.added_mass[fluid_index(za)];
        let c = (k.mass_per_length + alpha) * k.half_length;
        let b = beta * k.half_length;
        ([c, c], [b, b])
    } else {
        let (mut c, mut b) = ([0.0; 2], [0.0; 2]);
        for &xi in &GAUSS {
            let (alpha, beta) = k.added_mass[fluid_index(za * (1.0 - xi) + zb * xi)];
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
