//! The ROPOS deep-water tether (DG paper §6, Table 3; SPEC §7): a cage hangs from a ship on a
//! 200–1730 m tether; the fairlead orbits in the vertical plane; at 0.2 and 0.25 Hz the lower
//! tether goes slack and snaps taut, and the snap runs up the tether to the ship at the axial
//! wave speed c = √(EA/γ0).
//!
//! [`run_tether`] integrates a model whose line 0 runs from the ship (end A) to the cage
//! (end B), recording both end tensions and the smallest element strain along the line;
//! [`summarise`] finds the slack, the first snap at the cage and its arrival at the ship.

use super::RunError;
use super::signal::{peak, upward_crossing, value_at};
use crate::analysis::Channel;
use crate::math::{Real, Vec3};
use crate::model::{LineEnd, Model, Motion, PointKind};
use crate::session::{Observer, ObserverError, Session, View};

/// Tether lengths L of the DG paper's study [m] (eq. 47).
pub const LENGTHS: [Real; 4] = [200.0, 500.0, 975.0, 1730.0];
/// Bending stiffness factors α, EI = α EI* (eq. 48).
pub const ALPHAS: [Real; 4] = [0.0, 1.0, 10.0, 100.0];
/// Orbit frequencies f of the fairlead [Hz] (§6.2).
pub const FREQUENCIES: [Real; 3] = [0.10, 0.20, 0.25];
/// EI* = 2.62 kN·m², the field-tested tether's bending stiffness [N·m²] (§6.2).
pub const EI_STAR: Real = 2.62e3;
/// Periods of fairlead motion over which the orbit is built up (the motion's `ramp_time`).
pub const RAMP_PERIODS: Real = 2.0;

/// Axial wave speed c = √(EA/γ0) of line 0's first section [m/s] (EA the largest tangent
/// stiffness of its law).
pub fn wave_speed(model: &Model) -> Real {
    let t = &model.line_types[model.lines[0].sections[0].line_type];
    (t.axial_stiffness.max_tangent() / t.mass_per_length).sqrt()
}

/// One case of the study from `base` (`examples/ropos_tether.toml`: the ship is line 0's end
/// A, a prescribed circular orbit; the cage its end B): line 0 of unstretched `length` L [m]
/// (its sections scaled, element counts kept), its line types' EI = `alpha`·[`EI_STAR`], the
/// orbit at `frequency` f [Hz] built up over [`RAMP_PERIODS`] periods, the cage seeded L below
/// the ship, a run of [`RAMP_PERIODS`] + `periods` periods, and samples every τ/200 or finer
/// (τ = L/c, the snap's travel time: the largest of 1, 0.5, 0.2, 0.1 ms not above it), so that
/// the travel time is resolved to 0.5 % by the samples alone.
pub fn case(base: &Model, length: Real, alpha: Real, frequency: Real, periods: Real) -> Model {
    let mut m = base.clone();
    let old: Real = m.lines[0].sections.iter().map(|s| s.length).sum();
    for s in &mut m.lines[0].sections {
        s.length *= length / old;
    }
    for s in &m.lines[0].sections.clone() {
        m.line_types[s.line_type].bending_stiffness = alpha * EI_STAR;
    }
    if let (Some(ship), Some(cage)) = (point_of(&m.lines[0].end_a), point_of(&m.lines[0].end_b)) {
        if let PointKind::Prescribed(Motion::CircularOrbit {
            frequency: f, ramp, ..
        }) = &mut m.points[ship].kind
        {
            *f = frequency;
            *ramp = RAMP_PERIODS / frequency;
        }
        let top = m.points[ship].position;
        let target = top - Vec3::new(0.0, 0.0, length);
        match m.points[cage].kind {
            // The cage as a rigid body: the body moves so that its bridle point is L below
            // the ship (the body's orientation and the bridle offset kept).
            PointKind::Body { body, offset } => {
                let b = &mut m.bodies[body];
                let bridle = b.position + b.orientation * offset;
                b.position += target - bridle;
            }
            _ => m.points[cage].position = target,
        }
    }
    m.settings.duration = (RAMP_PERIODS + periods) / frequency;
    let tau = length / wave_speed(&m);
    m.settings.output_interval = [1e-3, 5e-4, 2e-4, 1e-4]
        .into_iter()
        .find(|&dt| dt <= tau / 200.0)
        .unwrap_or(1e-4);
    m
}

/// The point a line end is attached to, if it is a point.
#[allow(unreachable_patterns)]
fn point_of(end: &LineEnd) -> Option<usize> {
    match end {
        LineEnd::Point(p) => Some(*p),
        _ => None,
    }
}

/// The record of a tether run.
#[derive(Clone, Debug, Default)]
pub struct TetherRun {
    /// Sample times [s].
    pub time: Vec<Real>,
    /// Tension at the ship, line 0's end A ([`Channel::EndTension`]) [N].
    pub ship_tension: Vec<Real>,
    /// Tension at the cage, line 0's end B [N].
    pub cage_tension: Vec<Real>,
    /// Smallest element strain of line 0 ([`Channel::ElementStrain`]) [-]; ≤ 0 means slack.
    pub min_strain: Vec<Real>,
    /// Strain of the element at the cage, line 0's last [-].
    pub cage_strain: Vec<Real>,
    /// Strain of the element at the ship, line 0's first [-].
    pub ship_strain: Vec<Real>,
    /// Vertical position of the cage, line 0's end B [m].
    pub cage_z: Vec<Real>,
    /// Time step [s].
    pub step: Real,
    /// Steps taken.
    pub steps: u64,
    /// Wall-clock time of the integration (without the statics) [s].
    pub wall_seconds: Real,
}

struct Recorder {
    run: TetherRun,
    elements: usize,
}

impl Observer for Recorder {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        let r = &mut self.run;
        r.time.push(time);
        for (end_b, v) in [(false, &mut r.ship_tension), (true, &mut r.cage_tension)] {
            v.push(Channel::EndTension { line: 0, end_b }.value(system, ws));
        }
        let strain = |element| Channel::ElementStrain { line: 0, element }.value(system, ws);
        r.min_strain.push(
            (0..self.elements)
                .map(strain)
                .fold(Real::INFINITY, Real::min),
        );
        r.cage_strain.push(strain(self.elements - 1));
        r.ship_strain.push(strain(0));
        r.cage_z.push(
            Channel::NodePosition {
                line: 0,
                node: self.elements,
                axis: 2,
            }
            .value(system, ws),
        );
        Ok(())
    }
}

/// Runs `model` from its static equilibrium for `settings.duration`, sampling every
/// `settings.output_interval`.
pub fn run_tether(model: &Model) -> Result<TetherRun, RunError> {
    let mut session = Session::new(model.clone())?;
    let system = session.system();
    let recorder = Recorder {
        run: TetherRun::default(),
        elements: system.lines[0].mesh.elements(),
    };
    let id = session.attach(recorder);
    let start = std::time::Instant::now();
    session.run()?;
    let wall_seconds = start.elapsed().as_secs_f64();
    let (step, steps) = (session.step_size(), session.steps_done());
    let mut rec: Recorder = session.detach(id).expect("the recorder is attached");
    rec.run.wall_seconds = wall_seconds;
    rec.run.step = step;
    rec.run.steps = steps;
    Ok(rec.run)
}

/// A snap seen at one end of the tether.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Snap {
    /// When the tension has risen by half of the jump [s] (the middle of the front).
    pub time: Real,
    /// The tension just before the front [N].
    pub before: Real,
    /// The largest tension that follows [N].
    pub peak: Real,
    /// When the peak is reached [s].
    pub peak_time: Real,
}

impl Snap {
    /// The rise of the tension across the front, `peak − before` [N].
    pub fn jump(&self) -> Real {
        self.peak - self.before
    }
}

/// What a tether run shows.
#[derive(Clone, Debug, PartialEq)]
pub struct TetherSummary {
    /// Ship-end tension at t = 0, the static equilibrium [N].
    pub static_ship: Real,
    /// Cage-end tension at t = 0 [N].
    pub static_cage: Real,
    /// Smallest ship-end tension from `from` on [N].
    pub ship_min: Real,
    /// Largest ship-end tension from `from` on [N].
    pub ship_max: Real,
    /// Whether some element went slack (strain ≤ 0) at some sample.
    pub slack: bool,
    /// Time of the first slack sample [s].
    pub first_slack: Option<Real>,
    /// Time of the first sample with the element at the cage slack [s].
    pub first_cage_slack: Option<Real>,
    /// Whether the element at the ship went slack at some sample.
    pub ship_slack: bool,
    /// The first snap at the cage.
    pub cage_snap: Option<Snap>,
    /// That snap's arrival at the ship.
    pub ship_snap: Option<Snap>,
    /// Whether the element at the ship stayed taut from the cage snap to its arrival at the
    /// ship: the front then ran up a taut tether, at c = √(EA/γ0). Into a slack stretch a
    /// snap front runs slower, at c √(ε⁺/(ε⁺ − ε⁻)) between the strains ε⁺ > 0 behind it and
    /// ε⁻ < 0 ahead (the jump conditions of the bilinear law), so the travel time exceeds L/c.
    pub taut_path: bool,
}

impl TetherSummary {
    /// The static weight in water carried by the tether itself: ship-end minus cage-end
    /// tension at rest [N] (the DG paper's "tether self-weight in water", §6.1).
    pub fn tether_wet_weight(&self) -> Real {
        self.static_ship - self.static_cage
    }

    /// Time the first snap takes from the cage to the ship [s].
    pub fn travel_time(&self) -> Option<Real> {
        Some(self.ship_snap?.time - self.cage_snap?.time)
    }
}

/// Slack, the first snap and its arrival in `run`, for a tether of unstretched `length` [m]
/// with axial wave speed `wave_speed` [m/s] (τ = length / wave_speed); the ship tension's
/// extremes are taken from time `from` [s] on (after the build-up of the motion).
///
/// - Slack: the smallest element strain ≤ 0 at a sample.
/// - The first snap at the cage: at the first sample at which the element at the cage is taut
///   again after its first slack sample (`t_taut`; other parts of the tether may still be
///   slack: a short tether also slackens at the ship), with `before` the cage tension at the
///   element's last slack sample and `peak` the largest
///   cage tension in [t_taut, t_taut + τ] (before the front's reflection from the ship returns,
///   2τ after it left); its time is the upward crossing of (before + peak)/2 after the last
///   slack sample.
/// - Its arrival at the ship: within [t_c + τ/2, t_c + 3τ/2] of the cage snap time t_c, with
///   `before` the ship tension at t_c + τ/2 and `peak` the largest ship tension in the window;
///   its time is the upward crossing of (before + peak)/2.
///
/// A half-jump crossing marks the middle of a front; a front smeared symmetrically by damping
/// and discretisation keeps its middle where a sharp one would be.
pub fn summarise(run: &TetherRun, length: Real, wave_speed: Real, from: Real) -> TetherSummary {
    let tau = length / wave_speed;
    let (t, ship, cage) = (&run.time, &run.ship_tension, &run.cage_tension);
    let (mut ship_min, mut ship_max) = (Real::INFINITY, Real::NEG_INFINITY);
    for (&ti, &s) in t.iter().zip(ship) {
        if ti >= from {
            ship_min = ship_min.min(s);
            ship_max = ship_max.max(s);
        }
    }
    let first_slack = run.min_strain.iter().position(|&e| e <= 0.0);
    let first_cage_slack = run.cage_strain.iter().position(|&e| e <= 0.0);
    let taut_again =
        first_cage_slack.and_then(|i| (i..t.len()).find(|&j| run.cage_strain[j] > 0.0));
    let cage_snap = taut_again.and_then(|j| {
        let last_slack = t[j - 1];
        let before = cage[j - 1];
        let (peak_time, peak) = peak(t, cage, t[j], t[j] + tau)?;
        let time = upward_crossing(t, cage, 0.5 * (before + peak), last_slack, peak_time)?;
        Some(Snap {
            time,
            before,
            peak,
            peak_time,
        })
    });
    let ship_snap = cage_snap.and_then(|c| {
        let (a, b) = (c.time + 0.5 * tau, c.time + 1.5 * tau);
        if b > t[t.len() - 1] {
            return None;
        }
        let before = value_at(t, ship, a);
        let (peak_time, peak) = peak(t, ship, a, b)?;
        let time = upward_crossing(t, ship, 0.5 * (before + peak), a, peak_time)?;
        Some(Snap {
            time,
            before,
            peak,
            peak_time,
        })
    });
    let taut_path = match (cage_snap, ship_snap) {
        (Some(c), Some(p)) => t
            .iter()
            .zip(&run.ship_strain)
            .filter(|(ti, _)| (c.time..=p.time).contains(*ti))
            .all(|(_, &e)| e > 0.0),
        _ => false,
    };
    TetherSummary {
        static_ship: ship[0],
        static_cage: cage[0],
        ship_min,
        ship_max,
        slack: first_slack.is_some(),
        first_slack: first_slack.map(|i| t[i]),
        first_cage_slack: first_cage_slack.map(|i| t[i]),
        ship_slack: run.ship_strain.iter().any(|&e| e <= 0.0),
        cage_snap,
        ship_snap,
        taut_path,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A synthetic record: slack from 1 to 2 s, a front of 10 kN leaving the cage at 2.0025 s
    /// and reaching the ship 0.5 s later doubled (reflection at a velocity end).
    #[test]
    fn summary_of_a_synthetic_snap() {
        let dt = 1e-3;
        let n = 4000;
        let mut run = TetherRun::default();
        for i in 0..n {
            let ti = i as Real * dt;
            run.time.push(ti);
            let slack = (1.0..2.0).contains(&ti);
            run.min_strain.push(if slack { -1e-3 } else { 1e-3 });
            // The ship end slackens too, later: the cage snap is still the first at the cage.
            run.ship_strain.push(if (3.0..3.5).contains(&ti) {
                -1e-3
            } else {
                1e-3
            });
            run.cage_strain.push(if slack { -1e-3 } else { 1e-3 });
            run.cage_tension.push(if ti < 1.0 {
                5e3
            } else if ti < 2.0025 {
                0.0
            } else {
                1e4
            });
            run.ship_tension
                .push(if ti < 2.5025 { 2e4 } else { 4e4 } - 1.0 * ti);
        }
        let s = summarise(&run, 1000.0, 2000.0, 0.5);
        assert!(s.slack);
        assert_eq!(s.first_slack, Some(1.0));
        assert_eq!(s.first_cage_slack, Some(1.0));
        assert!(s.ship_slack);
        assert!(s.taut_path);
        let c = s.cage_snap.unwrap();
        assert!((c.time - 2.0025).abs() < 1e-3, "{c:?}");
        assert_eq!((c.before, c.peak), (0.0, 1e4));
        let p = s.ship_snap.unwrap();
        assert!((p.time - 2.5025).abs() < 1e-3, "{p:?}");
        assert!((p.jump() - 2e4).abs() < 1.0, "{p:?}");
        assert!((s.travel_time().unwrap() - 0.5).abs() < 1.5e-3);
        assert_eq!(s.tether_wet_weight(), 2e4 - 5e3);
    }
}
