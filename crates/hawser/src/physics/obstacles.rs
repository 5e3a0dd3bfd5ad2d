//! Obstacles in contact with lines: fixed or moving spheres and cylinders (the elastic-link
//! paper's "obstacles in water", §5, parameters 12–14: their coordinates, size and speed; the
//! paper names them and gives no contact law, so the law here is ours, built like the seabed
//! contact of DG paper eqs. 15–16 in [`crate::physics::seabed`]).
//!
//! A cable point at r with velocity v, diameter d and stretch 1 + ε touches an obstacle when
//! its surface does: with D(r) the distance from r to the obstacle's solid (negative inside,
//! the depth to the nearest surface) and n̂ the outward normal there, the gap is
//! g = D(r) − d/2 and the penetration δ = −g > 0. The force per unit unstretched length on the
//! cable is then
//!
//!   f = √(1+ε) [ N n̂ − μ N tanh(π |v_t| / v_μ) v̂_t ],   N = max(k δ − c v_n, 0),
//!
//! with v* = v − V the velocity relative to the obstacle (V its centre's velocity: obstacles
//! translate, they do not spin), v_n = v*·n̂ its normal part and v_t = v* − v_n n̂ its sliding
//! part. k [N/m²] is the contact stiffness per unit length of cable (the seabed's K_g d),
//! c [N·s/m²] the damping per unit length, 2ζ√(k γ0) for a damping ratio ζ of the contact
//! spring with the cable's own mass γ0 (the seabed's eq. 15); √(1+ε) is the seabed's factor
//! for a volume-preserving cable (DG paper §2: the contact length grows by 1+ε, the diameter
//! shrinks by √(1+ε)). Friction is Coulomb's μN on the normal contact force, regularised by the
//! seabed's tanh(π|v_t|/v_μ) (eq. 16); unlike the seabed's it acts on N, which here carries the
//! tension's pull around the obstacle (a capstan), not the cable's weight. The normal force is
//! clamped at zero: an obstacle pushes, it never pulls a cable leaving it fast.
//!
//! Geometry: a sphere of radius R about its centre c; a cylinder of radius R about the line
//! through c along the unit axis â, infinite or of length L centred on c (flat end caps, sharp
//! rims: the distance to the solid is exact, so a cable wraps round a rim as round a tube of
//! radius d/2). The centre follows a prescribed [`Motion`]; the axis keeps its direction.
//!
//! Every function here is allocation-free; [`Obstacle::may_touch`] is the quick bounding test
//! the formulations use to skip a far obstacle for a whole line or element.

use crate::math::{Real, Vec3};
use crate::model::Motion;

/// Shape of an obstacle, about its centre.
#[derive(Clone, Debug, PartialEq)]
pub enum ObstacleShape {
    /// A sphere.
    Sphere {
        /// Radius R [m].
        radius: Real,
    },
    /// A circular cylinder.
    Cylinder {
        /// Radius R [m].
        radius: Real,
        /// Direction of the axis [-], a unit vector (its direction at the start; obstacles
        /// do not rotate).
        axis: Vec3,
        /// Length L [m] along the axis, centred on the centre; `None` for an infinite
        /// cylinder.
        length: Option<Real>,
    },
}

/// Damping of an obstacle's normal contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ObstacleDamping {
    /// Damping ratio ζ [-] of the contact spring with the cable's own mass:
    /// c = 2ζ√(k γ0) per unit length (as the seabed's, DG paper eq. 15); 1 is critical.
    Ratio(Real),
    /// Damping coefficient per unit length of cable c [N·s/m²].
    PerLength(Real),
}

/// A rigid obstacle that lines touch: a sphere or a cylinder whose centre follows a prescribed
/// motion, with penalty contact, damping and friction (see the module doc for the law).
#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    /// Name, used by channels (`NAME.force_x`).
    pub name: String,
    /// Shape about the centre.
    pub shape: ObstacleShape,
    /// Trajectory of the centre [m] (a fixed obstacle has [`Motion::Fixed`]).
    pub motion: Motion,
    /// Contact stiffness k per unit length of cable [N/m²]: the normal force per unit length
    /// per metre of penetration.
    pub stiffness: Real,
    /// Damping of the normal contact.
    pub damping: ObstacleDamping,
    /// Coulomb friction coefficient μ [-] on the normal contact force.
    pub friction_coefficient: Real,
    /// Sliding speed v_μ [m/s] over which friction builds up, tanh(π|v_t|/v_μ) (as the
    /// seabed's, DG paper eq. 16).
    pub friction_velocity: Real,
}

impl Default for Obstacle {
    /// A fixed unit sphere at the origin with k = 1e6 N/m² (a 10 kN/m contact load
    /// penetrates 1 cm), critical damping, no friction and v_μ = 0.01 m/s (the seabed's).
    fn default() -> Self {
        Self {
            name: "obstacle".into(),
            shape: ObstacleShape::Sphere { radius: 1.0 },
            motion: Motion::Fixed {
                position: Vec3::zeros(),
            },
            stiffness: 1.0e6,
            damping: ObstacleDamping::Ratio(1.0),
            friction_coefficient: 0.0,
            friction_velocity: 0.01,
        }
    }
}

/// Position and velocity of an obstacle's centre at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObstacleKinematics {
    /// Centre [m].
    pub centre: Vec3,
    /// Velocity of the centre, and of every point of the obstacle [m/s].
    pub velocity: Vec3,
}

/// Where a cable point penetrates an obstacle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Penetration {
    /// Penetration δ = d/2 − D(r) > 0 [m] (D the distance to the obstacle's solid).
    pub depth: Real,
    /// Outward unit normal of the obstacle at the nearest surface point [-].
    pub normal: Vec3,
}

impl Obstacle {
    /// The centre's position and velocity at time `time` [s].
    #[inline]
    pub fn kinematics(&self, time: Real) -> ObstacleKinematics {
        match &self.motion {
            Motion::Fixed { position } => ObstacleKinematics {
                centre: *position,
                velocity: Vec3::zeros(),
            },
            m => {
                let (centre, velocity, _) = m.kinematics(time);
                ObstacleKinematics { centre, velocity }
            }
        }
    }

    /// Signed distance D [m] from `point` to the obstacle's solid with its centre at `centre`
    /// (positive outside; inside, minus the depth to the nearest surface), and the outward
    /// unit normal at the nearest surface point. Exact for both shapes, rims and caps
    /// included. On the centre (axis) itself, where the normal is undefined, it picks +z (a
    /// direction normal to the axis).
    #[inline]
    pub fn signed_distance(&self, centre: &Vec3, point: &Vec3) -> (Real, Vec3) {
        let d = point - centre;
        match &self.shape {
            ObstacleShape::Sphere { radius } => {
                let r = d.norm();
                let n = if r > 0.0 { d / r } else { Vec3::z() };
                (r - radius, n)
            }
            ObstacleShape::Cylinder {
                radius,
                axis,
                length,
            } => {
                let s = d.dot(axis);
                let radial = d - axis * s;
                let rho = radial.norm();
                let radial_hat = if rho > 0.0 {
                    radial / rho
                } else {
                    // On the axis: any normal to it.
                    let t = if axis.z.abs() < 0.9 {
                        Vec3::z()
                    } else {
                        Vec3::x()
                    };
                    (t - axis * t.dot(axis)).normalize()
                };
                let Some(length) = length else {
                    return (rho - radius, radial_hat);
                };
                let half = 0.5 * length;
                let axial_hat = if s >= 0.0 { *axis } else { -axis };
                let (dr, ds) = (rho - radius, s.abs() - half);
                if dr <= 0.0 && ds <= 0.0 {
                    // Inside: the nearer of the mantle and the cap.
                    if dr >= ds {
                        (dr, radial_hat)
                    } else {
                        (ds, axial_hat)
                    }
                } else {
                    let (a, b) = (dr.max(0.0), ds.max(0.0));
                    let dist = (a * a + b * b).sqrt();
                    (dist, (radial_hat * a + axial_hat * b) / dist)
                }
            }
        }
    }

    /// The penetration of a cable point of diameter `diameter` [m] at `position` [m], or
    /// `None` when its surface is clear of the obstacle (gap D − d/2 ≥ 0).
    #[inline]
    pub fn penetration(
        &self,
        kinematics: &ObstacleKinematics,
        position: &Vec3,
        diameter: Real,
    ) -> Option<Penetration> {
        let (distance, normal) = self.signed_distance(&kinematics.centre, position);
        let depth = 0.5 * diameter - distance;
        (depth > 0.0).then_some(Penetration { depth, normal })
    }

    /// Whether a ball of radius `radius` [m] about `centre` [m] can reach the obstacle: the
    /// quick bounding test (exact for the ball) by which the formulations skip a far obstacle
    /// for a line or an element. Include the cable radius in `radius`.
    #[inline]
    pub fn may_touch(&self, kinematics: &ObstacleKinematics, centre: &Vec3, radius: Real) -> bool {
        self.signed_distance(&kinematics.centre, centre).0 < radius
    }

    /// Normal contact damping per unit length c [N·s/m²] on a cable of `mass_per_length` γ0
    /// [kg/m]: 2ζ√(k γ0), or the coefficient given.
    #[inline]
    pub fn damping_per_length(&self, mass_per_length: Real) -> Real {
        match self.damping {
            ObstacleDamping::Ratio(zeta) => 2.0 * zeta * (self.stiffness * mass_per_length).sqrt(),
            ObstacleDamping::PerLength(c) => c,
        }
    }

    /// Largest slope d(friction)/d(sliding speed) per unit length [N·s/m²] under a normal
    /// contact load `normal` [N/m]: μ N π / v_μ, at rest (for a stable-step bound).
    pub fn friction_slope(&self, normal: Real) -> Real {
        self.friction_coefficient * normal * std::f64::consts::PI / self.friction_velocity
    }

    /// Contact force per unit unstretched length [N/m] on a cable point that penetrates as
    /// `penetration` says, moving at `velocity` [m/s], of γ0 `mass_per_length` [kg/m] and
    /// stretch 1 + ε `stretch` [-]: f = √(1+ε) [N n̂ − μ N tanh(π|v_t|/v_μ) v̂_t] with
    /// N = max(k δ − c v_n, 0) (module doc).
    #[inline]
    pub fn contact_force(
        &self,
        kinematics: &ObstacleKinematics,
        penetration: &Penetration,
        velocity: &Vec3,
        mass_per_length: Real,
        stretch: Real,
    ) -> Vec3 {
        let n = penetration.normal;
        let relative = velocity - kinematics.velocity;
        let vn = relative.dot(&n);
        let normal = (self.stiffness * penetration.depth
            - self.damping_per_length(mass_per_length) * vn)
            .max(0.0);
        let mut f = n * normal;
        if self.friction_coefficient > 0.0 && normal > 0.0 {
            let sliding = relative - n * vn;
            let speed = sliding.norm();
            if speed > 0.0 {
                let friction = self.friction_coefficient
                    * normal
                    * (std::f64::consts::PI * speed / self.friction_velocity).tanh();
                f -= sliding * (friction / speed);
            }
        }
        f * stretch.max(0.0).sqrt()
    }

    /// Contact force per unit unstretched length [N/m] on a cable point at `position` [m]
    /// moving at `velocity` [m/s], of `diameter` [m], γ0 `mass_per_length` [kg/m] and stretch
    /// `stretch` [-], at time `time` [s]; zero when clear. [`Obstacle::penetration`] then
    /// [`Obstacle::contact_force`].
    #[inline]
    pub fn force_at(
        &self,
        time: Real,
        position: &Vec3,
        velocity: &Vec3,
        diameter: Real,
        mass_per_length: Real,
        stretch: Real,
    ) -> Vec3 {
        let k = self.kinematics(time);
        match self.penetration(&k, position, diameter) {
            Some(p) => self.contact_force(&k, &p, velocity, mass_per_length, stretch),
            None => Vec3::zeros(),
        }
    }

    /// Radius [m] of the smallest ball about the centre holding the obstacle (∞ for an
    /// infinite cylinder).
    pub fn bounding_radius(&self) -> Real {
        match &self.shape {
            ObstacleShape::Sphere { radius } => *radius,
            ObstacleShape::Cylinder {
                radius,
                length: Some(l),
                ..
            } => (radius * radius + 0.25 * l * l).sqrt(),
            ObstacleShape::Cylinder { length: None, .. } => Real::INFINITY,
        }
    }

    /// Checks the parameters: radius and length > 0, a unit axis, k ≥ 0, damping ≥ 0, μ ≥ 0,
    /// v_μ > 0, all finite. The message names the parameter, its unit and its range.
    pub fn validate(&self) -> Result<(), String> {
        let positive = |x: Real| x.is_finite() && x > 0.0;
        let non_negative = |x: Real| x.is_finite() && x >= 0.0;
        match &self.shape {
            ObstacleShape::Sphere { radius } | ObstacleShape::Cylinder { radius, .. }
                if !positive(*radius) =>
            {
                return Err(format!("radius {radius} must be > 0 m"));
            }
            ObstacleShape::Cylinder { axis, length, .. } => {
                if !axis.iter().all(|x| x.is_finite()) || (axis.norm() - 1.0).abs() > 1e-9 {
                    return Err(format!(
                        "axis [{}, {}, {}] must be a unit vector",
                        axis.x, axis.y, axis.z
                    ));
                }
                if let Some(l) = length
                    && !positive(*l)
                {
                    return Err(format!(
                        "length {l} must be > 0 m (omit it for an infinite cylinder)"
                    ));
                }
            }
            _ => {}
        }
        if !non_negative(self.stiffness) {
            return Err(format!("stiffness {} must be ≥ 0 N/m²", self.stiffness));
        }
        match self.damping {
            ObstacleDamping::Ratio(z) if !non_negative(z) => {
                return Err(format!("damping ratio {z} must be ≥ 0"));
            }
            ObstacleDamping::PerLength(c) if !non_negative(c) => {
                return Err(format!("damping {c} must be ≥ 0 N·s/m²"));
            }
            _ => {}
        }
        if !non_negative(self.friction_coefficient) {
            return Err(format!(
                "friction coefficient {} must be ≥ 0",
                self.friction_coefficient
            ));
        }
        if !positive(self.friction_velocity) {
            return Err(format!(
                "friction velocity {} must be > 0 m/s",
                self.friction_velocity
            ));
        }
        Ok(())
    }
}

/// Sum of the contact forces per unit unstretched length [N/m] of every obstacle on one cable
/// point (arguments as [`Obstacle::force_at`]): the formulations that evaluate their loads
/// point by point (DG) call this; `fe` and `hermite` go through [`LineBall`] first.
#[inline]
pub fn total_force_at(
    obstacles: &[Obstacle],
    time: Real,
    position: &Vec3,
    velocity: &Vec3,
    diameter: Real,
    mass_per_length: Real,
    stretch: Real,
) -> Vec3 {
    let mut f = Vec3::zeros();
    for o in obstacles {
        f += o.force_at(time, position, velocity, diameter, mass_per_length, stretch);
    }
    f
}

/// A ball holding a set of points (from their axis-aligned bounding box), for
/// [`Obstacle::may_touch`].
#[derive(Clone, Copy, Debug)]
pub struct LineBall {
    lo: Vec3,
    hi: Vec3,
}

impl Default for LineBall {
    fn default() -> Self {
        Self::new()
    }
}

impl LineBall {
    /// An empty set.
    #[inline]
    pub fn new() -> Self {
        Self {
            lo: Vec3::repeat(Real::INFINITY),
            hi: Vec3::repeat(Real::NEG_INFINITY),
        }
    }

    /// Adds a point [m].
    #[inline]
    pub fn add(&mut self, p: &Vec3) {
        self.lo = self.lo.inf(p);
        self.hi = self.hi.sup(p);
    }

    /// Centre [m] and radius [m] of a ball holding every point added.
    #[inline]
    pub fn ball(&self) -> (Vec3, Real) {
        ((self.lo + self.hi) * 0.5, 0.5 * (self.hi - self.lo).norm())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cylinder(length: Option<Real>) -> Obstacle {
        Obstacle {
            shape: ObstacleShape::Cylinder {
                radius: 1.0,
                axis: Vec3::y(),
                length,
            },
            ..Default::default()
        }
    }

    /// The signed distance is exact: against closed forms at points outside, inside, beyond
    /// the caps and round the rims, and its normal is its gradient (central differences).
    #[test]
    fn signed_distance_is_exact_and_its_normal_is_its_gradient() {
        let c = Vec3::new(1.0, 2.0, 3.0);
        let sphere = Obstacle::default();
        let (d, n) = sphere.signed_distance(&c, &(c + Vec3::new(0.0, 3.0, 4.0)));
        assert!((d - 4.0).abs() < 1e-15 && (n - Vec3::new(0.0, 0.6, 0.8)).norm() < 1e-15);
        let finite = cylinder(Some(4.0));
        let infinite = cylinder(None);
        for (p, expected, expected_infinite) in [
            (Vec3::new(3.0, 0.0, 0.0), 2.0, 2.0),
            (Vec3::new(0.0, 5.0, 0.5), 3.0, -0.5),
            (Vec3::new(4.0, 6.0, 0.0), 5.0, 3.0),
            (Vec3::new(0.5, 1.0, 0.0), -0.5, -0.5),
            (Vec3::new(0.0, 1.8, 0.1), -0.2, -0.9),
        ] {
            let (d, _) = finite.signed_distance(&c, &(c + p));
            let (di, _) = infinite.signed_distance(&c, &(c + p));
            assert!((d - expected).abs() < 1e-14, "{p:?}: {d} vs {expected}");
            assert!((di - expected_infinite).abs() < 1e-14, "{p:?}: {di}");
        }
        let h = 1e-6;
        for o in [&sphere, &finite, &infinite] {
            for p in [
                Vec3::new(0.3, 2.7, 1.1),
                Vec3::new(1.7, 0.4, -0.2),
                Vec3::new(0.2, -1.9, 0.1),
                Vec3::new(-0.6, 0.3, 0.2),
            ] {
                let (_, n) = o.signed_distance(&c, &(c + p));
                let grad = Vec3::from_fn(|k, _| {
                    let e = Vec3::from_fn(|j, _| if j == k { h } else { 0.0 });
                    (o.signed_distance(&c, &(c + p + e)).0 - o.signed_distance(&c, &(c + p - e)).0)
                        / (2.0 * h)
                });
                assert!((grad - n).norm() < 1e-8, "{:?} at {p:?}", o.shape);
            }
        }
    }

    /// The force follows the law term by term: k δ √(1+ε) along the normal at rest, the
    /// damping c = 2ζ√(kγ0) on the normal velocity, no pull when leaving fast, and friction
    /// μN opposing the sliding velocity relative to the moving obstacle.
    #[test]
    fn force_follows_the_contact_law() {
        let mut o = Obstacle {
            stiffness: 4.0e4,
            friction_coefficient: 0.3,
            ..Default::default()
        };
        let gamma = 2.0;
        let c = 2.0 * (4.0e4 * gamma as Real).sqrt();
        assert_eq!(o.damping_per_length(gamma), c);
        // A cable of d = 0.1 whose axis is 1.04 m from the centre: δ = 0.01 m.
        let r = Vec3::new(0.0, 0.0, 1.04);
        let stretch: Real = 1.21;
        let f = o.force_at(0.0, &r, &Vec3::zeros(), 0.1, gamma, stretch);
        assert!(
            (f - Vec3::new(0.0, 0.0, 400.0 * 1.1)).norm() < 1e-9,
            "{f:?}"
        );
        // Approaching at 0.5 m/s.
        let f = o.force_at(0.0, &r, &Vec3::new(0.0, 0.0, -0.5), 0.1, gamma, 1.0);
        assert!((f.z - (400.0 + 0.5 * c)).abs() < 1e-9);
        // Leaving fast: no adhesion.
        let f = o.force_at(0.0, &r, &Vec3::new(0.0, 0.0, 5.0), 0.1, gamma, 1.0);
        assert_eq!(f, Vec3::zeros());
        // Sliding along x well above v_μ, on an obstacle moving along y at 1 m/s: the
        // relative sliding velocity is (1, −1, 0)/√2 · √2.
        o.motion = Motion::ConstantVelocity {
            start: Vec3::zeros(),
            velocity: Vec3::y(),
        };
        let f = o.force_at(0.0, &r, &Vec3::new(1.0, 0.0, 0.0), 0.1, gamma, 1.0);
        let friction = 0.3 * 400.0 * (std::f64::consts::PI * 2f64.sqrt() / 0.01).tanh();
        let expected = Vec3::new(-1.0, 1.0, 0.0) / 2f64.sqrt() * friction + Vec3::z() * 400.0;
        assert!((f - expected).norm() < 1e-9, "{f:?} vs {expected:?}");
        // Clear of it: nothing.
        let f = o.force_at(
            0.0,
            &Vec3::new(0.0, 0.0, 1.06),
            &Vec3::zeros(),
            0.1,
            gamma,
            1.0,
        );
        assert_eq!(f, Vec3::zeros());
    }

    #[test]
    fn bounding_ball_and_quick_test_never_miss_a_contact() {
        let o = cylinder(Some(2.0));
        let k = o.kinematics(0.0);
        let mut ball = LineBall::new();
        for p in [Vec3::new(1.2, 0.0, 0.0), Vec3::new(5.0, 3.0, 1.0)] {
            ball.add(&p);
        }
        let (c, r) = ball.ball();
        // The first point touches with a 0.5 m cable: the ball must be seen as touching.
        assert!(o.penetration(&k, &Vec3::new(1.2, 0.0, 0.0), 0.5).is_some());
        assert!(o.may_touch(&k, &c, r + 0.25));
        assert!(!o.may_touch(&k, &Vec3::new(10.0, 0.0, 0.0), 1.0));
        assert!(o.validate().is_ok());
        let bad = cylinder(Some(-1.0));
        assert!(bad.validate().unwrap_err().contains("length"));
    }
}
