//! hawser I/O: the input façade ([`input::load_input`], a scenario or a MoorDyn deck); scenario
//! files (TOML) with validation that names file, line, key, value, unit and a hint; the JSON
//! Schema of the format; MoorDyn v2 decks; the result writers (CSV time series, shape
//! snapshots, summary with design statistics and line strength, range graphs and final state
//! as JSON) and the reader of a run's files; with the `plot` feature, the figures and HTML
//! report of a run (`hawser plot`); the verification report (markdown table and SVG plots).
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN, which `x <= 0.0` would let through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod fuzzing;
pub mod input;
pub mod modes;
pub mod moordyn;
#[cfg(feature = "plot")]
pub mod plot;
pub mod results;
pub mod run_files;
pub mod scenario;
pub mod sweep;
pub mod verification_report;
