//! Scenario files: schema, validation and conversion into the core model.

pub mod build;
pub mod diagnostics;
pub mod schema;

pub use build::{InputFormat, LoadedScenario};
pub use diagnostics::{Diagnostic, ScenarioError};

use std::path::Path;

/// Reads and validates an input file: a hawser scenario (TOML) or a MoorDyn v2 deck,
/// recognised by its content (dashed MoorDyn section headers), not by its extension. `deck`
/// holds the choices a deck leaves to its host (duration, vessel motion); the notes say what
/// was converted or has no effect (empty for TOML).
pub fn load_input(
    path: &Path,
    deck: &crate::moordyn::ConvertOptions,
) -> Result<(LoadedScenario, Vec<crate::moordyn::Note>), ScenarioError> {
    let source = read(path)?;
    if crate::moordyn::looks_like_deck(&source) {
        let d = crate::moordyn::parse(path, &source, deck)?;
        Ok((d.loaded, d.notes))
    } else {
        Ok((build::build(path, &source)?, Vec::new()))
    }
}

fn read(path: &Path) -> Result<String, ScenarioError> {
    std::fs::read_to_string(path).map_err(|e| {
        ScenarioError::from(
            Diagnostic::new(
                path,
                "",
                None,
                "",
                format!("cannot read the input file: {e}"),
            )
            .hint("check the path"),
        )
    })
}

/// Reads and validates a scenario file.
pub fn load(path: &Path) -> Result<LoadedScenario, ScenarioError> {
    let source = read(path)?;
    build::build(path, &source)
}

/// Validates scenario text as if read from `path`.
pub fn parse(path: &Path, source: &str) -> Result<LoadedScenario, ScenarioError> {
    build::build(path, source)
}

/// The JSON Schema of scenario files, generated from the same types the reader uses.
pub fn json_schema() -> String {
    let schema = schemars::schema_for!(schema::Scenario);
    serde_json::to_string_pretty(&schema).expect("schema serialises")
}
