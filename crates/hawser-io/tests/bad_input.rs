//! Every class of bad scenario input gets a diagnostic naming the file, line and column, the
//! key, the value, the expected unit or range and a hint, and never a panic. Each test mutates
//! a small valid scenario and snapshots the rendered error.

mod common;
use common::*;
use hawser_io::scenario;
use std::path::Path;

/// A valid scenario: a chain from a fixed anchor to a prescribed fairlead, and a free buoy
/// held by a second line from a sinker, with a seabed and a current profile.
const BASE: &str = r#"# Base scenario for the bad-input tests.

[simulation]
duration = 20.0
time_step = "auto"
safety_factor = 0.8
output_interval = 0.1
channels = ["L1.node5.tension", "L1.element3.strain", "buoy.z"]

[environment]
water_density = 1025.0
depth = 100.0

[environment.seabed]
stiffness = 3.0e6
damping_ratio = 1.0
friction_coefficient = 0.5
friction_velocity = 0.01

[environment.current]
type = "profile"
profile = [[-100.0, 0.1, 0.0, 0.0], [0.0, 0.5, 0.0, 0.0]]

[[line_types]]
name = "chain"
diameter = 0.09
mass_per_length = 77.7
axial_stiffness = 3.84e8
normal_drag = 1.6
tangential_drag = 0.3

[[points]]
name = "anchor"
type = "fixed"
position = [400.0, 0.0, -100.0]

[[points]]
name = "fairlead"
type = "prescribed"
position = [5.0, 0.0, -10.0]
motion = { type = "sinusoid", amplitude = [2.0, 0.0, 0.0], period = 10.0 }

[[points]]
name = "sinker"
type = "fixed"
position = [-50.0, 0.0, -100.0]

[[points]]
name = "buoy"
type = "free"
position = [-50.0, 0.0, -60.0]
mass = 200.0
volume = 2.0

[[lines]]
name = "L1"
end_a = "anchor"
end_b = "fairlead"
type = "chain"
length = 420.0
elements = 10

[[lines]]
name = "L2"
end_a = "sinker"
end_b = "buoy"
type = "chain"
length = 40.0
elements = 4
"#;

/// `BASE` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn base_scenario_is_valid() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    assert_eq!(s.model.lines.len(), 2);
    assert_eq!(s.model.points.len(), 4);
    assert!(s.has_simulation);
}

#[test]
fn unknown_key() {
    let text = mutate("diameter = 0.09", "diamter = 0.09");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "diamter"),
        "line_types[0].diamter",
        true,
        true,
    );
    assert!(msg.contains("did you mean `diameter`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn wrong_type() {
    let text = mutate("mass_per_length = 77.7", "mass_per_length = \"77.7\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "mass_per_length"),
        "line_types[0].mass_per_length",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_required_field() {
    let text = mutate("diameter = 0.09\n", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "[[line_types]]"),
        "line_types[0].diameter",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_length() {
    let text = mutate("length = 420.0", "length = -420.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "-420.0"),
        "lines[0].length",
        true,
        true,
    );
    assert!(msg.contains("= value: -420.0"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_elements() {
    let text = mutate("elements = 10", "elements = 0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "elements = 0"),
        "lines[0].elements",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_elements() {
    let text = mutate("elements = 4", "elements = -4");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "elements = -4"),
        "lines[1].elements",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn fractional_elements() {
    let text = mutate("elements = 10", "elements = 10.5");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "elements = 10.5"),
        "lines[0].elements",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn wrong_type_in_vector() {
    let text = mutate("[400.0, 0.0, -100.0]", "[400.0, \"0\", -100.0]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"0\""),
        "points[0].position[1]",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn wrong_type_scalar_or_vector() {
    let text = mutate("period = 10.0", "period = \"10 s\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"10 s\""),
        "points[1].motion.period",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn wrong_type_time_step() {
    let text = mutate("time_step = \"auto\"", "time_step = true");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "time_step"),
        "simulation.time_step",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_time_step_keyword() {
    let text = mutate("time_step = \"auto\"", "time_step = \"automatic\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "time_step"),
        "simulation.time_step",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_key_in_inline_table() {
    let text = mutate("period = 10.0", "perod = 10.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "perod"),
        "points[1].motion.perod",
        true,
        true,
    );
    assert!(msg.contains("did you mean `period`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_table() {
    let text = mutate("[environment.current]", "[environment.currents]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "currents"),
        "environment.currents",
        true,
        true,
    );
    assert!(msg.contains("did you mean `current`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn missing_required_field_of_inline_table() {
    let text = mutate("{ type = \"sinusoid\", ", "{ ");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "motion = "),
        "points[1].motion.type",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_point_type() {
    let text = mutate("type = \"free\"", "type = \"floating\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"floating\""),
        "points[3].type",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn seabed_without_depth() {
    let text = mutate("depth = 100.0\n", "");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "[environment.seabed]"),
        "environment.depth",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn line_attached_to_missing_point_near_miss() {
    let text = mutate("end_b = \"fairlead\"", "end_b = \"fairled\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"fairled\""),
        "lines[0].end_b",
        true,
        true,
    );
    assert!(msg.contains("did you mean `fairlead`?"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn line_attached_to_missing_point_far_miss() {
    let text = mutate("end_a = \"sinker\"", "end_a = \"platform\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"platform\""),
        "lines[1].end_a",
        true,
        true,
    );
    assert!(msg.contains("anchor, buoy, fairlead, sinker"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_line_type() {
    let text = mutate("type = \"chain\"", "type = \"chian\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"chian\""),
        "lines[0].type",
        true,
        true,
    );
    assert!(msg.contains("did you mean `chain`?"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_mass_per_length() {
    let text = mutate("mass_per_length = 77.7", "mass_per_length = -77.7");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "-77.7"),
        "line_types[0].mass_per_length",
        true,
        true,
    );
    assert!(msg.contains("kg/m"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_diameter() {
    let text = mutate("diameter = 0.09", "diameter = 0.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "diameter = 0.0"),
        "line_types[0].diameter",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_water_depth() {
    let text = mutate("depth = 100.0", "depth = -100.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "depth = -100.0"),
        "environment.depth",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_friction_velocity() {
    let text = mutate("friction_velocity = 0.01", "friction_velocity = 0.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "friction_velocity"),
        "environment.seabed.friction_velocity",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn safety_factor_above_one() {
    let text = mutate("safety_factor = 0.8", "safety_factor = 1.5");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "safety_factor"),
        "simulation.safety_factor",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn point_below_seabed() {
    let text = mutate("[400.0, 0.0, -100.0]", "[400.0, 0.0, -120.0]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "-120.0"),
        "points[0].position",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn mass_on_fixed_point() {
    let text = mutate(
        "position = [-50.0, 0.0, -100.0]\n",
        "position = [-50.0, 0.0, -100.0]\nmass = 5000.0\n",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "mass = 5000.0"),
        "points[2].mass",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn prescribed_point_without_motion() {
    let text = mutate(
        "motion = { type = \"sinusoid\", amplitude = [2.0, 0.0, 0.0], period = 10.0 }\n",
        "",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"prescribed\""),
        "points[1].motion",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn sinusoid_without_period_or_frequency() {
    let text = mutate(", period = 10.0 }", " }");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"sinusoid\""),
        "points[1].motion.frequency",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn non_finite_amplitude() {
    let text = mutate("amplitude = [2.0, 0.0, 0.0]", "amplitude = [nan, 0.0, 0.0]");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "nan"),
        "points[1].motion.amplitude",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn current_profile_z_not_increasing() {
    let text = mutate(
        "[[-100.0, 0.1, 0.0, 0.0], [0.0, 0.5, 0.0, 0.0]]",
        "[[0.0, 0.5, 0.0, 0.0], [-100.0, 0.1, 0.0, 0.0]]",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "profile = "),
        "environment.current.profile",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn tension_strain_table_not_from_origin() {
    let text = mutate(
        "axial_stiffness = 3.84e8",
        "tension_strain = [[0.01, 2.0e6], [0.02, 5.0e6]]",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "tension_strain"),
        "line_types[0].tension_strain",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn tension_strain_table_decreasing_tension() {
    let text = mutate(
        "axial_stiffness = 3.84e8",
        "tension_strain = [[0.0, 0.0], [0.01, 5.0e6], [0.02, 2.0e6]]",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "tension_strain"),
        "line_types[0].tension_strain",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn both_axial_stiffness_and_tension_strain() {
    let text = mutate(
        "axial_stiffness = 3.84e8\n",
        "axial_stiffness = 3.84e8\ntension_strain = [[0.0, 0.0], [0.01, 3.84e6]]\n",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "axial_stiffness"),
        "line_types[0].axial_stiffness",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_channel() {
    let text = mutate("\"buoy.z\"", "\"buoy.tension\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "channels"),
        "simulation.channels[2]",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn channel_naming_nothing() {
    let text = mutate("\"L1.node5.tension\"", "\"L3.node5.tension\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "channels"),
        "simulation.channels[0]",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn channel_node_out_of_range() {
    let text = mutate("\"L1.node5.tension\"", "\"L1.node11.tension\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "channels"),
        "simulation.channels[0]",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_formulation() {
    let text = mutate("elements = 10\n", "elements = 10\nformulation = \"fem\"\n");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\"fem\""),
        "lines[0].formulation",
        true,
        true,
    );
    assert!(msg.contains("did you mean `fe`?"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn invalid_toml_syntax() {
    let text = mutate("diameter = 0.09", "diameter = 0.09 m");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "0.09 m"),
        "line_types[0].diameter",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn unclosed_array() {
    let text = mutate("[400.0, 0.0, -100.0]", "[400.0, 0.0, -100.0");
    let msg = error(&text);
    assert!(msg.contains(&format!("{FILE}:")), "{msg}");
    assert!(msg.contains("= hint: "), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn duplicate_toml_key() {
    let text = mutate("diameter = 0.09\n", "diameter = 0.09\ndiameter = 0.1\n");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "diameter = 0.1"),
        "line_types[0].diameter",
        true,
        false,
    );
    assert!(msg.contains("line 26"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn duplicate_point_name() {
    let text = mutate("name = \"sinker\"", "name = \"anchor\"");
    let msg = error(&text);
    let second = text.match_indices("name = \"anchor\"").nth(1).unwrap().0;
    assert_located(
        &msg,
        text[..second].matches('\n').count() + 1,
        "points[2].name",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn duplicate_line_name() {
    let text = mutate("name = \"L2\"", "name = \"L1\"");
    let msg = error(&text);
    let second = text.match_indices("name = \"L1\"").nth(1).unwrap().0;
    assert_located(
        &msg,
        text[..second].matches('\n').count() + 1,
        "lines[1].name",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn several_errors_at_once() {
    let text = BASE
        .replacen("depth = 100.0", "depth = -100.0", 1)
        .replacen("diameter = 0.09", "diameter = 0.0", 1)
        .replacen("end_b = \"fairlead\"", "end_b = \"fairled\"", 1)
        .replacen("elements = 4", "elements = 0", 1)
        .replacen("\"buoy.z\"", "\"buoy.q\"", 1);
    let msg = error(&text);
    for needle in [
        "depth = -100.0",
        "diameter = 0.0",
        "\"fairled\"",
        "elements = 0",
        "\"buoy.q\"",
    ] {
        let at = format!("{FILE}:{}:", line_of(&text, needle));
        assert!(msg.contains(&at), "`{needle}` not reported at {at}:\n{msg}");
    }
    assert!(msg.contains("errors in scenario.toml"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn several_schema_errors_at_once() {
    let text = BASE
        .replacen("duration = 20.0", "duration = \"20 s\"", 1)
        .replacen("diameter = 0.09", "diamter = 0.09", 1)
        .replacen("mass = 200.0", "mas = 200.0", 1)
        .replacen("elements = 4", "elements = 4.5", 1);
    let msg = error(&text);
    for needle in ["\"20 s\"", "diamter", "mas = ", "elements = 4.5"] {
        let at = format!("{FILE}:{}:", line_of(&text, needle));
        assert!(msg.contains(&at), "`{needle}` not reported at {at}:\n{msg}");
    }
    assert!(msg.contains("4 errors in scenario.toml"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn never_panics_on_truncation() {
    let bad: Vec<usize> = (0..=BASE.len())
        .filter(|&n| BASE.is_char_boundary(n))
        .filter(|&n| panics(&BASE[..n]))
        .collect();
    assert!(
        bad.is_empty(),
        "parse panicked on truncation at bytes {bad:?}"
    );
}

#[test]
fn never_panics_on_garbage_lines() {
    let lines: Vec<&str> = BASE.lines().collect();
    let garbage = [
        "%%% not toml %%%",
        "[",
        "[[",
        "[[lines]]",
        "[[points]]",
        "[environment.current]",
        "x = ",
        "= 1",
        "name = 1",
        "\"unterminated",
    ];
    let values = [
        "nan",
        "inf",
        "-inf",
        "0",
        "-0.0",
        "-1",
        "1e308",
        "-1e308",
        "9223372036854775807",
        "-9223372036854775808",
        "\"\"",
        "\"x\"",
        "[]",
        "[[]]",
        "[0.0]",
        "[nan, nan, nan]",
        "[inf, 0.0, 0.0]",
        "{}",
        "true",
    ];
    let mut bad = Vec::new();
    for i in 0..lines.len() {
        let mut candidates: Vec<String> = garbage.iter().map(|g| g.to_string()).collect();
        if let Some((key, _)) = lines[i].split_once(" = ") {
            candidates.extend(values.iter().map(|v| format!("{key} = {v}")));
        }
        for g in candidates {
            let mut l = lines.clone();
            l[i] = &g;
            let text = l.join("\n");
            if panics(&text) {
                bad.push(format!("line {}: {g}", i + 1));
            }
        }
    }
    assert!(bad.is_empty(), "parse panicked on:\n{}", bad.join("\n"));
}

#[test]
fn release_of_an_unknown_point() {
    let text = mutate("channels = [", "release = [\"boy\"]\nchannels = [");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "release"),
        "simulation.release[0]",
        true,
        true,
    );
    assert!(msg.contains("did you mean `buoy`?"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn release_of_a_fixed_point() {
    let text = mutate(
        "channels = [",
        "release = [\"buoy\", \"anchor\"]\nchannels = [",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "release"),
        "simulation.release[1]",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn vtk_format_without_snapshots() {
    let text = mutate("channels = [", "formats = [\"vtk\"]\nchannels = [");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "formats"),
        "simulation.formats",
        true,
        true,
    );
    assert!(msg.contains("snapshot_interval"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_format() {
    // CSV and JSON are always written: "csv" is not a format to choose.
    let text = mutate("channels = [", "formats = [\"csv\"]\nchannels = [");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "formats"),
        "simulation.formats[0]",
        true,
        true,
    );
    assert!(msg.contains("always written"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn formats_chosen() {
    let text = mutate(
        "channels = [",
        "snapshot_interval = 1.0\nformats = [\"vtk\"]\nchannels = [",
    );
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    assert!(s.formats.vtk && !s.formats.parquet);
    let s = scenario::parse(
        Path::new(FILE),
        &mutate("channels = [", "formats = []\nchannels = ["),
    )
    .unwrap();
    assert!(!s.formats.vtk && !s.formats.parquet);
    let s = scenario::parse(Path::new(FILE), BASE).unwrap();
    assert_eq!(s.formats, hawser_io::scenario::OutputFormats::default());
}
