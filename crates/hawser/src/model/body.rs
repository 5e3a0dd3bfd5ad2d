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
    /// A vertical cylinder in body axes (spar, buoy, cage): radius, height and the body-frame
    /// centre of its volume; the submerged part is taken below the instantaneous free surface
    /// at the body, so it floats, surfaces and sinks.
    Cylinder {
        /// Radius [m].
        radius: Real,
        /// Height along body z [m].
        height: Real,
    },
    /// A box in body axes (barge, vessel hull idealised as wall-sided).
    Box {
        /// Length along body x [m].
        length: Real,
        /// Breadth along body y [m].
        breadth: Real,
        /// Height along body z [m].
        height: Real,
    },
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
    /// Centre of the displaced volume (of the whole shape) in body axes [m].
    pub centre_of_buoyancy: Vec3,
    /// Added mass in body axes, per axis (surge, sway, heave [kg]; roll, pitch, yaw [kg·m²]),
    /// about the centre of buoyancy.
    pub added_mass: Vec6,
    /// Linear drag per axis in body axes (N·s/m for the translations, N·m·s/rad for the
    /// rotations), on the velocity relative to the water at the centre of buoyancy.
    pub linear_drag: Vec6,
    /// Quadratic drag per axis in body axes, F_i = −½ ρ C_i A_i |u_i| u_i: the products
    /// C_i·A_i [m²] for the translations and C_i·A_i·L_i³ [m⁵] for the rotations.
    pub quadratic_drag: Vec6,
    /// Thrust or control force.
    pub thrust: Thrust,
    /// Wind force, for vessels.
    pub wind: Option<Wind>,
}
