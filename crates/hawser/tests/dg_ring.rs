//! Ring-shaped beam (DG paper §4.1, SPEC §7): L2 convergence rates (eqs. 34–36) for P = 1..5
//! over three meshes with doubling element counts, centred LDG fluxes (β = 0).
//!
//! The paper reports P + 1 for P = 1 and even P, and P for odd P > 1. This implementation
//! reproduces P + 1 for P = 1, 2, 4 and converges at the optimal P + 1 also for P = 3 and 5
//! (measured 3.99 and 5.96): the test checks P + 1 ± 0.3 for every order and docs/dg.md
//! discusses the difference. The low orders need finer meshes to be asymptotic: P = 1 is
//! measured on 32, 64, 128 elements (16 → 32 gives 2.49), P = 2 on 16, 32, 64 (8 → 16 gives
//! 4.24), P ≥ 3 on 8, 16, 32.

mod dg_common;
use dg_common::*;
use hawser::math::Real;

#[test]
fn ring_beam_converges_at_optimal_rates() {
    let mut failures = Vec::new();
    for order in 1..=5 {
        let (errors, rates) = convergence(order);
        let errs: Vec<String> = errors.iter().map(|e| format!("{e:.3e}")).collect();
        println!(
            "P {order}: meshes {:?}, errors {errs:?}, rates {rates:.2?}",
            meshes(order)
        );
        let expected = (order + 1) as Real;
        // The rate between the two finer meshes (the coarser pair is printed).
        if (rates[1] - expected).abs() > 0.3 {
            failures.push((order, rates, expected));
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}
