//! A steady towed cable against an independent integration of the steady cable equations
//! (issue 4 item 3).
//!
//! The place for it: the steady-towing solver and its reference (`hawser::analysis::
//! steady_cable`) are being written separately; when they land, this case builds a towed
//! line, solves it with hawser's statics under current and compares its depth, layback and
//! end tensions with that integration.

use super::*;

/// Steady towed cable: not available until `hawser::analysis::steady_cable` exists.
pub fn steady_towed_cable(_f: Formulation, _fidelity: Fidelity) -> Result<Findings, CaseError> {
    Err(CaseError::NotAvailable(
        "the steady-cable reference (hawser::analysis::steady_cable) is not on main yet".into(),
    ))
}
