//! MoorDyn v2 input decks: read them, convert them into hawser scenarios, and run them with
//! MoorDyn's physics.
//!
//! A deck is lexed into sections ([`deck`]), converted into the same [`Scenario`] types a TOML
//! file deserialises into ([`convert`]), and validated by the same code
//! ([`crate::scenario::build::build_scenario`]). The converted values keep the byte spans of
//! the deck words they came from, so every error, from the reader or from validation, points
//! at the deck's line and column and names MoorDyn's section and column. `hawser convert`
//! serialises the converted scenario as TOML: the run of a deck and the run of its conversion
//! are the same by construction. docs/moordyn.md lists every convention converted.

pub mod convert;
pub mod deck;
pub mod host_coupling;

pub use convert::{Conversion, ConvertOptions, Note};
pub use deck::looks_like_deck;
pub use host_coupling::couple_deck_points;

use crate::scenario::schema::Scenario;
use crate::scenario::{LoadedScenario, ScenarioError};
use std::path::Path;

/// A deck read, converted and validated.
#[derive(Debug)]
pub struct LoadedDeck {
    /// The validated model, as from a TOML scenario.
    pub loaded: LoadedScenario,
    /// The equivalent hawser scenario (for `hawser convert`).
    pub scenario: Scenario,
    /// Conversions made and deck entries without effect, to tell the user.
    pub notes: Vec<Note>,
}

/// Reads, converts and validates a MoorDyn deck (`source` is the text of `file`).
pub fn parse(
    file: &Path,
    source: &str,
    options: &ConvertOptions,
) -> Result<LoadedDeck, ScenarioError> {
    let deck = deck::lex(file, source).map_err(|d| ScenarioError::from(*d))?;
    let conversion = convert::convert(file, source, &deck, options)?;
    let mut loaded = crate::scenario::build::build_scenario(file, source, &conversion.scenario)
        .map_err(|e| conversion.in_deck_words(e))?;
    loaded.format = crate::scenario::InputFormat::MoorDyn;
    Ok(LoadedDeck {
        loaded,
        scenario: conversion.scenario,
        notes: conversion.notes,
    })
}

/// The scenario as TOML text, headed by comments that give its origin and the conversion
/// notes. It always reads back (a test checks it over decks of arbitrary text): deck words
/// quoted in the comments have their control characters escaped, which TOML comments cannot
/// hold, and names in the scenario are TOML strings.
pub fn to_toml(deck: &LoadedDeck, origin: &Path) -> String {
    let mut out = format!(
        "# hawser scenario converted from the MoorDyn deck {}\n# by hawser {}; docs/moordyn.md lists the conventions converted.\n",
        comment_text(&origin.display().to_string()),
        env!("CARGO_PKG_VERSION")
    );
    for n in &deck.notes {
        if n.line > 0 {
            out += &format!("# deck line {}: {}\n", n.line, comment_text(&n.message));
        } else {
            out += &format!("# {}\n", comment_text(&n.message));
        }
    }
    out += "\n";
    out += &toml::to_string_pretty(&deck.scenario).expect("a scenario serialises");
    out
}

/// Reads a deck file.
pub fn load(path: &Path, options: &ConvertOptions) -> Result<LoadedDeck, ScenarioError> {
    let source = crate::scenario::read_file(path, "deck")?;
    parse(path, &source, options)
}

/// `text` as the body of a TOML comment: control characters (which a comment cannot hold, a
/// line break least of all) written as Rust escapes, `\u{7}`; the rest unchanged.
fn comment_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c.is_control() && c != '\t' {
            true => out.extend(c.escape_unicode()),
            false => out.push(c),
        }
    }
    out
}
