//! Prescribed motions of points.

use super::RigidMotion;
use crate::math::{Real, Vec3};
use std::f64::consts::TAU;

/// A prescribed trajectory. Positions are absolute [m]; t in [s].
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// Fixed at `position`.
    Fixed {
        /// Position [m].
        position: Vec3,
    },
    /// r(t) = start + velocity·t.
    ConstantVelocity {
        /// Position at t = 0 [m].
        start: Vec3,
        /// Velocity [m/s].
        velocity: Vec3,
    },
    /// r_i(t) = centre_i + R(t) · amplitude_i · (sin(2π f_i t + phase_i) − sin(phase_i)) per
    /// axis, with R the build-up ramp (see [`ramp`]); the point starts at `centre`.
    Sinusoid {
        /// Position at t = 0 [m] (the mean position when the phase is 0).
        centre: Vec3,
        /// Amplitude per axis [m].
        amplitude: Vec3,
        /// Frequency per axis [Hz].
        frequency: Vec3,
        /// Phase per axis [rad].
        phase: Vec3,
        /// Build-up time [s] over which the amplitude ramps from 0 (0 for none).
        ramp: Real,
    },
    /// Circular orbit r(t) = centre + R(t) a (cos θ e1 + sin θ e2 − cos φ e1 − sin φ e2),
    /// θ = 2π f t + φ, in the plane spanned by the orthonormal e1, e2 (the ROPOS fairlead: the
    /// x–z plane); the point starts at `centre` and orbits the centre
    /// `centre − a (cos φ e1 + sin φ e2)`; R is the build-up ramp.
    CircularOrbit {
        /// Position at t = 0 [m].
        centre: Vec3,
        /// Radius a [m].
        radius: Real,
        /// Frequency f [Hz].
        frequency: Real,
        /// Phase [rad].
        phase: Real,
        /// First in-plane unit vector.
        e1: Vec3,
        /// Second in-plane unit vector.
        e2: Vec3,
        /// Build-up time [s] (0 for none).
        ramp: Real,
    },
    /// Piecewise-linear interpolation of positions at strictly increasing times, held at the
    /// end values outside the table.
    TimeSeries {
        /// Times [s].
        times: Vec<Real>,
        /// Positions [m].
        positions: Vec<Vec3>,
    },
    /// A point fixed on a body (vessel) that moves as prescribed: r = r_o + R offset, with
    /// velocity and acceleration from [`crate::model::RigidKinematics::point`] (exact for any
    /// rigid motion: v = v_o + ω × ρ, a = a_o + α × ρ + ω × (ω × ρ), ρ = R offset).
    Rigid {
        /// The body's motion.
        motion: Box<RigidMotion>,
        /// The point in body axes, from the body origin [m].
        offset: Vec3,
    },
}

impl Motion {
    /// Position [m], velocity [m/s] and acceleration [m/s²] at time t [s].
    pub fn kinematics(&self, t: Real) -> (Vec3, Vec3, Vec3) {
        match self {
            Motion::Fixed { position } => (*position, Vec3::zeros(), Vec3::zeros()),
            Motion::ConstantVelocity { start, velocity } => {
                (start + velocity * t, *velocity, Vec3::zeros())
            }
            Motion::Sinusoid {
                centre,
                amplitude,
                frequency,
                phase,
                ramp: tr,
            } => {
                let (g, dg, ddg) = ramp(t, *tr);
                let mut r = *centre;
                let mut v = Vec3::zeros();
                let mut a = Vec3::zeros();
                for i in 0..3 {
                    if amplitude[i] == 0.0 {
                        continue;
                    }
                    let w = TAU * frequency[i];
                    let th = w * t + phase[i];
                    let (sn, cs) = th.sin_cos();
                    let s = amplitude[i] * (sn - phase[i].sin());
                    let ds = amplitude[i] * w * cs;
                    let dds = -amplitude[i] * w * w * sn;
                    r[i] += g * s;
                    v[i] = dg * s + g * ds;
                    a[i] = ddg * s + 2.0 * dg * ds + g * dds;
                }
                (r, v, a)
            }
            Motion::CircularOrbit {
                centre,
                radius,
                frequency,
                phase,
                e1,
                e2,
                ramp: tr,
            } => {
                let (g, dg, ddg) = ramp(t, *tr);
                let w = TAU * frequency;
                let th = w * t + phase;
                let (sn, cs) = th.sin_cos();
                let (s0, c0) = phase.sin_cos();
                let p = (e1 * (cs - c0) + e2 * (sn - s0)) * *radius;
                let dp = (-e1 * sn + e2 * cs) * (radius * w);
                let ddp = -(e1 * cs + e2 * sn) * (radius * w * w);
                (
                    centre + p * g,
                    p * dg + dp * g,
                    p * ddg + dp * (2.0 * dg) + ddp * g,
                )
            }
            Motion::Rigid { motion, offset } => motion.kinematics(t).point(offset),
            Motion::TimeSeries { times, positions } => {
                let n = times.len();
                if t <= times[0] {
                    return (positions[0], Vec3::zeros(), Vec3::zeros());
                }
                if t >= times[n - 1] {
                    return (positions[n - 1], Vec3::zeros(), Vec3::zeros());
                }
                let k = times.partition_point(|&tk| tk <= t).clamp(1, n - 1);
                let dt = times[k] - times[k - 1];
                let w = (t - times[k - 1]) / dt;
                let v = (positions[k] - positions[k - 1]) / dt;
                (
                    positions[k - 1] * (1.0 - w) + positions[k] * w,
                    v,
                    Vec3::zeros(),
                )
            }
        }
    }

    /// Position at t = 0 [m].
    pub fn initial_position(&self) -> Vec3 {
        self.kinematics(0.0).0
    }

    /// The periodic excitations this motion contains: (description, frequency [Hz]), e.g.
    /// ("sinusoid x", 0.1). A sinusoid gives one per axis with a non-zero amplitude, a circular
    /// orbit its orbit frequency; fixed, constant-velocity and time-series motions none (a time
    /// series would need a spectral estimate, not made here). The build-up ramp is ignored: it
    /// only shapes the start.
    pub fn excitation_frequencies(&self) -> Vec<(String, Real)> {
        match self {
            Motion::Sinusoid {
                amplitude,
                frequency,
                ..
            } => (0..3)
                .filter(|&i| amplitude[i] != 0.0 && frequency[i] > 0.0)
                .map(|i| (format!("sinusoid {}", ["x", "y", "z"][i]), frequency[i]))
                .collect(),
            Motion::CircularOrbit {
                radius, frequency, ..
            } if *radius != 0.0 && *frequency > 0.0 => {
                vec![("circular orbit".to_string(), *frequency)]
            }
            _ => Vec::new(),
        }
    }
}

/// Build-up ramp R(t) = 10τ³ − 15τ⁴ + 6τ⁵ with τ = t/T for t < T, 1 after (the quintic
/// smoothstep), with its first and second time derivatives. R' and R'' vanish at both ends,
/// so a ramped motion starts from rest and its velocity and acceleration are continuous at
/// t = 0 and at t = T: no start-up jerk for the lines to respond to.
pub fn ramp(t: Real, duration: Real) -> (Real, Real, Real) {
    if duration <= 0.0 || t >= duration {
        return (1.0, 0.0, 0.0);
    }
    if t <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let x = t / duration;
    let (x2, x3) = (x * x, x * x * x);
    (
        x3 * (10.0 - 15.0 * x + 6.0 * x2),
        30.0 * x2 * (1.0 - x) * (1.0 - x) / duration,
        60.0 * x * (1.0 - 3.0 * x + 2.0 * x2) / (duration * duration),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn orbit_velocity_is_derivative_of_position() {
        let m = Motion::CircularOrbit {
            centre: Vec3::new(1.0, 2.0, 3.0),
            radius: 2.0,
            frequency: 0.2,
            phase: 0.3,
            e1: Vec3::x(),
            e2: Vec3::z(),
            ramp: 2.0,
        };
        let h = 1e-6;
        for t in [0.0, 0.7, 1.3, 4.0] {
            let (r0, v, a) = m.kinematics(t);
            let (r1, v1, _) = m.kinematics(t + h);
            assert!(((r1 - r0) / h - v).norm() < 1e-5);
            assert!(((v1 - v) / h - a).norm() < 1e-4);
        }
    }

    #[test]
    fn ramped_sinusoid_is_consistent_and_starts_at_rest() {
        let m = Motion::Sinusoid {
            centre: Vec3::zeros(),
            amplitude: Vec3::new(0.0, 0.0, 0.1),
            frequency: Vec3::new(0.0, 0.0, 1.27),
            phase: Vec3::new(0.0, 0.0, 0.4),
            ramp: 3.0,
        };
        let (r, v, a) = m.kinematics(0.0);
        assert_eq!((r.norm(), v.norm(), a.norm()), (0.0, 0.0, 0.0));
        let h = 1e-6;
        // Continuous acceleration across the end of the ramp.
        let (_, _, a_before) = m.kinematics(3.0 - 1e-9);
        let (_, _, a_after) = m.kinematics(3.0 + 1e-9);
        assert!((a_before - a_after).norm() < 1e-6);
        for t in [0.5, 2.9, 3.5] {
            let (r0, v0, a0) = m.kinematics(t);
            let (r1, v1, _) = m.kinematics(t + h);
            assert!(((r1 - r0) / h - v0).norm() < 1e-5, "velocity at {t}");
            assert!(((v1 - v0) / h - a0).norm() < 1e-4, "acceleration at {t}");
        }
    }
}
