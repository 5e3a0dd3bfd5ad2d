//! The input façade: one entry point for every input file, above both readers. A hawser
//! scenario (TOML, [`crate::scenario`]) and a MoorDyn v2 deck ([`crate::moordyn`]) are told
//! apart by their content; the deck reader builds on the scenario types, never the other way.

use crate::moordyn::{self, ConvertOptions, Note};
use crate::scenario::{self, Diagnostic, LoadedScenario, ScenarioError};
use std::path::Path;

/// Reads and validates an input file: a hawser scenario (TOML) or a MoorDyn v2 deck,
/// recognised by its content (dashed MoorDyn section headers), not by its extension. `deck`
/// holds the choices a deck leaves to its host (duration, vessel motion); the notes say what
/// was converted or has no effect.
///
/// A scenario takes `deck.duration` in place of its `simulation.duration` (with a note), and
/// refuses `deck.vessel_motion`: a scenario names its vessel motions itself, on its points
/// and bodies, so a file given on the command line would have nothing to move.
pub fn load_input(
    path: &Path,
    deck: &ConvertOptions,
) -> Result<(LoadedScenario, Vec<Note>), ScenarioError> {
    let source = scenario::read_source(path)?;
    if moordyn::looks_like_deck(&source) {
        let d = moordyn::parse(path, &source, deck)?;
        Ok((d.loaded, d.notes))
    } else {
        if let Some(file) = &deck.vessel_motion {
            return Err(Diagnostic::new(
                path,
                &source,
                None,
                "--vessel-motion",
                format!(
                    "--vessel-motion {} applies to MoorDyn decks, whose coupled points a host \
                     moves; a hawser scenario names the motion of each point and body itself",
                    file.display()
                ),
            )
            .hint(
                "give the moving points or bodies `motion = { type = \"vessel-motion\", file = \
                 \"FILE\" }` (docs/motions.md; FILE relative to the scenario), and drop \
                 --vessel-motion",
            )
            .into());
        }
        let loaded = scenario::build::build_with_duration(path, &source, deck.duration).map_err(
            |mut e| {
                // The duration was the command line's: say so, with its value.
                for d in &mut e.diagnostics {
                    if let Some(dur) = deck.duration
                        && d.key == "simulation.duration"
                        && d.span == Some(0..0)
                    {
                        *d = Diagnostic::new(path, "", None, "--duration", d.message.clone())
                            .value(dur.to_string())
                            .expected(d.expected.clone())
                            .hint(d.hint.clone());
                    }
                }
                e
            },
        )?;
        let notes = match deck.duration {
            Some(d) if loaded.has_simulation => vec![Note {
                line: 0,
                message: format!("--duration {d} s replaces the scenario's simulation.duration"),
            }],
            Some(_) => vec![Note {
                line: 0,
                message: "--duration has no effect: the scenario has no [simulation] table"
                    .to_string(),
            }],
            None => Vec::new(),
        };
        Ok((loaded, notes))
    }
}
