//! Sampled signals: amplitude spectrum, FFT, level crossings, peaks.

use crate::math::Real;

/// Single-sided amplitude spectrum of `x` sampled every `dt` [s], at the DFT frequencies
/// f_k = k / (n dt) [Hz] up to `f_max`: A_k = (2/n) |Σ_j (x_j − x̄) e^(−2πi jk/n)| [unit of x]
/// for k ≥ 1, and A_0 = 0 (the mean x̄ is removed). No window: a sinusoid a·sin(2π f t + φ) whose
/// frequency is one of the f_k gives A_k = a and 0 at the other bins (checked in the tests).
/// Direct DFT, O(n · f_max n dt): meant for validation records (10⁴ samples, a few hundred
/// bins).
pub fn amplitude_spectrum(x: &[Real], dt: Real, f_max: Real) -> Vec<(Real, Real)> {
    let n = x.len();
    if n < 2 || !(dt > 0.0) {
        return Vec::new();
    }
    let mean = x.iter().sum::<Real>() / n as Real;
    let df = 1.0 / (n as Real * dt);
    let k_max = ((f_max / df).floor() as usize).min(n / 2);
    let w = 2.0 * std::f64::consts::PI / n as Real;
    (0..=k_max)
        .map(|k| {
            if k == 0 {
                return (0.0, 0.0);
            }
            let (mut re, mut im) = (0.0, 0.0);
            for (j, &v) in x.iter().enumerate() {
                // (j k) mod n keeps the argument in [0, 2π): no loss of accuracy for long records.
                let (s, c) = (w * ((j * k) % n) as Real).sin_cos();
                re += (v - mean) * c;
                im -= (v - mean) * s;
            }
            let scale = if 2 * k == n { 1.0 } else { 2.0 };
            (k as Real * df, scale * re.hypot(im) / n as Real)
        })
        .collect()
}

/// The first time in [`from`, `to`] [s] at which the samples `x` at `time` rise through
/// `level` (from below to at or above it), linearly interpolated between the two samples.
pub fn upward_crossing(
    time: &[Real],
    x: &[Real],
    level: Real,
    from: Real,
    to: Real,
) -> Option<Real> {
    let start = time.partition_point(|&t| t < from).max(1);
    for i in start..time.len() {
        if time[i] > to {
            break;
        }
        if x[i - 1] < level && x[i] >= level {
            let f = (level - x[i - 1]) / (x[i] - x[i - 1]);
            return Some(time[i - 1] + f * (time[i] - time[i - 1]));
        }
    }
    None
}

/// The largest sample of `x` with its time in [`from`, `to`] [s], as (time, value); `None` if
/// no sample lies in the window.
pub fn peak(time: &[Real], x: &[Real], from: Real, to: Real) -> Option<(Real, Real)> {
    let start = time.partition_point(|&t| t < from);
    let end = time.partition_point(|&t| t <= to);
    (start..end)
        .map(|i| (time[i], x[i]))
        .fold(None, |best, (t, v)| match best {
            Some((_, b)) if b >= v => best,
            _ => Some((t, v)),
        })
}

/// The value of the samples `x` at time `t` [s], linearly interpolated (held at the ends).
pub fn value_at(time: &[Real], x: &[Real], t: Real) -> Real {
    let i = time.partition_point(|&s| s < t);
    if i == 0 {
        return x[0];
    }
    if i >= time.len() {
        return x[time.len() - 1];
    }
    let f = (t - time[i - 1]) / (time[i] - time[i - 1]);
    x[i - 1] + f * (x[i] - x[i - 1])
}

/// Radix-2 decimation-in-time FFT in place: (re, im) ← Σ_j x_j e^(−2πi jk/n), n = re.len() a
/// power of two (spectra of long generated sea and response records in the tests).
pub fn fft(re: &mut [Real], im: &mut [Real]) {
    let n = re.len();
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let ang = -2.0 * std::f64::consts::PI / len as Real;
        for start in (0..n).step_by(len) {
            for k in 0..len / 2 {
                let (s, c) = (ang * k as Real).sin_cos();
                let (a, b) = (start + k, start + k + len / 2);
                let (xr, xi) = (re[b] * c - im[b] * s, re[b] * s + im[b] * c);
                re[b] = re[a] - xr;
                im[b] = im[a] - xi;
                re[a] += xr;
                im[a] += xi;
            }
        }
        len <<= 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two sinusoids on DFT bins come out at their amplitudes, every other bin at round-off;
    /// the mean is removed.
    #[test]
    fn spectrum_of_two_tones() {
        let (n, dt) = (1000, 1e-3);
        let x: Vec<Real> = (0..n)
            .map(|j| {
                let t = j as Real * dt;
                5.0 + 2.0 * (2.0 * std::f64::consts::PI * 7.0 * t + 0.3).sin()
                    + 0.5 * (2.0 * std::f64::consts::PI * 40.0 * t).cos()
            })
            .collect();
        let s = amplitude_spectrum(&x, dt, 60.0);
        assert_eq!(s.len(), 61);
        for &(f, a) in &s {
            let want = match f.round() as i64 {
                7 => 2.0,
                40 => 0.5,
                _ => 0.0,
            };
            assert!((a - want).abs() < 1e-10, "{f} Hz: {a} vs {want}");
        }
    }

    #[test]
    fn crossings_and_peaks() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        let x = [0.0, 2.0, 1.0, 3.0, 0.0];
        assert_eq!(upward_crossing(&t, &x, 1.0, 0.0, 4.0), Some(0.5));
        assert_eq!(upward_crossing(&t, &x, 1.5, 1.5, 4.0), Some(2.25));
        assert_eq!(upward_crossing(&t, &x, 5.0, 0.0, 4.0), None);
        assert_eq!(peak(&t, &x, 0.0, 2.0), Some((1.0, 2.0)));
        assert_eq!(peak(&t, &x, 2.5, 4.0), Some((3.0, 3.0)));
        assert_eq!(peak(&t, &x, 4.5, 5.0), None);
        assert_eq!(value_at(&t, &x, 2.5), 2.0);
        assert_eq!(value_at(&t, &x, 9.0), 0.0);
    }
}
