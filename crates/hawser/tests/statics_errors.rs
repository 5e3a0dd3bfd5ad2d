//! Statics that cannot succeed say why, naming the points.

mod common;
use common::*;
use hawser::StaticsError;
use hawser::math::Vec3;
use hawser::model::MassMatrix;
use hawser::statics::{StaticOptions, solve};
use hawser::system::System;

#[test]
fn free_points_held_by_nothing_have_no_equilibrium_and_are_named() {
    let model = single_line(
        line_type(0.02, 0.5, 1e6),
        10.0,
        5,
        free("a", Vec3::new(0.0, 0.0, -10.0), 5.0, 0.0),
        free("b", Vec3::new(10.0, 0.0, -10.0), 5.0, 0.0),
        MassMatrix::Lumped,
    );
    let system = System::new(&model).unwrap();
    let err = solve(&system, None, &StaticOptions::default()).unwrap_err();
    let StaticsError::Unsupported {
        points, net_force, ..
    } = &err
    else {
        panic!("expected Unsupported, got {err}")
    };
    assert_eq!(points, "`a`, `b`");
    // Net force = two 5 kg masses plus the rope's wet weight, all in g.
    let rope = (0.5 - 1025.0 * std::f64::consts::PI * 0.02f64.powi(2) / 4.0) * 10.0;
    let expected = (10.0 + rope) * 9.80665;
    assert!(
        (net_force - expected).abs() < 1e-9 * expected,
        "{net_force} vs {expected}"
    );
    assert!(
        err.to_string().contains("hint: attach them to an anchor"),
        "{err}"
    );
}

#[test]
fn the_same_pair_hung_from_an_anchor_has_an_equilibrium() {
    let model = single_line(
        line_type(0.02, 0.5, 1e6),
        10.0,
        5,
        fixed("a", Vec3::new(0.0, 0.0, -10.0)),
        free("b", Vec3::new(10.0, 0.0, -10.0), 5.0, 0.0),
        MassMatrix::Lumped,
    );
    let system = System::new(&model).unwrap();
    let sol =
        solve(&system, None, &StaticOptions::default()).expect("a hanging mass has an equilibrium");
    // The mass hangs straight below the anchor.
    let o = system.layout.point_offset[1].unwrap();
    assert!(
        sol.state[o].abs() < 1e-6 && sol.state[o + 2] < -19.9,
        "{:?}",
        &sol.state[o..o + 3]
    );
}
