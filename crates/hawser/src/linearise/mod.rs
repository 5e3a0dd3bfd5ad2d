//! Linearisation of the system about a static state: tangent stiffness, mass (with added mass)
//! and linearised damping, assembled in the block structure of the dynamics.
//!
//! About an equilibrium x₀ at rest, small motions x(t) = x₀ + u(t) obey
//!
//!   M ü + C u̇ + K u = 0,   K = −∂F/∂x,   C = −∂F/∂v,   M = the mass matrix at x₀,
//!
//! with F the nodal forces of the dynamics (the same `line_forces` and point loads that the
//! time integration evaluates: no second implementation of the physics). K and C are finite
//! differences of those forces, coloured three ways per line as a node only moves its
//! neighbours' forces ([`force_jacobian`], which Newton statics uses too). M is the mass the
//! dynamics assembles: structural plus added mass, consistent or lumped as the line asks,
//! plus the free points' own mass and added mass.
//!
//! Degrees of freedom are grouped by owner ([`DofOwner`]): the interior vectors of every line
//! (node positions, and a `hermite` line's tangents), then every free point, three
//! translations each, then every free rigid body, a group of three translations of its origin
//! and a group of three small rotations δθ about global axes. Fixed, prescribed and coupled
//! points and bodies are not degrees of freedom: their motion is given. A line end on a point
//! of a free body moves with the body, δx = δr + δθ × ρ (ρ the point's offset at the static
//! pose), so the line's rows and columns there join the body's through J = [1, −[ρ]×]
//! ([`DofTarget::Body`]); the body adds its own 6×6 blocks ([`bodies`]): its mass with added
//! mass, the stiffness of its own loads (hydrostatics) and the geometric stiffness
//! −Σ_p [F_p]× [ρ_p]× of the line forces F_p turning with it. [`body_stiffness`] condenses the
//! lines onto each body: the 6×6 mooring stiffness K₆ = Σ_pq J_pᵀ K_pq J_q + the geometric
//! term.

use crate::formulation::{LoadOptions, line_forces};
use crate::linalg::{BodySlot, CoupledSystem, EndKind, LineBlocks, Singular};
use crate::math::{Mat3, Mat3x6, Mat6, Real, Vec3, Vec6, get3, skew};
use crate::model::PointKind;
use crate::system::{System, Workspace};
use nalgebra::DMatrix;

mod bodies;
pub use bodies::{BodyStiffness, body_stiffness};

/// Which state variable a force Jacobian differentiates by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variable {
    /// Node and point positions: ∂F/∂x [N/m].
    Position,
    /// Node and point velocities: ∂F/∂v [N·s/m].
    Velocity,
}

/// Finite-difference formula of a force Jacobian.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Difference {
    /// (F(x + h) − F(x))/h with h = 10⁻⁶ L0: one evaluation per colour and axis, error
    /// O(h·F''). Enough for Newton's convergence.
    Forward,
    /// (F(x + h) − F(x − h))/2h with h = 4·10⁻⁶ L0 (positions) or 10⁻⁶ m/s (velocities):
    /// twice the cost, error O(h²·F''') + O(ε_mach F/h). The even second-order term cancels,
    /// which matters for the transverse stiffness T/L of a taut, stiff cable: a transverse
    /// step h stretches the element by h²/2L, whose tension change EA h²/2L² would swamp
    /// T h/L in a forward difference once EA/T exceeds about 10⁶ (1 % error).
    Central,
}

/// Finite-difference step [m] for positions of line `line`: a fraction of its shortest
/// element.
fn position_step(system: &System, line: usize, difference: Difference) -> Real {
    let min_l0 = system.lines[line].mesh.shortest_element();
    match difference {
        Difference::Forward => 1e-6 * min_l0,
        Difference::Central => 4e-6 * min_l0,
    }
}

/// Finite-difference step of velocities [m/s]: small against the friction velocity v_μ
/// (0.01 m/s by default) so that the tanh of seabed friction is in its linear range, large
/// against round-off of the forces.
const VELOCITY_STEP: Real = 1e-6;

/// Finite-difference step of free-point positions [m] (their own loads: weight, buoyancy,
/// drag, seabed contact vary on metre scales).
const POINT_POSITION_STEP: Real = 1e-6;

/// Sets the workspace's kinematics to the static state `y`: positions from the state,
/// prescribed points at their t = 0 positions, every velocity zero; in a steady tow
/// ([`System::tow_velocity`] V ≠ 0) every point and line node moves at `load_factor`·V instead
/// (the frame moving with the vessel, scaled with the current by load continuation), line
/// tangents and bodies' rotations at rest.
pub(crate) fn kinematics_at_rest(
    system: &System,
    y: &[Real],
    load_factor: Real,
    ws: &mut Workspace,
) {
    let v = system.tow_velocity * load_factor;
    system.point_kinematics(0.0, y, ws);
    for k in ws.points.iter_mut() {
        k.velocity = v;
    }
    system.gather_lines(y, ws);
    for (li, lw) in ws.lines.iter_mut().enumerate() {
        let l = &system.lines[li];
        for (j, x) in lw.velocity.iter_mut().enumerate() {
            *x = if l.is_tangent(j) { Vec3::zeros() } else { v };
        }
    }
}

/// Evaluates every line's forces at the static state `y` (see [`kinematics_at_rest`]) into
/// `ws.lines[..].force`, and its mass blocks into `ws.blocks` when `with_mass`.
pub(crate) fn line_forces_at_rest(
    system: &System,
    y: &[Real],
    current_factor: Real,
    with_mass: bool,
    ws: &mut Workspace,
) {
    kinematics_at_rest(system, y, current_factor, ws);
    for (li, l) in system.lines.iter().enumerate() {
        let lw = &mut ws.lines[li];
        line_forces(
            &l.mesh,
            &l.discretisation,
            &system.environment,
            0.0,
            &lw.position,
            &lw.velocity,
            &mut lw.force,
            &mut lw.elements,
            with_mass.then_some(&mut ws.blocks[li]),
            LoadOptions::direct(current_factor),
        );
    }
}

/// The force Jacobian ∂F/∂x or ∂F/∂v at state `y`, at rest and with prescribed points at
/// their t = 0 positions (the static state), into `ws.blocks` (per line, over every node 0..=N,
/// ends included: the columns of a known end give the forces its motion causes) and
/// `ws.coupled.point_diag` (the free points' own loads).
///
/// `current_factor` scales the current seen by drag (statics load continuation; 1 otherwise).
/// Every line's blocks are marked coupled. 2w + 1 colours per line of block bandwidth w:
/// vectors j ≡ c (mod 2w + 1) are perturbed together, since vector j moves only the forces of
/// vectors j − w ..= j + w (w = 1 for `fe`: three colours; 3 for `hermite`).
pub fn force_jacobian(
    system: &System,
    y: &[Real],
    variable: Variable,
    difference: Difference,
    current_factor: Real,
    ws: &mut Workspace,
) {
    kinematics_at_rest(system, y, current_factor, ws);
    let mut scratch = JacobianScratch::new(system);
    let Workspace {
        lines,
        blocks,
        points,
        coupled,
        ..
    } = ws;
    loads_jacobian(
        system,
        JacobianAt::Rest { current_factor },
        variable,
        difference,
        LoadsAt {
            lines,
            points,
            meshes: None,
            fluid: None,
        },
        blocks,
        &mut coupled.point_diag,
        &mut scratch,
        &|_| false,
    );
}

/// The force Jacobians ∂F/∂x [N/m] and ∂F/∂v [N·s/m] of the dynamics at time `t` [s] and
/// state `y`, with every point's kinematics (prescribed, coupled, free) and every line's
/// velocities as they are, the current mesh of lines on winches and the run's wave
/// kinematics: the stiffness and damping of the implicit scheme's Newton iteration
/// ([`crate::integrate::GeneralizedAlpha`]). Call after [`System::assemble`] at the same
/// (t, y) (it prepared the winches and the wave tables at t). Writes each line's blocks
/// (nodes 0..=N, marked coupled) into `lines[0]` (by positions) and `lines[1]` (by
/// velocities), and the free points' own-load blocks into `points[0]` and `points[1]`; `ws`
/// keeps only scratch. No allocation: the scratch is `scratch`.
///
/// An `fe` line's blocks are in closed form where it covers the line's forces
/// ([`crate::formulation::fe::jacobian`]: about two evaluations' work for both, against the
/// twenty of the differences), the others' forward differences, coloured as in
/// [`force_jacobian`]. Statics and the modes keep the differences for every line: their K
/// and C are then exact for every term, a profile current's depth gradient included, which
/// the closed form leaves out (Newton only needs a close Jacobian).
pub fn dynamic_force_jacobian(
    system: &System,
    t: Real,
    y: &[Real],
    ws: &mut Workspace,
    lines: [&mut [LineBlocks]; 2],
    points: [&mut [Mat3]; 2],
    scratch: &mut JacobianScratch,
) {
    system.point_kinematics(t, y, ws);
    system.gather_lines(y, ws);
    let Workspace {
        lines: work,
        points: kinematics,
        winches,
        wave_points,
        ..
    } = ws;
    let env = &system.environment;
    let mesh = |li: usize| match &winches[li] {
        Some(w) => &w.mesh,
        None => &system.lines[li].mesh,
    };
    let closed = |li: usize| {
        matches!(
            system.lines[li].discretisation,
            crate::formulation::Discretisation::Fe { .. }
        ) && crate::formulation::fe::jacobian::covers(mesh(li), env)
    };
    let [by_position, by_velocity] = lines;
    for li in (0..system.lines.len()).filter(|&li| closed(li)) {
        let lw = &work[li];
        let covered = crate::formulation::fe::jacobian::newton_jacobian(
            mesh(li),
            env,
            t,
            &lw.position,
            &lw.velocity,
            LoadOptions {
                current_factor: 1.0,
                fluid: wave_points.of_line(li),
            },
            Some(&mut by_position[li]),
            Some(&mut by_velocity[li]),
        );
        debug_assert!(covered, "`covers` said the closed form covers line {li}");
    }
    let [points_position, points_velocity] = points;
    for (variable, lines, points) in [
        (Variable::Position, by_position, points_position),
        (Variable::Velocity, by_velocity, points_velocity),
    ] {
        loads_jacobian(
            system,
            JacobianAt::State { time: t },
            variable,
            Difference::Forward,
            LoadsAt {
                lines: work,
                points: kinematics,
                meshes: Some(winches),
                fluid: Some(wave_points),
            },
            lines,
            points,
            scratch,
            &closed,
        );
    }
}

/// Scratch of a force Jacobian: the forces of one line at the base and perturbed states,
/// sized once for the longest line.
#[derive(Clone, Debug)]
pub struct JacobianScratch {
    base: Vec<Vec3>,
    plus: Vec<Vec3>,
}

impl JacobianScratch {
    /// Scratch for the lines of `system`.
    pub fn new(system: &System) -> Self {
        let n = system.lines.iter().map(|l| l.vectors()).max().unwrap_or(0);
        Self {
            base: vec![Vec3::zeros(); n],
            plus: vec![Vec3::zeros(); n],
        }
    }
}

/// Where a force Jacobian is taken.
#[derive(Clone, Copy, Debug)]
enum JacobianAt {
    /// The static state: t = 0, direct wave kinematics, the current scaled by this factor.
    Rest { current_factor: Real },
    /// A state of the dynamics at this time [s].
    State { time: Real },
}

/// What [`loads_jacobian`] reads and perturbs: the lines' gathered kinematics, the points'
/// kinematics, and in the dynamics the current meshes of winch lines and the run's wave
/// tables.
struct LoadsAt<'a> {
    lines: &'a mut [crate::system::LineWork],
    points: &'a [crate::system::PointKinematics],
    meshes: Option<&'a [Option<crate::system::WinchWork>]>,
    fluid: Option<&'a crate::system::WavePoints>,
}

/// The Jacobian of every line's forces and every free point's own load by coloured finite
/// differences (see [`force_jacobian`]), from the kinematics in `at`, into `out` and
/// `out_points`; the lines for which `skip` holds are left as they are.
#[allow(clippy::too_many_arguments)]
fn loads_jacobian(
    system: &System,
    place: JacobianAt,
    variable: Variable,
    difference: Difference,
    at: LoadsAt,
    out: &mut [LineBlocks],
    out_points: &mut [Mat3],
    scratch: &mut JacobianScratch,
    skip: &dyn Fn(usize) -> bool,
) {
    let (time, current_factor) = match place {
        JacobianAt::Rest { current_factor } => (0.0, current_factor),
        JacobianAt::State { time } => (time, 1.0),
    };
    let env = &system.environment;
    let JacobianScratch { base, plus } = scratch;
    for (li, l) in system.lines.iter().enumerate() {
        let n = l.vectors() - 1;
        let h = match variable {
            Variable::Position => position_step(system, li, difference),
            Variable::Velocity => VELOCITY_STEP,
        };
        let mesh = match at.meshes.and_then(|m| m[li].as_ref()) {
            Some(w) => &w.mesh,
            None => &l.mesh,
        };
        let options = LoadOptions {
            current_factor,
            fluid: match at.fluid {
                Some(w) => w.of_line(li),
                None => crate::physics::static_kinematics::FluidPoints::Direct,
            },
        };
        if skip(li) {
            continue;
        }
        let blocks = &mut out[li];
        let lw = &mut at.lines[li];
        // Tangents (dimensionless) take the step per metre of the shortest element.
        let scale = |j: usize| 1.0 / l.length_scale(j);
        blocks.coupled = true;
        blocks.clear();
        let stride = 2 * blocks.width() + 1;
        let evaluate = |lw: &mut crate::system::LineWork, out: &mut [Vec3]| {
            line_forces(
                mesh,
                &l.discretisation,
                env,
                time,
                &lw.position,
                &lw.velocity,
                &mut lw.force,
                &mut lw.elements,
                None,
                options,
            );
            out[..=n].copy_from_slice(&lw.force[..=n]);
        };
        let shift = |lw: &mut crate::system::LineWork, colour: usize, k: usize, by: Real| {
            let v = match variable {
                Variable::Position => &mut lw.position,
                Variable::Velocity => &mut lw.velocity,
            };
            for j in (colour..=n).step_by(stride) {
                v[j][k] += by * scale(j);
            }
        };
        if difference == Difference::Forward {
            evaluate(lw, base);
        }
        for colour in 0..stride.min(n + 1) {
            for k in 0..3 {
                shift(lw, colour, k, h);
                evaluate(lw, plus);
                let step = match difference {
                    Difference::Forward => {
                        shift(lw, colour, k, -h);
                        h
                    }
                    Difference::Central => {
                        shift(lw, colour, k, -2.0 * h);
                        evaluate(lw, base);
                        shift(lw, colour, k, h);
                        2.0 * h
                    }
                };
                for j in (colour..=n).step_by(stride) {
                    let step = step * scale(j);
                    for i in blocks.band_of(j) {
                        let column = (plus[i] - base[i]) / step;
                        blocks.block_mut(i, j).set_column(k, &column);
                    }
                }
            }
        }
    }
    for (f, &p) in system.free_points.iter().enumerate() {
        let k0 = at.points[p];
        let h = match variable {
            Variable::Position => POINT_POSITION_STEP,
            Variable::Velocity => VELOCITY_STEP,
        };
        let load = |axis: usize, by: Real| {
            let mut k = k0;
            match variable {
                Variable::Position => k.position[axis] += by,
                Variable::Velocity => k.velocity[axis] += by,
            }
            system.point_own_load(p, &k, time, current_factor).0
        };
        let f0 = system.point_own_load(p, &k0, time, current_factor).0;
        let mut m = Mat3::zeros();
        for k in 0..3 {
            let column = match difference {
                Difference::Forward => (load(k, h) - f0) / h,
                Difference::Central => (load(k, h) - load(k, -h)) / (2.0 * h),
            };
            m.set_column(k, &column);
        }
        out_points[f] = m;
    }
}

/// Who owns a group of three degrees of freedom.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DofOwner {
    /// An interior vector of a line: a node position (translations x, y, z), or a `hermite`
    /// line's tangent at a node.
    LineNode {
        /// Line index.
        line: usize,
        /// Vector index along the line (1 .. vectors − 2; 0 is end A): the node index for
        /// `fe`, [`crate::system::SystemLine::node_vector`] for `hermite`.
        node: usize,
        /// Whether the vector is a tangent [-] rather than a position [m].
        tangent: bool,
    },
    /// A free point (clump weight, buoy, joint): translations x, y, z.
    Point {
        /// Point index.
        point: usize,
    },
    /// A free body's origin: translations x, y, z [m].
    BodyTranslation {
        /// Body index.
        body: usize,
    },
    /// A free body's small rotations about the global x, y, z axes [rad].
    BodyRotation {
        /// Body index.
        body: usize,
    },
}

/// Where a line vector's (or a point's) three components go among the degrees of freedom.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DofTarget {
    /// Nowhere: an end on a fixed, prescribed or coupled point, or on a body that is not
    /// free.
    Fixed,
    /// Its own group of three.
    Group(usize),
    /// A point on a free body, moving with it: δx = δr + δθ × ρ, with δr the body's
    /// translation group `group`, δθ its rotation group `group + 1`.
    Body {
        /// The body's translation group.
        group: usize,
        /// Offset ρ of the point from the body origin at the static pose, global axes [m].
        offset: Vec3,
    },
}

impl DofTarget {
    /// Its first degree of freedom and the 3×6 map J from the target's degrees of freedom
    /// (3 used for a group, 6 for a body) to the vector's three components.
    fn map(&self) -> Option<(usize, usize, Mat3x6)> {
        let mut j = Mat3x6::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&Mat3::identity());
        match *self {
            DofTarget::Fixed => None,
            DofTarget::Group(g) => Some((3 * g, 3, j)),
            DofTarget::Body { group, offset } => {
                j.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-skew(&offset)));
                Some((3 * group, 6, j))
            }
        }
    }
}

/// The numbering of the degrees of freedom: groups of three, per line its interior vectors in
/// order, then the free points, then per free body its translation and rotation groups.
#[derive(Clone, Debug, PartialEq)]
pub struct DofMap {
    /// Owner of each group; DOF 3·g + axis belongs to group g.
    pub owners: Vec<DofOwner>,
    /// First group of each line's interior.
    line_first: Vec<usize>,
    /// Where each point's components go (free points: their group; points on free bodies:
    /// the body).
    point_target: Vec<DofTarget>,
    /// Group of each free point, in `System::free_points` order.
    free_point_groups: Vec<usize>,
    /// Translation group of each free body, in `System::free_bodies` order.
    body_groups: Vec<usize>,
    /// Whether each free body's translation is held by its pin (a pinned body: its origin
    /// follows the pin's given motion, so its translation group is a constrained group whose
    /// displacement is zero; only its rotations are free), in `System::free_bodies` order.
    body_pinned: Vec<bool>,
    /// Vector count of each line.
    line_vectors: Vec<usize>,
    /// Vector index of each node, per line.
    node_vectors: Vec<Vec<usize>>,
    /// End points (A, B) of each line.
    line_ends: Vec<(usize, usize)>,
}

impl DofMap {
    /// The numbering of `system` about the state `state` (which places the free bodies).
    pub fn new(system: &System, state: &[Real]) -> Self {
        let mut owners = Vec::new();
        let mut line_first = Vec::new();
        for (li, l) in system.lines.iter().enumerate() {
            line_first.push(owners.len());
            for node in 1..l.vectors() - 1 {
                owners.push(DofOwner::LineNode {
                    line: li,
                    node,
                    tangent: l.is_tangent(node),
                });
            }
        }
        let mut point_target = vec![DofTarget::Fixed; system.points.len()];
        let mut free_point_groups = Vec::new();
        for &p in &system.free_points {
            point_target[p] = DofTarget::Group(owners.len());
            free_point_groups.push(owners.len());
            owners.push(DofOwner::Point { point: p });
        }
        let mut body_groups = Vec::new();
        let mut body_group = vec![None; system.bodies.len()];
        for &b in &system.free_bodies {
            body_group[b] = Some(owners.len());
            body_groups.push(owners.len());
            owners.push(DofOwner::BodyTranslation { body: b });
            owners.push(DofOwner::BodyRotation { body: b });
        }
        for (p, point) in system.points.iter().enumerate() {
            if let PointKind::Body { body, offset } = &point.kind
                && let Some(group) = body_group[*body]
            {
                let o = system.layout.body_offset[*body].expect("a free body is in the state");
                let k = crate::bodies::read_state(&state[o..o + crate::bodies::STATE_LEN]);
                point_target[p] = DofTarget::Body {
                    group,
                    offset: k.orientation * offset,
                };
            }
        }
        let body_pinned = system
            .free_bodies
            .iter()
            .map(|&b| {
                // A pin whose motion is given (fixed, prescribed, coupled); a pin on another
                // body moves with it and is not held (the modal analysis refuses it).
                system.bodies[b]
                    .body
                    .kind
                    .pin()
                    .is_some_and(|p| p.parent().is_none())
            })
            .collect();
        Self {
            owners,
            line_first,
            point_target,
            free_point_groups,
            body_groups,
            body_pinned,
            line_vectors: system.lines.iter().map(|l| l.vectors()).collect(),
            node_vectors: system
                .lines
                .iter()
                .map(|l| (0..l.nodes()).map(|i| l.node_vector(i)).collect())
                .collect(),
            line_ends: system.lines.iter().map(|l| (l.end_a, l.end_b)).collect(),
        }
    }

    /// Number of degrees of freedom.
    pub fn len(&self) -> usize {
        3 * self.owners.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.owners.is_empty()
    }

    /// Where vector `j` (0..vectors) of line `line` goes: its own group for an interior vector,
    /// its point's target for an end.
    pub fn vector_target(&self, line: usize, j: usize) -> DofTarget {
        let last = self.line_vectors[line] - 1;
        if j == 0 {
            self.point_target[self.line_ends[line].0]
        } else if j == last {
            self.point_target[self.line_ends[line].1]
        } else {
            DofTarget::Group(self.line_first[line] + j - 1)
        }
    }

    /// Where the position of node `node` (0..=N) of line `line` goes.
    pub fn node_target(&self, line: usize, node: usize) -> DofTarget {
        self.vector_target(line, self.node_vectors[line][node])
    }

    /// The group of a free point, `None` for other points.
    pub fn point_group(&self, point: usize) -> Option<usize> {
        match self.point_target[point] {
            DofTarget::Group(g) => Some(g),
            _ => None,
        }
    }

    /// Where a point's components go.
    pub fn point_target(&self, point: usize) -> DofTarget {
        self.point_target[point]
    }

    /// The translation group of the free body `body` (the rotation group follows it), `None`
    /// for other bodies.
    pub fn body_group(&self, body: usize) -> Option<usize> {
        self.owners
            .iter()
            .position(|o| *o == DofOwner::BodyTranslation { body })
    }

    /// The degrees of freedom held at zero by pins: the three translations of each pinned
    /// body's origin, in increasing order. The linearisation keeps them (the dynamics' block
    /// structure has six unknowns per integrated body), and the solvers over the degrees of
    /// freedom hold them: [`BlockSolver`] replaces their rows by δr = 0, and the modal analysis
    /// removes them before the eigenproblem.
    pub fn held(&self) -> Vec<usize> {
        self.body_groups
            .iter()
            .zip(&self.body_pinned)
            .filter(|(_, pinned)| **pinned)
            .flat_map(|(&g, _)| 3 * g..3 * g + 3)
            .collect()
    }

    /// The displacement of a target in the degrees of freedom `x` [m] (zero for a fixed one).
    pub fn displacement(&self, x: &[Real], t: DofTarget) -> Vec3 {
        match t.map() {
            None => Vec3::zeros(),
            Some((first, width, j)) => {
                let mut u = Vec6::zeros();
                for k in 0..width {
                    u[k] = x[first + k];
                }
                j * u
            }
        }
    }

    /// Adds Jᵀ v to the degrees of freedom `y` of a target (nothing for a fixed one).
    fn add_force(&self, y: &mut [Real], t: DofTarget, v: &Vec3) {
        if let Some((first, width, j)) = t.map() {
            let g = j.transpose() * v;
            for k in 0..width {
                y[first + k] += g[k];
            }
        }
    }
}

/// A symmetric-structured sparse matrix over the degrees of freedom, stored as the dynamics
/// stores its mass: per line a block-banded matrix over all its vectors (rows and columns of
/// ends on fixed or prescribed points are kept but are not degrees of freedom; an end on a
/// free point adds into that point's rows, an end on a free body into the body's through J),
/// plus per free point its own block and per free body its own 6×6 block.
#[derive(Clone, Debug)]
pub struct BlockMatrix {
    /// Per line: `diag[i]`, `lower[i]` (row i+1, column i), `upper[i]` (row i, column i+1).
    pub lines: Vec<LineBlocks>,
    /// Per free point (in `System::free_points` order): its own block.
    pub points: Vec<Mat3>,
    /// Per free body (in `System::free_bodies` order): its own 6×6 block over
    /// [δr; δθ].
    pub bodies: Vec<Mat6>,
    /// The points on free bodies that line ends attach to, in the slot order of the lines'
    /// [`EndKind::Free`] ends after the free points (offsets at the static pose).
    pub slots: Vec<BodySlot>,
}

impl BlockMatrix {
    /// y = A x over the degrees of freedom of `map` (O(nodes)).
    pub fn apply(&self, map: &DofMap, x: &[Real], y: &mut [Real]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        for (li, b) in self.lines.iter().enumerate() {
            let n = b.nodes() - 1;
            for i in 0..=n {
                let row = map.vector_target(li, i);
                if row == DofTarget::Fixed {
                    continue;
                }
                let mut acc = Vec3::zeros();
                for j in b.band_of(i) {
                    let column = map.vector_target(li, j);
                    if column != DofTarget::Fixed {
                        acc += b.block(i, j) * map.displacement(x, column);
                    }
                }
                map.add_force(y, row, &acc);
            }
        }
        for (f, m) in self.points.iter().enumerate() {
            let g = map.free_point_groups[f];
            crate::math::add3(y, g, &(m * get3(x, g)));
        }
        for (f, m) in self.bodies.iter().enumerate() {
            let o = 3 * map.body_groups[f];
            let u = Vec6::from_fn(|k, _| x[o + k]);
            let v = m * u;
            for k in 0..6 {
                y[o + k] += v[k];
            }
        }
    }

    /// Non-zero entries (row, column, value) over the degrees of freedom, duplicates summed
    /// by the consumer (an end on a free point adds to its point's entries, an end on a free
    /// body to its body's through J).
    pub fn triplets(&self, map: &DofMap) -> Vec<(usize, usize, Real)> {
        let mut out = Vec::new();
        for (li, b) in self.lines.iter().enumerate() {
            let n = b.nodes() - 1;
            for i in 0..=n {
                let Some((ri, wi, ji)) = map.vector_target(li, i).map() else {
                    continue;
                };
                for j in b.band_of(i) {
                    let Some((rj, wj, jj)) = map.vector_target(li, j).map() else {
                        continue;
                    };
                    let full = ji.transpose() * b.block(i, j) * jj;
                    for r in 0..wi {
                        for c in 0..wj {
                            if full[(r, c)] != 0.0 {
                                out.push((ri + r, rj + c, full[(r, c)]));
                            }
                        }
                    }
                }
            }
        }
        for (f, m) in self.points.iter().enumerate() {
            let g = map.free_point_groups[f];
            for r in 0..3 {
                for c in 0..3 {
                    if m[(r, c)] != 0.0 {
                        out.push((3 * g + r, 3 * g + c, m[(r, c)]));
                    }
                }
            }
        }
        for (f, m) in self.bodies.iter().enumerate() {
            let o = 3 * map.body_groups[f];
            for r in 0..6 {
                for c in 0..6 {
                    if m[(r, c)] != 0.0 {
                        out.push((o + r, o + c, m[(r, c)]));
                    }
                }
            }
        }
        out
    }

    /// The diagonal entries over the degrees of freedom.
    pub fn to_diagonal(&self, map: &DofMap) -> Vec<Real> {
        let mut d = vec![0.0; map.len()];
        for (r, c, v) in self.triplets(map) {
            if r == c {
                d[r] += v;
            }
        }
        d
    }

    /// The largest absolute row sum ‖A‖_∞ over the degrees of freedom.
    pub fn row_sum_norm(&self, map: &DofMap) -> Real {
        let mut rows = vec![0.0; map.len()];
        for (r, _, v) in self.triplets(map) {
            rows[r] += v.abs();
        }
        rows.into_iter().fold(0.0, Real::max)
    }

    /// The dense matrix over the degrees of freedom (tests and small systems).
    pub fn to_dense(&self, map: &DofMap) -> DMatrix<Real> {
        let n = map.len();
        let mut a = DMatrix::zeros(n, n);
        for (r, c, v) in self.triplets(map) {
            a[(r, c)] += v;
        }
        a
    }

    /// The symmetric part (A + Aᵀ)/2, block by block.
    pub fn symmetric_part(&self) -> Self {
        let mut s = self.clone();
        for b in s.lines.iter_mut() {
            for d in b.diag.iter_mut() {
                *d = (*d + d.transpose()) * 0.5;
            }
            for (below, above) in b.band_pairs_mut() {
                for (lo, up) in below.iter_mut().zip(above.iter_mut()) {
                    let m = (*lo + up.transpose()) * 0.5;
                    *lo = m;
                    *up = m.transpose();
                }
            }
        }
        for m in s.points.iter_mut() {
            *m = (*m + m.transpose()) * 0.5;
        }
        for m in s.bodies.iter_mut() {
            *m = (*m + m.transpose()) * 0.5;
        }
        s
    }

    /// Largest entry magnitude of A − Aᵀ relative to the largest of A [-]: 0 for a
    /// conservative system; current drag (a follower load) and the √(1+ε) factor of seabed
    /// contact make the stiffness slightly non-symmetric.
    pub fn asymmetry(&self) -> Real {
        let (mut skew, mut size): (Real, Real) = (0.0, 0.0);
        for b in &self.lines {
            for d in &b.diag {
                skew = skew.max((d - d.transpose()).abs().max());
                size = size.max(d.abs().max());
            }
            for (below, above) in b.band_pairs() {
                for (lo, up) in below.iter().zip(above.iter()) {
                    skew = skew.max((lo - up.transpose()).abs().max());
                    size = size.max(lo.abs().max()).max(up.abs().max());
                }
            }
        }
        for m in &self.points {
            skew = skew.max((m - m.transpose()).abs().max());
            size = size.max(m.abs().max());
        }
        for m in &self.bodies {
            skew = skew.max((m - m.transpose()).abs().max());
            size = size.max(m.abs().max());
        }
        if size > 0.0 { skew / size } else { 0.0 }
    }

    /// A − σB, block by block (both over the same structure).
    pub fn shifted(&self, sigma: Real, b: &BlockMatrix) -> Self {
        let mut s = self.clone();
        for (sl, bl) in s.lines.iter_mut().zip(b.lines.iter()) {
            for (x, y) in sl.blocks_mut().zip(bl.blocks()) {
                *x -= y * sigma;
            }
            sl.coupled = true;
        }
        for (x, y) in s.points.iter_mut().zip(b.points.iter()) {
            *x -= y * sigma;
        }
        for (x, y) in s.bodies.iter_mut().zip(b.bodies.iter()) {
            *x -= y * sigma;
        }
        s
    }
}

/// What to linearise.
#[derive(Clone, Copy, Debug, Default)]
pub struct LinearisationOptions {
    /// Also form the linearised damping C = −∂F/∂v (axial damping, drag about the current,
    /// seabed damping and friction).
    pub damping: bool,
}

/// The linearised system about a static state.
#[derive(Clone, Debug)]
pub struct Linearisation {
    /// Degrees of freedom.
    pub dofs: DofMap,
    /// Tangent stiffness K = −∂F/∂x [N/m], as differentiated (not symmetrised).
    pub stiffness: BlockMatrix,
    /// Mass M [kg]: structural plus added mass, as the dynamics assembles it.
    pub mass: BlockMatrix,
    /// Linearised damping C = −∂F/∂v [N·s/m], when asked.
    pub damping: Option<BlockMatrix>,
    /// The state linearised about (positions at equilibrium, zero velocities).
    pub state: Vec<Real>,
}

impl Linearisation {
    /// All natural angular frequencies ω = √λ [rad/s] of K φ = λ M φ (K symmetrised), sorted
    /// ascending, by a dense solve: for small systems and checks; [`crate::analysis::modes`]
    /// gives labelled modes of large ones.
    pub fn angular_frequencies(&self) -> Result<Vec<Real>, crate::linalg::eigen::EigenFailure> {
        let k = self.stiffness.symmetric_part().to_dense(&self.dofs);
        let m = self.mass.to_dense(&self.dofs);
        let pairs = crate::linalg::eigen::dense_generalized(&k, &m)?;
        let mut omega: Vec<Real> = pairs.values.iter().map(|l| l.max(0.0).sqrt()).collect();
        omega.sort_by(|a, b| a.total_cmp(b));
        Ok(omega)
    }
}

/// Negates the line and point blocks (F-Jacobian → stiffness or damping) and adds the free
/// bodies' own blocks `bodies` (already stiffness or damping).
fn negated(
    system: &System,
    lines: &[LineBlocks],
    points: &[Mat3],
    bodies: Vec<Mat6>,
    slots: &[BodySlot],
) -> BlockMatrix {
    let mut m = BlockMatrix {
        lines: lines.to_vec(),
        points: points.to_vec(),
        bodies,
        slots: slots.to_vec(),
    };
    for b in m.lines.iter_mut() {
        b.blocks_mut().for_each(|x| *x = -*x);
        b.coupled = true;
    }
    m.points.iter_mut().for_each(|x| *x = -*x);
    debug_assert_eq!(m.bodies.len(), system.free_bodies.len());
    m
}

/// Linearises `system` about the static state `state` (as found by
/// [`crate::statics::solve`]): velocities are taken as zero and prescribed points sit at their
/// t = 0 positions. Free bodies are degrees of freedom ([`bodies`]).
///
/// # Panics
///
/// With `dg` lines (modal unknowns, not linearised): linearise their hermite twin
/// ([`crate::analysis::modes::modal_twin`]); [`crate::analysis::modes::supported`] checks.
pub fn linearise(system: &System, state: &[Real], options: LinearisationOptions) -> Linearisation {
    assert!(
        !system.has_dg_lines(),
        "linearise: dg lines are not linearised (linearise the model's modal_twin)"
    );
    let slots = bodies::slots(system, state);
    let mut ws = system.workspace();
    force_jacobian(
        system,
        state,
        Variable::Position,
        Difference::Central,
        1.0,
        &mut ws,
    );
    constrain_clamps(system, &mut ws.blocks);
    let forces = bodies::end_forces(system, state);
    let stiffness = negated(
        system,
        &ws.blocks,
        &ws.coupled.point_diag,
        bodies::own_blocks(system, state, Variable::Position, &forces),
        &slots,
    );
    let damping = options.damping.then(|| {
        force_jacobian(
            system,
            state,
            Variable::Velocity,
            Difference::Central,
            1.0,
            &mut ws,
        );
        constrain_clamps(system, &mut ws.blocks);
        negated(
            system,
            &ws.blocks,
            &ws.coupled.point_diag,
            bodies::own_blocks(system, state, Variable::Velocity, &forces),
            &slots,
        )
    });
    // Mass: the dynamics' own assembly at the static positions, at rest.
    let mass = mass_matrix(system, state);
    Linearisation {
        dofs: DofMap::new(system, state),
        stiffness,
        mass,
        damping,
        state: state.to_vec(),
    }
}

/// Clamped end tangents keep only their component along the clamp
/// ([`crate::system::SystemLine::apply_clamps`]); the constrained normal directions keep a
/// diagonal entry of the block's own scale, so K and M each carry them as uncoupled rows
/// (two spurious eigenvalues per clamp at the ratio of those scales, far above the modes of
/// interest).
fn constrain_clamps(system: &System, blocks: &mut [LineBlocks]) {
    for (l, b) in system.lines.iter().zip(blocks.iter_mut()) {
        l.apply_clamps(b);
    }
}

/// The mass matrix [kg] at state `y` (at rest, t = 0), assembled by the dynamics' force code:
/// line mass blocks with added mass, the free points' own mass with added mass, and each
/// free body's 6×6 mass about its origin with added mass ([`crate::model::Body::loads`]).
pub fn mass_matrix(system: &System, y: &[Real]) -> BlockMatrix {
    let mut ws = system.workspace();
    line_forces_at_rest(system, y, 1.0, true, &mut ws);
    constrain_clamps(system, &mut ws.blocks);
    let points = system
        .free_points
        .iter()
        .map(|&p| system.point_own_load(p, &ws.points[p], 0.0, 1.0).1)
        .collect();
    BlockMatrix {
        lines: ws.blocks,
        points,
        bodies: bodies::masses(system, y),
        slots: bodies::slots(system, y),
    }
}

/// Solves A x = b over the degrees of freedom with the dynamics' coupled block solver
/// (block Thomas along each line, Schur complement over the free points and bodies): O(nodes).
#[derive(Clone, Debug)]
pub struct BlockSolver {
    lines: Vec<LineBlocks>,
    coupled: CoupledSystem,
}

impl BlockSolver {
    /// A solver for `a` (its blocks are copied).
    pub fn new(a: &BlockMatrix) -> Self {
        let mut coupled = CoupledSystem::with_bodies(a.points.len(), a.bodies.len(), a.slots.len());
        coupled.point_diag.copy_from_slice(&a.points);
        coupled.body_diag.copy_from_slice(&a.bodies);
        coupled.body_slots.copy_from_slice(&a.slots);
        let mut lines = a.lines.clone();
        for l in lines.iter_mut() {
            l.coupled = true;
        }
        Self { lines, coupled }
    }

    /// A solver for `a` with the free bodies held: the line ends on their points become known
    /// ends, and the bodies' rows are left out (the condensation onto the bodies).
    fn holding_bodies(a: &BlockMatrix) -> Self {
        let np = a.points.len();
        let mut coupled = CoupledSystem::new(np);
        coupled.point_diag.copy_from_slice(&a.points);
        let mut lines = a.lines.clone();
        for l in lines.iter_mut() {
            l.coupled = true;
            for end in [&mut l.end_a, &mut l.end_b] {
                if matches!(*end, EndKind::Free(s) if s >= np) {
                    *end = EndKind::Known;
                }
            }
        }
        Self { lines, coupled }
    }

    /// x = A⁻¹ b for a right-hand side over the degrees of freedom of `map`.
    pub fn solve(&mut self, map: &DofMap, b: &[Real], x: &mut [Real]) -> Result<(), Singular> {
        self.solve_with_known(map, b, |_, _| Vec3::zeros())?;
        self.gather(map, x);
        Ok(())
    }

    /// Solves with the right-hand side `b` on the degrees of freedom and the displacement
    /// `known(line, vector)` imposed on ends that are known (on fixed and prescribed points,
    /// and on held bodies): their columns move to the right-hand side. Afterwards every line's
    /// `x` holds all its vectors' values.
    fn solve_with_known(
        &mut self,
        map: &DofMap,
        b: &[Real],
        known: impl Fn(usize, usize) -> Vec3,
    ) -> Result<(), Singular> {
        for (li, l) in self.lines.iter_mut().enumerate() {
            let n = l.nodes() - 1;
            for i in 0..=n {
                l.x[i] = if (i == 0 && l.end_a == EndKind::Known)
                    || (i == n && l.end_b == EndKind::Known)
                {
                    known(li, i)
                } else if i == 0 || i == n {
                    // A free end: its right-hand side is its point's or body's, given once
                    // below.
                    Vec3::zeros()
                } else {
                    match map.vector_target(li, i) {
                        DofTarget::Group(g) => get3(b, g),
                        _ => unreachable!("an interior vector has its own group"),
                    }
                };
            }
        }
        for (f, x) in self.coupled.point_x.iter_mut().enumerate() {
            *x = get3(b, map.free_point_groups[f]);
        }
        for (f, x) in self.coupled.body_x.iter_mut().enumerate() {
            let o = 3 * map.body_groups[f];
            *x = Vec6::from_fn(|k, _| b[o + k]);
        }
        // A pinned body's translation is held: its three rows become δr = 0 (the pin's
        // motion is given), as the dynamics hold them (`CoupledSystem::body_pin`).
        for (pin, &pinned) in self.coupled.body_pin.iter_mut().zip(&map.body_pinned) {
            *pin = pinned.then(Vec3::zeros);
        }
        self.coupled.solve(&mut self.lines)
    }

    fn gather(&self, map: &DofMap, x: &mut [Real]) {
        for (li, l) in self.lines.iter().enumerate() {
            for i in 1..l.nodes() - 1 {
                if let DofTarget::Group(g) = map.vector_target(li, i) {
                    crate::math::set3(x, g, &l.x[i]);
                }
            }
        }
        for (f, v) in self.coupled.point_x.iter().enumerate() {
            crate::math::set3(x, map.free_point_groups[f], v);
        }
        for (f, v) in self.coupled.body_x.iter().enumerate() {
            let o = 3 * map.body_groups[f];
            for k in 0..6 {
                x[o + k] = v[k];
            }
        }
    }
}

/// The stiffness [N/m] the lines offer their fixed and prescribed points, with every free
/// degree of freedom relaxed to its new equilibrium (static condensation).
///
/// For the points p, q: K_pq = −∂F_p/∂x_q, F_p the total force the lines exert on p, with
/// the free degrees of freedom u following x_q: K_uu u = −K_uq x_q. So
/// K_pq = K_pq⁰ − K_pu K_uu⁻¹ K_uq, computed column by column with the coupled block solver.
/// A diagonal block K_pp is a fairlead's (or anchor's) 3×3 stiffness; the off-diagonal blocks
/// couple points joined through lines and free points (what a body with several fairleads
/// needs, see the module documentation).
#[derive(Clone, Debug)]
pub struct ConnectionStiffness {
    /// Point indices, in the order of the matrix's 3×3 block rows.
    pub points: Vec<usize>,
    /// The 3P×3P matrix [N/m].
    pub matrix: DMatrix<Real>,
}

impl ConnectionStiffness {
    /// Block (p, q) by position in [`Self::points`].
    pub fn block(&self, p: usize, q: usize) -> Mat3 {
        Mat3::from_fn(|r, c| self.matrix[(3 * p + r, 3 * q + c)])
    }

    /// The 3×3 stiffness of point `point` (a model index), if it is a connection.
    pub fn of_point(&self, point: usize) -> Option<Mat3> {
        let i = self.points.iter().position(|&p| p == point)?;
        Some(self.block(i, i))
    }
}

/// The stiffness at every fixed or prescribed point that has a line attached, condensed over
/// the free degrees of freedom of `lin` (see [`ConnectionStiffness`]).
pub fn connection_stiffness(
    system: &System,
    lin: &Linearisation,
) -> Result<ConnectionStiffness, Singular> {
    let mut points: Vec<usize> = Vec::new();
    for l in &system.lines {
        for p in [l.end_a, l.end_b] {
            let moves = system.points[p].free_index.is_some() || system.point_slot[p].is_some();
            if !moves && !points.contains(&p) {
                points.push(p);
            }
        }
    }
    let np = points.len();
    let mut matrix = DMatrix::zeros(3 * np, 3 * np);
    let mut solver = BlockSolver::new(&lin.stiffness);
    let zero = vec![0.0; lin.dofs.len()];
    for (qi, &q) in points.iter().enumerate() {
        for axis in 0..3 {
            let unit = Vec3::ith(axis, 1.0);
            let known = |li: usize, node: usize| {
                let l = &system.lines[li];
                let p = if node == 0 { l.end_a } else { l.end_b };
                if p == q { unit } else { Vec3::zeros() }
            };
            solver.solve_with_known(&lin.dofs, &zero, known)?;
            // Rows of the connection points: (K x) at every end node on them.
            for (li, b) in solver.lines.iter().enumerate() {
                let n = b.nodes() - 1;
                let l = &system.lines[li];
                for (node, p) in [(0, l.end_a), (n, l.end_b)] {
                    let Some(pi) = points.iter().position(|&x| x == p) else {
                        continue;
                    };
                    let k = &lin.stiffness.lines[li];
                    let row = k.row_times(node, &b.x);
                    for r in 0..3 {
                        matrix[(3 * pi + r, 3 * qi + axis)] += row[r];
                    }
                }
            }
        }
    }
    Ok(ConnectionStiffness { points, matrix })
}
