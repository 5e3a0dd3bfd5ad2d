//! Cubic Hermite cable elements in absolute nodal coordinates (elastic-link paper §4).
//!
//! Each element of unstretched length l carries the positions and tangents of its two nodes,
//! e = (r_a, t_a, r_b, t_b) with t = ∂r/∂s along the unstretched arc length s, all in the
//! global frame (eq. 1, e = {r₀⁰ r₀¹ r_l⁰ r_l¹}). With ξ = s/l ∈ [0, 1] the position is
//! r(ξ) = s₁ r_a + s₂ t_a + s₃ r_b + s₄ t_b (eqs. 2–4) with the cubic Hermite functions
//!
//!   s₁ = 1 − 3ξ² + 2ξ³,  s₂ = l (ξ − 2ξ² + ξ³),  s₃ = 3ξ² − 2ξ³,  s₄ = l (−ξ² + ξ³),
//!
//! (the paper names them, our statement). Lagrange's equations (eq. 5) give M ë = Q (eq. 8):
//!
//! - mass (eqs. 9, 14): M_ij = ∫ s_i s_j (γ₀ I + m_a(τ)) ds. The structural part is the
//!   paper's constant matrix γ₀ l ∫ s_i s_j dξ ⊗ I; the added mass m_a = ρA (C_an (I − ττᵀ) +
//!   C_at ττᵀ) (SPEC §1) follows the tangent τ = r'/|r'| and is integrated with the same
//!   four-point Gauss rule, which is exact for the structural part (degree 6).
//! - weight and buoyancy as generalized forces (eqs. 10, 16–19): Q_i = ∫ s_i (−γ₀ g + ρ A g
//!   [z < 0]) ẑ ds, by Gauss quadrature (exact for a fully wet or dry element).
//! - axial strain energy (eqs. 11–15): U = ∫ ½ EA ε² ds, generalized to the axial law
//!   T(ε, ε̇) of SPEC §1 by δU = ∫ T δε ds. With the exact strain ε = |r'| − 1 (SPEC §1),
//!   δε = τ · δr' and Q_i = −∫ T τ s_i' ds, ε̇ = τ · ṙ'. The paper's small-strain form
//!   ε ≈ ½ (r'·r' − 1) (eq. 12) gives Q_i = −∫ T r' s_i' ds, ε̇ = r' · ṙ'; it is offered as
//!   [`StrainMeasure::SmallStrain`]. The paper writes Q^e = K^e(e) e (eqs. 13, 15); we
//!   evaluate the same integral directly at the Gauss points.
//! - bending (beyond the paper, which leaves it for future work): U_b = ∫ ½ EI |r''|² ds and
//!   a Kelvin–Voigt bending damping with moment ζ_b ṙ'', so Q_i = −∫ (EI r'' + ζ_b ṙ'') s_i''
//!   ds. |r''| is the curvature when |r'| = 1; for a stretched cable the error is O(ε) in the
//!   bending term, well below the uncertainty of EI for cables (the usual gradient-deficient
//!   ANCF cable element).
//! - Morison drag and fluid inertia (SPEC §1, the shared [`crate::physics::hydrodynamics`]),
//!   seabed contact (DG paper eqs. 15–16, [`crate::physics::seabed`]) and obstacle contact
//!   ([`crate::physics::obstacles`], [`obstacle_contacts`]) per unit unstretched length at the
//!   Gauss points, distributed with s_i.
//!
//! - on a winch (docs/winches.md) the element length l scales with the line, and s₂, s₄ (∝ l),
//!   s₁', s₃' (∝ 1/l) and the second derivatives change with it: the rates of r, r' and r''
//!   at fixed ξ gain σ (s₂ t_a + s₄ t_b), −σ (s₁' r_a + s₃' r_b) and
//!   −σ (2 s₁'' r_a + 2 s₃'' r_b + s₂'' t_a + s₄'' t_b), σ = L̇/L ([`Mesh::length_rate`]).
//!
//! The element couples the four consecutive vectors of its nodes (see
//! [`vector_index`]), so the line's matrices are block-banded with bandwidth 3.

use super::{ElementState, LoadOptions, Mesh};
use crate::formulation::fluid_load;
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3};
use crate::model::StrainMeasure;
use crate::physics::environment::Environment;
use crate::physics::hydrodynamics::added_mass_coefficients;
use crate::physics::obstacles::{LineBall, Obstacle};

/// Options of a `hermite` line.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct HermiteOptions {
    /// Strain measure.
    pub strain: StrainMeasure,
}

/// Four-point Gauss–Legendre rule on [0, 1]: (ξ, weight), weights summing to 1. Exact for
/// polynomials of degree 7.
pub const GAUSS: [(Real, Real); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// Index of node `node`'s position (or tangent) among the 2N + 2 vectors of a line of N
/// elements: r_i → 2i and t_i → 2i + 1 for i < N; t_N → 2N and r_N → 2N + 1, so that the end
/// positions are the first and the last vector.
#[inline]
pub fn vector_index(node: usize, tangent: bool, elements: usize) -> usize {
    match (node == elements, tangent) {
        (false, false) => 2 * node,
        (false, true) => 2 * node + 1,
        (true, false) => 2 * elements + 1,
        (true, true) => 2 * elements,
    }
}

/// The vector indices of element e's (r_a, t_a, r_b, t_b).
#[inline]
pub fn element_vectors(e: usize, elements: usize) -> [usize; 4] {
    [
        vector_index(e, false, elements),
        vector_index(e, true, elements),
        vector_index(e + 1, false, elements),
        vector_index(e + 1, true, elements),
    ]
}

/// Shape functions and their first three derivatives with respect to s at ξ, for an element
/// of length l: (s_i, s_i', s_i'', s_i''').
#[inline]
pub fn shape(xi: Real, l: Real) -> ([Real; 4], [Real; 4], [Real; 4], [Real; 4]) {
    let x2 = xi * xi;
    let x3 = x2 * xi;
    let n = [
        1.0 - 3.0 * x2 + 2.0 * x3,
        l * (xi - 2.0 * x2 + x3),
        3.0 * x2 - 2.0 * x3,
        l * (-x2 + x3),
    ];
    let il = 1.0 / l;
    let d1 = [
        (-6.0 * xi + 6.0 * x2) * il,
        1.0 - 4.0 * xi + 3.0 * x2,
        (6.0 * xi - 6.0 * x2) * il,
        -2.0 * xi + 3.0 * x2,
    ];
    let d2 = [
        (-6.0 + 12.0 * xi) * il * il,
        (-4.0 + 6.0 * xi) * il,
        (6.0 - 12.0 * xi) * il * il,
        (-2.0 + 6.0 * xi) * il,
    ];
    let d3 = [
        12.0 * il * il * il,
        6.0 * il * il,
        -12.0 * il * il * il,
        6.0 * il * il,
    ];
    (n, d1, d2, d3)
}

#[inline]
fn combine(w: &[Real; 4], v: &[Vec3; 4]) -> Vec3 {
    v[0] * w[0] + v[1] * w[1] + v[2] * w[2] + v[3] * w[3]
}

/// Axial strain ε, its rate ε̇ and ∂ε/∂r' at a point with r' = `r1` and ṙ' = `v1`: exact,
/// ε = |r'| − 1, ε̇ = τ·ṙ', ∂ε/∂r' = τ; small strain, ε = ½(r'·r' − 1), ε̇ = r'·ṙ', ∂ε/∂r' = r'.
#[inline]
pub fn axial_strain(r1: &Vec3, v1: &Vec3, measure: StrainMeasure) -> (Real, Real, Vec3) {
    match measure {
        StrainMeasure::SmallStrain => (0.5 * (r1.norm_squared() - 1.0), r1.dot(v1), *r1),
        StrainMeasure::Exact => {
            let stretch = r1.norm();
            let tau = r1 / stretch;
            (stretch - 1.0, tau.dot(v1), tau)
        }
    }
}

/// Mechanical energy of element e [J]: kinetic ½∫γ0|ṙ|² ds, weight ∫γ0 g z ds and strain
/// energy ∫ (W(ε) + ½ EI |r''|²) ds, W the axial law's energy density, by the same four-point
/// rule as the forces (whose gradient they are).
pub fn element_energy(
    mesh: &Mesh,
    options: &super::HermiteOptions,
    gravity: Real,
    q: &[Vec3],
    qdot: &[Vec3],
    e: usize,
) -> super::Energy {
    let n = mesh.elements();
    let s = mesh.section(e);
    let (l, gamma) = (s.element_length, s.line_type.mass_per_length);
    let idx = element_vectors(e, n);
    let qe = [q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]]];
    let ve = [qdot[idx[0]], qdot[idx[1]], qdot[idx[2]], qdot[idx[3]]];
    let mut energy = super::Energy::default();
    for (xi, weight) in GAUSS {
        let (sh, d1, d2, _) = shape(xi, l);
        let ds = weight * l;
        let r2 = combine(&d2, &qe);
        let (strain, _, _) = axial_strain(&combine(&d1, &qe), &Vec3::zeros(), options.strain);
        energy.kinetic += 0.5 * gamma * combine(&sh, &ve).norm_squared() * ds;
        energy.gravity += gamma * gravity * combine(&sh, &qe).z * ds;
        energy.elastic += (s.law.strain_energy_density(strain)
            + 0.5 * s.line_type.bending_stiffness * r2.norm_squared())
            * ds;
    }
    energy
}

/// Position r [m] and tangent vector ∂r/∂s [-] (its norm is the stretch 1 + ε) at ξ of
/// element e from the line's vectors `q`.
pub fn point_on_element(mesh: &Mesh, q: &[Vec3], e: usize, xi: Real) -> (Vec3, Vec3) {
    let n = mesh.elements();
    let idx = element_vectors(e, n);
    let qe = [q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]]];
    let (s, d1, _, _) = shape(xi, mesh.section(e).element_length);
    (combine(&s, &qe), combine(&d1, &qe))
}

/// Evaluates the generalized forces [N on positions, N·m on tangents] of a `hermite` line at
/// coordinates `q` and rates `qdot` (2N + 2 vectors, see [`vector_index`]), the element
/// results at each element's midpoint, and, if asked, its mass blocks [kg, kg·m, kg·m²].
#[allow(clippy::too_many_arguments)]
pub fn line_forces(
    mesh: &Mesh,
    options: &super::HermiteOptions,
    env: &Environment,
    time: Real,
    q: &[Vec3],
    qdot: &[Vec3],
    forces: &mut [Vec3],
    elements: &mut ElementState,
    blocks: Option<&mut LineBlocks>,
    load: LoadOptions,
) {
    let n = mesh.elements();
    forces[..2 * n + 2]
        .iter_mut()
        .for_each(|f| *f = Vec3::zeros());
    let g = env.gravity;
    let rho_w = env.water_density;
    let bed_top = env.seabed_top();
    let still_water = env.is_still_water();
    // σ = L̇/L of a line on a winch ([`Mesh::length_rate`]).
    let sigma = mesh.length_rate;
    let mut blocks = blocks;
    // The shape functions at the Gauss points and the derivatives at the midpoint, for the
    // element length they were taken at (the same for every element of a section).
    let mut shapes_length = Real::NAN;
    let mut shapes = [([0.0; 4], [0.0; 4], [0.0; 4]); 4];
    let mut midpoint = ([0.0; 4], [0.0; 4], [0.0; 4]);
    if let Some(b) = blocks.as_deref_mut() {
        b.clear();
    }
    for e in 0..n {
        let sec = mesh.section(e);
        let lt = &sec.line_type;
        let l = sec.element_length;
        let ei = lt.bending_stiffness;
        let zeta_b = lt.bending_damping;
        let bending = ei > 0.0 || zeta_b > 0.0;
        let idx = element_vectors(e, n);
        let qe = [q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]]];
        let ve = [qdot[idx[0]], qdot[idx[1]], qdot[idx[2]], qdot[idx[3]]];
        let mut fe = [Vec3::zeros(); 4];
        let mut element_mass = ElementMass::default();
        let net_weight = (rho_w * sec.area - lt.mass_per_length) * g;
        if l.to_bits() != shapes_length.to_bits() {
            shapes_length = l;
            for (sh, &(xi, _)) in shapes.iter_mut().zip(&GAUSS) {
                let (s, d1, d2, _) = shape(xi, l);
                *sh = (s, d1, d2);
            }
            let (_, d1, d2, d3) = shape(0.5, l);
            midpoint = (d1, d2, d3);
        }
        for (gp, &(_, wg)) in GAUSS.iter().enumerate() {
            let (s, d1, d2) = shapes[gp];
            let w = wg * l;
            let r = combine(&s, &qe);
            let r1 = combine(&d1, &qe);
            let mut v = combine(&s, &ve);
            let mut v1 = combine(&d1, &ve);
            if sigma != 0.0 {
                // On a winch l(t) = l(0) L(t)/L(0): the rates at fixed ξ of r = Σ s_i q_i and
                // r' = Σ s_i' q_i include ∂s_i/∂l l̇ (s₂, s₄ ∝ l; s₁', s₃' ∝ 1/l).
                v += (qe[1] * s[1] + qe[3] * s[3]) * sigma;
                v1 -= (qe[0] * d1[0] + qe[2] * d1[2]) * sigma;
            }
            let stretch = r1.norm();
            let tau = r1 / stretch;
            // Axial: Q_i −= ∫ T ∂ε/∂r' s_i' ds.
            let (strain, rate, direction) = axial_strain(&r1, &v1, options.strain);
            let tension = sec.law.tension(strain, rate);
            let axial = direction * (tension * w);
            for i in 0..4 {
                fe[i] -= axial * d1[i];
            }
            // Bending: Q_i −= ∫ (EI r'' + ζ_b ṙ'') s_i'' ds.
            if bending {
                let mut v2 = combine(&d2, &ve);
                if sigma != 0.0 {
                    // s₁'', s₃'' ∝ 1/l², s₂'', s₄'' ∝ 1/l.
                    v2 -= ((qe[0] * d2[0] + qe[2] * d2[2]) * 2.0 + qe[1] * d2[1] + qe[3] * d2[3])
                        * sigma;
                }
                let moment = (combine(&d2, &qe) * ei + v2 * zeta_b) * w;
                for i in 0..4 {
                    fe[i] -= moment * d2[i];
                }
            }
            // Distributed loads per unit unstretched length.
            let rho = env.fluid_density(r.z);
            let mut f = Vec3::new(0.0, 0.0, -lt.mass_per_length * g);
            if r.z < 0.0 {
                f.z += rho_w * sec.area * g;
            }
            f += fluid_load(
                env,
                &load.fluid,
                GAUSS.len() * e + gp,
                lt,
                sec.area,
                time,
                &r,
                &v,
                &tau,
                stretch.sqrt(),
                load.current_factor,
                still_water,
            );
            if r.z < bed_top {
                f += env.seabed_contact_force(
                    &r,
                    &v,
                    lt.diameter,
                    lt.mass_per_length,
                    stretch,
                    net_weight,
                    w,
                );
            }
            for i in 0..4 {
                fe[i] += f * (w * s[i]);
            }
            if blocks.is_some() {
                let (alpha, beta) = added_mass_coefficients(
                    rho,
                    sec.area,
                    lt.normal_added_mass,
                    lt.tangential_added_mass,
                );
                element_mass.add_gauss_point(&s, (lt.mass_per_length + alpha) * w, beta * w, &tau);
            }
        }
        if let Some(b) = blocks.as_deref_mut() {
            element_mass.add_to(b, &idx);
        }
        for i in 0..4 {
            forces[idx[i]] += fe[i];
        }
        // Element results at the midpoint.
        let (d1, d2, d3) = midpoint;
        let r1 = combine(&d1, &qe);
        let v1 = combine(&d1, &ve) - (qe[0] * d1[0] + qe[2] * d1[2]) * sigma;
        let r2 = combine(&d2, &qe);
        let stretch = r1.norm();
        let (strain, rate, direction) = axial_strain(&r1, &v1, options.strain);
        elements.strain[e] = strain;
        // The force along the line is T ∂ε/∂r' · τ: T for the exact strain, T |r'| for the
        // small strain (whose energy conjugate T is not the force).
        elements.tension[e] = sec.law.tension(strain, rate) * direction.dot(&(r1 / stretch));
        elements.curvature[e] = r1.cross(&r2).norm() / (stretch * stretch * stretch);
        elements.bending_moment[e] = (r2 * ei + combine(&d2, &ve) * zeta_b).norm();
        elements.shear_force[e] = (combine(&d3, &qe) * ei + combine(&d3, &ve) * zeta_b).norm();
    }
    // Obstacle contact at the same Gauss points, distributed with s_i.
    if !env.obstacles.is_empty() {
        obstacle_contacts(mesh, &env.obstacles, time, q, qdot, |_, idx, s, f, w| {
            for i in 0..4 {
                forces[idx[i]] += f * (w * s[i]);
            }
        });
    }
}

/// The pairs (i, j), i ≤ j, of an element's four vectors: the ten distinct blocks of its
/// symmetric mass matrix.
const MASS_PAIRS: [(usize, usize); 10] = [
    (0, 0),
    (0, 1),
    (0, 2),
    (0, 3),
    (1, 1),
    (1, 2),
    (1, 3),
    (2, 2),
    (2, 3),
    (3, 3),
];

/// One element's mass blocks summed over its Gauss points (eqs. 9, 14):
///
///   M_ij = ∫ s_i s_j (γ₀ I + m_a(τ)) ds = Σ_g s_i s_j [a_g I + b_g τ_g τ_gᵀ],
///
/// with a_g = (γ₀ + ρ A C_an) w_g [kg] and b_g = ρ A (C_at − C_an) w_g [kg], w_g the point's
/// weight times l (SPEC §1's added mass, m_a = ρA (C_an I + (C_at − C_an) ττᵀ)). Each of the
/// ten distinct blocks is a symmetric 3×3 matrix, kept as its isotropic part and the six
/// entries of its rank-one part, and added to blocks (i, j) and (j, i) alike, so the line's
/// matrix is symmetric to the bit. Where C_at = C_an (or the point is dry) the rank-one part
/// stays +0 exactly, so a line whose points stay wet or dry has the same blocks, bit for bit,
/// at every evaluation (and the solver reuses their factors: [`crate::linalg::BlockBandedLdl`]).
#[derive(Clone, Copy, Debug, Default)]
struct ElementMass {
    /// Σ_g a_g s_i s_j [kg, kg·m, kg·m²], per pair of [`MASS_PAIRS`].
    isotropic: [Real; 10],
    /// Σ_g b_g s_i s_j τ τᵀ: xx, xy, xz, yy, yz, zz, per pair.
    rank_one: [[Real; 6]; 10],
}

impl ElementMass {
    /// Adds Gauss point g with shape values `s`, a_g = `isotropic` and b_g = `rank_one` [kg]
    /// and unit tangent τ.
    #[inline(always)]
    fn add_gauss_point(&mut self, s: &[Real; 4], isotropic: Real, rank_one: Real, tau: &Vec3) {
        for (k, &(i, j)) in MASS_PAIRS.iter().enumerate() {
            self.isotropic[k] += isotropic * (s[i] * s[j]);
        }
        if rank_one != 0.0 {
            let (bx, by, bz) = (rank_one * tau.x, rank_one * tau.y, rank_one * tau.z);
            let p = [
                bx * tau.x,
                bx * tau.y,
                bx * tau.z,
                by * tau.y,
                by * tau.z,
                bz * tau.z,
            ];
            for (k, &(i, j)) in MASS_PAIRS.iter().enumerate() {
                let sij = s[i] * s[j];
                for (m, p) in self.rank_one[k].iter_mut().zip(p) {
                    *m += p * sij;
                }
            }
        }
    }

    /// Adds the element's blocks to the line's at its vectors `idx`.
    #[inline(always)]
    fn add_to(&self, blocks: &mut LineBlocks, idx: &[usize; 4]) {
        for (k, &(i, j)) in MASS_PAIRS.iter().enumerate() {
            let (a, [xx, xy, xz, yy, yz, zz]) = (self.isotropic[k], self.rank_one[k]);
            let m = Mat3::new(a + xx, xy, xz, xy, a + yy, yz, xz, yz, a + zz);
            *blocks.block_mut(idx[i], idx[j]) += m;
            if i != j {
                *blocks.block_mut(idx[j], idx[i]) += m;
            }
        }
    }
}

/// The Bézier control points r_a, r_a + t_a l/3, r_b − t_b l/3, r_b of element e's cubic
/// (with `qe` its r_a, t_a, r_b, t_b): the curve lies in their convex hull.
#[inline]
fn control_points(qe: &[Vec3; 4], l: Real) -> [Vec3; 4] {
    [
        qe[0],
        qe[0] + qe[1] * (l / 3.0),
        qe[2] - qe[3] * (l / 3.0),
        qe[2],
    ]
}

/// Contact of a `hermite` line with `obstacles` at time `time` [s], at the four Gauss points
/// of every element (those of the distributed loads and the seabed): at each point in contact
/// the force per unit unstretched length f [N/m] ([`Obstacle::contact_force`] with the
/// stretch |r'|) is passed to `visit(obstacle, vectors, s, f, w)` with the element's vector
/// indices, the shape functions s_i there and the quadrature weight w [m], so that vector
/// `vectors[i]` receives the generalized force f·w·s_i. The total force on the line is the sum
/// of f·w (s₁ + s₃ = 1 and the tangents' functions carry moments). An obstacle is skipped for
/// the line, and then for an element, when it cannot reach a ball holding the Bézier control
/// points ([`Obstacle::may_touch`]), which hold the curve. The dynamics ([`line_forces`]) and
/// the obstacle channels ([`crate::analysis::obstacles`]) both use this function.
pub fn obstacle_contacts(
    mesh: &Mesh,
    obstacles: &[Obstacle],
    time: Real,
    q: &[Vec3],
    qdot: &[Vec3],
    mut visit: impl FnMut(usize, &[usize; 4], &[Real; 4], Vec3, Real),
) {
    let n = mesh.elements();
    let element = |e: usize| {
        let idx = element_vectors(e, n);
        (idx, [q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]]])
    };
    let mut bounds = LineBall::new();
    let mut cable_radius: Real = 0.0;
    for e in 0..n {
        let sec = mesh.section(e);
        let (_, qe) = element(e);
        control_points(&qe, sec.element_length)
            .iter()
            .for_each(|p| bounds.add(p));
        cable_radius = cable_radius.max(0.5 * sec.line_type.diameter);
    }
    let (centre, radius) = bounds.ball();
    for (k, obstacle) in obstacles.iter().enumerate() {
        let kin = obstacle.kinematics(time);
        if !obstacle.may_touch(&kin, &centre, radius + cable_radius) {
            continue;
        }
        for e in 0..n {
            let sec = mesh.section(e);
            let lt = &sec.line_type;
            let l = sec.element_length;
            let (idx, qe) = element(e);
            let mut ball = LineBall::new();
            control_points(&qe, l).iter().for_each(|p| ball.add(p));
            let (c, rad) = ball.ball();
            if !obstacle.may_touch(&kin, &c, rad + 0.5 * lt.diameter) {
                continue;
            }
            let ve = [qdot[idx[0]], qdot[idx[1]], qdot[idx[2]], qdot[idx[3]]];
            for &(xi, wg) in &GAUSS {
                let (s, d1, _, _) = shape(xi, l);
                let r = combine(&s, &qe);
                if let Some(p) = obstacle.penetration(&kin, &r, lt.diameter) {
                    let v = combine(&s, &ve);
                    let stretch = combine(&d1, &qe).norm();
                    let f = obstacle.contact_force(&kin, &p, &v, lt.mass_per_length, stretch);
                    visit(k, &idx, &s, f, wg * l);
                }
            }
        }
    }
}

/// λ_max(K, M) of the element's scalar axial (K = ∫ s_i' s_j' ds, M = ∫ s_i s_j ds) and
/// bending (K = ∫ s_i'' s_j'' ds) pencils for l = 1, with both end vectors free: by the
/// element eigenvalue bound (Irons), the assembled line's highest frequency is at most
/// √(λ_axial EA/γ) / l and √(λ_bending EI/γ) / l² with these constants. Computed once from
/// the shape functions.
pub fn element_eigenvalue_bounds() -> (Real, Real) {
    use nalgebra::Matrix4;
    let mut m = Matrix4::<Real>::zeros();
    let mut ka = Matrix4::<Real>::zeros();
    let mut kb = Matrix4::<Real>::zeros();
    for &(xi, w) in &GAUSS {
        let (s, d1, d2, _) = shape(xi, 1.0);
        for i in 0..4 {
            for j in 0..4 {
                m[(i, j)] += w * s[i] * s[j];
                ka[(i, j)] += w * d1[i] * d1[j];
                kb[(i, j)] += w * d2[i] * d2[j];
            }
        }
    }
    let chol = m
        .cholesky()
        .expect("the Hermite mass matrix is positive definite");
    let l_inv = chol.l().try_inverse().expect("invertible");
    let top = |k: &Matrix4<Real>| {
        let a = l_inv * k * l_inv.transpose();
        a.symmetric_eigenvalues().max()
    };
    (top(&ka), top(&kb))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formulation::ElementState;

    #[test]
    fn structural_mass_is_the_classical_beam_matrix() {
        // γ l / 420 [156 22l 54 −13l; 22l 4l² 13l −3l²; 54 13l 156 −22l; −13l −3l² −22l 4l²].
        let l = 2.0;
        let exact = [
            [156.0, 22.0 * l, 54.0, -13.0 * l],
            [22.0 * l, 4.0 * l * l, 13.0 * l, -3.0 * l * l],
            [54.0, 13.0 * l, 156.0, -22.0 * l],
            [-13.0 * l, -3.0 * l * l, -22.0 * l, 4.0 * l * l],
        ];
        for i in 0..4 {
            for j in 0..4 {
                let m: Real = GAUSS
                    .iter()
                    .map(|&(xi, w)| {
                        let (s, _, _, _) = shape(xi, l);
                        w * l * s[i] * s[j]
                    })
                    .sum();
                assert!((m - exact[i][j] * l / 420.0).abs() < 1e-13, "{i}{j}");
            }
        }
    }

    #[test]
    fn shape_functions_interpolate_cubics_exactly() {
        // r(s) = s³ − 2s + 1 on an element of length 1.5 from its end values and slopes.
        let l = 1.5;
        let f = |s: Real| s * s * s - 2.0 * s + 1.0;
        let df = |s: Real| 3.0 * s * s - 2.0;
        let e = [f(0.0), df(0.0), f(l), df(l)];
        for k in 0..=10 {
            let xi = k as Real / 10.0;
            let (s, d1, d2, d3) = shape(xi, l);
            let dot = |w: [Real; 4]| w.iter().zip(e.iter()).map(|(a, b)| a * b).sum::<Real>();
            let x = xi * l;
            assert!((dot(s) - f(x)).abs() < 1e-13);
            assert!((dot(d1) - df(x)).abs() < 1e-13);
            assert!((dot(d2) - 6.0 * x).abs() < 1e-12);
            assert!((dot(d3) - 6.0).abs() < 1e-12);
        }
    }

    #[test]
    fn vector_order_puts_the_end_positions_at_the_ends() {
        let n = 3;
        assert_eq!(vector_index(0, false, n), 0);
        assert_eq!(vector_index(n, false, n), 2 * n + 1);
        let mut all: Vec<usize> = (0..=n)
            .flat_map(|i| [vector_index(i, false, n), vector_index(i, true, n)])
            .collect();
        all.sort();
        assert_eq!(all, (0..2 * n + 2).collect::<Vec<_>>());
        for e in 0..n {
            let v = element_vectors(e, n);
            let (lo, hi) = (v.iter().min().unwrap(), v.iter().max().unwrap());
            assert_eq!(hi - lo, 3, "element {e} spans four consecutive vectors");
        }
    }

    /// The mass blocks `line_forces` assembles (per element, [`ElementMass`]) are the
    /// quadrature of eqs. 9, 14 with SPEC §1's added mass, symmetric to the bit, and, with
    /// C_at = C_an on a line that stays wet, the same bits in any shape; with C_at ≠ C_an they
    /// turn with the tangents. 1e-12 relative: the reference sums the same products in
    /// another order (round-off of a few ulps of the largest block entry).
    #[test]
    fn mass_blocks_are_the_quadrature_and_constant_when_isotropic() {
        use crate::linalg::EndKind;
        use crate::physics::hydrodynamics::added_mass_matrix;
        let n = 4;
        let env = Environment {
            depth: 200.0,
            ..Environment::default()
        };
        // Two shapes of a 40 m line, wholly below the water (one end 1 m under it).
        let shape_of = |bend: Real| -> Vec<Vec3> {
            let mut q = vec![Vec3::zeros(); 2 * n + 2];
            for i in 0..=n {
                let a = bend * i as Real / n as Real;
                let r = Vec3::new(10.0 * i as Real, 2.0 * a.sin(), -41.0 + 10.0 * i as Real);
                let t = Vec3::new(1.0, bend * a.cos(), 1.0).normalize() * 1.001;
                q[vector_index(i, false, n)] = r;
                q[vector_index(i, true, n)] = t;
            }
            q
        };
        let blocks_at = |lt: &crate::model::LineType, q: &[Vec3]| {
            let mesh = Mesh::new(&[(lt.clone(), 40.0, n)]);
            let mut blocks = LineBlocks::banded(2 * n + 2, 3, EndKind::Known, EndKind::Known, true);
            let mut forces = vec![Vec3::zeros(); q.len()];
            let mut elements = ElementState::new(n);
            line_forces(
                &mesh,
                &HermiteOptions::default(),
                &env,
                0.0,
                q,
                &vec![Vec3::zeros(); q.len()],
                &mut forces,
                &mut elements,
                Some(&mut blocks),
                LoadOptions::direct(1.0),
            );
            // The reference: Σ_e Σ_g w s_i s_j (γ₀ I + m_a(τ)), block by block.
            let mut reference = vec![vec![Mat3::zeros(); 2 * n + 2]; 2 * n + 2];
            for e in 0..n {
                let idx = element_vectors(e, n);
                for (xi, wg) in GAUSS {
                    let (s, _, _, _) = shape(xi, 10.0);
                    let (r, r1) = point_on_element(&mesh, q, e, xi);
                    let m = added_mass_matrix(
                        env.fluid_density(r.z),
                        mesh.section(e).area,
                        lt.normal_added_mass,
                        lt.tangential_added_mass,
                        &r1.normalize(),
                    ) + Mat3::identity() * lt.mass_per_length;
                    for i in 0..4 {
                        for j in 0..4 {
                            reference[idx[i]][idx[j]] += m * (wg * 10.0 * s[i] * s[j]);
                        }
                    }
                }
            }
            let scale = reference
                .iter()
                .flatten()
                .map(|b| b.amax())
                .fold(0.0, Real::max);
            for (i, row) in reference.iter().enumerate() {
                for (j, want) in row.iter().enumerate() {
                    let got = blocks.block(i, j);
                    assert!((got - want).amax() < 1e-12 * scale, "block ({i}, {j})");
                }
            }
            assert!(blocks.interior_is_symmetric());
            blocks.blocks().copied().collect::<Vec<_>>()
        };
        let bits = |b: &[Mat3]| {
            b.iter()
                .flat_map(|m| m.iter().map(|x| x.to_bits()))
                .collect::<Vec<_>>()
        };
        let mut lt = crate::verification::line_type(0.09, 77.7, 3.8e8);
        for (normal, tangential) in [(1.0, 1.0), (1.0, 0.0)] {
            lt.normal_added_mass = normal;
            lt.tangential_added_mass = tangential;
            let (straight, bent) = (
                blocks_at(&lt, &shape_of(0.0)),
                blocks_at(&lt, &shape_of(0.7)),
            );
            assert_eq!(
                bits(&straight) == bits(&bent),
                normal == tangential,
                "C_an {normal}, C_at {tangential}"
            );
        }
    }

    /// The element bounds hold for an assembled free–free chain of elements, for the axial
    /// (second-order) and bending (fourth-order) pencils, and are within a factor 2.5 of its
    /// top eigenvalue (measured 91.2 against 170.1 and 3586 against 8400: the guaranteed
    /// bound costs a factor 1.4 to 1.5 in the step).
    #[test]
    fn eigenvalue_bounds_bound_an_assembled_chain() {
        use nalgebra::DMatrix;
        let (axial, bending) = element_eigenvalue_bounds();
        let n = 16;
        let dim = 2 * n + 2;
        let (mut m, mut ka, mut kb) = (
            DMatrix::<Real>::zeros(dim, dim),
            DMatrix::<Real>::zeros(dim, dim),
            DMatrix::<Real>::zeros(dim, dim),
        );
        for e in 0..n {
            for &(xi, w) in &GAUSS {
                let (s, d1, d2, _) = shape(xi, 1.0);
                for i in 0..4 {
                    for j in 0..4 {
                        m[(2 * e + i, 2 * e + j)] += w * s[i] * s[j];
                        ka[(2 * e + i, 2 * e + j)] += w * d1[i] * d1[j];
                        kb[(2 * e + i, 2 * e + j)] += w * d2[i] * d2[j];
                    }
                }
            }
        }
        let l = m.cholesky().unwrap().l();
        let li = l.try_inverse().unwrap();
        let top = |k: &DMatrix<Real>| {
            (&li * k * li.transpose())
                .symmetric_eigen()
                .eigenvalues
                .max()
        };
        let (ca, cb) = (top(&ka), top(&kb));
        eprintln!(
            "axial: chain {ca:.3}, bound {axial:.3}; bending: chain {cb:.1}, bound {bending:.1}"
        );
        assert!(
            ca <= axial * (1.0 + 1e-12) && ca > 0.4 * axial,
            "{ca} vs {axial}"
        );
        assert!(
            cb <= bending * (1.0 + 1e-12) && cb > 0.4 * bending,
            "{cb} vs {bending}"
        );
    }
}
