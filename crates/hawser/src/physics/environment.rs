//! Water, air, gravity, current and waves.

use crate::math::{Real, Vec3};
use crate::physics::obstacles::Obstacle;
use crate::physics::seabed::{Bathymetry, BedPoint};
use crate::physics::static_kinematics::WaveKinematicsMethod;
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
/// z is up and z = 0 is the still water level; the seabed is the flat plane z = −`depth` or
/// the shape of its `bathymetry`.
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
    /// Water depth [m]: the depth the waves are built for, and the seabed's: the plane
    /// z = −depth, or the depth at the origin of a sloping plane ([`Bathymetry`]).
    /// `Real::INFINITY` for deep water without a seabed (unless the bathymetry is a grid).
    pub depth: Real,
    /// Seabed contact parameters.
    pub seabed: crate::physics::seabed::Seabed,
    /// Shape of the seabed: flat at z = −depth (default), a sloping plane, or a grid.
    pub bathymetry: Bathymetry,
    /// Current velocity field.
    pub current: Current,
    /// Sea state; [`Waves::None`] by default. Build it with [`Waves::new`] for this
    /// environment's `depth` and `gravity`.
    pub waves: Waves,
    /// How line quadrature points take the wave kinematics: direct summation (default) or
    /// at their static position, interpolated in time.
    pub wave_kinematics: WaveKinematicsMethod,
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
            bathymetry: Bathymetry::Flat,
            current: Current::None,
            waves: Waves::None,
            wave_kinematics: WaveKinematicsMethod::Direct,
            obstacles: Vec::new(),
        }
    }
}

/// Current: water velocity [m/s] that depends on the height z, and for a table also on time.
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
    /// Profiles against time (MoorDyn's `current_profile_dynamic.txt`): velocity [m/s] at
    /// heights `z` [m] and times `time` [s], interpolated bilinearly (linearly in z, then in
    /// t) and held constant beyond the first and last height and time. Its local acceleration
    /// ∂u/∂t is that of the interpolant: within [t_k, t_{k+1}) the constant
    /// (u(z, t_{k+1}) − u(z, t_k)) / (t_{k+1} − t_k), zero before the first and from the last
    /// time on.
    Table {
        /// Heights z [m], strictly increasing.
        z: Vec<Real>,
        /// Times t [s], strictly increasing.
        time: Vec<Real>,
        /// Velocity [m/s] at (time k, height i), at index k · z.len() + i.
        velocity: Vec<Vec3>,
    },
}

/// Linear interpolation in a strictly increasing table `xs` at x, held constant beyond its
/// ends: (index k of the upper entry, weight w of it), the value being
/// (1 − w) f[k − 1] + w f[k] (k = 1 and w = 0 below the table, w = 1 at or above its end).
#[inline]
fn bracket(xs: &[Real], x: Real) -> (usize, Real) {
    let n = xs.len();
    if n < 2 || x <= xs[0] {
        return (1.min(n.saturating_sub(1)), 0.0);
    }
    if x >= xs[n - 1] {
        return (n - 1, 1.0);
    }
    let k = xs.partition_point(|&v| v <= x).clamp(1, n - 1);
    (k, (x - xs[k - 1]) / (xs[k] - xs[k - 1]))
}

/// Velocity [m/s] of a profile `velocity` at heights `zs` [m], at height z [m].
#[inline]
pub(crate) fn profile_at(zs: &[Real], velocity: &[Vec3], z: Real) -> Vec3 {
    match zs.len() {
        0 => Vec3::zeros(),
        1 => velocity[0],
        _ => {
            let (k, w) = bracket(zs, z);
            velocity[k - 1] * (1.0 - w) + velocity[k] * w
        }
    }
}

impl Current {
    /// Water velocity [m/s] at height z [m] and time t [s].
    #[inline]
    pub fn velocity(&self, z: Real, t: Real) -> Vec3 {
        match self {
            Current::None => Vec3::zeros(),
            Current::Uniform(u) => *u,
            Current::Profile { z: zs, velocity } => profile_at(zs, velocity, z),
            Current::Table {
                z: zs,
                time,
                velocity,
            } => {
                let nz = zs.len();
                if time.len() < 2 {
                    return profile_at(zs, &velocity[..nz], z);
                }
                let (k, w) = bracket(time, t);
                let before = profile_at(zs, &velocity[(k - 1) * nz..k * nz], z);
                let after = profile_at(zs, &velocity[k * nz..(k + 1) * nz], z);
                before * (1.0 - w) + after * w
            }
        }
    }

    /// Local acceleration ∂u/∂t [m/s²] of the water at height z [m] and time t [s]: zero but
    /// for a [`Current::Table`] inside its time range.
    #[inline]
    pub fn acceleration(&self, z: Real, t: Real) -> Vec3 {
        match self {
            Current::Table {
                z: zs,
                time,
                velocity,
            } => {
                let (nz, nt) = (zs.len(), time.len());
                if nt < 2 || t < time[0] || t >= time[nt - 1] {
                    return Vec3::zeros();
                }
                let (k, _) = bracket(time, t);
                let before = profile_at(zs, &velocity[(k - 1) * nz..k * nz], z);
                let after = profile_at(zs, &velocity[k * nz..(k + 1) * nz], z);
                (after - before) / (time[k] - time[k - 1])
            }
            _ => Vec3::zeros(),
        }
    }

    /// Whether the current changes in time (so that ∂u/∂t can be non-zero).
    #[inline]
    pub fn is_unsteady(&self) -> bool {
        matches!(self, Current::Table { .. })
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

    /// Local fluid acceleration ∂u/∂t at a point [m/s²] and time [s]: the waves' plus that of
    /// a current table (steady currents add none), zero in the air. This is what the Froude–Krylov and added-mass
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
            Waves::None => self.fluid_kinematics_with_waves(
                (position.z < 0.0, Vec3::zeros(), Vec3::zeros()),
                position,
                time,
            ),
            Waves::Airy(field) => {
                let k = field.kinematics(position, time);
                self.fluid_kinematics_with_waves(
                    (k.submerged, k.velocity, k.acceleration),
                    position,
                    time,
                )
            }
        }
    }

    /// Fluid velocity [m/s] and local acceleration [m/s²] at a point [m] and time [s] from the
    /// waves' part `(submerged, velocity, acceleration)` there, however it was found (direct
    /// summation or [`crate::physics::static_kinematics`]): in the water the current at the
    /// point's height plus the waves, and for an unsteady current its ∂u/∂t added to the
    /// waves' (it enters the Froude–Krylov and added-mass terms like theirs); nothing in the
    /// air.
    #[inline]
    pub fn fluid_kinematics_with_waves(
        &self,
        waves: (bool, Vec3, Vec3),
        position: &Vec3,
        time: Real,
    ) -> (Vec3, Vec3) {
        let (submerged, u, a) = waves;
        if !submerged {
            return (Vec3::zeros(), Vec3::zeros());
        }
        let z = position.z;
        let velocity = self.current.velocity(z, time) + u;
        if self.current.is_unsteady() {
            (velocity, a + self.current.acceleration(z, time))
        } else {
            (velocity, a)
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

    /// Whether there is a seabed: a finite depth, or a grid of heights.
    #[inline]
    pub fn has_seabed(&self) -> bool {
        self.depth.is_finite() || matches!(self.bathymetry, Bathymetry::Grid(_))
    }

    /// The seabed under (x, y) [m]: its height and upward normal ([`Bathymetry::at`]). Without
    /// a seabed, the height is −∞.
    #[inline]
    pub fn seabed_at(&self, x: Real, y: Real) -> BedPoint {
        self.bathymetry.at(self.depth, x, y)
    }

    /// The highest point of the seabed [m]: no point above it is in contact (−∞ without a
    /// seabed, +∞ for a sloping plane, −depth for a flat bed).
    #[inline]
    pub fn seabed_top(&self) -> Real {
        self.bathymetry.top(self.depth)
    }

    /// Seabed contact force per unit unstretched length [N/m] on a cable point at `position`
    /// [m] moving with `velocity` [m/s] ([`crate::physics::seabed::Seabed::contact_force`]
    /// over the bed under the point). A flat bed is a constant: no lookup.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn seabed_contact_force(
        &self,
        position: &Vec3,
        velocity: &Vec3,
        diameter: Real,
        mass_per_length: Real,
        stretch: Real,
        net_weight_z: Real,
        node_length: Real,
    ) -> Vec3 {
        let bed = self.seabed_at(position.x, position.y);
        self.seabed.contact_force(
            &bed,
            position,
            velocity,
            diameter,
            mass_per_length,
            stretch,
            net_weight_z,
            node_length,
        )
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
        assert_eq!(c.velocity(-50.0, 0.0).x, 0.5);
        assert_eq!(c.velocity(-200.0, 0.0).x, 0.0);
        assert_eq!(c.velocity(5.0, 0.0).x, 1.0);
        assert_eq!(c.acceleration(-50.0, 0.0), Vec3::zeros());
    }
}
