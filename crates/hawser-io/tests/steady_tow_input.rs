//! `[simulation] initial_condition = "steady-tow"`: a scenario whose vessel moves at one
//! constant velocity reads into `InitialCondition::SteadyTow` and a system with that tow
//! velocity; one whose prescribed motions are not one constant horizontal velocity, or with
//! waves, gets a diagnostic at the key naming file, line, value, the expectation and a hint,
//! never a panic (as in `bad_input.rs`). The examples `towing_system{1,2,3}_body.toml` solve
//! to the results in docs/towing.md.

mod common;
use common::*;
use hawser::math::{Real, Vec3};
use hawser::model::InitialCondition;
use hawser_io::scenario;
use std::path::Path;

const BASE: &str = r#"# A vehicle towed at 0.8 m/s.

[simulation]
duration = 10.0
initial_condition = "steady-tow"

[[line_types]]
name = "tether"
diameter = 0.012
mass_per_length = 0.2288
axial_stiffness = 1.08e7
normal_drag = 1.35
tangential_drag = 0.04

[[points]]
name = "ship"
type = "prescribed"
position = [0.0, 0.0, 0.0]
motion = { type = "constant-velocity", velocity = [0.8, 0.0, 0.0] }

[[points]]
name = "vehicle"
type = "free"
position = [-90.0, 0.0, -35.0]
mass = 250.0
volume = 0.243902
drag_area = 0.8

[[lines]]
name = "tow"
end_a = "ship"
end_b = "vehicle"
type = "tether"
length = 100.0
elements = 10
"#;

#[test]
fn steady_tow_reads_the_tow_velocity() {
    let s = scenario::parse(Path::new(FILE), BASE).unwrap();
    assert_eq!(
        s.model.settings.initial_condition,
        InitialCondition::SteadyTow
    );
    let system = hawser::system::System::new(&s.model).unwrap();
    assert_eq!(system.tow_velocity, Vec3::new(0.8, 0.0, 0.0));
}

fn bad(text: &str, key_line: &str) -> String {
    assert!(!panics(text));
    let msg = error(text);
    assert_located(
        &msg,
        line_of(text, key_line),
        "simulation.initial_condition",
        true,
        true,
    );
    msg
}

#[test]
fn an_anchor_in_a_steady_tow_is_refused() {
    let text = format!(
        "{BASE}\n[[points]]\nname = \"anchor\"\ntype = \"fixed\"\nposition = [0.0, 0.0, -50.0]\n\n\
         [[lines]]\nname = \"riser\"\nend_a = \"anchor\"\nend_b = \"vehicle\"\ntype = \"tether\"\n\
         length = 60.0\nelements = 5\n"
    );
    let msg = bad(&text, "initial_condition");
    assert!(msg.contains("anchor"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn a_sinusoid_in_a_steady_tow_is_refused() {
    let text = BASE.replace(
        "motion = { type = \"constant-velocity\", velocity = [0.8, 0.0, 0.0] }",
        "motion = { type = \"sinusoid\", amplitude = [1.0, 0.0, 0.0], period = 10.0 }",
    );
    let msg = bad(&text, "initial_condition");
    assert!(msg.contains("sinusoid"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn a_vertical_tow_velocity_is_refused() {
    let text = BASE.replace("velocity = [0.8, 0.0, 0.0]", "velocity = [0.8, 0.0, -0.2]");
    let msg = bad(&text, "initial_condition");
    assert!(msg.contains("horizontal"), "{msg}");
    insta::assert_snapshot!(msg);
}

/// Each example's steady tow: (free body, bridle point, line) and the bridle's depth [m],
/// layback [m], the ship-end and body-end tensions [N] and the pitch [deg], as docs/towing.md
/// quotes them (printed with `-- --nocapture`). The tolerance is the printed rounding, half a
/// unit of the last digit of the table.
fn check_example(file: &str, expected: &[(&str, &str, &str, [Real; 5])]) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(file);
    let s = scenario::load(&path).unwrap();
    let system = hawser::system::System::new(&s.model).unwrap();
    let sol = hawser::statics::solve(&system, None, &Default::default())
        .unwrap_or_else(|e| panic!("{e}"));
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    eprintln!("{file}: {} ({} iterations)", sol.method, sol.iterations);
    for (body, bridle, line, want) in expected {
        let b = system
            .bodies
            .iter()
            .position(|b| &b.body.name == body)
            .unwrap();
        let p = system
            .points
            .iter()
            .position(|p| &p.name == bridle)
            .unwrap();
        let l = system.lines.iter().position(|l| &l.name == line).unwrap();
        let ship = ws.points[system.lines[l].end_a].position;
        let r = ws.points[p].position - ship;
        let got = [
            -r.z,
            -r.x,
            system.end_force(&ws, l, false).norm(),
            system.end_force(&ws, l, true).norm(),
            ws.bodies[b].orientation.euler_angles().1.to_degrees(),
        ];
        eprintln!(
            "| {line} | {:.2} | {:.2} | {:.1} | {:.1} | {:.2} |",
            got[0], got[1], got[2], got[3], got[4]
        );
        // Half a unit of the table's last digit: 0.01 m, 0.1 N, 0.01°.
        for ((g, w), unit) in got.iter().zip(want).zip([0.01, 0.01, 0.1, 0.1, 0.01]) {
            assert!(
                (g - w).abs() <= 0.5 * unit,
                "{line}: {got:?} against {want:?}"
            );
        }
    }
}

#[test]
fn towing_system1_body_example() {
    check_example(
        "towing_system1_body.toml",
        &[
            (
                "carrier",
                "nose",
                "tow",
                [64.97, 394.29, 5385.8, 2785.2, 0.00],
            ),
            (
                "carrier_nodrag",
                "nose_nodrag",
                "tow_nodrag",
                [164.92, 353.02, 3926.1, 2785.2, 0.00],
            ),
        ],
    );
}

#[test]
fn towing_system2_body_example() {
    let cases: Vec<(String, String, String)> = ["T050", "T100", "T150", "T250"]
        .iter()
        .flat_map(|t| {
            ["", "_nodrag"].map(|d| {
                (
                    format!("vehicle_{t}{d}"),
                    format!("bridle_{t}{d}"),
                    format!("tow_{t}{d}"),
                )
            })
        })
        .collect();
    let want: [[Real; 5]; 8] = [
        [22.49, 96.97, 257.7, 218.0, 6.45],
        [26.68, 95.44, 247.6, 218.0, 6.45],
        [35.36, 93.41, 235.5, 182.6, 2.27],
        [47.47, 86.95, 235.1, 182.6, 2.27],
        [46.41, 88.54, 215.1, 151.4, -2.49],
        [70.88, 69.51, 229.8, 151.4, -2.49],
        [61.07, 75.76, 190.5, 113.4, -10.91],
        [99.53, 9.56, 223.6, 113.4, -10.91],
    ];
    let expected: Vec<(&str, &str, &str, [Real; 5])> = cases
        .iter()
        .zip(want)
        .map(|((b, p, l), w)| (b.as_str(), p.as_str(), l.as_str(), w))
        .collect();
    check_example("towing_system2_body.toml", &expected);
}

#[test]
fn towing_system3_body_example() {
    check_example(
        "towing_system3_body.toml",
        &[
            (
                "vehicle",
                "bridle",
                "tow",
                [78.91, 60.16, 197.4, 107.8, -8.85],
            ),
            (
                "vehicle_nodrag",
                "bridle_nodrag",
                "tow_nodrag",
                [97.34, 22.43, 215.5, 107.8, -8.85],
            ),
        ],
    );
}
