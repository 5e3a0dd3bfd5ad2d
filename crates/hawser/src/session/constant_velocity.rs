//! MoorDyn's coupling convention beside hawser's own: the host gives the kinematics at the
//! *start* of the interval [t₀, t₀ + Δt], and each coupled object moves through it at that
//! constant velocity (MoorDyn-C 2.7 `Point::updateFairlead`: r(t) = r_ves + ṙ_ves (t − t₀)).
//! A position that differs from where the last interval ended, or a velocity that differs from
//! its last one, is a jump at t₀, as in MoorDyn. A host that feeds samples x_k and the forward
//! differences (x_{k+1} − x_k)/Δt drives the objects along the piecewise-linear interpolant of
//! its samples, which is what a prescribed `vessel-motion` table does: the two runs step the
//! same state.
//!
//! hawser's own convention ([`Session::set_coupled`], kinematics at the interval's end and a
//! smooth interpolant) is the better one for a new host; this one exists so that a host
//! written for MoorDyn's library gets MoorDyn's motion.

use super::Session;
use crate::error::SimulationError;
use crate::math::{Quat, Real, Vec3};
use crate::model::{RigidKinematics, euler_kinematics};

impl Session {
    /// Sets every coupled object's motion over [t0, t0 + dt] [s] from its kinematics at `t0`
    /// in the layout of [`Session::set_coupled`] (per coupled body x, y, z [m], roll, pitch,
    /// yaw [rad] and the velocities [m/s, rad/s, global axes]; per coupled point x, y, z [m]
    /// and its velocity): x(t) = x₀ + ẋ₀ (t − t₀), the orientation turning at the constant
    /// angular velocity ω₀, q(t) = exp(ω₀ (t − t₀)) q₀. `t0` is the session's time (a new
    /// interval), or the start of the interval just computed with the same `dt` (a repeated
    /// interval: the session goes back to `t0`). [`Session::advance_to`]`(t0 + dt)` then
    /// computes it.
    pub fn set_coupled_constant_velocity(
        &mut self,
        t0: Real,
        dt: Real,
        x: &[Real],
        xd: &[Real],
    ) -> Result<(), SimulationError> {
        let err = |what: String| SimulationError::Coupling { what };
        let n = self.coupled_dofs();
        if x.len() != n || xd.len() != n {
            return Err(err(format!(
                "the coupled kinematics have {} positions and {} velocities where the model has \
                 {n} coupled degrees of freedom",
                x.len(),
                xd.len()
            )));
        }
        if !(dt > 0.0 && dt.is_finite() && t0.is_finite()) {
            return Err(err(format!(
                "the coupling interval [{t0} s, {t0} s + {dt} s] is not a finite interval of \
                 positive length"
            )));
        }
        let now = self.stepper.time();
        let tolerance = 1e-9 * self.stepper.clock.nominal;
        let t1 = t0 + dt;
        let repeated = self
            .coupling
            .interval
            .is_some_and(|(s, e)| (t0 - s).abs() <= tolerance && (t1 - e).abs() <= tolerance);
        if !repeated && (t0 - now).abs() > tolerance {
            return Err(err(format!(
                "the interval starts at t = {t0} s where the session is at {now} s: a new \
                 interval starts at the session's time, a repeated one at the start of the \
                 interval just computed, with the same length"
            )));
        }
        // The end time of a repeated interval is the one stored, so that the session sees the
        // same interval, not one that differs by round-off.
        let t1 = match self.coupling.interval {
            Some((_, e)) if repeated => e,
            _ => t1,
        };
        let h = t1 - t0;
        // Per body 6 entries, or 3 for a coupled pin (its angles then stay zero: unused).
        let mut o = 0;
        for k in 0..self.coupling.bodies.len() {
            let b = self.coupling.bodies[k];
            let n = self.coupled_body_dofs(b);
            let (mut p, mut v) = ([0.0; 6], [0.0; 6]);
            p[..n].copy_from_slice(&x[o..o + n]);
            v[..n].copy_from_slice(&xd[o..o + n]);
            o += n;
            let (q0, _, _) = euler_kinematics([p[3], p[4], p[5]], [0.0; 3], [0.0; 3]);
            let (x0, v0, w0) = (
                Vec3::new(p[0], p[1], p[2]),
                Vec3::new(v[0], v[1], v[2]),
                Vec3::new(v[3], v[4], v[5]),
            );
            let end = RigidKinematics {
                position: x0 + v0 * h,
                orientation: Quat::from_scaled_axis(w0 * h) * q0,
                velocity: v0,
                angular_velocity: w0,
                acceleration: Vec3::zeros(),
                angular_acceleration: Vec3::zeros(),
            };
            self.set_body_kinematics(b, t1, &end, false)?;
            let track = self.stepper.ws.coupling.bodies[b]
                .as_mut()
                .expect("a coupled body has a track");
            // The cubic Hermite interpolant of equal end velocities and a chord of h·v is the
            // straight line x₀ + v (t − t₀); the same for the rotation vector.
            track.origin.start = (x0, v0, None);
            track.orientation0 = q0;
            track.rotation = w0 * h;
            track.angular_velocity = (w0, w0);
            track.angular_acceleration = (None, None);
        }
        for k in 0..self.coupling.points.len() {
            let p = self.coupling.points[k];
            let o = o + 3 * k;
            let x0 = Vec3::new(x[o], x[o + 1], x[o + 2]);
            let v0 = Vec3::new(xd[o], xd[o + 1], xd[o + 2]);
            self.set_point_kinematics(p, t1, x0 + v0 * h, v0, None)?;
            let track = self.stepper.ws.coupling.points[p]
                .as_mut()
                .expect("a coupled point has a track");
            track.start = (x0, v0, None);
        }
        // The state at t0 now sees the jump.
        self.stepper.invalidate();
        Ok(())
    }
}
