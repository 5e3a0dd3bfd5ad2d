//! Validation against the DG paper's physical cases: the runs and the analysis of
//! their time series, formulation-neutral and without I/O. The models come from the scenario
//! files under `examples/` (read by `hawser-io`); the report is written by
//! `hawser-io`'s `dg_report` example into `docs/verification/dg.md`.
//!
//! - [`swinging_cable`]: Koh et al.'s swinging rubber cable (DG paper §5), a release test: the
//!   static sag between two pins, one pin pulled at t = 0; tension at the other pin and its
//!   spectrum.
//! - [`tether`]: the ROPOS deep-water tether (DG paper §6): a cage hanging on a 200–1730 m
//!   tether from a ship whose fairlead orbits; slack, snap at the cage and its arrival at the
//!   ship.
//! - [`signal`]: amplitude spectra, level crossings and peaks of sampled signals.

pub mod signal;
pub mod swinging_cable;
pub mod tether;

use crate::error::{ModelError, SimulationError, StaticsError};

/// Why a validation run failed.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The model was refused.
    #[error("model refused: {0}")]
    Model(#[from] ModelError),
    /// No static equilibrium to start from.
    #[error("statics failed: {0}")]
    Statics(#[from] StaticsError),
    /// The time integration stopped.
    #[error("simulation failed: {0}")]
    Simulation(#[from] SimulationError),
}
