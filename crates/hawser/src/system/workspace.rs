//! The scratch of the right-hand side, sized once at assembly: no allocation in the time loop.

use super::*;
use crate::formulation::dg::DgWorkspace;
use crate::formulation::{ElementState, Mesh};
use crate::linalg::{CoupledSystem, EndKind, LineBlocks};
use crate::math::{Real, Vec3};
use crate::model::PointKind;

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
    /// The host's kinematics of the coupled points and bodies over the current coupling
    /// interval, sized once.
    pub coupling: CouplingTracks,
    /// The run's wave kinematics at the static position, if it asks for them
    /// ([`System::start_wave_tables`]); direct summation otherwise.
    pub wave_points: WavePoints,
    /// Per point: the last evaluation of the rigid motion it is the source of
    /// ([`System::rigid_motion_source`]) and its time [s], reused by
    /// [`System::point_kinematics`] at the same time (a Runge–Kutta step evaluates the
    /// motion at t + Δt/2 twice, and at t + Δt where the next step starts). A system's
    /// motions do not change once it is built, so an entry is its motion's value at that time.
    pub rigid_motions: Vec<Option<(Real, crate::model::RigidKinematics)>>,
}

/// The kinematics a coupling host has set ([`crate::model::PointTrack`],
/// [`crate::model::BodyTrack`]): per point and per body, `Some` for the coupled ones.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CouplingTracks {
    /// Per point.
    pub points: Vec<Option<crate::model::PointTrack>>,
    /// Per body.
    pub bodies: Vec<Option<crate::model::BodyTrack>>,
}

impl System {
    /// Scratch for this system.
    pub fn workspace(&self) -> Workspace {
        let end_kind = |p: usize| self.end_kind(p);
        let lines = self.lines.iter().map(SystemLine::work).collect();
        let blocks = self
            .lines
            .iter()
            .map(|l| l.blocks(end_kind(l.end_a), end_kind(l.end_b)))
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
            dg: self.lines.iter().map(SystemLine::dg_work).collect(),
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
            rigid_motions: vec![None; self.points.len()],
            coupling: CouplingTracks {
                points: self
                    .points
                    .iter()
                    .map(|p| {
                        matches!(p.kind, PointKind::Coupled)
                            .then(|| crate::model::PointTrack::at_rest(p.position))
                    })
                    .collect(),
                bodies: self
                    .bodies
                    .iter()
                    .map(|b| {
                        matches!(
                            b.body.kind,
                            crate::model::BodyKind::Coupled
                                | crate::model::BodyKind::Pinned(crate::model::Pin::Coupled)
                        )
                        .then(|| {
                            crate::model::BodyTrack::at_rest(b.body.position, b.body.orientation)
                        })
                    })
                    .collect(),
            },
        }
    }

    /// What a line end attached to point `p` is in the coupled solve: the slot of a free
    /// point or of a point on a free body, or a known end.
    pub fn end_kind(&self, p: usize) -> EndKind {
        match (self.points[p].free_index, self.point_slot[p]) {
            (Some(f), _) => EndKind::Free(f),
            (None, Some(s)) => EndKind::Free(s),
            (None, None) => EndKind::Known,
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
}

impl Workspace {
    /// Whether the last evaluation met a state that is not finite: a node, point or body
    /// position or velocity, or a line force. A mass solve that fails on such a state is a
    /// blow-up within the step, not a singular mass matrix.
    pub fn holds_non_finite(&self) -> bool {
        let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
        self.lines.iter().any(|l| {
            !(l.position.iter().all(finite)
                && l.velocity.iter().all(finite)
                && l.force.iter().all(finite))
        }) || self
            .points
            .iter()
            .any(|p| !(finite(&p.position) && finite(&p.velocity)))
            || self
                .bodies
                .iter()
                .any(|b| !(finite(&b.position) && finite(&b.velocity)))
    }
}
