//! Prescribed motions of rigid bodies (vessels, test rigs): pose, velocity and acceleration of
//! the body origin and the body's rotation, at any time.
//!
//! Axes: global x, y horizontal, z up; body axes x forward, y to port, z up (as
//! [`crate::model::Body`]). A heading ψ is the yaw of the body x axis, measured from global +x
//! toward +y (counter-clockwise seen from above). Euler angles are roll φ, pitch θ, yaw ψ with
//! R = R_z(ψ) R_y(θ) R_x(φ) (body to global): positive roll lowers the starboard side, positive
//! pitch lowers the bow.
//!
//! Every motion gives exact derivatives: analytic ones for the manoeuvre and the RAO motion,
//! the derivatives of the interpolant for tables. Evaluation allocates nothing; everything a
//! motion needs is built by its constructor.
//!
//! docs/motions.md states the conventions and the manoeuvre geometry.

use crate::error::ModelError;
use crate::math::{Quat, Real, Vec3};
use crate::model::ramp;
use crate::physics::waves::Waves;
use std::f64::consts::TAU;

/// Kinematics of a rigid body at one instant, all in global axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidKinematics {
    /// Position of the body origin [m].
    pub position: Vec3,
    /// Rotation from body axes to global axes.
    pub orientation: Quat,
    /// Velocity of the body origin [m/s].
    pub velocity: Vec3,
    /// Angular velocity ω in global axes [rad/s].
    pub angular_velocity: Vec3,
    /// Acceleration of the body origin [m/s²].
    pub acceleration: Vec3,
    /// Angular acceleration dω/dt in global axes [rad/s²].
    pub angular_acceleration: Vec3,
}

impl Default for RigidKinematics {
    fn default() -> Self {
        Self::at_rest(Vec3::zeros(), Quat::identity())
    }
}

impl RigidKinematics {
    /// A body at rest at `position` with `orientation`.
    pub fn at_rest(position: Vec3, orientation: Quat) -> Self {
        Self {
            position,
            orientation,
            velocity: Vec3::zeros(),
            angular_velocity: Vec3::zeros(),
            acceleration: Vec3::zeros(),
            angular_acceleration: Vec3::zeros(),
        }
    }

    /// Position [m], velocity [m/s] and acceleration [m/s²] of the body-fixed point at
    /// `offset` (body axes, from the body origin [m]): ρ = R offset, r = r_o + ρ,
    /// v = v_o + ω × ρ, a = a_o + α × ρ + ω × (ω × ρ).
    #[inline]
    pub fn point(&self, offset: &Vec3) -> (Vec3, Vec3, Vec3) {
        let rho = self.orientation * offset;
        let w = self.angular_velocity;
        (
            self.position + rho,
            self.velocity + w.cross(&rho),
            self.acceleration + self.angular_acceleration.cross(&rho) + w.cross(&w.cross(&rho)),
        )
    }
}

/// A prescribed rigid-body trajectory; t in [s].
#[derive(Clone, Debug, PartialEq)]
pub enum RigidMotion {
    /// Held at a pose.
    Fixed {
        /// Position of the body origin [m].
        position: Vec3,
        /// Orientation.
        orientation: Quat,
    },
    /// r(t) = start + velocity·t, constant orientation.
    ConstantVelocity {
        /// Position of the body origin at t = 0 [m].
        start: Vec3,
        /// Orientation.
        orientation: Quat,
        /// Velocity [m/s].
        velocity: Vec3,
    },
    /// A ship manoeuvre: straight run, turn of constant radius, straight run ([`Manoeuvre`]).
    Manoeuvre(Box<Manoeuvre>),
    /// A 6-DOF table interpolated by cubic splines ([`RigidTimeSeries`]).
    TimeSeries(RigidTimeSeries),
    /// Wave-frequency motion from RAO tables on a mean motion ([`RaoMotion`]).
    Rao(Box<RaoMotion>),
}

impl RigidMotion {
    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        match self {
            RigidMotion::Fixed {
                position,
                orientation,
            } => RigidKinematics::at_rest(*position, *orientation),
            RigidMotion::ConstantVelocity {
                start,
                orientation,
                velocity,
            } => RigidKinematics {
                velocity: *velocity,
                ..RigidKinematics::at_rest(start + velocity * t, *orientation)
            },
            RigidMotion::Manoeuvre(m) => m.kinematics(t),
            RigidMotion::TimeSeries(s) => s.kinematics(t),
            RigidMotion::Rao(r) => r.kinematics(t),
        }
    }
}

fn invalid(what: &str, why: impl Into<String>) -> ModelError {
    ModelError::Invalid {
        what: what.to_string(),
        why: why.into(),
    }
}

fn check(ok: bool, what: &str, why: &str) -> Result<(), ModelError> {
    if ok { Ok(()) } else { Err(invalid(what, why)) }
}

// ---------------------------------------------------------------------------------------------
// Euler angles

/// Orientation, angular velocity ω and angular acceleration dω/dt (in the parent frame) of
/// the rotation R = R_z(ψ) R_y(θ) R_x(φ) from the Euler angles [φ, θ, ψ] [rad], their rates
/// [rad/s] and their second derivatives [rad/s²].
///
/// The kinematic map: ω = ψ̇ ẑ + θ̇ e_y' + φ̇ e_x'', with e_y' = R_z(ψ) ŷ the pitch axis and
/// e_x'' = R_z(ψ) R_y(θ) x̂ the roll axis (the body x axis); differentiating, with
/// de_y'/dt = ψ̇ ẑ × e_y' and de_x''/dt = (ψ̇ ẑ + θ̇ e_y') × e_x'',
/// dω/dt = ψ̈ ẑ + θ̈ e_y' + θ̇ ψ̇ ẑ × e_y' + φ̈ e_x'' + φ̇ (ψ̇ ẑ + θ̇ e_y') × e_x''.
#[inline]
pub fn euler_kinematics(
    angles: [Real; 3],
    rates: [Real; 3],
    accels: [Real; 3],
) -> (Quat, Vec3, Vec3) {
    let [_, theta, psi] = angles;
    let [roll_rate, pitch_rate, yaw_rate] = rates;
    let (sp, cp) = psi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let z = Vec3::z();
    let ey = Vec3::new(-sp, cp, 0.0);
    let ex = Vec3::new(cp * ct, sp * ct, -st);
    let omega = z * yaw_rate + ey * pitch_rate + ex * roll_rate;
    let yaw_pitch = z * yaw_rate + ey * pitch_rate;
    let alpha = z * accels[2]
        + ey * accels[1]
        + z.cross(&ey) * (pitch_rate * yaw_rate)
        + ex * accels[0]
        + yaw_pitch.cross(&ex) * roll_rate;
    (
        Quat::from_euler_angles(angles[0], angles[1], angles[2]),
        omega,
        alpha,
    )
}

mod manoeuvre;
mod rao;
mod time_series;
pub use manoeuvre::{Manoeuvre, ManoeuvreSpec};
pub use rao::{RaoMotion, RaoTable};
pub use time_series::RigidTimeSeries;
