//! Prescribed motions of points (and, later, bodies).

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
    /// r_i(t) = centre_i + amplitude_i · sin(2π f_i t + phase_i) per axis.
    Sinusoid {
        /// Mean position [m].
        centre: Vec3,
        /// Amplitude per axis [m].
        amplitude: Vec3,
        /// Frequency per axis [Hz].
        frequency: Vec3,
        /// Phase per axis [rad].
        phase: Vec3,
    },
    /// Circular orbit r(t) = centre + a (cos θ e1 + sin θ e2), θ = 2π f t + phase, in the
    /// plane spanned by the orthonormal e1, e2 (the ROPOS fairlead: the x–z plane).
    CircularOrbit {
        /// Centre [m].
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
    },
    /// Piecewise-linear interpolation of positions at strictly increasing times, held at the
    /// end values outside the table.
    TimeSeries {
        /// Times [s].
        times: Vec<Real>,
        /// Positions [m].
        positions: Vec<Vec3>,
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
            } => {
                let mut r = *centre;
                let mut v = Vec3::zeros();
                let mut a = Vec3::zeros();
                for i in 0..3 {
                    let w = TAU * frequency[i];
                    let th = w * t + phase[i];
                    r[i] += amplitude[i] * th.sin();
                    v[i] = amplitude[i] * w * th.cos();
                    a[i] = -amplitude[i] * w * w * th.sin();
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
            } => {
                let w = TAU * frequency;
                let th = w * t + phase;
                let (s, c) = th.sin_cos();
                (
                    centre + (e1 * c + e2 * s) * *radius,
                    (-e1 * s + e2 * c) * (radius * w),
                    -(e1 * c + e2 * s) * (radius * w * w),
                )
            }
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

    /// Frequencies this motion excites [Hz] (for resonance reports).
    pub fn frequencies(&self) -> Vec<Real> {
        match self {
            Motion::Sinusoid {
                frequency,
                amplitude,
                ..
            } => (0..3)
                .filter(|&i| amplitude[i] != 0.0)
                .map(|i| frequency[i])
                .collect(),
            Motion::CircularOrbit { frequency, .. } => vec![*frequency],
            _ => vec![],
        }
    }
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
        };
        let h = 1e-6;
        for t in [0.0, 1.3, 4.0] {
            let (r0, v, a) = m.kinematics(t);
            let (r1, v1, _) = m.kinematics(t + h);
            assert!(((r1 - r0) / h - v).norm() < 1e-5);
            assert!(((v1 - v) / h - a).norm() < 1e-4);
        }
    }
}
