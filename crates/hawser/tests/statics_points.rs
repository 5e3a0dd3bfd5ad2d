//! Statics of free points: unsupported groups are named; a hanging mass and a clump weight on the bed settle where they must.

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

/// A 5 kg mass on a 10 m line from an anchor, started level with the anchor 10 m to its side.
fn hanging_mass() -> hawser::Model {
    single_line(
        line_type(0.02, 0.5, 1e6),
        10.0,
        5,
        fixed("a", Vec3::new(0.0, 0.0, -10.0)),
        free("b", Vec3::new(10.0, 0.0, -10.0), 5.0, 0.0),
        MassMatrix::Lumped,
    )
}

#[test]
fn the_same_pair_hung_from_an_anchor_has_an_equilibrium() {
    let model = hanging_mass();
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

/// A clump weight resting on the bed (a free point with a volume) sinks into it until the
/// contact spring K_g π r² carries its wet weight: the sphere's bottom lies W/k below the bed.
/// The line to it is neutrally buoyant, so it adds no vertical load. Tolerance 1e-9 m: the
/// statics residual tolerance over k.
#[test]
fn a_clump_weight_rests_on_the_seabed() {
    let d: f64 = 0.05;
    let neutral = 1025.0 * std::f64::consts::PI * d * d / 4.0;
    let depth = 50.0;
    let (mass, volume) = (1000.0, 0.13);
    let radius = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
    let mut model = single_line(
        line_type(d, neutral, 1e7),
        10.0,
        10,
        fixed("anchor", Vec3::new(0.0, 0.0, -depth + radius)),
        free("clump", Vec3::new(10.0, 0.0, -depth + radius), mass, volume),
        MassMatrix::Consistent,
    );
    model.environment.depth = depth;
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
    let o = system.layout.point_offset[1].unwrap();
    let k = model.environment.seabed.stiffness * std::f64::consts::PI * radius * radius;
    let wet = (mass - 1025.0 * volume) * 9.80665;
    let bottom = sol.state[o + 2] - radius;
    let expected = -depth - wet / k;
    assert!(
        (bottom - expected).abs() < 1e-9,
        "bottom {bottom} vs {expected}"
    );
}

/// The point force channel is the net force of the attached lines on a point (MoorDyn's
/// P#FX): at the static equilibrium of the hanging mass it balances the mass's own wet weight
/// exactly, and at the anchor it is the line's pull, whose vertical part is the whole
/// system's wet weight. Tolerances: at the mass, one node's statics residual (Newton stops at
/// 1e-9 of the weight scale per unknown); at the anchor, the residuals of the line's six nodes
/// add up, so 1e-8 of the weight.
#[test]
fn point_force_balances_the_hanging_mass_in_statics() {
    use hawser::analysis::Channel;
    use hawser::statics::evaluate;
    let model = hanging_mass();
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let force = |point: usize| {
        Vec3::from_fn(|axis, _| Channel::PointForce { point, axis }.value(&system, &ws))
    };
    let g = 9.80665;
    let mass = 5.0 * g;
    let rope = (0.5 - 1025.0 * std::f64::consts::PI * 0.02f64.powi(2) / 4.0) * 10.0 * g;
    let on_mass = force(1);
    assert!(on_mass.x.abs() < 1e-9 * mass && on_mass.y.abs() < 1e-9 * mass);
    assert!((on_mass.z - mass).abs() < 1e-9 * mass, "{on_mass}");
    let on_anchor = force(0);
    assert!(
        (on_anchor.z + mass + rope).abs() < 1e-8 * (mass + rope),
        "{on_anchor}"
    );
}

/// The iteration log is kept only when asked for, and it tells the iterations as they were:
/// when Newton alone converged, the last accepted step's residual is the solution's; when it
/// fell back to another method, the log says that Newton failed and names the fallback. This
/// hanging mass (started 10 m to the side of its anchor) needs the fallback.
#[test]
fn the_trace_logs_the_iterations_only_when_asked() {
    let model = hanging_mass();
    let system = System::new(&model).unwrap();
    let quiet = solve(&system, None, &StaticOptions::default()).unwrap();
    assert!(quiet.log.is_empty(), "{:?}", quiet.log);
    let options = StaticOptions {
        trace: true,
        ..StaticOptions::default()
    };
    let traced = solve(&system, None, &options).unwrap();
    assert_eq!(traced.state, quiet.state, "tracing changes nothing");
    assert_eq!(traced.method, quiet.method);
    let failed = traced
        .log
        .iter()
        .any(|l| l.starts_with("newton failed after"));
    assert_eq!(
        failed,
        traced.method != "newton",
        "{}: {:?}",
        traced.method,
        traced.log
    );
    assert!(failed, "this case falls back ({})", traced.method);
    // The solution says so without the trace: Newton failed, with its residual.
    let why = quiet.fallback.as_deref().expect("the fallback is reported");
    assert!(
        why.starts_with("newton from the seed did not converge") && why.contains(" N"),
        "{why}"
    );
    let newton = |l: &String| l.starts_with("newton ") && l.contains(" -> ");
    assert!(traced.log.iter().any(newton), "{:?}", traced.log);
    // A case Newton solves alone: the same line with its end held, the mass hung below.
    let mut model = model.clone();
    model.points[1].position = Vec3::new(0.0, 0.0, -20.0);
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &options).unwrap();
    assert_eq!(sol.method, "newton", "{:?}", sol.log);
    assert_eq!(sol.fallback, None);
    let last = sol.log.iter().rev().find(|l| newton(l)).unwrap();
    let after = last.split(" -> ").nth(1).unwrap();
    let r: f64 = after.split(' ').next().unwrap().parse().unwrap();
    // The log prints 4 significant digits.
    assert!(
        (r - sol.residual).abs() <= 1e-3 * sol.residual,
        "{last} vs {}",
        sol.residual
    );
}
