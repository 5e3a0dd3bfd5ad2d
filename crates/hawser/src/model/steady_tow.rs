//! Steady towing: the tow velocity of a system whose vessel moves at constant velocity (the
//! elastic-link paper's "solution-setting mode", §5).
//!
//! A system towed at a constant velocity V settles into a shape that is steady in the frame
//! moving with the vessel: every material point moves at V, the water streams past each at
//! u(z) − V (u the current), and the seabed slides under it at −V. Its equilibrium is a
//! static problem in that frame ([`crate::statics::solve`] with
//! [`crate::system::System::tow_velocity`]). For it to be steady, everything whose motion is
//! prescribed (points, bodies, obstacles) must move at that one constant velocity, with a
//! constant orientation, from t = 0 on, and nothing in the environment may depend on time or
//! on the horizontal position: no waves. V must be horizontal: a vertical component would
//! carry the system through the free surface and the seabed.

use super::{BodyKind, Formulation, InitialCondition, Model, Motion, PointKind, RigidMotion};
use crate::error::ModelError;
use crate::math::Vec3;

/// The constant velocity [m/s] a prescribed point motion starts with and keeps (with a
/// constant orientation, for a point on a vessel), or why it has none. A manoeuvre qualifies
/// while on its first straight run if it starts at full speed (`build_up_time = 0`): the
/// steady tow is then the state before the turn.
pub fn steady_point_velocity(motion: &Motion) -> Result<Vec3, String> {
    match motion {
        Motion::Fixed { .. } => Ok(Vec3::zeros()),
        Motion::ConstantVelocity { velocity, .. } => Ok(*velocity),
        Motion::Rigid { motion, .. } => steady_rigid_velocity(motion),
        Motion::Sinusoid { .. } => Err("a sinusoid is not a constant velocity".into()),
        Motion::CircularOrbit { .. } => Err("a circular orbit is not a constant velocity".into()),
        Motion::TimeSeries { .. } => Err("a time series is not a constant velocity".into()),
    }
}

/// The constant velocity [m/s] a prescribed rigid-body motion starts with and keeps, with a
/// constant orientation, or why it has none (see [`steady_point_velocity`]).
pub fn steady_rigid_velocity(motion: &RigidMotion) -> Result<Vec3, String> {
    match motion {
        RigidMotion::Fixed { .. } => Ok(Vec3::zeros()),
        RigidMotion::ConstantVelocity { velocity, .. } => Ok(*velocity),
        RigidMotion::Manoeuvre(m) => {
            let s = m.spec();
            if s.build_up_time > 0.0 {
                Err(format!(
                    "a manoeuvre with build_up_time = {} s starts from rest and accelerates; \
                     set build_up_time = 0 for a steady tow at its speed before the turn",
                    s.build_up_time
                ))
            } else if !(s.straight_before > 0.0) {
                Err("a manoeuvre that turns at once has no straight run to be steady on".into())
            } else {
                Ok(m.kinematics(0.0).velocity)
            }
        }
        RigidMotion::TimeSeries(_) => Err("a 6-DOF time series is not a constant velocity".into()),
        RigidMotion::Rao(_) => Err("wave-frequency (RAO) motion is not a constant velocity".into()),
    }
}

/// The tow velocity V [m/s] of a model set to start from the steady tow
/// ([`InitialCondition::SteadyTow`]): the one constant velocity that every prescribed point,
/// prescribed body and obstacle moves at (a fixed point or obstacle moves at zero). Refused,
/// with the reason:
///
/// - a prescribed motion that is not a constant velocity, or two that differ (by more than
///   1e-9 of the larger speed);
/// - no prescribed point, body or obstacle at all (nothing sets V);
/// - a V with a vertical component (more than 1e-9 of its size);
/// - waves (the sea would not be steady in the moving frame);
/// - `dg` lines (the steady tow is solved on `fe` and `hermite` lines only);
/// - released points (a release test starts from a held equilibrium).
///
/// The seabed is allowed: in the moving frame it slides under the system at −V, and a line or
/// point on it feels the kinetic friction of its sliding at V, opposite to V, by the same law as
/// in the dynamics (the statics evaluate every material point's loads at velocity V).
pub fn tow_velocity(model: &Model) -> Result<Vec3, ModelError> {
    let bad = |what: String, why: String| ModelError::Invalid { what, why };
    let mut found: Option<(Vec3, String)> = None;
    let mut take = |v: Result<Vec3, String>, who: String| -> Result<(), ModelError> {
        let v = v.map_err(|why| {
            bad(
                who.clone(),
                format!("cannot start from a steady tow: {why} (every prescribed motion must be one constant velocity)"),
            )
        })?;
        match &found {
            None => found = Some((v, who)),
            Some((v0, first)) => {
                let scale = v0.norm().max(v.norm());
                if (v - v0).norm() > 1e-9 * scale {
                    return Err(bad(
                        who,
                        format!(
                            "moves at [{}, {}, {}] m/s, but {first} moves at [{}, {}, {}] m/s: a \
                             steady tow needs every prescribed point, body and obstacle to move \
                             at one constant velocity (fixed ones at zero)",
                            v.x, v.y, v.z, v0.x, v0.y, v0.z
                        ),
                    ));
                }
            }
        }
        Ok(())
    };
    for p in &model.points {
        match &p.kind {
            PointKind::Fixed => take(Ok(Vec3::zeros()), format!("point {} (fixed)", p.name))?,
            PointKind::Coupled => take(
                Ok(Vec3::zeros()),
                format!("point {} (coupled, at rest in the statics)", p.name),
            )?,
            PointKind::Prescribed(m) => {
                take(steady_point_velocity(m), format!("point {}", p.name))?
            }
            _ => {}
        }
    }
    for b in &model.bodies {
        if let BodyKind::Prescribed(m) = &b.kind {
            take(steady_rigid_velocity(m), format!("body {}", b.name))?;
        }
    }
    for o in &model.environment.obstacles {
        take(
            steady_point_velocity(&o.motion),
            format!("obstacle {}", o.name),
        )?;
    }
    let Some((v, who)) = found else {
        return Err(bad(
            "simulation.initial_condition".into(),
            "is \"steady-tow\", but no point, body or obstacle is prescribed: the tow velocity \
             is that of the towing vessel, a prescribed point or body with a constant-velocity \
             motion"
                .into(),
        ));
    };
    if v.z.abs() > 1e-9 * v.norm() {
        return Err(bad(
            who,
            format!(
                "moves at [{}, {}, {}] m/s: a steady tow needs a horizontal velocity (a vertical \
                 one carries the system through the surface and the seabed)",
                v.x, v.y, v.z
            ),
        ));
    }
    if model.environment.waves.field().is_some() {
        return Err(bad(
            "environment.waves".into(),
            "a steady tow needs calm water: waves make the flow past the system unsteady; \
             start from \"statics\" instead"
                .into(),
        ));
    }
    if let Some(l) = model
        .lines
        .iter()
        .find(|l| l.formulation == Formulation::Dg)
    {
        return Err(bad(
            format!("line {}", l.name),
            "uses `dg`: the steady tow is solved for `fe` and `hermite` lines only; use \
             formulation = \"hermite\""
                .into(),
        ));
    }
    if !model.settings.release.is_empty() {
        return Err(bad(
            "simulation.release".into(),
            "a release test starts from a held equilibrium at rest, not from a steady tow".into(),
        ));
    }
    Ok(v)
}

impl Model {
    /// The velocity [m/s] of the frame the statics are solved in: the tow velocity for
    /// [`InitialCondition::SteadyTow`] ([`tow_velocity`]), zero otherwise.
    pub fn statics_frame_velocity(&self) -> Result<Vec3, ModelError> {
        match self.settings.initial_condition {
            InitialCondition::SteadyTow => tow_velocity(self),
            _ => Ok(Vec3::zeros()),
        }
    }
}
