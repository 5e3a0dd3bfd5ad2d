//! Vessel motions of prescribed points (`manoeuvre`, `rao`, `vessel-motion`): a valid scenario
//! reads into the same motions the core builds from the same numbers, and every bad value —
//! in the scenario or in an RAO file — gets a diagnostic naming the file, line and column, the
//! key, the value, the expected unit or range and a hint, never a panic (as in `bad_input.rs`).

mod common;
use common::*;
use hawser::math::{Quat, Real, Vec3};
use hawser::model::{Manoeuvre, ManoeuvreSpec, Motion, PointKind, RaoMotion, RigidMotion};
use hawser_io::scenario;
use hawser_io::scenario::tables::read_rao_table;
use std::f64::consts::PI;
use std::path::Path;

/// A towing point on a ship doing a turn, and a crane tip on a vessel moving in waves, both
/// holding a payload.
const BASE: &str = r#"# Base scenario for the vessel-motion input tests.

[simulation]
duration = 10.0

[environment]
depth = 200.0

[environment.waves]
type = "regular"
height = 2.0
period = 8.0
direction = 30.0

[[line_types]]
name = "cable"
diameter = 0.04
mass_per_length = 5.0
axial_stiffness = 2.6e7
normal_drag = 1.2
tangential_drag = 0.01

[[points]]
name = "tow"
type = "prescribed"
position = [-40.0, 0.0, -2.0]

[points.motion]
type = "manoeuvre"
speed_knots = 12.0
heading = 30.0
start = [5.0, -5.0, 0.0]
straight_before = 500.0
turn_radius = 250.0
turn_angle = -270.0
straight_after = 400.0
build_up_time = 60.0
transition_length = 50.0

[[points]]
name = "crane"
type = "prescribed"
position = [10.0, 5.0, 3.0]

[points.motion]
type = "rao"
file = "tests/motion_data/vessel_raos.csv"

[points.motion.mean]
type = "constant-velocity"
start = [100.0, 0.0, 0.0]
heading = 90.0
velocity = [0.0, 1.0, 0.0]

[[points]]
name = "payload"
type = "free"
position = [-40.0, 0.0, -100.0]
mass = 500.0
volume = 0.1

[[lines]]
name = "tow_line"
end_a = "tow"
end_b = "payload"
type = "cable"
length = 100.0
elements = 10

[[lines]]
name = "crane_line"
end_a = "crane"
end_b = "payload"
type = "cable"
length = 150.0
elements = 10
"#;

fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

/// [`common::bad`], and the scenario must not panic when set up.
fn bad(text: &str, needle: &str, key: &str) -> String {
    let msg = common::bad(text, needle, key);
    assert!(!panics(text));
    msg
}

fn rigid(kind: &PointKind) -> (&RigidMotion, Vec3) {
    match kind {
        PointKind::Prescribed(Motion::Rigid { motion, offset }) => (motion, *offset),
        other => panic!("not a point on a vessel: {other:?}"),
    }
}

/// The manoeuvre reads as the core builds it (knots and degrees converted, 1 kn = 1852/3600
/// m/s); the point's `position` is its offset on the vessel, and its initial position is where
/// the vessel puts it at t = 0. The RAO motion reads the table file and the mean motion, and
/// is driven by the environment's waves.
#[test]
fn vessel_motions_read_as_the_core_builds_them() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    let tow = &s.model.points[0];
    let (m, offset) = rigid(&tow.kind);
    let want = Manoeuvre::new(ManoeuvreSpec {
        start: Vec3::new(5.0, -5.0, 0.0),
        heading: 30f64.to_radians(),
        speed: 12.0 * (1852.0 / 3600.0),
        straight_before: 500.0,
        turn_radius: 250.0,
        turn_angle: (-270f64).to_radians(),
        straight_after: Some(400.0),
        build_up_time: 60.0,
        transition_length: 50.0,
    })
    .unwrap();
    assert_eq!(m, &RigidMotion::Manoeuvre(Box::new(want)));
    assert_eq!(offset, Vec3::new(-40.0, 0.0, -2.0));
    let q = Quat::from_axis_angle(&Vec3::z_axis(), 30f64.to_radians());
    assert!((tow.position - (Vec3::new(5.0, -5.0, 0.0) + q * offset)).norm() < 1e-12);

    let crane = &s.model.points[1];
    let (m, offset) = rigid(&crane.kind);
    let table = read_rao_table(Path::new("tests/motion_data/vessel_raos.csv")).unwrap();
    let mean = RigidMotion::ConstantVelocity {
        start: Vec3::new(100.0, 0.0, 0.0),
        orientation: Quat::from_axis_angle(&Vec3::z_axis(), 90f64.to_radians()),
        velocity: Vec3::new(0.0, 1.0, 0.0),
    };
    let want = RaoMotion::new(table, &s.model.environment.waves, mean).unwrap();
    assert_eq!(m, &RigidMotion::Rao(Box::new(want)));
    assert_eq!(offset, Vec3::new(10.0, 5.0, 3.0));
}

/// The RAO file: periods become angular frequencies in increasing order, headings radians,
/// rotations rad/m and phase lags radians. At tabulated points the table returns the file's
/// numbers: 10 s, 90°: sway 0.48226 m/m lagging 90°, heave 0.80377 m/m lagging 53.13°, roll
/// 5.5618°/m lagging 90° (to the file's 5 digits).
#[test]
fn rao_file_reads_with_its_units() {
    let t = read_rao_table(Path::new("tests/motion_data/vessel_raos.csv")).unwrap();
    assert_eq!(t.frequencies().len(), 11);
    assert!((t.frequencies()[0] - 2.0 * PI / 30.0).abs() < 1e-15);
    assert!(t.frequencies().windows(2).all(|w| w[1] > w[0]));
    assert_eq!(t.headings().len(), 12);
    let h = t.at(2.0 * PI / 10.0, PI / 2.0);
    let polar = |c: [Real; 2]| (c[0].hypot(c[1]), (-c[1]).atan2(c[0]).to_degrees());
    let close =
        |a: (Real, Real), b: (Real, Real)| (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-9;
    assert!(close(polar(h[1]), (0.48226, 90.0)), "{:?}", polar(h[1]));
    assert!(close(polar(h[2]), (0.80377, 53.13)), "{:?}", polar(h[2]));
    assert!(
        close(polar(h[3]), (5.5618f64.to_radians(), 90.0)),
        "{:?}",
        polar(h[3])
    );
    // A table in Hz reads too: heave 1 m/m everywhere within its frequency range.
    let t = read_rao_table(Path::new("tests/motion_data/rao_unit_heave.csv")).unwrap();
    assert!((t.frequencies()[2] - 2.0 * PI * 0.5).abs() < 1e-15);
    assert_eq!(t.at(1.0, 1.0)[2], [1.0, 0.0]);
}

/// A vessel with the unit-heave table, moored at the origin in the scenario's regular wave,
/// heaves with the surface: the point's z is its offset plus η at the vessel origin, for a
/// point on the origin's vertical (to 1e-12 m).
#[test]
fn unit_heave_vessel_rides_the_scenario_waves() {
    let text = mutate(
        "file = \"tests/motion_data/vessel_raos.csv\"\n\n[points.motion.mean]\ntype = \"constant-velocity\"\nstart = [100.0, 0.0, 0.0]\nheading = 90.0\nvelocity = [0.0, 1.0, 0.0]",
        "file = \"tests/motion_data/rao_unit_heave.csv\"\nheading = 45.0",
    )
    .replacen("position = [10.0, 5.0, 3.0]", "position = [0.0, 0.0, 3.0]", 1);
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    let PointKind::Prescribed(m) = &s.model.points[1].kind else {
        panic!()
    };
    for i in 0..100 {
        let t = 0.37 * i as Real;
        let (r, _, _) = m.kinematics(t);
        let eta = s.model.environment.surface_elevation(0.0, 0.0, t);
        assert!(
            (r.z - 3.0 - eta).abs() < 1e-12 && r.x.abs() < 1e-12,
            "t {t}"
        );
    }
}

// ---- bad input -------------------------------------------------------------------------------

#[test]
fn manoeuvre_without_turn_radius() {
    let text = mutate("turn_radius = 250.0\n", "");
    let msg = bad(
        &text,
        "type = \"manoeuvre\"",
        "points[0].motion.turn_radius",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_without_speed() {
    let text = mutate("speed_knots = 12.0\n", "");
    let msg = bad(&text, "type = \"manoeuvre\"", "points[0].motion.speed");
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_negative_radius() {
    let text = mutate("turn_radius = 250.0", "turn_radius = -250.0");
    let msg = bad(&text, "turn_radius", "points[0].motion.turn_radius");
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_speed_twice() {
    let text = mutate("speed_knots = 12.0", "speed = 6.0\nspeed_knots = 12.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "speed_knots"),
        "points[0].motion.speed_knots",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_non_finite_heading() {
    let text = mutate("heading = 30.0", "heading = nan");
    let msg = bad(&text, "heading = nan", "points[0].motion.heading");
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_transition_longer_than_the_turn() {
    let text = mutate("transition_length = 50.0", "transition_length = 1500.0");
    let msg = bad(
        &text,
        "transition_length",
        "points[0].motion.transition_length",
    );
    assert!(msg.contains("1178.1 m"), "{msg}");
    insta::assert_snapshot!(msg);
}

/// A subnormal transition once hung the loader (the clothoid's curvature rate κ/L_c was ∞
/// and its quadrature loop ran usize::MAX times); transitions too short to resolve are
/// refused at their key, whatever their size below the limit.
#[test]
fn manoeuvre_transition_too_short() {
    for lc in ["5e-324", "1e-300", "1e-5"] {
        let text = mutate(
            "transition_length = 50.0",
            &format!("transition_length = {lc}"),
        );
        let msg = bad(
            &text,
            "transition_length",
            "points[0].motion.transition_length",
        );
        assert!(msg.contains("2.500e-4 m"), "{msg}");
        if lc == "5e-324" {
            insta::assert_snapshot!(msg);
        }
    }
}

/// A turn of more than 100 full turns is refused at its key (each evaluation of a clothoid
/// costs in proportion to the heading it turns).
#[test]
fn manoeuvre_turn_too_large() {
    let text = mutate("turn_angle = -270.0", "turn_angle = -1e12");
    let msg = bad(&text, "turn_angle", "points[0].motion.turn_angle");
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_track_shorter_than_the_build_up() {
    let text = mutate("build_up_time = 60.0", "build_up_time = 1000.0");
    let msg = bad(&text, "straight_after", "points[0].motion.straight_after");
    insta::assert_snapshot!(msg);
}

#[test]
fn manoeuvre_with_an_orbit_key() {
    let text = mutate("turn_radius = 250.0", "turn_radius = 250.0\nradius = 250.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\nradius") + 1,
        "points[0].motion.radius",
        true,
        false,
    );
    assert!(
        msg.contains("turn_radius"),
        "the hint lists the keys: {msg}"
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn vessel_point_without_position() {
    let text = mutate("position = [-40.0, 0.0, -2.0]\n", "");
    let msg = bad(&text, "type = \"manoeuvre\"", "points[0].motion.type");
    insta::assert_snapshot!(msg);
}

#[test]
fn rao_without_file() {
    let text = mutate("file = \"tests/motion_data/vessel_raos.csv\"\n", "");
    let msg = bad(&text, "type = \"rao\"", "points[1].motion.file");
    insta::assert_snapshot!(msg);
}

fn bad_rao_file(name: &str, file_line: usize, fragment: &str) -> String {
    let text = mutate("vessel_raos.csv", name);
    let msg = bad(&text, "file = ", "points[1].motion.file");
    let at = format!("tests/motion_data/{name}:{file_line}:");
    assert!(msg.contains(&at), "the message names `{at}`:\n{msg}");
    assert!(
        msg.contains(fragment),
        "the message says `{fragment}`:\n{msg}"
    );
    msg
}

#[test]
fn rao_file_with_a_bad_number() {
    insta::assert_snapshot!(bad_rao_file("rao_bad_row.csv", 5, "not a number"));
}

#[test]
fn rao_file_with_unsorted_periods() {
    insta::assert_snapshot!(bad_rao_file(
        "rao_unsorted.csv",
        6,
        "sorted by increasing period_s"
    ));
}

#[test]
fn rao_file_with_a_short_row() {
    insta::assert_snapshot!(bad_rao_file("rao_columns.csv", 4, "expected 14 columns"));
}

#[test]
fn rao_file_with_mismatched_headings() {
    insta::assert_snapshot!(bad_rao_file("rao_headings.csv", 4, "same headings"));
}

#[test]
fn rao_file_with_a_negative_amplitude() {
    insta::assert_snapshot!(bad_rao_file(
        "rao_negative.csv",
        3,
        "negative RAO amplitude -0.5 of heave"
    ));
}

#[test]
fn rao_file_with_an_unknown_first_column() {
    insta::assert_snapshot!(bad_rao_file(
        "rao_header.csv",
        1,
        "`period_s`, `frequency_hz` or `omega_rad_s`"
    ));
}

#[test]
fn rao_file_missing() {
    let text = mutate("vessel_raos.csv", "no_such_file.csv");
    let msg = bad(&text, "file = ", "points[1].motion.file");
    assert!(
        msg.contains("cannot read tests/motion_data/no_such_file.csv"),
        "{msg}"
    );
}

/// `/dev/zero` as a motion file was read until memory ran out, and a FIFO blocked for ever:
/// both are refused at the `file` key, naming the file and what it is.
#[cfg(unix)]
#[test]
fn rao_file_not_a_regular_file() {
    let text = mutate("tests/motion_data/vessel_raos.csv", "/dev/zero");
    let msg = bad(&text, "file = ", "points[1].motion.file");
    assert!(
        msg.contains("cannot read /dev/zero: it is a character device, not a regular file"),
        "{msg}"
    );
    // The input façade refuses them as input files too, before opening them.
    let options = hawser_io::moordyn::ConvertOptions::default();
    let e = hawser_io::input::load_input(Path::new("/dev/zero"), &options).unwrap_err();
    insta::assert_snapshot!(e.to_string());
}

#[test]
fn rao_mean_of_a_point_motion_type() {
    let text = mutate("type = \"constant-velocity\"", "type = \"sinusoid\"");
    let msg = bad(&text, "type = \"sinusoid\"", "points[1].motion.mean.type");
    insta::assert_snapshot!(msg);
}

#[test]
fn rao_start_given_twice() {
    let text = mutate(
        "file = \"tests/motion_data/vessel_raos.csv\"",
        "file = \"tests/motion_data/vessel_raos.csv\"\nstart = [1.0, 2.0, 0.0]",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "start = [1.0"),
        "points[1].motion.start",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn rao_mean_missing_velocity() {
    let text = mutate("velocity = [0.0, 1.0, 0.0]\n", "");
    let msg = bad(
        &text,
        "type = \"constant-velocity\"",
        "points[1].motion.mean.velocity",
    );
    insta::assert_snapshot!(msg);
}

/// Every error of a badly broken motion table is reported at once.
#[test]
fn several_motion_errors_at_once() {
    let text = mutate("turn_radius = 250.0", "turn_radius = 0.0")
        .replacen("build_up_time = 60.0", "build_up_time = -1.0", 1)
        .replacen("vessel_raos.csv", "rao_unsorted.csv", 1);
    let msg = error(&text);
    for key in [
        "points[0].motion.turn_radius",
        "points[0].motion.build_up_time",
        "points[1].motion.file",
    ] {
        assert!(
            msg.contains(&format!("= key: {key}")),
            "{key} missing:\n{msg}"
        );
    }
    assert!(!panics(&text));
}

/// examples/turn_270.toml reads into the manoeuvre docs/motions.md describes: 12 kn, 150 m
/// radius, 270° to port after 2900 m, the tow point 30 m aft; the body a free point of the
/// paper's mass and volume; the cable 355 m bare over 125 m faired in 9 + 3 elements.
#[test]
fn turn_270_example_is_the_documented_one() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/turn_270.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let s = scenario::parse(&path, &text).unwrap();
    let (m, offset) = rigid(&s.model.points[0].kind);
    let RigidMotion::Manoeuvre(m) = m else {
        panic!("a manoeuvre")
    };
    let spec = m.spec();
    assert!((spec.speed - 12.0 * 1852.0 / 3600.0).abs() < 1e-12);
    assert_eq!((spec.turn_radius, spec.straight_before), (150.0, 2900.0));
    assert!((spec.turn_angle - 1.5 * PI).abs() < 1e-15);
    assert_eq!(offset, Vec3::new(-30.0, 0.0, 0.0));
    let u = spec.speed;
    let t_in = 2900.0 / u + 0.5 * spec.build_up_time;
    assert!((t_in - 529.76).abs() < 0.01, "the turn starts at {t_in} s");
    let PointKind::Free { mass, volume, .. } = s.model.points[1].kind else {
        panic!("the body is a free point")
    };
    assert_eq!((mass, volume), (9500.0, 6.25));
    let line = &s.model.lines[0];
    let sections: Vec<(f64, usize)> = line
        .sections
        .iter()
        .map(|x| (x.length, x.elements))
        .collect();
    assert_eq!(sections, vec![(355.0, 9), (125.0, 3)]);
}
