//! Seabed contact of a rigid body over its shape: a Winkler bed (a pressure K_g δ at depth δ
//! below the bed) acting on the shape's surface, sampled by patches.
//!
//! The surface of a `Box` or `Cylinder` displacement (docs/bodies.md) is divided into patches,
//! each a point p (body axes, from the body origin) with an outward unit normal m and an area
//! A. A patch below the bed, at depth δ = (z_bed − z) n_z along the bed's normal n, carries the
//! normal pressure K_g δ − c_A v·n over its area projected on the bed, A·max(−m·n, 0), and the
//! friction of the seabed's law ([`crate::physics::seabed::Seabed::friction`]) against the
//! sliding velocity v − (v·n) n of its point, bounded by μ times its normal force. The forces
//! act at the patch points, so they also give the moment that turns a tilted body flat onto the
//! bed. With a face flat on the bed every patch of it is at the same depth and the midpoint rule
//! is exact; a tilted face is integrated to O(patch²) while wholly in contact.
//!
//! c_A is the seabed's damping per area ([`crate::physics::seabed::ContactDamping::PerArea`]),
//! or for a damping ratio ζ, c_A = 2ζ √(K_g m / A_f) with m the body's mass plus its heave added
//! mass and A_f its footprint (the base of a box, l·b; the end of a cylinder, π r²): ζ of the
//! body's critical damping standing on its base. A `Submerged` body rests on the bed as the
//! sphere of its volume about its centre of buoyancy (the free points' contact); a body without
//! a displacement has no extent to rest on and no contact.

use crate::math::{Mat3, Real, Vec3};
use crate::model::{Body, Displacement, RigidKinematics};
use crate::physics::environment::Environment;
use crate::physics::seabed::ContactDamping;

/// Patches per edge of each face of a box (16 per face).
const BOX_DIVISIONS: usize = 4;
/// Sectors around a cylinder (its side and its ends).
const CYLINDER_SECTORS: usize = 32;
/// Bands along a cylinder's side.
const CYLINDER_BANDS: usize = 4;
/// Rings of equal area on each end of a cylinder.
const CYLINDER_RINGS: usize = 3;

/// One patch of a body's surface.
#[derive(Clone, Copy, Debug)]
struct Patch {
    /// Centre, body axes, from the body origin [m].
    point: Vec3,
    /// Outward unit normal, body axes [-].
    normal: Vec3,
    /// Area [m²].
    area: Real,
}

/// Calls `visit` for every patch of the surface of a box of half-sides `h` centred at `c`.
fn box_patches(c: Vec3, h: Vec3, mut visit: impl FnMut(Patch)) {
    let n = BOX_DIVISIONS;
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        let area = 4.0 * h[u] * h[v] / (n * n) as Real;
        for sign in [-1.0, 1.0] {
            let mut normal = Vec3::zeros();
            normal[axis] = sign;
            for i in 0..n {
                for j in 0..n {
                    let mut p = c;
                    p[axis] += sign * h[axis];
                    p[u] += h[u] * (2.0 * (i as Real + 0.5) / n as Real - 1.0);
                    p[v] += h[v] * (2.0 * (j as Real + 0.5) / n as Real - 1.0);
                    visit(Patch {
                        point: p,
                        normal,
                        area,
                    });
                }
            }
        }
    }
}

/// Calls `visit` for every patch of the surface of a cylinder of radius `r` and half-height
/// `hh` along body z, centred at `c`: bands of sectors on its side, rings of equal area on its
/// ends (each patch at the radius that halves its ring's area).
fn cylinder_patches(c: Vec3, r: Real, hh: Real, mut visit: impl FnMut(Patch)) {
    let sectors = CYLINDER_SECTORS as Real;
    let side = 2.0 * std::f64::consts::PI * r / sectors * (2.0 * hh / CYLINDER_BANDS as Real);
    let ring = std::f64::consts::PI * r * r / (CYLINDER_RINGS as Real * sectors);
    for k in 0..CYLINDER_SECTORS {
        let theta = 2.0 * std::f64::consts::PI * (k as Real + 0.5) / sectors;
        let (s, co) = theta.sin_cos();
        let radial = Vec3::new(co, s, 0.0);
        for b in 0..CYLINDER_BANDS {
            let z = hh * (2.0 * (b as Real + 0.5) / CYLINDER_BANDS as Real - 1.0);
            visit(Patch {
                point: c + radial * r + Vec3::z() * z,
                normal: radial,
                area: side,
            });
        }
        for q in 0..CYLINDER_RINGS {
            let rho = r * ((q as Real + 0.5) / CYLINDER_RINGS as Real).sqrt();
            for sign in [-1.0, 1.0] {
                visit(Patch {
                    point: c + radial * rho + Vec3::z() * (sign * hh),
                    normal: Vec3::z() * sign,
                    area: ring,
                });
            }
        }
    }
}

/// The seabed's force [N] and moment about the body origin [N·m] on a body, in global axes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SeabedContact {
    /// Resultant force [N].
    pub force: Vec3,
    /// Moment about the body origin [N·m].
    pub moment: Vec3,
}

impl Body {
    /// The footprint A_f [m²] the damping ratio of the seabed contact refers to (the base of a
    /// box, the end of a cylinder, the section of the sphere of a `Submerged` volume), and the
    /// largest area the shape can press on the bed [m²] (for the stable step); `None` without
    /// a shape.
    pub fn contact_areas(&self) -> Option<(Real, Real)> {
        match self.displacement {
            Displacement::None => None,
            Displacement::Submerged { volume } => {
                let r = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
                let a = std::f64::consts::PI * r * r;
                Some((a, a))
            }
            Displacement::Box {
                length,
                breadth,
                height,
            } => Some((
                length * breadth,
                (length * breadth)
                    .max(length * height)
                    .max(breadth * height),
            )),
            Displacement::Cylinder { radius, height } => {
                let end = std::f64::consts::PI * radius * radius;
                Some((end, end.max(2.0 * radius * height)))
            }
        }
    }

    /// Radius [m] of a ball about the body origin that holds its shape.
    fn contact_reach(&self) -> Real {
        let c = self.centre_of_buoyancy.norm();
        c + match self.displacement {
            Displacement::None => 0.0,
            Displacement::Submerged { volume } => {
                (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt()
            }
            Displacement::Box {
                length,
                breadth,
                height,
            } => 0.5 * (length * length + breadth * breadth + height * height).sqrt(),
            Displacement::Cylinder { radius, height } => radius.hypot(0.5 * height),
        }
    }

    /// Damping of the contact per unit area c_A [Pa·s/m] (module docs).
    fn contact_damping(&self, env: &Environment, footprint: Real) -> Real {
        let k = env.seabed.stiffness;
        match env.seabed.damping {
            ContactDamping::PerArea(c) => c,
            ContactDamping::Ratio(zeta) => {
                2.0 * zeta * (k * (self.mass + self.added_mass[2]) / footprint).sqrt()
            }
        }
    }

    /// The seabed's force and moment on the body at kinematics `k` (rotation matrix `r`), or
    /// `None` when no part of it is in contact (module docs). Allocates nothing; a body whose
    /// bounding ball stays above the bed's highest point costs one comparison.
    pub fn seabed_contact(
        &self,
        k: &RigidKinematics,
        r: &Mat3,
        env: &Environment,
    ) -> Option<SeabedContact> {
        let stiffness = env.seabed.stiffness;
        if !(env.has_seabed() && stiffness > 0.0) {
            return None;
        }
        let (footprint, _) = self.contact_areas()?;
        if k.position.z - self.contact_reach() > env.seabed_top() {
            return None;
        }
        let c_area = self.contact_damping(env, footprint);
        let seabed = &env.seabed;
        let mut total = SeabedContact::default();
        let mut touching = false;
        let w = k.angular_velocity;
        // A force `f` at the point `arm` from the origin.
        let mut apply = |arm: Vec3, f: Vec3| {
            total.force += f;
            total.moment += arm.cross(&f);
            touching = true;
        };
        if let Displacement::Submerged { volume } = self.displacement {
            // The sphere of the volume: its lowest point along −n.
            let radius = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
            let centre = r * self.centre_of_buoyancy;
            let x = k.position + centre;
            let bed = env.seabed_at(x.x, x.y);
            let n = bed.normal;
            let penetration = (bed.z - (x.z - radius / n.z)) * n.z;
            if penetration > 0.0 {
                let arm = centre - n * radius;
                let v = k.velocity + w.cross(&arm);
                let vn = v.dot(&n);
                let normal = (stiffness * penetration - c_area * vn) * footprint;
                let vt = v - n * vn;
                let speed = vt.norm();
                let mut f = n * normal;
                if seabed.friction_coefficient > 0.0 && speed > 0.0 && normal > 0.0 {
                    f -= vt * (seabed.friction(speed, normal, 1.0) / speed);
                }
                apply(arm, f);
            }
            return touching.then_some(total);
        }
        let mut patch = |p: Patch| {
            let arm = r * p.point;
            let x = k.position + arm;
            let bed = env.seabed_at(x.x, x.y);
            let penetration = bed.penetration(&x);
            if penetration <= 0.0 {
                return;
            }
            let n = bed.normal;
            let area = p.area * (-(r * p.normal).dot(&n)).max(0.0);
            if area == 0.0 {
                return;
            }
            let v = k.velocity + w.cross(&arm);
            let vn = v.dot(&n);
            let normal = (stiffness * penetration - c_area * vn) * area;
            let vt = v - n * vn;
            let speed = vt.norm();
            let mut f = n * normal;
            if seabed.friction_coefficient > 0.0 && speed > 0.0 && normal > 0.0 {
                // A viscous law's damping is the body's, shared by area.
                f -= vt * (seabed.friction(speed, normal, footprint / area) / speed);
            }
            apply(arm, f);
        };
        match self.displacement {
            Displacement::Box {
                length,
                breadth,
                height,
            } => box_patches(
                self.centre_of_buoyancy,
                Vec3::new(0.5 * length, 0.5 * breadth, 0.5 * height),
                &mut patch,
            ),
            Displacement::Cylinder { radius, height } => {
                cylinder_patches(self.centre_of_buoyancy, radius, 0.5 * height, &mut patch)
            }
            Displacement::None | Displacement::Submerged { .. } => {}
        }
        touching.then_some(total)
    }

    /// Bound on the rate |λ| [1/s] of the seabed contact of the body, for the stable step.
    /// The contact's stiffness K_g A_max (A_max the largest area the shape can press on the
    /// bed), its damping c_A A_max and the friction's slope at rest μ W π/v_μ (W the body's
    /// weight in water, the normal force of a body resting on the bed alone) act on its
    /// translation, with mass m (its own plus the smallest translational added mass), and, at
    /// arms up to R (the reach of its shape from its origin), on its rotation, with inertia J
    /// (the smallest principal inertia plus the smallest rotational added mass): the rate is
    /// the largest of √(k/m), c/m, √(k R²/J) and c R²/J over these. The normal force on a
    /// `Submerged` body's sphere passes through the sphere's centre, so its spring and damper
    /// act at the arm of that centre only (its friction at the full reach).
    pub fn seabed_rate(&self, env: &Environment) -> Option<Real> {
        let k = env.seabed.stiffness;
        if !(env.has_seabed() && k > 0.0) {
            return None;
        }
        let (footprint, largest) = self.contact_areas()?;
        let m = self.mass + self.added_mass.fixed_rows::<3>(0).min().max(0.0);
        let j = self.inertia.symmetric_eigenvalues().min()
            + self.added_mass.fixed_rows::<3>(3).min().max(0.0);
        let r2 = self.contact_reach().powi(2);
        let normal_r2 = match self.displacement {
            Displacement::Submerged { .. } => self.centre_of_buoyancy.norm_squared(),
            _ => r2,
        };
        let stiffness = k * largest;
        let damping = self.contact_damping(env, footprint) * largest;
        let wet = (self.mass - env.water_density * self.displacement.volume()) * env.gravity;
        let friction = if env.seabed.friction_coefficient > 0.0 && wet > 0.0 {
            env.seabed.friction_slope(wet, 1.0)
        } else {
            0.0
        };
        let translation = (stiffness / m).sqrt().max(damping.max(friction) / m);
        let rotation = if j > 0.0 {
            (stiffness * normal_r2 / j)
                .sqrt()
                .max(damping * normal_r2 / j)
                .max(friction * r2 / j)
        } else {
            Real::INFINITY
        };
        Some(translation.max(rotation))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The patches tile the surface: their areas add up to the shape's area, and their
    /// outward normals weighted by area to zero (a closed surface).
    #[test]
    fn patches_tile_the_surface() {
        let c = Vec3::new(0.3, -0.2, 0.5);
        let (mut area, mut flux) = (0.0, Vec3::zeros());
        box_patches(c, Vec3::new(1.0, 2.0, 3.0), |p| {
            area += p.area;
            flux += p.normal * p.area;
        });
        assert!((area - 2.0 * (2.0 * 4.0 + 2.0 * 6.0 + 4.0 * 6.0)).abs() < 1e-12);
        assert!(flux.norm() < 1e-12);
        let (r, h) = (0.7, 2.5);
        let (mut area, mut flux) = (0.0, Vec3::zeros());
        cylinder_patches(c, r, 0.5 * h, |p| {
            area += p.area;
            flux += p.normal * p.area;
        });
        let exact = 2.0 * std::f64::consts::PI * r * (r + h);
        assert!((area - exact).abs() < 1e-12 * exact, "{area} {exact}");
        assert!(flux.norm() < 1e-12);
    }
}
