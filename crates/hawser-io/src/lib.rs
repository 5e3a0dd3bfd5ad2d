//! hawser I/O: the input façade ([`input::load_input`], a scenario or a MoorDyn deck); scenario
//! files (TOML) with validation that names file, line, key, value, unit and a hint; the JSON
//! Schema of the format; MoorDyn v2 decks; the result writers (CSV time series, shape
//! snapshots, summary and final state as JSON); the verification report (markdown table and SVG
//! plots).
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN, which `x <= 0.0` would let through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod fuzzing;
pub mod input;
pub mod modes;
pub mod moordyn;
pub mod results;
pub mod scenario;
pub mod verification_report;
