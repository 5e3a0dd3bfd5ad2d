//! Input checks added after the first snapshot round: names that would break channel names,
//! a scenario without lines, and circular-orbit parameters.

use hawser_io::scenario::parse;
use std::path::Path;

const BASE: &str = r#"
[[line_types]]
name = "rope"
diameter = 0.02
mass_per_length = 0.5
axial_stiffness = 1e7
normal_drag = 1.2
tangential_drag = 0.01

[[points]]
name = "top"
type = "prescribed"
position = [0.0, 0.0, -1.0]
MOTION

[[points]]
name = "POINT"
type = "free"
position = [0.0, 0.0, -51.0]
mass = 10.0

[[lines]]
name = "L1"
end_a = "top"
end_b = "POINT"
type = "rope"
length = 50.0
elements = 10
"#;

fn scenario(motion: &str, point: &str) -> String {
    BASE.replace("MOTION", motion).replace("POINT", point)
}

fn error(text: &str) -> String {
    parse(Path::new("scenario.toml"), text)
        .unwrap_err()
        .to_string()
}

#[test]
fn a_point_name_with_a_dot_is_refused_with_its_position() {
    let e = error(&scenario(r#"motion = { type = "fixed" }"#, "weight.1"));
    assert!(
        e.contains("point names must be non-empty without `.`"),
        "{e}"
    );
    assert!(e.contains("scenario.toml:17:8"), "{e}");
    assert!(!e.contains("has no `motion`"), "{e}");
}

#[test]
fn a_point_named_like_a_line_is_refused() {
    let e = error(&scenario(r#"motion = { type = "fixed" }"#, "L1"));
    assert!(e.contains("point `L1` has the name of line 0"), "{e}");
    assert!(
        e.contains("hint: points and lines share the channel namespace"),
        "{e}"
    );
}

#[test]
fn a_scenario_without_lines_is_refused() {
    let e = error("[[points]]\nname = \"a\"\ntype = \"fixed\"\nposition = [0.0, 0.0, -1.0]\n");
    assert!(e.contains("the scenario defines no lines"), "{e}");
    assert!(e.contains("hint: add a line between two points"), "{e}");
}

#[test]
fn an_orbit_accepts_a_period_and_refuses_per_axis_values() {
    let ok = scenario(
        r#"motion = { type = "circular-orbit", radius = 2.0, period = 5.0 }"#,
        "payload",
    );
    let loaded = parse(Path::new("scenario.toml"), &ok).expect("a period is accepted for an orbit");
    let hawser::model::PointKind::Prescribed(hawser::model::Motion::CircularOrbit {
        frequency,
        ..
    }) = &loaded.model.points[0].kind
    else {
        panic!("not an orbit")
    };
    assert!((frequency - 0.2).abs() < 1e-15);
    let e = error(&scenario(
        r#"motion = { type = "circular-orbit", radius = 2.0, frequency = [0.2, 0.2, 0.2] }"#,
        "payload",
    ));
    assert!(
        e.contains("an orbit takes one `frequency`, not one per axis"),
        "{e}"
    );
    let e = error(&scenario(
        r#"motion = { type = "circular-orbit", radius = 2.0, frequency = 0.2, amplitude = 1.0 }"#,
        "payload",
    ));
    assert!(
        e.contains("does not apply to a `circular-orbit` motion"),
        "{e}"
    );
}

/// A point on a vessel follows r = X + R r0 with R = R_z(yaw) R_y(pitch) R_x(roll) about the
/// vessel origin: a quarter turn of each angle moves the unit vectors as right-handed rotations
/// do, the displacement adds, and times shift by the offset.
#[test]
fn vessel_motion_rotates_points_about_the_vessel_origin() {
    use hawser::math::Vec3;
    use hawser_io::scenario::build::vessel_point_motion;
    let at = |row: [f64; 7], r0: Vec3| {
        let m = vessel_point_motion(&[row], r0, 5.0).unwrap();
        let (p, _, _) = m.kinematics(5.0);
        p
    };
    let close = |a: Vec3, b: Vec3| (a - b).norm() < 1e-12;
    // yaw 90°: x → y
    assert!(close(
        at([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 90.0], Vec3::x()),
        Vec3::y()
    ));
    // pitch 90°: x → −z (nose down for a positive pitch about y)
    assert!(close(
        at([0.0, 0.0, 0.0, 0.0, 0.0, 90.0, 0.0], Vec3::x()),
        -Vec3::z()
    ));
    // roll 90°: y → z
    assert!(close(
        at([0.0, 0.0, 0.0, 0.0, 90.0, 0.0, 0.0], Vec3::y()),
        Vec3::z()
    ));
    // the displacement adds; yaw then applies to the body point
    assert!(close(
        at(
            [0.0, 1.0, 2.0, 3.0, 0.0, 0.0, 180.0],
            Vec3::new(1.0, 0.0, -1.0)
        ),
        Vec3::new(0.0, 2.0, 2.0)
    ));
    // roll, pitch, yaw compose as R_z R_y R_x: (0, 90, 90) takes x to −z, then yaw leaves z.
    assert!(close(
        at([0.0, 0.0, 0.0, 0.0, 0.0, 90.0, 90.0], Vec3::x()),
        -Vec3::z()
    ));
    // and y: R_x(0) y = y, R_y(90) y = y, R_z(90) y = −x
    assert!(close(
        at([0.0, 0.0, 0.0, 0.0, 0.0, 90.0, 90.0], Vec3::y()),
        -Vec3::x()
    ));
}

/// Names become file names (snapshots/NAME.csv): a path separator, `:` or a control
/// character in a line's or point's name is refused at the name, so nothing can be written
/// outside the output folder.
#[test]
fn names_that_would_leave_the_output_folder_are_refused() {
    const FIXED: &str = "motion = { type = \"fixed\" }";
    // As written in TOML (basic strings): `up/x`, `a\b`, `c:d`, `bell` + BEL.
    for bad in [r#""up/x""#, r#""a\\b""#, r#""c:d""#, r#""bell\u0007""#] {
        let text = scenario(FIXED, "p").replace("name = \"L1\"", &format!("name = {bad}"));
        let e = parse(Path::new("s.toml"), &text).unwrap_err().to_string();
        assert!(
            e.contains("lines[0].name") && e.contains("file names"),
            "{bad}: {e}"
        );
        let text = scenario(FIXED, "p").replace("name = \"p\"", &format!("name = {bad}"));
        let text = text.replace("end_b = \"p\"", &format!("end_b = {bad}"));
        let e = parse(Path::new("s.toml"), &text).unwrap_err().to_string();
        assert!(e.contains("points[1].name"), "{bad}: {e}");
    }
}
