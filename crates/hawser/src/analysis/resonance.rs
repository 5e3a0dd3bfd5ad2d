//! Resonance report: the excitation frequencies a scenario contains against the natural
//! frequencies of its linearisation (the elastic-link paper's call to keep excitation away
//! from the resonant modes of stretching).
//!
//! Excitations today come from prescribed point motions (a sinusoid per axis, a circular
//! orbit); regular waves and the spectral peak of irregular seas join when waves exist. An
//! excitation at f_e warns when a natural frequency f_n lies within the margin,
//! |f_e − f_n| ≤ margin · f_n. Only the computed modes are compared: an excitation above
//! (1 − margin) of the highest computed frequency is flagged as not covered, since a mode
//! that was not computed could be near it.

use super::modes::Modes;
use crate::math::Real;
use crate::system::System;

/// A periodic excitation of the scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Excitation {
    /// Where it comes from, e.g. "point fairlead1: sinusoid x".
    pub source: String,
    /// Frequency [Hz].
    pub frequency: Real,
}

/// The excitations of the system's prescribed points, in point order.
pub fn excitations(system: &System) -> Vec<Excitation> {
    let mut out = Vec::new();
    for p in &system.points {
        if let crate::model::PointKind::Prescribed(motion) = &p.kind {
            for (what, frequency) in motion.excitation_frequencies() {
                out.push(Excitation {
                    source: format!("point {}: {what}", p.name),
                    frequency,
                });
            }
        }
    }
    out
}

/// One excitation against the natural frequencies.
#[derive(Clone, Debug, PartialEq)]
pub struct ResonanceCheck {
    /// The excitation.
    pub excitation: Excitation,
    /// Index (into [`Modes::modes`]) of the nearest natural frequency.
    pub nearest_mode: usize,
    /// Its frequency [Hz].
    pub natural_frequency: Real,
    /// (f_e − f_n)/f_n [-].
    pub relative_distance: Real,
    /// Indices of every mode within the margin.
    pub within_margin: Vec<usize>,
    /// Whether the computed modes reach far enough above f_e to be sure of the check.
    pub covered: bool,
}

impl ResonanceCheck {
    /// A natural frequency lies within the margin.
    pub fn warning(&self) -> bool {
        !self.within_margin.is_empty()
    }
}

/// Compares each excitation with the natural frequencies; `margin` is relative (0.1 = 10 %).
pub fn resonance_report(
    excitations: &[Excitation],
    modes: &Modes,
    margin: Real,
) -> Vec<ResonanceCheck> {
    let highest = modes.modes.iter().map(|m| m.frequency).fold(0.0, Real::max);
    excitations
        .iter()
        .filter_map(|e| {
            let (nearest, mode) = modes.modes.iter().enumerate().min_by(|a, b| {
                (a.1.frequency - e.frequency)
                    .abs()
                    .total_cmp(&(b.1.frequency - e.frequency).abs())
            })?;
            let within_margin = modes
                .modes
                .iter()
                .enumerate()
                .filter(|(_, m)| (e.frequency - m.frequency).abs() <= margin * m.frequency)
                .map(|(i, _)| i)
                .collect();
            Some(ResonanceCheck {
                excitation: e.clone(),
                nearest_mode: nearest,
                natural_frequency: mode.frequency,
                relative_distance: (e.frequency - mode.frequency) / mode.frequency,
                within_margin,
                covered: e.frequency <= (1.0 - margin) * highest,
            })
        })
        .collect()
}
