//! Coupled points and bodies: kinematics a host program (OpenFAST, WEC-Sim, a CFD code, a Python
//! script) sets at each coupling step, interpolated inside the coupling interval.
//!
//! Semantics (docs/coupling.md): the host gives the kinematics at the *end* t₁ of each coupling
//! interval [t₀, t₁]; inside it they are the cubic Hermite interpolant of the position and
//! velocity at t₀ (the previous interval's end, or the initial state) and at t₁, so position
//! and velocity are continuous across intervals and the answer does not depend on the coupling
//! interval beyond the interpolation error (O(Δt⁴) in position, O(Δt³) in velocity, O(Δt²)
//! in acceleration for smooth motions); at t₁ itself the acceleration is the interpolant's.
//! Past t₁ the motion goes on at the last velocity.

use crate::math::{Quat, Real, Vec3};
use crate::model::{Motion, PointKind, RigidKinematics};

/// Cubic Hermite interpolation on s ∈ [0, 1] of span h: value, first and second time
/// derivatives from (x₀, ẋ₀) and (x₁, ẋ₁). Basis h₀₀ = 2s³ − 3s² + 1, h₁₀ = s³ − 2s² + s,
/// h₀₁ = −2s³ + 3s², h₁₁ = s³ − s².
#[inline]
fn hermite(s: Real, h: Real, x0: Vec3, v0: Vec3, x1: Vec3, v1: Vec3) -> (Vec3, Vec3, Vec3) {
    let (s2, s3) = (s * s, s * s * s);
    let x = x0 * (2.0 * s3 - 3.0 * s2 + 1.0)
        + v0 * (h * (s3 - 2.0 * s2 + s))
        + x1 * (3.0 * s2 - 2.0 * s3)
        + v1 * (h * (s3 - s2));
    let v = (x0 - x1) * ((6.0 * s2 - 6.0 * s) / h)
        + v0 * (3.0 * s2 - 4.0 * s + 1.0)
        + v1 * (3.0 * s2 - 2.0 * s);
    let a = (x0 - x1) * ((12.0 * s - 6.0) / (h * h))
        + v0 * ((6.0 * s - 4.0) / h)
        + v1 * ((6.0 * s - 2.0) / h);
    (x, v, a)
}

/// Quintic Hermite interpolation on s ∈ [0, 1] of span h from values, first and second
/// derivatives at both ends: exact for polynomials of degree 5. Basis
/// H₀ = 1 − 10s³ + 15s⁴ − 6s⁵, H₁ = s − 6s³ + 8s⁴ − 3s⁵, H₂ = ½s² − 3⁄2 s³ + 3⁄2 s⁴ − ½s⁵
/// (at s = 0) and H₅ = 10s³ − 15s⁴ + 6s⁵, H₄ = −4s³ + 7s⁴ − 3s⁵, H₃ = ½s³ − s⁴ + ½s⁵ (at s = 1).
#[inline]
fn quintic(s: Real, h: Real, start: [Vec3; 3], end: [Vec3; 3]) -> (Vec3, Vec3, Vec3) {
    let (s2, s3, s4, s5) = (s * s, s * s * s, s * s * s * s, s * s * s * s * s);
    let [x0, v0, a0] = start;
    let [x1, v1, a1] = end;
    let (hv0, ha0, hv1, ha1) = (v0 * h, a0 * (h * h), v1 * h, a1 * (h * h));
    let x = x0 * (1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5)
        + hv0 * (s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5)
        + ha0 * (0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5)
        + ha1 * (0.5 * s3 - s4 + 0.5 * s5)
        + hv1 * (-4.0 * s3 + 7.0 * s4 - 3.0 * s5)
        + x1 * (10.0 * s3 - 15.0 * s4 + 6.0 * s5);
    let d = (x1 - x0) * (30.0 * s2 - 60.0 * s3 + 30.0 * s4)
        + hv0 * (1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4)
        + ha0 * (s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4)
        + ha1 * (1.5 * s2 - 4.0 * s3 + 2.5 * s4)
        + hv1 * (-12.0 * s2 + 28.0 * s3 - 15.0 * s4);
    let dd = (x1 - x0) * (60.0 * s - 180.0 * s2 + 120.0 * s3)
        + hv0 * (-36.0 * s + 96.0 * s2 - 60.0 * s3)
        + ha0 * (1.0 - 9.0 * s + 18.0 * s2 - 10.0 * s3)
        + ha1 * (3.0 * s - 12.0 * s2 + 10.0 * s3)
        + hv1 * (-24.0 * s + 84.0 * s2 - 60.0 * s3);
    (x, d / h, dd / (h * h))
}

/// The interpolant of an interval: quintic when the accelerations of both ends are known,
/// cubic otherwise.
#[inline]
fn interpolate(
    s: Real,
    h: Real,
    start: (Vec3, Vec3, Option<Vec3>),
    end: (Vec3, Vec3, Option<Vec3>),
) -> (Vec3, Vec3, Vec3) {
    match (start.2, end.2) {
        (Some(a0), Some(a1)) => quintic(s, h, [start.0, start.1, a0], [end.0, end.1, a1]),
        _ => hermite(s, h, start.0, start.1, end.0, end.1),
    }
}

/// The kinematics of a coupled point over the current coupling interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointTrack {
    /// Start of the interval [s].
    pub t0: Real,
    /// End of the interval [s] (equal to `t0` before the host gives one).
    pub t1: Real,
    /// Position [m], velocity [m/s] and, when the host gave it, acceleration [m/s²] at t₀.
    pub start: (Vec3, Vec3, Option<Vec3>),
    /// Position [m], velocity [m/s] and, when the host gave it, acceleration [m/s²] at t₁.
    pub end: (Vec3, Vec3, Option<Vec3>),
}

impl PointTrack {
    /// At rest at `position` from t = 0.
    pub fn at_rest(position: Vec3) -> Self {
        let k = (position, Vec3::zeros(), Some(Vec3::zeros()));
        Self {
            t0: 0.0,
            t1: 0.0,
            start: k,
            end: k,
        }
    }

    /// Position [m], velocity [m/s] and acceleration [m/s²] at time t [s].
    pub fn at(&self, t: Real) -> (Vec3, Vec3, Vec3) {
        let h = self.t1 - self.t0;
        // A stage time past t₁ by round-off (t₀ + n·Δt) is t₁.
        if t > self.t1 + 1e-6 * h || !(h > 0.0) {
            let (x, v, a) = self.end;
            if t <= self.t1 {
                return (x, v, a.unwrap_or_else(Vec3::zeros));
            }
            return (x + v * (t - self.t1), v, Vec3::zeros());
        }
        let s = ((t - self.t0) / h).clamp(0.0, 1.0);
        interpolate(s, h, self.start, self.end)
    }

    /// Starts an interval at t₀ = `t` from the kinematics there, its end pending (until the
    /// host sets it, the motion goes on at the velocity of t₀).
    pub fn start_at(&mut self, t: Real) {
        let (x, v, a) = self.at(t);
        // The acceleration is known where the last interval's end gave it.
        let known = if t == self.t1 { self.end.2 } else { None };
        let a = known.map(|_| a);
        self.t0 = t;
        self.t1 = t;
        self.start = (x, v, a);
        self.end = (x, v, a);
    }

    /// Sets the end of the interval started by [`PointTrack::start_at`]: position [m],
    /// velocity [m/s] and, if known, acceleration [m/s²] (with the start's, the interpolant
    /// is quintic).
    pub fn set_end(
        &mut self,
        t1: Real,
        position: Vec3,
        velocity: Vec3,
        acceleration: Option<Vec3>,
    ) {
        self.t1 = t1;
        self.end = (position, velocity, acceleration);
    }
}

/// The kinematics of a coupled body over the current coupling interval: its origin as a
/// [`PointTrack`], its orientation by the rotation vector θ(t) from the orientation at t₀,
/// q(t) = exp(θ(t)) q₀, with θ the cubic Hermite interpolant of θ(t₀) = 0, θ̇(t₀) = ω₀,
/// θ(t₁) = log(q₁ q₀⁻¹), θ̇(t₁) = ω₁, and ω(t) = θ̇(t), dω/dt = θ̈(t) (global axes). The
/// identification θ̇ = ω holds to first order in |θ| (the rotation within one interval), which
/// is the order of the interpolation error itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyTrack {
    /// The body origin.
    pub origin: PointTrack,
    /// Orientation at t₀.
    pub orientation0: Quat,
    /// Rotation from `orientation0` to the orientation at t₁, as a rotation vector [rad].
    pub rotation: Vec3,
    /// Angular velocities at t₀ and t₁ [rad/s], global axes.
    pub angular_velocity: (Vec3, Vec3),
    /// Angular accelerations at t₀ and t₁ [rad/s²], when the host gave them.
    pub angular_acceleration: (Option<Vec3>, Option<Vec3>),
}

impl BodyTrack {
    /// At rest in `pose` from t = 0.
    pub fn at_rest(position: Vec3, orientation: Quat) -> Self {
        Self {
            origin: PointTrack::at_rest(position),
            orientation0: orientation,
            rotation: Vec3::zeros(),
            angular_velocity: (Vec3::zeros(), Vec3::zeros()),
            angular_acceleration: (Some(Vec3::zeros()), Some(Vec3::zeros())),
        }
    }

    /// Rotation vector [rad], angular velocity [rad/s] and acceleration [rad/s²] at t.
    fn rotation_at(&self, t: Real) -> (Vec3, Vec3, Vec3) {
        let (t0, t1) = (self.origin.t0, self.origin.t1);
        let h = t1 - t0;
        let (w0, w1) = self.angular_velocity;
        let (a0, a1) = self.angular_acceleration;
        if t > t1 + 1e-6 * h || !(h > 0.0) {
            if t <= t1 {
                return (self.rotation, w1, a1.unwrap_or_else(Vec3::zeros));
            }
            return (self.rotation + w1 * (t - t1), w1, Vec3::zeros());
        }
        let s = ((t - t0) / h).clamp(0.0, 1.0);
        interpolate(s, h, (Vec3::zeros(), w0, a0), (self.rotation, w1, a1))
    }

    /// The body's kinematics at time t [s].
    pub fn at(&self, t: Real) -> RigidKinematics {
        let (position, velocity, acceleration) = self.origin.at(t);
        let (theta, angular_velocity, angular_acceleration) = self.rotation_at(t);
        RigidKinematics {
            position,
            orientation: Quat::from_scaled_axis(theta) * self.orientation0,
            velocity,
            angular_velocity,
            acceleration,
            angular_acceleration,
        }
    }

    /// Starts an interval at t₀ = `t` from the kinematics there.
    pub fn start_at(&mut self, t: Real) {
        let k = self.at(t);
        let known = if t == self.origin.t1 {
            self.angular_acceleration.1
        } else {
            None
        };
        let alpha = known.map(|_| k.angular_acceleration);
        self.origin.start_at(t);
        self.orientation0 = k.orientation;
        self.rotation = Vec3::zeros();
        self.angular_velocity = (k.angular_velocity, k.angular_velocity);
        self.angular_acceleration = (alpha, alpha);
    }

    /// Sets the end of the interval started by [`BodyTrack::start_at`]: the pose and
    /// velocities of `end`, and its accelerations when `accelerations` (with the start's,
    /// the interpolants are quintic).
    pub fn set_end(&mut self, t1: Real, end: &RigidKinematics, accelerations: bool) {
        let acc = |a: Vec3| accelerations.then_some(a);
        self.origin
            .set_end(t1, end.position, end.velocity, acc(end.acceleration));
        self.rotation = (end.orientation * self.orientation0.inverse()).scaled_axis();
        self.angular_velocity.1 = end.angular_velocity;
        self.angular_acceleration.1 = acc(end.angular_acceleration);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quintic_is_exact_for_quintics() {
        let c = [0.3, -1.0, 2.0, 0.7, -0.4, 0.25];
        let x = |t: Real| c.iter().rev().fold(0.0, |acc, k| acc * t + k);
        let v = |t: Real| (1..6).rev().fold(0.0, |acc, k| acc * t + k as Real * c[k]);
        let a = |t: Real| {
            (2..6)
                .rev()
                .fold(0.0, |acc, k| acc * t + (k * (k - 1)) as Real * c[k])
        };
        let e = Vec3::new(0.5, 1.0, -1.5);
        let mut track = PointTrack::at_rest(Vec3::zeros());
        track.t0 = 0.2;
        track.start = (e * x(0.2), e * v(0.2), Some(e * a(0.2)));
        track.set_end(0.9, e * x(0.9), e * v(0.9), Some(e * a(0.9)));
        for t in [0.2, 0.33, 0.5, 0.77, 0.9] {
            let (p, u, acc) = track.at(t);
            assert!((p - e * x(t)).norm() < 1e-13, "x at {t}");
            assert!((u - e * v(t)).norm() < 1e-12, "v at {t}");
            assert!((acc - e * a(t)).norm() < 1e-11, "a at {t}");
        }
    }

    #[test]
    fn hermite_is_exact_for_cubics() {
        // x(t) = 1 + 2t − t² + 0.5t³ on [0.3, 0.8].
        let x = |t: Real| 1.0 + 2.0 * t - t * t + 0.5 * t * t * t;
        let v = |t: Real| 2.0 - 2.0 * t + 1.5 * t * t;
        let a = |t: Real| -2.0 + 3.0 * t;
        let e = Vec3::new(1.0, -2.0, 0.5);
        let mut track = PointTrack::at_rest(e * x(0.3));
        track.start = (e * x(0.3), e * v(0.3), None);
        track.t0 = 0.3;
        track.set_end(0.8, e * x(0.8), e * v(0.8), None);
        for t in [0.3, 0.41, 0.55, 0.79, 0.8] {
            let (p, u, acc) = track.at(t);
            assert!((p - e * x(t)).norm() < 1e-13, "x at {t}");
            assert!((u - e * v(t)).norm() < 1e-12, "v at {t}");
            assert!((acc - e * a(t)).norm() < 1e-11, "a at {t}");
        }
        // Past t₁: on at the last velocity.
        let (p, u, acc) = track.at(1.0);
        assert!((p - (e * x(0.8) + e * v(0.8) * 0.2)).norm() < 1e-14);
        assert_eq!((u, acc), (e * v(0.8), Vec3::zeros()));
    }

    #[test]
    fn body_track_reaches_the_end_pose_and_turns_steadily() {
        // A steady turn ω about z: the interpolant of a rotation at constant rate is exact.
        let w = Vec3::new(0.0, 0.0, 0.3);
        let q0 = Quat::from_euler_angles(0.1, -0.2, 0.4);
        let mut track = BodyTrack::at_rest(Vec3::zeros(), q0);
        track.angular_velocity = (w, w);
        let h = 0.5;
        let end = RigidKinematics {
            orientation: Quat::from_scaled_axis(w * h) * q0,
            angular_velocity: w,
            ..RigidKinematics::at_rest(Vec3::zeros(), q0)
        };
        track.set_end(h, &end, false);
        for t in [0.0, 0.1, 0.25, 0.5] {
            let k = track.at(t);
            let expected = Quat::from_scaled_axis(w * t) * q0;
            assert!(k.orientation.angle_to(&expected) < 1e-14, "t = {t}");
            assert!((k.angular_velocity - w).norm() < 1e-14);
            assert!(k.angular_acceleration.norm() < 1e-13);
        }
    }
}

/// `model` with every prescribed point made coupled, placed at its motion's position at t = 0,
/// and those motions by point index: what a host needs to drive the coupled model along the
/// prescribed one (the coupling tests, `hawser bench --coupling`).
pub fn couple_prescribed_points(model: &crate::Model) -> (crate::Model, Vec<(usize, Motion)>) {
    let mut m = model.clone();
    let mut motions = Vec::new();
    for (i, p) in m.points.iter_mut().enumerate() {
        if let PointKind::Prescribed(motion) = &p.kind {
            p.position = motion.initial_position();
            motions.push((i, motion.clone()));
            p.kind = PointKind::Coupled;
        }
    }
    (m, motions)
}
