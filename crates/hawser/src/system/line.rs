//! A line of the assembled system: its mesh, discretisation, ends and clamps, and every
//! operation on its block of the state that depends on the formulation, each one `match` on
//! [`Discretisation`] here: the state length, gathering node kinematics, evaluating forces and
//! rates, writing rates, setting a shape, the energy, the end force and node tension, and
//! naming the node of a state entry. (The stable rate's match is in `stability.rs`, beside
//! the Gershgorin rows it feeds; the statics twin's in `shapes.rs`.)

use super::{LineWork, PointKinematics};
use crate::formulation::dg::{DgLine, DgWorkspace, EndState, Translation};
use crate::formulation::{Discretisation, Energy, LoadOptions, Mesh, line_forces};
use crate::linalg::{EndKind, LineBlocks};
use crate::math::{Mat3, Real, Vec3, set3};
use crate::physics::environment::Environment;
use crate::physics::static_kinematics::FluidPoints;

/// A line of the system.
#[derive(Clone, Debug)]
pub struct SystemLine {
    /// Name.
    pub name: String,
    /// Elements along the unstretched arc length.
    pub mesh: Mesh,
    /// Formulation, its options, and for `dg` its whole discretisation.
    pub discretisation: Discretisation,
    /// Unit directions of the clamped end tangents (A, B), `None` for pinned ends.
    pub clamp: [Option<Vec3>; 2],
    /// Point index of end A.
    pub end_a: usize,
    /// Point index of end B.
    pub end_b: usize,
    /// The line's winch: its unstretched length follows the winch's schedule, and its
    /// `mesh` is the mesh at t = 0 ([`super::Workspace::winches`] holds the current one).
    pub winch: Option<crate::model::Winch>,
}

/// What a line's evaluation knows of its two ends (A, B): their points' kinematics, and the
/// external force of a point that is a `dg` line's free end (DG paper Table 1 row 5).
/// The kinematics are borrowed: a copy of them per line and evaluation was a 192-byte
/// `memcpy`, 1 % of the OC3 deck's RK4 step.
#[derive(Clone, Copy, Debug)]
pub struct LineEnds<'a> {
    /// Kinematics of the points at ends A and B.
    pub kinematics: [&'a PointKinematics; 2],
    /// External force [N] on each end's point, used by a `dg` end with a force condition.
    pub force: [Vec3; 2],
}

impl SystemLine {
    /// The `dg` discretisation, `None` for the element formulations.
    #[inline]
    pub fn dg(&self) -> Option<&DgLine> {
        self.discretisation.dg()
    }

    /// Number of 3-vectors, ends included (`fe` and `dg`: N + 1 nodes; `hermite`: 2N + 2
    /// positions and tangents).
    #[inline]
    pub fn vectors(&self) -> usize {
        self.discretisation.vectors(self.mesh.elements())
    }

    /// Number of nodes N + 1.
    #[inline]
    pub fn nodes(&self) -> usize {
        self.mesh.elements() + 1
    }

    /// The line's share of the state: (interior 3-vector unknowns m, entries of its block).
    /// `fe`/`hermite`: m vectors of coordinates then m of rates, 6m entries; `dg`: no
    /// 3-vector unknowns, its modal coefficients.
    pub fn state_len(&self) -> (usize, usize) {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let m = self.vectors() - 2;
                (m, 6 * m)
            }
            Discretisation::Dg(dg) => (0, dg.state_len()),
        }
    }

    /// Number of vectors of the line's mass blocks: all its vectors, or for `dg` only the two
    /// ends (which carry the flux tractions to the points and no mass).
    #[inline]
    pub fn block_vectors(&self) -> usize {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => self.vectors(),
            Discretisation::Dg(_) => 2,
        }
    }

    /// Scratch of this line's evaluation, sized once.
    pub fn work(&self) -> LineWork {
        let n = self.mesh.elements();
        let m = self.vectors();
        LineWork {
            position: vec![Vec3::zeros(); m],
            velocity: vec![Vec3::zeros(); m],
            force: vec![Vec3::zeros(); m],
            elements: crate::formulation::ElementState::new(n),
            node_tension: match &self.discretisation {
                Discretisation::Fe { .. } | Discretisation::Hermite(_) => Vec::new(),
                Discretisation::Dg(_) => vec![0.0; n + 1],
            },
        }
    }

    /// The line's mass blocks with its ends' kinds, sized once.
    pub fn blocks(&self, end_a: EndKind, end_b: EndKind) -> LineBlocks {
        LineBlocks::banded(
            self.block_vectors(),
            self.discretisation.bandwidth(),
            end_a,
            end_b,
            self.discretisation.consistent_mass(),
        )
    }

    /// The `dg` scratch, `None` for the element formulations.
    pub fn dg_work(&self) -> Option<DgWorkspace> {
        self.dg().map(DgWorkspace::new)
    }

    /// Whether the line's evaluation gives curvature and bending moment
    /// ([`crate::formulation::ElementState`]): `hermite` lines always, `dg` lines with
    /// bending stiffness or damping in some section; `fe` lines never (they leave zeros).
    pub fn has_bending_outputs(&self) -> bool {
        match &self.discretisation {
            Discretisation::Fe { .. } => false,
            Discretisation::Hermite(_) => true,
            Discretisation::Dg(d) => d.bending,
        }
    }

    /// Index of node i's position among the line's vectors (`LineWork::position`).
    #[inline]
    pub fn node_vector(&self, node: usize) -> usize {
        self.discretisation.node_vector(node, self.mesh.elements())
    }

    /// The vectors of element `e`: its two end positions (A, B) and, for `hermite`, its two
    /// end tangents (`fe` has none; a `dg` line has no element vectors and gives its node
    /// outputs).
    pub fn element_vectors(&self, e: usize) -> ([usize; 2], Option<[usize; 2]>) {
        let n = self.mesh.elements();
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Dg(_) => ([e, e + 1], None),
            Discretisation::Hermite(_) => {
                let [ra, ta, rb, tb] = crate::formulation::hermite::element_vectors(e, n);
                ([ra, rb], Some([ta, tb]))
            }
        }
    }

    /// Number of quadrature points at which the line evaluates the fluid: 2 per `fe`
    /// element, 4 per `hermite` element, the Gauss points of a `dg` line.
    pub fn fluid_points(&self) -> usize {
        let n = self.mesh.elements();
        match &self.discretisation {
            Discretisation::Fe { .. } => 2 * n,
            Discretisation::Hermite(_) => crate::formulation::hermite::GAUSS.len() * n,
            Discretisation::Dg(dg) => dg.point_len(),
        }
    }

    /// Where an entry `index` of the line's state block belongs, as a node number: `fe` the
    /// node, `hermite` the index of its vector (positions and tangents counted in turn), `dg`
    /// the element whose coefficients hold it, named by its end A node.
    pub fn locate(&self, index: usize) -> usize {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let m = self.vectors() - 2;
                (index % (3 * m)) / 3 + 1
            }
            Discretisation::Dg(dg) => dg.elements.partition_point(|el| el.state <= index) - 1,
        }
    }

    /// Fills the node positions and velocities of `lw` from the line's state block `y` and
    /// its end points. A `dg` line fills them in [`SystemLine::evaluate`] (its positions come
    /// with the evaluation of its fields).
    pub fn gather(&self, y: &[Real], a: &PointKinematics, b: &PointKinematics, lw: &mut LineWork) {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let n = self.vectors() - 1;
                let m = n - 1;
                lw.position[0] = a.position;
                lw.velocity[0] = a.velocity;
                lw.position[n] = b.position;
                lw.velocity[n] = b.velocity;
                // Coordinates then rates of nodes 1..n, three entries a node.
                let (coordinates, rates) = y[..6 * m].split_at(3 * m);
                crate::math::coordinates_mut(&mut lw.position[1..n]).copy_from_slice(coordinates);
                crate::math::coordinates_mut(&mut lw.velocity[1..n]).copy_from_slice(rates);
            }
            Discretisation::Dg(_) => {}
        }
    }

    /// Evaluates the line at time t [s] from its state block `y` and its ends: node forces
    /// and element results into `lw`, and its mass blocks into `blocks` with `x` holding the
    /// forces (the known accelerations at ends on fixed, prescribed or coupled points).
    /// `fe`/`hermite` on the current `mesh` (a winch's); `dg` through [`DgLine::rhs_with`],
    /// writing its own rate into `dydt` and its node outputs into `lw`, its blocks holding
    /// its end tractions as forces on the points (no mass). With `dydt` `None` (an assembly
    /// without a rate, as the statics and the three-level scheme ask) a `dg` line passes on
    /// the tractions of its last evaluation.
    #[allow(clippy::too_many_arguments)]
    pub fn evaluate(
        &self,
        env: &Environment,
        t: Real,
        mesh: &Mesh,
        fluid: FluidPoints,
        y: &[Real],
        dydt: Option<&mut [Real]>,
        ends: &LineEnds<'_>,
        lw: &mut LineWork,
        blocks: &mut LineBlocks,
        dws: Option<&mut DgWorkspace>,
    ) {
        let n = self.vectors() - 1;
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let [a, b] = &ends.kinematics;
                self.gather(y, a, b, lw);
                line_forces(
                    mesh,
                    &self.discretisation,
                    env,
                    t,
                    &lw.position,
                    &lw.velocity,
                    &mut lw.force,
                    &mut lw.elements,
                    Some(blocks),
                    LoadOptions {
                        current_factor: 1.0,
                        fluid,
                    },
                );
                blocks.x.copy_from_slice(&lw.force);
                self.apply_clamps(blocks);
                if blocks.end_a == EndKind::Known {
                    blocks.x[0] = a.acceleration;
                }
                if blocks.end_b == EndKind::Known {
                    blocks.x[n] = b.acceleration;
                }
            }
            Discretisation::Dg(dg) => {
                if let (Some(dydt), Some(dws)) = (dydt, dws) {
                    let end_state = |side: usize| {
                        let k = &ends.kinematics[side];
                        EndState {
                            position: k.position,
                            velocity: k.velocity,
                            acceleration: k.acceleration,
                            force: match dg.ends[side].translation {
                                Translation::Force => ends.force[side],
                                _ => Vec3::zeros(),
                            },
                            moment: Vec3::zeros(),
                            direction: self.clamp[side].unwrap_or_else(Vec3::zeros),
                            direction_rate: Vec3::zeros(),
                        }
                    };
                    let end_states = [end_state(0), end_state(1)];
                    let loads = dg.rhs_with(env, fluid, t, y, &end_states, dydt, dws);
                    dg.sample(
                        y,
                        dws,
                        &loads,
                        &mut lw.position,
                        &mut lw.velocity,
                        &mut lw.node_tension,
                        &mut lw.elements,
                    );
                    lw.force[0] = loads[0].force;
                    lw.force[n] = loads[1].force;
                }
                // The end tractions as forces on the points.
                blocks.x[0] = match blocks.end_a {
                    EndKind::Known => ends.kinematics[0].acceleration,
                    _ => lw.force[0],
                };
                blocks.x[1] = match blocks.end_b {
                    EndKind::Known => ends.kinematics[1].acceleration,
                    _ => lw.force[n],
                };
            }
        }
    }

    /// Writes the rate of the line's state block into `dydt` after the coupled solve (node
    /// accelerations in `blocks.x`): `fe`/`hermite` velocities then accelerations of the
    /// interior vectors; a `dg` line wrote its rate in [`SystemLine::evaluate`].
    pub fn write_rate(&self, lw: &LineWork, blocks: &LineBlocks, dydt: &mut [Real]) {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let m = self.vectors() - 2;
                let (coordinates, rates) = dydt[..6 * m].split_at_mut(3 * m);
                coordinates.copy_from_slice(crate::math::coordinates(&lw.velocity[1..=m]));
                rates.copy_from_slice(crate::math::coordinates(&blocks.x[1..=m]));
            }
            Discretisation::Dg(_) => {}
        }
    }

    /// Force [N] the line exerts on the attachment of one end (`end_b` false: end A), from
    /// the last evaluation: the end node's share of the line's forces minus the inertia of
    /// its share of the line's mass, F_end − (M_ee a_e + M_en a_n); for a `dg` line the
    /// traction of the numerical flux at that end.
    pub fn end_force(&self, lw: &LineWork, blocks: &LineBlocks, end_b: bool) -> Vec3 {
        let n = self.vectors() - 1;
        let node = if end_b { n } else { 0 };
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                lw.force[node] - blocks.row_times_x(node)
            }
            Discretisation::Dg(_) => lw.force[node],
        }
    }

    /// Tension [N] at node i from the last evaluation: the mean of its elements' tensions at
    /// interior nodes and the magnitude of the end force at the ends; for a `dg` line the
    /// tension at the element ends (the mean of the two sides at an interface).
    pub fn node_tension(&self, lw: &LineWork, blocks: &LineBlocks, node: usize) -> Real {
        let n = self.mesh.elements();
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let t = &lw.elements.tension;
                if node == 0 {
                    self.end_force(lw, blocks, false).norm()
                } else if node == n {
                    self.end_force(lw, blocks, true).norm()
                } else {
                    0.5 * (t[node - 1] + t[node])
                }
            }
            Discretisation::Dg(_) => lw.node_tension[node],
        }
    }

    /// Sets the line's state block `y` from a continuous configuration: `shape(s)` gives the
    /// position [m] and velocity [m/s] at unstretched arc length s [m] from end A (see
    /// [`super::System::set_line_shape`]). `fe`/`hermite`: the nodes take it at their arc
    /// lengths and [`SystemLine::set_node_shape`] derives the other unknowns. `dg`: the L2
    /// projection of the shape, its tangent ∂r/∂s by fourth-order central differences with
    /// a step of 5 % of the shortest element (exact for polynomials of degree 4; the
    /// round-off is ~10⁻¹⁶ |r| / h).
    pub fn set_shape(&self, y: &mut [Real], shape: impl Fn(Real) -> (Vec3, Vec3)) {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let (r, v): (Vec<Vec3>, Vec<Vec3>) = (0..self.nodes())
                    .map(|i| shape(self.mesh.arc_length(i)))
                    .unzip();
                let m = self.vectors() - 2;
                self.set_node_shape(&r, &mut y[..3 * m]);
                self.set_node_shape(&v, &mut y[3 * m..6 * m]);
            }
            Discretisation::Dg(dg) => {
                let h = 5e-2 * self.mesh.shortest_element();
                dg.project(y, |s| {
                    let (r, v) = shape(s);
                    let at = |k: Real| shape(s + k * h).0;
                    let q = ((at(-2.0) - at(2.0)) + (at(1.0) - at(-1.0)) * 8.0) / (12.0 * h);
                    (r, q, v)
                });
            }
        }
    }

    /// Sets the line's state block `y` to the straight line from `a` to `b` [m], at rest.
    pub fn set_straight(&self, y: &mut [Real], a: Vec3, b: Vec3) {
        match &self.discretisation {
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                let total = self.mesh.length();
                let shape: Vec<Vec3> = (0..=self.mesh.elements())
                    .map(|i| a + (b - a) * (self.mesh.arc_length(i) / total))
                    .collect();
                self.set_node_shape(&shape, y);
            }
            Discretisation::Dg(dg) => dg.straight(y, a, b),
        }
    }

    /// Mechanical energy of the line [J] (see [`super::System::mechanical_energy`]) from its
    /// state block `y` and `lw` filled by [`SystemLine::gather`] with its ends at `a`, `b`,
    /// on the current `mesh`, each by its formulation's own quadrature.
    pub fn energy(
        &self,
        mesh: &Mesh,
        y: &[Real],
        lw: &LineWork,
        a: Vec3,
        b: Vec3,
        gravity: Real,
    ) -> Energy {
        let (q, qdot) = (&lw.position, &lw.velocity);
        let mut energy = Energy::default();
        match &self.discretisation {
            Discretisation::Fe { mass_matrix } => {
                for e in 0..mesh.elements() {
                    energy += crate::formulation::fe::element_energy(
                        mesh,
                        *mass_matrix,
                        gravity,
                        q,
                        qdot,
                        e,
                    );
                }
            }
            Discretisation::Hermite(options) => {
                for e in 0..mesh.elements() {
                    energy += crate::formulation::hermite::element_energy(
                        mesh, options, gravity, q, qdot, e,
                    );
                }
            }
            Discretisation::Dg(dg) => {
                let ends = [
                    EndState::fixed(a, Vec3::zeros()),
                    EndState::fixed(b, Vec3::zeros()),
                ];
                energy += dg.energy(y, dg.position_base(y, &ends), gravity);
            }
        }
        energy
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
        self.discretisation.is_tangent(j, self.mesh.elements())
    }

    /// Writes the coordinates of the line's interior vectors into its state block `y` (the
    /// coordinates part) from the node positions `shape` (nodes 0..=N, ends included).
    /// `hermite` tangents t = ∂r/∂s come from second-order finite differences over the
    /// unstretched arc length (one-sided at the ends; exact for a straight line). `fe` and
    /// `hermite` only: a `dg` line's state is modal ([`SystemLine::set_shape`]).
    pub fn set_node_shape(&self, shape: &[Vec3], y: &mut [Real]) {
        let n = self.mesh.elements();
        match &self.discretisation {
            Discretisation::Fe { .. } => {
                for (i, r) in shape.iter().enumerate().take(n).skip(1) {
                    set3(y, i - 1, r);
                }
            }
            Discretisation::Dg(_) => {
                unreachable!("a dg line's state is modal: use SystemLine::set_shape")
            }
            Discretisation::Hermite(_) => {
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
