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

use crate::error::ModelError;
pub use crate::formulation::Energy;
use crate::formulation::dg::{
    DgLine, DgSectionSpec, DgWorkspace, EndCondition, EndState, Translation,
};
use crate::formulation::{ElementState, LineKind, LoadOptions, Mesh, line_forces};
use crate::linalg::{CoupledSystem, EndKind, LineBlocks, Singular};
use crate::math::{Mat3, Real, Vec3, get3, set3};
use crate::model::{Formulation, LineEnd, Model, PointKind, Scheme};
use crate::physics::environment::Environment;

mod wave_tables;
pub use wave_tables::WavePoints;

/// Where each object's unknowns sit in the state vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Offset of each line's block: 3·m coordinates then 3·m rates.
    pub line_offset: Vec<usize>,
    /// Interior vector count m of each line (`fe`: N − 1 nodes; `hermite`: 2N; `dg`: 0, its
    /// block is modal coefficients).
    pub line_interior: Vec<usize>,
    /// Length of each line's block (6m, or the `dg` line's state length).
    pub line_len: Vec<usize>,
    /// Offset of each free point's block (position then velocity), `None` otherwise.
    pub point_offset: Vec<Option<usize>>,
    /// Offset of each free body's block ([`crate::bodies::STATE_LEN`] entries: position,
    /// quaternion, velocity, angular velocity), `None` otherwise.
    pub body_offset: Vec<Option<usize>>,
    /// Total length.
    pub len: usize,
}

impl Layout {
    /// Every second-order block of the state as (offset, node count): each `fe` or `hermite`
    /// line's interior nodes, then each free point (one node). A block holds 3·count
    /// positions then 3·count velocities. `dg` blocks (first order) are not listed.
    pub fn blocks(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.line_offset
            .iter()
            .copied()
            .zip(self.line_interior.iter().copied())
            .chain(self.point_offset.iter().flatten().map(|&o| (o, 1)))
    }
}

/// A line of the system.
#[derive(Clone, Debug)]
pub struct SystemLine {
    /// Name.
    pub name: String,
    /// Elements along the unstretched arc length.
    pub mesh: Mesh,
    /// Formulation and its options.
    pub kind: LineKind,
    /// Unit directions of the clamped end tangents (A, B), `None` for pinned ends.
    pub clamp: [Option<Vec3>; 2],
    /// Point index of end A.
    pub end_a: usize,
    /// Point index of end B.
    pub end_b: usize,
    /// The discontinuous Galerkin discretisation of a `dg` line.
    pub dg: Option<Box<DgLine>>,
    /// The line's winch: its unstretched length follows the winch's schedule, and its
    /// `mesh` is the mesh at t = 0 ([`Workspace::winches`] holds the current one).
    pub winch: Option<crate::model::Winch>,
}

impl SystemLine {
    /// Number of 3-vector unknowns, ends included (`fe`: N + 1; `hermite`: 2N + 2).
    #[inline]
    pub fn vectors(&self) -> usize {
        self.kind.vectors(self.mesh.elements())
    }

    /// Number of nodes N + 1.
    #[inline]
    pub fn nodes(&self) -> usize {
        self.mesh.elements() + 1
    }

    /// Number of vectors of the line's mass blocks: all its vectors, or for `dg` only the two
    /// ends (which carry the flux tractions to the points and no mass).
    #[inline]
    pub fn block_vectors(&self) -> usize {
        if self.dg.is_some() { 2 } else { self.vectors() }
    }

    /// Index of node i's position among the line's vectors (`LineWork::position`).
    #[inline]
    pub fn node_vector(&self, node: usize) -> usize {
        self.kind.node_vector(node, self.mesh.elements())
    }

    /// The clamped tangents: (vector index, unit direction) of each clamped end.
    pub fn clamped(&self) -> impl Iterator<Item = (usize, Vec3)> + '_ {
        let n = self.mesh.elements();
        self.clamp.iter().enumerate().filter_map(move |(k, d)| {
            d.map(|d| {
                let node = if k == 0 { 0 } else { n };
                (crate::formulation::hermite::vector_index(node, true, n), d)
            })
        })
    }

    /// Constrains each clamped end tangent to its direction in a line's block matrix and
    /// right-hand side: with P = d dᵀ, Q = I − P, row j becomes P A_j· (and Q x_j = 0), column
    /// j becomes A_·j P, and the rhs P b_j. The solution's tangent rate then stays along d (the
    /// stretch at the clamp stays free); the normal part of the row's residual is the clamp's
    /// reaction moment, which the constraint absorbs.
    pub fn apply_clamps(&self, blocks: &mut LineBlocks) {
        for (j, d) in self.clamped() {
            let p = d * d.transpose();
            let q = Mat3::identity() - p;
            for i in blocks.band_of(j) {
                if i != j {
                    let c = blocks.block(i, j) * p;
                    *blocks.block_mut(i, j) = c;
                    let r = p * blocks.block(j, i);
                    *blocks.block_mut(j, i) = r;
                }
            }
            let djj = blocks.block(j, j);
            let scale = djj.trace() / 3.0;
            let scale = if scale != 0.0 { scale } else { 1.0 };
            *blocks.block_mut(j, j) = p * djj * p + q * scale;
            blocks.x[j] = p * blocks.x[j];
        }
    }

    /// Length [m] that a unit of vector j moves a point of the line by: 1 for a position, the
    /// shortest element length for a tangent (a tangent's change δt moves points of its
    /// element by about l δt). Scales finite-difference steps and regularisation per vector.
    #[inline]
    pub fn length_scale(&self, j: usize) -> Real {
        if self.is_tangent(j) {
            self.mesh.shortest_element()
        } else {
            1.0
        }
    }

    /// Whether vector j is a tangent [-] rather than a position [m].
    #[inline]
    pub fn is_tangent(&self, j: usize) -> bool {
        self.kind.is_tangent(j, self.mesh.elements())
    }

    /// Writes the coordinates of the line's interior vectors into its state block `y` (the
    /// coordinates part) from the node positions `shape` (nodes 0..=N, ends included).
    /// `hermite` tangents t = ∂r/∂s come from second-order finite differences over the
    /// unstretched arc length (one-sided at the ends; exact for a straight line).
    pub fn set_shape(&self, shape: &[Vec3], y: &mut [Real]) {
        let n = self.mesh.elements();
        match self.kind {
            LineKind::Fe { .. } => {
                for (i, r) in shape.iter().enumerate().take(n).skip(1) {
                    set3(y, i - 1, r);
                }
            }
            LineKind::Dg => {
                unreachable!("a dg line's state is modal: use System::set_line_shape")
            }
            LineKind::Hermite(_) => {
                use crate::formulation::hermite::vector_index;
                let s: Vec<Real> = (0..=n).map(|i| self.mesh.arc_length(i)).collect();
                for i in 0..=n {
                    let t = if n == 1 {
                        (shape[1] - shape[0]) / (s[1] - s[0])
                    } else if i == 0 || i == n {
                        // One-sided, second order, through the end and its two neighbours.
                        let (a, b, c) = if i == 0 { (0, 1, 2) } else { (n, n - 1, n - 2) };
                        let (h1, h2) = (s[b] - s[a], s[c] - s[b]);
                        (shape[b] - shape[a]) * ((h1 + h2) / (h1 * h2))
                            - (shape[c] - shape[a]) * (h1 / (h2 * (h1 + h2)))
                    } else {
                        let (h1, h2) = (s[i] - s[i - 1], s[i + 1] - s[i]);
                        ((shape[i + 1] - shape[i]) * (h1 * h1)
                            + (shape[i] - shape[i - 1]) * (h2 * h2))
                            / (h1 * h2 * (h1 + h2))
                    };
                    let j = vector_index(i, true, n);
                    let t = match self.clamped().find(|c| c.0 == j) {
                        Some((_, d)) => d * t.dot(&d).max(Real::EPSILON),
                        None => t,
                    };
                    set3(y, j - 1, &t);
                    if i > 0 && i < n {
                        set3(y, vector_index(i, false, n) - 1, &shape[i]);
                    }
                }
            }
        }
    }
}

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
    /// Indices of the free bodies.
    pub free_bodies: Vec<usize>,
    /// Per point: its slot in the coupled system when it is on a free body (numbered after
    /// the free points, see [`crate::linalg::CoupledSystem`]).
    pub point_slot: Vec<Option<usize>>,
    /// State layout.
    pub layout: Layout,
    /// Velocity of the frame the statics are solved in [m/s]: the tow velocity V of a steady
    /// tow ([`crate::model::InitialCondition::SteadyTow`], [`crate::model::tow_velocity`]),
    /// zero otherwise. The static residuals, force Jacobians and end forces are evaluated with
    /// every material point moving at V (line tangents and body rotations at rest), so drag
    /// sees u − V and seabed friction opposes V; the dynamics do not use it.
    pub tow_velocity: Vec3,
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
    /// Kinematics at t = 0: a free body at rest at its initial pose, a prescribed body on its
    /// motion.
    pub fn initial_kinematics(&self) -> crate::model::RigidKinematics {
        match &self.body.kind {
            crate::model::BodyKind::Free => {
                crate::model::RigidKinematics::at_rest(self.body.position, self.body.orientation)
            }
            crate::model::BodyKind::Prescribed(m) => m.kinematics(0.0),
        }
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

/// Scratch of one line, sized once.
#[derive(Clone, Debug)]
pub struct LineWork {
    /// Node positions [m], ends included.
    pub position: Vec<Vec3>,
    /// Node velocities [m/s].
    pub velocity: Vec<Vec3>,
    /// Node forces [N] from the line's physics.
    pub force: Vec<Vec3>,
    /// Element tension and strain.
    pub elements: ElementState,
    /// Tension at the nodes [N] (`dg` only: at the element ends, the mean of the two sides'
    /// values at an interface).
    pub node_tension: Vec<Real>,
}

/// The current state of a line on a winch, updated at the start of every evaluation
/// ([`System::update_winches`]).
#[derive(Clone, Debug)]
pub struct WinchWork {
    /// The line's mesh rescaled to the current unstretched length L(t), with σ = L̇/L.
    pub mesh: Mesh,
    /// Unstretched length at t = 0, L(0) [m].
    pub initial_length: Real,
    /// Current unstretched length L(t) = L(0) + payout [m].
    pub length: Real,
    /// Payout, its rate and acceleration at the time of the last evaluation.
    pub state: crate::model::WinchState,
}

/// All scratch of the right-hand side, sized once: no allocation in the time loop.
#[derive(Clone, Debug)]
pub struct Workspace {
    /// Per line.
    pub lines: Vec<LineWork>,
    /// Per line: mass blocks; after a solve, `x` holds node accelerations [m/s²].
    pub blocks: Vec<LineBlocks>,
    /// Per point.
    pub points: Vec<PointKinematics>,
    /// Shared-point system.
    pub coupled: CoupledSystem,
    /// Per line: the `dg` scratch (`None` for other formulations).
    pub dg: Vec<Option<DgWorkspace>>,
    /// Per body: its kinematics (free bodies: accelerations solved by the last evaluation).
    pub bodies: Vec<crate::model::RigidKinematics>,
    /// Per line: the current mesh and length of a line on a winch (`None` for other lines).
    pub winches: Vec<Option<WinchWork>>,
    /// The run's wave kinematics at the static position, if it asks for them
    /// ([`System::start_wave_tables`]); direct summation otherwise.
    pub wave_points: WavePoints,
}

/// Identifies the place in the model a state entry belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Location {
    /// Line or point name.
    pub object: String,
    /// Node index along the line (0 at end A), 0 for a point.
    pub node: usize,
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
            })
            .collect();
        let mut lines = Vec::new();
        for l in &model.lines {
            let sections: Vec<_> = l
                .sections
                .iter()
                .map(|s| (model.line_types[s.line_type].clone(), s.length, s.elements))
                .collect();
            let mesh = Mesh::new(&sections);
            let kind = match l.formulation {
                Formulation::Fe => LineKind::Fe {
                    mass_matrix: l.mass_matrix,
                },
                Formulation::Hermite => LineKind::Hermite(crate::formulation::HermiteOptions {
                    strain: l.strain_measure,
                }),
                Formulation::Dg => LineKind::Dg,
            };
            let dg = (l.formulation == Formulation::Dg).then(|| {
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
                Box::new(line)
            });
            let LineEnd::Point(end_a) = l.end_a;
            let LineEnd::Point(end_b) = l.end_b;
            lines.push(SystemLine {
                name: l.name.clone(),
                mesh,
                kind,
                clamp: l.clamp.map(|d| d.map(|d| d.normalize())),
                end_a,
                end_b,
                dg,
                winch: l.winch.clone(),
            });
        }
        let mut system = Self::from_parts(model.environment.clone(), lines, points, bodies)?;
        system.tow_velocity = model.statics_frame_velocity()?;
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
            let Some(dg) = l.dg.as_mut() else { continue };
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
            let only_dg = lines
                .iter()
                .filter(|l| l.end_a == p || l.end_b == p)
                .all(|l| l.dg.is_some());
            if only_dg && !(mass > 0.0) {
                return Err(ModelError::Invalid {
                    what: format!("point {}", points[p].name),
                    why: "is a massless free point joining dg lines, whose ends carry no mass: \
                          give it a mass (a massless point at the end of a single dg line is \
                          that line's free end)"
                        .into(),
                });
            }
        }
        let mut line_offset = Vec::new();
        let mut line_interior = Vec::new();
        let mut line_len = Vec::new();
        let mut len = 0;
        for l in &lines {
            let (interior, block) = match &l.dg {
                Some(dg) => (0, dg.state_len()),
                None => {
                    let m = l.vectors() - 2;
                    (m, 6 * m)
                }
            };
            line_offset.push(len);
            line_interior.push(interior);
            line_len.push(block);
            len += block;
        }
        let mut point_offset = vec![None; points.len()];
        for &p in &free_points {
            point_offset[p] = Some(len);
            len += 6;
        }
        let mut free_bodies = Vec::new();
        let mut body_offset = vec![None; bodies.len()];
        for (i, b) in bodies.iter_mut().enumerate() {
            if b.body.kind == crate::model::BodyKind::Free {
                b.free_index = Some(free_bodies.len());
                free_bodies.push(i);
                body_offset[i] = Some(len);
                len += crate::bodies::STATE_LEN;
            }
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
        Ok(Self {
            environment,
            lines,
            points,
            free_points,
            bodies,
            free_bodies,
            point_slot,
            layout: Layout {
                line_offset,
                line_interior,
                line_len,
                point_offset,
                body_offset,
                len,
            },
            tow_velocity: Vec3::zeros(),
        })
    }

    /// The system with every `dg` line replaced by a `hermite` line over the same sections,
    /// with ⌈(P + 1)/2⌉ cubic elements per dg element of order P (about as many unknowns),
    /// the same ends and clamps, and every free body held at its initial pose: the statics of
    /// such systems are solved on it ([`crate::statics::solve`]) and carried over by
    /// [`System::state_from_twin`] (free bodies start at their initial pose, at rest).
    pub fn statics_twin(&self) -> System {
        let poses: Vec<_> = self.bodies.iter().map(|b| b.initial_kinematics()).collect();
        self.statics_twin_at(&poses)
    }

    /// [`System::statics_twin`] with the free bodies held at `poses` (one per body; entries
    /// of prescribed bodies are not used).
    pub fn statics_twin_at(&self, poses: &[crate::model::RigidKinematics]) -> System {
        let lines = self
            .lines
            .iter()
            .map(|l| match &l.dg {
                None => l.clone(),
                Some(dg) => {
                    let sections: Vec<_> = dg
                        .sections
                        .iter()
                        .enumerate()
                        .map(|(k, sec)| {
                            let count = dg.elements.iter().filter(|e| e.section == k).count();
                            (
                                sec.properties.line_type.clone(),
                                count as Real * sec.properties.element_length,
                                count * sec.basis.order.div_ceil(2).max(1),
                            )
                        })
                        .collect();
                    SystemLine {
                        mesh: Mesh::new(&sections),
                        kind: LineKind::Hermite(Default::default()),
                        dg: None,
                        ..l.clone()
                    }
                }
            })
            .collect();
        let points = self
            .points
            .iter()
            .map(|p| SystemPoint {
                free_index: None,
                line_end: None,
                ..p.clone()
            })
            .collect();
        // Free bodies are held at their initial pose.
        let bodies = self
            .bodies
            .iter()
            .zip(poses)
            .map(|(b, k)| {
                let mut body = b.body.clone();
                if b.free_index.is_none() {
                    return SystemBody {
                        body,
                        free_index: None,
                    };
                }
                body.kind = crate::model::BodyKind::Prescribed(crate::model::RigidMotion::Fixed {
                    position: k.position,
                    orientation: k.orientation,
                });
                SystemBody {
                    body,
                    free_index: None,
                }
            })
            .collect();
        let mut twin = Self::from_parts(self.environment.clone(), lines, points, bodies)
            .expect("a system without dg lines has no dg end to refuse");
        twin.tow_velocity = self.tow_velocity;
        twin
    }

    /// This system's state from a state `y_twin` of its [`System::statics_twin`]: free points
    /// and `fe`/`hermite` lines copied, each `dg` line the L2 projection of its twin's cubic
    /// shape (positions and tangents ∂r/∂s, at rest), then, when `refine` and the line has at
    /// most 3000 modal unknowns, Newton on the dg line's own steady equations with its ends
    /// held where the twin put them ([`crate::formulation::dg::steady_state`]), so that the
    /// run starts in the dg discretisation's own equilibrium (a failed refinement keeps the
    /// projection). The free points keep the twin's equilibrium: their residual is the
    /// difference of the two discretisations' end forces.
    pub fn state_from_twin(&self, twin: &System, y_twin: &[Real], refine: bool) -> Vec<Real> {
        let poses: Vec<_> = self.bodies.iter().map(|b| b.initial_kinematics()).collect();
        self.state_from_twin_at(twin, y_twin, refine, &poses)
    }

    /// [`System::state_from_twin`] with the free bodies at rest at `poses`.
    pub fn state_from_twin_at(
        &self,
        twin: &System,
        y_twin: &[Real],
        refine: bool,
        poses: &[crate::model::RigidKinematics],
    ) -> Vec<Real> {
        let mut y = vec![0.0; self.layout.len];
        let mut tws = twin.workspace();
        twin.point_kinematics(0.0, y_twin, &mut tws);
        twin.gather_lines(y_twin, &mut tws);
        for (p, off) in self.layout.point_offset.iter().enumerate() {
            if let (Some(o), Some(ot)) = (off, twin.layout.point_offset[p]) {
                y[*o..o + 6].copy_from_slice(&y_twin[ot..ot + 6]);
            }
        }
        for (b, off) in self.layout.body_offset.iter().enumerate() {
            if let Some(o) = off {
                let k =
                    crate::model::RigidKinematics::at_rest(poses[b].position, poses[b].orientation);
                crate::bodies::write_state(&k, &mut y[*o..o + crate::bodies::STATE_LEN]);
            }
        }
        for (li, l) in self.lines.iter().enumerate() {
            let (o, len) = (self.layout.line_offset[li], self.layout.line_len[li]);
            let Some(dg) = &l.dg else {
                let ot = twin.layout.line_offset[li];
                y[o..o + len].copy_from_slice(&y_twin[ot..ot + len]);
                continue;
            };
            let tl = &twin.lines[li];
            let q = &tws.lines[li].position;
            let nodes: Vec<Real> = (0..=tl.mesh.elements())
                .map(|i| tl.mesh.arc_length(i))
                .collect();
            let state = &mut y[o..o + len];
            dg.project(state, |s| {
                let e = (nodes.partition_point(|&x| x <= s).max(1) - 1).min(nodes.len() - 2);
                let xi = ((s - nodes[e]) / (nodes[e + 1] - nodes[e])).clamp(0.0, 1.0);
                let (r, t) = crate::formulation::hermite::point_on_element(&tl.mesh, q, e, xi);
                (r, t, Vec3::zeros())
            });
            if refine && 2 * dg.state_len() / 3 <= 3000 {
                let end = |side: usize, p: usize| {
                    let mut end = EndState::fixed(
                        tws.points[p].position,
                        l.clamp[side].unwrap_or_else(Vec3::zeros),
                    );
                    if let PointKind::Free { force, .. } = &self.points[p].kind
                        && dg.ends[side].translation == Translation::Force
                    {
                        end.force = *force;
                    }
                    end
                };
                let ends = [end(0, l.end_a), end(1, l.end_b)];
                let mut trial = state.to_vec();
                if crate::formulation::dg::steady_state(
                    dg,
                    &self.environment,
                    0.0,
                    &mut trial,
                    &ends,
                    1e-10,
                    30,
                )
                .is_ok()
                {
                    state.copy_from_slice(&trial);
                }
            }
        }
        y
    }

    /// Whether any line uses the `dg` formulation.
    pub fn has_dg_lines(&self) -> bool {
        self.lines.iter().any(|l| l.dg.is_some())
    }

    /// Whether the statics must go through [`System::statics_twin`]: `dg` lines or free
    /// bodies.
    pub fn needs_statics_twin(&self) -> bool {
        self.has_dg_lines() || !self.free_bodies.is_empty()
    }

    /// Scratch for this system.
    pub fn workspace(&self) -> Workspace {
        let end_kind = |p: usize| match (self.points[p].free_index, self.point_slot[p]) {
            (Some(f), _) => EndKind::Free(f),
            (None, Some(s)) => EndKind::Free(s),
            (None, None) => EndKind::Known,
        };
        let lines = self
            .lines
            .iter()
            .map(|l| {
                let n = l.mesh.elements();
                let m = l.vectors();
                LineWork {
                    position: vec![Vec3::zeros(); m],
                    velocity: vec![Vec3::zeros(); m],
                    force: vec![Vec3::zeros(); m],
                    elements: ElementState::new(n),
                    node_tension: vec![0.0; if l.dg.is_some() { n + 1 } else { 0 }],
                }
            })
            .collect();
        let blocks = self
            .lines
            .iter()
            .map(|l| {
                LineBlocks::banded(
                    l.block_vectors(),
                    l.kind.bandwidth(),
                    end_kind(l.end_a),
                    end_kind(l.end_b),
                    l.kind.consistent_mass(),
                )
            })
            .collect();
        Workspace {
            lines,
            blocks,
            points: vec![PointKinematics::default(); self.points.len()],
            coupled: CoupledSystem::with_bodies(
                self.free_points.len(),
                self.free_bodies.len(),
                self.point_slot.iter().flatten().count(),
            ),
            dg: self
                .lines
                .iter()
                .map(|l| l.dg.as_deref().map(DgWorkspace::new))
                .collect(),
            bodies: self.bodies.iter().map(|b| b.initial_kinematics()).collect(),
            winches: self
                .lines
                .iter()
                .map(|l| {
                    l.winch.as_ref().map(|_| WinchWork {
                        mesh: l.mesh.clone(),
                        initial_length: l.mesh.length(),
                        length: l.mesh.length(),
                        state: Default::default(),
                    })
                })
                .collect(),
            wave_points: WavePoints::Direct,
        }
    }

    /// Sets every winch line's current mesh to its unstretched length at time t [s]:
    /// L(t) = L(0) + payout(t), each element l₀(t) = l₀(0) L(t)/L(0), σ = L̇/L
    /// ([`Mesh::rescale`]). Called at the start of every evaluation; no allocation.
    pub fn update_winches(&self, t: Real, ws: &mut Workspace) {
        for (l, w) in self.lines.iter().zip(ws.winches.iter_mut()) {
            let (Some(winch), Some(w)) = (&l.winch, w.as_mut()) else {
                continue;
            };
            let state = winch.state(t);
            let length = w.initial_length + state.payout;
            w.state = state;
            w.length = length;
            w.mesh
                .rescale(&l.mesh, length / w.initial_length, state.rate / length);
        }
    }

    /// The current mesh of a line: for a line on a winch, rescaled to its length at the
    /// time of the last evaluation in `ws`; otherwise the line's own.
    #[inline]
    pub fn line_mesh<'a>(&'a self, ws: &'a Workspace, line: usize) -> &'a Mesh {
        match &ws.winches[line] {
            Some(w) => &w.mesh,
            None => &self.lines[line].mesh,
        }
    }

    /// A state with every line straight between its ends, free bodies at their initial pose,
    /// and everything at rest.
    pub fn straight_state(&self) -> Vec<Real> {
        let mut y = vec![0.0; self.layout.len];
        for (b, off) in self.layout.body_offset.iter().enumerate() {
            if let Some(o) = off {
                let k = self.bodies[b].initial_kinematics();
                crate::bodies::write_state(&k, &mut y[*o..o + crate::bodies::STATE_LEN]);
            }
        }
        for (i, p) in self.points.iter().enumerate() {
            if let Some(o) = self.layout.point_offset[i] {
                set3(&mut y[o..], 0, &p.position);
            }
        }
        for (li, l) in self.lines.iter().enumerate() {
            let a = self.points[l.end_a].position;
            let b = self.points[l.end_b].position;
            let total = l.mesh.length();
            let o = self.layout.line_offset[li];
            if let Some(dg) = &l.dg {
                dg.straight(&mut y[o..o + self.layout.line_len[li]], a, b);
                continue;
            }
            let shape: Vec<Vec3> = (0..=l.mesh.elements())
                .map(|i| a + (b - a) * (l.mesh.arc_length(i) / total))
                .collect();
            l.set_shape(&shape, &mut y[o..]);
        }
        y
    }

    /// Sets line `line`'s unknowns in `y` from a continuous configuration: `shape(s)` gives the
    /// position [m] and velocity [m/s] at unstretched arc length s [m] from end A. The ends
    /// stay with their points (set free points through [`Layout::point_offset`]). This is the
    /// formulation-neutral way to start a line from a given shape: the nodes take it at their
    /// arc lengths and [`SystemLine::set_shape`] derives the other unknowns (`hermite`
    /// tangents and their rates by finite differences, exact for straight lines and linear in
    /// the shape, so a rigidly moved shape gives rigidly moved unknowns). A `dg` line takes
    /// the L2 projection of the shape, its tangent ∂r/∂s by fourth-order central differences
    /// with a step of 5 % of the shortest element (exact for polynomials of degree 4; the
    /// round-off is ~10⁻¹⁶ |r| / h).
    pub fn set_line_shape(
        &self,
        y: &mut [Real],
        line: usize,
        shape: impl Fn(Real) -> (Vec3, Vec3),
    ) {
        let l = &self.lines[line];
        if let Some(dg) = &l.dg {
            let o = self.layout.line_offset[line];
            let h = 5e-2 * l.mesh.shortest_element();
            dg.project(&mut y[o..o + self.layout.line_len[line]], |s| {
                let (r, v) = shape(s);
                let at = |k: Real| shape(s + k * h).0;
                let q = ((at(-2.0) - at(2.0)) + (at(1.0) - at(-1.0)) * 8.0) / (12.0 * h);
                (r, q, v)
            });
            return;
        }
        let (r, v): (Vec<Vec3>, Vec<Vec3>) =
            (0..l.nodes()).map(|i| shape(l.mesh.arc_length(i))).unzip();
        let o = self.layout.line_offset[line];
        let m = self.layout.line_interior[line];
        l.set_shape(&r, &mut y[o..o + 3 * m]);
        l.set_shape(&v, &mut y[o + 3 * m..o + 6 * m]);
    }

    /// Mechanical energy of the state `y` at time t [J]: kinetic energy ½ q̇ᵀ M q̇ of the lines
    /// (with the mass matrix of their formulation, without added mass) and of the free points
    /// (their own mass) and free bodies (½ m |v_G|² + ½ ωᵀ I ω), the potential of weight in air (γ0 g z integrated along the lines,
    /// m g z of the points: buoyancy and fluid forces are not conservative in general and are
    /// left out, so the sum is conserved only in air or vacuum without drag or damping), and
    /// the strain energy: axial ∫ ∫₀^ε T_e(e) de ds and, for `hermite`, bending ∫ ½ EI |r''|² ds.
    /// Each integral uses the formulation's own quadrature, so the potential is the one whose
    /// gradient the formulation's forces are. Fills `ws`'s line vectors and point kinematics.
    pub fn mechanical_energy(&self, t: Real, y: &[Real], ws: &mut Workspace) -> Energy {
        self.update_winches(t, ws);
        self.point_kinematics(t, y, ws);
        self.gather_lines(y, ws);
        let g = self.environment.gravity;
        let mut energy = Energy::default();
        for (li, l) in self.lines.iter().enumerate() {
            if let Some(dg) = &l.dg {
                let o = self.layout.line_offset[li];
                let state = &y[o..o + self.layout.line_len[li]];
                let ends = [
                    EndState::fixed(ws.points[l.end_a].position, Vec3::zeros()),
                    EndState::fixed(ws.points[l.end_b].position, Vec3::zeros()),
                ];
                energy += dg.energy(state, dg.position_base(state, &ends), g);
                continue;
            }
            let (q, qdot) = (&ws.lines[li].position, &ws.lines[li].velocity);
            let mesh = self.line_mesh(ws, li);
            for e in 0..mesh.elements() {
                energy += match &l.kind {
                    LineKind::Fe { mass_matrix } => {
                        crate::formulation::fe::element_energy(mesh, *mass_matrix, g, q, qdot, e)
                    }
                    LineKind::Hermite(options) => {
                        crate::formulation::hermite::element_energy(mesh, options, g, q, qdot, e)
                    }
                    LineKind::Dg => unreachable!("dg lines are summed above"),
                };
            }
        }
        for (p, point) in self.points.iter().enumerate() {
            if let PointKind::Free { mass, .. } = point.kind {
                let k = &ws.points[p];
                energy.kinetic += 0.5 * mass * k.velocity.norm_squared();
                energy.gravity += mass * g * k.position.z;
            }
        }
        for &b in &self.free_bodies {
            let (body, k) = (&self.bodies[b].body, &ws.bodies[b]);
            let (cg, v_cg, _) = k.point(&body.centre_of_gravity);
            let r = k.orientation.to_rotation_matrix();
            let inertia = r * body.inertia * r.transpose();
            let w = k.angular_velocity;
            energy.kinetic += 0.5 * body.mass * v_cg.norm_squared() + 0.5 * w.dot(&(inertia * w));
            energy.gravity += body.mass * g * cg.z;
        }
        energy
    }

    /// Updates the point kinematics at time t from the state (positions and velocities).
    /// The free end of a `dg` line keeps the kinematics its line gave it in the last
    /// evaluation ([`System::evaluate_dg_lines`]).
    /// Bodies first: free ones from the state (accelerations from the last solve are kept
    /// only by [`System::rhs`]), prescribed ones from their motion; points on bodies follow.
    pub fn point_kinematics(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        for (b, body) in self.bodies.iter().enumerate() {
            ws.bodies[b] = match (&body.body.kind, self.layout.body_offset[b]) {
                (_, Some(o)) => crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]),
                (crate::model::BodyKind::Prescribed(m), None) => m.kinematics(t),
                (crate::model::BodyKind::Free, None) => body.initial_kinematics(),
            };
        }
        for (i, p) in self.points.iter().enumerate() {
            if p.line_end.is_some() {
                continue;
            }
            ws.points[i] = match &p.kind {
                PointKind::Fixed => PointKinematics {
                    position: p.position,
                    ..Default::default()
                },
                PointKind::Prescribed(m) => {
                    let (position, velocity, acceleration) = m.kinematics(t);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
                PointKind::Free { .. } => {
                    let o = self.layout.point_offset[i].expect("free point has a state block");
                    PointKinematics {
                        position: get3(y, o / 3),
                        velocity: get3(y, o / 3 + 1),
                        acceleration: Vec3::zeros(),
                    }
                }
                PointKind::Body { body, offset } => {
                    let (position, velocity, acceleration) = ws.bodies[*body].point(offset);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
            };
        }
    }

    /// Fills each line's node positions and velocities from the state and its ends.
    /// `dg` lines fill theirs in [`System::evaluate_dg_lines`].
    pub fn gather_lines(&self, y: &[Real], ws: &mut Workspace) {
        for (li, l) in self.lines.iter().enumerate() {
            if l.dg.is_some() {
                continue;
            }
            let n = l.vectors() - 1;
            let o = self.layout.line_offset[li];
            let m = self.layout.line_interior[li];
            let lw = &mut ws.lines[li];
            lw.position[0] = ws.points[l.end_a].position;
            lw.velocity[0] = ws.points[l.end_a].velocity;
            lw.position[n] = ws.points[l.end_b].position;
            lw.velocity[n] = ws.points[l.end_b].velocity;
            for i in 1..n {
                lw.position[i] = get3(&y[o..], i - 1);
                lw.velocity[i] = get3(&y[o + 3 * m..], i - 1);
            }
        }
    }

    /// Forces of a free point's own physics [N] (weight, buoyancy, drag, external force) and
    /// its own mass matrix [kg] (mass plus added mass when submerged).
    pub fn point_own_load(
        &self,
        p: usize,
        k: &PointKinematics,
        t: Real,
        load_factor: Real,
    ) -> (Vec3, Mat3) {
        let PointKind::Free {
            mass,
            volume,
            drag_area,
            added_mass_coefficient,
            force,
        } = &self.points[p].kind
        else {
            return (Vec3::zeros(), Mat3::zeros());
        };
        let env = &self.environment;
        let rho = env.fluid_density(k.position.z);
        let submerged = k.position.z < 0.0;
        let mut f = Vec3::new(0.0, 0.0, -mass * env.gravity) + force * load_factor;
        let mut m = *mass;
        let (uw, aw) = env.fluid_kinematics(&k.position, t);
        if submerged {
            f.z += rho * volume * env.gravity;
            m += rho * volume * added_mass_coefficient;
            f += aw * (rho * volume * (1.0 + added_mass_coefficient));
        }
        let rel = uw * load_factor - k.velocity;
        f += rel * (0.5 * rho * drag_area * rel.norm());
        if let Some(contact) = &self.points[p].seabed_contact {
            f += contact.force(env.seabed_z(), &k.position, &k.velocity, &env.seabed);
        }
        (f, Mat3::identity() * m)
    }

    /// Right-hand side of the equations of motion: dy/dt at (t, y).
    ///
    /// Lines: M a = F with M block-tridiagonal (consistent) or block-diagonal (lumped); free
    /// points: (m_p + added mass + the line ends' mass) a_p = F_p + Σ line end forces. Solved
    /// together in O(nodes) by [`CoupledSystem`]. `dg` lines are evaluated first, with their
    /// ends' kinematics at t ([`System::evaluate_dg_lines`]): their flux tractions enter the
    /// points' forces and their ends add no mass (explicit coupling, DG paper §3.3).
    pub fn rhs(
        &self,
        t: Real,
        y: &[Real],
        dydt: &mut [Real],
        ws: &mut Workspace,
    ) -> Result<(), Location> {
        self.prepare_wave_tables(t, ws);
        self.point_kinematics(t, y, ws);
        self.evaluate_dg_lines(t, y, dydt, ws);
        self.assemble_loads(t, y, ws);
        ws.coupled
            .solve(&mut ws.blocks)
            .map_err(|s| self.singular_location(s))?;
        // Write dy/dt.
        for (li, l) in self.lines.iter().enumerate() {
            if l.dg.is_some() {
                continue;
            }
            let o = self.layout.line_offset[li];
            let m = self.layout.line_interior[li];
            let lw = &ws.lines[li];
            let acc = &ws.blocks[li].x;
            for i in 1..l.vectors() - 1 {
                set3(&mut dydt[o..], i - 1, &lw.velocity[i]);
                set3(&mut dydt[o + 3 * m..], i - 1, &acc[i]);
            }
        }
        for (f, &p) in self.free_points.iter().enumerate() {
            let o = self.layout.point_offset[p].expect("free point");
            set3(&mut dydt[o..], 0, &ws.points[p].velocity);
            set3(&mut dydt[o..], 1, &ws.coupled.point_x[f]);
            ws.points[p].acceleration = ws.coupled.point_x[f];
        }
        for (f, &b) in self.free_bodies.iter().enumerate() {
            let o = self.layout.body_offset[b].expect("free body");
            let u = ws.coupled.body_x[f];
            let k = &mut ws.bodies[b];
            k.acceleration = Vec3::new(u[0], u[1], u[2]);
            k.angular_acceleration = Vec3::new(u[3], u[4], u[5]);
            crate::bodies::write_rate(
                k,
                &k.acceleration,
                &k.angular_acceleration,
                &mut dydt[o..o + crate::bodies::STATE_LEN],
            );
        }
        for (p, slot) in self.point_slot.iter().enumerate() {
            if let Some(s) = slot {
                ws.points[p].acceleration = ws.coupled.slot_x[*s];
            }
        }
        Ok(())
    }

    /// Evaluates every `dg` line at (t, y) with its ends' kinematics from `ws.points` (filled
    /// by [`System::point_kinematics`]): writes its state's rate into `dydt`, its end loads
    /// (the force on each attachment [N]) into `ws.lines[l].force[0]` and `[N]`, its node
    /// outputs into `ws.lines[l]`, and the kinematics of a free end's point.
    pub fn evaluate_dg_lines(&self, t: Real, y: &[Real], dydt: &mut [Real], ws: &mut Workspace) {
        for (li, l) in self.lines.iter().enumerate() {
            let (Some(dg), Some(dws)) = (&l.dg, ws.dg[li].as_mut()) else {
                continue;
            };
            let range =
                self.layout.line_offset[li]..self.layout.line_offset[li] + self.layout.line_len[li];
            let end_state = |side: usize, p: usize| {
                let k = &ws.points[p];
                let force = match (&self.points[p].kind, dg.ends[side].translation) {
                    (PointKind::Free { force, .. }, Translation::Force) => *force,
                    _ => Vec3::zeros(),
                };
                EndState {
                    position: k.position,
                    velocity: k.velocity,
                    acceleration: k.acceleration,
                    force,
                    moment: Vec3::zeros(),
                    direction: l.clamp[side].unwrap_or_else(Vec3::zeros),
                    direction_rate: Vec3::zeros(),
                }
            };
            let ends = [end_state(0, l.end_a), end_state(1, l.end_b)];
            let loads = dg.rhs_with(
                &self.environment,
                ws.wave_points.of_line(li),
                t,
                &y[range.clone()],
                &ends,
                &mut dydt[range.clone()],
                dws,
            );
            let n = l.mesh.elements();
            let lw = &mut ws.lines[li];
            dg.sample(
                &y[range],
                dws,
                &loads,
                &mut lw.position,
                &mut lw.velocity,
                &mut lw.node_tension,
                &mut lw.elements,
            );
            lw.force[0] = loads[0].force;
            lw.force[n] = loads[1].force;
            for (side, p) in [(0, l.end_a), (1, l.end_b)] {
                if self.points[p].line_end.is_some() {
                    let node = if side == 0 { 0 } else { n };
                    ws.points[p] = PointKinematics {
                        position: lw.position[node],
                        velocity: lw.velocity[node],
                        acceleration: Vec3::zeros(),
                    };
                }
            }
        }
    }

    /// The equations of motion at (t, y), assembled but not solved: point kinematics (free
    /// points from the state, others from their motion, with their accelerations), node
    /// positions and velocities, node forces `ws.lines[l].force` and mass blocks
    /// `ws.blocks[l]` (whose `x` holds the forces, with the known accelerations at ends on
    /// fixed or prescribed points), and each free point's own load and mass in
    /// `ws.coupled.point_x`, `ws.coupled.point_diag`.
    pub fn assemble(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        self.prepare_wave_tables(t, ws);
        self.point_kinematics(t, y, ws);
        self.assemble_loads(t, y, ws);
    }

    /// [`System::assemble`] after [`System::point_kinematics`] (and, for `dg` lines,
    /// [`System::evaluate_dg_lines`]) at the same (t, y).
    fn assemble_loads(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        self.update_winches(t, ws);
        self.gather_lines(y, ws);
        for (li, l) in self.lines.iter().enumerate() {
            let options = LoadOptions {
                current_factor: 1.0,
                fluid: ws.wave_points.of_line(li),
            };
            let lw = &mut ws.lines[li];
            let blocks = &mut ws.blocks[li];
            if l.dg.is_some() {
                // The end tractions of the last `dg` evaluation, as forces on the points.
                let n = l.vectors() - 1;
                blocks.x[0] = match blocks.end_a {
                    EndKind::Known => ws.points[l.end_a].acceleration,
                    _ => lw.force[0],
                };
                blocks.x[1] = match blocks.end_b {
                    EndKind::Known => ws.points[l.end_b].acceleration,
                    _ => lw.force[n],
                };
                continue;
            }
            let mesh = match &ws.winches[li] {
                Some(w) => &w.mesh,
                None => &l.mesh,
            };
            line_forces(
                mesh,
                &l.kind,
                &self.environment,
                t,
                &lw.position,
                &lw.velocity,
                &mut lw.force,
                &mut lw.elements,
                Some(blocks),
                options,
            );
            let n = l.vectors() - 1;
            blocks.x.copy_from_slice(&lw.force);
            l.apply_clamps(blocks);
            if blocks.end_a == EndKind::Known {
                blocks.x[0] = ws.points[l.end_a].acceleration;
            }
            if blocks.end_b == EndKind::Known {
                blocks.x[n] = ws.points[l.end_b].acceleration;
            }
        }
        for (f, &p) in self.free_points.iter().enumerate() {
            let (force, mass) = self.point_own_load(p, &ws.points[p], t, 1.0);
            ws.coupled.point_x[f] = force;
            ws.coupled.point_diag[f] = mass;
        }
        self.assemble_bodies(t, ws);
    }

    /// Each free body's own loads and 6×6 mass as its block of the coupled system, and the
    /// offsets and centripetal accelerations of its points' slots. (A prescribed body's own
    /// loads do not enter the equations: its points are known ends.)
    fn assemble_bodies(&self, t: Real, ws: &mut Workspace) {
        for (f, &b) in self.free_bodies.iter().enumerate() {
            let loads = self.bodies[b]
                .body
                .loads(&ws.bodies[b], &self.environment, t);
            ws.coupled.body_diag[f] = loads.mass;
            ws.coupled.body_x[f] = loads.generalized();
        }
        let np = self.free_points.len();
        for (p, slot) in self.point_slot.iter().enumerate() {
            let (Some(s), PointKind::Body { body, offset }) = (slot, &self.points[p].kind) else {
                continue;
            };
            let k = &ws.bodies[*body];
            let rho = k.orientation * offset;
            let w = k.angular_velocity;
            ws.coupled.body_slots[s - np] = crate::linalg::BodySlot {
                body: self.bodies[*body]
                    .free_index
                    .expect("a slot is on a free body"),
                offset: rho,
                bias: w.cross(&w.cross(&rho)),
            };
        }
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
            let m = self.layout.line_interior[li];
            if let Some(dg) = &l.dg {
                if index >= o && index < o + self.layout.line_len[li] {
                    // The element whose coefficients hold the entry, named by its end A node.
                    let node = dg.elements.partition_point(|el| o + el.state <= index) - 1;
                    return Location {
                        object: l.name.clone(),
                        node,
                    };
                }
                continue;
            }
            if index >= o && index < o + 6 * m {
                let node = ((index - o) % (3 * m)) / 3 + 1;
                return Location {
                    object: l.name.clone(),
                    node,
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
    /// last right-hand-side evaluation: the end node's share of the line's forces minus the
    /// inertia of its share of the line's mass, F_end − (M_ee a_e + M_en a_n).
    /// For a `dg` line it is the traction of the numerical flux at that end.
    pub fn end_force(&self, ws: &Workspace, line: usize, end_b: bool) -> Vec3 {
        let lw = &ws.lines[line];
        let n = self.lines[line].vectors() - 1;
        if self.lines[line].dg.is_some() {
            return lw.force[if end_b { n } else { 0 }];
        }
        let b = &ws.blocks[line];
        let node = if end_b { n } else { 0 };
        lw.force[node] - b.row_times_x(node)
    }

    /// The time step of the elastic-link paper's condition Δt ≤ C_k l / c (eq. 48) over every
    /// element [s], at the strains in `ws` (from the last evaluation), with c the faster of the
    /// axial wave √(EA_t/γ0) (EA_t the tangent stiffness) and the transverse wave √(T/γ0)
    /// (the paper's eq. 49), and l the unstretched element length (the waves travel
    /// √(EA/γ0) metres of unstretched cable per second); and the line and element that set it.
    pub fn wave_step(&self, ws: &Workspace, c_k: Real) -> (Real, usize, usize) {
        let mut best = (Real::INFINITY, 0, 0);
        for li in 0..self.lines.len() {
            let el = &ws.lines[li].elements;
            let mesh = self.line_mesh(ws, li);
            for (e, &k) in mesh.element_section.iter().enumerate() {
                let s = &mesh.sections[k];
                let gamma = s.line_type.mass_per_length;
                let axial = s.law.stiffness.max_tangent() / gamma;
                let transverse = el.tension[e].max(0.0) / gamma;
                let c = axial.max(transverse).sqrt();
                let dt = c_k * s.element_length / c;
                if dt < best.0 {
                    best = (dt, li, e);
                }
            }
        }
        best
    }

    /// Tension [N] at node i of a line: the mean of its elements' tensions at interior nodes
    /// and the magnitude of the end force at the ends.
    /// `dg` lines give the tension at the element ends (the mean of the two sides at an
    /// interface).
    pub fn node_tension(&self, ws: &Workspace, line: usize, node: usize) -> Real {
        let n = self.lines[line].mesh.elements();
        if self.lines[line].dg.is_some() {
            return ws.lines[line].node_tension[node];
        }
        let t = &ws.lines[line].elements.tension;
        if node == 0 {
            self.end_force(ws, line, false).norm()
        } else if node == n {
            self.end_force(ws, line, true).norm()
        } else {
            0.5 * (t[node - 1] + t[node])
        }
    }

    /// Largest stable time step [s] of `scheme` for this system, and what sets it.
    ///
    /// The linearised equations at a node are M ẍ + C ẋ + K x = 0. For an eigenvector, with
    /// the Rayleigh quotients m, c, k, λ² m + λ c + k = 0, so |λ| ≤ max(c/m, √(k/m)) (the
    /// larger root is √(k/m) when underdamped and below c/m when overdamped). We bound c and k
    /// by Gershgorin row sums at every node, and m by the node's smallest mass: the lumped
    /// mass (γ0 + ρA·min(C_an, C_at)) L_node, a third of it for the consistent mass matrix
    /// (whose top mode has that mass), plus a free point's own mass and added mass.
    ///
    /// Rows per adjacent element: axial stiffness 2·EA_max/L0 and damping 2·c/L0. Where the
    /// line can reach the seabed, the contact spring K_g d L0/2 and damper 2ζ√(K_g d γ0) L0/2
    /// act vertically and the friction, linearised about rest, μ|w|π/v_μ · L0/2, horizontally
    /// (DG paper eqs. 15–16). A line resting on the bed is horizontal, so the vertical bound
    /// takes the contact terms alone and the horizontal bound the axial terms plus friction.
    /// The step is R/|λ|max with R the smallest radius of the scheme's stability region over
    /// the left half-plane: RK4 2.6 (2.615 computed), SSP-RK3 1.7 (1.732).
    pub fn stable_step(&self, scheme: Scheme) -> (Real, String) {
        let radius = match scheme {
            Scheme::Rk4 => 2.6,
            Scheme::SspRk3 => 1.7,
            // The predictor–corrector on ẍ = −ω²x gives x^{n+1} = (2 − 2h² + h⁴) x^n −
            // (1 − h²) x^{n−1}, h = ωΔt, whose roots stay in the unit disc for h ≤ 1
            // (derived in integrate/three_level.rs): half the central difference's limit.
            Scheme::ThreeLevel => 1.0,
        };
        let env = &self.environment;
        let rho = env.water_density;
        let seabed = &env.seabed;
        let mut point_rows = vec![NodeRows::default(); self.points.len()];
        for (i, p) in self.points.iter().enumerate() {
            if let PointKind::Free {
                mass,
                volume,
                added_mass_coefficient,
                ..
            } = &p.kind
            {
                point_rows[i].mass = mass + rho * volume * added_mass_coefficient;
            }
        }
        let mut worst = 0.0;
        let mut culprit = String::from("nothing (no elements)");
        let (lambda_axial, lambda_bending) =
            crate::formulation::hermite::element_eigenvalue_bounds();
        for l in &self.lines {
            if let Some(dg) = &l.dg {
                // The DG CFL limit (calibrated for SSP-RK3, whose stability region RK4's
                // contains on both axes, so it serves RK4 too), as a rate for this scheme.
                let lambda = radius / crate::formulation::dg::stable_step(dg, 1.0);
                if lambda > worst {
                    worst = lambda;
                    culprit = format!(
                        "the dg CFL limit (axial waves, bending and damping at orders {}) of line {}",
                        dg.sections
                            .iter()
                            .map(|s| s.basis.order.to_string())
                            .collect::<Vec<_>>()
                            .join(", "),
                        l.name
                    );
                }
                // A free point at a dg end feels the flux's axial impedance Z = γ0 c as a
                // damper (T̂ = T⁺ + Z (ν_point − ν⁺)).
                let n = dg.elements.len();
                for (p, e) in [(l.end_a, 0), (l.end_b, n - 1)] {
                    let sec = dg.section(e);
                    point_rows[p].axial_damping +=
                        sec.properties.line_type.mass_per_length * sec.wave_speed;
                }
                continue;
            }
            // A line on a winch: its shortest elements (at its shortest length over the
            // schedule) give the largest stiffness and damping rows, 2 EA/l₀ and 2c/l₀ over a
            // mass ∝ l₀ (the rate grows as 1/l₀); its longest reaches the seabed first.
            let scaled;
            let (mesh, longest) = match &l.winch {
                Some(w) => {
                    let ((low, _), (high, _)) = w.payout_range();
                    let length = l.mesh.length();
                    let mut m = l.mesh.clone();
                    m.rescale(&l.mesh, (length + low) / length, 0.0);
                    scaled = m;
                    (&scaled, length + high)
                }
                None => (&l.mesh, l.mesh.length()),
            };
            let n = mesh.elements();
            let hermite = matches!(l.kind, LineKind::Hermite(_));
            let mass_factor = if l.kind.consistent_mass() {
                1.0 / 3.0
            } else {
                1.0
            };
            // Can this line touch the seabed? Its lowest possible point is its lower end minus
            // its length.
            let low = self.points[l.end_a]
                .position
                .z
                .min(self.points[l.end_b].position.z);
            let reaches_bed =
                env.depth.is_finite() && seabed.stiffness > 0.0 && low - longest <= env.seabed_z();
            // The obstacles this line may touch, as the seabed: a fixed one within its length
            // of an end (its bounding ball), a moving one always. Each adds its contact
            // stiffness k and damping c per unit length over a node's share of the line;
            // several add (a node wedged between two). Friction is left out: its slope
            // μ N π / v_μ grows with the normal force N, which here is the tension's pull
            // round the obstacle, unknown before the run (the seabed's is the wet weight).
            let touching: Vec<&crate::physics::obstacles::Obstacle> = env
                .obstacles
                .iter()
                .filter(|o| {
                    !matches!(o.motion, crate::model::Motion::Fixed { .. })
                        || [l.end_a, l.end_b].iter().any(|&p| {
                            let centre = o.kinematics(0.0).centre;
                            (self.points[p].position - centre).norm() - o.bounding_radius()
                                <= longest
                        })
                })
                .collect();
            let mut rows = vec![NodeRows::default(); n + 1];
            let describe = |what: &str, at: String, s: &crate::formulation::SectionProperties| {
                format!(
                    "{what} at line {} {at} (element length {:.4} m, axial wave speed {:.1} m/s)",
                    l.name,
                    s.element_length,
                    (s.law.stiffness.max_tangent() / s.line_type.mass_per_length).sqrt()
                )
            };
            for e in 0..n {
                let s = mesh.section(e);
                let lt = &s.line_type;
                let l0 = s.element_length;
                let gamma = lt.mass_per_length
                    + rho * s.area * lt.normal_added_mass.min(lt.tangential_added_mass).max(0.0);
                let mut add = NodeRows {
                    mass: gamma * 0.5 * l0 * mass_factor,
                    axial_damping: 2.0 * s.law.damping / l0,
                    axial_stiffness: 2.0 * s.law.stiffness.max_tangent() / l0,
                    ..Default::default()
                };
                if reaches_bed {
                    let kd = seabed.stiffness * lt.diameter;
                    add.contact_stiffness = kd * 0.5 * l0;
                    add.contact_damping =
                        seabed.damping_per_length(lt.diameter, lt.mass_per_length) * 0.5 * l0;
                    let wet = (lt.mass_per_length - rho * s.area) * env.gravity;
                    if seabed.friction_coefficient > 0.0 && wet > 0.0 {
                        // per node: the node carries at least half this element
                        add.friction_damping = seabed.friction_slope(wet, 0.5 * l0) * 0.5 * l0;
                    }
                }
                for o in &touching {
                    add.obstacle_stiffness += o.stiffness * 0.5 * l0;
                    add.obstacle_damping += o.damping_per_length(lt.mass_per_length) * 0.5 * l0;
                }
                if hermite {
                    // Element bound (Irons): the assembled line's frequencies are below the
                    // element's, whose pencils scale as λ EA/(γ l²) and λ_b EI/(γ l⁴); the
                    // contact, integrated with the mass's own quadrature, as K_g d/γ.
                    let element = NodeRows {
                        mass: gamma * l0,
                        axial_damping: lambda_axial * s.law.damping / l0,
                        axial_stiffness: lambda_axial * s.law.stiffness.max_tangent() / l0,
                        bending_stiffness: lambda_bending * lt.bending_stiffness / (l0 * l0 * l0),
                        bending_damping: lambda_bending * lt.bending_damping / (l0 * l0 * l0),
                        contact_stiffness: 2.0 * add.contact_stiffness,
                        contact_damping: 2.0 * add.contact_damping,
                        friction_damping: 2.0 * add.friction_damping,
                        obstacle_damping: 2.0 * add.obstacle_damping,
                        obstacle_stiffness: 2.0 * add.obstacle_stiffness,
                    };
                    let (lambda, what) = element.bound();
                    if lambda > worst {
                        worst = lambda;
                        culprit = describe(what, format!("element {e}"), s);
                    }
                }
                rows[e].add(&add);
                rows[e + 1].add(&add);
            }
            for (node, row) in rows.iter().enumerate() {
                let end = if node == 0 {
                    Some(l.end_a)
                } else if node == n {
                    Some(l.end_b)
                } else {
                    None
                };
                if let Some(p) = end {
                    // End nodes move with their point: only free points are unknowns.
                    if self.points[p].free_index.is_some() || self.point_slot[p].is_some() {
                        point_rows[p].add(row);
                    }
                    continue;
                }
                if hermite {
                    continue;
                }
                let (lambda, what) = row.bound();
                if lambda > worst {
                    worst = lambda;
                    culprit = describe(what, format!("node {node}"), mesh.section(node.min(n - 1)));
                }
            }
        }
        // A point on a free body moves the body: its line ends act on the body's mass (its
        // smallest translational mass, mass plus the smallest added mass).
        for (p, slot) in self.point_slot.iter().enumerate() {
            if slot.is_some()
                && let PointKind::Body { body, .. } = self.points[p].kind
            {
                let b = &self.bodies[body].body;
                point_rows[p].mass += b.mass + b.added_mass.fixed_rows::<3>(0).min().max(0.0);
            }
        }
        for &b in &self.free_bodies {
            let (lambda, what) = self.bodies[b]
                .body
                .own_rate(self.environment.water_density, self.environment.gravity);
            if lambda > worst {
                worst = lambda;
                culprit = format!("{what} of body {}", self.bodies[b].body.name);
            }
        }
        for (p, row) in point_rows.iter().enumerate() {
            if (self.points[p].free_index.is_some() || self.point_slot[p].is_some())
                && row.mass > 0.0
            {
                let (lambda, what) = row.bound();
                if lambda > worst {
                    worst = lambda;
                    culprit = format!(
                        "{what} at free point {} and its line ends",
                        self.points[p].name
                    );
                }
            }
        }
        if worst == 0.0 {
            return (Real::INFINITY, culprit);
        }
        (radius / worst, culprit)
    }
}

/// Seabed contact of a free point: a sphere of the point's displaced volume pressing on the
/// bed with the ground stiffness K_g over its projected area, k = K_g π r² [N/m], damped at
/// the seabed's damping ratio of the point's own critical damping, with sliding friction
/// μ N tanh(π|v_xy|/v_μ) (the line contact of DG paper eqs. 15–16 applied to a sphere).
#[derive(Clone, Copy, Debug)]
struct SphereContact {
    radius: Real,
    stiffness: Real,
    damping: Real,
}

impl SphereContact {
    /// The contact of a free point with a volume V (mass with added mass m), modelled as a
    /// sphere of that volume; `None` for other points, without a seabed, or without a volume
    /// (a joint or a point mass has no extent to rest on).
    fn new(env: &Environment, kind: &PointKind) -> Option<Self> {
        let PointKind::Free {
            mass,
            volume,
            added_mass_coefficient,
            ..
        } = kind
        else {
            return None;
        };
        let m = mass + env.water_density * volume * added_mass_coefficient;
        if !(env.depth.is_finite() && env.seabed.stiffness > 0.0 && *volume > 0.0 && *mass > 0.0) {
            return None;
        }
        let radius = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
        let stiffness = env.seabed.stiffness * std::f64::consts::PI * radius * radius;
        Some(Self {
            radius,
            stiffness,
            damping: env.seabed.damping_of_area(
                std::f64::consts::PI * radius * radius,
                stiffness,
                m,
            ),
        })
    }

    fn force(
        &self,
        bed_z: Real,
        position: &Vec3,
        velocity: &Vec3,
        seabed: &crate::physics::seabed::Seabed,
    ) -> Vec3 {
        let penetration = bed_z - (position.z - self.radius);
        if penetration <= 0.0 {
            return Vec3::zeros();
        }
        let normal = self.stiffness * penetration - self.damping * velocity.z;
        let mut f = Vec3::new(0.0, 0.0, normal);
        let vxy = Vec3::new(velocity.x, velocity.y, 0.0);
        let speed = vxy.norm();
        if seabed.friction_coefficient > 0.0 && speed > 0.0 && normal > 0.0 {
            f -= vxy * (seabed.friction(speed, normal, 1.0) / speed);
        }
        f
    }
}

/// Gershgorin row sums of one node's linearised mass, damping and stiffness, by direction.
#[derive(Clone, Copy, Debug, Default)]
struct NodeRows {
    mass: Real,
    axial_damping: Real,
    axial_stiffness: Real,
    contact_damping: Real,
    contact_stiffness: Real,
    friction_damping: Real,
    bending_damping: Real,
    bending_stiffness: Real,
    obstacle_damping: Real,
    obstacle_stiffness: Real,
}

impl NodeRows {
    fn add(&mut self, o: &NodeRows) {
        self.mass += o.mass;
        self.axial_damping += o.axial_damping;
        self.axial_stiffness += o.axial_stiffness;
        self.contact_damping += o.contact_damping;
        self.contact_stiffness += o.contact_stiffness;
        self.friction_damping += o.friction_damping;
        self.bending_damping += o.bending_damping;
        self.bending_stiffness += o.bending_stiffness;
        self.obstacle_damping += o.obstacle_damping;
        self.obstacle_stiffness += o.obstacle_stiffness;
    }

    /// Bound on |λ| [1/s] and the term that sets it.
    fn bound(&self) -> (Real, &'static str) {
        let m = self.mass;
        [
            (
                (self.axial_damping + self.friction_damping) / m,
                if self.friction_damping > 0.0 {
                    "axial damping and seabed friction"
                } else {
                    "axial damping"
                },
            ),
            ((self.axial_stiffness / m).sqrt(), "axial stiffness"),
            (self.contact_damping / m, "seabed contact damping"),
            (
                (self.contact_stiffness / m).sqrt(),
                "seabed contact stiffness",
            ),
            (self.bending_damping / m, "bending damping"),
            ((self.bending_stiffness / m).sqrt(), "bending stiffness"),
            (self.obstacle_damping / m, "obstacle contact damping"),
            (
                (self.obstacle_stiffness / m).sqrt(),
                "obstacle contact stiffness",
            ),
        ]
        .into_iter()
        .fold((0.0, "nothing"), |a, b| if b.0 > a.0 { b } else { a })
    }
}
