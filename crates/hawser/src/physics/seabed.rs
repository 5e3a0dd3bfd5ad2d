//! Seabed contact per unit unstretched length (DG paper eqs. 15–16).

use crate::math::{Real, Vec3};

/// Seabed contact parameters: a vertical bilinear spring–damper and sliding friction.
#[derive(Clone, Debug, PartialEq)]
pub struct Seabed {
    /// Ground stiffness K_g per unit contact area [Pa/m = N/m³] (DG paper eq. 15).
    pub stiffness: Real,
    /// Damping of the vertical contact.
    pub damping: ContactDamping,
    /// Dynamic friction coefficient μ [-] (DG paper eq. 16).
    pub friction_coefficient: Real,
    /// Sliding speed v_μ [m/s] over which friction builds up (DG paper eq. 16).
    pub friction_velocity: Real,
    /// How friction grows with the sliding speed.
    pub friction_law: FrictionLaw,
}

/// How seabed friction grows with the sliding speed |v| up to its limit μ·N.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// μ N tanh(π|v|/v_μ), with N the cable's net weight per length (DG paper eq. 16).
    Tanh,
    /// MoorDyn's law (`Line::getStateDeriv`, v2.7): a node's friction force is μ·c·|v|, or
    /// μ·|F_z| with F_z the node's vertical contact force once μ·c·|v| exceeds
    /// `static_scale`·μ·|F_z|. `damping` c [N·s/m] is per node (MoorDyn's `FricDamp`), so
    /// the law depends on the mesh as MoorDyn's does.
    Viscous {
        /// c [N·s/m] per node (`FricDamp`).
        damping: Real,
        /// Ratio of static to dynamic friction (`StatDynFricScale`).
        static_scale: Real,
    },
}

impl Default for Seabed {
    /// 3 MPa/m, ζ = 1, no friction, v_μ = 0.01 m/s: a firm, frictionless bed (MoorDyn's kBot
    /// default order of magnitude) that a user tunes to the soil.
    fn default() -> Self {
        Self {
            stiffness: 3.0e6,
            damping: ContactDamping::Ratio(1.0),
            friction_coefficient: 0.0,
            friction_velocity: 0.01,
            friction_law: FrictionLaw::Tanh,
        }
    }
}

/// Damping of the vertical seabed contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactDamping {
    /// Damping ratio ζ [-] of the contact spring with the cable's own mass: c = 2ζ√(K_g d γ0)
    /// per unit length (DG paper eq. 15); 1 is critical.
    Ratio(Real),
    /// Damping per unit contact area c_A [Pa·s/m]: c = c_A·d per unit length (MoorDyn's
    /// `cBot`).
    PerArea(Real),
}

impl Seabed {
    /// Vertical contact damping per unit length [N·s/m²] of a cable of `diameter` [m] and
    /// `mass_per_length` [kg/m].
    #[inline]
    pub fn damping_per_length(&self, diameter: Real, mass_per_length: Real) -> Real {
        match self.damping {
            ContactDamping::Ratio(zeta) => {
                2.0 * zeta * (self.stiffness * diameter * mass_per_length).sqrt()
            }
            ContactDamping::PerArea(c) => c * diameter,
        }
    }

    /// Vertical contact damping [N·s/m] of a body resting on `area` [m²] with spring
    /// stiffness `stiffness` [N/m] and mass `mass` [kg].
    pub fn damping_of_area(&self, area: Real, stiffness: Real, mass: Real) -> Real {
        match self.damping {
            ContactDamping::Ratio(zeta) => 2.0 * zeta * (stiffness * mass).sqrt(),
            ContactDamping::PerArea(c) => c * area,
        }
    }

    /// Magnitude of the friction force [N, or N/m per length] at sliding `speed` [m/s] under
    /// the normal load `normal` [N or N/m], for a node (or body) carrying `node_length` [m]
    /// of cable (1 for a body: the result is then a force).
    #[inline]
    pub fn friction(&self, speed: Real, normal: Real, node_length: Real) -> Real {
        let mu = self.friction_coefficient;
        match self.friction_law {
            FrictionLaw::Tanh => {
                mu * normal * (std::f64::consts::PI * speed / self.friction_velocity).tanh()
            }
            FrictionLaw::Viscous {
                damping,
                static_scale,
            } => {
                let limit = mu * normal;
                let viscous = mu * damping * speed / node_length;
                if viscous > static_scale * limit {
                    limit
                } else {
                    viscous
                }
            }
        }
    }

    /// Largest slope d(friction)/d(speed) [N·s/m per m of cable] at rest, for the stable step.
    pub fn friction_slope(&self, normal: Real, node_length: Real) -> Real {
        let mu = self.friction_coefficient;
        match self.friction_law {
            FrictionLaw::Tanh => mu * normal * std::f64::consts::PI / self.friction_velocity,
            FrictionLaw::Viscous { damping, .. } => mu * damping / node_length,
        }
    }

    /// Contact force per unit unstretched length [N/m] on a cable point at height `z` [m]
    /// moving with `velocity` [m/s], for a bed at `bed_z` [m].
    ///
    /// Vertical (eq. 15): √(1+ε) (K_g d δ − c v_z) with δ = bed_z − z > 0 and c from
    /// [`Seabed::damping_per_length`] (2ζ √(K_g d γ0), or c_A·d).
    /// Horizontal (eq. 16): −√(1+ε) μ tanh(π|v_xy|/v_μ) v̂_xy · max(−w_z, 0), with w_z the
    /// net weight per length (negative when the cable sinks), so friction opposes sliding;
    /// or MoorDyn's law on the vertical contact force ([`FrictionLaw`]). `node_length` [m] is
    /// the length of cable the node carries (half of each adjacent element).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn contact_force(
        &self,
        bed_z: Real,
        z: Real,
        velocity: &Vec3,
        diameter: Real,
        mass_per_length: Real,
        stretch: Real,
        net_weight_z: Real,
        node_length: Real,
    ) -> Vec3 {
        if bed_z - z <= 0.0 {
            return Vec3::zeros();
        }
        self.contact_force_with(
            bed_z,
            z,
            velocity,
            diameter,
            stretch.max(0.0).sqrt(),
            self.damping_per_length(diameter, mass_per_length),
            net_weight_z,
            node_length,
        )
    }

    /// [`Seabed::contact_force`] with √(1+ε) `root` and the damping per unit length
    /// `damping` [N·s/m²] ([`Seabed::damping_per_length`]) given: a line's element loop
    /// has the first already and computes the second once per line type.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub fn contact_force_with(
        &self,
        bed_z: Real,
        z: Real,
        velocity: &Vec3,
        diameter: Real,
        root: Real,
        damping: Real,
        net_weight_z: Real,
        node_length: Real,
    ) -> Vec3 {
        let penetration = bed_z - z;
        if penetration <= 0.0 {
            return Vec3::zeros();
        }
        let kd = self.stiffness * diameter;
        let fz = root * (kd * penetration - damping * velocity.z);
        let mut f = Vec3::new(0.0, 0.0, fz);
        let normal = match self.friction_law {
            FrictionLaw::Tanh => -net_weight_z,
            FrictionLaw::Viscous { .. } => fz.abs() / root.max(Real::MIN_POSITIVE),
        };
        if self.friction_coefficient > 0.0 && normal > 0.0 {
            let vxy = Vec3::new(velocity.x, velocity.y, 0.0);
            let speed = vxy.norm();
            if speed > 0.0 {
                f -= vxy * (root * self.friction(speed, normal, node_length) / speed);
            }
        }
        f
    }
}
