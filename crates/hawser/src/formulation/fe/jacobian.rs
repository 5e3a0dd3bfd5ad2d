//! The Jacobian of an `fe` line's nodal forces in closed form: ∂F/∂r [N/m] and ∂F/∂v
//! [N·s/m] over its nodes 0..=N, for the Newton iterations of the implicit scheme
//! ([`crate::integrate::GeneralizedAlpha`]).
//!
//! Differentiated term by term from what [`super::line_forces`] evaluates (our derivation;
//! the position-vector paper gives the forces, eqs. 13–25, not their derivatives). For an
//! element from node a to node b, d = r_b − r_a, ℓ = |d|, t = d/ℓ, ε = ℓ/L0 − 1,
//! ε̇ = t·(v_b − v_a)/L0 − σ(1 + ε), and P = (I − t tᵀ)/ℓ = ∂t/∂r_b:
//!
//! - tension, F_a = T t = −F_b: ∂(T t)/∂r_b = t ∂T/∂r_b + T P with
//!   ∂T/∂r_b = (T_e'(ε) − c σ) tᵀ/L0 + c (P Δv)ᵀ/L0, and ∂(T t)/∂v_b = (c/L0) t tᵀ
//!   (c the axial damping coefficient [N·s], T_e' the elastic tangent, zero where a cable
//!   without compression is slack); the derivatives by r_a and v_a are their negatives;
//! - weight and buoyancy: constant but for an element crossing the surface, whose submerged
//!   shape integrals move with the crossing ξ* = z_a/(z_a − z_b);
//! - Morison drag at each Gauss point, f = q (C_dn |u_n| u_n + C_dt |u_t| u_t t) with the
//!   relative velocity u = c_f U − v (U the current, v interpolated), u_t = t·u,
//!   u_n = u − u_t t, q = ½ ρ d √(1 + ε) and Π = I − t tᵀ: by the relative velocity
//!   ∂f/∂u = q (C_dn (|u_n| Π + u_n u_nᵀ/|u_n|) + 2 C_dt |u_t| t tᵀ); by the tangent
//!   ∂f/∂t = q (C_dn (−|u_n| (u_t I + t uᵀ) − u_t u_n u_nᵀ/|u_n|) + C_dt |u_t| (u_t I + 2 t uᵀ));
//!   by the stretch ∂f/∂ε = f / (2 (1 + ε));
//! - seabed contact at each node in contact, f = √(1+ε) (n (k d p − c_b v·n) − friction) with
//!   p the penetration (∂p/∂r = −nᵀ on the bed's tangent plane): ∂f/∂r = −√(1+ε) k d n nᵀ,
//!   ∂f/∂v = −√(1+ε) (c_b n nᵀ + ∂friction/∂v), the tanh friction μ N tanh(π s/v_μ) ŝ of the
//!   sliding velocity s ŝ differentiated exactly, and ∂f/∂ε = f / (2 (1 + ε)).
//!
//! Exact but for the current's variation with depth (a profile's ∂U/∂z is left out), so it
//! agrees with finite differences of the forces to their own error (test below). Where the
//! forces hold a term it does not cover (waves and a current that changes in time, whose
//! fluid inertia turns with the tangent; obstacles; drag loading functions; MoorDyn's viscous
//! friction) [`newton_jacobian`] declines and the caller takes finite differences.

use super::{GAUSS, SectionConstants, fluid_index};
use crate::formulation::{LoadOptions, Mesh};
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3};
use crate::physics::environment::{Current, Environment};
use crate::physics::hydrodynamics::DragModel;
use crate::physics::seabed::FrictionLaw;

/// Whether [`newton_jacobian`] covers every force term of a line of `mesh` in `env`.
pub fn covers(mesh: &Mesh, env: &Environment) -> bool {
    env.waves.is_none()
        && !matches!(env.current, Current::Table { .. })
        && env.obstacles.is_empty()
        && !(env.seabed.friction_coefficient > 0.0
            && matches!(env.seabed.friction_law, FrictionLaw::Viscous { .. }))
        && mesh
            .sections
            .iter()
            .all(|s| matches!(s.line_type.drag, DragModel::Morison { .. }))
}

/// Writes ∂F/∂r [N/m] into `position` and ∂F/∂v [N·s/m] into `velocity` (either may be
/// `None`), over the nodes 0..=N of the `fe` line of `mesh` at positions `r` [m] and
/// velocities `v` [m/s] at time `time` [s] (module doc), every block written (the blocks
/// marked coupled). Returns false, writing nothing, where it does not cover the line's
/// forces ([`covers`]).
#[allow(clippy::too_many_arguments)]
pub fn newton_jacobian(
    mesh: &Mesh,
    env: &Environment,
    time: Real,
    r: &[Vec3],
    v: &[Vec3],
    options: LoadOptions,
    mut position: Option<&mut LineBlocks>,
    mut velocity: Option<&mut LineBlocks>,
) -> bool {
    if !covers(mesh, env) {
        return false;
    }
    for b in [position.as_deref_mut(), velocity.as_deref_mut()]
        .into_iter()
        .flatten()
    {
        b.coupled = true;
        b.clear();
    }
    let n = mesh.elements();
    let still_water = env.is_still_water();
    let bed_top = env.seabed_top();
    let sigma = mesh.length_rate;
    let seabed = &env.seabed;
    for e in 0..n {
        let sec = mesh.section(e);
        let lt = &sec.line_type;
        // What `line_forces` takes per section: buoyancy, drag factors, contact damping, net
        // weight.
        let k = SectionConstants::new(sec, env);
        let (il, half) = (sec.inverse_length, k.half_length);
        let (ra, rb, va, vb) = (r[e], r[e + 1], v[e], v[e + 1]);
        let d = rb - ra;
        let length = d.norm();
        let t = d / length;
        let strain = length * il - 1.0;
        let dv = vb - va;
        let rate = t.dot(&dv) * il - sigma * (1.0 + strain);
        let law = &sec.law;
        let tension = law.tension(strain, rate);
        let elastic_tangent = if strain > 0.0 {
            law.stiffness.tension_and_tangent(strain).1
        } else if law.compression {
            law.stiffness.max_tangent()
        } else {
            0.0
        };
        let c = law.damping;
        let tt = t * t.transpose();
        let projector = Mat3::identity() - tt;
        let p = projector / length;
        // ∂ε/∂r_b = tᵀ/L0, and the stretch's share of forces proportional to √(1+ε):
        // ∂√(1+ε)/∂r_b / √(1+ε) = tᵀ / (2 (1+ε) L0).
        let stretch = 1.0 + strain;
        let root = stretch.max(0.0).sqrt();
        let per_stretch = if stretch > 0.0 {
            t.transpose() * (0.5 / stretch * il)
        } else {
            nalgebra::RowVector3::zeros()
        };
        // Column blocks of node b by r (node a's are their negatives), rows a and b.
        let mut row_a = Mat3::zeros();
        let mut row_b = Mat3::zeros();
        // By v: rows a and b, columns a and b.
        let mut va_a = Mat3::zeros();
        let mut vb_a = Mat3::zeros();
        let mut va_b = Mat3::zeros();
        let mut vb_b = Mat3::zeros();

        // Tension.
        let dt_dr =
            t.transpose() * ((elastic_tangent - c * sigma) * il) + (p * dv).transpose() * (c * il);
        let g = t * dt_dr + p * tension;
        row_a += g;
        row_b -= g;
        let gv = tt * (c * il);
        va_a -= gv;
        vb_a += gv;
        va_b += gv;
        vb_b -= gv;

        // Weight and buoyancy: only a crossing element's depends on the nodes' heights.
        let (za, zb) = (ra.z, rb.z);
        let mut heights = [[0.0; 2]; 2];
        if (za < 0.0 && zb > 0.0) || (za > 0.0 && zb < 0.0) {
            let gap = za - zb;
            let xs = za / gap;
            let dxs = [-zb / (gap * gap), za / (gap * gap)];
            // ∂(∫N_a, ∫N_b)/∂ξ* (fe.rs `submerged_shape_integrals`).
            let ds = if za < 0.0 {
                [1.0 - xs, xs]
            } else {
                [-(1.0 - xs), -xs]
            };
            for (row, s) in ds.iter().enumerate() {
                for (col, x) in dxs.iter().enumerate() {
                    heights[row][col] = k.buoyancy * s * x;
                }
            }
        }

        // Morison drag at the two Gauss points.
        if let Some((normal, tangential)) = k.morison {
            for (gi, &xi) in GAUSS.iter().enumerate() {
                let (na, nb) = (1.0 - xi, xi);
                let point = ra * na + rb * nb;
                let current = if still_water {
                    Vec3::zeros()
                } else {
                    let (u, _) = options.fluid.kinematics(env, 2 * e + gi, &point, time);
                    u * options.current_factor
                };
                let u = current - (va * na + vb * nb);
                let factor = k.drag_factor[fluid_index(point.z)];
                let q = factor * root;
                let ut = t.dot(&u);
                let un = u - t * ut;
                let un_size = un.norm();
                let drag = (un * (normal * un_size) + t * (tangential * ut.abs() * ut)) * q;
                // ∂f/∂t P = ∂f/∂t Π / ℓ, using Π u = u_n and u_nᵀ Π = u_nᵀ:
                // ((C_dt |u_t| − C_dn |u_n|) u_t Π + (2 C_dt |u_t| − C_dn |u_n|) t u_nᵀ
                //  − C_dn u_t u_n u_nᵀ/|u_n|) / ℓ.
                let (cn, ct) = (normal * un_size, tangential * ut.abs());
                let mut by_u = projector * cn + tt * (2.0 * ct);
                let mut by_tp = projector * ((ct - cn) * ut) + t * un.transpose() * (2.0 * ct - cn);
                if un_size > 0.0 {
                    let outer = un * un.transpose() / un_size;
                    by_u += outer * normal;
                    by_tp -= outer * (normal * ut);
                }
                let by_rb = by_tp * (q / length) + drag * per_stretch;
                let by_u = by_u * q;
                let (wa, wb) = (half * na, half * nb);
                row_a += by_rb * wa;
                row_b += by_rb * wb;
                // ∂u/∂v_a = −N_a I, ∂u/∂v_b = −N_b I.
                va_a -= by_u * (wa * na);
                vb_a -= by_u * (wa * nb);
                va_b -= by_u * (wb * na);
                vb_b -= by_u * (wb * nb);
            }
        }

        // Seabed contact at both nodes, each carrying half of the element.
        let mut contact_r = [Mat3::zeros(); 2];
        if ra.z < bed_top || rb.z < bed_top {
            let kd = seabed.stiffness * lt.diameter;
            let damping = k.seabed_damping;
            for (j, (x, w)) in [(ra, va), (rb, vb)].into_iter().enumerate() {
                let bed = env.seabed_at(x.x, x.y);
                let depth = bed.penetration(&x);
                if !(depth > 0.0) {
                    continue;
                }
                let nrm = bed.normal;
                let nn = nrm * nrm.transpose();
                let vn = w.dot(&nrm);
                let mut force = nrm * (root * (kd * depth - damping * vn));
                let mut by_v = nn * damping;
                let normal_load = -k.net_weight * nrm.z;
                if seabed.friction_coefficient > 0.0 && normal_load > 0.0 {
                    // μ N tanh(π s / v_μ) along the sliding direction ŝ, s = |v − (v·n) n|.
                    let slide = w - nrm * vn;
                    let speed = slide.norm();
                    let scale = std::f64::consts::PI / seabed.friction_velocity;
                    let limit = seabed.friction_coefficient * normal_load;
                    let slope = limit * scale / (scale * speed).cosh().powi(2);
                    let plane = Mat3::identity() - nn;
                    if speed > 0.0 {
                        let magnitude = seabed.friction(speed, normal_load, 1.0);
                        force -= slide * (root * magnitude / speed);
                        let along = slide / speed;
                        by_v += plane * (magnitude / speed)
                            + along * along.transpose() * (slope - magnitude / speed);
                    } else {
                        by_v += plane * slope;
                    }
                }
                let by_v = by_v * (-root * half);
                contact_r[j] = nn * (-root * kd * half);
                // Through the element's stretch (the whole contact force scales with √(1+ε)).
                let through_stretch = force * half * per_stretch;
                if j == 0 {
                    row_a += through_stretch;
                    va_a += by_v;
                } else {
                    row_b += through_stretch;
                    vb_b += by_v;
                }
            }
        }

        if let Some(b) = position.as_deref_mut() {
            // Columns: node b's blocks are row_*, node a's −row_*, plus the heights and the
            // contact on the diagonal.
            let mut aa = -row_a + contact_r[0];
            let mut bb = row_b + contact_r[1];
            let mut ab = row_a;
            let mut ba = -row_b;
            aa[(2, 2)] += heights[0][0];
            ab[(2, 2)] += heights[0][1];
            ba[(2, 2)] += heights[1][0];
            bb[(2, 2)] += heights[1][1];
            b.diag[e] += aa;
            b.upper[e] += ab;
            b.lower[e] += ba;
            b.diag[e + 1] += bb;
        }
        if let Some(b) = velocity.as_deref_mut() {
            b.diag[e] += va_a;
            b.upper[e] += vb_a;
            b.lower[e] += va_b;
            b.diag[e + 1] += vb_b;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formulation::{ElementState, LoadOptions};
    use crate::linalg::EndKind;
    use crate::model::MassMatrix;
    use crate::physics::material::{AxialDamping, AxialStiffness};
    use crate::physics::seabed::{Bathymetry, ContactDamping, Seabed};

    fn chain(drag: (Real, Real), stiffness: AxialStiffness) -> crate::model::LineType {
        crate::model::LineType {
            axial_stiffness: stiffness,
            axial_damping: AxialDamping::Coefficient(2.0e5),
            drag: DragModel::Morison {
                normal: drag.0,
                tangential: drag.1,
            },
            ..crate::verification::line_type(0.09, 77.7, 3.8e8)
        }
    }

    /// The forces of the line at (r, v), as `line_forces` evaluates them in the dynamics.
    fn forces(mesh: &Mesh, env: &Environment, r: &[Vec3], v: &[Vec3]) -> Vec<Vec3> {
        let mut f = vec![Vec3::zeros(); r.len()];
        let mut elements = ElementState::new(mesh.elements());
        super::super::line_forces(
            mesh,
            MassMatrix::Lumped,
            env,
            0.0,
            r,
            v,
            &mut f,
            &mut elements,
            None,
            LoadOptions::direct(1.0),
        );
        f
    }

    /// Central differences of the forces by positions (`by_velocity` false) or velocities,
    /// step `h` [m or m/s], as block (i, j) = ∂F_i/∂x_j.
    fn differences(
        mesh: &Mesh,
        env: &Environment,
        r: &[Vec3],
        v: &[Vec3],
        by_velocity: bool,
        h: Real,
    ) -> Vec<Vec<Mat3>> {
        let nodes = r.len();
        let mut out = vec![vec![Mat3::zeros(); nodes]; nodes];
        for j in 0..nodes {
            for k in 0..3 {
                let shifted = |by: Real| {
                    let (mut r, mut v) = (r.to_vec(), v.to_vec());
                    if by_velocity {
                        v[j][k] += by;
                    } else {
                        r[j][k] += by;
                    }
                    forces(mesh, env, &r, &v)
                };
                let (plus, minus) = (shifted(h), shifted(-h));
                for i in 0..nodes {
                    out[i][j].set_column(k, &((plus[i] - minus[i]) / (2.0 * h)));
                }
            }
        }
        out
    }

    /// Compares the closed form with central differences block by block: every entry within
    /// 1e-6 of its block's largest difference plus 1e-9 of the line's largest (the floor for
    /// blocks that are zero but for round-off), and every block outside the band zero.
    #[allow(clippy::needless_range_loop)] // blocks (i, j) of two tables
    fn check(mesh: &Mesh, env: &Environment, r: &[Vec3], v: &[Vec3], case: &str) {
        let nodes = r.len();
        let mut blocks = [false, true]
            .map(|_| LineBlocks::banded(nodes, 1, EndKind::Known, EndKind::Known, true));
        let [position, velocity] = &mut blocks;
        assert!(newton_jacobian(
            mesh,
            env,
            0.0,
            r,
            v,
            LoadOptions::direct(1.0),
            Some(position),
            Some(velocity),
        ));
        for (by_velocity, b) in [(false, &blocks[0]), (true, &blocks[1])] {
            // Steps: 1e-6 m against elements of 10 m and penetrations of centimetres;
            // 1e-6 m/s against the friction's v_μ/π = 3e-3 m/s and relative speeds of 0.1–2
            // m/s. Their truncation errors are (h/scale)² ≤ 1e-7 of each term.
            let fd = differences(mesh, env, r, v, by_velocity, 1e-6);
            let largest = fd.iter().flatten().map(|m| m.amax()).fold(0.0, Real::max);
            for i in 0..nodes {
                for j in 0..nodes {
                    let exact = if i.abs_diff(j) <= 1 {
                        b.block(i, j)
                    } else {
                        Mat3::zeros()
                    };
                    let error = (exact - fd[i][j]).amax();
                    let allowed = 1e-6 * fd[i][j].amax() + 1e-9 * largest;
                    assert!(
                        error <= allowed,
                        "{case}: block ({i}, {j}) by {}: {error:.3e} off (allowed {allowed:.3e})\n\
                         closed form {exact:.6e}\ndifferences {:.6e}",
                        if by_velocity { "v" } else { "r" },
                        fd[i][j]
                    );
                }
            }
        }
    }

    /// A deterministic spread of numbers in [−1, 1].
    fn wobble(i: usize, k: usize) -> Real {
        ((i * 7919 + k * 104_729) % 1000) as Real / 500.0 - 1.0
    }

    #[test]
    fn closed_form_matches_finite_differences() {
        // A taut line in a uniform current, two sections (linear, and a tension table), with
        // axial damping and Morison drag both ways, moving.
        let table = AxialStiffness::Table {
            strain: vec![0.0, 0.002, 0.01],
            tension: vec![0.0, 4.0e5, 3.0e6],
        };
        let mesh = Mesh::new(&[
            (chain((1.2, 0.3), AxialStiffness::Linear(3.8e8)), 40.0, 4),
            (chain((2.0, 0.5), table), 20.0, 2),
        ]);
        let env = Environment {
            depth: 200.0,
            current: Current::Uniform(Vec3::new(0.6, -0.3, 0.1)),
            ..Environment::default()
        };
        let r: Vec<Vec3> = (0..=6)
            .map(|i| {
                let s = i as Real * 10.005;
                Vec3::new(
                    s * 0.8,
                    0.3 * wobble(i, 1),
                    -150.0 + s * 0.6 + 0.2 * wobble(i, 2),
                )
            })
            .collect();
        let v: Vec<Vec3> = (0..=6)
            .map(|i| Vec3::new(wobble(i, 3), wobble(i, 4), 0.5 * wobble(i, 5)))
            .collect();
        check(&mesh, &env, &r, &v, "taut in a current");

        // Slack elements (no compression: only damping and drag), one crossing the surface,
        // one in air; still water; on a winch paying out.
        let mut mesh = Mesh::new(&[(chain((1.2, 0.2), AxialStiffness::Linear(1.0e7)), 50.0, 5)]);
        mesh.length_rate = 0.02;
        let env = Environment {
            depth: 200.0,
            ..Environment::default()
        };
        let r = vec![
            Vec3::new(0.0, 0.0, -25.0),
            Vec3::new(9.0, 0.5, -21.0),
            Vec3::new(16.0, 0.2, -17.5),
            Vec3::new(22.0, -0.4, -6.1),
            Vec3::new(24.0, -0.1, 3.3),
            Vec3::new(30.0, 0.3, 5.2),
        ];
        let v: Vec<Vec3> = (0..=5)
            .map(|i| Vec3::new(wobble(i, 6), 0.4 * wobble(i, 7), wobble(i, 8)))
            .collect();
        check(
            &mesh,
            &env,
            &r,
            &v,
            "slack, through the surface, on a winch",
        );

        // On a sloping bed with tanh friction: nodes pressed in by centimetres, sliding
        // slowly (within the friction's build-up) and fast, one node just above the bed.
        let mesh = Mesh::new(&[(chain((1.2, 0.3), AxialStiffness::Linear(3.8e8)), 40.0, 4)]);
        let env = Environment {
            depth: 100.0,
            bathymetry: Bathymetry::Plane {
                gradient: [0.05, -0.02],
            },
            seabed: Seabed {
                stiffness: 3.0e6,
                damping: ContactDamping::Ratio(2.948),
                friction_coefficient: 0.6,
                friction_velocity: 0.01,
                friction_law: FrictionLaw::Tanh,
            },
            ..Environment::default()
        };
        let bed = |x: Real, y: Real| -100.0 + 0.05 * x - 0.02 * y;
        let xs = [0.0, 10.001, 20.003, 30.004, 40.006];
        let dips = [0.004, 0.012, -0.05, 0.02, 0.008];
        let r: Vec<Vec3> = xs
            .iter()
            .zip(dips)
            .enumerate()
            .map(|(i, (&x, dip))| {
                let y = 0.5 * wobble(i, 9);
                Vec3::new(x, y, bed(x, y) - dip)
            })
            .collect();
        let v = vec![
            Vec3::new(0.002, -0.001, -0.01),
            Vec3::new(0.3, 0.1, 0.02),
            Vec3::new(0.001, 0.002, 0.0),
            Vec3::new(-0.004, 0.003, 0.05),
            Vec3::new(1.2, -0.4, -0.1),
        ];
        check(&mesh, &env, &r, &v, "on a sloping bed with friction");
    }

    #[test]
    fn declines_what_it_does_not_cover() {
        let mesh = Mesh::new(&[(chain((1.2, 0.3), AxialStiffness::Linear(3.8e8)), 40.0, 4)]);
        let viscous = Environment {
            seabed: Seabed {
                friction_coefficient: 0.5,
                friction_law: FrictionLaw::Viscous {
                    damping: 200.0,
                    static_scale: 1.0,
                },
                ..Seabed::default()
            },
            ..Environment::default()
        };
        assert!(covers(&mesh, &Environment::default()));
        assert!(!covers(&mesh, &viscous));
        let changing = Environment {
            current: Current::Table {
                z: vec![-100.0, 0.0],
                time: vec![0.0, 10.0],
                velocity: vec![Vec3::zeros(); 4],
            },
            ..Environment::default()
        };
        assert!(!covers(&mesh, &changing));
        let mut b = LineBlocks::banded(5, 1, EndKind::Known, EndKind::Known, true);
        b.diag[2] = Mat3::identity();
        let r: Vec<Vec3> = (0..5)
            .map(|i| Vec3::new(10.0 * i as Real, 0.0, -50.0))
            .collect();
        let v = vec![Vec3::zeros(); 5];
        let options = LoadOptions::direct(1.0);
        assert!(!newton_jacobian(
            &mesh,
            &viscous,
            0.0,
            &r,
            &v,
            options,
            Some(&mut b),
            None
        ));
        assert_eq!(b.diag[2], Mat3::identity(), "declined: nothing written");
    }
}
