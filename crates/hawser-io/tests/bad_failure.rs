//! `[lines.failure]` and MoorDyn's FAILURE section: a valid failure read into the core's
//! [`LineFailure`], and every bad value gets a diagnostic naming the file, line and column,
//! the key, the value, the expected unit or range and a hint, never a panic (as in
//! `bad_input.rs`).

use hawser::model::{End, LineFailure};
mod common;
use common::*;
use hawser_io::moordyn::{self, ConvertOptions};
use hawser_io::scenario;
use std::path::{Path, PathBuf};

/// A buoy held by two lines to anchors; line `east` parts at its buoy end at 30 s or at
/// 200 kN.
const BASE: &str = r#"# Base scenario for the failure input tests.

[simulation]
duration = 60.0

[[line_types]]
name = "chain"
diameter = 0.08
mass_per_length = 120.0
axial_stiffness = 5.0e8
minimum_breaking_load = 4.0e6
normal_drag = 1.2
tangential_drag = 0.1

[[points]]
name = "west_anchor"
type = "fixed"
position = [-300.0, 0.0, -100.0]

[[points]]
name = "east_anchor"
type = "fixed"
position = [300.0, 0.0, -100.0]

[[points]]
name = "buoy"
type = "free"
position = [0.0, 0.0, -20.0]
mass = 5000.0
volume = 30.0

[[lines]]
name = "west"
end_a = "west_anchor"
end_b = "buoy"
type = "chain"
length = 330.0
elements = 20

[[lines]]
name = "east"
end_a = "east_anchor"
end_b = "buoy"
type = "chain"
length = 330.0
elements = 20

[lines.failure]
end = "B"
time = 30.0
tension = 2.0e5

[environment]
depth = 100.0
"#;

/// `BASE` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn failure_reads_as_the_core_type() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    assert_eq!(
        s.model.failures,
        [LineFailure {
            line: 1,
            end: End::B,
            joined: vec![],
            time: Some(30.0),
            tension: Some(2.0e5),
        }]
    );
    // At the line type's breaking load, without a time: the host may still call it.
    let text = mutate("time = 30.0\ntension = 2.0e5", "at_breaking_load = true");
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    assert_eq!(s.model.failures[0].tension, Some(4.0e6));
    assert_eq!(s.model.failures[0].time, None);
    let text = mutate("time = 30.0\ntension = 2.0e5", "");
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    assert_eq!(
        (s.model.failures[0].time, s.model.failures[0].tension),
        (None, None)
    );
}

#[test]
fn unknown_end() {
    let text = mutate("end = \"B\"", "end = \"fairlead\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "end = \"fairlead\""),
        "lines[1].failure.end",
        true,
        true,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_tension() {
    let text = mutate("tension = 2.0e5", "tension = -2.0e5");
    let msg = bad(&text, "tension = -2.0e5", "lines[1].failure.tension");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_time() {
    let text = mutate("time = 30.0", "time = -1.0");
    let msg = bad(&text, "time = -1.0", "lines[1].failure.time");
    insta::assert_snapshot!(msg);
}

#[test]
fn breaking_load_and_tension_both() {
    let text = mutate(
        "tension = 2.0e5",
        "tension = 2.0e5\nat_breaking_load = true",
    );
    let msg = bad(
        &text,
        "at_breaking_load = true",
        "lines[1].failure.at_breaking_load",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn breaking_load_without_one() {
    let text = mutate("minimum_breaking_load = 4.0e6\n", "").replacen(
        "time = 30.0\ntension = 2.0e5",
        "at_breaking_load = true",
        1,
    );
    let msg = bad(
        &text,
        "at_breaking_load = true",
        "lines[1].failure.at_breaking_load",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn failure_on_a_dg_line() {
    let text = mutate(
        "elements = 20\n\n[lines.failure]",
        "elements = 4\nformulation = \"dg\"\n\n[lines.failure]",
    );
    let msg = bad(&text, "end = \"B\"", "lines[1].failure");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_key() {
    let text = mutate("time = 30.0", "time = 30.0\nline = \"east\"");
    let msg = error(&text);
    assert!(msg.contains("line"), "{msg}");
    assert!(!panics(&text));
    insta::assert_snapshot!(msg);
}

// ---- MoorDyn FAILURE rows -------------------------------------------------------------------

fn deck_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn")
}

/// The OC3 deck with a FAILURE section of `rows` before its OPTIONS.
fn deck_with(rows: &str) -> String {
    let t = std::fs::read_to_string(deck_dir().join("oc3_lines.txt")).unwrap();
    t.replacen(
        "---------------------- OPTIONS",
        &format!(
            "---------------------- FAILURE ----------------------\n\
             FailureID  Point    Line(s)   FailTime   FailTen\n\
             ()           ()       (,)      (s or 0)   (N or 0)\n\
             {rows}---------------------- OPTIONS"
        ),
        1,
    )
}

fn parse_deck(text: &str) -> Result<moordyn::LoadedDeck, String> {
    moordyn::parse(
        &deck_dir().join("deck.txt"),
        text,
        &ConvertOptions::default(),
    )
    .map_err(|e| {
        e.to_string()
            .replace(&deck_dir().display().to_string(), "<decks>")
    })
}

/// FAILURE rows map to the line end at the row's point, with 0 for no trigger; the
/// converted scenario's TOML reads back to the same failures.
#[test]
fn moordyn_failure_rows_map_to_line_ends() {
    let d = parse_deck(&deck_with("1  4  1  12.5  0\n2  P2  2  0  3.0e6\n")).unwrap();
    let f = &d.loaded.model.failures;
    assert_eq!(
        f,
        &[
            LineFailure {
                line: 0,
                end: End::B,
                joined: vec![],
                time: Some(12.5),
                tension: None
            },
            LineFailure {
                line: 1,
                end: End::A,
                joined: vec![],
                time: None,
                tension: Some(3.0e6)
            },
        ]
    );
    let toml = moordyn::to_toml(&d, Path::new("deck.txt"));
    assert!(toml.contains("[lines.failure]"), "{toml}");
    let again = scenario::parse(Path::new("deck.toml"), &toml).unwrap();
    assert_eq!(&again.model.failures, f);
}

/// A row of several lines must name lines that all have an end at its point: OC3's line 2
/// runs from point 2 to point 5, not to point 4.
#[test]
fn moordyn_failure_of_several_lines_not_all_at_the_point() {
    let e = parse_deck(&deck_with("1  4  1,2  0  1.2e6\n")).unwrap_err();
    assert!(
        e.contains("failure 1: line 2 is not attached to 4 (its ends are at P2 and P5)")
            && e.contains("FAILURE › 1 › Lines")
            && e.contains("hint:"),
        "{e}"
    );
}

#[test]
fn moordyn_failure_at_a_point_the_line_does_not_touch() {
    insta::assert_snapshot!(parse_deck(&deck_with("1  5  1  10  0\n")).unwrap_err());
}

#[test]
fn moordyn_failure_of_an_unknown_line() {
    insta::assert_snapshot!(parse_deck(&deck_with("1  4  9  10  0\n")).unwrap_err());
}

#[test]
fn moordyn_failure_with_a_negative_tension() {
    insta::assert_snapshot!(parse_deck(&deck_with("1  4  1  0  -5\n")).unwrap_err());
}

// ---- [[failures]]: several line ends released together ---------------------------------------

/// `BASE` without the line's own failure and with a `[[failures]]` table of `table` (its keys).
fn joined(table: &str) -> String {
    let base = replaced(
        BASE,
        "[lines.failure]\nend = \"B\"\ntime = 30.0\ntension = 2.0e5\n",
        "",
    );
    format!("{base}\n[[failures]]\n{table}")
}

/// Both lines' buoy ends release together at 30 s onto one free point: the model's failure
/// has the first end and the second as joined; the tension trigger reads the same way.
#[test]
fn joined_failure_reads_as_the_core_type() {
    let s = scenario::parse(
        Path::new(FILE),
        &joined("point = \"buoy\"\nlines = [\"west\", \"east\"]\ntime = 30.0\ntension = 4.0e5\n"),
    )
    .unwrap();
    assert_eq!(
        s.model.failures,
        vec![LineFailure {
            line: 0,
            end: End::B,
            joined: vec![(1, End::B)],
            time: Some(30.0),
            tension: Some(4.0e5),
        }]
    );
}

/// Bad `[[failures]]` tables are refused at the line and key of the bad value, with what is
/// expected and a hint: an unknown point, one line only, an unknown line, a line not at the
/// point, a line listed twice, a line end that already has a `[lines.failure]`, a negative
/// time.
#[test]
fn bad_joined_failures_are_refused() {
    let both = "lines = [\"west\", \"east\"]\n";
    let m = bad(
        &joined(&format!("point = \"boy\"\n{both}time = 1.0\n")),
        "point = \"boy\"",
        "failures[0].point",
    );
    assert!(m.contains("did you mean `buoy`?"), "{m}");
    let m = bad(
        &joined("point = \"buoy\"\nlines = [\"west\"]\n"),
        "lines = [\"west\"]",
        "failures[0].lines",
    );
    assert!(m.contains("`[lines.failure]`"), "{m}");
    let m = bad(
        &joined("point = \"buoy\"\nlines = [\"west\", \"eats\"]\n"),
        "lines = [",
        "failures[0].lines[1]",
    );
    assert!(m.contains("did you mean `east`?"), "{m}");
    let m = bad(
        &joined(&format!("point = \"west_anchor\"\n{both}")),
        "lines = [",
        "failures[0].lines[1]",
    );
    assert!(m.contains("neither of its ends is at the point"), "{m}");
    let m = bad(
        &joined("point = \"buoy\"\nlines = [\"west\", \"east\", \"west\"]\n"),
        "lines = [",
        "failures[0].lines[2]",
    );
    assert!(m.contains("listed twice"), "{m}");
    let with_own = format!("{BASE}\n[[failures]]\npoint = \"buoy\"\n{both}");
    let m = bad(&with_own, "lines = [", "failures[0].lines[1]");
    assert!(m.contains("already has a failure"), "{m}");
    bad(
        &joined(&format!("point = \"buoy\"\n{both}time = -1.0\n")),
        "time = -1.0",
        "failures[0].time",
    );
}
