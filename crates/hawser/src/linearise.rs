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
//! Degrees of freedom are grouped by owner ([`DofOwner`]): the interior nodes of every line,
//! then every free point, three translations each. Fixed and prescribed points are not degrees
//! of freedom: their motion is given. Free rigid bodies are not linearised yet: each would add an owner with six
//! degrees of freedom (translation and rotation about a reference point); their rows couple
//! to the line ends at their fairleads through the rigid-body transformation, and the
//! [`connection_stiffness`] condensation below is the hook for the 6×6 mooring stiffness a
//! body sees: K₆ = Σ_pq T_pᵀ K_pq T_q + the geometric term of the fairlead forces, with
//! T_p = [I  −[r_p×]] for the body-fixed fairlead offset r_p.

use crate::formulation::{LoadOptions, line_forces};
use crate::linalg::{CoupledSystem, EndKind, LineBlocks, Singular};
use crate::math::{Mat3, Real, Vec3, get3};
use crate::system::{System, Workspace};
use nalgebra::DMatrix;

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
    let options = LoadOptions::direct(current_factor);
    kinematics_at_rest(system, y, current_factor, ws);
    let env = &system.environment;
    let mut base: Vec<Vec3> = Vec::new();
    let mut plus: Vec<Vec3> = Vec::new();
    for (li, l) in system.lines.iter().enumerate() {
        let n = l.vectors() - 1;
        let h = match variable {
            Variable::Position => position_step(system, li, difference),
            Variable::Velocity => VELOCITY_STEP,
        };
        // Tangents (dimensionless) take the step per metre of the shortest element.
        let scale = |j: usize| 1.0 / l.length_scale(j);
        let blocks = &mut ws.blocks[li];
        blocks.coupled = true;
        blocks.clear();
        let stride = 2 * blocks.width() + 1;
        let lw = &mut ws.lines[li];
        let evaluate = |lw: &mut crate::system::LineWork, out: &mut Vec<Vec3>| {
            line_forces(
                &l.mesh,
                &l.discretisation,
                env,
                0.0,
                &lw.position,
                &lw.velocity,
                &mut lw.force,
                &mut lw.elements,
                None,
                options,
            );
            out.clear();
            out.extend_from_slice(&lw.force);
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
            evaluate(lw, &mut base);
        }
        for colour in 0..stride.min(n + 1) {
            for k in 0..3 {
                shift(lw, colour, k, h);
                evaluate(lw, &mut plus);
                let step = match difference {
                    Difference::Forward => {
                        shift(lw, colour, k, -h);
                        h
                    }
                    Difference::Central => {
                        shift(lw, colour, k, -2.0 * h);
                        evaluate(lw, &mut base);
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
        let k0 = ws.points[p];
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
            system.point_own_load(p, &k, 0.0, current_factor).0
        };
        let f0 = system.point_own_load(p, &k0, 0.0, current_factor).0;
        let mut m = Mat3::zeros();
        for k in 0..3 {
            let column = match difference {
                Difference::Forward => (load(k, h) - f0) / h,
                Difference::Central => (load(k, h) - load(k, -h)) / (2.0 * h),
            };
            m.set_column(k, &column);
        }
        ws.coupled.point_diag[f] = m;
    }
}

/// Who owns a group of three degrees of freedom (translations x, y, z).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DofOwner {
    /// An interior node of a line.
    LineNode {
        /// Line index.
        line: usize,
        /// Node index (1..N−1; 0 is end A).
        node: usize,
    },
    /// A free point (clump weight, buoy, joint).
    Point {
        /// Point index.
        point: usize,
    },
}

/// The numbering of the degrees of freedom: groups of three (a node's or a point's
/// translations), per line its interior nodes in order, then the free points.
#[derive(Clone, Debug, PartialEq)]
pub struct DofMap {
    /// Owner of each group; DOF 3·g + axis belongs to group g.
    pub owners: Vec<DofOwner>,
    /// First group of each line's interior.
    line_first: Vec<usize>,
    /// Group of each point (`None` for fixed and prescribed points).
    point_group: Vec<Option<usize>>,
    /// Node count N + 1 of each line.
    line_nodes: Vec<usize>,
    /// End points (A, B) of each line.
    line_ends: Vec<(usize, usize)>,
}

impl DofMap {
    /// The numbering of `system`.
    pub fn new(system: &System) -> Self {
        let mut owners = Vec::new();
        let mut line_first = Vec::new();
        for (li, l) in system.lines.iter().enumerate() {
            line_first.push(owners.len());
            for node in 1..l.vectors() - 1 {
                owners.push(DofOwner::LineNode { line: li, node });
            }
        }
        let mut point_group = vec![None; system.points.len()];
        for &p in &system.free_points {
            point_group[p] = Some(owners.len());
            owners.push(DofOwner::Point { point: p });
        }
        Self {
            owners,
            line_first,
            point_group,
            line_nodes: system.lines.iter().map(|l| l.vectors()).collect(),
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

    /// The group of node `node` (0..=N) of line `line`: its own for an interior node, its
    /// point's for an end on a free point, `None` for an end on a fixed or prescribed point.
    pub fn node_group(&self, line: usize, node: usize) -> Option<usize> {
        let last = self.line_nodes[line] - 1;
        if node == 0 {
            self.point_group[self.line_ends[line].0]
        } else if node == last {
            self.point_group[self.line_ends[line].1]
        } else {
            Some(self.line_first[line] + node - 1)
        }
    }

    /// The group of a free point, `None` for fixed and prescribed points.
    pub fn point_group(&self, point: usize) -> Option<usize> {
        self.point_group[point]
    }
}

/// A symmetric-structured sparse matrix over the degrees of freedom, stored as the dynamics
/// stores its mass: per line a block-tridiagonal matrix over all its nodes 0..=N (rows and
/// columns of ends on fixed or prescribed points are kept but are not degrees of freedom; an
/// end on a free point adds into that point's rows), plus per free point its own block.
#[derive(Clone, Debug)]
pub struct BlockMatrix {
    /// Per line: `diag[i]`, `lower[i]` (row i+1, column i), `upper[i]` (row i, column i+1).
    pub lines: Vec<LineBlocks>,
    /// Per free point (in `System::free_points` order): its own block.
    pub points: Vec<Mat3>,
}

impl BlockMatrix {
    /// y = A x over the degrees of freedom of `map` (O(nodes)).
    pub fn apply(&self, map: &DofMap, x: &[Real], y: &mut [Real]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        let at = |g: usize| get3(x, g);
        for (li, b) in self.lines.iter().enumerate() {
            let n = b.nodes() - 1;
            for i in 0..=n {
                let Some(row) = map.node_group(li, i) else {
                    continue;
                };
                let mut acc = Vec3::zeros();
                for j in b.band_of(i) {
                    if let Some(c) = map.node_group(li, j) {
                        acc += b.block(i, j) * at(c);
                    }
                }
                crate::math::add3(y, row, &acc);
            }
        }
        for (f, m) in self.points.iter().enumerate() {
            let g = map.owners.len() - self.points.len() + f;
            crate::math::add3(y, g, &(m * at(g)));
        }
    }

    /// Non-zero entries (row, column, value) over the degrees of freedom, duplicates summed
    /// by the consumer (an end on a free point adds to its point's entries).
    pub fn triplets(&self, map: &DofMap) -> Vec<(usize, usize, Real)> {
        let mut out = Vec::new();
        let mut push = |r: usize, c: usize, m: &Mat3| {
            for i in 0..3 {
                for j in 0..3 {
                    if m[(i, j)] != 0.0 {
                        out.push((3 * r + i, 3 * c + j, m[(i, j)]));
                    }
                }
            }
        };
        for (li, b) in self.lines.iter().enumerate() {
            let n = b.nodes() - 1;
            for i in 0..=n {
                let Some(r) = map.node_group(li, i) else {
                    continue;
                };
                for j in b.band_of(i) {
                    if let Some(c) = map.node_group(li, j) {
                        push(r, c, &b.block(i, j));
                    }
                }
            }
        }
        let first = map.owners.len() - self.points.len();
        for (f, m) in self.points.iter().enumerate() {
            push(first + f, first + f, m);
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

/// Negates every block in place (F-Jacobian → stiffness or damping).
fn negated(lines: &[LineBlocks], points: &[Mat3]) -> BlockMatrix {
    let mut m = BlockMatrix {
        lines: lines.to_vec(),
        points: points.to_vec(),
    };
    for b in m.lines.iter_mut() {
        b.blocks_mut().for_each(|x| *x = -*x);
        b.coupled = true;
    }
    m.points.iter_mut().for_each(|x| *x = -*x);
    m
}

/// Linearises `system` about the static state `state` (as found by
/// [`crate::statics::solve`]): velocities are taken as zero and prescribed points sit at their
/// t = 0 positions.
///
/// # Panics
///
/// With `dg` lines (modal unknowns, not linearised): check with
/// [`crate::analysis::modes::supported`] first.
pub fn linearise(system: &System, state: &[Real], options: LinearisationOptions) -> Linearisation {
    assert!(
        !system.has_dg_lines(),
        "linearise: dg lines are not linearised (check analysis::modes::supported first)"
    );
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
    let stiffness = negated(&ws.blocks, &ws.coupled.point_diag);
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
        negated(&ws.blocks, &ws.coupled.point_diag)
    });
    // Mass: the dynamics' own assembly at the static positions, at rest.
    let mass = mass_matrix(system, state);
    Linearisation {
        dofs: DofMap::new(system),
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
/// line mass blocks with added mass, and the free points' own mass with added mass.
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
    }
}

/// Solves A x = b over the degrees of freedom with the dynamics' coupled block solver
/// (block Thomas along each line, Schur complement over the free points): O(nodes).
#[derive(Clone, Debug)]
pub struct BlockSolver {
    lines: Vec<LineBlocks>,
    coupled: CoupledSystem,
}

impl BlockSolver {
    /// A solver for `a` (its blocks are copied).
    pub fn new(a: &BlockMatrix) -> Self {
        let mut coupled = CoupledSystem::new(a.points.len());
        coupled.point_diag.copy_from_slice(&a.points);
        let mut lines = a.lines.clone();
        for l in lines.iter_mut() {
            l.coupled = true;
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
    /// `known(line, node)` imposed on ends on fixed and prescribed points (their columns move
    /// to the right-hand side). Afterwards every line's `x` holds all its nodes' values.
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
                    // A free end: its right-hand side is its point's, given once below.
                    Vec3::zeros()
                } else {
                    get3(b, map.node_group(li, i).expect("interior node"))
                };
            }
        }
        let first = map.owners.len() - self.coupled.point_x.len();
        for (f, x) in self.coupled.point_x.iter_mut().enumerate() {
            *x = get3(b, first + f);
        }
        self.coupled.solve(&mut self.lines)
    }

    fn gather(&self, map: &DofMap, x: &mut [Real]) {
        for (li, l) in self.lines.iter().enumerate() {
            for i in 1..l.nodes() - 1 {
                let g = map.node_group(li, i).expect("interior node");
                crate::math::set3(x, g, &l.x[i]);
            }
        }
        let first = map.owners.len() - self.coupled.point_x.len();
        for (f, v) in self.coupled.point_x.iter().enumerate() {
            crate::math::set3(x, first + f, v);
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
            if system.points[p].free_index.is_none() && !points.contains(&p) {
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
