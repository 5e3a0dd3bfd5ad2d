//! The modal analysis of `hawser modes` and of the Python package's `Scenario.modes()`: the
//! static equilibrium, the linearisation about it, the natural modes, the stiffness the lines
//! offer their fixed and prescribed points and every body, and the resonance report (with the
//! modes inside the sea's band); as data and as the JSON document `modes.json` holds.

use hawser::analysis::modes::{EigenMethod, ModalOptions, ModeOwner, Modes, natural_modes};
use hawser::analysis::resonance::{
    ResonanceCheck, SpectrumCheck, excitations, resonance_report, spectrum_report, wave_band,
};
use hawser::linearise::{BodyStiffness, ConnectionStiffness, Linearisation, LinearisationOptions};
use hawser::math::{Real, Vec3};
use hawser::model::{BodyKind, Model, PointKind};
use hawser::statics::{StaticOptions, StaticSolution};
use hawser::system::System;
use serde_json::{Value, json};
use std::time::Instant;

/// Wall times [s] of the stages of a [`ModalAnalysis`].
#[derive(Clone, Copy, Debug, Default)]
pub struct ModalTiming {
    /// The static equilibrium.
    pub statics: f64,
    /// The linearisation.
    pub linearisation: f64,
    /// The eigenvalue problem.
    pub modes: f64,
    /// The connection stiffness.
    pub stiffness: f64,
}

/// Everything `hawser modes` reports.
pub struct ModalAnalysis {
    /// The static equilibrium the system is linearised about.
    pub statics: StaticSolution,
    /// Stiffness, damping and mass about it.
    pub linearisation: Linearisation,
    /// The lowest natural modes.
    pub modes: Modes,
    /// The stiffness at the fixed and prescribed points, free points and nodes relaxed.
    pub stiffness: ConnectionStiffness,
    /// The 6×6 mooring stiffness of every body with lines, everything else relaxed.
    pub body_stiffness: Vec<BodyStiffness>,
    /// The scenario's periodic excitations against the natural frequencies.
    pub resonance: Vec<ResonanceCheck>,
    /// The modes inside the band holding 90 % of the wave energy (`None` in calm water).
    pub spectrum: Option<SpectrumCheck>,
    /// Resonance warning margin [-] (a fraction of the natural frequency).
    pub margin: Real,
    /// Wall times of the stages.
    pub timing: ModalTiming,
}

/// Static positions and scaled mode shapes of every node and free point
/// ([`ModalAnalysis::shapes`]).
pub struct ModeShapes {
    /// Per line, the static position [m] of each node (end A to end B).
    pub line_positions: Vec<Vec<Vec3>>,
    /// Per mode, per line, the displacement [-] of each node, scaled so that the largest
    /// nodal displacement of the mode over the whole system is 1.
    pub line_displacements: Vec<Vec<Vec<Vec3>>>,
    /// The free points (indices into the model's points).
    pub points: Vec<usize>,
    /// Static position [m] of each free point.
    pub point_positions: Vec<Vec3>,
    /// Per mode, the displacement [-] of each free point, scaled as the lines'.
    pub point_displacements: Vec<Vec<Vec3>>,
    /// The free bodies (indices into the model's bodies).
    pub bodies: Vec<usize>,
    /// Static position [m] of each free body's origin.
    pub body_positions: Vec<Vec3>,
    /// Per mode, each free body's origin displacement [-] (scaled as the lines') and small
    /// rotation about the global axes [rad per the scale's metre].
    pub body_motions: Vec<Vec<(Vec3, Vec3)>>,
}

/// The model whose modes `hawser modes` computes for `model`: `model` itself, or, when it has
/// `dg` lines, its hermite twin ([`hawser::analysis::modes::modal_twin`]), with a note per
/// replaced line saying so.
pub fn modal_model(model: &Model) -> (std::borrow::Cow<'_, Model>, Vec<String>) {
    match hawser::analysis::modes::modal_twin(model) {
        None => (std::borrow::Cow::Borrowed(model), Vec::new()),
        Some(twin) => {
            let notes = model
                .lines
                .iter()
                .zip(&twin.lines)
                .filter(|(l, t)| l.formulation != t.formulation)
                .map(|(l, t)| {
                    format!(
                        "line {} (dg, {} elements) is linearised through its hermite twin ({} \
                         cubic elements over the same sections; docs/modes.md)",
                        l.name,
                        l.elements(),
                        t.elements()
                    )
                })
                .collect();
            (std::borrow::Cow::Owned(twin), notes)
        }
    }
}

/// The fraction of the wave variance inside the band the resonance report checks [-].
pub const WAVE_ENERGY_FRACTION: Real = 0.9;

impl ModalAnalysis {
    /// Solves the statics of `system`, linearises about them, finds the lowest `count`
    /// modes, the connection stiffness and the resonance report with `margin` (a fraction).
    /// The error is the message `hawser modes` prints.
    pub fn compute(system: &System, count: usize, margin: Real) -> Result<Self, String> {
        if !(0.0..1.0).contains(&margin) || count == 0 {
            return Err(format!(
                "the resonance margin must be in [0, 100) % and the mode count at least 1 (got \
                 {} %, {count})",
                100.0 * margin
            ));
        }
        hawser::analysis::modes::supported(system).map_err(|e| e.to_string())?;
        let t = Instant::now();
        let statics = hawser::statics::solve(system, None, &StaticOptions::default())
            .map_err(|e| e.to_string())?;
        let statics_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let linearisation =
            hawser::linearise::linearise(system, &statics.state, LinearisationOptions::default());
        let linearisation_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let options = ModalOptions {
            count,
            ..Default::default()
        };
        let modes = natural_modes(system, &linearisation, &options).map_err(|e| e.to_string())?;
        let modes_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let singular = |s| {
            format!(
                "the stiffness is singular at {}: a line or joint there has no stiffness (slack, \
                 or an unloaded free point); check the static state",
                system.singular_location(s)
            )
        };
        let stiffness =
            hawser::linearise::connection_stiffness(system, &linearisation).map_err(singular)?;
        let body_stiffness =
            hawser::linearise::body_stiffness(system, &linearisation).map_err(singular)?;
        let timing = ModalTiming {
            statics: statics_time,
            linearisation: linearisation_time,
            modes: modes_time,
            stiffness: t.elapsed().as_secs_f64(),
        };
        let resonance = resonance_report(&excitations(system), &modes, margin);
        let spectrum = wave_band(&system.environment.waves, WAVE_ENERGY_FRACTION)
            .map(|band| spectrum_report(&band, &modes));
        Ok(Self {
            statics,
            linearisation,
            modes,
            stiffness,
            body_stiffness,
            resonance,
            spectrum,
            margin,
            timing,
        })
    }

    /// How the eigenvalues were found, in words.
    pub fn method_name(&self) -> String {
        let modes = &self.modes;
        match modes.method {
            EigenMethod::Dense => match &modes.fallback {
                Some(why) => format!("dense ({why})"),
                None => "dense".to_string(),
            },
            _ => format!(
                "shift-invert subspace iteration, {} iterations, shift {:.3e} rad²/s²",
                modes.iterations, modes.shift
            ),
        }
    }

    /// The static positions and the mode shapes, scaled to a largest displacement of 1.
    pub fn shapes(&self, system: &System) -> ModeShapes {
        let (lin, modes) = (&self.linearisation, &self.modes.modes);
        let mut ws = system.workspace();
        system.point_kinematics(0.0, &lin.state, &mut ws);
        system.gather_lines(&lin.state, &mut ws);
        let scale: Vec<Real> = modes
            .iter()
            .map(|m| 1.0 / m.largest_displacement(&lin.dofs).max(Real::MIN_POSITIVE))
            .collect();
        let line_positions = system
            .lines
            .iter()
            .enumerate()
            .map(|(li, l)| {
                (0..l.nodes())
                    .map(|n| ws.lines[li].position[l.node_vector(n)])
                    .collect()
            })
            .collect();
        let line_displacements = modes
            .iter()
            .zip(&scale)
            .map(|(m, s)| {
                (0..system.lines.len())
                    .map(|li| {
                        (0..system.lines[li].nodes())
                            .map(|n| m.node_displacement(&lin.dofs, li, n) * *s)
                            .collect()
                    })
                    .collect()
            })
            .collect();
        let points = system.free_points.clone();
        let bodies = system.free_bodies.clone();
        ModeShapes {
            body_positions: bodies.iter().map(|&b| ws.bodies[b].position).collect(),
            body_motions: modes
                .iter()
                .zip(&scale)
                .map(|(m, s)| {
                    bodies
                        .iter()
                        .map(|&b| {
                            let (u, th) = m.body_motion(&lin.dofs, b).unwrap_or_default();
                            (u * *s, th * *s)
                        })
                        .collect()
                })
                .collect(),
            bodies,
            point_positions: points.iter().map(|&p| ws.points[p].position).collect(),
            point_displacements: modes
                .iter()
                .zip(&scale)
                .map(|(m, s)| {
                    points
                        .iter()
                        .map(|&p| m.point_displacement(&lin.dofs, p) * *s)
                        .collect()
                })
                .collect(),
            points,
            line_positions,
            line_displacements,
        }
    }

    /// The document `hawser modes --json` prints and `modes.json` holds.
    pub fn to_json(&self, system: &System) -> Value {
        let (sol, lin, modes) = (&self.statics, &self.linearisation, &self.modes);
        let owner_name = |o: &ModeOwner| match *o {
            ModeOwner::Line(l) => system.lines[l].name.clone(),
            ModeOwner::Point(p) => system.points[p].name.clone(),
            ModeOwner::Body(b) => system.bodies[b].body.name.clone(),
        };
        let mode_list: Vec<Value> = modes
            .modes
            .iter()
            .enumerate()
            .map(|(i, m)| {
                let lines: serde_json::Map<String, Value> = system
                    .lines
                    .iter()
                    .zip(&m.line_shares)
                    .map(|(l, s)| (l.name.clone(), json!(s)))
                    .collect();
                let points: serde_json::Map<String, Value> = system
                    .free_points
                    .iter()
                    .map(|&p| (system.points[p].name.clone(), json!(m.point_shares[p])))
                    .collect();
                let bodies: serde_json::Map<String, Value> = system
                    .free_bodies
                    .iter()
                    .map(|&b| (system.bodies[b].body.name.clone(), json!(m.body_shares[b])))
                    .collect();
                let directions: serde_json::Map<String, Value> = m
                    .direction_shares
                    .iter()
                    .map(|(d, s)| (d.name().to_string(), json!(s)))
                    .collect();
                json!({
                    "mode": i + 1,
                    "frequency_hz": m.frequency,
                    "period_s": m.period,
                    "eigenvalue_rad2_per_s2": m.eigenvalue,
                    "label": m.label.text,
                    "direction": m.label.direction.name(),
                    "owners": m.label.owners.iter().map(owner_name).collect::<Vec<_>>(),
                    "kinetic_energy_share": {"lines": lines, "points": points, "bodies": bodies, "directions": directions},
                })
            })
            .collect();
        let stiff: serde_json::Map<String, Value> = self
            .stiffness
            .points
            .iter()
            .enumerate()
            .map(|(i, &p)| {
                let k = self.stiffness.block(i, i);
                let rows: Vec<Vec<Real>> = (0..3)
                    .map(|r| (0..3).map(|c| k[(r, c)]).collect())
                    .collect();
                (
                    system.points[p].name.clone(),
                    json!({"kind": point_kind(system, p), "matrix_n_per_m": rows}),
                )
            })
            .collect();
        let body_stiffness: serde_json::Map<String, Value> = self
            .body_stiffness
            .iter()
            .map(|b| {
                let rows: Vec<Vec<Real>> = (0..6)
                    .map(|r| (0..6).map(|c| b.matrix[(r, c)]).collect())
                    .collect();
                (
                    system.bodies[b.body].body.name.clone(),
                    json!({"kind": body_kind(system, b.body), "matrix_6x6": rows}),
                )
            })
            .collect();
        let spectrum = self.spectrum.as_ref().map(|c| {
            json!({
                "energy_fraction": c.band.fraction,
                "low_hz": c.band.low,
                "high_hz": c.band.high,
                "peak_hz": c.band.peak,
                "modes_inside": c.inside.iter().map(|i| i + 1).collect::<Vec<_>>(),
                "warning": c.warning(),
                "covered": c.covered,
            })
        });
        let checks: Vec<Value> = self
            .resonance
            .iter()
            .map(|r| {
                json!({
                    "source": r.excitation.source,
                    "frequency_hz": r.excitation.frequency,
                    "nearest_mode": r.nearest_mode + 1,
                    "natural_frequency_hz": r.natural_frequency,
                    "relative_distance": r.relative_distance,
                    "modes_within_margin": r.within_margin.iter().map(|i| i + 1).collect::<Vec<_>>(),
                    "warning": r.warning(),
                    "covered": r.covered,
                })
            })
            .collect();
        let timing = &self.timing;
        json!({
            "statics": {"method": sol.method, "fallback": sol.fallback, "iterations": sol.iterations, "residual_n": sol.residual},
            "degrees_of_freedom": lin.dofs.len(),
            "method": self.method_name(),
            "stiffness_asymmetry": modes.stiffness_asymmetry,
            "modes": mode_list,
            "stiffness": stiff,
            "body_stiffness": body_stiffness,
            "resonance": {"margin": self.margin, "checks": checks, "wave_band": spectrum},
            "timing_s": {
                "statics": timing.statics,
                "linearisation": timing.linearisation,
                "modes": timing.modes,
                "stiffness": timing.stiffness,
            },
        })
    }
}

/// What body `b` is, in words: free, prescribed, coupled or pinned.
pub fn body_kind(system: &System, b: usize) -> &'static str {
    match system.bodies[b].body.kind {
        BodyKind::Free => "free",
        BodyKind::Prescribed(_) => "prescribed",
        BodyKind::Coupled => "coupled",
        BodyKind::Pinned(_) => "pinned",
    }
}

/// What point `p` is, in words: fixed, prescribed, coupled, free or on a body.
pub fn point_kind(system: &System, p: usize) -> &'static str {
    match system.points[p].kind {
        PointKind::Fixed => "fixed",
        PointKind::Prescribed(_) => "prescribed",
        PointKind::Coupled => "coupled",
        PointKind::Free { .. } => "free",
        PointKind::Body { .. } => "on a body",
    }
}
