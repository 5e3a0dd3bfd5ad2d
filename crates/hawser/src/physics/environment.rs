//! Water, air, gravity and current.

use crate::math::{Real, Vec3};

/// Standard gravity [m/s²] (SPEC §1).
pub const STANDARD_GRAVITY: Real = 9.80665;
/// Default sea-water density [kg/m³] (SPEC §1).
pub const SEA_WATER_DENSITY: Real = 1025.0;
/// Default air density [kg/m³] (SPEC §1).
pub const AIR_DENSITY: Real = 1.225;

/// The medium around a cable: water, air above z = 0, the seabed and the current.
///
/// z is up and z = 0 is the still water level; the flat seabed is at z = −`depth`.
#[derive(Clone, Debug, PartialEq)]
pub struct Environment {
    /// Gravitational acceleration [m/s²]; default [`STANDARD_GRAVITY`].
    pub gravity: Real,
    /// Water density [kg/m³]; default [`SEA_WATER_DENSITY`].
    pub water_density: Real,
    /// Air density above z = 0 [kg/m³]; default [`AIR_DENSITY`]. Air exerts drag, not buoyancy.
    pub air_density: Real,
    /// Water depth [m]: the seabed is the plane z = −depth. `Real::INFINITY` for no seabed.
    pub depth: Real,
    /// Seabed contact parameters.
    pub seabed: crate::physics::seabed::Seabed,
    /// Current velocity field.
    pub current: Current,
}

impl Default for Environment {
    fn default() -> Self {
        Self {
            gravity: STANDARD_GRAVITY,
            water_density: SEA_WATER_DENSITY,
            air_density: AIR_DENSITY,
            depth: Real::INFINITY,
            seabed: Default::default(),
            current: Current::None,
        }
    }
}

/// Current: steady, depth-dependent water velocity [m/s].
#[derive(Clone, Debug, PartialEq, Default)]
pub enum Current {
    /// Still water.
    #[default]
    None,
    /// The same velocity [m/s] at every depth.
    Uniform(Vec3),
    /// Velocity [m/s] given at increasing heights z [m] (negative below the surface),
    /// interpolated linearly in z and held constant beyond the first and last entries.
    Profile {
        /// Heights z [m], strictly increasing.
        z: Vec<Real>,
        /// Velocity [m/s] at each height.
        velocity: Vec<Vec3>,
    },
}

impl Current {
    /// Water velocity [m/s] at height z [m].
    #[inline]
    pub fn velocity(&self, z: Real) -> Vec3 {
        match self {
            Current::None => Vec3::zeros(),
            Current::Uniform(u) => *u,
            Current::Profile { z: zs, velocity } => {
                let n = zs.len();
                if n == 0 {
                    return Vec3::zeros();
                }
                if z <= zs[0] {
                    return velocity[0];
                }
                if z >= zs[n - 1] {
                    return velocity[n - 1];
                }
                // Binary search for the bracketing interval.
                let k = zs.partition_point(|&zk| zk <= z).clamp(1, n - 1);
                let w = (z - zs[k - 1]) / (zs[k] - zs[k - 1]);
                velocity[k - 1] * (1.0 - w) + velocity[k] * w
            }
        }
    }
}

impl Environment {
    /// Density of the fluid at height z [m]: water below z = 0, air above [kg/m³].
    #[inline]
    pub fn fluid_density(&self, z: Real) -> Real {
        if z < 0.0 {
            self.water_density
        } else {
            self.air_density
        }
    }

    /// Fluid velocity at a point [m/s]: the current under water, still air above.
    #[inline]
    pub fn fluid_velocity(&self, position: &Vec3, _time: Real) -> Vec3 {
        if position.z < 0.0 {
            self.current.velocity(position.z)
        } else {
            Vec3::zeros()
        }
    }

    /// Fluid acceleration at a point [m/s²]. Zero for steady currents; wave kinematics
    /// (issue 6) enter here.
    #[inline]
    pub fn fluid_acceleration(&self, _position: &Vec3, _time: Real) -> Vec3 {
        Vec3::zeros()
    }

    /// Whether the fluid is at rest everywhere (no current; waves come with issue 6): drag and
    /// fluid inertia then need no fluid kinematics.
    #[inline]
    pub fn is_still_water(&self) -> bool {
        matches!(self.current, Current::None)
    }

    /// Height of the seabed z = −depth [m].
    #[inline]
    pub fn seabed_z(&self) -> Real {
        -self.depth
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn profile_interpolates_and_clamps() {
        let c = Current::Profile {
            z: vec![-100.0, 0.0],
            velocity: vec![Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0)],
        };
        assert_eq!(c.velocity(-50.0).x, 0.5);
        assert_eq!(c.velocity(-200.0).x, 0.0);
        assert_eq!(c.velocity(5.0).x, 1.0);
    }
}
