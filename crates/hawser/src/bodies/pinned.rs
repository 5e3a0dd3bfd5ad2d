//! Pinned bodies: a rigid body whose origin (the pin) moves as given while it turns freely
//! ([`crate::model::BodyKind::Pinned`]; MoorDyn's `CoupledPinned` bodies and `Pinned` and
//! `Body#Pinned` rods).
//!
//! # Equations
//!
//! The free body's equations about its origin o, in global axes ([`crate::model::Body::loads`]
//! and the lines' end loads through the points on the body, [`crate::linalg::CoupledSystem`]),
//!
//! ```text
//! [M_tt  M_tr] [a_o]   [F  ]   [R]
//! [M_rt  M_rr] [α  ] = [M_o] + [0]
//! ```
//!
//! hold for a pinned body with a_o = a_pin [m/s²] given by the pin's motion and an unknown pin
//! force R [N] (the force the pin applies to the body at o, which has no moment about o). The
//! blocks: M_tt = m 1 + A_tt [kg], M_tr = −m [c]× + A_tr and M_rt = m [c]× + A_rt [kg·m],
//! M_rr = I_o + A_rr [kg·m²] with I_o = R I_G Rᵀ − m [c]×[c]× the inertia about the pin (c the
//! centre of gravity from the pin, [c]× the cross-product matrix) and A the added mass moved to
//! the pin (the lines' end masses add Jᵀ A_end J, J = [1, −[ρ]×], as for a free body). F [N]
//! and M_o [N·m] hold gravity, buoyancy, fluid inertia, drag, thrust, wind, the centripetal
//! and gyroscopic terms −m ω×(ω×c), −ω×(I_o ω), and the lines' end forces and their moments
//! about the pin.
//!
//! The three rotational rows are Euler's equations about the moving pin:
//!
//! ```text
//! M_rr α = M_o − M_rt a_pin
//!        = M_o + c × (−m a_pin) − A_rt a_pin                       [N·m]
//! ```
//!
//! the moment about the pin of gravity, buoyancy, hydrodynamic and line loads, plus the moment
//! of the d'Alembert force −m a_pin at the centre of gravity (a pin accelerating at a tilts a
//! pendulum back by atan(a/g)) and the added-mass coupling −A_rt a_pin of the translational
//! added mass through its lever arm from the pin. The three translational rows give the pin
//! force once α is known:
//!
//! ```text
//! R = M_tt a_pin + M_tr α − F                                     [N]
//! ```
//!
//! and the body pushes on its pin (on the host of a coupled pin) with −R (MoorDyn's
//! `Body::getFnet` for a `CPLDPIN` body: F6net − M a over the translations).
//!
//! # A pin on another body
//!
//! A body pinned to a point of a parent body ([`crate::model::Pin::Body`]) has its origin on
//! the parent's point p = o_p + R_p ρ₀ (ρ₀ [m] in the parent's axes, ρ = R_p ρ₀). With u_p =
//! [a_op; α_p] the parent's unknowns and J = [1, −[ρ]×] (3×6), the constraint on the child's
//! origin is
//!
//! ```text
//! a_o = J u_p + ω_p × (ω_p × ρ)                                   [m/s²]
//! ```
//!
//! the child's equations about its origin are the ones above with its pin force R [N], and
//! the parent receives −R at the point: −Jᵀ R (force −R, moment ρ × (−R) [N·m] about its
//! origin) on its six rows. R is eliminated exactly by adding Jᵀ × (the child's three
//! translational rows) to the parent's six rows, then replacing the child's translational
//! rows by the constraint: a row operation on the coupled system after assembly
//! ([`crate::linalg::CoupledSystem::body_parent`], beside `body_pin`), 9 unknowns per pair.
//! The pin force for outputs is the child's translational residual R = M_tt a_o + M_tr α − F,
//! as for any pin. On a prescribed or coupled parent, whose point's acceleration is known,
//! the child is a pinned body on that known track. Statics place the child's origin on the
//! parent's point, seek the child's rotational equilibrium, and add the child's net force F
//! and its moment ρ × F to the parent's equilibrium. Chains are one level deep: a parent is
//! not itself pinned to a body ([`crate::model::Model::validate`]).
//!
//! # In the solvers
//!
//! The body keeps the free body's [`super::STATE_LEN`] state entries; its translational
//! entries follow the pin (their rates are the pin's velocity and acceleration, and the
//! kinematics are read from the pin's motion at every evaluation, so the state's copy of the
//! translation never drifts into the physics). In the coupled solve its three force rows are
//! replaced by a_o = a_pin ([`crate::linalg::CoupledSystem::body_pin`]), which leaves the
//! rotational rows above with the line ends coupled in, as for a free body; statics hold the
//! origin at the pin and seek the rotational equilibrium only.

use crate::math::{Real, Vec3, Vec6};
use crate::model::{BodyTrack, Pin, RigidKinematics};

/// Position [m], velocity [m/s] and acceleration [m/s²] of the pin at time t [s]: the body's
/// initial `position` for a fixed pin, the motion's origin for a prescribed one, the host's
/// track for a coupled one (`track`, which a coupled pin has), the parent's point for a pin
/// on a body (`parent`, the parent's kinematics at t; the acceleration is then the parent's
/// point's with the parent's accelerations as `parent` holds them, which the coupled solve
/// replaces for an integrated parent). Without its track or parent, a pin is at rest at
/// `position`.
pub fn pin_kinematics(
    pin: &Pin,
    position: &Vec3,
    track: Option<&BodyTrack>,
    parent: Option<&RigidKinematics>,
    t: Real,
) -> (Vec3, Vec3, Vec3) {
    let at_rest = (*position, Vec3::zeros(), Vec3::zeros());
    match pin {
        Pin::Fixed => at_rest,
        Pin::Prescribed(m) => translation(&m.kinematics(t)),
        Pin::Coupled => track.map_or(at_rest, |track| translation(&track.at(t))),
        Pin::Body { point, .. } => parent.map_or(at_rest, |k| k.point(point)),
    }
}

/// The translation of rigid kinematics: origin position, velocity, acceleration.
fn translation(k: &RigidKinematics) -> (Vec3, Vec3, Vec3) {
    (k.position, k.velocity, k.acceleration)
}

/// The pin's position at t = 0 for a body at `position` [m]: the motion's origin for a
/// prescribed pin, `position` otherwise.
pub fn initial_pin(pin: &Pin, position: &Vec3) -> Vec3 {
    match pin {
        Pin::Prescribed(m) => m.kinematics(0.0).position,
        _ => *position,
    }
}

/// Puts the pin's translation into a pinned body's kinematics `k`, keeping its orientation
/// and angular velocity (the body's own degrees of freedom).
pub fn follow_pin(k: &mut RigidKinematics, pin: (Vec3, Vec3, Vec3)) {
    (k.position, k.velocity, k.acceleration) = pin;
}

/// The force R [N] the pin applies to the body, in global axes: R = M_tt a_pin + M_tr α − F
/// (module docs) from the body's own 6×6 mass about the pin `mass` [kg, kg·m], its own loads
/// `own` [N, N·m], the lines' load on it `lines` [N, N·m] (each line's end force less its end
/// mass's inertia) and its accelerations `k.acceleration` (= a_pin) and
/// `k.angular_acceleration` [rad/s²].
pub fn pin_force(mass: &crate::math::Mat6, own: &Vec6, lines: &Vec6, k: &RigidKinematics) -> Vec3 {
    let u = Vec6::new(
        k.acceleration.x,
        k.acceleration.y,
        k.acceleration.z,
        k.angular_acceleration.x,
        k.angular_acceleration.y,
        k.angular_acceleration.z,
    );
    let r = mass * u - own - lines;
    Vec3::new(r[0], r[1], r[2])
}
