//! The vibrating cantilever of the DG paper (§4.2, eqs. 37–46): m = 10 kg/m, EI = 0.1 MN·m²,
//! EA = 0.1 MN, L = 100 m, tip amplitude A = 1 mm, clamped at s = 0 and free at s = L,
//! released from rest in an eigenmode; N = 16, P = 4.
//!
//! Checks: the period (from the zero crossings of the tip deflection) within 0.5 % of
//! eq. 45; the moment M = EI y'' and shear T_s = −EI y''' along the line against the analytic
//! envelope A EI |Φ''|, A EI |Φ'''| (their values at t = 0, the envelope of eq. 46), and the
//! tip amplitude after the measured half-periods. Φ_0 (period 179 s, 130 000 steps) takes
//! about 7 s in release.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};

/// Roots Ω_i L of 1 + cos x cosh x = 0 (eq. 44).
pub const ROOTS: [Real; 5] = [
    1.875_104_068_711_961,
    4.694_091_132_974_175,
    7.854_757_438_237_613,
    10.995_540_734_875_467,
    14.137_168_391_046_47,
];

const M: Real = 10.0;
const EI: Real = 1.0e5;
const EA: Real = 1.0e5;
const L: Real = 100.0;
const A: Real = 1.0e-3;

/// Mode shape Φ_i and its first three derivatives at s (eqs. 41–42), normalised to Φ(L) = 1.
fn mode(i: usize, s: Real) -> [Real; 4] {
    let om = ROOTS[i] / L;
    let d = (ROOTS[i].cos() + ROOTS[i].cosh()) / (ROOTS[i].sin() + ROOTS[i].sinh());
    let raw = |s: Real| {
        let x = om * s;
        let (c, ch, sn, sh) = (x.cos(), x.cosh(), x.sin(), x.sinh());
        [
            0.5 * (c - ch + d * (sh - sn)),
            0.5 * om * (-sn - sh + d * (ch - c)),
            0.5 * om * om * (-c - ch + d * (sh + sn)),
            0.5 * om.powi(3) * (sn - sh + d * (ch + c)),
        ]
    };
    let tip = raw(L)[0];
    raw(s).map(|v| v / tip)
}

/// Analytic period [s] (eq. 45).
fn period(i: usize) -> Real {
    2.0 * std::f64::consts::PI / (ROOTS[i] * ROOTS[i] * (EI / (M * L.powi(4))).sqrt())
}

struct Outcome {
    period: Real,
    moment_error: Real,
    shear_error: Real,
    amplitude: Real,
}

fn run(i: usize, elements: usize, order: usize, half_periods: usize) -> Outcome {
    let line = single(
        beam_type(M, EA, EI),
        L,
        elements,
        order,
        [EndCondition::CLAMPED, EndCondition::FREE],
    );
    let env = vacuum();
    let mut state = vec![0.0; line.state_len()];
    line.project(&mut state, |s| {
        let f = mode(i, s);
        let q = Vec3::new(1.0, 0.0, A * f[1]);
        (Vec3::new(s, 0.0, A * f[0]), q / q.norm(), Vec3::zeros())
    });
    let ends = fixed_ends(Vec3::zeros(), Vec3::new(L, 0.0, 0.0));
    let mut ws = DgWorkspace::new(&line);
    let mut rate = vec![0.0; line.state_len()];
    line.rhs(&env, 0.0, &state, &ends, &mut rate, &mut ws);
    // Moment and shear at t = 0 against A EI Φ'' and −A EI Φ''' (y along +z: M = EI y'' ŷ·(−1)
    // for a deflection in z, see below), relative to their largest values.
    let (mut em, mut es, mut mmax, mut smax) = (0.0 as Real, 0.0 as Real, 0.0 as Real, 0.0 as Real);
    for k in 0..=200 {
        let s = L * k as Real / 200.0;
        let c = line.channels(&state, &rate, &ws, s);
        let f = mode(i, s);
        // î = x̂, κ = y'' ẑ: M = î × EI κ = −EI y'' ŷ; T_s = î × ∂M/∂s = EI y''' ... × = −EI y''' ẑ.
        let m_exact = -A * EI * f[2];
        let s_exact = -A * EI * f[3];
        em = em.max((c.moment.y - m_exact).abs());
        es = es.max((c.shear.z - s_exact).abs());
        mmax = mmax.max(m_exact.abs());
        smax = smax.max(s_exact.abs());
    }
    let mut stepper = DgStepper::new(&line);
    let dt = stable_step(&line, 0.8);
    let mut t = 0.0;
    let mut prev = line.position(&state, &ends, L).z;
    let mut crossings = Vec::new();
    let mut amplitude: Real = 0.0;
    while crossings.len() < half_periods + 1 {
        stepper.step(&line, &env, t, dt, &mut state, &mut ws, |_| ends);
        t += dt;
        let z = line.position(&state, &ends, L).z;
        if (prev > 0.0) != (z > 0.0) {
            crossings.push(t - dt * z / (z - prev));
        }
        if crossings.len() == half_periods {
            amplitude = amplitude.max(z.abs());
        }
        prev = z;
        assert!(z.is_finite() && t < 10.0 * period(i) * half_periods as Real);
    }
    let n = crossings.len() - 1;
    Outcome {
        period: 2.0 * (crossings[n] - crossings[0]) / n as Real,
        moment_error: em / mmax,
        shear_error: es / smax,
        amplitude,
    }
}

fn check(i: usize, half_periods: usize) {
    let started = std::time::Instant::now();
    let o = run(i, 16, 4, half_periods);
    let exact = period(i);
    let err = (o.period - exact) / exact;
    println!(
        "mode {i}: period {:.5} s vs {exact:.5} ({:+.4} %), moment error {:.2e}, shear error {:.2e}, \
         amplitude after {half_periods} half-periods {:.4e} m ({:.2} s wall)",
        o.period,
        100.0 * err,
        o.moment_error,
        o.shear_error,
        o.amplitude,
        started.elapsed().as_secs_f64()
    );
    assert!(err.abs() < 0.005, "mode {i}: period error {err}");
    assert!(
        o.moment_error < 0.01,
        "mode {i}: moment error {}",
        o.moment_error
    );
    assert!(
        o.shear_error < 0.02,
        "mode {i}: shear error {}",
        o.shear_error
    );
    assert!(
        (o.amplitude - A).abs() < 0.05 * A,
        "mode {i}: amplitude {}",
        o.amplitude
    );
}

#[test]
fn cantilever_modes_2_and_4_vibrate_at_their_periods() {
    check(4, 4);
    check(2, 2);
}

#[test]
fn cantilever_mode_0_vibrates_at_its_period() {
    check(0, 2);
}
