//! `line_types[].minimum_breaking_load`, `line_types[].design_safety_factor` and
//! `[statistics]`: valid values reach the model and the statistics options, and every bad
//! value gets a diagnostic naming the file, line and column, the key, the value, the expected
//! unit or range and a hint (as in `bad_input.rs`).

use hawser::analysis::Channel;
mod common;
use common::*;
use hawser_io::scenario;
use std::path::Path;

const BASE: &str = r#"[simulation]
duration = 60.0
channels = ["FairTen = chain.end_b.node_force"]

[[line_types]]
name = "chain"
diameter = 0.137
mass_per_length = 126.0
axial_stiffness = 5.8e8
normal_drag = 2.4
tangential_drag = 1.15
minimum_breaking_load = 4.88e6
design_safety_factor = 1.67

[[points]]
name = "anchor"
type = "fixed"
position = [-600.0, 0.0, -150.0]

[[points]]
name = "fairlead"
type = "fixed"
position = [0.0, 0.0, -15.0]

[[lines]]
name = "chain"
end_a = "anchor"
end_b = "fairlead"
type = "chain"
length = 680.0
elements = 20

[statistics]
start = 24.0
storm_duration = 3600.0
linked_channels = ["fairlead.x", "FairTen", "chain.end_a.tension"]
"#;

fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn strength_and_statistics_reach_the_model() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    let t = &s.model.line_types[0];
    assert_eq!(t.minimum_breaking_load, Some(4.88e6));
    assert_eq!(t.design_safety_factor, Some(1.67));
    assert!((t.permissible_tension().unwrap() - 4.88e6 / 1.67).abs() < 1e-6);
    // Outputs: end A and B tensions (defaults), FairTen, then fairlead.x, added because it
    // is linked and was not recorded.
    let channels: Vec<Channel> = s.model.outputs.iter().map(|c| c.channel).collect();
    assert_eq!(
        channels[3],
        Channel::PointPosition { point: 1, axis: 0 },
        "{channels:?}"
    );
    assert_eq!(channels.len(), 4);
    assert_eq!(s.statistics.start, 24.0);
    assert_eq!(s.statistics.storm_duration, 3600.0);
    // fairlead.x (appended), FairTen (by its column name), chain.end_a.tension (a default).
    assert_eq!(s.statistics.linked, vec![3, 2, 0]);
    // Without [statistics]: the whole run, 3 h, nothing linked.
    let text = BASE.split("[statistics]").next().unwrap();
    let s = scenario::parse(Path::new(FILE), text).unwrap();
    assert_eq!(s.statistics, Default::default());
    assert_eq!(s.statistics.storm_duration, 10800.0);
}

#[test]
fn bad_strength_values() {
    let text = mutate(
        "minimum_breaking_load = 4.88e6",
        "minimum_breaking_load = -1.0",
    );
    let msg = bad(
        &text,
        "minimum_breaking_load",
        "line_types[0].minimum_breaking_load",
    );
    assert!(msg.contains("N, > 0"), "{msg}");
    let text = mutate("design_safety_factor = 1.67", "design_safety_factor = 0.5");
    let msg = bad(
        &text,
        "design_safety_factor",
        "line_types[0].design_safety_factor",
    );
    assert!(msg.contains("≥ 1"), "{msg}");
    let text = mutate("minimum_breaking_load = 4.88e6\n", "");
    let msg = bad(
        &text,
        "design_safety_factor",
        "line_types[0].design_safety_factor",
    );
    assert!(msg.contains("no minimum breaking load"), "{msg}");
    insta::assert_snapshot!(msg);
    let text = mutate(
        "minimum_breaking_load = 4.88e6",
        "minimum_breaking_load = 1e300",
    );
    let msg = bad(
        &text,
        "minimum_breaking_load",
        "line_types[0].minimum_breaking_load",
    );
    assert!(msg.contains("physical range"), "{msg}");
}

#[test]
fn bad_statistics_values() {
    let text = mutate("start = 24.0", "start = 60.0");
    let msg = bad(&text, "start = 60.0", "statistics.start");
    assert!(msg.contains("leaves at most the last sample"), "{msg}");
    insta::assert_snapshot!(msg);
    let text = mutate("start = 24.0", "start = -1.0");
    bad(&text, "start = -1.0", "statistics.start");
    let text = mutate("storm_duration = 3600.0", "storm_duration = 0.0");
    bad(&text, "storm_duration", "statistics.storm_duration");
    let text = mutate("\"fairlead.x\",", "\"fairlead.q\",");
    let msg = bad(&text, "linked_channels", "statistics.linked_channels[0]");
    assert!(msg.contains("fairlead.x|y|z"), "{msg}");
    insta::assert_snapshot!(msg);
    let text = mutate(
        "\"chain.end_a.tension\"]",
        "\"chain.end_a.tension\", \"FairTen\"]",
    );
    let msg = bad(&text, "linked_channels", "statistics.linked_channels[3]");
    assert!(msg.contains("linked twice"), "{msg}");
    let text = mutate("storm_duration = 3600.0", "storm_hours = 1.0");
    let msg = error(&text);
    assert!(msg.contains("storm_hours"), "{msg}");
}
