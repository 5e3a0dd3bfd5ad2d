//! The physics of one rigid body: its state in the flat state vector, and the loads and mass
//! matrix of its equations of motion (docs/bodies.md).
//!
//! # State
//!
//! A free body (and a pinned one, [`pinned`]) owns [`STATE_LEN`] = 13 numbers of the state
//! vector:
//!
//! | index | quantity | unit |
//! |---|---|---|
//! | 0..3 | position of the body origin r_o, global axes | m |
//! | 3..7 | unit quaternion q = (w, i, j, k), body axes → global axes | - |
//! | 7..10 | velocity of the body origin v_o, global axes | m/s |
//! | 10..13 | angular velocity ω, **global** axes | rad/s |
//!
//! and their rates are ṙ_o = v_o, q̇ = ½ (0, ω) ⊗ q (ω in global axes, so it multiplies from
//! the left), v̇_o = a_o, ω̇ = α. The quaternion in the state drifts from unit norm by the
//! integrator's error only: [`read_state`] normalises it, and the rate keeps |q| constant in
//! exact arithmetic (q̇ ⊥ q).
//!
//! # Equations of motion
//!
//! [`Body::loads`](crate::model::Body::loads) returns, in global axes and about the body
//! origin, the 6×6 mass matrix M and the loads [F; M_o] such that the body alone obeys
//!
//! ```text
//! M [a_o; α] = [F; M_o]
//! ```
//!
//! Attached lines add their end forces (and the moments of those forces about the origin) to
//! the right-hand side, and their end masses to M.

mod contact;
mod hydrostatics;
mod loads;
mod members;
mod pinned;

pub use contact::SeabedContact;
pub use hydrostatics::{CYLINDER_SIDES, Section, Wetted, wetted_prism};
pub use loads::BodyLoads;
pub use members::member_loads;
pub use pinned::{follow_pin, initial_pin, pin_force, pin_kinematics};

use crate::math::{Quat, Real, Vec3};
use crate::model::RigidKinematics;

/// Number of state entries of a free body: position (3), quaternion (4), velocity (3),
/// angular velocity (3).
pub const STATE_LEN: usize = 13;

/// The body's kinematics from its [`STATE_LEN`] state entries `y` (layout in the module
/// docs). The quaternion is normalised (a zero quaternion gives NaN, which the driver's
/// finiteness check reports); the accelerations are zero.
#[inline]
pub fn read_state(y: &[Real]) -> RigidKinematics {
    let q = nalgebra::Quaternion::new(y[3], y[4], y[5], y[6]);
    RigidKinematics {
        position: Vec3::new(y[0], y[1], y[2]),
        orientation: Quat::from_quaternion(q),
        velocity: Vec3::new(y[7], y[8], y[9]),
        angular_velocity: Vec3::new(y[10], y[11], y[12]),
        acceleration: Vec3::zeros(),
        angular_acceleration: Vec3::zeros(),
    }
}

/// Writes the pose and velocities of `k` into the [`STATE_LEN`] entries `y`.
#[inline]
pub fn write_state(k: &RigidKinematics, y: &mut [Real]) {
    let q = k.orientation;
    y[0..3].copy_from_slice(k.position.as_slice());
    y[3] = q.w;
    y[4] = q.i;
    y[5] = q.j;
    y[6] = q.k;
    y[7..10].copy_from_slice(k.velocity.as_slice());
    y[10..13].copy_from_slice(k.angular_velocity.as_slice());
}

/// Writes the time derivative of the [`STATE_LEN`] entries into `dy`: ṙ_o = v_o,
/// q̇ = ½ (0, ω) ⊗ q = ½ (−ω·v, w ω + ω × v) for q = (w, v) and ω in global axes,
/// v̇_o = `acceleration` [m/s²], ω̇ = `angular_acceleration` [rad/s²] (both in global axes).
#[inline]
pub fn write_rate(
    k: &RigidKinematics,
    acceleration: &Vec3,
    angular_acceleration: &Vec3,
    dy: &mut [Real],
) {
    let q = k.orientation;
    let w = k.angular_velocity;
    let v = Vec3::new(q.i, q.j, q.k);
    let dv = 0.5 * (q.w * w + w.cross(&v));
    dy[0..3].copy_from_slice(k.velocity.as_slice());
    dy[3] = -0.5 * w.dot(&v);
    dy[4] = dv.x;
    dy[5] = dv.y;
    dy[6] = dv.z;
    dy[7..10].copy_from_slice(acceleration.as_slice());
    dy[10..13].copy_from_slice(angular_acceleration.as_slice());
}

/// Finite-difference steps of [`crate::model::Body::load_jacobian`]: translation [m],
/// rotation [rad], velocity [m/s] and angular velocity [rad/s]. Small against the metre and
/// second scales on which a body's hydrostatics, drag and inertia terms vary, large against
/// the round-off of loads of the size of its weight.
const BODY_STEP: Real = 1e-6;

impl crate::model::Body {
    /// The stiffness K = −∂[F; M_o]/∂[x_o; θ] and damping C = −∂[F; M_o]/∂[v_o; ω] of the
    /// body's own loads ([`crate::model::Body::loads`]) at kinematics `k`, in `env` at time `t`
    /// [s], by forward differences: θ is a small rotation about the global axes (the
    /// orientation becomes exp(θ) q, as the generalized-α scheme updates it), [N/m, N, N·m/rad]
    /// and [N·s/m, N·s, N·m·s/rad]. Twelve evaluations of the loads; no allocation.
    pub fn load_jacobian(
        &self,
        k: &RigidKinematics,
        env: &crate::physics::environment::Environment,
        t: Real,
    ) -> (crate::math::Mat6, crate::math::Mat6) {
        use crate::math::Mat6;
        let base = self.loads(k, env, t).generalized();
        let mut stiffness = Mat6::zeros();
        let mut damping = Mat6::zeros();
        for axis in 0..6 {
            let mut moved = *k;
            let mut rated = *k;
            let e = Vec3::ith(axis % 3, BODY_STEP);
            if axis < 3 {
                moved.position += e;
                rated.velocity += e;
            } else {
                moved.orientation = Quat::from_scaled_axis(e) * k.orientation;
                rated.angular_velocity += e;
            }
            let dk = (self.loads(&moved, env, t).generalized() - base) / BODY_STEP;
            let dc = (self.loads(&rated, env, t).generalized() - base) / BODY_STEP;
            stiffness.set_column(axis, &-dk);
            damping.set_column(axis, &-dc);
        }
        (stiffness, damping)
    }

    /// Bound on the rate |λ| [1/s] of the body's own linear dynamics and what sets it, for the
    /// stable step: the hydrostatic heave frequency √(ρ g A_wp / (m + A₃₃)) of a floating
    /// shape (A_wp its waterplane area upright), the linear drag rates b_i / (m + A_i) and
    /// b_j / (I_j + A_j) (the smallest principal inertia for the rotations). Quadratic drag is
    /// left out: its rate ρ C A |u| / (m + A) is far below the lines' at any speed a tether
    /// reaches. `water_density` [kg/m³] and `gravity` [m/s²] are the environment's.
    pub fn own_rate(&self, water_density: Real, gravity: Real) -> (Real, &'static str) {
        use crate::model::Displacement;
        let m = self.mass;
        let a = self.added_mass;
        let waterplane = match self.displacement {
            Displacement::Cylinder { radius, .. } => std::f64::consts::PI * radius * radius,
            Displacement::Box {
                length, breadth, ..
            } => length * breadth,
            _ => 0.0,
        };
        let inertia = self
            .inertia
            .symmetric_eigenvalues()
            .min()
            .max(Real::MIN_POSITIVE);
        let mut best = (
            (water_density * gravity * waterplane / (m + a[2])).sqrt(),
            "hydrostatic heave",
        );
        for i in 0..6 {
            let mass = if i < 3 { m + a[i] } else { inertia + a[i] };
            let rate = self.linear_drag[i] / mass;
            if rate > best.0 {
                best = (rate, "linear drag");
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use crate::math::{Mat3, Real};
    use crate::model::{Body, Displacement};

    /// The stable-step bound of a floating cylinder is its hydrostatic heave frequency
    /// √(ρ g π r² / (m + A₃₃)) with the environment's density and gravity (fresh water on
    /// another planet moves it), and a larger linear-drag rate takes over when it is faster.
    #[test]
    fn own_rate_is_the_heave_frequency_with_the_environments_water() {
        let mut body = Body::new("buoy", 2000.0, Mat3::identity() * 500.0);
        body.displacement = Displacement::Cylinder {
            radius: 0.8,
            height: 3.0,
        };
        body.added_mass = nalgebra::Vector6::new(0.0, 0.0, 600.0, 0.0, 0.0, 0.0);
        let area = std::f64::consts::PI * 0.64;
        for (rho, g) in [(1025.0, 9.81), (1000.0, 3.71)] {
            let (rate, what) = body.own_rate(rho, g);
            let expected: Real = (rho * g * area / 2600.0).sqrt();
            assert!(
                (rate - expected).abs() <= 1e-12 * expected,
                "{rate} vs {expected}"
            );
            assert_eq!(what, "hydrostatic heave");
        }
        body.linear_drag[0] = 2000.0 * 10.0;
        let (rate, what) = body.own_rate(1025.0, 9.81);
        assert_eq!((rate, what), (10.0, "linear drag"));
    }
}
