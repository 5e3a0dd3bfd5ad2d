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

    /// Contact force per unit unstretched length [N/m] on a cable point at height `z` [m]
    /// moving with `velocity` [m/s], for a bed at `bed_z` [m].
    ///
    /// Vertical (eq. 15): √(1+ε) (K_g d δ − c v_z) with δ = bed_z − z > 0 and c from
    /// [`Seabed::damping_per_length`] (2ζ √(K_g d γ0), or c_A·d).
    /// Horizontal (eq. 16): √(1+ε) μ tanh(π|v_xy|/v_μ) v̂_xy · min(w_z, 0), with w_z the
    /// net weight per length (negative when the cable sinks), so friction opposes sliding.
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
    ) -> Vec3 {
        let penetration = bed_z - z;
        if penetration <= 0.0 {
            return Vec3::zeros();
        }
        let root = stretch.max(0.0).sqrt();
        let kd = self.stiffness * diameter;
        let fz = root
            * (kd * penetration - self.damping_per_length(diameter, mass_per_length) * velocity.z);
        let mut f = Vec3::new(0.0, 0.0, fz);
        if self.friction_coefficient > 0.0 && net_weight_z < 0.0 {
            let vxy = Vec3::new(velocity.x, velocity.y, 0.0);
            let speed = vxy.norm();
            if speed > 0.0 {
                let mag = (std::f64::consts::PI * speed / self.friction_velocity).tanh();
                f += vxy * (root * self.friction_coefficient * mag * net_weight_z / speed);
            }
        }
        f
    }
}
