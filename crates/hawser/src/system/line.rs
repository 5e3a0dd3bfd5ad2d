//! A line of the assembled system: its mesh, formulation, ends and clamps, and the operations
//! on its block of the state.

use crate::formulation::dg::DgLine;
use crate::formulation::{LineKind, Mesh};
use crate::linalg::LineBlocks;
use crate::math::{Mat3, Real, Vec3, set3};

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

    /// Whether the line's evaluation gives curvature and bending moment
    /// ([`crate::formulation::ElementState`]): `hermite` lines always, `dg` lines with
    /// bending stiffness or damping in some section; `fe` lines never (they leave zeros).
    pub fn has_bending_outputs(&self) -> bool {
        match self.kind {
            LineKind::Fe { .. } => false,
            LineKind::Hermite(_) => true,
            LineKind::Dg => self.dg.as_ref().is_some_and(|d| d.bending),
        }
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
