//! The properties the fuzzers check, one function per target, shared by the cargo-fuzz
//! targets in `fuzz/` and the proptest smoke run in `tests/fuzz_smoke.rs` (docs/fuzzing.md).
//! Each takes arbitrary bytes and panics when a property fails; a returned error is a pass.

use crate::moordyn::{self, ConvertOptions};
use crate::scenario;
use std::path::Path;

/// The TOML reader with the builder: whatever the bytes, the reader returns a model (checked
/// by `Model::validate`) or errors that each render with a position inside the text, never
/// a panic.
pub fn scenario_bytes(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let file = Path::new("fuzzed.toml");
    match scenario::parse(file, text) {
        Ok(_) => {}
        Err(e) => check_errors(&e, text),
    }
}

/// The deck reader with the converter and a round trip: whatever the bytes, the reader
/// returns a model or located errors, never a panic; an accepted deck converts to TOML that
/// loads back into the same scenario.
pub fn deck_bytes(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let file = Path::new("fuzzed.txt");
    match moordyn::parse(file, text, &ConvertOptions::default()) {
        Ok(d) => {
            let toml_text = moordyn::to_toml(&d, file);
            if let Err(e) = scenario::parse(Path::new("fuzzed.toml"), &toml_text) {
                panic!("a converted deck does not load:\n{e}\n\n{toml_text}");
            }
            let again: scenario::schema::Scenario =
                toml::from_str(&toml_text).expect("the converted TOML parses");
            assert_eq!(
                toml::to_string(&again).expect("serialises"),
                toml::to_string(&d.scenario).expect("serialises"),
                "the converted TOML holds another scenario"
            );
        }
        Err(e) => check_errors(&e, text),
    }
}

/// Every error has a message, a located span lies in the text on a line that exists, and the
/// whole renders.
fn check_errors(e: &scenario::ScenarioError, text: &str) {
    assert!(!e.diagnostics.is_empty(), "an error without diagnostics");
    let lines = text.split('\n').count();
    for d in &e.diagnostics {
        assert!(
            !d.message.is_empty(),
            "a diagnostic without a message: {d:?}"
        );
        if let Some(s) = &d.span {
            assert!(s.start <= text.len(), "a span past the end: {d:?}");
            assert!(
                d.line >= 1 && d.line <= lines,
                "a line outside the text: {d:?}"
            );
        }
    }
    let _ = e.to_string();
}
