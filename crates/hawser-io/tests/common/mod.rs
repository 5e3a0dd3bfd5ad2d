//! Helpers shared by the bad-input tests: every rejected scenario must name the file, line and
//! column, the key, the value, the expected unit or range and a hint, and never panic.
#![allow(dead_code)]

use hawser_io::scenario;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

/// The file name the test scenarios are parsed as.
pub const FILE: &str = "scenario.toml";

/// The rendered error for `text`, which must be rejected.
pub fn error(text: &str) -> String {
    match scenario::parse(Path::new(FILE), text) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// 1-based line of the first occurrence of `needle` in `text`.
pub fn line_of(text: &str, needle: &str) -> usize {
    let at = text
        .find(needle)
        .unwrap_or_else(|| panic!("no `{needle}` in the text"));
    text[..at].matches('\n').count() + 1
}

/// `text` with the first occurrence of `from` replaced by `to` (which must exist): a valid
/// base scenario made bad in one place.
pub fn replaced(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "the scenario has no `{from}`");
    text.replacen(from, to, 1)
}

/// The error for `text`, a bad value on the line of `needle`: checked to be located there,
/// to name `key`, and to have a hint and an expected unit or range.
pub fn bad(text: &str, needle: &str, key: &str) -> String {
    let msg = error(text);
    assert_located(&msg, line_of(text, needle), key, true, true);
    msg
}

/// Checks the message points at `scenario.toml:LINE:`, names `key` and, if asked, has a hint
/// and an expected unit or range.
pub fn assert_located(msg: &str, line: usize, key: &str, hint: bool, expected: bool) {
    let at = format!("{FILE}:{line}:");
    assert!(msg.contains(&at), "message lacks `{at}`:\n{msg}");
    assert!(
        msg.contains(&format!("= key: {key}\n")) || msg.ends_with(&format!("= key: {key}")),
        "message lacks key `{key}`:\n{msg}"
    );
    if hint {
        assert!(msg.contains("= hint: "), "message lacks a hint:\n{msg}");
    }
    if expected {
        assert!(
            msg.contains("= expected: "),
            "message lacks an expected unit or range:\n{msg}"
        );
    }
    assert!(!msg.contains("panicked"), "{msg}");
}

/// Runs `parse` on `text` and, if it is accepted, sets the model up as `hawser check` does and
/// evaluates the fluid kinematics at a point under water after any wave ramp; returns whether
/// anything panicked.
pub fn panics(text: &str) -> bool {
    catch_unwind(AssertUnwindSafe(|| {
        if let Ok(s) = scenario::parse(Path::new(FILE), text)
            && let Ok(system) = hawser::system::System::new(&s.model)
        {
            let _ = system.stable_step(s.model.settings.scheme);
            let env = &s.model.environment;
            let p = hawser::math::Vec3::new(1.0, 2.0, -3.0);
            let _ = (env.fluid_velocity(&p, 1e3), env.fluid_acceleration(&p, 1e3));
        }
    }))
    .is_err()
}

/// Runs the example at `path` the way `hawser run` does, for `samples` output intervals with a
/// snapshot every `snapshot_every` of them, writing its results into `dir`.
pub fn run_example_briefly(path: &Path, dir: &Path, samples: usize, snapshot_every: usize) {
    let (mut loaded, _) = hawser_io::input::load_input(path, &Default::default())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let settings = &mut loaded.model.settings;
    settings.duration = settings
        .duration
        .min(samples as f64 * settings.output_interval);
    settings.snapshot_interval = Some(snapshot_every as f64 * settings.output_interval);
    let mut session = hawser::Session::new(loaded.model.clone())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    // The formats written whatever the build's features: CSV, JSON and VTK (the Parquet file
    // is made from the CSV; its own test reads it back).
    let formats = hawser_io::scenario::OutputFormats {
        parquet: false,
        vtk: true,
    };
    let writer =
        hawser_io::results::RunWriter::create(dir, &session, path, &formats, &loaded.statistics)
            .expect("writer");
    session.attach(writer);
    let result = session.run();
    session.finish(result.as_ref().err()).expect("finish");
}
