//! Resonance report: the excitation frequencies a scenario contains against the natural
//! frequencies of its linearisation (the elastic-link paper's call to keep excitation away
//! from the resonant modes of stretching).
//!
//! Excitations come from prescribed point motions (a sinusoid per axis, a circular orbit) and
//! from the sea: a regular wave's frequency, an irregular sea's spectral peak, a recorded
//! sea's most energetic component. An excitation at f_e warns when a natural frequency f_n
//! lies within the margin, |f_e − f_n| ≤ margin · f_n. Only the computed modes are compared:
//! an excitation above (1 − margin) of the highest computed frequency is flagged as not
//! covered, since a mode that was not computed could be near it.
//!
//! The sea also excites every mode inside its band: [`wave_band`] finds the frequencies that
//! hold the central 90 % of the wave energy (5 % of the variance below the band, 5 % above:
//! the spectrum's cumulative moment m₀(f) for a JONSWAP or Pierson–Moskowitz sea, the
//! components' ½ a² for a record, the one frequency of a regular wave), and
//! [`spectrum_report`] lists the modes inside it.

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

/// The excitations of the system's prescribed points, in point order, then the sea's: a
/// regular wave's frequency, an irregular sea's spectral peak 1/Tp, or a record's most
/// energetic component.
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
    if let Some(band) = wave_band(&system.environment.waves, 0.9) {
        out.push(Excitation {
            source: format!("waves: {}", band.peak_source),
            frequency: band.peak,
        });
    }
    out
}

/// The band of frequencies that holds a fraction of the wave energy.
#[derive(Clone, Debug, PartialEq)]
pub struct WaveBand {
    /// Lower end f_lo [Hz]: (1 − fraction)/2 of the variance lies below it.
    pub low: Real,
    /// Upper end f_hi [Hz]: (1 − fraction)/2 of the variance lies above it.
    pub high: Real,
    /// The fraction of the variance between them [-].
    pub fraction: Real,
    /// The sea's most energetic frequency [Hz]: a regular wave's, the spectral peak 1/Tp, a
    /// record's largest component.
    pub peak: Real,
    /// What the peak is, in words ("spectral peak Tp = 10 s").
    pub peak_source: String,
}

/// The central band holding `fraction` (0 < fraction < 1) of the variance of the sea `waves`,
/// `None` for a calm sea. For a spectrum, the cumulative moment m₀(ω) = ∫₀^ω S dω' on a grid of
/// 20 000 intervals up to 20 ωp (the tail above it holds ≈ (ωp/20ωp)⁴ ≈ 6e-6 of m₀ for a
/// Pierson–Moskowitz sea, less for JONSWAP), interpolated linearly; for given components,
/// their ½ a² sorted by frequency, the band's ends at the components that cross the quantiles.
pub fn wave_band(waves: &crate::physics::waves::Waves, fraction: Real) -> Option<WaveBand> {
    use crate::physics::waves::SeaState;
    use std::f64::consts::TAU;
    let field = waves.field()?;
    let tail = 0.5 * (1.0 - fraction);
    match &field.spec().sea {
        SeaState::Regular(w) => Some(WaveBand {
            low: 1.0 / w.period,
            high: 1.0 / w.period,
            fraction,
            peak: 1.0 / w.period,
            peak_source: format!("regular wave, T = {} s", w.period),
        }),
        SeaState::Irregular(sea) => {
            let s = sea.spectrum.density_function();
            let wp = sea.spectrum.peak_frequency();
            let (n, top) = (20_000, 20.0 * wp);
            let h = top / n as Real;
            let mut cumulative = vec![0.0; n + 1];
            for i in 1..=n {
                let (a, b) = ((i - 1) as Real * h, i as Real * h);
                cumulative[i] = cumulative[i - 1] + 0.5 * h * (s(a) + s(b));
            }
            let total = cumulative[n];
            let quantile = |q: Real| {
                let target = q * total;
                let i = cumulative.partition_point(|c| *c < target).clamp(1, n);
                let (c0, c1) = (cumulative[i - 1], cumulative[i]);
                let x = if c1 > c0 {
                    (target - c0) / (c1 - c0)
                } else {
                    0.0
                };
                ((i - 1) as Real + x) * h / TAU
            };
            Some(WaveBand {
                low: quantile(tail),
                high: quantile(1.0 - tail),
                fraction,
                peak: wp / TAU,
                peak_source: format!("spectral peak, Tp = {} s", sea.spectrum.peak_period()),
            })
        }
        SeaState::Components(_) => {
            let mut energy: Vec<(Real, Real)> = field
                .components()
                .iter()
                .map(|c| {
                    (
                        c.angular_frequency() / TAU,
                        0.5 * c.amplitude() * c.amplitude(),
                    )
                })
                .collect();
            energy.sort_by(|a, b| a.0.total_cmp(&b.0));
            let total: Real = energy.iter().map(|e| e.1).sum();
            if !(total > 0.0) {
                return None;
            }
            let quantile = |q: Real| {
                let mut sum = 0.0;
                for &(f, e) in &energy {
                    sum += e;
                    if sum >= q * total {
                        return f;
                    }
                }
                energy.last().map_or(0.0, |e| e.0)
            };
            let peak = energy
                .iter()
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map_or(0.0, |e| e.0);
            Some(WaveBand {
                low: quantile(tail),
                high: quantile(1.0 - tail),
                fraction,
                peak,
                peak_source: format!("largest component of the record, {peak:.4} Hz"),
            })
        }
    }
}

/// The modes inside the sea's band.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectrumCheck {
    /// The band.
    pub band: WaveBand,
    /// Indices (into [`Modes::modes`]) of the modes with f_lo ≤ f_n ≤ f_hi.
    pub inside: Vec<usize>,
    /// Whether the computed modes reach above the band (a mode not computed cannot be in it).
    pub covered: bool,
}

impl SpectrumCheck {
    /// A natural frequency lies inside the band.
    pub fn warning(&self) -> bool {
        !self.inside.is_empty()
    }
}

/// The modes inside `band`.
pub fn spectrum_report(band: &WaveBand, modes: &Modes) -> SpectrumCheck {
    let highest = modes.modes.iter().map(|m| m.frequency).fold(0.0, Real::max);
    SpectrumCheck {
        band: band.clone(),
        inside: modes
            .modes
            .iter()
            .enumerate()
            .filter(|(_, m)| m.frequency >= band.low && m.frequency <= band.high)
            .map(|(i, _)| i)
            .collect(),
        covered: highest >= band.high,
    }
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
