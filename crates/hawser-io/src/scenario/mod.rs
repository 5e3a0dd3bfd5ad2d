//! Scenario files: schema, validation and conversion into the core model.

pub mod build;
pub mod diagnostics;
pub mod schema;
pub mod tables;

pub use build::{InputFormat, LoadedScenario};
pub use diagnostics::{Diagnostic, ScenarioError};

use std::path::Path;

/// The text of an input file, or a diagnostic naming it.
pub(crate) fn read_source(path: &Path) -> Result<String, ScenarioError> {
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
    let source = read_source(path)?;
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
