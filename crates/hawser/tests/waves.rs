//! The sea state against linear wave theory: the dispersion relation, regular
//! Airy kinematics at several depths, Wheeler stretching, the deep-water limit, spectra
//! recovered from generated elevation records, reproducibility from the seed, and a taut line
//! loaded by a regular wave.

mod common;
use common::*;
use hawser::math::{Real, Vec3};
use hawser::model::{MassMatrix, Settings, TimeStep};
use hawser::physics::environment::Environment;
use hawser::physics::waves::{
    IrregularSea, RegularWave, SeaState, Spectrum, Stretching, WaveKinematics, WaveSpec, Waves,
    jonswap_normalisation, wavenumber,
};
use hawser::simulation::{Observer, Simulation};
use hawser::system::System;
use hawser::validation::signal::fft;
use std::f64::consts::PI;

const G: Real = 9.80665;

fn regular(
    height: Real,
    period: Real,
    direction: Real,
    depth: Real,
    stretching: Stretching,
) -> Waves {
    regular_ramped(height, period, direction, depth, stretching, 0.0)
}

fn regular_ramped(
    height: Real,
    period: Real,
    direction: Real,
    depth: Real,
    stretching: Stretching,
    ramp_time: Real,
) -> Waves {
    Waves::new(
        &WaveSpec {
            sea: SeaState::Regular(RegularWave {
                height,
                period,
                direction,
            }),
            ramp_time,
            stretching,
        },
        depth,
        G,
    )
    .expect("valid waves")
}

fn jonswap(seed: u64, components: usize, spreading: Option<Real>, depth: Real) -> Waves {
    irregular(
        Spectrum::Jonswap {
            significant_height: 4.0,
            peak_period: 10.0,
            peak_enhancement: 3.3,
        },
        seed,
        components,
        spreading,
        depth,
    )
}

fn irregular(
    spectrum: Spectrum,
    seed: u64,
    components: usize,
    spreading: Option<Real>,
    depth: Real,
) -> Waves {
    let wp = spectrum.peak_frequency();
    Waves::new(
        &WaveSpec {
            sea: SeaState::Irregular(IrregularSea {
                spectrum,
                direction: 0.3,
                spreading,
                seed,
                components,
                frequency_range: (0.5 * wp, 5.0 * wp),
            }),
            ramp_time: 0.0,
            stretching: Stretching::Wheeler,
        },
        depth,
        G,
    )
    .expect("valid waves")
}

fn close(a: Real, b: Real, tol: Real) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300)
}

// ---------------------------------------------------------------------------------------------
// Dispersion relation
// ---------------------------------------------------------------------------------------------

/// h/L against the deep-water h/L0 (L0 = g T²/2π): the classical table of linear wave theory
/// (e.g. the Shore Protection Manual's Table C-1 prints 0.04032, 0.09416, 0.1410, 0.2251,
/// 0.5018), here to 15 digits from a 40-digit root of (h/L) tanh(2π h/L) = h/L0 (mpmath).
/// From very shallow (kh = 0.08) to deep (kh = 6.3) water. Tolerance 1e-14 relative.
#[test]
fn dispersion_matches_the_tables_from_shallow_to_deep_water() {
    let table = [
        (0.001, 0.0126288889297232),
        (0.01, 0.0403168448751839),
        (0.02, 0.0576281876205266),
        (0.05, 0.0941548696271501),
        (0.1, 0.140980696875425),
        (0.2, 0.225115318254942),
        (0.3, 0.312118456490887),
        (0.5, 0.501828362547556),
        (1.0, 1.0000069740978),
    ];
    let depth = 30.0;
    for (h_over_l0, h_over_l) in table {
        let l0 = depth / h_over_l0;
        let omega = (2.0 * PI * G / l0).sqrt();
        let k = wavenumber(omega, depth, G);
        let got = depth * k / (2.0 * PI);
        assert!(
            close(got, h_over_l, 1e-14),
            "h/L0 = {h_over_l0}: h/L = {got:.16} vs {h_over_l}"
        );
    }
}

/// Physical cases (g = 9.80665) against 40-digit roots: wavelength of a 10 s wave in 1 m and
/// 20 m of water, 8 s in 50 m, 12 s in 100 m, 6 s in 1000 m, 20 s in 5 m. Then every k from
/// 1e-5 to 1 rad/m in depths from 0.5 m to 5 km: ω = √(g k tanh kh) solved back to k within
/// 4 ulp, and in shallow water the wave speed tends to √(g h).
#[test]
fn dispersion_is_solved_to_machine_precision() {
    let cases = [
        (10.0, 1.0, 0.20199710165684718),
        (10.0, 20.0, 0.05183725263394577),
        (8.0, 50.0, 0.06312967213742764),
        (12.0, 100.0, 0.028157176843015774),
        (6.0, 1000.0, 0.11182439581632371),
        (20.0, 5.0, 0.04524443853258179),
    ];
    for (period, depth, k_ref) in cases {
        let k = wavenumber(2.0 * PI / period, depth, G);
        assert!(
            close(k, k_ref, 4e-16),
            "T {period}, h {depth}: {k} vs {k_ref}"
        );
    }
    let mut worst: Real = 0.0;
    for i in 0..=50 {
        let k = 1e-5 * (1e5 as Real).powf(i as Real / 50.0);
        for depth in [0.5, 3.0, 20.0, 150.0, 5000.0] {
            let omega = (G * k * (k * depth).tanh()).sqrt();
            let back = wavenumber(omega, depth, G);
            worst = worst.max((back - k).abs() / k);
        }
    }
    assert!(worst < 4.0 * Real::EPSILON, "round trip error {worst:.2e}");
    // Shallow water: c = ω/k → √(g h) (kh = 1e-4).
    let depth = 2.0;
    let omega = 1e-4 / depth * (G * depth).sqrt();
    let c = omega / wavenumber(omega, depth, G);
    assert!(close(c, (G * depth).sqrt(), 1e-8), "{c}");
    // Deep water: k = ω²/g exactly.
    assert_eq!(wavenumber(1.3, Real::INFINITY, G), 1.3 * 1.3 / G);
}

// ---------------------------------------------------------------------------------------------
// Regular waves
// ---------------------------------------------------------------------------------------------

/// Closed-form linear theory for a wave along x: (u, w, du/dt, dw/dt, p_d/ρ) at (x, z, t),
/// written directly with cosh/sinh (finite depth) or exp (deep water).
fn airy(a: Real, omega: Real, k: Real, depth: Real, x: Real, z: Real, t: Real) -> [Real; 5] {
    let th = k * x - omega * t;
    let (c, s, p) = if depth.is_finite() {
        (
            (k * (z + depth)).cosh() / (k * depth).sinh(),
            (k * (z + depth)).sinh() / (k * depth).sinh(),
            (k * (z + depth)).cosh() / (k * depth).cosh(),
        )
    } else {
        let e = (k * z).exp();
        (e, e, e)
    };
    [
        a * omega * c * th.cos(),
        a * omega * s * th.sin(),
        a * omega * omega * c * th.sin(),
        -a * omega * omega * s * th.cos(),
        G * a * p * th.cos(),
    ]
}

/// Checks (u_x, u_y, u_z, ∂u_x/∂t, ∂u_z/∂t, p_d/ρ) of `got` against `want`, each within its
/// absolute tolerance.
fn assert_fields(got: &WaveKinematics, want: [Real; 6], tol: [Real; 6], what: &str) {
    let fields = [
        got.velocity.x,
        got.velocity.y,
        got.velocity.z,
        got.acceleration.x,
        got.acceleration.z,
        got.kinematic_pressure,
    ];
    for i in 0..6 {
        assert!(
            (fields[i] - want[i]).abs() <= tol[i],
            "{what}, field {i}: {} vs {}",
            fields[i],
            want[i]
        );
    }
}

/// Below the mean level (vertical stretching is plain linear theory there) every field matches
/// the closed form in shallow (kh = 0.3), intermediate (kh = 1.3) and deep (kh = 4, ∞) water,
/// at points from the surface to the seabed, over a period: amplitude, phase and decay with
/// depth at once. Tolerance 1e-12 of the field's amplitude at the surface (the closed form's
/// own rounding in cosh/sinh is ~1e-15).
#[test]
fn regular_kinematics_match_linear_theory_at_several_depths() {
    let (height, period) = (2.0, 9.0);
    let omega = 2.0 * PI / period;
    for depth in [4.0, 60.0, 500.0, Real::INFINITY] {
        let w = regular(height, period, 0.0, depth, Stretching::Vertical);
        let k = wavenumber(omega, depth, G);
        let a = height / 2.0;
        let top = airy(a, omega, k, depth, 0.0, 0.0, 0.0);
        let scale = [
            top[0],
            top[0],
            top[0],
            top[2].max(a * omega * omega),
            a * omega * omega,
            top[4],
        ];
        let bottom = if depth.is_finite() { -depth } else { -300.0 };
        for iz in 0..=10 {
            let z = -a - (bottom + a).abs() * iz as Real / 10.0;
            for it in 0..8 {
                let t = period * it as Real / 8.0 + 0.37;
                let x = 13.0;
                let got = w.kinematics(&Vec3::new(x, 5.0, z), t);
                assert!(got.submerged);
                let [u, w, du, dw, p] = airy(a, omega, k, depth, x, z, t);
                assert_fields(
                    &got,
                    [u, 0.0, w, du, dw, p],
                    scale.map(|s| 1e-12 * s.abs()),
                    &format!("h {depth}, z {z}, t {t}"),
                );
                assert_eq!(got.velocity.y, 0.0);
            }
        }
        // Decay with depth: the horizontal velocity amplitude at z relative to the surface is
        // cosh k(z+h)/cosh kh (e^{kz} in deep water); at the crest phase (θ = 0).
        let z = -0.3 * bottom.abs();
        let ratio = w.kinematics(&Vec3::new(0.0, 0.0, z), period).velocity.x
            / (a * omega
                * if depth.is_finite() {
                    1.0 / (k * depth).tanh()
                } else {
                    1.0
                });
        let expect = if depth.is_finite() {
            (k * (z + depth)).cosh() / (k * depth).cosh()
        } else {
            (k * z).exp()
        };
        assert!(close(ratio, expect, 1e-12), "decay {ratio} vs {expect}");
    }
}

/// The direction rotates the field: a wave toward β = 30° seen at a point p equals the wave
/// toward 0° seen at p rotated by −β, with its horizontal velocity rotated by +β.
#[test]
fn direction_rotates_the_field() {
    let beta = 30f64.to_radians();
    let along = regular(3.0, 11.0, 0.0, 80.0, Stretching::Wheeler);
    let rotated = regular(3.0, 11.0, beta, 80.0, Stretching::Wheeler);
    let (s, c) = beta.sin_cos();
    for (x, y, z, t) in [
        (10.0, 20.0, -5.0, 1.0),
        (-40.0, 7.0, -30.0, 4.5),
        (3.0, -9.0, 0.5, 7.0),
    ] {
        let p = Vec3::new(x, y, z);
        let q = Vec3::new(c * x + s * y, -s * x + c * y, z);
        let a = along.kinematics(&q, t);
        let b = rotated.kinematics(&p, t);
        let v = Vec3::new(
            c * a.velocity.x - s * a.velocity.y,
            s * a.velocity.x + c * a.velocity.y,
            a.velocity.z,
        );
        assert!((b.velocity - v).norm() < 1e-12, "{} vs {}", b.velocity, v);
        assert!((rotated.elevation(x, y, t) - along.elevation(q.x, q.y, t)).abs() < 1e-12);
    }
}

/// The acceleration is the local ∂u/∂t: against a central difference in time (step 1e-4 s,
/// error ~ (ω δt)² / 6 ≈ 1e-9), during the build-up ramp (which adds ṙ u) and after it.
/// Tolerance 1e-7 of a ω². With Wheeler stretching the stretched height moves with η, and
/// ∂u/∂t at a fixed point differs from the linear acceleration at the stretched height by
/// (∂u/∂z') ż', which is of order k a relative to it (second order in the steepness, dropped by
/// linear theory): the difference stays within 2 k a of a ω².
#[test]
fn acceleration_is_the_time_derivative_of_velocity() {
    let (height, period, depth) = (2.0, 8.0, 40.0);
    let omega = 2.0 * PI / period;
    let a = height / 2.0;
    let k = wavenumber(omega, depth, G);
    let scale = a * omega * omega;
    let dt = 1e-4;
    for (stretching, tol) in [
        (Stretching::Vertical, 1e-7),
        (Stretching::Wheeler, 2.0 * k * a),
    ] {
        let w = regular_ramped(height, period, 0.4, depth, stretching, 12.0);
        for t in [3.1, 7.9, 10.3, 15.2, 20.7] {
            for z in [-35.0, -10.0, -2.0, -0.9] {
                let p = Vec3::new(6.0, -2.0, z);
                let fd = (w.kinematics(&p, t + dt).velocity - w.kinematics(&p, t - dt).velocity)
                    / (2.0 * dt);
                let acc = w.kinematics(&p, t).acceleration;
                assert!(
                    (fd - acc).norm() <= tol * scale,
                    "{stretching:?} t {t} z {z}: {acc} vs {fd}"
                );
            }
        }
    }
}

/// Wheeler stretching: under the crest the velocity at the surface z = η is the linear velocity
/// at z = 0 (a ω coth kh), the dynamic pressure there is ρ g η (zero total pressure), and above η
/// everything is zero; under the trough the surface again carries the z = 0 values and the band
/// η < z ≤ 0 is dry. Half-way down the stretched column the field is the linear one at the
/// mapped height z' = h (z − η)/(h + η).
#[test]
fn wheeler_stretching_maps_the_surface_to_the_mean_level() {
    let (height, period) = (6.0, 10.0);
    let omega = 2.0 * PI / period;
    let a = height / 2.0;
    for depth in [30.0, Real::INFINITY] {
        let w = regular(height, period, 0.0, depth, Stretching::Wheeler);
        let k = wavenumber(omega, depth, G);
        let coth = if depth.is_finite() {
            1.0 / (k * depth).tanh()
        } else {
            1.0
        };
        // Crest at x = 0, t = 0.
        let eta = w.elevation(0.0, 0.0, 0.0);
        assert!(close(eta, a, 1e-15));
        let surface = w.kinematics(&Vec3::new(0.0, 0.0, eta), 0.0);
        assert!(surface.submerged);
        assert!(
            close(surface.velocity.x, a * omega * coth, 1e-14),
            "{}",
            surface.velocity.x
        );
        assert!(surface.velocity.z.abs() < 1e-14);
        assert!(close(surface.kinematic_pressure, G * eta, 1e-14));
        let above = w.kinematics(&Vec3::new(0.0, 0.0, eta + 1e-9), 0.0);
        assert!(!above.submerged);
        assert_eq!(above.velocity, Vec3::zeros());
        assert_eq!(above.acceleration, Vec3::zeros());
        assert_eq!(above.kinematic_pressure, 0.0);
        // Trough at t = T/2.
        let t = period / 2.0;
        let trough = w.elevation(0.0, 0.0, t);
        assert!(close(trough, -a, 1e-14));
        let surface = w.kinematics(&Vec3::new(0.0, 0.0, trough), t);
        assert!(close(surface.velocity.x, -a * omega * coth, 1e-13));
        let dry = w.kinematics(&Vec3::new(0.0, 0.0, -0.5 * a), t);
        assert!(!dry.submerged && dry.velocity == Vec3::zeros());
        // Inside the column.
        let z = -12.0;
        let zs = if depth.is_finite() {
            depth * (z - eta) / (depth + eta)
        } else {
            z - eta
        };
        let got = w.kinematics(&Vec3::new(0.0, 0.0, z), 0.0).velocity.x;
        let want = airy(a, omega, k, depth, 0.0, zs, 0.0)[0];
        assert!(close(got, want, 1e-13), "{got} vs {want}");
    }
}

/// The deep-water field equals the finite-depth one when kh ≫ 1: identical for kh > 20 (tanh
/// and the e^{−2kh} terms round away), within 3 e^{−k(z+2h)} (the size of the neglected terms,
/// relative to the surface value) at kh = 6. (With vertical stretching: Wheeler's map itself depends on h, z' = h (z − η)/(h + η)
/// against z − η, a relative shift of the stretched height of order η/h, which vanishes only as
/// h → ∞; checked within 2 k |z − η| |η| / h.)
#[test]
fn deep_water_is_the_limit_of_finite_depth() {
    let (height, period) = (2.0, 7.0);
    let k = (2.0 * PI / period).powi(2) / G;
    let scale = PI * height / period;
    for stretching in [Stretching::Vertical, Stretching::Wheeler] {
        let deep = regular(height, period, 0.2, Real::INFINITY, stretching);
        for kh in [25.0, 6.0] {
            let depth = kh / k;
            let finite = regular(height, period, 0.2, depth, stretching);
            for (z, t) in [(-1.0, 0.3), (-8.0, 2.0), (0.5, 0.0), (-20.0, 5.5)] {
                let p = Vec3::new(4.0, 1.0, z);
                let (d, f) = (deep.kinematics(&p, t), finite.kinematics(&p, t));
                if stretching == Stretching::Vertical && kh > 20.0 {
                    assert_eq!(d, f, "kh {kh} z {z}");
                    continue;
                }
                let tol = 3.0 * (-k * (z.min(0.0) + 2.0 * depth)).exp();
                let tol = if stretching == Stretching::Wheeler {
                    let eta = deep.elevation(4.0, 1.0, t);
                    tol + 2.0 * k * (z - eta).abs() * eta.abs() / depth
                } else {
                    tol
                };
                let dv = (d.velocity - f.velocity).norm();
                let da = (d.acceleration - f.acceleration).norm();
                assert!(dv <= tol * scale, "{stretching:?} kh {kh} z {z}: {dv:.2e}");
                assert!(
                    da <= tol * scale * 2.0 * PI / period,
                    "{stretching:?} kh {kh}"
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Irregular seas
// ---------------------------------------------------------------------------------------------

/// The JONSWAP normalisation gives m0 = Hs²/16: the spectrum integrated independently
/// (Simpson, 2e5 intervals on [0.05, 60] rad/s, tail beyond by its ω⁻⁵ asymptote) matches within
/// 1e-8, for γ from 1 (Pierson–Moskowitz) to 7. DNV-RP-C205's approximation
/// A_γ = 1 − 0.287 ln γ agrees within 2 % (it is 1.75 % low at γ = 7).
#[test]
fn jonswap_normalisation_recovers_the_significant_height() {
    for gamma in [1.0, 2.0, 3.3, 5.0, 7.0] {
        let s = Spectrum::Jonswap {
            significant_height: 3.0,
            peak_period: 9.0,
            peak_enhancement: gamma,
        };
        let density = s.density_function();
        let (a, b, n) = (0.05, 60.0, 200_000);
        let h = (b - a) / n as Real;
        let mut m0 = density(a) + density(b);
        for i in 1..n {
            m0 += if i % 2 == 1 { 4.0 } else { 2.0 } * density(a + i as Real * h);
        }
        m0 *= h / 3.0;
        m0 += density(b) * b / 4.0; // ∫_b^∞ c ω⁻⁵ = c b⁻⁴/4 = S(b) b/4
        assert!(close(m0, 9.0 / 16.0, 1e-8), "γ {gamma}: m0 {m0}");
        let dnv = 1.0 - 0.287 * gamma.ln();
        assert!(close(jonswap_normalisation(gamma), dnv, 0.02), "γ {gamma}");
    }
}

/// Welch's one-sided spectral estimate S(ω) [m²·s/rad] of a record sampled every `dt`:
/// Hann-windowed segments of `m` samples overlapping by half. Returns (S per bin, segments).
fn welch(x: &[Real], dt: Real, m: usize) -> (Vec<Real>, usize) {
    let window: Vec<Real> = (0..m)
        .map(|i| 0.5 * (1.0 - (2.0 * PI * i as Real / m as Real).cos()))
        .collect();
    let u: Real = window.iter().map(|w| w * w).sum::<Real>() / m as Real;
    let mut psd = vec![0.0; m / 2 + 1];
    let mut segments = 0;
    let mut start = 0;
    while start + m <= x.len() {
        let seg = &x[start..start + m];
        let mean = seg.iter().sum::<Real>() / m as Real;
        let mut re: Vec<Real> = seg
            .iter()
            .zip(&window)
            .map(|(v, w)| (v - mean) * w)
            .collect();
        let mut im = vec![0.0; m];
        fft(&mut re, &mut im);
        for (i, p) in psd.iter_mut().enumerate() {
            let one_sided = if i == 0 || i == m / 2 { 1.0 } else { 2.0 };
            *p += one_sided * (re[i] * re[i] + im[i] * im[i]) * dt / (m as Real * u);
        }
        segments += 1;
        start += m / 2;
    }
    // Per Hz → per rad/s.
    psd.iter_mut()
        .for_each(|p| *p /= segments as Real * 2.0 * PI);
    (psd, segments)
}

/// Surface elevation at the origin every `dt` for `n` samples.
fn record(w: &Waves, dt: Real, n: usize) -> Vec<Real> {
    (0..n)
        .map(|i| w.elevation(0.0, 0.0, i as Real * dt))
        .collect()
}

/// Checks an elevation record of `waves` (spectrum `s`) against the spectrum: Hs, the peak and
/// the energy in bands. Returns (Hs measured, peak ω measured).
fn check_spectrum(waves: &Waves, s: &Spectrum, check_peak: bool) -> (Real, Real) {
    let field = waves.field().unwrap();
    let comps = field.components();
    // The record: 2^16 samples at 0.5 s (Nyquist 2π rad/s, above 5 ωp), 9.1 h.
    let (dt, n) = (0.5, 1 << 16);
    let duration = dt * n as Real;
    let x = record(waves, dt, n);
    let mean = x.iter().sum::<Real>() / n as Real;
    let m0_hat = x.iter().map(|v| (v - mean) * (v - mean)).sum::<Real>() / n as Real;
    // The sea's own m0: the components carry the spectrum's energy over the frequency range,
    // Hs²/16 less the tails outside it.
    let m0_sea: Real = comps
        .iter()
        .map(|c| 0.5 * c.amplitude() * c.amplitude())
        .sum();
    let m0 = s.significant_height().powi(2) / 16.0;
    assert!(
        m0_sea < m0 && m0_sea > 0.995 * m0,
        "truncation of the range: m0 {m0_sea} of {m0}"
    );
    // Random phases make the sample variance over T scatter about m0_sea through the cross
    // terms of pairs of components: each pair (i, j) adds a_i a_j times the mean of
    // cos((ω_i − ω_j) t + ψ) over T, whose variance over a uniform ψ is 2 sin²(δT/2)/(δT)².
    let mut var = 0.0;
    for i in 0..comps.len() {
        for j in i + 1..comps.len() {
            let d = (comps[i].angular_frequency() - comps[j].angular_frequency()) * duration;
            let aa = comps[i].amplitude() * comps[j].amplitude();
            var += aa * aa * 2.0 * (0.5 * d).sin().powi(2) / (d * d);
        }
    }
    let sigma = var.sqrt();
    assert!(
        (m0_hat - m0_sea).abs() <= 4.0 * sigma,
        "m0 {m0_hat} vs {m0_sea} (σ {sigma:.2e})"
    );
    let hs_hat = 4.0 * m0_hat.sqrt();
    // Relative to the requested Hs: the truncation (< 0.25 %) plus 4σ of the estimate.
    let tol = 1.0 - (m0_sea / m0).sqrt() + 2.0 * sigma / m0_sea;
    assert!(
        close(hs_hat, s.significant_height(), tol.max(1e-3)),
        "Hs {hs_hat} vs {} (tolerance {tol:.2e})",
        s.significant_height()
    );
    // Energy in bands from 0.7 to 2.5 ωp, from the periodogram of the whole record (bins
    // 2π/T = 1.9e-4 rad/s, 74 to a component's bin) against the spectrum integrated over the
    // band. Band edges fall on edges of the components' frequency bins, so each component's
    // energy belongs to one band; what remains is the rectangular window's leakage across the
    // edges (a sinusoid D periodogram bins from an edge leaks at most 1/(π² D) of its energy
    // across, ~0.5 % of a component on average) and the cross terms of pairs of components
    // within a band (as for m0, ~0.1 %). Tolerance 1 %.
    let Some(SeaState::Irregular(sea)) = Some(&field.spec().sea) else {
        unreachable!()
    };
    let (w0, w1) = sea.frequency_range;
    let dwc = (w1 - w0) / sea.components as Real;
    let mut re: Vec<Real> = x.iter().map(|v| v - mean).collect();
    let mut im = vec![0.0; n];
    fft(&mut re, &mut im);
    let dw = 2.0 * PI / duration;
    let wp = s.peak_frequency();
    let mut worst: Real = 0.0;
    let edges = [0.7, 0.85, 1.0, 1.15, 1.35, 1.7, 2.5];
    for e in edges.windows(2) {
        let (wa, wb) = (
            w0 + ((e[0] * wp - w0) / dwc).round() * dwc,
            w0 + ((e[1] * wp - w0) / dwc).round() * dwc,
        );
        let (ia, ib) = ((wa / dw).round() as usize, (wb / dw).round() as usize);
        let est: Real = (ia..ib)
            .map(|i| 2.0 * (re[i] * re[i] + im[i] * im[i]) / (n as Real * n as Real))
            .sum();
        let steps = 2000;
        let h = (wb - wa) / steps as Real;
        let density = s.density_function();
        let want: Real = (0..steps)
            .map(|i| density(wa + (i as Real + 0.5) * h) * h)
            .sum();
        let err = (est - want) / want;
        worst = worst.max(err.abs());
        assert!(err.abs() <= 0.01, "band {e:?} ωp: {est} vs {want} m²");
    }
    // The peak of a Welch estimate with 256 s segments (511 of them, bins 0.0245 rad/s).
    let m = 512;
    let (psd, _) = welch(&x, dt, m);
    let dw = 2.0 * PI / (m as Real * dt);
    let peak = (1..psd.len())
        .max_by(|&a, &b| psd[a].partial_cmp(&psd[b]).unwrap())
        .unwrap();
    let w_peak = peak as Real * dw;
    if check_peak {
        assert!(
            (w_peak - wp).abs() <= dw,
            "peak at {w_peak} rad/s vs {wp} (bin {dw})"
        );
    }
    eprintln!("band energies within {:.3} %", 100.0 * worst);
    eprintln!(
        "Hs {hs_hat:.4} m (requested {}, sea {:.4}, σ(m0) {sigma:.2e} m²); peak {w_peak:.4} rad/s \
         vs {:.4} (bin {dw:.4})",
        s.significant_height(),
        4.0 * m0_sea.sqrt(),
        s.peak_frequency()
    );
    (hs_hat, w_peak)
}

/// A JONSWAP sea (Hs 4 m, Tp 10 s, γ 3.3, 200 components, 0.5–5 ωp) recovered from a 9.1 h
/// elevation record: Hs within the statistics of the estimate, the Welch peak within one bin
/// of ωp, the energy in six bands around the peak within their χ² tolerance.
#[test]
fn jonswap_spectrum_is_recovered_from_the_elevation_record() {
    let s = Spectrum::Jonswap {
        significant_height: 4.0,
        peak_period: 10.0,
        peak_enhancement: 3.3,
    };
    check_spectrum(&jonswap(7, 200, None, 150.0), &s, true);
}

/// A Pierson–Moskowitz sea (Hs 2.5 m, Tp 8 s) likewise; its flat peak (the spectrum changes by
/// 1.5 % over a bin) is too flat for a one-bin peak test, so the mean period T1 = 2π m0/m1 of
/// the Welch estimate is checked instead, against the spectrum's over the frequency range,
/// within 0.2 % (Hann leakage and the statistics of m1, like those of m0, are ~0.1 %).
#[test]
fn pierson_moskowitz_spectrum_is_recovered_from_the_elevation_record() {
    let s = Spectrum::PiersonMoskowitz {
        significant_height: 2.5,
        peak_period: 8.0,
    };
    let waves = irregular(s.clone(), 11, 200, None, Real::INFINITY);
    check_spectrum(&waves, &s, false);
    let (dt, n) = (0.5, 1 << 16);
    let (psd, _) = welch(&record(&waves, dt, n), dt, 512);
    let dw = 2.0 * PI / (512.0 * dt);
    let m0: Real = psd.iter().sum::<Real>() * dw;
    let m1: Real = psd
        .iter()
        .enumerate()
        .map(|(i, p)| p * i as Real * dw)
        .sum::<Real>()
        * dw;
    let t1 = 2.0 * PI * m0 / m1;
    // T1 of the PM spectrum is Tp (5/4)^{-1/4} / Γ(3/4) = 0.77181 Tp = 6.1742 s; cut at 5 fp
    // it is 6.2258 s (the tail above holds 0.2 % of m0 but more of m1).
    let full = 8.0 * 1.25f64.powf(-0.25) / 1.2254167024651776;
    let density = s.density_function();
    let (wa, wb) = (0.5 * s.peak_frequency(), 5.0 * s.peak_frequency());
    let h = (wb - wa) / 20000.0;
    let (mut c0, mut c1) = (0.0, 0.0);
    for i in 0..20000 {
        let w = wa + (i as Real + 0.5) * h;
        c0 += density(w) * h;
        c1 += w * density(w) * h;
    }
    let expect = 2.0 * PI * c0 / c1;
    assert!(close(expect, 6.2258, 1e-4) && close(full, 6.1742, 1e-4));
    eprintln!("T1 {t1:.4} s vs {expect:.4} s");
    assert!(close(t1, expect, 0.002), "T1 {t1} vs {expect}");
}

/// An irregular, short-crested sea is the sum of its components: velocity, acceleration and
/// dynamic pressure against the closed forms of linear theory summed over the components (their
/// amplitudes, frequencies, wavenumbers, directions and phases), at the Wheeler-mapped height,
/// in 45 m of water; with 100 components (phases kept on the stack) and 300 (computed twice).
/// Tolerance 1e-12 of the sum of the component amplitudes.
#[test]
fn irregular_kinematics_are_the_sum_of_the_components() {
    let depth = 45.0;
    for n in [100, 300] {
        let w = jonswap(9, n, Some(5.0), depth);
        let comps = w.field().unwrap().components();
        let scale: Real = comps
            .iter()
            .map(|c| c.amplitude() * c.angular_frequency().powi(2).max(G))
            .sum();
        for (x, y, z, t) in [
            (3.0, -4.0, -2.0, 17.0),
            (-20.0, 11.0, -30.0, 140.5),
            (0.0, 0.0, -44.0, 3.3),
        ] {
            let eta: Real = comps
                .iter()
                .map(|c| {
                    let th = c.wavenumber() * (x * c.direction().cos() + y * c.direction().sin())
                        - c.angular_frequency() * t
                        + c.phase();
                    c.amplitude() * th.cos()
                })
                .sum();
            let zs = depth * (z - eta) / (depth + eta);
            let mut want = [0.0; 6];
            for c in comps {
                let (sb, cb) = c.direction().sin_cos();
                let xi = x * cb + y * sb;
                // The closed form along the component's direction, at the phase shifted by φ.
                let f = airy(
                    c.amplitude(),
                    c.angular_frequency(),
                    c.wavenumber(),
                    depth,
                    xi + c.phase() / c.wavenumber(),
                    zs,
                    t,
                );
                want[0] += f[0] * cb;
                want[1] += f[0] * sb;
                want[2] += f[1];
                want[3] += f[2] * cb;
                want[4] += f[3];
                want[5] += f[4];
            }
            let got = w.kinematics(&Vec3::new(x, y, z), t);
            assert_fields(
                &got,
                want,
                [1e-12 * scale; 6],
                &format!("{n} components, z {z}"),
            );
        }
    }
}

/// The same seed gives the same sea bit for bit; another seed another sea; spreading draws
/// directions without changing the frequencies and phases.
#[test]
fn the_seed_fixes_the_sea() {
    let a = jonswap(42, 120, None, 80.0);
    let b = jonswap(42, 120, None, 80.0);
    let c = jonswap(43, 120, None, 80.0);
    let ra = record(&a, 0.7, 2000);
    let rb = record(&b, 0.7, 2000);
    let rc = record(&c, 0.7, 2000);
    assert!(ra.iter().zip(&rb).all(|(x, y)| x.to_bits() == y.to_bits()));
    let p = Vec3::new(3.0, 4.0, -6.0);
    for t in [0.0, 10.0, 1234.5] {
        let (ka, kb) = (a.kinematics(&p, t), b.kinematics(&p, t));
        assert_eq!(
            ka.velocity.map(Real::to_bits),
            kb.velocity.map(Real::to_bits)
        );
        assert_eq!(
            ka.acceleration.map(Real::to_bits),
            kb.acceleration.map(Real::to_bits)
        );
    }
    let differ = ra
        .iter()
        .zip(&rc)
        .filter(|(x, y)| (*x - *y).abs() > 1e-3)
        .count();
    assert!(
        differ > 1900,
        "seeds 42 and 43 give nearly the same sea ({differ})"
    );
    let spread = jonswap(42, 120, Some(8.0), 80.0);
    for (x, y) in a
        .field()
        .unwrap()
        .components()
        .iter()
        .zip(spread.field().unwrap().components())
    {
        assert_eq!(x.angular_frequency(), y.angular_frequency());
        assert_eq!(x.phase(), y.phase());
        assert_eq!(x.amplitude(), y.amplitude());
    }
}

/// cos-2s spreading: the component directions β' follow D ∝ cos^{2s}((β' − β)/2), whose mean of
/// cos(β' − β) is s/(s + 1); with 4000 components the sample mean lies within 4 standard errors
/// (the sample standard deviation over √4000).
#[test]
fn spreading_follows_the_cos_2s_distribution() {
    for s in [1.0, 4.0, 15.0] {
        let w = jonswap(5, 4000, Some(s), Real::INFINITY);
        let c: Vec<Real> = w
            .field()
            .unwrap()
            .components()
            .iter()
            .map(|k| (k.direction() - 0.3).cos())
            .collect();
        let n = c.len() as Real;
        let mean = c.iter().sum::<Real>() / n;
        let sd = (c.iter().map(|x| (x - mean).powi(2)).sum::<Real>() / (n - 1.0)).sqrt();
        let expect = s / (s + 1.0);
        assert!(
            (mean - expect).abs() < 4.0 * sd / n.sqrt(),
            "s {s}: mean cos {mean} vs {expect}"
        );
    }
}

/// Bad wave inputs are errors, not panics.
#[test]
fn invalid_waves_are_rejected() {
    let spec = |height: Real, period: Real| WaveSpec {
        sea: SeaState::Regular(RegularWave {
            height,
            period,
            direction: 0.0,
        }),
        ramp_time: 0.0,
        stretching: Stretching::Wheeler,
    };
    assert!(Waves::new(&spec(1.0, 0.0), 10.0, G).is_err());
    assert!(Waves::new(&spec(-1.0, 5.0), 10.0, G).is_err());
    assert!(Waves::new(&spec(Real::NAN, 5.0), 10.0, G).is_err());
    assert!(Waves::new(&spec(1.0, 5.0), 0.0, G).is_err());
    assert!(Waves::new(&spec(1.0, 5.0), 10.0, 0.0).is_err());
    // A model whose waves were built for another depth is refused.
    let mut model = single_line(
        line_type(0.05, 20.0, 1e8),
        20.0,
        4,
        fixed("a", Vec3::new(0.0, 0.0, -30.0)),
        fixed("b", Vec3::new(0.0, 0.0, -10.0)),
        MassMatrix::Lumped,
    );
    model.environment.depth = 30.0;
    model.environment.waves = Waves::new(&spec(1.0, 5.0), 40.0, G).unwrap();
    assert!(model.validate().is_err());
    model.environment.waves = Waves::new(&spec(1.0, 5.0), 30.0, G).unwrap();
    assert!(model.validate().is_ok());
}

// ---------------------------------------------------------------------------------------------
// A line in waves
// ---------------------------------------------------------------------------------------------

/// The force the line puts on its top, every sample.
struct TopForce(Vec<(Real, Vec3)>);
impl Observer for TopForce {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, t, ws) = (view.system, view.time, view.workspace);
        self.0.push((t, system.end_force(ws, 0, true)));
        Ok(())
    }
}

/// A taut vertical riser (d 0.2 m, C_dn 1.2, C_an 1), 30 m from a seabed anchor to a fixed top
/// 2 m below the surface in 32 m of water, under a 2 m, 6 s regular wave along x (kh = 3.6).
/// The line's lowest lateral mode is near 1 Hz, six times the wave frequency, so it answers
/// quasi-statically: the top carries ∫ f_x(s) s/L ds of the lateral load f_x (s from the
/// anchor), made of the inertia ρA(1 + C_an) ∂u/∂t, in phase with sin ωt at x = 0, and the drag
/// ½ρ d C_dn |u| u, whose first harmonic (8/3π of its peak) is in phase with cos ωt. After the
/// 12 s ramp and a start-up transient, over six wave periods: the horizontal top force has the
/// wave period (upward mean crossings within 1 %), and its two first-harmonic parts match the
/// quasi-static inertia and drag within 10 % (the line's own inertia, its motion in the drag
/// and the dynamic amplification of the 1 Hz mode are each a few %). Vertical stretching keeps
/// the loads on the linear profiles.
#[test]
fn a_taut_riser_carries_the_wave_load_at_the_wave_period() {
    let (d, cd, depth, top) = (0.2, 1.2, 32.0, -2.0);
    let (height, period) = (2.0, 6.0);
    let mut lt = line_type(d, 60.0, 5.0e8);
    lt.drag = hawser::physics::hydrodynamics::DragModel::Morison {
        normal: cd,
        tangential: 0.0,
    };
    let length = depth + top;
    let mut model = single_line(
        lt,
        length - 0.02,
        30,
        fixed("anchor", Vec3::new(0.0, 0.0, -depth)),
        fixed("top", Vec3::new(0.0, 0.0, top)),
        MassMatrix::Lumped,
    );
    model.environment = Environment {
        depth,
        waves: regular_ramped(height, period, 0.0, depth, Stretching::Vertical, 12.0),
        ..Default::default()
    };
    let (t0, t1) = (24.0, 60.0);
    let sample = 0.02;
    model.settings = Settings {
        duration: t1,
        time_step: TimeStep::Auto,
        output_interval: sample,
        ..Default::default()
    };
    let system = System::new(&model).unwrap();
    let y0 = system.straight_state();
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let mut rec = TopForce(Vec::new());
    sim.run(t1, &mut rec).unwrap();
    let late: Vec<(Real, Real)> = rec
        .0
        .iter()
        .filter(|(t, _)| *t >= t0 - 1e-9 && *t < t1 - 1e-9)
        .map(|(t, f)| (*t, f.x))
        .collect();
    let fx: Vec<Real> = late.iter().map(|p| p.1).collect();
    let mean = fx.iter().sum::<Real>() / fx.len() as Real;
    let measured_period = mean_period(&upward_crossings(&fx, mean, sample));
    // First-harmonic parts over the six periods.
    let omega = 2.0 * PI / period;
    let (mut fs, mut fc) = (0.0, 0.0);
    for (t, f) in &late {
        fs += f * (omega * t).sin();
        fc += f * (omega * t).cos();
    }
    let n = late.len() as Real;
    let (fs, fc) = (2.0 * fs / n, 2.0 * fc / n);
    // Quasi-static expectation: at x = 0, u = a ω C(z) cos ωt and ∂u/∂t = −a ω² C(z) sin ωt.
    let k = wavenumber(omega, depth, G);
    let a = height / 2.0;
    let rho = 1025.0;
    let area = PI * d * d / 4.0;
    let steps = 3000;
    let (mut inertia, mut drag) = (0.0, 0.0);
    for i in 0..steps {
        let s = (i as Real + 0.5) / steps as Real * length;
        let c = (k * s).cosh() / (k * depth).sinh();
        let share = s / length * length / steps as Real;
        inertia -= rho * area * 2.0 * a * omega * omega * c * share;
        drag += 0.5 * rho * d * cd * (a * omega * c).powi(2) * 8.0 / (3.0 * PI) * share;
    }
    eprintln!(
        "top force x: period {measured_period:.4} s; sin part {fs:.1} N (quasi-static inertia \
         {inertia:.1} N), cos part {fc:.1} N (quasi-static drag {drag:.1} N)"
    );
    assert!(
        close(measured_period, period, 0.01),
        "period {measured_period}"
    );
    assert!(close(fs, inertia, 0.1), "inertia part {fs} vs {inertia}");
    assert!(close(fc, drag, 0.1), "drag part {fc} vs {drag}");
}

// ---- Kinematics at the static position (physics::static_kinematics) ----

use hawser::physics::static_kinematics::StaticPositionKinematics;

/// At the sample times the cache holds the direct sum at the static position: the time and
/// space parts of every phase combined by angle addition instead of one sine–cosine pair,
/// so they agree to round-off, within 1e-12 of Σ a_j max(ω_j², 1) (a JONSWAP sea of 200
/// components in 150 m, short-crested, Wheeler; points from the bed to above the crests).
#[test]
fn static_position_samples_are_the_direct_sum() {
    let waves = jonswap(7, 200, Some(4.0), 150.0);
    let f = waves.field().unwrap();
    let scale: Real = f
        .components()
        .iter()
        .map(|c| c.amplitude() * c.angular_frequency().powi(2).max(1.0))
        .sum();
    let points: Vec<Vec3> = [-149.0, -60.0, -8.0, -1.0, 0.5, 4.0]
        .iter()
        .enumerate()
        .map(|(i, &z)| Vec3::new(30.0 * i as Real - 70.0, 11.0 * i as Real, z))
        .collect();
    let h = 0.1;
    let mut table = StaticPositionKinematics::new(f, h, &[points.clone()]);
    for m in [3, 4, 57, 58, 1200] {
        let t = m as Real * h;
        table.prepare(t);
        for (p, x) in points.iter().enumerate() {
            let eta = f.elevation(x.x, x.y, t);
            let (wet, u, a) = table.at(p, x.z);
            assert_eq!(wet, x.z <= eta, "point {p} at t {t}: wet");
            // The direct field at min(z, η), which is what a point carried into the water
            // above its static position takes.
            let k = f.kinematics(&Vec3::new(x.x, x.y, x.z.min(eta)), t);
            if wet {
                assert!(
                    (u - k.velocity).norm() < 1e-12 * scale,
                    "u at point {p}, t {t}"
                );
                assert!(
                    (a - k.acceleration).norm() < 1e-12 * scale,
                    "a at point {p}, t {t}"
                );
            } else {
                assert_eq!((u, a), (Vec3::zeros(), Vec3::zeros()));
            }
        }
    }
}

/// Between samples the interpolation is cubic: on a regular wave at a fixed depth (vertical
/// stretching, so each field is a pure sinusoid of frequency ω) its largest error over many
/// times (x components) stays within the Lagrange bound (3/128)(ω h)⁴ of the amplitude (+1e-13 round-off),
/// comes within 30 % of it (the bound is reached at mid-interval), and falls 16-fold when h
/// halves (fourth order: the ratio within 14–18).
#[test]
fn static_position_interpolation_is_fourth_order() {
    let (height, period, depth) = (2.0, 6.0, 60.0);
    let waves = regular(height, period, 0.4, depth, Stretching::Vertical);
    let f = waves.field().unwrap();
    let omega = 2.0 * PI / period;
    let x = Vec3::new(12.0, -5.0, -9.0);
    // The x components: pure sinusoids (the vector's norm is not).
    let error = |h: Real| {
        let mut table = StaticPositionKinematics::new(f, h, &[vec![x]]);
        let (mut eu, mut ea, mut au, mut aa) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
        for i in 0..4000 {
            let t = 3.0 + 0.00731 * i as Real;
            table.prepare(t);
            let (_, u, a) = table.at(0, x.z);
            let k = f.kinematics(&x, t);
            eu = eu.max((u.x - k.velocity.x).abs());
            ea = ea.max((a.x - k.acceleration.x).abs());
            au = au.max(k.velocity.x.abs());
            aa = aa.max(k.acceleration.x.abs());
        }
        (eu / au, ea / aa)
    };
    for h in [0.05, 0.1, 0.2] {
        let bound = 3.0 / 128.0 * (omega * h).powi(4);
        let (eu, ea) = error(h);
        eprintln!("h {h} s: velocity {eu:.3e}, acceleration {ea:.3e}, bound {bound:.3e}");
        for e in [eu, ea] {
            assert!(
                e <= bound * 1.0001 + 1e-13,
                "h {h}: {e:.3e} > bound {bound:.3e}"
            );
            assert!(
                e >= 0.7 * bound,
                "h {h}: {e:.3e} far below the bound {bound:.3e}"
            );
        }
    }
    let (e1, _) = error(0.2);
    let (e2, _) = error(0.1);
    assert!(
        (14.0..18.0).contains(&(e1 / e2)),
        "order: ratio {}",
        e1 / e2
    );
}

/// A sample's value depends only on its index: stepping forward, jumping back to the start,
/// jumping ahead past the ring and coming back give the same bits at the same times (so
/// restarts and any stepping order reproduce a run), and two caches of the same seed agree
/// bit for bit.
#[test]
fn static_position_cache_is_reproducible() {
    let waves = jonswap(3, 120, None, 200.0);
    let f = waves.field().unwrap();
    let points = vec![Vec3::new(5.0, 1.0, -30.0), Vec3::new(-40.0, 9.0, -2.0)];
    let times: Vec<Real> = (0..300).map(|i| 0.013 * i as Real).collect();
    let read = |table: &mut StaticPositionKinematics, t: Real| {
        table.prepare(t);
        (table.at(0, -30.0), table.at(1, -2.0))
    };
    let mut a = StaticPositionKinematics::new(f, 0.08, &[points.clone()]);
    let forward: Vec<_> = times.iter().map(|&t| read(&mut a, t)).collect();
    let again = jonswap(3, 120, None, 200.0);
    let mut b = StaticPositionKinematics::new(again.field().unwrap(), 0.08, &[points]);
    for (i, &t) in times.iter().enumerate().rev() {
        if i % 7 == 0 {
            read(&mut b, 500.0 + t); // far ahead: the ring is refilled
        }
        assert_eq!(read(&mut b, t), forward[i], "t {t}");
    }
}

/// Every formulation numbers its quadrature points for the static-position cache: the taut
/// riser above (H 2 m, T 6 s, 12 s ramp, vertical stretching) as `fe`, `hermite` and `dg`,
/// with direct and static-position kinematics (h = T/60). The first harmonics of the top
/// force over 18–24 s (one period after the ramp) agree within 2 k δ of their amplitude + the interpolation bound, δ the
/// largest node displacement from the static position in the run (what the static-position
/// field leaves out is the change of the waves over δ, a relative k δ per component).
#[test]
fn static_position_serves_every_formulation() {
    use hawser::model::Formulation;
    use hawser::physics::static_kinematics::WaveKinematicsMethod;
    let (d, depth, top, period) = (0.2, 32.0, -2.0, 6.0);
    let mut lt = line_type(d, 60.0, 5.0e8);
    lt.drag = hawser::physics::hydrodynamics::DragModel::Morison {
        normal: 1.2,
        tangential: 0.0,
    };
    let omega = 2.0 * PI / period;
    let k = wavenumber(omega, depth, G);
    let h = period / 60.0;
    struct Rec(Vec<(Real, Real)>, Vec<Vec3>, Real);
    impl Observer for Rec {
        fn sample(
            &mut self,
            view: &hawser::session::View<'_>,
        ) -> Result<(), hawser::session::ObserverError> {
            let (s, t, ws) = (view.system, view.time, view.workspace);
            let l = &s.lines[0];
            let n = l.mesh.elements();
            let lw = &ws.lines[0];
            let nodes: Vec<Vec3> = (0..=n).map(|i| lw.position[l.node_vector(i)]).collect();
            if self.1.is_empty() {
                self.1 = nodes.clone();
            }
            for (a, b) in nodes.iter().zip(&self.1) {
                self.2 = self.2.max((a - b).norm());
            }
            self.0.push((t, lw.force[l.node_vector(n)].x));
            Ok(())
        }
    }
    for formulation in [Formulation::Fe, Formulation::Hermite, Formulation::Dg] {
        let mut harmonics = Vec::new();
        let mut displacement: Real = 0.0;
        for method in [
            WaveKinematicsMethod::Direct,
            WaveKinematicsMethod::StaticPosition { sample_interval: h },
        ] {
            let mut model = single_line(
                lt.clone(),
                depth + top - 0.02,
                if formulation == Formulation::Fe {
                    30
                } else {
                    6
                },
                fixed("anchor", Vec3::new(0.0, 0.0, -depth)),
                fixed("top", Vec3::new(0.0, 0.0, top)),
                MassMatrix::Lumped,
            );
            model.lines[0].formulation = formulation;
            if formulation == Formulation::Dg {
                model.settings.scheme = hawser::model::Scheme::SspRk3;
            }
            model.environment = Environment {
                depth,
                waves: regular_ramped(2.0, period, 0.0, depth, Stretching::Vertical, 12.0),
                wave_kinematics: method,
                ..Default::default()
            };
            model.settings.duration = 24.0;
            model.settings.time_step = TimeStep::Auto;
            model.settings.output_interval = 0.02;
            let system = System::new(&model).unwrap();
            let mut sim =
                Simulation::new(&system, &model.settings, system.straight_state()).unwrap();
            if matches!(method, WaveKinematicsMethod::StaticPosition { .. }) {
                assert_eq!(
                    sim.workspace().wave_points.tables().unwrap().points(),
                    system.fluid_points(0)
                );
            }
            let mut rec = Rec(Vec::new(), Vec::new(), 0.0);
            sim.run(24.0, &mut rec).unwrap();
            displacement = displacement.max(rec.2);
            let late: Vec<_> = rec
                .0
                .iter()
                .filter(|(t, _)| *t >= 18.0 - 1e-9 && *t < 24.0 - 1e-9)
                .collect();
            let (mut fs, mut fc) = (0.0, 0.0);
            for (t, f) in &late {
                fs += f * (omega * t).sin();
                fc += f * (omega * t).cos();
            }
            let n = late.len() as Real;
            harmonics.push((2.0 * fs / n, 2.0 * fc / n));
        }
        let ((s0, c0), (s1, c1)) = (harmonics[0], harmonics[1]);
        let amplitude = s0.hypot(c0);
        let error = (s1 - s0).hypot(c1 - c0) / amplitude;
        let tolerance = 2.0 * k * displacement + 3.0 / 128.0 * (omega * h).powi(4);
        eprintln!(
            "{formulation:?}: direct ({s0:.2}, {c0:.2}) N, static ({s1:.2}, {c1:.2}) N: {:.3e} of \
             the amplitude (tolerance {tolerance:.3e}, δ {displacement:.4} m)",
            error
        );
        assert!(
            error < tolerance,
            "{formulation:?}: {error:.3e} > {tolerance:.3e}"
        );
    }
}

/// The `fe` element loop computes the fluid load of its Gauss points in lanes, four elements
/// at a time (drag, and the Froude–Krylov and added-mass force of the fluid's acceleration):
/// it must take each point's kinematics where the per-point `fluid_load` would. A line
/// crossing the surface in a 200-component JONSWAP sea over a uniform current, with the
/// kinematics summed directly and taken from the static-position table (where the point's
/// index selects its kinematics): the nodal forces minus those in still water at the same
/// positions and velocities (tension, weight and buoyancy cancel) equal the sum over each
/// element's two Gauss points of `fluid_load` minus the still-water drag, times each node's
/// share N(ξ) L0/2. Tolerance 1e-12 of the largest nodal force (the difference of two runs
/// cancels the tension, weight and buoyancy to round-off of the whole force; the same fluid
/// terms are summed in another order, with the test's own tangent and stretch); a point given
/// another point's kinematics would err by a fraction of the fluid force itself.
#[test]
fn element_loop_fluid_load_is_the_per_point_fluid_load() {
    use hawser::formulation::{ElementState, LoadOptions, fe::line_forces, fluid_load};
    use hawser::physics::environment::Current;
    use hawser::physics::static_kinematics::{FluidPoints, StaticPositionKinematics};
    let n = 22; // elements: five batches of four and one of two
    let mut lt = line_type(0.12, 40.0, 5.0e8);
    lt.drag = hawser::physics::hydrodynamics::DragModel::Morison {
        normal: 1.2,
        tangential: 0.3,
    };
    lt.tangential_added_mass = 0.5;
    let mut model = single_line(
        lt,
        // Every element longer than its chord below: slack, so no tension swamps the fluid
        // load.
        200.0,
        n,
        fixed("A", Vec3::new(0.0, 0.0, -60.0)),
        fixed("B", Vec3::new(70.0, 0.0, 2.0)),
        MassMatrix::Lumped,
    );
    model.environment.depth = 150.0;
    let still = model.environment.clone();
    let system = System::new(&model).expect("valid model");
    let mesh = &system.lines[0].mesh;
    let mut moving = still.clone();
    moving.current = Current::Uniform(Vec3::new(0.4, -0.1, 0.0));
    moving.waves = jonswap(7, 200, Some(4.0), 150.0);
    // Nodes along a sagging curve through the surface, moving.
    let r: Vec<Vec3> = (0..=n)
        .map(|i| {
            let s = i as Real / n as Real;
            Vec3::new(
                70.0 * s,
                3.0 * s * s,
                -60.0 + 62.0 * s - 9.0 * (PI * s).sin(),
            )
        })
        .collect();
    let v: Vec<Vec3> = (0..=n)
        .map(|i| {
            let a = 0.7 * i as Real;
            Vec3::new(0.3 * a.cos(), 0.2 * a.sin(), -0.5 * (1.3 * a).cos())
        })
        .collect();
    let gauss = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];
    let t = 7.3;
    let forces = |env: &hawser::physics::environment::Environment, fluid: FluidPoints| {
        let mut f = vec![Vec3::zeros(); n + 1];
        let mut elements = ElementState::new(n);
        let options = LoadOptions {
            current_factor: 1.0,
            fluid,
        };
        line_forces(
            mesh,
            MassMatrix::Lumped,
            env,
            t,
            &r,
            &v,
            &mut f,
            &mut elements,
            None,
            options,
        );
        f
    };
    let at_rest = forces(&still, FluidPoints::Direct);
    let points: Vec<Vec3> = (0..n)
        .flat_map(|e| gauss.map(|xi| r[e] * (1.0 - xi) + r[e + 1] * xi))
        .collect();
    let mut table = StaticPositionKinematics::new(moving.waves.field().unwrap(), 0.1, &[points]);
    table.prepare(t);
    for fluid in [
        FluidPoints::Direct,
        FluidPoints::Static {
            table: &table,
            first: 0,
        },
    ] {
        let got = forces(&moving, fluid);
        let mut expected = vec![Vec3::zeros(); n + 1];
        for e in 0..n {
            let sec = mesh.section(e);
            let d = r[e + 1] - r[e];
            let tau = d / d.norm();
            let root = (d.norm() / sec.element_length).sqrt();
            for (g, xi) in gauss.into_iter().enumerate() {
                let (p, u) = (
                    r[e] * (1.0 - xi) + r[e + 1] * xi,
                    v[e] * (1.0 - xi) + v[e + 1] * xi,
                );
                let load = |env, fluid: &FluidPoints, still_water| {
                    let lt = &sec.line_type;
                    fluid_load(
                        env,
                        fluid,
                        2 * e + g,
                        lt,
                        sec.area,
                        t,
                        &p,
                        &u,
                        &tau,
                        root,
                        1.0,
                        still_water,
                    )
                };
                let f = load(&moving, &fluid, false) - load(&still, &FluidPoints::Direct, true);
                expected[e] += f * (0.5 * sec.element_length * (1.0 - xi));
                expected[e + 1] += f * (0.5 * sec.element_length * xi);
            }
        }
        let largest = |f: &[Vec3]| f.iter().map(|f| f.norm()).fold(0.0, Real::max);
        let fluid = largest(&expected);
        assert!(fluid > 1.0, "the sea loads the line: {fluid} N");
        let scale = fluid.max(largest(&got)).max(largest(&at_rest));
        // Weight and buoyancy, no tension: the tolerance stays near the fluid force's round-off.
        assert!(scale < 100.0 * fluid, "{scale} N against {fluid} N");
        for i in 0..=n {
            let err = (got[i] - at_rest[i] - expected[i]).norm();
            assert!(
                err <= 1e-12 * scale,
                "node {i}: {err:.3e} N of {scale:.3e} N (fluid {fluid:.3e} N)"
            );
        }
    }
}
