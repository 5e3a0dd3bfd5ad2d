//! Water, air, gravity, current and waves.

use crate::math::{Real, Vec3};
use crate::physics::obstacles::Obstacle;
use crate::physics::waves::Waves;

/// Standard gravity [m/s²] (SPEC §1).
pub const STANDARD_GRAVITY: Real = 9.80665;
/// Default sea-water density [kg/m³] (SPEC §1).
pub const SEA_WATER_DENSITY: Real = 1025.0;
/// Default air density [kg/m³] (SPEC §1).
pub const AIR_DENSITY: Real = 1.225;

/// The medium around a cable: water, air above z = 0, the seabed, the current, the waves and
/// the obstacles in the water.
///
/// z is up and z = 0 is the still water level; the flat seabed is at z = −`depth`.
/// Current and waves are superposed: in the water their velocities add, with no wave–current
/// interaction (the waves are not Doppler-shifted by the current, nor the current profile
/// stretched by the waves).
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
    /// Sea state; [`Waves::None`] by default. Build it with [`Waves::new`] for this
    /// environment's `depth` and `gravity`.
    pub waves: Waves,
    /// Rigid spheres and cylinders, fixed or moving, that lines touch; none by default.
    pub obstacles: Vec<Obstacle>,
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
            waves: Waves::None,
            obstacles: Vec::new(),
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

    /// Fluid velocity at a point [m/s] and time [s]: under water the current plus the wave
    /// particle velocity, still air above. Without waves the water ends at z = 0; with waves
    /// at the instantaneous surface η (see [`crate::physics::waves`] for the stretching).
    #[inline]
    pub fn fluid_velocity(&self, position: &Vec3, time: Real) -> Vec3 {
        self.fluid_kinematics(position, time).0
    }

    /// Local fluid acceleration ∂u/∂t at a point [m/s²] and time [s]: the waves' (steady
    /// currents add none), zero in the air. This is what the Froude–Krylov and added-mass
    /// terms of Morison's equation take (SPEC §1).
    #[inline]
    pub fn fluid_acceleration(&self, position: &Vec3, time: Real) -> Vec3 {
        self.fluid_kinematics(position, time).1
    }

    /// Fluid velocity [m/s] and local acceleration ∂u/∂t [m/s²] at a point [m] and time [s]
    /// together, from one sum over the wave components ([`Self::fluid_velocity`] and
    /// [`Self::fluid_acceleration`] each take one part of it). Morison's equation needs both
    /// at every quadrature point, and the wave sum is the dominant cost of a line in waves
    /// (BENCHMARKS.md, "Wave kinematics"): call this once rather than the two.
    #[inline]
    pub fn fluid_kinematics(&self, position: &Vec3, time: Real) -> (Vec3, Vec3) {
        match &self.waves {
            Waves::None if position.z < 0.0 => (self.current.velocity(position.z), Vec3::zeros()),
            Waves::None => (Vec3::zeros(), Vec3::zeros()),
            Waves::Airy(field) => {
                let k = field.kinematics(position, time);
                let velocity = if k.submerged {
                    self.current.velocity(position.z) + k.velocity
                } else {
                    Vec3::zeros()
                };
                (velocity, k.acceleration)
            }
        }
    }

    /// Surface elevation η [m] at (x, y) [m] and time [s]: 0 without waves.
    #[inline]
    pub fn surface_elevation(&self, x: Real, y: Real, time: Real) -> Real {
        self.waves.elevation(x, y, time)
    }

    /// Dynamic wave pressure p_d [Pa] at a point [m] and time [s]: the pressure beyond the
    /// hydrostatic −ρ g z, zero above the surface and without waves.
    #[inline]
    pub fn dynamic_pressure(&self, position: &Vec3, time: Real) -> Real {
        match &self.waves {
            Waves::None => 0.0,
            Waves::Airy(field) => {
                self.water_density * field.kinematics(position, time).kinematic_pressure
            }
        }
    }

    /// Whether the fluid is at rest everywhere (no current and no waves): drag and fluid
    /// inertia then need no fluid kinematics.
    #[inline]
    pub fn is_still_water(&self) -> bool {
        matches!(self.current, Current::None) && self.waves.is_none()
    }

    /// Whether the fluid is at rest everywhere at time t [s]: no current, and no waves or
    /// waves not yet built up by their ramp.
    #[inline]
    pub fn is_still_at(&self, time: Real) -> bool {
        matches!(self.current, Current::None)
            && self.waves.field().is_none_or(|w| w.ramp(time).0 == 0.0)
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
    use crate::physics::waves::{RegularWave, SeaState, Stretching, WaveSpec};

    /// The combined kinematics are the separate calls exactly (same sum, same order of
    /// operations), under a current and a ramped regular wave, above and below the surface,
    /// during and after the ramp, and in still water with a current.
    #[test]
    fn fluid_kinematics_is_velocity_and_acceleration_together() {
        let spec = WaveSpec {
            sea: SeaState::Regular(RegularWave {
                height: 2.0,
                period: 7.0,
                direction: 0.3,
            }),
            ramp_time: 10.0,
            stretching: Stretching::Wheeler,
        };
        let mut env = Environment {
            waves: Waves::new(&spec, 60.0, STANDARD_GRAVITY).unwrap(),
            current: Current::Uniform(Vec3::new(0.4, -0.1, 0.0)),
            ..Default::default()
        };
        for waves in [true, false] {
            if !waves {
                env.waves = Waves::None;
            }
            for z in [-55.0, -10.0, -0.3, 0.0, 0.4, 1.2] {
                for t in [0.0, 3.0, 11.0, 40.0] {
                    let p = Vec3::new(3.0, -7.0, z);
                    let (u, a) = env.fluid_kinematics(&p, t);
                    assert_eq!(u, env.fluid_velocity(&p, t), "z {z}, t {t}");
                    assert_eq!(a, env.fluid_acceleration(&p, t), "z {z}, t {t}");
                }
            }
        }
    }

    #[test]
    fn ramped_waves_are_still_at_the_start() {
        let waves = |ramp_time| {
            let spec = WaveSpec {
                sea: SeaState::Regular(RegularWave {
                    height: 1.0,
                    period: 6.0,
                    direction: 0.0,
                }),
                ramp_time,
                stretching: Stretching::Wheeler,
            };
            Waves::new(&spec, Real::INFINITY, STANDARD_GRAVITY).unwrap()
        };
        let mut env = Environment {
            waves: waves(12.0),
            ..Default::default()
        };
        assert!(env.is_still_at(0.0) && !env.is_still_at(1.0) && !env.is_still_water());
        env.waves = waves(0.0);
        assert!(!env.is_still_at(0.0));
        env.waves = Waves::None;
        assert!(env.is_still_at(0.0) && env.is_still_water());
        env.current = Current::Uniform(Vec3::x());
        assert!(!env.is_still_at(0.0));
    }

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
