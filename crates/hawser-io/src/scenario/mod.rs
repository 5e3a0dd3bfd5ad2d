//! Scenario files: schema, validation and conversion into the core model.

pub mod build;
pub mod diagnostics;
pub mod overrides;
pub mod schema;
pub mod tables;

pub use build::{InputFormat, LoadedScenario, OutputFormats};
pub use diagnostics::{Diagnostic, ScenarioError};

use std::path::Path;

/// The text of an input file, or a diagnostic naming it.
pub(crate) fn read_source(path: &Path) -> Result<String, ScenarioError> {
    read_file(path, "input file")
}

/// The text of `path`, or a diagnostic "cannot read the `what`: …" naming it.
pub(crate) fn read_file(path: &Path, what: &str) -> Result<String, ScenarioError> {
    tables::read_text_file(path).map_err(|e| {
        let hint = match e.is_refused() {
            true => format!(
                "hawser reads regular files of at most {} MiB",
                tables::MAX_FILE_BYTES >> 20
            ),
            false => "check the path".to_string(),
        };
        ScenarioError::from(
            Diagnostic::new(path, "", None, "", format!("cannot read the {what}: {e}")).hint(hint),
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
