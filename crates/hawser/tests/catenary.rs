//! Elastic catenary: FE statics against the closed form (SPEC §7, issue 2 item 7).
//!
//! Tolerance 0.1 % on end tensions at 100 elements: the FE end force converges as O(h²)
//! (linear elements, end force = half-element loads + end element tension), and the observed
//! error at 100 elements is far below 0.1 %; the tolerance is the issue's.

mod common;
use common::*;
use hawser::math::Vec3;
use hawser::model::MassMatrix;
use hawser::statics::{StaticOptions, catenary, solve};
use hawser::system::System;

fn fe_end_tensions(model: &hawser::Model) -> (f64, f64, Vec<Vec3>) {
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics converges");
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    let ta = system.end_force(&ws, 0, false).norm();
    let tb = system.end_force(&ws, 0, true).norm();
    (ta, tb, ws.lines[0].position.clone())
}

#[test]
fn suspended_catenary_end_tensions_match_closed_form() {
    // A 110 m line in deep water between points 80 m apart horizontally and 60 m vertically.
    let lt = line_type(0.05, 20.0, 5.0e7);
    let w = (20.0 - 1025.0 * std::f64::consts::PI * 0.05f64.powi(2) / 4.0) * 9.80665;
    let a = Vec3::new(0.0, 0.0, -500.0);
    let b = Vec3::new(80.0, 0.0, -440.0);
    let model = single_line(
        lt,
        110.0,
        100,
        fixed("A", a),
        fixed("B", b),
        MassMatrix::Consistent,
    );
    let exact = catenary::solve(80.0, 60.0, 110.0, w, 5.0e7, false).unwrap();
    let (ta, tb, pos) = fe_end_tensions(&model);
    let ea = (ta - exact.tension_a()).abs() / exact.tension_a();
    let eb = (tb - exact.tension_b()).abs() / exact.tension_b();
    eprintln!(
        "suspended catenary, 100 elements: relative end tension errors A {ea:.2e}, B {eb:.2e}"
    );
    assert!(
        ea < 1e-3 && eb < 1e-3,
        "end A {ta} vs {} ({ea:.2e}); end B {tb} vs {} ({eb:.2e})",
        exact.tension_a(),
        exact.tension_b()
    );
    // The shape too: mid node against the closed-form profile.
    let (x, z) = exact.position(55.0);
    let mid = pos[50];
    assert!(
        (mid.x - x).abs() < 0.05 && (mid.z - (-500.0 + z)).abs() < 0.05,
        "{mid} vs ({x}, {z})"
    );
}

#[test]
fn catenary_on_frictionless_seabed_matches_closed_form() {
    // OC3-like chain: 902.2 m from an anchor on the bed at 320 m depth to a fairlead at 70 m depth.
    let (d, m, ea) = (0.09, 77.7066, 384.243e6);
    let w = (m - 1025.0 * std::f64::consts::PI * d * d / 4.0) * 9.80665;
    // A stiff bed so the penetration (w / (K d) ≈ 0.3 mm) does not move the touchdown.
    let model = oc3_chain(200, Vec3::new(0.0, 0.0, -70.0));
    let exact = catenary::solve(848.67, 250.0, 902.2, w, ea, true).unwrap();
    assert!(
        exact.grounded_length > 10.0,
        "the case must have line on the bed"
    );
    let (ta, tb, _) = fe_end_tensions(&model);
    let ea_err = (ta - exact.tension_a()).abs() / exact.tension_a();
    let eb_err = (tb - exact.tension_b()).abs() / exact.tension_b();
    eprintln!(
        "grounded catenary, 200 elements: relative end tension errors anchor {ea_err:.2e}, fairlead {eb_err:.2e}"
    );
    assert!(
        ea_err < 1e-3 && eb_err < 1e-3,
        "anchor {ta} vs {} ({ea_err:.2e}); fairlead {tb} vs {} ({eb_err:.2e})",
        exact.tension_a(),
        exact.tension_b()
    );
}
