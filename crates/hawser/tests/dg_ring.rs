//! Ring-shaped beam (DG paper §4.1, SPEC §7): L2 convergence rates (eqs. 34–36) for P = 1..5
//! over three meshes with doubling element counts, centred LDG fluxes (β = 0).
//!
//! The paper reports P + 1 for P = 1 and even P, and P for odd P > 1. With the paper's
//! Lax–Friedrichs flux on the axial q–v system (eq. 24) this implementation converges at the
//! optimal P + 1 for every order (measured 2.05, 3.14, 3.98, 4.96, 5.96): the first test
//! checks P + 1 ± 0.3. The second switches the Lax–Friedrichs dissipation off
//! ([`DgLine::axial_dissipation`] = 0, every flux centred): odd orders then lose one order,
//! P = 3 and 5 matching the paper's table, but so does P = 1 (≈ 1.2, where the paper has 2),
//! so centred fluxes alone do not reproduce the table; docs/dg.md records the measurements.
//! The low orders need finer meshes to be asymptotic: P = 1 is measured on 32, 64, 128
//! elements (16 → 32 gives 2.49), P = 2 on 16, 32, 64 (8 → 16 gives 4.24), P ≥ 3 on 8, 16, 32.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::DgLine;
use hawser::math::Real;

/// Rates for P = 1..5 with the line adjusted by `setup`; the orders whose finer-pair rate is
/// more than 0.3 from `expected(P)`.
fn check(
    setup: impl Fn(&mut DgLine),
    expected: impl Fn(usize) -> Real,
) -> Vec<(usize, Vec<Real>, Real)> {
    let mut failures = Vec::new();
    for order in 1..=5 {
        let (errors, rates) = convergence_with(order, &setup);
        let errs: Vec<String> = errors.iter().map(|e| format!("{e:.3e}")).collect();
        println!(
            "P {order}: meshes {:?}, errors {errs:?}, rates {rates:.2?}",
            meshes(order)
        );
        let expected = expected(order);
        // The rate between the two finer meshes (the coarser pair is printed).
        if (rates[1] - expected).abs() > 0.3 {
            failures.push((order, rates, expected));
        }
    }
    failures
}

#[test]
fn ring_beam_converges_at_optimal_rates() {
    let failures = check(|_| {}, |p| (p + 1) as Real);
    assert!(failures.is_empty(), "{failures:?}");
}

/// Without the Lax–Friedrichs terms (½λ[q] in the q flux, ½Z[ν] in the v flux) the steady
/// state is that of purely centred fluxes, whose derivative operators are known to converge at
/// P for odd P and P + 1 for even P on uniform meshes. Measured: 1.20, 3.00, 3.14, 4.96, 4.97
/// (P = 1..5), against the paper's 2, 3, 3, 5, 5: the odd orders above 1 and the even orders
/// agree, P = 1 does not. With the dissipation on, the steady ν and the q jumps are O(h^(P+1))
/// for every P, and the jump penalty restores the optimal rate of the odd orders.
#[test]
fn ring_beam_with_centred_axial_fluxes_loses_an_order_for_odd_p() {
    let failures = check(
        |line| line.axial_dissipation = 0.0,
        |p| {
            if p % 2 == 1 {
                p as Real
            } else {
                (p + 1) as Real
            }
        },
    );
    assert!(failures.is_empty(), "{failures:?}");
}
