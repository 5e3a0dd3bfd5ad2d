//! Prescribed motions of rigid bodies (vessels, test rigs): pose, velocity and acceleration of
//! the body origin and the body's rotation, at any time.

use crate::math::{Quat, Real, Vec3};

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
        }
    }
}
