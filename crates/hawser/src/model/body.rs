//! Rigid bodies: towed bodies, underwater vehicles, ROV cages, buoys and vessels.
//!
//! Axes: the body frame is fixed in the body with its origin at the body's reference point
//! (the point whose position the state and the results give); its orientation is the rotation
//! from body axes to global axes. Body axes follow the ship convention: x forward (surge),
//! y to port (sway), z up (heave); roll, pitch and yaw are rotations about x, y and z.
//! Lines attach to points fixed on the body.

use super::rigid_motion::RigidMotion;
use crate::math::{Mat3, Quat, Real, Vec3, Vec6};

/// How a body moves.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyKind {
    /// Six degrees of freedom integrated with the lines.
    Free,
    /// Moves as prescribed; the loads on it are reported, not integrated.
    Prescribed(RigidMotion),
}

/// The volume a body displaces, for buoyancy and hydrostatic restoring.
#[derive(Clone, Debug, PartialEq)]
pub enum Displacement {
    /// No buoyancy.
    None,
    /// Always fully submerged (deep vehicles, cages): buoyancy ρ V g at the centre of
    /// buoyancy, whatever the position.
    Submerged {
        /// Displaced volume V [m³].
        volume: Real,
    },
    /// A circular cylinder with its axis along body z (spar, buoy, cage), centred at the
    /// body's `centre_of_buoyancy`; the submerged part is taken below the instantaneous free
    /// surface at the body, so it floats, surfaces and sinks, upright or tilted
    /// ([`crate::bodies::wetted_prism`]).
    Cylinder {
        /// Radius [m].
        radius: Real,
        /// Height along body z [m].
        height: Real,
    },
    /// A box with its edges along the body axes, centred at the body's `centre_of_buoyancy`
    /// (barge, vessel hull idealised as wall-sided); submerged part as for `Cylinder`.
    Box {
        /// Length along body x [m].
        length: Real,
        /// Breadth along body y [m].
        breadth: Real,
        /// Height along body z [m].
        height: Real,
    },
}

impl Displacement {
    /// Volume of the whole shape [m³]: V, π r² h or l b h; 0 for `None`.
    pub fn volume(&self) -> Real {
        match *self {
            Displacement::None => 0.0,
            Displacement::Submerged { volume } => volume,
            Displacement::Cylinder { radius, height } => {
                std::f64::consts::PI * radius * radius * height
            }
            Displacement::Box {
                length,
                breadth,
                height,
            } => length * breadth * height,
        }
    }
}

/// A body's thrust or control force, in body axes.
#[derive(Clone, Debug, PartialEq)]
pub enum Thrust {
    /// None.
    None,
    /// Constant force [N] and moment [N·m] in body axes, about the body origin.
    Constant {
        /// Force [N].
        force: Vec3,
        /// Moment [N·m].
        moment: Vec3,
    },
    /// Piecewise-linear schedule of force and moment in body axes, held at the end values
    /// outside the table.
    Schedule {
        /// Strictly increasing times [s].
        times: Vec<Real>,
        /// Force at each time [N].
        forces: Vec<Vec3>,
        /// Moment at each time [N·m].
        moments: Vec<Vec3>,
    },
}

impl Thrust {
    /// Force [N] and moment [N·m] in body axes at time t [s]: constant, or interpolated
    /// linearly in the schedule (binary search; no allocation) and held at the end values
    /// outside it.
    pub fn at(&self, t: Real) -> (Vec3, Vec3) {
        match self {
            Thrust::None => (Vec3::zeros(), Vec3::zeros()),
            Thrust::Constant { force, moment } => (*force, *moment),
            Thrust::Schedule {
                times,
                forces,
                moments,
            } => {
                let n = times.len();
                if n == 0 {
                    return (Vec3::zeros(), Vec3::zeros());
                }
                if t <= times[0] {
                    return (forces[0], moments[0]);
                }
                if t >= times[n - 1] {
                    return (forces[n - 1], moments[n - 1]);
                }
                let j = times.partition_point(|&tj| tj <= t).clamp(1, n - 1);
                let s = (t - times[j - 1]) / (times[j] - times[j - 1]);
                (
                    forces[j - 1] * (1.0 - s) + forces[j] * s,
                    moments[j - 1] * (1.0 - s) + moments[j] * s,
                )
            }
        }
    }
}

/// Wind on a vessel's superstructure: F = ½ ρ_air C_d A |u|² in the direction of u, u the wind
/// velocity relative to the body, applied at a body-frame point.
#[derive(Clone, Debug, PartialEq)]
pub struct Wind {
    /// Wind velocity in global axes [m/s] (uniform, constant).
    pub velocity: Vec3,
    /// Drag area C_d·A [m²].
    pub drag_area: Real,
    /// Centre of wind pressure in body axes [m].
    pub centre: Vec3,
}

/// A rigid body.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Name used by points and channels.
    pub name: String,
    /// Position of the body origin at t = 0 [m] (for prescribed bodies, their motion's).
    pub position: Vec3,
    /// Orientation at t = 0 (body axes to global axes).
    pub orientation: Quat,
    /// How it moves.
    pub kind: BodyKind,
    /// Mass [kg].
    pub mass: Real,
    /// Centre of gravity in body axes [m].
    pub centre_of_gravity: Vec3,
    /// Inertia tensor about the centre of gravity in body axes [kg·m²].
    pub inertia: Mat3,
    /// Displaced volume.
    pub displacement: Displacement,
    /// Centre of the displaced volume (of the whole shape) in body axes [m]: the centre of a
    /// `Cylinder` or `Box`, the point where the buoyancy of `Submerged` acts, and the
    /// hydrodynamic centre of `None`.
    pub centre_of_buoyancy: Vec3,
    /// Added mass in body axes, per axis (surge, sway, heave [kg]; roll, pitch, yaw [kg·m²]),
    /// of the whole shape fully submerged, about the hydrodynamic centre: the centre of
    /// buoyancy when fully submerged, the centroid of the submerged volume of a partly
    /// submerged `Cylinder` or `Box`, whose coefficients are scaled by the submerged fraction
    /// V_s / V (so give the fully submerged shape's values).
    pub added_mass: Vec6,
    /// Linear drag per axis in body axes (N·s/m for the translations, N·m·s/rad for the
    /// rotations), on the velocity relative to the water at the hydrodynamic centre and on
    /// the angular velocity; scaled by the submerged fraction like `added_mass`.
    pub linear_drag: Vec6,
    /// Quadratic drag per axis in body axes, F_i = −½ ρ C_i A_i |u_i| u_i: the products
    /// C_i·A_i [m²] for the translations and C_i·A_i·L_i³ [m⁵] for the rotations (moment
    /// −½ ρ C A L³ |Ω_i| Ω_i); scaled by the submerged fraction like `added_mass`.
    pub quadratic_drag: Vec6,
    /// Thrust or control force.
    pub thrust: Thrust,
    /// Wind force, for vessels.
    pub wind: Option<Wind>,
}
