//! The input façade: one entry point for every input file, above both readers. A hawser
//! scenario (TOML, [`crate::scenario`]) and a MoorDyn v2 deck ([`crate::moordyn`]) are told
//! apart by their content; the deck reader builds on the scenario types, never the other way.

use crate::moordyn::{self, ConvertOptions, Note};
use crate::scenario::overrides::{Override, apply_overrides, overridden_path};
use crate::scenario::{self, LoadedScenario, ScenarioError};
use std::path::{Path, PathBuf};

/// Reads and validates an input file: a hawser scenario (TOML) or a MoorDyn v2 deck,
/// recognised by its content (dashed MoorDyn section headers), not by its extension. `deck`
/// holds the choices a deck leaves to its host (duration, vessel motion); the notes say what
/// was converted or has no effect (empty for TOML).
pub fn load_input(
    path: &Path,
    deck: &ConvertOptions,
) -> Result<(LoadedScenario, Vec<Note>), ScenarioError> {
    let source = scenario::read_source(path)?;
    parse_input(path, &source, deck)
}

/// [`load_input`] of the text `source`, as if read from `path` (files it names are found
/// beside `path`).
pub fn parse_input(
    path: &Path,
    source: &str,
    deck: &ConvertOptions,
) -> Result<(LoadedScenario, Vec<Note>), ScenarioError> {
    if moordyn::looks_like_deck(source) {
        let d = moordyn::parse(path, source, deck)?;
        Ok((d.loaded, d.notes))
    } else {
        Ok((scenario::parse(path, source)?, Vec::new()))
    }
}

/// The scenario text of an input: a scenario's own text, a deck's conversion (what `hawser
/// convert` writes). Invalid input gives its diagnostics.
pub fn scenario_text(
    path: &Path,
    source: &str,
    deck: &ConvertOptions,
) -> Result<String, ScenarioError> {
    if moordyn::looks_like_deck(source) {
        let d = moordyn::parse(path, source, deck)?;
        Ok(moordyn::to_toml(&d, path))
    } else {
        Ok(source.to_string())
    }
}

/// An input with dotted-key overrides applied ([`crate::scenario::overrides`]): the scenario
/// text (a deck's conversion for a deck), each override set in it, and the result validated
/// under [`overridden_path`]`(path)`, whose diagnostics' lines and columns are those of the
/// returned text. Returns that name, the text and the loaded scenario, whose format stays a
/// deck's for a deck (its `dtM` was chosen for MoorDyn, its coupled points are a host's).
pub fn with_overrides(
    path: &Path,
    source: &str,
    deck: &ConvertOptions,
    overrides: &[Override],
) -> Result<(PathBuf, String, LoadedScenario), ScenarioError> {
    let text = scenario_text(path, source, deck)?;
    let mut table: toml::Table = match toml::from_str(&text) {
        Ok(t) => t,
        // Invalid TOML: the scenario reader's diagnostics say where.
        Err(_) => {
            return Err(scenario::parse(path, &text).err().unwrap_or_else(|| {
                ScenarioError::from(scenario::Diagnostic::new(
                    path,
                    "",
                    None,
                    "",
                    "the scenario is not a TOML table",
                ))
            }));
        }
    };
    apply_overrides(path, &mut table, overrides)?;
    let name = overridden_path(path);
    let text = toml::to_string_pretty(&table).map_err(|e| {
        ScenarioError::from(scenario::Diagnostic::new(
            path,
            "",
            None,
            "",
            format!("the scenario with its overrides cannot be written as TOML: {e}"),
        ))
    })?;
    let mut loaded = scenario::parse(&name, &text)?;
    if moordyn::looks_like_deck(source) {
        loaded.format = scenario::InputFormat::MoorDyn;
    }
    Ok((name, text, loaded))
}

/// A time step refused by the stability check ([`hawser::SimulationError::StepTooLarge`])
/// as a diagnostic at the `simulation.time_step` key of `source` (the text of `file`, as
/// loaded into `loaded`): the step, the limit and what sets it, and a hint. `None` for
/// other errors.
pub fn step_diagnostic(
    file: &Path,
    source: &str,
    loaded: &LoadedScenario,
    e: &hawser::SimulationError,
) -> Option<scenario::Diagnostic> {
    let hawser::SimulationError::StepTooLarge {
        step,
        limit,
        culprit,
    } = e
    else {
        return None;
    };
    Some(
        scenario::Diagnostic::new(
            file,
            source,
            loaded.time_step_span.clone(),
            "simulation.time_step",
            format!("time_step = {step} s is above the stability limit {limit:.4e} s"),
        )
        .expected(format!("s, ≤ {limit:.4e} (set by {culprit})"))
        .hint("use time_step = \"auto\", a smaller step, or fewer elements"),
    )
}
