//! hawser I/O: scenario files (TOML) with validation that names file, line, key, value, unit
//! and a hint; the JSON Schema of the format; and the result writers (CSV time series, shape
//! snapshots, summary and final state as JSON).
#![warn(missing_docs)]

pub mod results;
pub mod scenario;
