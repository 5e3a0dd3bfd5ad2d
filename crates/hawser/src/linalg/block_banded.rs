//! Block-banded factorisations with 3×3 blocks, for the interior of a line whose element
//! couples more than two neighbouring 3-vectors (`hermite` elements: r_a, t_a, r_b, t_b, block
//! bandwidth 3): L D Lᵀ for its mass matrix, which is symmetric positive definite, and L U
//! without pivoting between blocks for the iteration matrices and stiffness Jacobians, which
//! are not symmetric.

use crate::math::{Mat3, Mat3xC, inverse3};

/// The widest block band [`BlockBandedLdl`] and [`BlockBandedLu`] take (a `hermite` line's is 3).
pub const MAX_WIDTH: usize = 4;

/// The L D Lᵀ factors of a symmetric n-block matrix of block bandwidth w with 3×3 blocks,
/// A = L D Lᵀ with L block lower triangular (identity blocks on its diagonal) and D block
/// diagonal, no pivoting between blocks (which suits a symmetric positive definite mass).
///
/// Row by row (left-looking, "row Cholesky" on blocks): for each row i, with f = max(0, i − w),
///
///   W_ij = A_ij − Σ_{k = f}^{j−1} W_ik L_jkᵀ   (j = f … i − 1, W_ij = L_ij D_j),
///   L_ij = W_ij D_j⁻¹,   D_i = A_ii − Σ_{j = f}^{i−1} L_ij W_ijᵀ,
///
/// about w(w + 1)/2 + 2w products of 3×3 blocks and one 3×3 inverse per block row: for w = 3,
/// 9 products, where a banded L U of the same matrix by scalar rows (half-bandwidth 3w + 2)
/// takes about (3w + 2)² multiply–adds per scalar row, 363 per block row, in short loops, and
/// [`BlockBandedLu`] 12 products.
/// Only the lower blocks are read; the caller checks that the matrix is symmetric.
///
/// The factors are kept with the matrix they came from: [`BlockBandedLdl::factor`] of a
/// matrix whose blocks are, bit for bit, those it last factored returns at once and leaves the
/// factors as they are (a line mass that does not change between evaluations: a `hermite`
/// line with C_at = C_an whose points stay wet, or dry). Comparing costs a read of each block
/// as it is set; factoring, about 9 block products and a 3×3 inverse per block row.
#[derive(Clone, Debug, Default)]
pub struct BlockBandedLdl {
    width: usize,
    /// A_ii as set.
    matrix_diag: Vec<Mat3>,
    /// A_{i, i−k} as set, at i w + k − 1, k = 1 … w.
    matrix_lower: Vec<Mat3>,
    /// Whether a block set since the last factorisation differs from the one factored.
    changed: bool,
    /// The block rows n of the factors held, if they are those of `matrix_*`.
    factored: Option<usize>,
    /// Factorisations done (not counting the reuses).
    factorisations: usize,
    /// D_i⁻¹.
    inv_diag: Vec<Mat3>,
    /// L_{i, i−k} at i w + k − 1, k = 1 … w.
    lower: Vec<Mat3>,
}

impl BlockBandedLdl {
    /// Storage for up to `n` block rows of block bandwidth `width` (at most [`MAX_WIDTH`]).
    pub fn new(n: usize, width: usize) -> Self {
        let (matrix_diag, matrix_lower) = band_storage(n, width);
        let (inv_diag, lower) = band_storage(n, width);
        Self {
            width,
            matrix_diag,
            matrix_lower,
            changed: true,
            factored: None,
            factorisations: 0,
            inv_diag,
            lower,
        }
    }

    #[inline(always)]
    fn l(&self, i: usize, j: usize) -> &Mat3 {
        &self.lower[lower_at(self.width, i, j)]
    }

    /// Sets block (i, j) of the lower band, i − w ≤ j ≤ i, before [`BlockBandedLdl::factor`].
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, block: Mat3) {
        let a = if i == j {
            &mut self.matrix_diag[i]
        } else {
            &mut self.matrix_lower[lower_at(self.width, i, j)]
        };
        if !self.changed && !same_bits(a, &block) {
            self.changed = true;
        }
        *a = block;
    }

    /// Factors the n-block matrix whose lower band [`BlockBandedLdl::set`] gave, unless its
    /// blocks are those of the factors held (then nothing is done). `Err(i)` if D_i is
    /// singular or not finite.
    pub fn factor(&mut self, n: usize) -> Result<(), usize> {
        if !self.changed && self.factored == Some(n) {
            return Ok(());
        }
        self.changed = false;
        self.factored = None;
        self.factorisations += 1;
        ldl_factor(
            &self.matrix_diag,
            &self.matrix_lower,
            &mut self.inv_diag,
            &mut self.lower,
            self.width,
            n,
        )?;
        self.factored = Some(n);
        Ok(())
    }

    /// The factorisations done so far; a [`BlockBandedLdl::factor`] that reused the factors
    /// held does not count.
    pub fn factorisations(&self) -> usize {
        self.factorisations
    }

    /// Solves A X = B in place for the n-block right-hand side `x` (3-vectors, C = 1, or
    /// 3×3 blocks, C = 3, one column per right-hand side): L Y = B from the top, then
    /// X = D⁻¹ Y − Σ_{j > i} L_jiᵀ X_j from the bottom.
    #[allow(clippy::needless_range_loop)] // j indexes both x and the factors
    pub fn solve<const C: usize>(&self, n: usize, x: &mut [Mat3xC<C>]) {
        let w = self.width;
        forward_unit_lower(&self.lower, w, n, x);
        for i in (0..n).rev() {
            let mut s = self.inv_diag[i] * x[i];
            for j in i + 1..(i + w + 1).min(n) {
                s -= self.l(j, i).tr_mul(&x[j]);
            }
            x[i] = s;
        }
    }
}

/// Whether two blocks are equal bit for bit (+0 and −0 differ; a NaN equals its own bits).
#[inline(always)]
pub(crate) fn same_bits(a: &Mat3, b: &Mat3) -> bool {
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// L Y = B in place from the top for a unit block lower triangular L of bandwidth w whose
/// block (i, j) is `lower[lower_at(w, i, j)]` (the forward substitution of both factorisations).
#[allow(clippy::needless_range_loop)] // j indexes both x and the factors
fn forward_unit_lower<const C: usize>(lower: &[Mat3], w: usize, n: usize, x: &mut [Mat3xC<C>]) {
    for i in 1..n {
        let mut s = x[i];
        for j in i.saturating_sub(w)..i {
            s -= lower[lower_at(w, i, j)] * x[j];
        }
        x[i] = s;
    }
}

/// Zeroed storage of n diagonal blocks and of a band of `width` blocks beside each (at most
/// [`MAX_WIDTH`]).
fn band_storage(n: usize, width: usize) -> (Vec<Mat3>, Vec<Mat3>) {
    assert!(
        width <= MAX_WIDTH,
        "block bandwidth {width} above {MAX_WIDTH}"
    );
    (vec![Mat3::zeros(); n], vec![Mat3::zeros(); n * width])
}

/// The index of block (i, j), i − w ≤ j < i, in the lower band's storage: i w + (i − j) − 1.
#[inline(always)]
fn lower_at(w: usize, i: usize, j: usize) -> usize {
    i * w + (i - j) - 1
}

crate::math::wide_simd_fn! {
    /// [`BlockBandedLdl::factor`]: from A's diagonal `a_diag` and lower band `a_lower`
    /// (A_{i,i−k} at i w + k − 1), `inv_diag[i]` becomes D_i⁻¹ and `lower` holds W_{i,i−k},
    /// then L_{i,i−k}.
    fn ldl_factor(
        a_diag: &[Mat3],
        a_lower: &[Mat3],
        diag: &mut [Mat3],
        lower: &mut [Mat3],
        w: usize,
        n: usize,
    ) -> Result<(), usize> {
        let at = |i: usize, j: usize| lower_at(w, i, j);
        for i in 0..n {
            let first = i.saturating_sub(w);
            for j in first..i {
                let mut s = a_lower[at(i, j)];
                for k in first..j {
                    s -= lower[at(i, k)] * lower[at(j, k)].transpose();
                }
                lower[at(i, j)] = s;
            }
            let mut d = a_diag[i];
            for j in first..i {
                let wij = lower[at(i, j)];
                let l = wij * diag[j];
                d -= l * wij.transpose();
                lower[at(i, j)] = l;
            }
            // `None` for a singular or non-finite D_i, as in the block-tridiagonal factors.
            diag[i] = inverse3(&d).ok_or(i)?;
        }
        Ok(())
    }
}

/// The L U factors of an n-block matrix of block bandwidth w with 3×3 blocks, A = L U with L
/// block lower triangular (identity blocks on its diagonal) and U block upper triangular, no
/// pivoting between blocks (as the block-tridiagonal factors: an implicit scheme's iteration
/// matrix is the mass plus small multiples of the damping and stiffness, and Newton statics
/// regularises slack lines). Each pivot block U_ii is inverted whole, so a block needs only
/// be invertible, where a scalar L U without pivoting needs each of its leading minors to be.
///
/// Row by row (Doolittle on blocks): for each row i, with f = max(0, i − w),
///
///   L_ij = (A_ij − Σ_{k = f}^{j−1} L_ik U_kj) U_jj⁻¹   (j = f … i − 1),
///   U_ij = A_ij − Σ_{k = max(f, j − w)}^{i−1} L_ik U_kj   (j = i … i + w),
///
/// about w² + w products of 3×3 blocks and one 3×3 inverse per block row (12 for w = 3).
#[derive(Clone, Debug, Default)]
pub struct BlockBandedLu {
    width: usize,
    /// A_ii, then U_ii⁻¹.
    inv_diag: Vec<Mat3>,
    /// A_{i, i−k}, then L_{i, i−k}, at i w + k − 1, k = 1 … w.
    lower: Vec<Mat3>,
    /// A_{i, i+k}, then U_{i, i+k}, at i w + k − 1, k = 1 … w.
    upper: Vec<Mat3>,
}

impl BlockBandedLu {
    /// Storage for up to `n` block rows of block bandwidth `width` (at most [`MAX_WIDTH`]).
    pub fn new(n: usize, width: usize) -> Self {
        let (inv_diag, lower) = band_storage(n, width);
        Self {
            width,
            inv_diag,
            lower,
            upper: band_storage(n, width).1,
        }
    }

    /// Sets block (i, j), |i − j| ≤ w, before [`BlockBandedLu::factor`].
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, block: Mat3) {
        match i.cmp(&j) {
            std::cmp::Ordering::Equal => self.inv_diag[i] = block,
            std::cmp::Ordering::Greater => self.lower[lower_at(self.width, i, j)] = block,
            std::cmp::Ordering::Less => self.upper[lower_at(self.width, j, i)] = block,
        }
    }

    /// Factors in place the n-block matrix [`BlockBandedLu::set`] gave. `Err(i)` if U_ii is
    /// singular or not finite.
    pub fn factor(&mut self, n: usize) -> Result<(), usize> {
        lu_factor(
            &mut self.inv_diag,
            &mut self.lower,
            &mut self.upper,
            self.width,
            n,
        )
    }

    /// Solves A X = B in place for the n-block right-hand side `x` (3-vectors, C = 1, or
    /// 3×3 blocks, C = 3): L Y = B from the top, then X_i = U_ii⁻¹ (Y_i − Σ_{j > i} U_ij X_j)
    /// from the bottom.
    #[allow(clippy::needless_range_loop)] // j indexes both x and the factors
    pub fn solve<const C: usize>(&self, n: usize, x: &mut [Mat3xC<C>]) {
        let w = self.width;
        forward_unit_lower(&self.lower, w, n, x);
        for i in (0..n).rev() {
            let mut s = x[i];
            for j in i + 1..(i + w + 1).min(n) {
                s -= self.upper[lower_at(w, j, i)] * x[j];
            }
            x[i] = self.inv_diag[i] * s;
        }
    }
}

crate::math::wide_simd_fn! {
    /// [`BlockBandedLu::factor`] on its storage (A's blocks in, the factors out, in place).
    fn lu_factor(
        diag: &mut [Mat3],
        lower: &mut [Mat3],
        upper: &mut [Mat3],
        w: usize,
        n: usize,
    ) -> Result<(), usize> {
        // L_ij at lower_at(w, i, j) (j < i); U_ij at lower_at(w, j, i) (j > i).
        for i in 0..n {
            let first = i.saturating_sub(w);
            for j in first..i {
                let mut s = lower[lower_at(w, i, j)];
                for k in first..j {
                    s -= lower[lower_at(w, i, k)] * upper[lower_at(w, j, k)];
                }
                lower[lower_at(w, i, j)] = s * diag[j];
            }
            let mut d = diag[i];
            for k in first..i {
                d -= lower[lower_at(w, i, k)] * upper[lower_at(w, i, k)];
            }
            // `None` for a singular or non-finite U_ii, as in the block-tridiagonal factors.
            diag[i] = inverse3(&d).ok_or(i)?;
            for j in i + 1..(i + w + 1).min(n) {
                let mut s = upper[lower_at(w, j, i)];
                for k in j.saturating_sub(w).max(first)..i {
                    s -= lower[lower_at(w, i, k)] * upper[lower_at(w, j, k)];
                }
                upper[lower_at(w, j, i)] = s;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Real, Vec3};
    use nalgebra::{DMatrix, DVector};

    /// Against nalgebra's dense LU for symmetric positive definite block-banded matrices of
    /// bandwidths 1 to 3, with as many blocks as the band and more, one vector and three
    /// columns at once. 1e-12 relative: the matrices are strictly diagonally dominant
    /// (diagonal 40 to 42, the rest of a row at most 3 (2w + 1) × 0.5 ≤ 10.5), so their
    /// condition numbers are below 2 by Gershgorin and both solves are accurate to a few
    /// ulps of the O(1) solution.
    #[test]
    fn matches_dense_lu() {
        for (n, w) in [(9, 3), (3, 3), (1, 3), (7, 2), (5, 1)] {
            let f = |i: usize, j: usize, r: usize, c: usize| {
                let (a, b) = ((3 * i + r).min(3 * j + c), (3 * i + r).max(3 * j + c));
                ((a * 7 + b * 3) % 11) as Real / 11.0 - 0.5
                    + if a == b { 40.0 + (a % 3) as Real } else { 0.0 }
            };
            let block = |i: usize, j: usize| Mat3::from_fn(|r, c| f(i, j, r, c));
            let dense = DMatrix::from_fn(3 * n, 3 * n, |p, q| {
                let (i, j) = (p / 3, q / 3);
                if i.abs_diff(j) <= w {
                    f(i, j, p % 3, q % 3)
                } else {
                    0.0
                }
            });
            let mut ldl = BlockBandedLdl::new(n, w);
            for i in 0..n {
                for j in i.saturating_sub(w)..=i {
                    ldl.set(i, j, block(i, j));
                }
            }
            ldl.factor(n).unwrap();
            let b = DVector::from_fn(3 * n, |p, _| (p as Real).sin() + 1.0);
            check_solves(n, w, &dense, &b, |x| ldl.solve(n, x), |x| ldl.solve(n, x));
        }
    }

    /// Solves A x = b (`solve_vectors`) and A X = [b 2b 3b] (`solve_columns`) and compares
    /// them with nalgebra's dense LU of `dense` to 1e-12 of the solution's largest entry (3e-12
    /// for the columns, up to 3× larger).
    fn check_solves(
        n: usize,
        w: usize,
        dense: &DMatrix<Real>,
        b: &DVector<Real>,
        solve_vectors: impl Fn(&mut [Vec3]),
        solve_columns: impl Fn(&mut [Mat3]),
    ) {
        let exact = dense.clone().lu().solve(b).unwrap();
        let mut x: Vec<Vec3> = (0..n)
            .map(|i| Vec3::new(b[3 * i], b[3 * i + 1], b[3 * i + 2]))
            .collect();
        solve_vectors(&mut x);
        let mut columns: Vec<Mat3> = (0..n)
            .map(|i| Mat3::from_fn(|r, c| b[3 * i + r] * (c + 1) as Real))
            .collect();
        solve_columns(&mut columns);
        let scale = exact.amax();
        for p in 0..3 * n {
            let (i, r) = (p / 3, p % 3);
            assert!(
                (x[i][r] - exact[p]).abs() < 1e-12 * scale,
                "n {n} w {w} entry {p}: {} vs {}",
                x[i][r],
                exact[p]
            );
            for c in 0..3 {
                let want = exact[p] * (c + 1) as Real;
                assert!(
                    (columns[i][(r, c)] - want).abs() < 1e-12 * scale * 3.0,
                    "n {n} w {w} column {c} entry {p}"
                );
            }
        }
    }

    /// A singular pivot block is reported at its block row.
    #[test]
    fn reports_a_singular_block() {
        // Diagonal blocks 2I but I/1.5 at row 2, I beside them: D_0 = 2I, D_1 = 2I − I (2I)⁻¹ I
        // = 1.5 I, D_2 = I/1.5 − I (1.5 I)⁻¹ I = 0.
        let block = |i: usize, j: usize| {
            if i == j {
                if i == 2 {
                    Mat3::identity() / 1.5
                } else {
                    Mat3::identity() * 2.0
                }
            } else {
                Mat3::identity()
            }
        };
        let mut ldl = BlockBandedLdl::new(4, 1);
        for i in 0..4usize {
            for j in i.saturating_sub(1)..=i {
                ldl.set(i, j, block(i, j));
            }
        }
        assert_eq!(ldl.factor(4), Err(2));
    }

    /// The factors of an unchanged matrix are reused, and any changed bit of any block (even
    /// +0 to −0), a different size or a failed factorisation makes the next call factor
    /// again; the solve after a reuse is the solve of a fresh factorisation to the bit.
    #[test]
    fn reuses_the_factors_of_an_unchanged_matrix() {
        let (n, w): (usize, usize) = (6, 3);
        let block = |i: usize, j: usize| {
            Mat3::from_fn(|r, c| {
                let (p, q) = ((3 * i + r).min(3 * j + c), (3 * i + r).max(3 * j + c));
                ((p * 5 + q * 3) % 7) as Real / 7.0 + if p == q { 20.0 } else { 0.0 }
            })
        };
        let set_all = |ldl: &mut BlockBandedLdl, change: Option<(usize, usize, Mat3)>| {
            for i in 0..n {
                for j in i.saturating_sub(w)..=i {
                    let b = match change {
                        Some((ci, cj, b)) if (ci, cj) == (i, j) => b,
                        _ => block(i, j),
                    };
                    ldl.set(i, j, b);
                }
            }
        };
        let solution = |ldl: &BlockBandedLdl| {
            let mut x: Vec<Vec3> = (0..n).map(|i| Vec3::new(1.0, i as Real, -2.0)).collect();
            ldl.solve(n, &mut x);
            x
        };
        let mut ldl = BlockBandedLdl::new(n, w);
        set_all(&mut ldl, None);
        ldl.factor(n).unwrap();
        let first = solution(&ldl);
        set_all(&mut ldl, None);
        ldl.factor(n).unwrap();
        assert_eq!(
            ldl.factorisations(),
            1,
            "the same blocks: the factors reused"
        );
        assert_eq!(solution(&ldl), first);
        // One entry one ulp up, in the far band; then a zero's sign.
        let mut up = block(4, 1);
        up[(2, 0)] = Real::from_bits(up[(2, 0)].to_bits() + 1);
        let (mut zero, mut negative_zero) = (block(5, 3), block(5, 3));
        zero[(0, 1)] = 0.0;
        negative_zero[(0, 1)] = -0.0;
        for (count, change) in [
            (2, (4, 1, up)),
            (3, (5, 3, zero)),
            (4, (5, 3, negative_zero)),
        ] {
            set_all(&mut ldl, Some(change));
            ldl.factor(n).unwrap();
            assert_eq!(
                ldl.factorisations(),
                count,
                "changed block {:?}",
                (change.0, change.1)
            );
            let mut fresh = BlockBandedLdl::new(n, w);
            set_all(&mut fresh, Some(change));
            fresh.factor(n).unwrap();
            assert_eq!(solution(&ldl), solution(&fresh));
        }
        // Fewer block rows: factored again.
        ldl.factor(n - 1).unwrap();
        assert_eq!(ldl.factorisations(), 5);
        // A singular matrix fails every time it is factored, not only the first.
        let mut singular = BlockBandedLdl::new(2, 1);
        for _ in 0..2 {
            singular.set(0, 0, Mat3::identity());
            singular.set(1, 0, Mat3::identity());
            singular.set(1, 1, Mat3::identity());
            assert_eq!(singular.factor(2), Err(1));
        }
    }

    /// [`BlockBandedLu`] against nalgebra's dense LU for non-symmetric block-banded matrices of
    /// bandwidths 1 to 4, with as many blocks as the band and more, one vector and three
    /// columns at once. 1e-12 relative, as for the L D Lᵀ: the diagonal is 40 to 42 and the
    /// rest of a row at most 3 (2w + 1) × 0.5 ≤ 13.5, so the matrices are strictly diagonally
    /// dominant and well conditioned. And a pivot block singular as a whole but with a zero
    /// leading entry elsewhere is no obstacle: only a singular U_ii is reported, at its row.
    #[test]
    fn lu_matches_dense_lu() {
        for (n, w) in [(9, 3), (3, 3), (1, 3), (7, 2), (5, 1), (11, 4)] {
            let f = |p: usize, q: usize| {
                ((p * 7 + q * 3) % 11) as Real / 11.0 - 0.5
                    + if p == q { 40.0 + (p % 3) as Real } else { 0.0 }
            };
            let dense = DMatrix::from_fn(3 * n, 3 * n, |p, q| {
                if (p / 3).abs_diff(q / 3) <= w {
                    f(p, q)
                } else {
                    0.0
                }
            });
            let mut lu = BlockBandedLu::new(n, w);
            for i in 0..n {
                for j in i.saturating_sub(w)..=(i + w).min(n - 1) {
                    lu.set(i, j, Mat3::from_fn(|r, c| f(3 * i + r, 3 * j + c)));
                }
            }
            lu.factor(n).unwrap();
            let b = DVector::from_fn(3 * n, |p, _| (p as Real).cos() - 0.3);
            check_solves(n, w, &dense, &b, |x| lu.solve(n, x), |x| lu.solve(n, x));
        }
        // Pivot blocks P = [[0, 1, 0], [1, 0, 0], [0, 0, 2]], whose zero first entry would stop
        // a scalar L U without pivoting, with −I beside them: U_00 = P is inverted whole, and
        // U_11 = P − (−I) P⁻¹ (−I) = P − P⁻¹ = diag(0, 0, 1.5) is singular, reported at row 1.
        let p = Mat3::new(0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0);
        let mut lu = BlockBandedLu::new(3, 1);
        for i in 0..3usize {
            for j in i.saturating_sub(1)..=(i + 1).min(2) {
                lu.set(i, j, if i == j { p } else { -Mat3::identity() });
            }
        }
        assert_eq!(lu.factor(3), Err(1));
    }
}
