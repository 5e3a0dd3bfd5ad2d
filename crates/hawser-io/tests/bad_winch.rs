//! `[lines.winch]`: a valid winch read into the core's [`Winch`] with its defaults and
//! channels, and every bad value gets a diagnostic naming the file, line and column, the key,
//! the value, the expected unit or range and a hint, never a panic (as in `bad_input.rs`).

use hawser::analysis::Channel;
use hawser::model::{Winch, WinchEnd, WinchStage};
mod common;
use common::*;
use hawser_io::scenario;
use std::path::Path;

/// A payload lowered 7 m from a crane tip: hold 2 s, pay out at 0.5 m/s for 14 s.
const BASE: &str = r#"# Base scenario for the winch input tests.

[simulation]
duration = 20.0
channels = ["wire.stretch", "wire.stretched_length"]

[[line_types]]
name = "wire"
diameter = 0.03
mass_per_length = 5.0
axial_stiffness = 1.0e7
normal_drag = 1.2
tangential_drag = 0.0

[[points]]
name = "crane"
type = "fixed"
position = [0.0, 0.0, 5.0]

[[points]]
name = "payload"
type = "free"
position = [0.0, 0.0, -15.0]
mass = 1000.0
volume = 0.1

[[lines]]
name = "wire"
end_a = "crane"
end_b = "payload"
type = "wire"
length = 20.0
elements = 10

[lines.winch]
end = "A"
ramp_time = 2.0
minimum_length = 5.0
stages = [
  { duration = 2.0, payout_rate = 0.0 },
  { duration = 14.0, payout_rate = 0.5 },
]
"#;

/// `BASE` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn winch_reads_as_the_core_type_with_its_channels() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    assert_eq!(
        s.model.lines[0].winch,
        Some(Winch {
            end: WinchEnd::A,
            stages: vec![
                WinchStage {
                    duration: 2.0,
                    payout_rate: 0.0
                },
                WinchStage {
                    duration: 14.0,
                    payout_rate: 0.5
                },
            ],
            ramp_time: 2.0,
            minimum_length: 5.0,
        })
    );
    // Default channels: the end tensions, then the winch line's length and winch tension,
    // then the free point; then the requested ones.
    let channels: Vec<Channel> = s.model.outputs.iter().map(|c| c.channel).collect();
    assert_eq!(
        channels[2..4],
        [
            Channel::LineLength { line: 0 },
            Channel::WinchTension { line: 0 }
        ]
    );
    assert_eq!(
        channels[7..],
        [
            Channel::LineStretch { line: 0 },
            Channel::LineStretchedLength { line: 0 }
        ]
    );
    let system = hawser::system::System::new(&s.model).unwrap();
    let names: Vec<String> = channels[2..4].iter().map(|c| c.name(&system)).collect();
    assert_eq!(names, ["wire.length", "wire.winch_tension"]);
    // Defaults: no ramp, no minimum length.
    let text = mutate("ramp_time = 2.0\nminimum_length = 5.0\n", "");
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    let w = s.model.lines[0].winch.as_ref().unwrap();
    assert_eq!((w.ramp_time, w.minimum_length), (0.0, 0.0));
}

#[test]
fn unknown_end() {
    let text = mutate("end = \"A\"", "end = \"top\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "end = \"top\""),
        "lines[0].winch.end",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_end() {
    let text = mutate("end = \"A\"\n", "");
    let msg = error(&text);
    assert!(msg.contains("lines[0].winch.end"), "{msg}");
    assert!(!panics(&text));
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_payout_rate() {
    let text = mutate(
        "{ duration = 14.0, payout_rate = 0.5 }",
        "{ duration = 14.0 }",
    );
    let msg = error(&text);
    assert!(msg.contains("payout_rate"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn no_stages() {
    let text = mutate(
        "stages = [\n  { duration = 2.0, payout_rate = 0.0 },\n  { duration = 14.0, payout_rate = 0.5 },\n]",
        "stages = []",
    );
    let msg = bad(&text, "end = \"A\"", "lines[0].winch.stages");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_duration() {
    let text = mutate("duration = 14.0", "duration = -14.0");
    let msg = bad(
        &text,
        "duration = -14.0",
        "lines[0].winch.stages[1].duration",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_ramp_time() {
    let text = mutate("ramp_time = 2.0", "ramp_time = -2.0");
    let msg = bad(&text, "ramp_time = -2.0", "lines[0].winch.ramp_time");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_minimum_length() {
    let text = mutate("minimum_length = 5.0", "minimum_length = -5.0");
    let msg = bad(
        &text,
        "minimum_length = -5.0",
        "lines[0].winch.minimum_length",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn ramp_longer_than_a_stage_that_changes_the_rate() {
    // The 2 s hold keeps the rate (0 before t = 0): only the paying-out stage needs the ramp.
    let text = mutate("duration = 14.0", "duration = 1.5");
    let msg = bad(&text, "ramp_time = 2.0", "lines[0].winch.ramp_time");
    insta::assert_snapshot!(msg);
    let text = mutate("ramp_time = 2.0", "ramp_time = 3.0");
    assert!(scenario::parse(Path::new(FILE), &text).is_ok());
}

#[test]
fn hauling_in_below_the_minimum_length() {
    // 16 s at −1 m/s with 2 s ramps hauls in 16 m: 4 m left, below the 5 m minimum.
    let text = mutate("payout_rate = 0.5", "payout_rate = -1.0");
    let text = text.replacen("duration = 14.0", "duration = 16.0", 1);
    let msg = bad(
        &text,
        "payout_rate = -1.0",
        "lines[0].winch.stages[1].payout_rate",
    );
    assert!(msg.contains("to 4.0000 m"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn winch_on_a_dg_line() {
    let text = mutate("elements = 10\n", "elements = 10\nformulation = \"dg\"\n");
    let msg = bad(&text, "end = \"A\"", "lines[0].winch");
    insta::assert_snapshot!(msg);
}

#[test]
fn winch_on_a_line_of_two_sections() {
    let text = mutate(
        "type = \"wire\"\nlength = 20.0\nelements = 10\n",
        "sections = [\n  { type = \"wire\", length = 15.0, elements = 6 },\n  { type = \"wire\", length = 5.0, elements = 4 },\n]\n",
    );
    let msg = bad(&text, "end = \"A\"", "lines[0].winch");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_key_in_a_stage() {
    let text = mutate(
        "{ duration = 2.0, payout_rate = 0.0 }",
        "{ duration = 2.0, rate = 0.0 }",
    );
    let msg = error(&text);
    assert!(msg.contains("rate"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn winch_tension_of_a_line_without_winch() {
    let text = mutate("[lines.winch]", "[lines.winch_]");
    // (an unknown table is a schema error; remove the winch instead)
    assert!(scenario::parse(Path::new(FILE), &text).is_err());
    let start = BASE.find("[lines.winch]").unwrap();
    let text = BASE[..start].replacen("channels = [", "channels = [\"wire.winch_tension\", ", 1);
    let msg = bad(&text, "wire.winch_tension", "simulation.channels[0]");
    assert!(msg.contains("no winch"), "{msg}");
    insta::assert_snapshot!(msg);
}

/// The bundled example `examples/winch_lowering.toml` as the file is: its static winch
/// tension at t = 0 is the module's wet weight plus the wire's weight, 10 m of it in air
/// (the crane tip is 10 m above the water; the stretch ε = T/EA ≈ 1.1e-3 shortens the
/// unstretched part in air to 10/(1 + ε)) and the rest wet. Tolerance 0.05 N: the tension,
/// hence ε, varies along the line by 0.7 % (≈ 0.1 mm of wire, 5e-4 N of weight difference
/// between air and water).
#[test]
fn winch_lowering_example_starts_at_its_static_tension() {
    use hawser::statics::{StaticOptions, evaluate, solve};
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/winch_lowering.toml");
    let s = scenario::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let system = hawser::system::System::new(&s.model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let tension = Channel::WinchTension { line: 0 }.value(&system, &ws);
    let env = &s.model.environment;
    let (g, rho) = (env.gravity, env.water_density);
    let (mass, volume, mu, d, ea) = (5000.0, 1.5, 2.4, 0.024, 3.0e7);
    let area = std::f64::consts::PI * d * d / 4.0;
    let eps = tension / ea;
    let in_air = 10.0 / (1.0 + eps);
    let expected =
        (mass - rho * volume) * g + mu * g * in_air + (mu - rho * area) * g * (20.0 - in_air);
    eprintln!("example: static winch tension {tension:.3} N, analytic {expected:.3} N");
    assert!((tension - expected).abs() < 0.05, "{tension} vs {expected}");
    assert_eq!(Channel::LineLength { line: 0 }.value(&system, &ws), 20.0);
}
