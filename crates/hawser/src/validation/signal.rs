//! Sampled signals: amplitude spectrum, FFT (both by `rustfft`), level crossings, peaks.

use crate::math::Real;

/// Single-sided amplitude spectrum of `x` sampled every `dt` [s], at the DFT frequencies
/// f_k = k / (n dt) [Hz] up to `f_max`: A_k = (2/n) |Σ_j (x_j − x̄) e^(−2πi jk/n)| [unit of x]
/// for k ≥ 1 (1/n at the Nyquist bin k = n/2), and A_0 = 0 (the mean x̄ is removed). No
/// window: a sinusoid a·sin(2π f t + φ) whose frequency is one of the f_k gives A_k = a and 0
/// at the other bins (checked in the tests). Any length n, by the real FFT of `realfft`
/// (O(n log n)).
pub fn amplitude_spectrum(x: &[Real], dt: Real, f_max: Real) -> Vec<(Real, Real)> {
    let n = x.len();
    if n < 2 || !(dt > 0.0) {
        return Vec::new();
    }
    let mean = x.iter().sum::<Real>() / n as Real;
    let df = 1.0 / (n as Real * dt);
    let k_max = if f_max >= 0.0 {
        ((f_max / df).floor() as usize).min(n / 2)
    } else {
        0
    };
    let fft = realfft::RealFftPlanner::<Real>::new().plan_fft_forward(n);
    let mut input: Vec<Real> = x.iter().map(|v| v - mean).collect();
    let mut spectrum = fft.make_output_vec();
    fft.process(&mut input, &mut spectrum)
        .expect("buffers sized by the plan");
    (0..=k_max)
        .map(|k| {
            if k == 0 {
                return (0.0, 0.0);
            }
            let scale = if 2 * k == n { 1.0 } else { 2.0 };
            (k as Real * df, scale * spectrum[k].norm() / n as Real)
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

/// Discrete Fourier transform in place: (re, im) ← Σ_j x_j e^(−2πi jk/n) with x_j = re_j +
/// i im_j, any length n = re.len() (spectra of long generated sea and response records in the
/// tests), by `rustfft`.
pub fn fft(re: &mut [Real], im: &mut [Real]) {
    use rustfft::num_complex::Complex;
    let n = re.len();
    assert_eq!(n, im.len(), "re and im have one length");
    let mut buffer: Vec<Complex<Real>> = re
        .iter()
        .zip(im.iter())
        .map(|(&r, &i)| Complex::new(r, i))
        .collect();
    rustfft::FftPlanner::<Real>::new()
        .plan_fft_forward(n)
        .process(&mut buffer);
    for ((r, i), c) in re.iter_mut().zip(im.iter_mut()).zip(&buffer) {
        (*r, *i) = (c.re, c.im);
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

    /// The FFT against the direct sum Σ_j x_j e^(−2πi jk/n) on a length that is no power of
    /// two (6 · 7 = 42, mixed radices); round-off of a few ulps of the sum's magnitude.
    #[test]
    fn fft_is_the_dft() {
        let n = 42;
        let x: Vec<(Real, Real)> = (0..n)
            .map(|j| {
                let j = j as Real;
                (
                    (0.3 * j).sin() + 0.1 * j,
                    (1.7 * j).cos() - 0.05 * j * j / n as Real,
                )
            })
            .collect();
        let (mut re, mut im): (Vec<Real>, Vec<Real>) = x.iter().copied().unzip();
        fft(&mut re, &mut im);
        for k in 0..n {
            let (mut sr, mut si) = (0.0, 0.0);
            for (j, &(a, b)) in x.iter().enumerate() {
                let w = -2.0 * std::f64::consts::PI * ((j * k) % n) as Real / n as Real;
                let (s, c) = w.sin_cos();
                sr += a * c - b * s;
                si += a * s + b * c;
            }
            assert!(
                (re[k] - sr).abs() < 1e-12 && (im[k] - si).abs() < 1e-12,
                "bin {k}"
            );
        }
    }

    /// An odd-length record (no Nyquist bin) and an even one with a tone at the Nyquist
    /// frequency, whose amplitude is |X|/n rather than 2|X|/n.
    #[test]
    fn spectrum_of_odd_lengths_and_the_nyquist_bin() {
        let (n, dt) = (999, 0.01);
        let x: Vec<Real> = (0..n)
            .map(|j| 1.5 * (2.0 * std::f64::consts::PI * 3.0 * 9.0 / 9.99 * j as Real * dt).cos())
            .collect();
        let s = amplitude_spectrum(&x, dt, 100.0);
        assert_eq!(s.len(), n / 2 + 1);
        let (k, a) = s
            .iter()
            .enumerate()
            .fold((0, 0.0), |b, (k, &(_, a))| if a > b.1 { (k, a) } else { b });
        assert_eq!(k, 27);
        assert!((a - 1.5).abs() < 1e-10, "{a}");
        let x: Vec<Real> = (0..8)
            .map(|j| if j % 2 == 0 { 0.25 } else { -0.25 })
            .collect();
        let s = amplitude_spectrum(&x, 1.0, 1.0);
        assert!((s[4].1 - 0.25).abs() < 1e-15 && s[1..4].iter().all(|p| p.1 < 1e-15));
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
