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
    /// Moves as a host program sets it at each coupling step (a floating platform in OpenFAST
    /// or WEC-Sim): its pose starts at the body's `position` and `orientation`, and the loads
    /// of the lines on it are read back ([`crate::Session::body_reaction`]).
    Coupled,
    /// Pinned at its origin (the reference point): the origin moves as the [`Pin`] says, the
    /// three rotations are free and integrated with the lines (MoorDyn's `CoupledPinned`
    /// bodies and `Pinned` rods). Its equations are the rotational rows of the free body's
    /// about the pin ([`crate::bodies`], "Pinned bodies"); the pin supplies the force that
    /// keeps the origin on its track ([`crate::Session::pin_reaction`]).
    Pinned(Pin),
}

impl BodyKind {
    /// Whether the body has rotations of its own to integrate: a free or a pinned body (it
    /// then owns a block of the state and a row block of the coupled system).
    pub fn integrates(&self) -> bool {
        matches!(self, BodyKind::Free | BodyKind::Pinned(_))
    }

    /// Degrees of freedom a coupling host sets for a body of this kind: 6 for a coupled body
    /// (pose), 3 for a body on a coupled pin (the pin's position), 0 otherwise (MoorDyn's
    /// layout: a `CoupledPinned` body takes 3 entries).
    pub fn coupled_dofs(&self) -> usize {
        match self {
            BodyKind::Coupled => 6,
            BodyKind::Pinned(Pin::Coupled) => 3,
            _ => 0,
        }
    }

    /// The pin's motion of a pinned body, `None` for other kinds.
    pub fn pin(&self) -> Option<&Pin> {
        match self {
            BodyKind::Pinned(p) => Some(p),
            _ => None,
        }
    }
}

/// How the pin of a [`BodyKind::Pinned`] body moves: the motion of the body's origin.
#[derive(Clone, Debug, PartialEq)]
pub enum Pin {
    /// Held at the body's `position`.
    Fixed,
    /// On a prescribed rigid motion: the pin follows the motion's origin (position, velocity
    /// and acceleration); the motion's orientation is not used (the body turns freely).
    Prescribed(RigidMotion),
    /// Set by a host program at each coupling step (three translations, MoorDyn's
    /// `CoupledPinned`), starting at the body's `position`.
    Coupled,
    /// On a point fixed on another body (the parent, MoorDyn's `Body#Pinned` rods): the pin
    /// is the parent's point p = o_p + R_p ρ₀ (position, velocity v_p + ω_p × ρ and
    /// acceleration a_p + α_p × ρ + ω_p × (ω_p × ρ), ρ = R_p ρ₀), and the body pushes back on
    /// the parent at that point ([`crate::bodies`], "Pinned bodies"). The body's `position`
    /// is the point's position at t = 0. The parent is free, pinned (not itself on a body),
    /// prescribed or coupled.
    Body {
        /// Index of the parent body in the model.
        body: usize,
        /// The point ρ₀ in the parent's body axes, from the parent's origin [m].
        point: Vec3,
    },
}

impl Pin {
    /// The parent body and the point on it [m, parent's body axes] of a pin on a body.
    pub fn parent(&self) -> Option<(usize, Vec3)> {
        match self {
            Pin::Body { body, point } => Some((*body, *point)),
            _ => None,
        }
    }
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

/// Which speed scales a body's quadratic drag along each axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DragSpeed {
    /// Each axis by its own component: F_i = −½ ρ Q_i |u_i| u_i (OrcaFlex's 6D buoys, and
    /// hawser's default).
    #[default]
    Component,
    /// Each axis by the magnitude of the relative velocity: F_i = −½ ρ Q_i |u| u_i, and
    /// M_i = −½ ρ Q_{3+i} |Ω| Ω_i for the rotations: MoorDyn's bodies (`Body::doRHS`, drag
    /// R diag(CdA) Rᵀ v |v|). For equal coefficients this is drag along the relative velocity.
    Magnitude,
}

/// A rigid cylindrical member of a body (MoorDyn's rod): side drag and added mass on its
/// length, drag and added mass at its wet ends, buoyancy of its wet part, vertical seabed
/// contact, lumped at N + 1 nodes along it ([`crate::bodies::member_loads`]). Its mass is the
/// body's: give the body's `mass`, centre of gravity and inertia with the member in them.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// End A in body axes from the body origin [m].
    pub end_a: Vec3,
    /// End B in body axes from the body origin [m].
    pub end_b: Vec3,
    /// Diameter d [m].
    pub diameter: Real,
    /// Segments N ≥ 1: nodes at the ends and N − 1 between, each standing for its share of
    /// the length (half a segment at an end).
    pub segments: usize,
    /// Normal drag coefficient C_dn on d per unit length [-].
    pub normal_drag: Real,
    /// Normal added-mass coefficient C_an on π d²/4 per unit length [-].
    pub normal_added_mass: Real,
    /// Drag coefficient of each wet end on its area π d²/4 [-] (MoorDyn's `CdEnd`).
    pub end_drag: Real,
    /// Added-mass coefficient of each wet end along the axis on the half-sphere volume
    /// (2/3) π (d/2)³ [-] (MoorDyn's `CaEnd`).
    pub end_added_mass: Real,
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
    /// Which speed multiplies the quadratic drag: each axis's own (default) or the magnitude
    /// of the relative velocity (MoorDyn's bodies).
    pub drag_speed: DragSpeed,
    /// Where added mass, fluid inertia and drag act, in body axes from the origin [m], when
    /// it is not the centre of buoyancy: only for a `Submerged` displacement or none (a
    /// `Cylinder` or `Box` takes the centroid of its wet volume). MoorDyn's bodies put their
    /// added mass and drag at the body origin and their buoyancy at the centre of gravity.
    pub hydrodynamic_centre: Option<Vec3>,
    /// Cylindrical members with their own hydrodynamics (MoorDyn's rods), beside the body's
    /// displacement, added mass and drag above.
    pub members: Vec<Member>,
    /// Thrust or control force.
    pub thrust: Thrust,
    /// Wind force, for vessels.
    pub wind: Option<Wind>,
}

impl Body {
    /// A free body of `mass` [kg] and `inertia` about its centre of gravity [kg·m²] at the
    /// global origin with body axes along the global ones, its centre of gravity at its
    /// origin, and nothing else: no displacement, added mass, drag, thrust or wind. Set the
    /// other fields with struct update syntax.
    pub fn new(name: &str, mass: Real, inertia: Mat3) -> Self {
        Self {
            name: name.into(),
            position: Vec3::zeros(),
            orientation: Quat::identity(),
            kind: BodyKind::Free,
            mass,
            centre_of_gravity: Vec3::zeros(),
            inertia,
            displacement: Displacement::None,
            centre_of_buoyancy: Vec3::zeros(),
            added_mass: Vec6::zeros(),
            linear_drag: Vec6::zeros(),
            quadratic_drag: Vec6::zeros(),
            drag_speed: DragSpeed::Component,
            hydrodynamic_centre: None,
            members: Vec::new(),
            thrust: Thrust::None,
            wind: None,
        }
    }
}

impl Body {
    /// Kinematics at t = 0: a free or coupled body at rest at its initial pose, a prescribed
    /// body on its motion, a pinned body at its initial orientation at rest about its pin,
    /// the pin on its motion (a pin on a body: at rest at the body's `position`, which is the
    /// parent's point at t = 0; the system moves it with its parent,
    /// [`crate::System::point_kinematics`]).
    pub fn initial_kinematics(&self) -> super::RigidKinematics {
        match &self.kind {
            BodyKind::Free | BodyKind::Coupled => {
                super::RigidKinematics::at_rest(self.position, self.orientation)
            }
            BodyKind::Prescribed(m) => m.kinematics(0.0),
            BodyKind::Pinned(pin) => {
                let mut k = super::RigidKinematics::at_rest(self.position, self.orientation);
                let track = matches!(pin, Pin::Coupled)
                    .then(|| super::BodyTrack::at_rest(self.position, self.orientation));
                crate::bodies::follow_pin(
                    &mut k,
                    crate::bodies::pin_kinematics(pin, &self.position, track.as_ref(), None, 0.0),
                );
                k
            }
        }
    }

    /// Checks the physical ranges: a positive finite mass, an inertia tensor that is finite,
    /// symmetric (to 1e-9 of its largest entry) and positive definite, a finite pose and
    /// centres, a shape with positive dimensions (a volume ≥ 0), added mass and drag
    /// coefficients ≥ 0, a thrust schedule with strictly increasing times and as many forces
    /// and moments as times, a wind with a drag area ≥ 0. The error names the field and says
    /// why. [`super::Model::validate`] calls it.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        let finite3 = |v: &Vec3| v.iter().all(|x| x.is_finite());
        // Only a free or pinned body's mass and inertia enter its motion; a fixed, prescribed
        // or coupled one may leave them zero (MoorDyn's coupled bodies do).
        let free = self.kind.integrates();
        if !self.mass.is_finite() || !(self.mass > 0.0 || (!free && self.mass == 0.0)) {
            return Err((
                "mass",
                format!(
                    "must be {} kg and finite, not {}",
                    if free { "> 0" } else { "≥ 0" },
                    self.mass
                ),
            ));
        }
        let i = &self.inertia;
        let scale = i.abs().max();
        if !i.iter().all(|x| x.is_finite()) {
            return Err(("inertia", "must be finite".into()));
        }
        if (i - i.transpose()).abs().max() > 1e-9 * scale {
            return Err(("inertia", "must be symmetric (I_xy = I_yx, ...)".into()));
        }
        if free && (i.cholesky().is_none() || !(scale > 0.0)) {
            return Err((
                "inertia",
                "must be positive definite (every principal moment > 0 kg·m²)".into(),
            ));
        }
        if let Some(p) = &self.hydrodynamic_centre {
            if !finite3(p) {
                return Err(("hydrodynamic_centre", "must be finite".into()));
            }
            if matches!(
                self.displacement,
                Displacement::Cylinder { .. } | Displacement::Box { .. }
            ) {
                return Err((
                    "hydrodynamic_centre",
                    "is the centroid of the wet volume for a cylinder or box displacement; \
                     give it only with a submerged displacement or none"
                        .into(),
                ));
            }
        }
        let q = &self.orientation;
        if !(finite3(&self.position) && q.w.is_finite() && finite3(&q.imag())) {
            return Err(("position", "pose must be finite".into()));
        }
        if !finite3(&self.centre_of_gravity) {
            return Err(("centre_of_gravity", "must be finite".into()));
        }
        if !finite3(&self.centre_of_buoyancy) {
            return Err(("centre_of_buoyancy", "must be finite".into()));
        }
        let positive = |x: Real| x > 0.0 && x.is_finite();
        match self.displacement {
            Displacement::None => {}
            Displacement::Submerged { volume } => {
                if !(volume >= 0.0) || !volume.is_finite() {
                    return Err(("displacement", "volume must be ≥ 0 m³".into()));
                }
            }
            Displacement::Cylinder { radius, height } => {
                if !positive(radius) || !positive(height) {
                    return Err((
                        "displacement",
                        "cylinder radius and height must be > 0 m".into(),
                    ));
                }
            }
            Displacement::Box {
                length,
                breadth,
                height,
            } => {
                if !positive(length) || !positive(breadth) || !positive(height) {
                    return Err((
                        "displacement",
                        "box length, breadth and height must be > 0 m".into(),
                    ));
                }
            }
        }
        let non_negative = |v: &Vec6| v.iter().all(|x| *x >= 0.0 && x.is_finite());
        if !non_negative(&self.added_mass) {
            return Err(("added_mass", "must be ≥ 0 (kg, kg·m²) and finite".into()));
        }
        if !non_negative(&self.linear_drag) {
            return Err((
                "linear_drag",
                "must be ≥ 0 (N·s/m, N·m·s/rad) and finite".into(),
            ));
        }
        if !non_negative(&self.quadratic_drag) {
            return Err(("quadratic_drag", "must be ≥ 0 (m², m⁵) and finite".into()));
        }
        for m in &self.members {
            let ok = finite3(&m.end_a)
                && finite3(&m.end_b)
                && (m.end_b - m.end_a).norm() > 0.0
                && m.diameter > 0.0
                && m.diameter.is_finite()
                && m.segments >= 1
                && [
                    m.normal_drag,
                    m.normal_added_mass,
                    m.end_drag,
                    m.end_added_mass,
                ]
                .iter()
                .all(|c| *c >= 0.0 && c.is_finite());
            if !ok {
                return Err((
                    "members",
                    "a member needs distinct finite ends, a diameter > 0 m, at least one \
                     segment and coefficients ≥ 0"
                        .into(),
                ));
            }
        }
        match &self.thrust {
            Thrust::None => {}
            Thrust::Constant { force, moment } => {
                if !finite3(force) || !finite3(moment) {
                    return Err(("thrust", "force and moment must be finite".into()));
                }
            }
            Thrust::Schedule {
                times,
                forces,
                moments,
            } => {
                if times.is_empty() || forces.len() != times.len() || moments.len() != times.len() {
                    return Err((
                        "thrust",
                        "the schedule needs at least one time and a force and a moment per time"
                            .into(),
                    ));
                }
                if !times.iter().all(|t| t.is_finite()) || times.windows(2).any(|w| !(w[1] > w[0]))
                {
                    return Err((
                        "thrust",
                        "schedule times must be finite and strictly increasing".into(),
                    ));
                }
                if !forces.iter().chain(moments).all(finite3) {
                    return Err((
                        "thrust",
                        "schedule forces and moments must be finite".into(),
                    ));
                }
            }
        }
        if let Some(w) = &self.wind
            && (!finite3(&w.velocity)
                || !finite3(&w.centre)
                || !(w.drag_area >= 0.0)
                || !w.drag_area.is_finite())
        {
            return Err((
                "wind",
                "velocity and centre must be finite and drag_area ≥ 0 m²".into(),
            ));
        }
        Ok(())
    }
}
