//! `[[obstacles]]`: valid obstacles read into the core's [`Obstacle`] with their defaults and
//! channels, and every bad value gets a diagnostic naming the file, line and column, the key,
//! the value, the expected unit or range and a hint, never a panic (as in `bad_input.rs`).

use hawser::analysis::Channel;
use hawser::math::Vec3;
use hawser::model::Motion;
use hawser::physics::obstacles::{Obstacle, ObstacleDamping, ObstacleShape};
mod common;
use common::*;
use hawser_io::scenario;
use std::path::Path;

/// A line over a fixed drum, and a sphere sweeping past it.
const BASE: &str = r#"# Base scenario for the obstacle input tests.

[simulation]
duration = 10.0
channels = ["drum.contact_length", "ball.force_y"]

[[line_types]]
name = "rope"
diameter = 0.02
mass_per_length = 0.5
axial_stiffness = 1.0e6
normal_drag = 1.2
tangential_drag = 0.02

[[points]]
name = "a"
type = "fixed"
position = [-5.0, 0.0, 0.0]

[[points]]
name = "b"
type = "fixed"
position = [5.0, 0.0, 0.0]

[[lines]]
name = "rope"
end_a = "a"
end_b = "b"
type = "rope"
length = 10.5
elements = 40

[[obstacles]]
name = "drum"
shape = "cylinder"
radius = 0.5
axis = [0.0, 3.0, 4.0]
length = 2.0
position = [0.0, 0.0, -1.0]
stiffness = 2.0e5
damping = 50.0
friction_coefficient = 0.3
friction_velocity = 0.02

[[obstacles]]
name = "ball"
shape = "sphere"
radius = 0.3
position = [2.0, -3.0, -1.5]
stiffness = 1.0e5
damping_ratio = 0.5

[obstacles.motion]
type = "constant-velocity"
velocity = [0.0, 1.0, 0.0]
"#;

/// `BASE` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn obstacles_read_as_the_core_types_with_their_defaults_and_channels() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    let o = &s.model.environment.obstacles;
    assert_eq!(
        o[0],
        Obstacle {
            name: "drum".into(),
            shape: ObstacleShape::Cylinder {
                radius: 0.5,
                axis: Vec3::new(0.0, 0.6, 0.8),
                length: Some(2.0),
            },
            motion: Motion::Fixed {
                position: Vec3::new(0.0, 0.0, -1.0)
            },
            stiffness: 2.0e5,
            damping: ObstacleDamping::PerLength(50.0),
            friction_coefficient: 0.3,
            friction_velocity: 0.02,
        }
    );
    assert_eq!(
        o[1],
        Obstacle {
            name: "ball".into(),
            shape: ObstacleShape::Sphere { radius: 0.3 },
            motion: Motion::ConstantVelocity {
                start: Vec3::new(2.0, -3.0, -1.5),
                velocity: Vec3::y(),
            },
            stiffness: 1.0e5,
            damping: ObstacleDamping::Ratio(0.5),
            friction_coefficient: 0.0,
            friction_velocity: 0.01,
        }
    );
    // Default channels: the force on every obstacle, after the end tensions; then the
    // requested ones.
    let channels: Vec<Channel> = s.model.outputs.iter().map(|c| c.channel).collect();
    let force = |obstacle, axis| Channel::ObstacleForce { obstacle, axis };
    assert_eq!(
        channels[2..],
        [
            force(0, 0),
            force(0, 1),
            force(0, 2),
            force(1, 0),
            force(1, 1),
            force(1, 2),
            Channel::ObstacleContactLength { obstacle: 0 },
        ]
    );
    let system = hawser::system::System::new(&s.model).unwrap();
    assert_eq!(force(1, 2).name(&system), "ball.force_z");
    assert_eq!(
        Channel::ObstacleContactLength { obstacle: 0 }.name(&system),
        "drum.contact_length"
    );
    // A cylinder without `length` is infinite.
    let text = mutate("length = 2.0\n", "");
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    assert!(matches!(
        s.model.environment.obstacles[0].shape,
        ObstacleShape::Cylinder { length: None, .. }
    ));
}

#[test]
fn negative_radius() {
    let text = mutate("radius = 0.5", "radius = -0.5");
    let msg = bad(&text, "radius = -0.5", "obstacles[0].radius");
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_axis() {
    let text = mutate("axis = [0.0, 3.0, 4.0]", "axis = [0.0, 0.0, 0.0]");
    let msg = bad(&text, "axis =", "obstacles[0].axis");
    insta::assert_snapshot!(msg);
}

#[test]
fn cylinder_without_axis() {
    let text = mutate("axis = [0.0, 3.0, 4.0]\n", "");
    let msg = bad(&text, "shape = \"cylinder\"", "obstacles[0].axis");
    insta::assert_snapshot!(msg);
}

#[test]
fn axis_on_a_sphere() {
    let text = mutate("radius = 0.3\n", "radius = 0.3\naxis = [0.0, 0.0, 1.0]\n");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "axis = [0.0, 0.0, 1.0]"),
        "obstacles[1].axis",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_length() {
    let text = mutate("length = 2.0", "length = -2.0");
    let msg = bad(&text, "length = -2.0", "obstacles[0].length");
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_stiffness() {
    let text = mutate("stiffness = 2.0e5", "stiffness = 0.0");
    let msg = bad(&text, "stiffness = 0.0", "obstacles[0].stiffness");
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_stiffness() {
    let text = mutate("stiffness = 1.0e5\n", "");
    let msg = error(&text);
    assert!(msg.contains("stiffness"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn both_dampings() {
    let text = mutate("damping = 50.0", "damping = 50.0\ndamping_ratio = 1.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "damping = 50.0"),
        "obstacles[0].damping",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_friction() {
    let text = mutate("friction_coefficient = 0.3", "friction_coefficient = -0.3");
    let msg = bad(
        &text,
        "friction_coefficient",
        "obstacles[0].friction_coefficient",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_friction_velocity() {
    let text = mutate("friction_velocity = 0.02", "friction_velocity = 0.0");
    let msg = bad(&text, "friction_velocity", "obstacles[0].friction_velocity");
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_position() {
    let text = mutate("position = [0.0, 0.0, -1.0]\n", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "name = \"drum\""),
        "obstacles[0].position",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn duplicate_obstacle_name() {
    let text =
        mutate("name = \"ball\"", "name = \"drum\"").replacen("ball.force_y", "drum.force_y", 1);
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "name = \"drum\"\nshape = \"sphere\""),
        "obstacles[1].name",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn obstacle_named_like_a_line() {
    let text = mutate("name = \"drum\"", "name = \"rope\"");
    let text = text.replacen("\"drum.contact_length\", ", "", 1);
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "name = \"rope\"\nshape"),
        "obstacles[0].name",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_shape() {
    let text = mutate("shape = \"sphere\"", "shape = \"cube\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "cube"),
        "obstacles[1].shape",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn motion_key_that_does_not_apply() {
    let text = mutate(
        "velocity = [0.0, 1.0, 0.0]",
        "velocity = [0.0, 1.0, 0.0]\nradius = 2.0",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "radius = 2.0"),
        "obstacles[1].motion.radius",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_obstacle_channel() {
    let text = mutate("\"ball.force_y\"", "\"ball.force_w\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "ball.force_w"),
        "simulation.channels[1]",
        true,
        true,
    );
    assert!(
        msg.contains("ball.force_x|force_y|force_z|contact_length"),
        "{msg}"
    );
    insta::assert_snapshot!(msg);
}

/// As `common::panics`, and if the model is accepted, one right-hand side of the straight
/// state at t = 1 s (the obstacle contact) and the obstacle channels.
fn panics_in_contact(text: &str) -> bool {
    use std::panic::{AssertUnwindSafe, catch_unwind};
    panics(text)
        || catch_unwind(AssertUnwindSafe(|| {
            if let Ok(s) = scenario::parse(Path::new(FILE), text)
                && let Ok(system) = hawser::system::System::new(&s.model)
            {
                let y = system.straight_state();
                let mut dydt = vec![0.0; y.len()];
                let mut ws = system.workspace();
                let _ = system.rhs(1.0, &y, &mut dydt, &mut ws);
                for c in &s.model.outputs {
                    let _ = c.channel.value_at(&system, &ws, 1.0);
                }
            }
        }))
        .is_err()
}

/// Every line of the obstacle tables replaced by extreme and ill-typed values: no panic, in
/// reading or in evaluating the contact.
#[test]
fn never_panics_on_bad_obstacle_values() {
    let values = [
        "nan",
        "inf",
        "-inf",
        "0",
        "-0.0",
        "-1",
        "1e308",
        "-1e308",
        "1e-300",
        "\"\"",
        "\"sphere\"",
        "\"cylinder\"",
        "[]",
        "[0.0]",
        "[0.0, 0.0, 0.0]",
        "[1e308, inf, 0.0]",
        "[1e-300, 0.0, 0.0]",
        "{}",
        "true",
    ];
    let lines: Vec<&str> = BASE.lines().collect();
    let start = line_of(BASE, "[[obstacles]]");
    let mut bad = Vec::new();
    for i in start..lines.len() {
        let Some((key, _)) = lines[i].split_once(" = ") else {
            continue;
        };
        for v in values {
            let mut l = lines.clone();
            let g = format!("{key} = {v}");
            l[i] = &g;
            if panics_in_contact(&l.join("\n")) {
                bad.push(format!("line {}: {g}", i + 1));
            }
        }
    }
    assert!(bad.is_empty(), "panics: {bad:?}");
}
