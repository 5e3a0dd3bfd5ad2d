//! Lines (block-tridiagonal over their nodes) coupled through shared free points and free
//! rigid bodies.
//!
//! One solver serves the consistent mass matrix of the dynamics (symmetric blocks) and the
//! stiffness Jacobian of Newton statics (non-symmetric blocks). Each line's interior is
//! eliminated by block Thomas; the free points and bodies are solved from their Schur
//! complement, a small dense system; then the interior is back-substituted. Cost O(nodes) +
//! O((3 points + 6 bodies)³).
//!
//! A line end is a *slot*: a free point (its 3 accelerations are unknowns), or a point fixed on
//! a free body, whose acceleration is a = J u + c with u = [a_o; α] the body's 6 unknowns
//! (acceleration of its origin and angular acceleration), J = [I, −[ρ]×] (ρ the point's offset
//! from the origin in global axes) and c = ω × (ω × ρ). The end's row of a line, Σ_q A_pq a_q =
//! b_p, then enters the body's equations as Jₚᵀ (Σ_q A_pq (J_q u_q + c_q) − b_p): the line's
//! end force acts on the body as a force and the moment ρ × F about its origin, and the
//! line's end mass adds Jᵀ A J to the body's 6×6 mass.

use super::block_banded::MAX_WIDTH;
use super::block_banded::same_bits;
use super::{BlockBandedLdl, BlockBandedLu, BlockTridiagonal, DenseLu};
use crate::math::Mat3x6 as Matrix3x6;
use crate::math::{Mat3, Mat6, Real, Vec3, Vec6, skew};

/// What an end node of a line is in the coupled system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EndKind {
    /// Its unknown is known (fixed or prescribed end): the caller puts the value in `x`.
    Known,
    /// It is the slot with this index in [`CoupledSystem`]: a free point (indices below the
    /// free-point count) or a point on a free body (above, see [`CoupledSystem::body_slots`]).
    Free(usize),
}

/// The blocks of one line over its nodes 0..=N: 3×3 blocks over the line's 3-vector unknowns
/// ("nodes": positions for `fe`; positions and tangents for `hermite`), banded with block
/// bandwidth w (1 for `fe`, block-tridiagonal; 3 for `hermite`, whose element couples the four
/// consecutive vectors r_a, t_a, r_b, t_b). Nodes 0 and N are the ends, owned by points.
#[derive(Clone, Debug)]
pub struct LineBlocks {
    /// Diagonal blocks, one per node.
    pub diag: Vec<Mat3>,
    /// Block (row i+1, column i), one per element.
    pub lower: Vec<Mat3>,
    /// Block (row i, column i+1), one per element.
    pub upper: Vec<Mat3>,
    /// Bands k = 2..=w below the diagonal: `far_lower[k-2][j]` is block (j + k, j).
    pub far_lower: Vec<Vec<Mat3>>,
    /// Bands k = 2..=w above the diagonal: `far_upper[k-2][j]` is block (j, j + k).
    pub far_upper: Vec<Vec<Mat3>>,
    /// Right-hand side per node on input (known ends: their value); solution on output.
    pub x: Vec<Vec3>,
    /// End A kind.
    pub end_a: EndKind,
    /// End B kind.
    pub end_b: EndKind,
    /// Whether `lower`/`upper` hold non-zero blocks (false for a lumped mass matrix).
    pub coupled: bool,
    /// A lumped `fe` line's diagonal blocks in factored form ([`LumpedMass`]): when
    /// [`LumpedMass::current`], the solve of an uncoupled line uses it instead of the blocks.
    pub lumped: LumpedMass,
    factor: BlockTridiagonal,
    /// A banded line's interior factors (block bandwidth w > 1).
    interior: InteriorFactors,
    response_a: Vec<Mat3>,
    response_b: Vec<Mat3>,
}

/// The diagonal mass blocks of a lumped `fe` line in factored form: node i's block is
///
/// M_i = c_i I + b₁ t₁t₁ᵀ + b₂ t₂t₂ᵀ [kg],
///
/// c_i the structural mass and the isotropic added mass ρ A C_an of its share of its two
/// elements, t₁ and t₂ the unit tangents of elements i − 1 and i, and b₁, b₂ the node's share of
/// their anisotropic added mass ρ A (C_at − C_an) (position-vector paper eqs. 12, 17–18,
/// lumped). [`LumpedMass::solve_interior`] solves M_i x = f from these scalars in about 50 flops
/// instead of assembling the 3×3 block and solving it by Cramer's rule.
#[derive(Clone, Debug, Default)]
pub struct LumpedMass {
    /// c_i per node [kg].
    pub isotropic: Vec<Real>,
    /// Unit tangent t_e of each element, by component: `tangent[k][e]` (contiguous per
    /// component, so the solve reads consecutive elements in lanes).
    pub tangent: [Vec<Real>; 3],
    /// The weights of t_e t_eᵀ in the blocks of element e's first node (`rank_one[0][e]`,
    /// b_a) and second node (`rank_one[1][e]`, b_b) [kg].
    pub rank_one: [Vec<Real>; 2],
    /// Whether these are the line's current diagonal blocks: set by the `fe` loads
    /// ([`crate::formulation::fe::line_forces`]) where they fill them, cleared by
    /// [`LineBlocks::clear`] and [`LineBlocks::block_mut`] (anything else that changes the
    /// diagonal blocks of an uncoupled line must clear it).
    pub current: bool,
    /// Whether the `fe` loads may leave the interior nodes' diagonal blocks unwritten (only
    /// the ends' are formed): set by [`crate::system::System::rhs`] for its evaluation, whose
    /// solve of an uncoupled line reads the factored form (and by
    /// [`crate::system::System::rhs_with_accelerations`], whose end forces read only the
    /// ends' blocks), and cleared by every other
    /// assembly, whose readers (the three-level scheme, generalized-α, the linearisation)
    /// read the blocks. A reader of the blocks after `rhs` calls
    /// [`LineBlocks::form_lumped_diagonal`] first (generalized-α's start does).
    pub ends_only: bool,
}

impl LumpedMass {
    /// Storage for a line of `nodes` nodes (ends included).
    pub fn new(nodes: usize) -> Self {
        Self {
            isotropic: vec![0.0; nodes],
            tangent: std::array::from_fn(|_| vec![0.0; nodes.saturating_sub(1)]),
            rank_one: std::array::from_fn(|_| vec![0.0; nodes.saturating_sub(1)]),
            current: false,
            ends_only: false,
        }
    }

    /// The block M_i [kg] of node i (ends included).
    pub fn block(&self, i: usize) -> Mat3 {
        let mut m = Mat3::identity() * self.isotropic[i];
        if i > 0 {
            let t = self.tangent_of(i - 1);
            m += t * t.transpose() * self.rank_one[1][i - 1];
        }
        if i < self.tangent[0].len() {
            let t = self.tangent_of(i);
            m += t * t.transpose() * self.rank_one[0][i];
        }
        m
    }

    /// The unit tangent t_e of element e.
    #[inline]
    pub fn tangent_of(&self, e: usize) -> Vec3 {
        tangent_at(&self.tangent, e)
    }

    /// Sets element e's unit tangent `t` and its weights `rank_one` ([b_a, b_b]) (the
    /// element loop writes them lane by lane instead).
    #[cfg(test)]
    fn set_element(&mut self, e: usize, t: [Real; 3], rank_one: [Real; 2]) {
        for (component, value) in self.tangent.iter_mut().zip(t) {
            component[e] = value;
        }
        self.rank_one[0][e] = rank_one[0];
        self.rank_one[1][e] = rank_one[1];
    }

    /// Solves M_i x_i = f_i in place for the interior nodes i = 1 … N − 1 of a line of N + 1
    /// nodes: `x` holds f [N] for those nodes and receives x [m/s²]. Err(i) for the first
    /// node whose block is singular relative to its diagonal (the test of
    /// [`crate::math::solve3`]).
    #[inline]
    pub fn solve_interior(&self, x: &mut [Vec3]) -> Result<(), usize> {
        solve_lumped_interior(&self.isotropic, &self.tangent, &self.rank_one, x)
    }
}

/// Element e's vector of a by-component store (`tangent[k][e]`).
#[inline(always)]
fn tangent_at(tangent: &[Vec<Real>; 3], e: usize) -> Vec3 {
    Vec3::new(tangent[0][e], tangent[1][e], tangent[2][e])
}

/// The interior node count from which a processor with AVX-512 solves eight nodes at a time
/// ([`solve_lumped_wide`]) instead of four ([`solve_lumped_narrow`]).
const WIDE_SOLVE: usize = 16;

/// [`LumpedMass::solve_interior`] of the blocks `isotropic`, `tangent` and `rank_one`:
/// [`solve_two_rank_one`] at each interior node, several nodes at a time in lanes
/// ([`solve_two_rank_one_lanes`], the same operations, so the same bits;
/// [`solve_lumped_in_lanes`] says how the nodes are grouped): four at a time compiled for
/// AVX2 and for SSE2, and eight compiled for AVX-512 on a processor that has it, from
/// [`WIDE_SOLVE`] nodes (`crate::math::wide_simd_fn`).
#[inline]
fn solve_lumped_interior(
    isotropic: &[Real],
    tangent: &[Vec<Real>; 3],
    rank_one: &[Vec<Real>; 2],
    x: &mut [Vec3],
) -> Result<(), usize> {
    let wide = crate::math::simd_level() == crate::math::SimdLevel::Avx512;
    if wide && x.len() >= WIDE_SOLVE {
        solve_lumped_wide(isotropic, tangent, rank_one, x)
    } else {
        solve_lumped_narrow(isotropic, tangent, rank_one, x)
    }
}

crate::math::wide_simd_fn! {
    /// [`solve_lumped_interior`] four nodes at a time.
    fn solve_lumped_narrow(
        isotropic: &[Real],
        tangent: &[Vec<Real>; 3],
        rank_one: &[Vec<Real>; 2],
        x: &mut [Vec3],
    ) -> Result<(), usize> {
        solve_lumped_in_lanes::<4>(isotropic, tangent, rank_one, x)
    }
}

crate::math::wide_simd_fn! {
    avx512;
    /// [`solve_lumped_interior`] eight nodes at a time.
    fn solve_lumped_wide(
        isotropic: &[Real],
        tangent: &[Vec<Real>; 3],
        rank_one: &[Vec<Real>; 2],
        x: &mut [Vec3],
    ) -> Result<(), usize> {
        solve_lumped_in_lanes::<8>(isotropic, tangent, rank_one, x)
    }
}

/// [`solve_lumped_interior`] `L` nodes at a time: the groups of `L` from the first node, and
/// a last group of `L` ending at the last node for the nodes after them (solved first, from
/// the forces, and kept until the groups are done); fewer nodes than `L` one by one.
#[inline(always)]
fn solve_lumped_in_lanes<const L: usize>(
    isotropic: &[Real],
    tangent: &[Vec<Real>; 3],
    rank_one: &[Vec<Real>; 2],
    x: &mut [Vec3],
) -> Result<(), usize> {
    let count = x.len();
    if count < L {
        return solve_nodes(isotropic, tangent, rank_one, x, 0);
    }
    let whole = count - count % L;
    let last = if whole < count {
        match group_of_nodes::<L>(isotropic, tangent, rank_one, x, count - L) {
            Some(solved) => Some(solved),
            // A singular block there: node by node from the first, for the first index.
            None => return solve_nodes(isotropic, tangent, rank_one, x, 0),
        }
    } else {
        None
    };
    for i in (0..whole).step_by(L) {
        match group_of_nodes::<L>(isotropic, tangent, rank_one, x, i) {
            Some(solved) => {
                for l in 0..L {
                    x[i + l] = Vec3::new(solved[0][l], solved[1][l], solved[2][l]);
                }
            }
            None => solve_nodes(isotropic, tangent, rank_one, &mut x[..i + L], i)?,
        }
    }
    if let Some(solved) = last {
        for l in L - (count - whole)..L {
            x[count - L + l] = Vec3::new(solved[0][l], solved[1][l], solved[2][l]);
        }
    }
    Ok(())
}

/// [`solve_two_rank_one_lanes`] at interior nodes i + 1 … i + L (`x[i..i + L]` their
/// forces), between elements i … i + L.
#[inline(always)]
#[allow(clippy::needless_range_loop)]
fn group_of_nodes<const L: usize>(
    isotropic: &[Real],
    tangent: &[Vec<Real>; 3],
    rank_one: &[Vec<Real>; 2],
    x: &[Vec3],
    i: usize,
) -> Option<[[Real; L]; 3]> {
    let lanes =
        |v: &[Real], from: usize| -> [Real; L] { v[from..from + L].try_into().expect("L entries") };
    // (Gathered by a loop: `std::array::from_fn` per component was slower.)
    let mut f = [[0.0; L]; 3];
    for l in 0..L {
        for k in 0..3 {
            f[k][l] = x[i + l][k];
        }
    }
    solve_two_rank_one_lanes(&[
        lanes(isotropic, i + 1),
        lanes(&rank_one[1], i),
        lanes(&rank_one[0], i + 1),
        lanes(&tangent[0], i),
        lanes(&tangent[1], i),
        lanes(&tangent[2], i),
        lanes(&tangent[0], i + 1),
        lanes(&tangent[1], i + 1),
        lanes(&tangent[2], i + 1),
        f[0],
        f[1],
        f[2],
    ])
}

/// [`solve_two_rank_one`] at interior nodes `from + 1 ..= x.len()` (`x[j − 1]` holds node
/// j's force and receives its acceleration); Err(j) at the first singular block.
#[inline(always)]
fn solve_nodes(
    isotropic: &[Real],
    tangent: &[Vec<Real>; 3],
    rank_one: &[Vec<Real>; 2],
    x: &mut [Vec3],
    from: usize,
) -> Result<(), usize> {
    for (k, x) in x.iter_mut().enumerate().skip(from) {
        let j = k + 1;
        let (b1, b2) = (rank_one[1][j - 1], rank_one[0][j]);
        let (t1, t2) = (tangent_at(tangent, j - 1), tangent_at(tangent, j));
        *x = solve_two_rank_one(isotropic[j], b1, &t1, b2, &t2, x).ok_or(j)?;
    }
    Ok(())
}

/// [`solve_two_rank_one`] in `L` lanes, each lane's operations those of the scalar function
/// in its order: `lanes` holds c, b₁, b₂, t₁ (3), t₂ (3), f (3); the result x by component,
/// `None` if any lane's block is singular.
#[inline(always)]
#[allow(clippy::needless_range_loop)]
fn solve_two_rank_one_lanes<const L: usize>(lanes: &[[Real; L]; 12]) -> Option<[[Real; L]; 3]> {
    let [c, b1, b2, t1x, t1y, t1z, t2x, t2y, t2z, fx, fy, fz] = lanes;
    let mut out = [[0.0; L]; 3];
    let mut regular = true;
    for l in 0..L {
        let (g11, g22) = (
            t1x[l] * t1x[l] + t1y[l] * t1y[l] + t1z[l] * t1z[l],
            t2x[l] * t2x[l] + t2y[l] * t2y[l] + t2z[l] * t2z[l],
        );
        let s = t1x[l] * t2x[l] + t1y[l] * t2y[l] + t1z[l] * t2z[l];
        let f1 = t1x[l] * fx[l] + t1y[l] * fy[l] + t1z[l] * fz[l];
        let f2 = t2x[l] * fx[l] + t2y[l] * fy[l] + t2z[l] * fz[l];
        let (a11, a22) = (c[l] + b1[l] * g11, c[l] + b2[l] * g22);
        let (a12, a21) = (b2[l] * s, b1[l] * s);
        let det2 = a11 * a22 - a12 * a21;
        let d = c[l] + (b1[l] * g11 + b2[l] * g22) * (1.0 / 3.0);
        regular &= (c[l] * det2).abs() > 1e-14 * (d * d * d).abs();
        let inv = 1.0 / det2;
        let bp = b1[l] * ((a22 * f1 - a12 * f2) * inv);
        let bq = b2[l] * ((a11 * f2 - a21 * f1) * inv);
        let inv_c = 1.0 / c[l];
        out[0][l] = (fx[l] - t1x[l] * bp - t2x[l] * bq) * inv_c;
        out[1][l] = (fy[l] - t1y[l] * bp - t2y[l] * bq) * inv_c;
        out[2][l] = (fz[l] - t1z[l] * bp - t2z[l] * bq) * inv_c;
    }
    regular.then_some(out)
}

/// Solves (c I + b₁ t₁t₁ᵀ + b₂ t₂t₂ᵀ) x = f.
///
/// With p = t₁·x and q = t₂·x, x = (f − b₁ p t₁ − b₂ q t₂)/c, and p, q solve the 2×2 system
/// (c + b₁ g₁₁) p + b₂ s q = t₁·f, b₁ s p + (c + b₂ g₂₂) q = t₂·f (g₁₁ = t₁·t₁, g₂₂ = t₂·t₂,
/// s = t₁·t₂): Sherman–Morrison–Woodbury for the two rank-one terms. The 3×3 determinant is
/// c (the 2×2 determinant); `None` when it is below 1e-14 d³, d the mean diagonal entry
/// (c + (b₁ g₁₁ + b₂ g₂₂)/3), as in [`crate::math::solve3`].
#[inline(always)]
pub fn solve_two_rank_one(
    c: Real,
    b1: Real,
    t1: &Vec3,
    b2: Real,
    t2: &Vec3,
    f: &Vec3,
) -> Option<Vec3> {
    // Written component by component: nalgebra's dot products were left as loops.
    let (g11, g22) = (
        t1.x * t1.x + t1.y * t1.y + t1.z * t1.z,
        t2.x * t2.x + t2.y * t2.y + t2.z * t2.z,
    );
    let s = t1.x * t2.x + t1.y * t2.y + t1.z * t2.z;
    let f1 = t1.x * f.x + t1.y * f.y + t1.z * f.z;
    let f2 = t2.x * f.x + t2.y * f.y + t2.z * f.z;
    let (a11, a22) = (c + b1 * g11, c + b2 * g22);
    let (a12, a21) = (b2 * s, b1 * s);
    let det2 = a11 * a22 - a12 * a21;
    let d = c + (b1 * g11 + b2 * g22) * (1.0 / 3.0);
    if !((c * det2).abs() > 1e-14 * (d * d * d).abs()) {
        return None;
    }
    let inv = 1.0 / det2;
    let bp = b1 * ((a22 * f1 - a12 * f2) * inv);
    let bq = b2 * ((a11 * f2 - a21 * f1) * inv);
    let inv_c = 1.0 / c;
    Some(Vec3::new(
        (f.x - t1.x * bp - t2.x * bq) * inv_c,
        (f.y - t1.y * bp - t2.y * bq) * inv_c,
        (f.z - t1.z * bp - t2.z * bq) * inv_c,
    ))
}

/// A singular block met while solving.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Singular {
    /// In a line's interior, at this node.
    Line {
        /// Line index.
        line: usize,
        /// Node index.
        node: usize,
    },
    /// In the shared-point system, at this point.
    Point(usize),
}

impl LineBlocks {
    /// Storage for `nodes` 3-vector unknowns (ends included) with block bandwidth `width`.
    pub fn banded(
        nodes: usize,
        width: usize,
        end_a: EndKind,
        end_b: EndKind,
        coupled: bool,
    ) -> Self {
        assert!(nodes >= 2 && width >= 1, "a line has two ends and a band");
        let interior = nodes - 2;
        let band = |k: usize| vec![Mat3::zeros(); nodes.saturating_sub(k)];
        Self {
            diag: vec![Mat3::zeros(); nodes],
            lower: band(1),
            upper: band(1),
            far_lower: (2..=width).map(band).collect(),
            far_upper: (2..=width).map(band).collect(),
            x: vec![Vec3::zeros(); nodes],
            end_a,
            end_b,
            coupled,
            lumped: if width == 1 {
                LumpedMass::new(nodes)
            } else {
                LumpedMass::default()
            },
            factor: BlockTridiagonal::with_capacity(if width == 1 { interior.max(1) } else { 0 }),
            interior: if width == 1 {
                InteriorFactors::default()
            } else {
                InteriorFactors::new(interior, width)
            },
            response_a: vec![Mat3::zeros(); interior],
            response_b: vec![Mat3::zeros(); interior],
        }
    }

    /// Block bandwidth w.
    pub fn width(&self) -> usize {
        self.far_lower.len() + 1
    }

    /// Block (i, j), zero outside the band.
    #[inline]
    pub fn block(&self, i: usize, j: usize) -> Mat3 {
        match i as isize - j as isize {
            0 => self.diag[i],
            1 => self.lower[j],
            -1 => self.upper[i],
            d if d > 1 => self
                .far_lower
                .get(d as usize - 2)
                .map_or(Mat3::zeros(), |b| b[j]),
            d => self
                .far_upper
                .get((-d) as usize - 2)
                .map_or(Mat3::zeros(), |b| b[i]),
        }
    }

    /// Mutable block (i, j); |i − j| must be within the band.
    #[inline]
    pub fn block_mut(&mut self, i: usize, j: usize) -> &mut Mat3 {
        self.lumped.current = false;
        match i as isize - j as isize {
            0 => &mut self.diag[i],
            1 => &mut self.lower[j],
            -1 => &mut self.upper[i],
            d if d > 1 => &mut self.far_lower[d as usize - 2][j],
            d => &mut self.far_upper[(-d) as usize - 2][i],
        }
    }

    /// Σ_j A_ij x_j over row i's band: the product of row i with the current `x`.
    pub fn row_times_x(&self, i: usize) -> Vec3 {
        self.row_times(i, &self.x)
    }

    /// Σ_j A_ij x_j over row i's band for any `x` over the same nodes, summed from zero in the
    /// order of j, reading the bands directly.
    pub fn row_times(&self, i: usize, x: &[Vec3]) -> Vec3 {
        let (w, last) = (self.width(), self.nodes() - 1);
        let mut s = Vec3::zeros();
        for k in (1..=w.min(i)).rev() {
            let j = i - k;
            let b = if k == 1 {
                &self.lower[j]
            } else {
                &self.far_lower[k - 2][j]
            };
            s += b * x[j];
        }
        s += self.diag[i] * x[i];
        for k in 1..=w.min(last - i) {
            let b = if k == 1 {
                &self.upper[i]
            } else {
                &self.far_upper[k - 2][i]
            };
            s += b * x[i + k];
        }
        s
    }

    /// The columns j of row i's band.
    #[inline]
    pub fn band_of(&self, i: usize) -> std::ops::RangeInclusive<usize> {
        let w = self.width();
        i.saturating_sub(w)..=(i + w).min(self.nodes() - 1)
    }

    /// The pairs of bands (below, above) at distance k = 1..=w: `below[j]` is block
    /// (j + k, j) and `above[j]` block (j, j + k).
    pub fn band_pairs(&self) -> impl Iterator<Item = (&Vec<Mat3>, &Vec<Mat3>)> {
        std::iter::once((&self.lower, &self.upper))
            .chain(self.far_lower.iter().zip(self.far_upper.iter()))
    }

    /// Mutable [`LineBlocks::band_pairs`].
    pub fn band_pairs_mut(&mut self) -> impl Iterator<Item = (&mut Vec<Mat3>, &mut Vec<Mat3>)> {
        std::iter::once((&mut self.lower, &mut self.upper))
            .chain(self.far_lower.iter_mut().zip(self.far_upper.iter_mut()))
    }

    /// Every stored block (diagonal, then the bands), in a fixed order.
    pub fn blocks_mut(&mut self) -> impl Iterator<Item = &mut Mat3> {
        self.diag
            .iter_mut()
            .chain(self.lower.iter_mut())
            .chain(self.upper.iter_mut())
            .chain(
                self.far_lower
                    .iter_mut()
                    .zip(self.far_upper.iter_mut())
                    .flat_map(|(l, u)| l.iter_mut().chain(u.iter_mut())),
            )
    }

    /// Every stored block in the order of [`LineBlocks::blocks_mut`].
    pub fn blocks(&self) -> impl Iterator<Item = &Mat3> {
        self.diag.iter().chain(
            self.band_pairs()
                .flat_map(|(l, u)| l.iter().chain(u.iter())),
        )
    }

    /// Whether the interior block rows 1 … N − 1 of a banded line (block bandwidth 2 to
    /// [`MAX_WIDTH`]) are symmetric to the bit: every diagonal block, and block (i, j) against
    /// (j, i)ᵀ. A mass matrix is (its blocks are ∫ s_i s_j m(s) ds with m symmetric); an
    /// implicit scheme's iteration matrix, with its drag Jacobian, is not.
    pub fn interior_is_symmetric(&self) -> bool {
        self.each_symmetric_lower_block(|_, _, _| {})
    }

    /// [`LineBlocks::interior_is_symmetric`], handing each interior block (i, j) of the lower
    /// band, j ≤ i, to `each` row by row as it is checked (up to the first that is not
    /// symmetric).
    fn each_symmetric_lower_block(&self, mut each: impl FnMut(usize, usize, &Mat3)) -> bool {
        let (n, w) = (self.nodes() - 1, self.width());
        if !(2..=MAX_WIDTH).contains(&w) {
            return false;
        }
        for i in 1..n {
            for k in (0..=w.min(i - 1)).rev() {
                let j = i - k;
                let (below, above) = match k {
                    0 => (&self.diag[i], &self.diag[i]),
                    1 => (&self.lower[j], &self.upper[j]),
                    _ => (&self.far_lower[k - 2][j], &self.far_upper[k - 2][j]),
                };
                if !same_bits(below, &above.transpose()) {
                    return false;
                }
                each(i, j, below);
            }
        }
        true
    }

    /// Factors the interior rows 1 … N − 1 of a banded line: by L D Lᵀ if they are symmetric
    /// to the bit ([`LineBlocks::interior_is_symmetric`], checked as the lower band is copied
    /// in), else by L U. `Err(i)` for a singular pivot block at interior row i (node i + 1).
    fn factor_interior(&mut self) -> Result<(), usize> {
        let (n, w) = (self.nodes() - 1, self.width());
        let mut f = std::mem::take(&mut self.interior);
        f.symmetric = self.each_symmetric_lower_block(|i, j, b| f.ldl.set(i - 1, j - 1, *b));
        let factored = if f.symmetric {
            f.ldl.factor(n - 1)
        } else {
            for i in 1..n {
                f.lu.set(i - 1, i - 1, self.diag[i]);
            }
            for (k, (below, above)) in (1..=w).zip(self.band_pairs()) {
                // below[j] is block (j + k, j), above[j] block (j, j + k).
                for j in 1..n.saturating_sub(k) {
                    f.lu.set(j + k - 1, j - 1, below[j]);
                    f.lu.set(j - 1, j + k - 1, above[j]);
                }
            }
            f.lu.factor(n - 1)
        };
        self.interior = f;
        factored
    }

    /// Number of nodes N + 1.
    pub fn nodes(&self) -> usize {
        self.diag.len()
    }

    /// Forms every diagonal block from the factored lumped mass when it is current
    /// ([`LumpedMass::current`]), for readers of the blocks after an evaluation that formed
    /// only the ends' ([`LumpedMass::ends_only`]); otherwise does nothing.
    pub fn form_lumped_diagonal(&mut self) {
        if self.lumped.current {
            for (i, d) in self.diag.iter_mut().enumerate() {
                *d = self.lumped.block(i);
            }
        }
    }

    /// Zeroes the blocks (not the ends' kinds).
    pub fn clear(&mut self) {
        self.lumped.current = false;
        self.diag.iter_mut().for_each(|m| *m = Mat3::zeros());
        if self.coupled {
            self.lower.iter_mut().for_each(|m| *m = Mat3::zeros());
            self.upper.iter_mut().for_each(|m| *m = Mat3::zeros());
            for b in self.far_lower.iter_mut().chain(self.far_upper.iter_mut()) {
                b.iter_mut().for_each(|m| *m = Mat3::zeros());
            }
        }
    }
}

/// The factors of a banded line's interior: its mass matrix, symmetric, by block L D Lᵀ
/// (whose factors are kept while the blocks do not change), anything else by block L U.
#[derive(Clone, Debug, Default)]
struct InteriorFactors {
    ldl: BlockBandedLdl,
    lu: BlockBandedLu,
    /// Whether the last factorisation was `ldl` (else `lu`).
    symmetric: bool,
}

impl InteriorFactors {
    fn new(interior: usize, width: usize) -> Self {
        Self {
            ldl: BlockBandedLdl::new(interior, width),
            lu: BlockBandedLu::new(interior, width),
            symmetric: false,
        }
    }

    /// Solves with the last factors for the interior's right-hand sides `x` (3-vectors, or
    /// 3×3 blocks of three columns).
    fn solve<const C: usize>(&self, n: usize, x: &mut [crate::math::Mat3xC<C>]) {
        if self.symmetric {
            self.ldl.solve(n, x);
        } else {
            self.lu.solve(n, x);
        }
    }
}

/// A point fixed on a free body that line ends attach to (a slot after the free points).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodySlot {
    /// Index of the body among the free bodies.
    pub body: usize,
    /// Offset ρ of the point from the body origin, in global axes [m].
    pub offset: Vec3,
    /// Centripetal acceleration c = ω × (ω × ρ) of the point [m/s²] (zero in statics).
    pub bias: Vec3,
}

/// The pin of a body on a point of another free (or pinned) body: the body's three
/// translational unknowns are the acceleration of the parent's point, a_o = J u_p + c with
/// J = [1, −[ρ]×] and c = ω_p × (ω_p × ρ) ([`crate::bodies`], "Pinned bodies").
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ParentPin {
    /// Index of the parent among the free bodies.
    pub body: usize,
    /// Offset ρ of the pin from the parent's origin, in global axes [m].
    pub offset: Vec3,
    /// The known part c of the pin's acceleration [m/s²]: ω_p × (ω_p × ρ) in the dynamics
    /// (zero in a Newton correction that starts on the constraint; its residual otherwise).
    pub bias: Vec3,
}

/// The shared part: per free point a diagonal block and right-hand side, per free body a 6×6
/// block and right-hand side, and the dense Schur-complement system.
#[derive(Clone, Debug)]
pub struct CoupledSystem {
    /// The points' own diagonal blocks (point mass, or the point's own stiffness).
    pub point_diag: Vec<Mat3>,
    /// The points' own right-hand sides on input; their solution on output.
    pub point_x: Vec<Vec3>,
    /// The bodies' own 6×6 blocks (mass about the origin in global axes).
    pub body_diag: Vec<Mat6>,
    /// The bodies' own right-hand sides [force; moment about the origin] on input; their
    /// solution [a_o; α] on output.
    pub body_x: Vec<Vec6>,
    /// Per body, the known translational unknowns of a pinned body ([`crate::bodies`]'s
    /// pinned bodies): `Some(a)` replaces the body's three force rows by a_o = a (the pin's
    /// acceleration, or a Newton increment), keeping its rotational rows; `None` for a free
    /// body. Set before each solve, like `body_x`.
    pub body_pin: Vec<Option<Vec3>>,
    /// Per body, the pin on a parent body's point of a body pinned to a body: `Some` adds
    /// Jᵀ times the body's three force rows to the parent's six rows (the pin force's reaction
    /// −R on the parent at the point, eliminated) and then replaces those rows by
    /// a_o − J u_p = c; `None` otherwise (with `body_pin` unset for such a body). Set before
    /// each solve, like `body_x`.
    pub body_parent: Vec<Option<ParentPin>>,
    /// The body-point slots, numbered after the free points; set offsets and biases before
    /// each solve.
    pub body_slots: Vec<BodySlot>,
    /// Acceleration of every slot after a solve (free points, then body points).
    pub slot_x: Vec<Vec3>,
    lu: DenseLu,
    b: Vec<Real>,
    tmp: Vec<Real>,
    /// Whether the solve in progress factors the matrices (false: it reuses the factors of
    /// the last solve, [`CoupledSystem::solve_again`]).
    factoring: bool,
}

impl CoupledSystem {
    /// Storage for `points` free points (and no bodies).
    pub fn new(points: usize) -> Self {
        Self::with_bodies(points, 0, 0)
    }

    /// Storage for `points` free points, `bodies` free bodies and `slots` points on them.
    pub fn with_bodies(points: usize, bodies: usize, slots: usize) -> Self {
        let n = 3 * points + 6 * bodies;
        Self {
            point_diag: vec![Mat3::zeros(); points],
            point_x: vec![Vec3::zeros(); points],
            body_diag: vec![Mat6::zeros(); bodies],
            body_x: vec![Vec6::zeros(); bodies],
            body_pin: vec![None; bodies],
            body_parent: vec![None; bodies],
            body_slots: vec![BodySlot::default(); slots],
            slot_x: vec![Vec3::zeros(); points + slots],
            lu: DenseLu::new(n),
            b: vec![0.0; n],
            tmp: vec![0.0; n],
            factoring: true,
        }
    }

    /// Row offset of body k's unknowns.
    #[inline]
    fn body_row(&self, k: usize) -> usize {
        3 * self.point_diag.len() + 6 * k
    }

    /// J of slot s as a 3×6 map and its row offset and width: [I 0] for a free point (width
    /// 3), [I, −[ρ]×] for a body point (width 6).
    #[inline]
    fn slot_map(&self, s: usize) -> (usize, usize, Matrix3x6, Vec3) {
        let np = self.point_diag.len();
        let mut j = Matrix3x6::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&Mat3::identity());
        if s < np {
            return (3 * s, 3, j, Vec3::zeros());
        }
        let slot = &self.body_slots[s - np];
        j.fixed_view_mut::<3, 3>(0, 3)
            .copy_from(&(-skew(&slot.offset)));
        (self.body_row(slot.body), 6, j, slot.bias)
    }

    /// Adds `sign`·m as the coefficient of slot q's acceleration in slot p's row.
    /// When the solve reuses the factors, only the right-hand side's part is added.
    fn add_block(&mut self, p: usize, q: usize, m: &Mat3, sign: Real) {
        let np = self.point_diag.len();
        if p < np && q < np {
            if !self.factoring {
                return;
            }
            for r in 0..3 {
                for c in 0..3 {
                    self.lu.add(3 * p + r, 3 * q + c, sign * m[(r, c)]);
                }
            }
            return;
        }
        let (op, wp, jp, _) = self.slot_map(p);
        let (oq, wq, jq, cq) = self.slot_map(q);
        if self.factoring {
            let full = jp.transpose() * m * jq;
            for r in 0..wp {
                for c in 0..wq {
                    self.lu.add(op + r, oq + c, sign * full[(r, c)]);
                }
            }
        }
        // The known part of a_q = J_q u + c_q moves to the right-hand side.
        let known = jp.transpose() * (m * cq) * sign;
        for r in 0..wp {
            self.b[op + r] -= known[r];
        }
    }

    /// Adds `v` (a force-like right-hand side at slot p) into p's rows: Jₚᵀ v.
    fn add_rhs(&mut self, p: usize, v: &Vec3) {
        if p < self.point_diag.len() {
            for k in 0..3 {
                self.b[3 * p + k] += v[k];
            }
            return;
        }
        let (op, wp, jp, _) = self.slot_map(p);
        let g = jp.transpose() * v;
        for r in 0..wp {
            self.b[op + r] += g[r];
        }
    }

    /// Step 1 of [`CoupledSystem::solve`] for a line of block bandwidth w > 1: the interior by
    /// block L D Lᵀ or L U and its responses to the free ends (step 2 is
    /// [`CoupledSystem::banded_contributions`]).
    fn eliminate_banded(&mut self, li: usize, line: &mut LineBlocks) -> Result<(), Singular> {
        let n = line.nodes() - 1;
        let w = line.width();
        let near = |i: usize, node: usize| i.abs_diff(node) <= w;
        if n > 1 {
            if line.end_a == EndKind::Known {
                let xa = line.x[0];
                for i in 1..n {
                    if near(i, 0) {
                        let b = line.block(i, 0);
                        line.x[i] -= b * xa;
                    }
                }
            }
            if line.end_b == EndKind::Known {
                let xb = line.x[n];
                for i in 1..n {
                    if near(i, n) {
                        let b = line.block(i, n);
                        line.x[i] -= b * xb;
                    }
                }
            }
            if self.factoring {
                line.factor_interior().map_err(|k| Singular::Line {
                    line: li,
                    node: k + 1,
                })?;
            }
            line.interior.solve(n - 1, &mut line.x[1..n]);
            for (end, node) in [(line.end_a, 0), (line.end_b, n)] {
                if !matches!(end, EndKind::Free(_)) || !self.factoring {
                    continue;
                }
                // The three columns at once.
                let mut response = std::mem::take(if node == 0 {
                    &mut line.response_a
                } else {
                    &mut line.response_b
                });
                for (i, m) in response.iter_mut().enumerate() {
                    *m = if near(i + 1, node) {
                        line.block(i + 1, node)
                    } else {
                        Mat3::zeros()
                    };
                }
                line.interior.solve(n - 1, &mut response);
                if node == 0 {
                    line.response_a = response;
                } else {
                    line.response_b = response;
                }
            }
        }
        Ok(())
    }

    /// Step 2 of [`CoupledSystem::solve`] for a line of block bandwidth w > 1 after
    /// [`CoupledSystem::eliminate_banded`]: its contributions to the points' Schur
    /// complement, S_pp += A_ee − Σ_j A_ej R_j, b_p += x_e − Σ_j A_ej z_j.
    fn banded_contributions(&mut self, line: &LineBlocks) {
        let n = line.nodes() - 1;
        let w = line.width();
        let near = |i: usize, node: usize| i.abs_diff(node) <= w;
        for (end, node) in [(line.end_a, 0), (line.end_b, n)] {
            let EndKind::Free(p) = end else { continue };
            let d = line.diag[node];
            self.add_block(p, p, &d, 1.0);
            let v = line.x[node];
            self.add_rhs(p, &v);
            let (other_node, other) = if node == 0 {
                (n, line.end_b)
            } else {
                (0, line.end_a)
            };
            if near(node, other_node) {
                let c = line.block(node, other_node);
                match other {
                    EndKind::Free(q) => self.add_block(p, q, &c, 1.0),
                    EndKind::Known => {
                        let v = -(c * line.x[other_node]);
                        self.add_rhs(p, &v);
                    }
                }
            }
            for j in 1..n {
                if !near(j, node) {
                    continue;
                }
                let c = line.block(node, j);
                let g = -(c * line.x[j]);
                self.add_rhs(p, &g);
                if let EndKind::Free(q) = line.end_a {
                    let m = c * line.response_a[j - 1];
                    self.add_block(p, q, &m, -1.0);
                }
                if let EndKind::Free(q) = line.end_b {
                    let m = c * line.response_b[j - 1];
                    self.add_block(p, q, &m, -1.0);
                }
            }
        }
    }

    /// Solves the whole system in place: every line's `x` and `point_x` become the solution.
    pub fn solve(&mut self, lines: &mut [LineBlocks]) -> Result<(), Singular> {
        self.factoring = true;
        self.eliminate(lines)
    }

    /// Solves for new right-hand sides (every line's `x`, `point_x`, `body_x`) with the
    /// factors of the last [`CoupledSystem::solve`]: the lines' blocks, the points' and
    /// bodies' own blocks and the body slots' offsets must be those it factored (the biases
    /// may differ). The same arithmetic as `solve` on the right-hand side, without the
    /// factorisations (the implicit scheme's Newton iterations on one iteration matrix).
    pub fn solve_again(&mut self, lines: &mut [LineBlocks]) -> Result<(), Singular> {
        self.factoring = false;
        let solved = self.eliminate(lines);
        self.factoring = true;
        solved
    }

    /// [`CoupledSystem::solve`], factoring when `self.factoring`.
    fn eliminate(&mut self, lines: &mut [LineBlocks]) -> Result<(), Singular> {
        let np = self.point_diag.len();
        if self.factoring {
            self.lu.clear();
        }
        for p in 0..np {
            let d = self.point_diag[p];
            self.add_block(p, p, &d, 1.0);
            for k in 0..3 {
                self.b[3 * p + k] = self.point_x[p][k];
            }
        }
        for k in 0..self.body_diag.len() {
            let o = self.body_row(k);
            for r in 0..6 {
                if self.factoring {
                    for c in 0..6 {
                        self.lu.add(o + r, o + c, self.body_diag[k][(r, c)]);
                    }
                }
                self.b[o + r] = self.body_x[k][r];
            }
        }
        // 1. Eliminate each line's interior.
        for (li, line) in lines.iter_mut().enumerate() {
            if line.coupled && line.width() > 1 {
                self.eliminate_banded(li, line)?;
                continue;
            }
            let n = line.nodes() - 1; // elements
            let interior = n - 1;
            if interior > 0 {
                // Known ends move to the right-hand side.
                if line.end_a == EndKind::Known {
                    let xa = line.x[0];
                    line.x[1] -= line.lower[0] * xa;
                }
                if line.end_b == EndKind::Known {
                    let xb = line.x[n];
                    line.x[n - 1] -= line.upper[n - 1] * xb;
                }
                if line.coupled {
                    if self.factoring {
                        line.factor
                            .factor(
                                &line.diag[1..n],
                                &line.lower[1..n - 1],
                                &line.upper[1..n - 1],
                            )
                            .map_err(|k| Singular::Line {
                                line: li,
                                node: k + 1,
                            })?;
                    }
                    // The solve waits for the other lines' (below).
                    if !self.factoring {
                        // The responses depend on the blocks only: kept.
                    } else if let EndKind::Free(_) = line.end_a {
                        line.response_a.iter_mut().for_each(|m| *m = Mat3::zeros());
                        line.response_a[0] = line.lower[0];
                        line.factor.solve_blocks(interior, &mut line.response_a);
                    }
                    if let (true, EndKind::Free(_)) = (self.factoring, line.end_b) {
                        line.response_b.iter_mut().for_each(|m| *m = Mat3::zeros());
                        line.response_b[interior - 1] = line.upper[n - 1];
                        line.factor.solve_blocks(interior, &mut line.response_b);
                    }
                } else if line.lumped.current {
                    line.lumped
                        .solve_interior(&mut line.x[1..n])
                        .map_err(|node| Singular::Line { line: li, node })?;
                } else {
                    for i in 1..n {
                        line.x[i] = crate::math::solve3(&line.diag[i], &line.x[i])
                            .ok_or(Singular::Line { line: li, node: i })?;
                    }
                }
            }
        }
        // The coupled tridiagonal lines' solves, interleaved four lines at a time.
        let mut group: [Option<(&BlockTridiagonal, usize, &mut [Vec3])>; 4] = Default::default();
        let mut members = 0;
        let solvable = lines
            .iter_mut()
            .filter(|l| l.coupled && l.width() == 1 && l.nodes() > 2);
        for line in solvable {
            let n = line.nodes() - 1;
            group[members] = Some((&line.factor, n - 1, &mut line.x[1..n]));
            members += 1;
            if members == group.len() {
                BlockTridiagonal::solve_group(&mut group);
                group = Default::default();
                members = 0;
            }
        }
        BlockTridiagonal::solve_group(&mut group);
        // 2. Contributions of each line to the point system, in the lines' order.
        for line in lines.iter() {
            if line.coupled && line.width() > 1 {
                self.banded_contributions(line);
                continue;
            }
            let n = line.nodes() - 1;
            let interior = n - 1;
            for (end, node, next) in [(line.end_a, 0usize, 1usize), (line.end_b, n, n - 1)] {
                let EndKind::Free(p) = end else { continue };
                let d = line.diag[node];
                self.add_block(p, p, &d, 1.0);
                let v = line.x[node];
                self.add_rhs(p, &v);
                // Coupling block from the neighbouring node into this end's row.
                let c = if node == 0 {
                    line.upper[0]
                } else {
                    line.lower[n - 1]
                };
                if !line.coupled {
                    continue;
                }
                if interior == 0 {
                    // One element: the two ends couple directly.
                    let other = if node == 0 { line.end_b } else { line.end_a };
                    match other {
                        EndKind::Free(q) => self.add_block(p, q, &c, 1.0),
                        EndKind::Known => {
                            let xo = -(c * line.x[next]);
                            self.add_rhs(p, &xo);
                        }
                    }
                    continue;
                }
                let j = next - 1; // interior index of the neighbour
                let g = -(c * line.x[next]);
                self.add_rhs(p, &g);
                if let EndKind::Free(q) = line.end_a {
                    let m = c * line.response_a[j];
                    self.add_block(p, q, &m, -1.0);
                }
                if let EndKind::Free(q) = line.end_b {
                    let m = c * line.response_b[j];
                    self.add_block(p, q, &m, -1.0);
                }
            }
        }
        // 3. Solve the points and bodies. A body pinned to a body: R (the pin's force on it)
        // is eliminated by adding Jᵀ × its force rows to the parent's rows, and its force rows
        // become the constraint a_o − J u_p = c.
        for k in 0..self.body_diag.len() {
            let Some(pin) = self.body_parent[k] else {
                continue;
            };
            let (o, op) = (self.body_row(k), self.body_row(pin.body));
            let mut j = Matrix3x6::zeros();
            j.fixed_view_mut::<3, 3>(0, 0).copy_from(&Mat3::identity());
            j.fixed_view_mut::<3, 3>(0, 3)
                .copy_from(&(-skew(&pin.offset)));
            for r in 0..3 {
                for i in 0..6 {
                    if self.factoring {
                        self.lu.add_scaled_row(op + i, o + r, j[(r, i)]);
                    }
                    self.b[op + i] += j[(r, i)] * self.b[o + r];
                }
                if self.factoring {
                    self.lu.identity_row(o + r);
                    for c in 0..6 {
                        self.lu.add(o + r, op + c, -j[(r, c)]);
                    }
                }
                self.b[o + r] = pin.bias[r];
            }
        }
        // A pinned body's translations held.
        for k in 0..self.body_diag.len() {
            let Some(a) = self.body_pin[k] else { continue };
            let o = self.body_row(k);
            for r in 0..3 {
                if self.factoring {
                    self.lu.identity_row(o + r);
                }
                self.b[o + r] = a[r];
            }
        }
        if !self.b.is_empty() {
            if self.factoring {
                self.lu
                    .factor()
                    .map_err(|k| Singular::Point((k / 3).min(np)))?;
            }
            self.lu.solve(&mut self.b, &mut self.tmp);
            for p in 0..np {
                self.point_x[p] = Vec3::new(self.b[3 * p], self.b[3 * p + 1], self.b[3 * p + 2]);
                self.slot_x[p] = self.point_x[p];
            }
            for k in 0..self.body_diag.len() {
                let o = self.body_row(k);
                self.body_x[k] = Vec6::from_fn(|r, _| self.b[o + r]);
            }
            for s in 0..self.body_slots.len() {
                let slot = self.body_slots[s];
                let u = self.body_x[slot.body];
                let a = Vec3::new(u[0], u[1], u[2]);
                let alpha = Vec3::new(u[3], u[4], u[5]);
                self.slot_x[np + s] = a + alpha.cross(&slot.offset) + slot.bias;
            }
        }
        // 4. Back-substitute the interiors and set the free ends.
        for line in lines.iter_mut() {
            let n = line.nodes() - 1;
            let interior = n - 1;
            let xa = match line.end_a {
                EndKind::Free(p) => Some(self.slot_x[p]),
                EndKind::Known => None,
            };
            let xb = match line.end_b {
                EndKind::Free(p) => Some(self.slot_x[p]),
                EndKind::Known => None,
            };
            if line.coupled && interior > 0 {
                for j in 0..interior {
                    let mut v = line.x[j + 1];
                    if let Some(xa) = xa {
                        v -= line.response_a[j] * xa;
                    }
                    if let Some(xb) = xb {
                        v -= line.response_b[j] * xb;
                    }
                    line.x[j + 1] = v;
                }
            }
            if let Some(xa) = xa {
                line.x[0] = xa;
            }
            if let Some(xb) = xb {
                line.x[n] = xb;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// The factored lumped solve against Cramer's rule on the assembled block, for tangents
    /// at every angle (parallel to perpendicular), anisotropic added mass of either sign
    /// (C_at < C_an, as in most decks, and C_at > C_an) and tangents off unit length by
    /// round-off. Both solve the same 3×3 system in double precision; its condition number is
    /// below 1e3 here, so they agree to 1e-12 relative (a few hundred ulps of the result).
    #[test]
    fn lumped_solve_matches_assembled_block() {
        let mut m = LumpedMass::new(3);
        let mut worst: Real = 0.0;
        for k in 0..200 {
            let a = 0.1 * k as Real;
            let t1 = Vec3::new(a.cos(), a.sin() * 0.6, a.sin() * 0.8) * (1.0 + 1e-15);
            let t2 = Vec3::new((1.3 * a).sin(), 0.2, (1.3 * a).cos()).normalize();
            let (c, beta) = (2.5 + 0.01 * k as Real, if k % 2 == 0 { -0.9 } else { 1.7 });
            m.isotropic = vec![1.0, c, 1.0];
            m.set_element(0, t1.into(), [0.3, beta]);
            m.set_element(1, t2.into(), [0.8 * beta, 0.2]);
            let f = Vec3::new(1.0, -2.0 + 0.03 * k as Real, 0.5);
            let mut x = [f];
            m.solve_interior(&mut x).unwrap();
            let x = x[0];
            let reference = crate::math::solve3(&m.block(1), &f).unwrap();
            worst = worst.max((x - reference).norm() / reference.norm());
            assert!((m.block(1) * x - f).norm() < 1e-13 * f.norm());
        }
        assert!(worst < 1e-12, "{worst}");
        // A singular block (no isotropic mass) is reported, not divided by.
        m.isotropic[1] = 0.0;
        assert_eq!(m.solve_interior(&mut [Vec3::x()]), Err(1));
    }

    /// The solve of a line's interior, whose nodes go in groups of lanes (four, or eight from
    /// [`WIDE_SOLVE`] nodes with AVX-512), the nodes after the last whole group in a group
    /// ending at the last node, gives each node the bits of [`solve_two_rank_one`] at that
    /// node, for interiors of 1 to 27 nodes (no group, groups with and without remainder, in
    /// four and in eight lanes), and reports the first singular node wherever it lies, also
    /// when the last node is singular too. (The instruction set the process runs; the `simd`
    /// test of the command-line crate compares AVX-512, AVX2 and SSE2 on whole runs.)
    #[test]
    fn lumped_lanes_are_the_node_solve_to_the_bit() {
        for interior in 1..=27 {
            let nodes = interior + 2;
            let mut m = LumpedMass::new(nodes);
            for i in 0..nodes {
                m.isotropic[i] = 3.0 + 0.37 * i as Real;
            }
            for e in 0..nodes - 1 {
                let a = 0.7 * e as Real + 0.1;
                let t = Vec3::new(a.cos(), 0.3 * a.sin(), a.sin()).normalize();
                let beta = if e % 3 == 0 {
                    -1.1
                } else {
                    0.6 + 0.1 * e as Real
                };
                m.set_element(e, t.into(), [beta, 0.9 * beta]);
            }
            let force =
                |j: usize| Vec3::new(1.0 + j as Real, -0.5 * j as Real, 2.0 - 0.1 * j as Real);
            let expected: Vec<Vec3> = (1..=interior)
                .map(|j| {
                    let (t1, t2) = (m.tangent_of(j - 1), m.tangent_of(j));
                    let (b1, b2) = (m.rank_one[1][j - 1], m.rank_one[0][j]);
                    solve_two_rank_one(m.isotropic[j], b1, &t1, b2, &t2, &force(j)).unwrap()
                })
                .collect();
            let mut x: Vec<Vec3> = (1..=interior).map(force).collect();
            m.solve_interior(&mut x).unwrap();
            for (j, (a, b)) in x.iter().zip(&expected).enumerate() {
                for k in 0..3 {
                    assert_eq!(a[k].to_bits(), b[k].to_bits(), "{interior} nodes, node {j}");
                }
            }
            // A singular block at each node in turn is reported at that node.
            for j in 1..=interior {
                let kept = m.isotropic[j];
                m.isotropic[j] = 0.0;
                let mut x: Vec<Vec3> = (1..=interior).map(force).collect();
                assert_eq!(m.solve_interior(&mut x), Err(j), "{interior} nodes");
                let kept_last = m.isotropic[interior];
                m.isotropic[interior] = 0.0;
                let mut x: Vec<Vec3> = (1..=interior).map(force).collect();
                assert_eq!(
                    m.solve_interior(&mut x),
                    Err(j),
                    "{interior} nodes, last too"
                );
                m.isotropic[interior] = kept_last;
                m.isotropic[j] = kept;
            }
        }
    }

    /// Two lines sharing a free point, one end fixed each, compared with a dense solve.
    #[test]
    fn matches_dense_assembly() {
        check_against_dense(1, &[4, 3, 1], false);
    }

    /// The same with block bandwidth 3 (Hermite lines), including lines short enough for
    /// their ends to couple directly.
    #[test]
    fn banded_matches_dense_assembly() {
        // Not symmetric (the block L U) and symmetric (the block L D Lᵀ).
        for symmetric in [false, true] {
            check_against_dense(3, &[9, 6, 3], symmetric);
            check_against_dense(3, &[4, 2, 2], symmetric);
            check_against_dense(2, &[5, 7, 2], symmetric);
        }
    }

    /// Lines on points of a free rigid body (and a free point), bandwidths 1 and 3, against a
    /// dense assembly of Σ Tᵀ (A (T z + t) − x) + own = 0, with T mapping the unknowns z
    /// (interior nodes, the point, the body's [a_o; α]) to every node's acceleration and t
    /// the known parts (fixed ends, centripetal terms).
    #[test]
    fn body_slots_match_dense_assembly() {
        for (width, symmetric) in [(1, false), (3, false), (3, true)] {
            check_bodies_against_dense(width, symmetric);
        }
    }

    /// Fills every block of `l` from `seed` on: diagonal blocks dominant (+5 I), the others
    /// half-size; with `symmetric`, to the bit (block (j, i) is block (i, j)ᵀ, the diagonal
    /// blocks symmetric), as a mass matrix's are.
    fn fill_blocks(l: &mut LineBlocks, width: usize, symmetric: bool, seed: &mut usize) {
        let f = |i: usize, r: usize, c: usize| ((i * 13 + r * 5 + c * 7) % 17) as f64 / 17.0 - 0.5;
        for m in l.diag.iter_mut() {
            *seed += 1;
            *m = Mat3::from_fn(|r, c| {
                let (r, c) = if symmetric {
                    (r.min(c), r.max(c))
                } else {
                    (r, c)
                };
                f(*seed, r, c)
            }) + Mat3::identity() * 5.0;
        }
        let last = l.nodes() - 1;
        for i in 0..=last {
            for j in i.saturating_sub(width)..=(i + width).min(last) {
                if i != j && !(symmetric && j < i) {
                    *seed += 1;
                    let m = Mat3::from_fn(|r, c| f(*seed, r, c)) * 0.5;
                    *l.block_mut(i, j) = m;
                    if symmetric {
                        *l.block_mut(j, i) = m.transpose();
                    }
                }
            }
        }
        if width > 1 && l.nodes() > 3 {
            assert_eq!(l.interior_is_symmetric(), symmetric);
        }
    }

    fn check_bodies_against_dense(width: usize, symmetric: bool) {
        let f = |i: usize, r: usize, c: usize| ((i * 13 + r * 5 + c * 7) % 17) as f64 / 17.0 - 0.5;
        // Slots: 0 is the free point; 1 and 2 are points on body 0.
        let ends = [
            (EndKind::Known, EndKind::Free(1)),
            (EndKind::Free(0), EndKind::Free(2)),
            (EndKind::Free(2), EndKind::Known),
            (EndKind::Free(1), EndKind::Free(2)),
        ];
        let nodes = [5usize, 4, 3, 1];
        let mut lines: Vec<_> = nodes
            .iter()
            .zip(ends)
            .map(|(&m, (a, b))| {
                LineBlocks::banded(if width > 1 { 2 * m + 2 } else { m + 1 }, width, a, b, true)
            })
            .collect();
        let mut seed = 0;
        for l in lines.iter_mut() {
            fill_blocks(l, width, symmetric, &mut seed);
            for (i, x) in l.x.iter_mut().enumerate() {
                *x = Vec3::new(i as f64, 1.0 + seed as f64 * 0.1, -0.3);
            }
        }
        let mut sys = CoupledSystem::with_bodies(1, 1, 2);
        sys.point_diag = vec![Mat3::identity() * 2.0];
        sys.point_x = vec![Vec3::new(1.0, 2.0, 3.0)];
        sys.body_diag = vec![Mat6::from_fn(|r, c| {
            if r == c { 40.0 } else { f(r + 6 * c, r, c) }
        })];
        sys.body_diag[0] = (sys.body_diag[0] + sys.body_diag[0].transpose()) * 0.5;
        sys.body_x = vec![Vec6::new(1.0, -2.0, 0.5, 0.3, -0.1, 0.2)];
        sys.body_slots = vec![
            BodySlot {
                body: 0,
                offset: Vec3::new(1.0, 0.5, -0.2),
                bias: Vec3::new(0.1, 0.0, -0.3),
            },
            BodySlot {
                body: 0,
                offset: Vec3::new(-0.7, 0.2, 0.9),
                bias: Vec3::new(0.0, 0.2, 0.1),
            },
        ];
        // Unknowns: interior nodes, then the point (3), then the body (6).
        let mut interior = vec![];
        let mut count = 0;
        for l in &lines {
            let n = l.nodes() - 1;
            interior.push(count);
            count += n - 1;
        }
        let (pz, bz) = (3 * count, 3 * count + 3);
        let dim = bz + 6;
        let mut g = DMatrix::<f64>::zeros(dim, dim);
        let mut rhs = DVector::<f64>::zeros(dim);
        for (li, l) in lines.iter().enumerate() {
            let n = l.nodes() - 1;
            let rows = 3 * (n + 1);
            let mut t = DMatrix::<f64>::zeros(rows, dim);
            let mut t0 = DVector::<f64>::zeros(rows);
            let mut equation = vec![true; n + 1];
            for i in 0..=n {
                let end = if i == 0 {
                    Some(l.end_a)
                } else if i == n {
                    Some(l.end_b)
                } else {
                    None
                };
                match end {
                    None => {
                        let c = 3 * (interior[li] + i - 1);
                        t.view_mut((3 * i, c), (3, 3)).copy_from(&Mat3::identity());
                    }
                    Some(EndKind::Known) => {
                        equation[i] = false;
                        for k in 0..3 {
                            t0[3 * i + k] = l.x[i][k];
                        }
                    }
                    Some(EndKind::Free(0)) => {
                        t.view_mut((3 * i, pz), (3, 3)).copy_from(&Mat3::identity());
                    }
                    Some(EndKind::Free(s)) => {
                        let slot = sys.body_slots[s - 1];
                        t.view_mut((3 * i, bz), (3, 3)).copy_from(&Mat3::identity());
                        t.view_mut((3 * i, bz + 3), (3, 3))
                            .copy_from(&(-skew(&slot.offset)));
                        for k in 0..3 {
                            t0[3 * i + k] = slot.bias[k];
                        }
                    }
                }
            }
            let mut a = DMatrix::<f64>::zeros(rows, rows);
            let mut x = DVector::<f64>::zeros(rows);
            for i in 0..=n {
                for k in 0..3 {
                    x[3 * i + k] = l.x[i][k];
                }
                for j in i.saturating_sub(width)..=(i + width).min(n) {
                    a.view_mut((3 * i, 3 * j), (3, 3)).copy_from(&l.block(i, j));
                }
            }
            for i in (0..=n).filter(|&i| !equation[i]) {
                a.view_mut((3 * i, 0), (3, rows)).fill(0.0);
                x.view_mut((3 * i, 0), (3, 1)).fill(0.0);
            }
            g += t.transpose() * &a * &t;
            rhs += t.transpose() * (x - &a * t0);
        }
        let own = g.view((pz, pz), (3, 3)) + sys.point_diag[0];
        g.view_mut((pz, pz), (3, 3)).copy_from(&own);
        let own = g.view((bz, bz), (6, 6)) + sys.body_diag[0];
        g.view_mut((bz, bz), (6, 6)).copy_from(&own);
        for k in 0..3 {
            rhs[pz + k] += sys.point_x[0][k];
        }
        for k in 0..6 {
            rhs[bz + k] += sys.body_x[0][k];
        }
        let z = g.lu().solve(&rhs).unwrap();
        sys.solve(&mut lines).unwrap();
        for k in 0..6 {
            assert!(
                (sys.body_x[0][k] - z[bz + k]).abs() < 1e-10,
                "body {k}: {} vs {}",
                sys.body_x[0][k],
                z[bz + k]
            );
        }
        for k in 0..3 {
            assert!((sys.point_x[0][k] - z[pz + k]).abs() < 1e-10);
        }
        for (li, l) in lines.iter().enumerate() {
            let n = l.nodes() - 1;
            for i in 1..n {
                for k in 0..3 {
                    let r = 3 * (interior[li] + i - 1) + k;
                    assert!(
                        (l.x[i][k] - z[r]).abs() < 1e-10,
                        "line {li} node {i}: {} vs {}",
                        l.x[i][k],
                        z[r]
                    );
                }
            }
        }
    }

    /// With `symmetric`, every line's blocks are symmetric to the bit (block (j, i) is block
    /// (i, j)ᵀ, the diagonal blocks symmetric), as a mass matrix's are.
    fn check_against_dense(width: usize, nodes: &[usize], symmetric: bool) {
        let ends = [
            (EndKind::Known, EndKind::Free(0)),
            (EndKind::Free(0), EndKind::Free(1)),
            (EndKind::Free(1), EndKind::Known),
        ];
        let mut lines: Vec<_> = nodes
            .iter()
            .zip(ends)
            .map(|(&m, (a, b))| LineBlocks::banded(m + 1, width, a, b, true))
            .collect();
        let mut seed = 0;
        for l in lines.iter_mut() {
            fill_blocks(l, width, symmetric, &mut seed);
            for (i, x) in l.x.iter_mut().enumerate() {
                *x = Vec3::new(i as f64, 1.0 + seed as f64 * 0.1, -0.3);
            }
        }
        let mut sys = CoupledSystem::new(2);
        sys.point_diag = vec![Mat3::identity() * 2.0, Mat3::identity() * 3.0];
        sys.point_x = vec![Vec3::new(1.0, 2.0, 3.0), Vec3::new(-1.0, 0.5, 0.0)];
        // Dense reference: unknowns are interior nodes of each line then the two points.
        let mut index = vec![];
        let mut count = 0;
        for l in &lines {
            let n = l.nodes() - 1;
            let mut idx = vec![None; n + 1];
            for slot in idx.iter_mut().take(n).skip(1) {
                *slot = Some(count);
                count += 1;
            }
            index.push(idx);
        }
        let p0 = count;
        let dim = 3 * (count + 2);
        for (l, idx) in lines.iter().zip(index.iter_mut()) {
            let n = l.nodes() - 1;
            if let EndKind::Free(p) = l.end_a {
                idx[0] = Some(p0 + p);
            }
            if let EndKind::Free(p) = l.end_b {
                idx[n] = Some(p0 + p);
            }
        }
        let mut a = DMatrix::<f64>::zeros(dim, dim);
        let mut b = DVector::<f64>::zeros(dim);
        for p in 0..2 {
            a.view_mut((3 * (p0 + p), 3 * (p0 + p)), (3, 3))
                .copy_from(&sys.point_diag[p]);
            for k in 0..3 {
                b[3 * (p0 + p) + k] = sys.point_x[p][k];
            }
        }
        for (l, idx) in lines.iter().zip(index.iter()) {
            let n = l.nodes() - 1;
            for i in 0..=n {
                let Some(ri) = idx[i] else { continue };
                let mut blk = a.view_mut((3 * ri, 3 * ri), (3, 3)).clone_owned();
                blk += l.diag[i];
                a.view_mut((3 * ri, 3 * ri), (3, 3)).copy_from(&blk);
                for k in 0..3 {
                    b[3 * ri + k] += l.x[i][k];
                }
                for j in i.saturating_sub(width)..=(i + width).min(n) {
                    if j == i {
                        continue;
                    }
                    let m = l.block(i, j);
                    match idx.get(j).copied().flatten() {
                        Some(cj) => {
                            let mut blk = a.view_mut((3 * ri, 3 * cj), (3, 3)).clone_owned();
                            blk += m;
                            a.view_mut((3 * ri, 3 * cj), (3, 3)).copy_from(&blk);
                        }
                        None => {
                            let v = m * l.x[j];
                            for k in 0..3 {
                                b[3 * ri + k] -= v[k];
                            }
                        }
                    }
                }
            }
        }
        let xd = a.lu().solve(&b).unwrap();
        sys.solve(&mut lines).unwrap();
        for (l, idx) in lines.iter().zip(index.iter()) {
            for (i, slot) in idx.iter().enumerate() {
                if let Some(r) = slot {
                    for k in 0..3 {
                        assert!(
                            (l.x[i][k] - xd[3 * r + k]).abs() < 1e-11,
                            "{} vs {}",
                            l.x[i][k],
                            xd[3 * r + k]
                        );
                    }
                }
            }
        }
    }
}
