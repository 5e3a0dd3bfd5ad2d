//! The input façade: one entry point for every input file, above both readers. A hawser
//! scenario (TOML, [`crate::scenario`]) and a MoorDyn v2 deck ([`crate::moordyn`]) are told
//! apart by their content; the deck reader builds on the scenario types, never the other way.

use crate::moordyn::{self, ConvertOptions, Note};
use crate::scenario::{self, LoadedScenario, ScenarioError};
use std::path::Path;

/// Reads and validates an input file: a hawser scenario (TOML) or a MoorDyn v2 deck,
/// recognised by its content (dashed MoorDyn section headers), not by its extension. `deck`
/// holds the choices a deck leaves to its host (duration, vessel motion); the notes say what
/// was converted or has no effect (empty for TOML).
pub fn load_input(
    path: &Path,
    deck: &ConvertOptions,
) -> Result<(LoadedScenario, Vec<Note>), ScenarioError> {
    let source = scenario::read_source(path)?;
    if moordyn::looks_like_deck(&source) {
        let d = moordyn::parse(path, &source, deck)?;
        Ok((d.loaded, d.notes))
    } else {
        Ok((scenario::parse(path, &source)?, Vec::new()))
    }
}
