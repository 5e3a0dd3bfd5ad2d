//! The assembled system: the model discretised for simulation, its state layout, and the
//! right-hand side of the equations of motion.
//!
//! State layout (one contiguous `Vec<f64>`, see [`Layout`]): for every line, its interior
//! 3-vector unknowns (positions of interior nodes for `fe`; positions and tangents for
//! `hermite`, see [`crate::formulation`]) then their rates, or, for `dg`, its modal
//! coefficients ([`DgLine`]'s layout); then for every free point its position then its
//! velocity. End nodes are not line state: they belong to the point they are attached to
//! (fixed, prescribed, or free and then in the state). A `dg` line's end is a velocity
//! condition of its point (DG paper Table 1) and the flux traction is the force on the point;
//! a massless free point at the end of a single `dg` line is that line's free end (Table 1
//! row 3, or row 5 with the point's force) and follows the line.

mod layout;
mod line;
mod rhs;
mod shapes;
mod stability;
mod wave_tables;
mod workspace;

pub use layout::Layout;
pub use line::{LineEnds, SystemLine};
use rhs::SphereContact;
pub use wave_tables::WavePoints;
pub use workspace::{CouplingTracks, LineWork, WinchWork, Workspace};

use crate::error::ModelError;
pub use crate::formulation::Energy;
use crate::formulation::dg::{DgLine, DgSectionSpec, EndCondition};
use crate::formulation::{Discretisation, Mesh};
use crate::linalg::Singular;
use crate::math::{Real, Vec3};
use crate::model::{Formulation, LineEnd, Model, PointKind};
use crate::physics::environment::Environment;

/// A point of the system.
#[derive(Clone, Debug)]
pub struct SystemPoint {
    /// Name.
    pub name: String,
    /// Initial position [m].
    pub position: Vec3,
    /// Kind.
    pub kind: PointKind,
    /// Index among free points.
    pub free_index: Option<usize>,
    /// (line, end: 0 = A, 1 = B) when the point is the free end of a `dg` line: a massless
    /// free point attached to that line only, which moves with the line end and applies its
    /// force to it (DG paper Table 1 rows 3 and 5). Not in the state.
    pub line_end: Option<(usize, usize)>,
    /// Seabed contact of a free point with a volume, fixed at assembly.
    seabed_contact: Option<SphereContact>,
    /// Whether the point is the reserved free end of a failure not released yet
    /// ([`SystemFailure::free_end`]): its state entries exist but rest (zero rates, a unit
    /// mass and no force in the coupled solve, no line attached).
    pub dormant: bool,
}

/// A line end that may release during a run ([`crate::model::LineFailure`]), with the free
/// point reserved for it when the system is assembled, so that a release allocates nothing
/// and the state keeps its length (checkpoints, coupling hosts).
#[derive(Clone, Debug, PartialEq)]
pub struct SystemFailure {
    /// Line index.
    pub line: usize,
    /// Which end releases.
    pub end: crate::model::End,
    /// Further line ends released with it onto the same free point
    /// ([`crate::model::LineFailure::joined`]).
    pub joined: Vec<(usize, crate::model::End)>,
    /// The point the end is attached to until it releases.
    pub attachment: usize,
    /// The massless free point that owns the end after the release: dormant until then,
    /// its 6 state entries (position, velocity) placed after every other block.
    pub free_end: usize,
    /// Release time [s], if any.
    pub time: Option<Real>,
    /// Release tension [N], if any.
    pub tension: Option<Real>,
}

impl SystemFailure {
    /// Every end of the failure, (line index, end): the first, then the joined ones.
    pub fn ends(&self) -> impl Iterator<Item = (usize, crate::model::End)> + '_ {
        std::iter::once((self.line, self.end)).chain(self.joined.iter().copied())
    }
}

/// The immutable, assembled system.
#[derive(Clone, Debug)]
pub struct System {
    /// Environment.
    pub environment: Environment,
    /// Lines.
    pub lines: Vec<SystemLine>,
    /// Points.
    pub points: Vec<SystemPoint>,
    /// Indices of the free points.
    pub free_points: Vec<usize>,
    /// Rigid bodies.
    pub bodies: Vec<SystemBody>,
    /// Indices of the free and pinned bodies: those with rotations to integrate, a block of
    /// the state and a row block of the coupled system ([`crate::model::BodyKind::integrates`]).
    pub free_bodies: Vec<usize>,
    /// Per point: its slot in the coupled system when it is on a free body (numbered after
    /// the free points, see [`crate::linalg::CoupledSystem`]).
    pub point_slot: Vec<Option<usize>>,
    /// Per point: for a point prescribed on a rigid motion ([`crate::model::Motion::Rigid`]),
    /// the first point whose rigid motion is the same (itself if no earlier one), so that
    /// [`System::point_kinematics`] evaluates the motion once for all the points on it (a
    /// vessel's fairleads); `None` for other points.
    pub rigid_motion_source: Vec<Option<usize>>,
    /// State layout.
    pub layout: Layout,
    /// Velocity of the frame the statics are solved in [m/s]: the tow velocity V of a steady
    /// tow ([`crate::model::InitialCondition::SteadyTow`], [`crate::model::tow_velocity`]),
    /// zero otherwise. The static residuals, force Jacobians and end forces are evaluated with
    /// every material point moving at V (line tangents and body rotations at rest), so drag
    /// sees u − V and seabed friction opposes V; the dynamics do not use it.
    pub tow_velocity: Vec3,
    /// The line ends that may release, in the order of [`crate::model::Model::failures`].
    pub failures: Vec<SystemFailure>,
}

/// A rigid body of the system.
#[derive(Clone, Debug)]
pub struct SystemBody {
    /// The body's description.
    pub body: crate::model::Body,
    /// Index among free bodies.
    pub free_index: Option<usize>,
}

impl SystemBody {
    /// Kinematics at t = 0 ([`crate::model::Body::initial_kinematics`]).
    pub fn initial_kinematics(&self) -> crate::model::RigidKinematics {
        self.body.initial_kinematics()
    }
}

/// Kinematics of a point at one instant.
#[derive(Clone, Copy, Debug, Default)]
pub struct PointKinematics {
    /// Position [m].
    pub position: Vec3,
    /// Velocity [m/s].
    pub velocity: Vec3,
    /// Acceleration [m/s²] (prescribed points; solved for free points).
    pub acceleration: Vec3,
}

/// Identifies the place in the model a state entry belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Location {
    /// Line or point name.
    pub object: String,
    /// Node index along the line (0 at end A), 0 for a point.
    pub node: usize,
}

impl SystemPoint {
    /// Whether the seabed holds this point: a free point with a volume, in water with a
    /// seabed ([`crate::bodies`] and other points pass through it).
    pub fn has_seabed_contact(&self) -> bool {
        self.seabed_contact.is_some()
    }
}

impl System {
    /// Assembles a validated model.
    pub fn new(model: &Model) -> Result<Self, ModelError> {
        model.validate()?;
        let bodies: Vec<SystemBody> = model
            .bodies
            .iter()
            .map(|b| SystemBody {
                body: b.clone(),
                free_index: None,
            })
            .collect();
        let points = model
            .points
            .iter()
            .map(|p| SystemPoint {
                name: p.name.clone(),
                position: match &p.kind {
                    PointKind::Prescribed(m) => m.initial_position(),
                    PointKind::Body { body, offset } => {
                        bodies[*body].initial_kinematics().point(offset).0
                    }
                    _ => p.position,
                },
                kind: p.kind.clone(),
                free_index: None,
                line_end: None,
                seabed_contact: SphereContact::new(&model.environment, &p.kind),
                dormant: false,
            })
            .collect::<Vec<_>>();
        // The free end reserved for each failure: a massless, dimensionless free point.
        let mut points = points;
        let mut failures = Vec::with_capacity(model.failures.len());
        for f in &model.failures {
            let attachment = f.attachment(model);
            let line = &model.lines[f.line];
            points.push(SystemPoint {
                name: format!("{}.end_{}.released", line.name, f.end.name()),
                position: points[attachment].position,
                kind: PointKind::Free {
                    mass: 0.0,
                    volume: 0.0,
                    drag_area: 0.0,
                    added_mass_coefficient: 0.0,
                    force: Vec3::zeros(),
                },
                free_index: None,
                line_end: None,
                seabed_contact: None,
                dormant: true,
            });
            failures.push(SystemFailure {
                line: f.line,
                end: f.end,
                joined: f.joined.clone(),
                attachment,
                free_end: points.len() - 1,
                time: f.time,
                tension: f.tension,
            });
        }
        let mut lines = Vec::new();
        for l in &model.lines {
            let sections: Vec<_> = l
                .sections
                .iter()
                .map(|s| (model.line_types[s.line_type].clone(), s.length, s.elements))
                .collect();
            let mesh = Mesh::new(&sections);
            let discretisation = match l.formulation {
                Formulation::Fe => Discretisation::Fe {
                    mass_matrix: l.mass_matrix,
                },
                Formulation::Hermite => {
                    Discretisation::Hermite(crate::formulation::HermiteOptions {
                        strain: l.strain_measure,
                    })
                }
                Formulation::Dg => {
                    let specs: Vec<DgSectionSpec> = l
                        .sections
                        .iter()
                        .map(|s| DgSectionSpec {
                            line_type: model.line_types[s.line_type].clone(),
                            length: s.length,
                            elements: s.elements,
                            order: s.order,
                        })
                        .collect();
                    let mut line = DgLine::new(&specs, [EndCondition::PINNED_JOINT; 2]);
                    line.modal_filter = l.modal_filter;
                    line.shock_filter = l.shock_filter;
                    Discretisation::Dg(Box::new(line))
                }
            };
            let LineEnd::Point(end_a) = l.end_a;
            let LineEnd::Point(end_b) = l.end_b;
            lines.push(SystemLine {
                name: l.name.clone(),
                mesh,
                discretisation,
                clamp: l.clamp.map(|d| d.map(|d| d.normalize())),
                end_a,
                end_b,
                winch: l.winch.clone(),
            });
        }
        let mut system = Self::from_parts(model.environment.clone(), lines, points, bodies)?;
        system.tow_velocity = model.statics_frame_velocity()?;
        system.failures = failures;
        Ok(system)
    }

    /// Finishes the assembly from lines and points: free ends of `dg` lines, the `dg` end
    /// conditions, the free points and the state layout.
    fn from_parts(
        environment: Environment,
        mut lines: Vec<SystemLine>,
        mut points: Vec<SystemPoint>,
        mut bodies: Vec<SystemBody>,
    ) -> Result<Self, ModelError> {
        let mut attached = vec![0usize; points.len()];
        for l in &lines {
            attached[l.end_a] += 1;
            attached[l.end_b] += 1;
        }
        for (li, l) in lines.iter_mut().enumerate() {
            let Discretisation::Dg(dg) = &mut l.discretisation else {
                continue;
            };
            for (side, p) in [l.end_a, l.end_b].into_iter().enumerate() {
                let massless = matches!(
                    points[p].kind,
                    PointKind::Free { mass, volume, drag_area, .. }
                        if mass == 0.0 && volume == 0.0 && drag_area == 0.0
                );
                dg.ends[side] = if massless && attached[p] == 1 {
                    points[p].line_end = Some((li, side));
                    EndCondition::FREE
                } else if l.clamp[side].is_some() {
                    EndCondition::CLAMPED
                } else {
                    EndCondition::PINNED_JOINT
                };
            }
        }
        let mut free_points = Vec::new();
        for (i, p) in points.iter_mut().enumerate() {
            if matches!(p.kind, PointKind::Free { .. }) && p.line_end.is_none() {
                free_points.push(i);
                p.free_index = Some(free_points.len() - 1);
            }
        }
        // A free point held only by `dg` ends has no mass from its lines: it needs its own.
        for &p in &free_points {
            let PointKind::Free { mass, .. } = points[p].kind else {
                continue;
            };
            if points[p].dormant {
                continue;
            }
            let only_dg = lines
                .iter()
                .filter(|l| l.end_a == p || l.end_b == p)
                .all(|l| l.dg().is_some());
            if only_dg && !(mass > 0.0) {
                return Err(ModelError::MasslessDgJoint {
                    point: points[p].name.clone(),
                });
            }
        }
        let mut line_offset = Vec::new();
        let mut line_interior = Vec::new();
        let mut line_len = Vec::new();
        let mut len = 0;
        for l in &lines {
            let (interior, block) = l.state_len();
            line_offset.push(len);
            line_interior.push(interior);
            line_len.push(block);
            len += block;
        }
        let mut point_offset = vec![None; points.len()];
        for &p in free_points.iter().filter(|&&p| !points[p].dormant) {
            point_offset[p] = Some(len);
            len += 6;
        }
        let mut free_bodies = Vec::new();
        let mut body_offset = vec![None; bodies.len()];
        for (i, b) in bodies.iter_mut().enumerate() {
            if b.body.kind.integrates() {
                b.free_index = Some(free_bodies.len());
                free_bodies.push(i);
                body_offset[i] = Some(len);
                len += crate::bodies::STATE_LEN;
            }
        }
        // The reserved free ends of failures last, so that the intact system's state (the
        // initial statics) is a prefix of this one.
        for &p in free_points.iter().filter(|&&p| points[p].dormant) {
            point_offset[p] = Some(len);
            len += 6;
        }
        let mut slots = 0;
        let point_slot = points
            .iter()
            .map(|p| match p.kind {
                PointKind::Body { body, .. } if bodies[body].free_index.is_some() => {
                    slots += 1;
                    Some(free_points.len() + slots - 1)
                }
                _ => None,
            })
            .collect();
        fn rigid_motion(p: &SystemPoint) -> Option<&crate::model::RigidMotion> {
            match &p.kind {
                PointKind::Prescribed(crate::model::Motion::Rigid { motion, .. }) => Some(motion),
                _ => None,
            }
        }
        let rigid_motion_source = points
            .iter()
            .map(|p| {
                let motion = rigid_motion(p)?;
                points.iter().position(|q| rigid_motion(q) == Some(motion))
            })
            .collect();
        Ok(Self {
            environment,
            lines,
            points,
            free_points,
            bodies,
            free_bodies,
            point_slot,
            rigid_motion_source,
            layout: Layout {
                line_offset,
                line_interior,
                line_len,
                point_offset,
                body_offset,
                len,
            },
            tow_velocity: Vec3::zeros(),
            failures: Vec::new(),
        })
    }

    /// Whether any line uses the `dg` formulation.
    pub fn has_dg_lines(&self) -> bool {
        self.lines.iter().any(|l| l.dg().is_some())
    }

    /// Whether the statics must go through [`System::statics_twin`]: `dg` lines or free
    /// bodies.
    pub fn needs_statics_twin(&self) -> bool {
        self.has_dg_lines() || !self.free_bodies.is_empty()
    }

    /// Names the place of a singular block.
    pub fn singular_location(&self, s: Singular) -> Location {
        match s {
            Singular::Line { line, node } => Location {
                object: self.lines[line].name.clone(),
                node,
            },
            Singular::Point(f) => Location {
                // Indices past the free points are the free bodies' rows (in CoupledSystem's
                // order: points, then bodies).
                object: match self.free_points.get(f) {
                    Some(&p) => self.points[p].name.clone(),
                    None => self
                        .free_bodies
                        .first()
                        .map_or("?".into(), |&b| self.bodies[b].body.name.clone()),
                },
                node: 0,
            },
        }
    }

    /// Names the place a state index belongs to.
    pub fn locate(&self, index: usize) -> Location {
        for (li, l) in self.lines.iter().enumerate() {
            let o = self.layout.line_offset[li];
            if index >= o && index < o + self.layout.line_len[li] {
                return Location {
                    object: l.name.clone(),
                    node: l.locate(index - o),
                };
            }
        }
        for (b, off) in self.layout.body_offset.iter().enumerate() {
            if let Some(o) = off
                && index >= *o
                && index < o + crate::bodies::STATE_LEN
            {
                return Location {
                    object: self.bodies[b].body.name.clone(),
                    node: 0,
                };
            }
        }
        for (p, off) in self.layout.point_offset.iter().enumerate() {
            if let Some(o) = off
                && index >= *o
                && index < o + 6
            {
                return Location {
                    object: self.points[p].name.clone(),
                    node: 0,
                };
            }
        }
        Location {
            object: "?".into(),
            node: 0,
        }
    }

    /// Force [N] a line exerts on the attachment of one end (`end_b` false: end A), from the
    /// last right-hand-side evaluation ([`SystemLine::end_force`]).
    pub fn end_force(&self, ws: &Workspace, line: usize, end_b: bool) -> Vec3 {
        self.lines[line].end_force(&ws.lines[line], &ws.blocks[line], end_b)
    }

    /// Tension [N] at node i of a line from the last evaluation ([`SystemLine::node_tension`]).
    pub fn node_tension(&self, ws: &Workspace, line: usize, node: usize) -> Real {
        self.lines[line].node_tension(&ws.lines[line], &ws.blocks[line], node)
    }
}
