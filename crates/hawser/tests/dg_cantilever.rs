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
use dg_common::cantilever::*;

fn check(i: usize, half_periods: usize) {
    let started = std::time::Instant::now();
    let o = cantilever(i, 16, 4, half_periods);
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
