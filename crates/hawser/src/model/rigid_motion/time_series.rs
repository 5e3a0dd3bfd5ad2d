//! A 6-DOF pose table interpolated by not-a-knot cubic splines.

use super::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A 6-DOF motion table: times and, per channel (x, y, z [m], roll, pitch, yaw [rad]), a cubic
/// spline with not-a-knot end conditions (the third derivative continuous at the second and
/// the last-but-one times): position, velocity and acceleration are continuous (C²), and for
/// a smooth motion sampled every h the interpolant's errors are O(h⁴), O(h³) and O(h²).
/// With three rows a channel is the interpolating parabola, with two a straight line, with one
/// a constant. Outside the table the motion is held at the first or last pose, at rest.
///
/// Angles are unwrapped by the constructor (multiples of 2π added so that consecutive values
/// differ by less than π), so a yaw going through ±180° does not spin the vessel round. The
/// orientation is R = R_z(ψ) R_y(θ) R_x(φ), and the angular velocity and acceleration follow
/// from the splines' rates through the kinematic map of [`euler_kinematics`].
#[derive(Clone, PartialEq)]
pub struct RigidTimeSeries {
    times: Vec<Real>,
    /// x, y, z, roll, pitch, yaw at each time.
    values: Vec<[Real; 6]>,
    /// Second derivatives of the splines at each time.
    second: Vec<[Real; 6]>,
    /// The interval of the last lookup, tried first by the next.
    last: LastInterval,
}

/// The table, without the lookup's hint: the `Debug` form is the model's hash
/// ([`crate::session::checkpoint::model_hash`]), which must not change as a run goes.
impl std::fmt::Debug for RigidTimeSeries {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RigidTimeSeries")
            .field("times", &self.times)
            .field("values", &self.values)
            .field("second", &self.second)
            .finish()
    }
}

/// The index k of the interval [t_k, t_{k+1}) that a table's last lookup found: a time
/// loop asks for times in order, so the next lookup is most often in the same interval or
/// the next, and finds it in two comparisons instead of a binary search (which took 2.4 % of
/// the OC3 deck's RK4 step driven by a 3001-row table). Only a hint: a lookup that misses it
/// searches, so the interval found (and every result) is the same whatever it holds. An
/// atomic so that a table shared between threads stays `Sync`; relaxed, as nothing else is
/// ordered by it.
#[derive(Default)]
struct LastInterval(AtomicUsize);

impl Clone for LastInterval {
    fn clone(&self) -> Self {
        Self(AtomicUsize::new(self.0.load(Ordering::Relaxed)))
    }
}

impl PartialEq for LastInterval {
    /// A cache, not part of the table's value.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl RigidTimeSeries {
    /// Builds the splines from strictly increasing `times` [s], `positions` of the body origin
    /// [m] and `angles` [roll, pitch, yaw] [rad] at each time.
    pub fn new(
        times: Vec<Real>,
        positions: &[Vec3],
        angles: &[[Real; 3]],
    ) -> Result<Self, ModelError> {
        let n = times.len();
        check(
            n >= 1 && positions.len() == n && angles.len() == n,
            "time series",
            "needs at least one row, and as many positions and angles as times",
        )?;
        check(
            times.windows(2).all(|w| w[1] > w[0]) && times.iter().all(|t| t.is_finite()),
            "time series",
            "the times must be finite and strictly increasing",
        )?;
        check(
            positions
                .iter()
                .flatten()
                .chain(angles.iter().flatten())
                .all(|x| x.is_finite()),
            "time series",
            "positions and angles must be finite",
        )?;
        let mut values: Vec<[Real; 6]> = positions
            .iter()
            .zip(angles)
            .map(|(p, a)| [p.x, p.y, p.z, a[0], a[1], a[2]])
            .collect();
        for i in 1..n {
            let previous = values[i - 1];
            for (angle, before) in values[i][3..].iter_mut().zip(&previous[3..]) {
                *angle -= TAU * ((*angle - before) / TAU).round();
            }
        }
        let mut second = vec![[0.0; 6]; n];
        let mut channel = vec![0.0; n];
        let mut m = vec![0.0; n];
        for c in 0..6 {
            for i in 0..n {
                channel[i] = values[i][c];
            }
            not_a_knot_second_derivatives(&times, &channel, &mut m);
            for i in 0..n {
                second[i][c] = m[i];
            }
        }
        Ok(Self {
            times,
            values,
            second,
            last: LastInterval::default(),
        })
    }

    /// Times of the table [s].
    pub fn times(&self) -> &[Real] {
        &self.times
    }

    /// Channel values [x, y, z, roll, pitch, yaw] (m, rad; angles unwrapped), their rates and
    /// their second derivatives at time t [s].
    pub fn channels(&self, t: Real) -> ([Real; 6], [Real; 6], [Real; 6]) {
        let n = self.times.len();
        if n == 1 || t <= self.times[0] {
            return (self.values[0], [0.0; 6], [0.0; 6]);
        }
        if t >= self.times[n - 1] {
            return (self.values[n - 1], [0.0; 6], [0.0; 6]);
        }
        // t_0 < t < t_{n−1} here: the one k with t_k ≤ t < t_{k+1}, from the last lookup's
        // interval or the next where t lies in them, by binary search else.
        let times = &self.times;
        let inside = |k: usize| k + 1 < n && times[k] <= t && t < times[k + 1];
        let hint = self.last.0.load(Ordering::Relaxed);
        let k = if inside(hint) {
            hint
        } else if inside(hint + 1) {
            hint + 1
        } else {
            times.partition_point(|&tk| tk <= t).clamp(1, n - 1) - 1
        };
        self.last.0.store(k, Ordering::Relaxed);
        let h = self.times[k + 1] - self.times[k];
        let a = (self.times[k + 1] - t) / h;
        let b = 1.0 - a;
        let (y0, y1) = (&self.values[k], &self.values[k + 1]);
        let (m0, m1) = (&self.second[k], &self.second[k + 1]);
        let mut y = [0.0; 6];
        let mut dy = [0.0; 6];
        let mut ddy = [0.0; 6];
        for c in 0..6 {
            y[c] = a * y0[c]
                + b * y1[c]
                + ((a * a * a - a) * m0[c] + (b * b * b - b) * m1[c]) * h * h / 6.0;
            dy[c] = (y1[c] - y0[c]) / h - (3.0 * a * a - 1.0) / 6.0 * h * m0[c]
                + (3.0 * b * b - 1.0) / 6.0 * h * m1[c];
            ddy[c] = a * m0[c] + b * m1[c];
        }
        (y, dy, ddy)
    }

    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        let (y, dy, ddy) = self.channels(t);
        let (orientation, angular_velocity, angular_acceleration) = euler_kinematics(
            [y[3], y[4], y[5]],
            [dy[3], dy[4], dy[5]],
            [ddy[3], ddy[4], ddy[5]],
        );
        RigidKinematics {
            position: Vec3::new(y[0], y[1], y[2]),
            orientation,
            velocity: Vec3::new(dy[0], dy[1], dy[2]),
            angular_velocity,
            acceleration: Vec3::new(ddy[0], ddy[1], ddy[2]),
            angular_acceleration,
        }
    }
}

/// Second derivatives M_i of the not-a-knot cubic spline through (t_i, y_i) into `m`.
///
/// Interior equations h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (d_i − d_{i−1}),
/// d_i = (y_{i+1} − y_i)/h_i; not-a-knot: (M_1 − M_0)/h_0 = (M_2 − M_1)/h_1 and likewise at the
/// other end, substituted into the first and last interior equations, leaving a tridiagonal
/// system in M_1 … M_{n−2} solved by the Thomas algorithm. Three points give the parabola
/// (M constant), two or one a straight line or constant (M = 0).
fn not_a_knot_second_derivatives(t: &[Real], y: &[Real], m: &mut [Real]) {
    let n = t.len();
    m.iter_mut().for_each(|v| *v = 0.0);
    if n < 3 {
        return;
    }
    let h: Vec<Real> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let d: Vec<Real> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
    if n == 3 {
        let c = 2.0 * (d[1] - d[0]) / (h[0] + h[1]);
        m.iter_mut().for_each(|v| *v = c);
        return;
    }
    // Unknowns M_1 .. M_{n-2}: rows i = 1 .. n-2 with sub, diag, sup, rhs.
    let k = n - 2;
    let mut sub = vec![0.0; k];
    let mut diag = vec![0.0; k];
    let mut sup = vec![0.0; k];
    let mut rhs = vec![0.0; k];
    for r in 0..k {
        let i = r + 1;
        sub[r] = h[i - 1];
        diag[r] = 2.0 * (h[i - 1] + h[i]);
        sup[r] = h[i];
        rhs[r] = 6.0 * (d[i] - d[i - 1]);
    }
    // M_0 = M_1 (1 + h0/h1) − M_2 h0/h1.
    let (h0, h1) = (h[0], h[1]);
    diag[0] += h0 * (1.0 + h0 / h1);
    sup[0] -= h0 * h0 / h1;
    // M_{n-1} = M_{n-2} (1 + h_{n-2}/h_{n-3}) − M_{n-3} h_{n-2}/h_{n-3}.
    let (ha, hb) = (h[n - 3], h[n - 2]);
    diag[k - 1] += hb * (1.0 + hb / ha);
    sub[k - 1] -= hb * hb / ha;
    // Thomas.
    for r in 1..k {
        let w = sub[r] / diag[r - 1];
        diag[r] -= w * sup[r - 1];
        rhs[r] -= w * rhs[r - 1];
    }
    m[k] = rhs[k - 1] / diag[k - 1];
    for r in (0..k - 1).rev() {
        m[r + 1] = (rhs[r] - sup[r] * m[r + 2]) / diag[r];
    }
    m[0] = m[1] * (1.0 + h0 / h1) - m[2] * h0 / h1;
    m[n - 1] = m[n - 2] * (1.0 + hb / ha) - m[n - 3] * hb / ha;
}

// ---------------------------------------------------------------------------------------------
// RAO motion
