//! Koh et al.'s swinging rubber cable (DG paper §5, Table 2; SPEC §7): a 2.022 m neoprene cable
//! hangs in air between two pins 1.805 m apart; at t = 0 one pin is pulled and the cable
//! swings about the other. The scenario (`examples/koh_swinging_cable*.toml`) makes the pulled
//! pin a massless free point at the end of the line (a free cable end, DG paper Table 1 row 3)
//! listed in `simulation.release`: the statics hold it at its position, so the run starts from
//! the static sag between the two pins ([`crate::statics::solve_with_release`]).
//!
//! [`run_release`] integrates such a model and records the tension at the remaining pin (line
//! 0, end A), the path of the free end (line 0, end B) and snapshots of the line's shape.

use super::RunError;
use crate::analysis::Channel;
use crate::math::{Real, Vec3};
use crate::model::{Formulation, Model};
use crate::session::{Observer, ObserverError, Session, View};

/// The record of a release run.
#[derive(Clone, Debug, Default)]
pub struct ReleaseRun {
    /// Sample times [s] (every `output_interval` of the model's settings).
    pub time: Vec<Real>,
    /// Tension at the remaining pin, line 0's end A ([`Channel::EndTension`]) [N].
    pub pin_tension: Vec<Real>,
    /// Position of the free end, line 0's end B [m].
    pub tail: Vec<Vec3>,
    /// Velocity of the free end [m/s].
    pub tail_velocity: Vec<Vec3>,
    /// Node positions of line 0 (nodes 0..=N) at the first sample at or after each multiple of
    /// the shape interval, with their times [s, m].
    pub shapes: Vec<(Real, Vec<Vec3>)>,
    /// Time step [s].
    pub step: Real,
    /// Steps taken.
    pub steps: u64,
    /// Wall-clock time of the integration (without the statics) [s].
    pub wall_seconds: Real,
}

struct Recorder {
    run: ReleaseRun,
    nodes: usize,
    shape_interval: Option<Real>,
}

impl Observer for Recorder {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        let node_vec = |node: usize, velocity: bool| {
            Vec3::from_fn(|axis, _| {
                let c = if velocity {
                    Channel::NodeVelocity {
                        line: 0,
                        node,
                        axis,
                    }
                } else {
                    Channel::NodePosition {
                        line: 0,
                        node,
                        axis,
                    }
                };
                c.value(system, ws)
            })
        };
        let r = &mut self.run;
        r.time.push(time);
        r.pin_tension.push(
            Channel::EndTension {
                line: 0,
                end_b: false,
            }
            .value(system, ws),
        );
        r.tail.push(node_vec(self.nodes - 1, false));
        r.tail_velocity.push(node_vec(self.nodes - 1, true));
        if let Some(every) = self.shape_interval {
            let due = r.shapes.len() as Real * every;
            if time >= due - 1e-9 * every {
                let shape = (0..self.nodes).map(|i| node_vec(i, false)).collect();
                r.shapes.push((time, shape));
            }
        }
        Ok(())
    }
}

/// `base` with line 0 in `formulation`, with `elements` elements per unit of its sections'
/// element counts scaled to `elements` in all (a single-section line gets exactly `elements`)
/// and, for `dg`, order `order` in every section.
pub fn with_discretisation(
    base: &Model,
    formulation: Formulation,
    elements: usize,
    order: usize,
) -> Model {
    let mut m = base.clone();
    let line = &mut m.lines[0];
    let old = line.elements();
    line.formulation = formulation;
    for s in &mut line.sections {
        s.elements = (s.elements * elements).div_ceil(old).max(1);
        s.order = order;
    }
    m
}

/// Runs `model` from its static equilibrium with `settings.release` applied (the pins' sag,
/// then the release) for `settings.duration`, recording every `settings.output_interval` and
/// the line's shape every `shape_interval` [s] (none if `None`).
pub fn run_release(model: &Model, shape_interval: Option<Real>) -> Result<ReleaseRun, RunError> {
    let mut session = Session::new(model.clone())?;
    let system = session.system();
    let recorder = Recorder {
        run: ReleaseRun::default(),
        nodes: system.lines[0].mesh.elements() + 1,
        shape_interval,
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
