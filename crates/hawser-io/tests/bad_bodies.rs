//! Bad `[[bodies]]` input: every class gets a diagnostic naming the file, line and column, the
//! key, the value, the expected unit or range and a hint, never a panic. Each test mutates a
//! small valid scenario (a line and a towed body) and snapshots the rendered error.
//!
mod common;
use common::*;
use hawser_io::scenario;
use std::path::Path;

const BASE: &str = r#"# Base scenario for the bad-body tests.

[[line_types]]
name = "cable"
diameter = 0.03
mass_per_length = 2.0
axial_stiffness = 5.0e7
normal_drag = 1.2
tangential_drag = 0.01

[[points]]
name = "ship"
type = "fixed"
position = [0.0, 0.0, 0.0]

[[points]]
name = "towpoint"
type = "fixed"
position = [-100.0, 0.0, -50.0]

[[lines]]
name = "tow"
end_a = "ship"
end_b = "towpoint"
type = "cable"
length = 115.0
elements = 10

[[bodies]]
name = "towfish"
type = "free"
position = [-100.0, 0.0, -50.0]
orientation = [0.0, 0.0, 180.0]
mass = 9500.0
centre_of_gravity = [0.0, 0.0, -0.2]
inertia = [4000.0, 9000.0, 9500.0]
displacement = { type = "cylinder", radius = 0.6, height = 4.0 }
centre_of_buoyancy = [0.0, 0.0, 0.1]
added_mass = [600.0, 2000.0, 2500.0, 300.0, 3000.0, 2800.0]
linear_drag = [0.0, 0.0, 100.0, 0.0, 0.0, 0.0]
drag_coefficients = [0.8, 1.2, 1.2]
drag_areas = [1.5, 4.0, 6.0]
thrust = { force = [1.0e4, 0.0, 0.0] }
wind = { velocity = [15.0, 0.0, 0.0], drag_area = 20.0 }
"#;

/// `BASE` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

/// The valid base builds, free or fixed, with the body's values.
#[test]
fn valid_bodies_build() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    let b = &s.model.bodies[0];
    assert_eq!((b.name.as_str(), b.mass), ("towfish", 9500.0));
    assert_eq!(b.kind, hawser::model::BodyKind::Free);
    assert!((b.quadratic_drag[2] - 7.2).abs() < 1e-12);
    let fixed = mutate("type = \"free\"", "type = \"fixed\"");
    let s = scenario::parse(Path::new(FILE), &fixed).expect("valid");
    assert!(matches!(
        s.model.bodies[0].kind,
        hawser::model::BodyKind::Prescribed(_)
    ));
}

#[test]
fn missing_mass() {
    let text = mutate("mass = 9500.0\n", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "type = \"free\""),
        "bodies[0].mass",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_mass() {
    let text = mutate("mass = 9500.0", "mass = 0.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "mass = 0.0"),
        "bodies[0].mass",
        true,
        true,
    );
    assert!(msg.contains("kg, > 0"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn mass_with_a_unit() {
    let text = mutate("mass = 9500.0", "mass = \"9500 kg\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "9500 kg"),
        "bodies[0].mass",
        true,
        true,
    );
    assert!(msg.contains("mass = 9500"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_principal_inertia() {
    let text = mutate("[4000.0, 9000.0, 9500.0]", "[4000.0, -9000.0, 9500.0]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "inertia ="),
        "bodies[0].inertia",
        true,
        true,
    );
    assert!(msg.contains("principal moment ≤ 0"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn asymmetric_inertia_tensor() {
    let text = mutate(
        "[4000.0, 9000.0, 9500.0]",
        "[[4000.0, 10.0, 0.0], [0.0, 9000.0, 0.0], [0.0, 0.0, 9500.0]]",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "inertia ="),
        "bodies[0].inertia",
        true,
        true,
    );
    assert!(msg.contains("not symmetric"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn inertia_of_the_wrong_shape() {
    let text = mutate("[4000.0, 9000.0, 9500.0]", "[4000.0, 9000.0]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "inertia ="),
        "bodies[0].inertia",
        true,
        true,
    );
    assert!(msg.contains("[Ixx, Iyy, Izz] or a 3×3 matrix"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_key() {
    let text = mutate("centre_of_gravity", "centre_of_gravty");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "centre_of_gravty"),
        "bodies[0].centre_of_gravty",
        true,
        true,
    );
    assert!(msg.contains("did you mean `centre_of_gravity`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn motion_on_a_free_body() {
    let text = mutate(
        "type = \"free\"",
        "type = \"free\"\nmotion = { type = \"fixed\" }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion"),
        "bodies[0].motion",
        true,
        false,
    );
    assert!(msg.contains("type = \"prescribed\""), "{msg}");
    insta::assert_snapshot!(msg);
}

/// The base body made prescribed: its pose lines replaced by `motion`.
fn prescribed(motion: &str) -> String {
    mutate(
        "type = \"free\"\nposition = [-100.0, 0.0, -50.0]\norientation = [0.0, 0.0, 180.0]",
        &format!("type = \"prescribed\"\n{motion}"),
    )
}

/// A valid prescribed body: `motion` builds, and the pose is the motion's at t = 0.
#[test]
fn prescribed_body_builds() {
    let text = prescribed(
        "motion = { type = \"constant-velocity\", start = [5.0, 0.0, -20.0], heading = 90.0, velocity = [0.0, 2.0, 0.0] }",
    );
    let s = scenario::parse(Path::new(FILE), &text).unwrap_or_else(|e| panic!("{e}"));
    let b = &s.model.bodies[0];
    assert_eq!(b.position, hawser::math::Vec3::new(5.0, 0.0, -20.0));
    assert!((b.orientation.euler_angles().2 - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    match &b.kind {
        hawser::model::BodyKind::Prescribed(m) => {
            let k = m.kinematics(10.0);
            assert_eq!(k.position, hawser::math::Vec3::new(5.0, 20.0, -20.0));
        }
        k => panic!("{k:?}"),
    }
}

#[test]
fn prescribed_body_without_motion() {
    let text = prescribed("");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "type = \"prescribed\""),
        "bodies[0].motion",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_body_with_a_position() {
    let text = prescribed(
        "position = [0.0, 0.0, -5.0]\nmotion = { type = \"constant-velocity\", velocity = [1.0, 0.0, 0.0] }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "position = [0.0, 0.0, -5.0]"),
        "bodies[0].position",
        true,
        false,
    );
    assert!(msg.contains("`start`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_body_with_a_point_motion() {
    let text = prescribed("motion = { type = \"sinusoid\", amplitude = 1.0, period = 10.0 }");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion ="),
        "bodies[0].motion.type",
        true,
        true,
    );
    assert!(msg.contains("not a motion of a vessel or body"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_manoeuvre_without_turn_radius() {
    let text =
        prescribed("motion = { type = \"manoeuvre\", speed_knots = 12.0, turn_angle = 270.0 }");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion ="),
        "bodies[0].motion.turn_radius",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_motion_key_of_another_type() {
    let text = prescribed(
        "motion = { type = \"manoeuvre\", speed = 6.0, turn_radius = 150.0, turn_angle = 90.0, velocity = [1.0, 0.0, 0.0] }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion ="),
        "bodies[0].motion.velocity",
        true,
        false,
    );
    assert!(
        msg.contains("does not apply to a `manoeuvre` motion"),
        "{msg}"
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_rao_with_a_missing_file() {
    let text = prescribed("motion = { type = \"rao\", file = \"no_such_raos.csv\" }");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion ="),
        "bodies[0].motion.file",
        true,
        true,
    );
    assert!(msg.contains("no_such_raos.csv"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_displacement_type() {
    let text = mutate("type = \"cylinder\"", "type = \"sphere\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "sphere"),
        "bodies[0].displacement.type",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn cylinder_without_radius() {
    let text = mutate("radius = 0.6, ", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "displacement ="),
        "bodies[0].displacement.radius",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn volume_given_to_a_box() {
    let text = mutate(
        "{ type = \"cylinder\", radius = 0.6, height = 4.0 }",
        "{ type = \"box\", length = 4.0, breadth = 1.0, height = 1.0, volume = 4.0 }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "displacement ="),
        "bodies[0].displacement.volume",
        true,
        false,
    );
    assert!(msg.contains("`length`, `breadth`, `height`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_volume() {
    let text = mutate(
        "{ type = \"cylinder\", radius = 0.6, height = 4.0 }",
        "{ type = \"submerged\", volume = -4.0 }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "displacement ="),
        "bodies[0].displacement.volume",
        true,
        true,
    );
    assert!(
        msg.contains("= value: -4.0") && msg.contains("m³, ≥ 0"),
        "{msg}"
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_added_mass() {
    let text = mutate("300.0, 3000.0", "300.0, -3000.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "added_mass"),
        "bodies[0].added_mass",
        true,
        true,
    );
    assert!(msg.contains("pitch"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn five_added_masses() {
    let text = mutate(", 2800.0]", "]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "added_mass"),
        "bodies[0].added_mass",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn drag_coefficients_without_areas() {
    let text = mutate("drag_areas = [1.5, 4.0, 6.0]\n", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "drag_coefficients"),
        "bodies[0].drag_areas",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn both_forms_of_quadratic_drag() {
    let text = mutate(
        "drag_areas = [1.5, 4.0, 6.0]\n",
        "drag_areas = [1.5, 4.0, 6.0]\nquadratic_drag = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]\n",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "quadratic_drag"),
        "bodies[0].quadratic_drag",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn thrust_schedule_not_increasing() {
    let text = mutate(
        "thrust = { force = [1.0e4, 0.0, 0.0] }",
        "thrust = { table = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.0, 1e4, 0.0, 0.0, 0.0, 0.0, 0.0]] }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "thrust ="),
        "bodies[0].thrust.table",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn thrust_force_and_table() {
    let text = mutate(
        "thrust = { force = [1.0e4, 0.0, 0.0] }",
        "thrust = { force = [1.0e4, 0.0, 0.0], table = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]] }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "thrust ="),
        "bodies[0].thrust.force",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_wind_drag_area() {
    let text = mutate("drag_area = 20.0", "drag_area = -20.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "wind ="),
        "bodies[0].wind.drag_area",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_position() {
    let text = mutate(
        "position = [-100.0, 0.0, -50.0]\norientation",
        "orientation",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "name = \"towfish\""),
        "bodies[0].position",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn body_named_like_a_line() {
    let text = mutate("name = \"towfish\"", "name = \"tow\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "name = \"tow\"\ntype = \"free\""),
        "bodies[0].name",
        true,
        false,
    );
    assert!(msg.contains("has the name of a line"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn duplicate_body_name() {
    let text = format!(
        "{BASE}\n[[bodies]]\nname = \"towfish\"\ntype = \"fixed\"\nposition = [0.0, 0.0, -5.0]\nmass = 1.0\ninertia = [1.0, 1.0, 1.0]\n"
    );
    let msg = error(&text);
    let second = text.rfind("name = \"towfish\"").unwrap();
    let line = text[..second].matches('\n').count() + 1;
    assert_located(&msg, line, "bodies[1].name", true, false);
    assert!(msg.contains("first defined on line"), "{msg}");
    insta::assert_snapshot!(msg);
}

/// Range errors in one body are all reported together, each at its own line.
#[test]
fn several_body_errors_at_once() {
    let text = mutate("mass = 9500.0", "mass = -1.0")
        .replacen("[4000.0, 9000.0, 9500.0]", "[0.0, 9000.0, 9500.0]", 1)
        .replacen("drag_area = 20.0", "drag_area = -1.0", 1);
    let msg = error(&text);
    assert!(msg.contains("3 errors in scenario.toml"), "{msg}");
    for key in [
        "bodies[0].mass",
        "bodies[0].inertia",
        "bodies[0].wind.drag_area",
    ] {
        assert!(msg.contains(&format!("= key: {key}\n")), "{key}: {msg}");
    }
}

/// No mutation of a body's values panics the reader.
#[test]
fn no_panic_on_odd_values() {
    for (from, to) in [
        ("mass = 9500.0", "mass = nan"),
        ("mass = 9500.0", "mass = inf"),
        ("[4000.0, 9000.0, 9500.0]", "[nan, 1.0, 1.0]"),
        (
            "[4000.0, 9000.0, 9500.0]",
            "[[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]",
        ),
        ("radius = 0.6", "radius = -inf"),
        (
            "orientation = [0.0, 0.0, 180.0]",
            "orientation = [nan, 0.0, 0.0]",
        ),
        (
            "thrust = { force = [1.0e4, 0.0, 0.0] }",
            "thrust = { table = [] }",
        ),
        ("thrust = { force = [1.0e4, 0.0, 0.0] }", "thrust = { }"),
        ("velocity = [15.0, 0.0, 0.0]", "velocity = [inf, 0.0, 0.0]"),
    ] {
        let text = mutate(from, to);
        assert!(!panics(&text), "{to}");
        assert!(scenario::parse(Path::new(FILE), &text).is_err(), "{to}");
    }
}

/// The `[[bodies]]` example of docs/scenario.md is valid.
#[test]
fn documented_example_is_valid() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario.md"),
    )
    .expect("docs/scenario.md");
    let start = doc.find("# A towed body").expect("the bodies example");
    let example = &doc[start..start + doc[start..].find("```").unwrap()];
    let lines_only = &BASE[..BASE.find("[[bodies]]").unwrap()];
    let text = format!("{lines_only}\n{example}");
    let s = scenario::parse(Path::new(FILE), &text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.model.bodies.len(), 2);
}

/// The `[bodies.motion]` example of docs/scenario.md is valid: a ship on the 270° turn with a
/// tow point on it.
#[test]
fn documented_prescribed_example_is_valid() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario.md"),
    )
    .expect("docs/scenario.md");
    let start = doc
        .find("# A survey vessel")
        .expect("the prescribed body example");
    let example = &doc[start..start + doc[start..].find("```").unwrap()];
    let lines_only = &BASE[..BASE.find("[[bodies]]").unwrap()].replace("\"ship\"", "\"deck\"");
    let text = format!("{lines_only}\n{example}");
    let s = scenario::parse(Path::new(FILE), &text).unwrap_or_else(|e| panic!("{e}"));
    let k = match &s.model.bodies[0].kind {
        hawser::model::BodyKind::Prescribed(m) => m.kinematics(1000.0),
        k => panic!("{k:?}"),
    };
    assert!((k.velocity.norm() - 12.0 * 1852.0 / 3600.0).abs() < 1e-9);
}

/// The `[[bodies.members]]` example of docs/scenario.md is valid and reaches the model.
#[test]
fn documented_member_example_is_valid() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario.md"),
    )
    .expect("docs/scenario.md");
    let start = doc.find("# A rod of 20 m").expect("the member example");
    let example = &doc[start..start + doc[start..].find("```").unwrap()];
    let lines_only = &BASE[..BASE.find("[[bodies]]").unwrap()];
    let text = format!("{lines_only}\n{example}");
    let s = scenario::parse(Path::new(FILE), &text).unwrap_or_else(|e| panic!("{e}"));
    let m = &s.model.bodies[0].members[0];
    assert_eq!((m.diameter, m.segments, m.end_added_mass), (0.25, 4, 1.0));
}

/// A member with its ends at one place, no segment or a negative coefficient is refused at
/// its key.
#[test]
fn bad_members() {
    let base = BASE.replace(
        "[[bodies]]",
        "[[bodies]]\nmembers = [{ end_a = [0.0, 0.0, 0.0], end_b = [0.0, 0.0, 0.0], diameter = 0.2, segments = 0, end_drag = -1.0 }]",
    );
    let msg = error(&base);
    for needle in [
        "a member's ends are at the same place",
        "a member needs at least one segment",
        "bodies[0].members[0].end_drag",
    ] {
        assert!(msg.contains(needle), "{needle}:\n{msg}");
    }
}

/// `type = "pinned"` builds a pinned body: fixed at `position` by default, on a coupling host
/// with `pin = "coupled"`, on its `motion` with `pin = "prescribed"` (the origin starts where
/// the motion is at t = 0, the orientation is the body's own).
#[test]
fn pinned_bodies_build() {
    use hawser::model::{BodyKind, Pin};
    let text = mutate("type = \"free\"", "type = \"pinned\"");
    let s = scenario::parse(Path::new(FILE), &text).expect("valid");
    assert_eq!(s.model.bodies[0].kind, BodyKind::Pinned(Pin::Fixed));
    let text = mutate("type = \"free\"", "type = \"pinned\"\npin = \"coupled\"");
    let s = scenario::parse(Path::new(FILE), &text).expect("valid");
    assert_eq!(s.model.bodies[0].kind, BodyKind::Pinned(Pin::Coupled));
    let text = mutate(
        "type = \"free\"\nposition = [-100.0, 0.0, -50.0]",
        "type = \"pinned\"\npin = \"prescribed\"\n\
         motion = { type = \"constant-velocity\", start = [-90.0, 1.0, -40.0], velocity = [2.0, 0.0, 0.0] }",
    );
    let s = scenario::parse(Path::new(FILE), &text).expect("valid");
    let b = &s.model.bodies[0];
    assert!(matches!(b.kind, BodyKind::Pinned(Pin::Prescribed(_))));
    assert_eq!(b.position, hawser::math::Vec3::new(-90.0, 1.0, -40.0));
    let yaw = b.orientation.euler_angles().2.to_degrees();
    assert!((yaw.abs() - 180.0).abs() < 1e-9, "yaw {yaw}");
}

#[test]
fn pin_on_a_free_body() {
    let text = mutate("type = \"free\"", "type = \"free\"\npin = \"fixed\"");
    let msg = error(&text);
    assert_located(&msg, line_of(&text, "pin = "), "bodies[0].pin", true, false);
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_pin_without_motion() {
    let text = mutate(
        "type = \"free\"\nposition = [-100.0, 0.0, -50.0]",
        "type = \"pinned\"\npin = \"prescribed\"",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "pin = "),
        "bodies[0].motion",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_pin_with_a_position() {
    let text = mutate(
        "type = \"free\"",
        "type = \"pinned\"\npin = \"prescribed\"\n\
         motion = { type = \"constant-velocity\", start = [-90.0, 1.0, -40.0], velocity = [2.0, 0.0, 0.0] }",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "position = [-100.0, 0.0, -50.0]\norientation"),
        "bodies[0].position",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn pinned_body_without_inertia() {
    let text = replaced(
        &mutate("type = \"free\"", "type = \"pinned\""),
        "inertia = [4000.0, 9000.0, 9500.0]\n",
        "",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "type = \"pinned\""),
        "bodies[0].inertia",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

/// The pinned-body example of docs/scenario.md is valid: a body on a prescribed pin starting
/// at the motion's start with its own orientation, and one on a fixed pin.
#[test]
fn documented_pinned_example_is_valid() {
    use hawser::model::{BodyKind, Pin};
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario.md"),
    )
    .expect("docs/scenario.md");
    let start = doc.find("# A davit arm").expect("the pinned body example");
    let example = &doc[start..start + doc[start..].find("```").unwrap()];
    let lines_only = &BASE[..BASE.find("[[bodies]]").unwrap()];
    let text = format!("{lines_only}\n{example}");
    let s = scenario::parse(Path::new(FILE), &text).unwrap_or_else(|e| panic!("{e}"));
    let (arm, buoy) = (&s.model.bodies[0], &s.model.bodies[1]);
    assert!(matches!(arm.kind, BodyKind::Pinned(Pin::Prescribed(_))));
    assert_eq!(arm.position, hawser::math::Vec3::new(0.0, 0.0, 10.0));
    assert!((arm.orientation.euler_angles().1.to_degrees() - 30.0).abs() < 1e-9);
    assert_eq!(buoy.kind, BodyKind::Pinned(Pin::Fixed));
}

/// A second body, `arm`, pinned to the towfish at (1, 0, −0.5) in the towfish's axes, given
/// by the keys `pin_keys` (appended to the arm's table).
fn with_arm(pin_keys: &str) -> String {
    format!(
        "{BASE}\n[[bodies]]\nname = \"arm\"\ntype = \"pinned\"\nmass = 100.0\n\
         centre_of_gravity = [0.0, 0.0, -1.0]\ninertia = [30.0, 30.0, 5.0]\n{pin_keys}\n"
    )
}

/// `pin = "body"` pins a body to a point of another: its origin starts on that point (the
/// towfish at (−100, 0, −50) turned 180° in yaw puts (1, 0, −0.5) at (−101, 0, −50.5)).
#[test]
fn pin_on_a_body_builds() {
    use hawser::math::Vec3;
    use hawser::model::{BodyKind, Pin};
    let text = with_arm("pin = \"body\"\npin_body = \"towfish\"\npin_point = [1.0, 0.0, -0.5]");
    let s = scenario::parse(Path::new(FILE), &text).expect("valid");
    let arm = &s.model.bodies[1];
    assert_eq!(
        arm.kind,
        BodyKind::Pinned(Pin::Body {
            body: 0,
            point: Vec3::new(1.0, 0.0, -0.5)
        })
    );
    assert!(
        (arm.position - Vec3::new(-101.0, 0.0, -50.5)).norm() < 1e-9,
        "{}",
        arm.position
    );
}

/// A pin on an unknown body, on the body itself, on a body that is itself pinned to a body,
/// without `pin_body`, or with a `position`, is refused at its key, with a hint.
#[test]
fn bad_pins_on_bodies() {
    for (keys, key, needle) in [
        (
            "pin = \"body\"\npin_body = \"tug\"",
            "bodies[1].pin_body",
            "which does not exist",
        ),
        (
            "pin = \"body\"\npin_body = \"arm\"",
            "bodies[1].pin_body",
            "is pinned to itself",
        ),
        ("pin = \"body\"", "bodies[1].pin_body", "has no `pin_body`"),
        (
            "pin = \"body\"\npin_body = \"towfish\"\nposition = [0.0, 0.0, 0.0]",
            "bodies[1].position",
            "takes its `position` from the pin",
        ),
        (
            "pin = \"fixed\"\nposition = [0.0, 0.0, -50.0]\npin_point = [0.0, 0.0, 1.0]",
            "bodies[1].pin_point",
            "only a body with `pin = \"body\"`",
        ),
    ] {
        let msg = error(&with_arm(keys));
        assert!(
            msg.contains(key) && msg.contains(needle),
            "{key}, {needle}:\n{msg}"
        );
    }
    // A chain: a third body pinned to the arm, which is pinned to the towfish.
    let text = with_arm("pin = \"body\"\npin_body = \"towfish\"")
        + "\n[[bodies]]\nname = \"hook\"\ntype = \"pinned\"\nmass = 10.0\n\
           inertia = [1.0, 1.0, 1.0]\npin = \"body\"\npin_body = \"arm\"\n";
    let msg = error(&text);
    assert!(
        msg.contains("bodies[2].pin_body") && msg.contains("itself pinned to a body"),
        "{msg}"
    );
    insta::assert_snapshot!(msg);
}
