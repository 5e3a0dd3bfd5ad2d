//! Prescribed bodies (`type = "prescribed"` with `[bodies.motion]`): every rigid motion a
//! vessel takes reaches the body as the core builds it from the same numbers, and a line
//! attached to a point on a body doing a manoeuvre has its end exactly where the manoeuvre
//! puts that point.
//!
//! `cargo test --release -p hawser-io --test prescribed_bodies -- --nocapture`

use hawser::analysis::Channel;
use hawser::math::{Quat, Real, Vec3};
use hawser::model::{BodyKind, Manoeuvre, ManoeuvreSpec, Motion, PointKind, RigidMotion};
use hawser::simulation::Simulation;
use hawser::statics::{StaticOptions, solve};
use hawser::system::System;
use hawser_io::scenario;
use std::path::Path;

const KNOT: Real = 1852.0 / 3600.0;

/// A ship (prescribed body) with a tow point 30 m aft, 4 m to port and 2 m below its origin,
/// towing a 200 kg weight on 40 m of rope. `MOTION` is the body's motion table; `TWIN`, if
/// used, a prescribed point on the same motion.
const BASE: &str = r#"
[simulation]
duration = 60.0
output_interval = 0.5
time_step = "auto"
channels = ["rope.node0.x", "rope.node0.y", "rope.node0.z", "rope.node0.vx", "rope.node0.vy", "rope.node0.vz"]

[environment]
depth = 200.0

[environment.waves]
type = "jonswap"
significant_height = 2.0
peak_period = 8.0
direction = 150.0
seed = 11
components = 12

[[line_types]]
name = "rope"
diameter = 0.03
mass_per_length = 1.5
axial_stiffness = 2.0e6
normal_drag = 1.2
tangential_drag = 0.02

[[bodies]]
name = "ship"
type = "prescribed"
mass = 2.0e6
inertia = [1.0e8, 1.0e9, 1.0e9]

[bodies.motion]
MOTION

[[points]]
name = "towpoint"
type = "body"
body = "ship"
position = [-30.0, 4.0, -2.0]

[[points]]
name = "weight"
type = "free"
position = [-60.0, 4.0, -30.0]
mass = 200.0
volume = 0.02
drag_area = 0.5

[[lines]]
name = "rope"
end_a = "towpoint"
end_b = "weight"
type = "rope"
length = 40.0
elements = 8
TWIN
"#;

const MANOEUVRE: &str = r#"type = "manoeuvre"
start = [10.0, -20.0, 0.0]
heading = 30.0
speed_knots = 8.0
straight_before = 40.0
turn_radius = 60.0
turn_angle = -120.0
transition_length = 15.0
build_up_time = 8.0"#;

/// The manoeuvre of `MANOEUVRE`, built directly in the core: degrees and knots converted here.
fn manoeuvre() -> Manoeuvre {
    Manoeuvre::new(ManoeuvreSpec {
        start: Vec3::new(10.0, -20.0, 0.0),
        heading: 30f64.to_radians(),
        speed: 8.0 * KNOT,
        straight_before: 40.0,
        turn_radius: 60.0,
        turn_angle: -120f64.to_radians(),
        straight_after: None,
        build_up_time: 8.0,
        transition_length: 15.0,
    })
    .unwrap()
}

/// An observer that hands every sample (time, system, workspace) to a closure.
struct Probe<'a, F: FnMut(Real, &System, &hawser::system::Workspace)>(&'a mut F);

impl<F: FnMut(Real, &System, &hawser::system::Workspace)> hawser::simulation::Observer
    for Probe<'_, F>
{
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        (self.0)(time, system, ws);
        Ok(())
    }
}

fn scenario(motion: &str, twin: &str) -> String {
    BASE.replace("MOTION", motion).replace("TWIN", twin)
}

fn body_motion(s: &scenario::LoadedScenario) -> &RigidMotion {
    match &s.model.bodies[0].kind {
        BodyKind::Prescribed(m) => m,
        k => panic!("the ship is not prescribed: {k:?}"),
    }
}

/// `fixed` and `constant-velocity` place the body at `start` on `heading`; `manoeuvre`,
/// `vessel-motion` and `rao` give it the very motion a prescribed point on a vessel gets from
/// the same table (compared at the vessel origin, offset 0, at 7 times over 60 s: equal to
/// rounding, 1e-12 m and rad, as both are the same function of the same numbers). The body's
/// initial pose is its motion's at t = 0.
#[test]
fn every_vessel_motion_moves_a_prescribed_body() {
    let heading = Quat::from_axis_angle(&Vec3::z_axis(), 30f64.to_radians());
    let direct = [
        (
            "type = \"fixed\"\nstart = [1.0, 2.0, 3.0]\nheading = 30.0",
            RigidMotion::Fixed {
                position: Vec3::new(1.0, 2.0, 3.0),
                orientation: heading,
            },
        ),
        (
            "type = \"constant-velocity\"\nstart = [1.0, 2.0, 3.0]\nheading = 30.0\nvelocity = [2.0, 1.0, 0.0]",
            RigidMotion::ConstantVelocity {
                start: Vec3::new(1.0, 2.0, 3.0),
                orientation: heading,
                velocity: Vec3::new(2.0, 1.0, 0.0),
            },
        ),
        ("", RigidMotion::Manoeuvre(Box::new(manoeuvre()))),
    ];
    for (table, expected) in direct {
        let table = if table.is_empty() { MANOEUVRE } else { table };
        let s = scenario::parse(Path::new("scenario.toml"), &scenario(table, ""))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(body_motion(&s), &expected, "{table}");
    }

    // A 6-DOF file: written beside the scenario, read by the same reader as points'.
    let dir = std::env::temp_dir().join(format!("hawser-prescribed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut rows = String::from("t x y z roll pitch yaw\n");
    for i in 0..=60 {
        let t = i as Real;
        rows += &format!(
            "{t} {} {} {} {} {} {}\n",
            1.5 * t,
            3.0 * (0.2 * t).sin(),
            0.5 * (0.7 * t).cos(),
            4.0 * (0.5 * t).sin(),
            2.0 * (0.4 * t).cos(),
            170.0 + 0.5 * t
        );
    }
    std::fs::write(dir.join("motion.txt"), rows).unwrap();
    std::fs::copy(
        "tests/motion_data/vessel_raos.csv",
        dir.join("vessel_raos.csv"),
    )
    .unwrap();
    let vessel_kinds = [
        "type = \"vessel-motion\"\nfile = \"motion.txt\"\ntime_offset = -2.0".to_string(),
        MANOEUVRE.to_string(),
        "type = \"rao\"\nfile = \"vessel_raos.csv\"\n\n[bodies.motion.mean]\n".to_string()
            + MANOEUVRE,
    ];
    for table in vessel_kinds {
        // The twin is a prescribed point on the vessel origin with the same table.
        let twin_table = table.replace("[bodies.motion.mean]", "[points.motion.mean]");
        let twin = format!(
            "\n[[points]]\nname = \"twin\"\ntype = \"prescribed\"\nposition = [0.0, 0.0, 0.0]\n\n[points.motion]\n{twin_table}\n"
        );
        let text = scenario(&table, &twin)
            + "\n[[lines]]\nname = \"twin_line\"\nend_a = \"twin\"\nend_b = \"weight\"\ntype = \"rope\"\nlength = 40.0\nelements = 8\n";
        let path = dir.join("scenario.toml");
        let s = scenario::parse(&path, &text).unwrap_or_else(|e| panic!("{table}: {e}"));
        let body = body_motion(&s);
        let point = match &s
            .model
            .points
            .iter()
            .find(|p| p.name == "twin")
            .unwrap()
            .kind
        {
            PointKind::Prescribed(Motion::Rigid { motion, offset }) => {
                assert_eq!(*offset, Vec3::zeros());
                motion.as_ref().clone()
            }
            k => panic!("{k:?}"),
        };
        let k0 = body.kinematics(0.0);
        assert_eq!(s.model.bodies[0].position, k0.position, "{table}");
        assert_eq!(s.model.bodies[0].orientation, k0.orientation, "{table}");
        for t in [0.0, 3.0, 7.5, 12.0, 25.0, 40.0, 60.0] {
            let (a, b) = (body.kinematics(t), point.kinematics(t));
            let moved = (a.position - k0.position).norm();
            assert!(t < 5.0 || moved > 1.0, "{table}: moved {moved} m by {t} s");
            for (x, y) in [
                (a.position, b.position),
                (a.velocity, b.velocity),
                (a.acceleration, b.acceleration),
                (a.angular_velocity, b.angular_velocity),
                (a.angular_acceleration, b.angular_acceleration),
            ] {
                assert!((x - y).norm() < 1e-12, "{table} at {t} s: {x:?} vs {y:?}");
            }
            assert!(a.orientation.angle_to(&b.orientation) < 1e-12, "{table}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A rope hangs from a point 30 m aft, 4 m to port and 2 m below the origin of a ship doing a
/// turn to starboard through 120° with clothoid transitions (built up from rest; the turn ends
/// at t ≈ 44 s). Over 60 s of dynamics
/// (statics first, automatic step), the rope's end node, read through its channels, is where
/// `RigidKinematics::point(offset)` of the manoeuvre built directly in the core puts the tow
/// point, and moves at its velocity: to 1e-9 m and 1e-9 m/s, round-off on positions of
/// 100 m (the end node is the point; no integration error enters).
#[test]
fn a_line_on_a_manoeuvring_body_follows_the_body_point() {
    let s = scenario::parse(Path::new("scenario.toml"), &scenario(MANOEUVRE, ""))
        .unwrap_or_else(|e| panic!("{e}"));
    let system = System::new(&s.model).unwrap();
    let statics = solve(&system, None, &StaticOptions::default()).expect("statics");
    let mut sim = Simulation::new(&system, &s.model.settings, statics.state).unwrap();
    let channels: Vec<Channel> = s.model.outputs.iter().map(|c| c.channel).collect();
    let find = |suffix: &str| {
        let n = channels
            .iter()
            .position(|c| c.name(&system) == format!("rope.node0.{suffix}"))
            .unwrap_or_else(|| panic!("no rope.node0.{suffix}"));
        channels[n]
    };
    let pos = ["x", "y", "z"].map(find);
    let vel = ["vx", "vy", "vz"].map(find);
    let offset = Vec3::new(-30.0, 4.0, -2.0);
    let ship = manoeuvre();
    let (mut worst_p, mut worst_v, mut samples) = (0.0 as Real, 0.0 as Real, 0);
    let mut check = |t: Real, sys: &System, ws: &hawser::system::Workspace| {
        let (p, v, _) = ship.kinematics(t).point(&offset);
        let got_p = Vec3::from(pos.map(|c| c.value(sys, ws)));
        let got_v = Vec3::from(vel.map(|c| c.value(sys, ws)));
        worst_p = worst_p.max((got_p - p).norm());
        worst_v = worst_v.max((got_v - v).norm());
        samples += 1;
    };
    sim.run(s.model.settings.duration, &mut Probe(&mut check))
        .expect("the run completes");
    let end = ship.kinematics(60.0);
    eprintln!(
        "{samples} samples; tow point against the manoeuvre: position {worst_p:.2e} m, velocity \
         {worst_v:.2e} m/s; ship heading at 60 s {:.1}°, speed {:.3} m/s",
        end.orientation.euler_angles().2.to_degrees(),
        end.velocity.norm()
    );
    assert_eq!(samples, 121);
    assert!(worst_p < 1e-9, "{worst_p}");
    assert!(worst_v < 1e-9, "{worst_v}");
}

/// `OBJECT.relative_to.REFERENCE.x|y|z` (the elastic-link paper's "position of the vehicle
/// relative to the vessel", §5). Over the manoeuvre, which turns the ship through 120°:
/// the tow point relative to the ship is its body-fixed offset (−30, 4, −2) m (1e-9 m: the
/// positions are O(100 m), rotated and subtracted in double precision); the towed weight
/// relative to the ship equals R_z(ψ)ᵀ (x_weight − x_ship) built here from the recorded yaw
/// and positions (the manoeuvre keeps roll and pitch at zero), and relative to the tow point
/// (a point: global axes) the plain difference, both to 1e-9 m.
#[test]
fn relative_position_channels_follow_the_ship_axes() {
    let mut text = scenario(MANOEUVRE, "");
    text = text.replace(
        r#"channels = ["#,
        r#"channels = ["towpoint.relative_to.ship.x", "towpoint.relative_to.ship.y", "towpoint.relative_to.ship.z", "weight.relative_to.ship.x", "weight.relative_to.ship.y", "weight.relative_to.ship.z", "weight.relative_to.towpoint.x", "weight.relative_to.towpoint.y", "weight.relative_to.towpoint.z", "towpoint.x", "towpoint.y", "towpoint.z", "#,
    );
    let s = scenario::parse(Path::new("scenario.toml"), &text).unwrap_or_else(|e| panic!("{e}"));
    let system = System::new(&s.model).unwrap();
    let statics = solve(&system, None, &StaticOptions::default()).expect("statics");
    let mut sim = Simulation::new(&system, &s.model.settings, statics.state).unwrap();
    let by_name: std::collections::HashMap<String, Channel> = s
        .model
        .outputs
        .iter()
        .map(|c| (c.channel.name(&system), c.channel))
        .collect();
    let get = |n: &str| *by_name.get(n).unwrap_or_else(|| panic!("no channel {n}"));
    let triple = |prefix: &str| ["x", "y", "z"].map(|a| get(&format!("{prefix}.{a}")));
    let tow_ship = triple("towpoint.relative_to.ship");
    let weight_ship = triple("weight.relative_to.ship");
    let weight_tow = triple("weight.relative_to.towpoint");
    let (ship, weight, tow) = (triple("ship"), triple("weight"), triple("towpoint"));
    let (ship_yaw, ship_roll, ship_pitch) = (get("ship.yaw"), get("ship.roll"), get("ship.pitch"));
    let offset = Vec3::new(-30.0, 4.0, -2.0);
    let (mut worst, mut turned, mut samples) = (0.0 as Real, 0.0 as Real, 0);
    let mut check = |_: Real, sys: &System, ws: &hawser::system::Workspace| {
        let v = |c: [Channel; 3]| Vec3::from(c.map(|c| c.value(sys, ws)));
        let yaw = ship_yaw.value(sys, ws).to_radians();
        assert!(ship_roll.value(sys, ws).abs() < 1e-12 && ship_pitch.value(sys, ws).abs() < 1e-12);
        let rz = Quat::from_axis_angle(&Vec3::z_axis(), yaw);
        let expected = rz.inverse_transform_vector(&(v(weight) - v(ship)));
        worst = worst
            .max((v(tow_ship) - offset).norm())
            .max((v(weight_ship) - expected).norm())
            .max((v(weight_tow) - (v(weight) - v(tow))).norm());
        turned = turned.max((yaw - 30f64.to_radians()).abs());
        samples += 1;
    };
    sim.run(s.model.settings.duration, &mut Probe(&mut check))
        .expect("the run completes");
    eprintln!(
        "{samples} samples; relative positions against the recorded positions and yaw: {worst:.2e} m; \
         heading changed by up to {:.1}°",
        turned.to_degrees()
    );
    assert_eq!(samples, 121);
    assert!(turned > 100f64.to_radians(), "the ship must turn: {turned}");
    assert!(worst < 1e-9, "{worst}");
}

/// Bad relative-position channels say what is wrong.
#[test]
fn bad_relative_position_channels_are_refused() {
    let s = scenario::parse(Path::new("scenario.toml"), &scenario(MANOEUVRE, "")).unwrap();
    for (name, needle) in [
        ("weight.relative_to.nowhere.x", "no point or body"),
        ("weight.relative_to.weight.x", "relative to itself"),
        ("weight.relative_to.ship.w", "not an axis"),
    ] {
        let e = hawser::analysis::Channel::parse(name, &s.model).unwrap_err();
        assert!(e.contains(needle), "{name}: {e}");
    }
    assert!(hawser::analysis::Channel::parse("ship.relative_to.towpoint.z", &s.model).is_ok());
}
