//! Block-tridiagonal factorisation with 3×3 blocks (block Thomas algorithm).

use crate::math::{Mat3, Vec3, inverse3};

/// An n-block tridiagonal matrix with 3×3 blocks, factorised in place.
///
/// Row i holds `lower[i-1]` (column i−1), `diag[i]`, `upper[i]` (column i+1). The factors are
/// D'_0 = D_0, W_i = L_{i−1} D'^{-1}_{i−1}, D'_i = D_i − W_i U_{i−1}; no pivoting between
/// blocks, which suits the symmetric positive-definite mass matrices and the stiffness
/// Jacobians of taut cables (Newton regularises slack ones).
#[derive(Clone, Debug, Default)]
pub struct BlockTridiagonal {
    inv_diag: Vec<Mat3>,
    multiplier: Vec<Mat3>,
    upper: Vec<Mat3>,
}

impl BlockTridiagonal {
    /// Workspace for up to `n` blocks.
    pub fn with_capacity(n: usize) -> Self {
        Self {
            inv_diag: vec![Mat3::zeros(); n],
            multiplier: vec![Mat3::zeros(); n],
            upper: vec![Mat3::zeros(); n],
        }
    }

    /// Factorises the matrix with blocks `diag[0..n]`, `lower[0..n-1]`, `upper[0..n-1]`.
    /// Returns the index of a singular pivot block on failure.
    pub fn factor(&mut self, diag: &[Mat3], lower: &[Mat3], upper: &[Mat3]) -> Result<(), usize> {
        let n = diag.len();
        debug_assert!(self.inv_diag.len() >= n);
        let mut pivot = diag[0];
        for i in 0..n {
            if i > 0 {
                let w = lower[i - 1] * self.inv_diag[i - 1];
                pivot = diag[i] - w * upper[i - 1];
                self.multiplier[i] = w;
                self.upper[i - 1] = upper[i - 1];
            }
            self.inv_diag[i] = inverse3(&pivot).ok_or(i)?;
        }
        Ok(())
    }

    /// Solves in place for one right-hand side of `n` 3-vectors.
    #[inline]
    #[allow(clippy::needless_range_loop)] // rows i of three arrays
    pub fn solve(&self, n: usize, x: &mut [Vec3]) {
        // Each substitution's last result is carried in registers to the next row, rather than
        // stored and loaded again (a store-to-load delay on the dependency chain).
        let mut last = x[0];
        for i in 1..n {
            last = x[i] - self.multiplier[i] * last;
            x[i] = last;
        }
        last = self.inv_diag[n - 1] * last;
        x[n - 1] = last;
        for i in (0..n.saturating_sub(1)).rev() {
            last = self.inv_diag[i] * (x[i] - self.upper[i] * last);
            x[i] = last;
        }
    }

    /// [`BlockTridiagonal::solve`] for several systems at once, `(factors, n, x)` each, their
    /// substitutions interleaved step by step so that the processor overlaps the systems'
    /// dependency chains. Each system runs its own operations in its own order: the same bits
    /// as one at a time. `None` entries are skipped; every n is at least 1.
    pub fn solve_group(group: &mut [Option<(&Self, usize, &mut [Vec3])>]) {
        if group.iter().flatten().count() == 1 {
            // Nothing to interleave with: the plain loop, which has no per-step tests.
            let (f, n, x) = group.iter_mut().flatten().next().expect("one system");
            f.solve(*n, x);
            return;
        }
        let longest = group.iter().flatten().map(|g| g.1).max().unwrap_or(0);
        for i in 1..longest {
            for (f, n, x) in group.iter_mut().flatten() {
                if i < *n {
                    let y = x[i] - f.multiplier[i] * x[i - 1];
                    x[i] = y;
                }
            }
        }
        for (f, n, x) in group.iter_mut().flatten() {
            x[*n - 1] = f.inv_diag[*n - 1] * x[*n - 1];
        }
        // Step j of the back substitution is row n − 1 − j of each system.
        for j in 1..longest {
            for (f, n, x) in group.iter_mut().flatten() {
                if j < *n {
                    let i = *n - 1 - j;
                    x[i] = f.inv_diag[i] * (x[i] - f.upper[i] * x[i + 1]);
                }
            }
        }
    }

    /// Solves in place for a right-hand side of `n` 3×3 blocks (three columns at once).
    pub fn solve_blocks(&self, n: usize, x: &mut [Mat3]) {
        for i in 1..n {
            let y = x[i] - self.multiplier[i] * x[i - 1];
            x[i] = y;
        }
        x[n - 1] = self.inv_diag[n - 1] * x[n - 1];
        for i in (0..n.saturating_sub(1)).rev() {
            x[i] = self.inv_diag[i] * (x[i] - self.upper[i] * x[i + 1]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    #[test]
    fn matches_dense_lu() {
        let n = 7;
        let mut diag = vec![];
        let mut lower = vec![];
        let mut upper = vec![];
        let f = |i: usize, j: usize, k: usize| ((i * 7 + j * 3 + k * 5) % 11) as f64 / 11.0 - 0.5;
        for i in 0..n {
            diag.push(Mat3::from_fn(|r, c| f(i, r, c)) + Mat3::identity() * 6.0);
            if i + 1 < n {
                lower.push(Mat3::from_fn(|r, c| f(i + 20, r, c)));
                upper.push(Mat3::from_fn(|r, c| f(i + 40, r, c)));
            }
        }
        let mut dense = DMatrix::<f64>::zeros(3 * n, 3 * n);
        for i in 0..n {
            dense.view_mut((3 * i, 3 * i), (3, 3)).copy_from(&diag[i]);
            if i + 1 < n {
                dense
                    .view_mut((3 * i + 3, 3 * i), (3, 3))
                    .copy_from(&lower[i]);
                dense
                    .view_mut((3 * i, 3 * i + 3), (3, 3))
                    .copy_from(&upper[i]);
            }
        }
        let b: Vec<Vec3> = (0..n)
            .map(|i| Vec3::new(i as f64, 1.0, -(i as f64) * 0.5))
            .collect();
        let bd = DVector::from_iterator(3 * n, b.iter().flat_map(|v| [v.x, v.y, v.z]));
        let xd = dense.lu().solve(&bd).unwrap();
        let mut bt = BlockTridiagonal::with_capacity(n);
        bt.factor(&diag, &lower, &upper).unwrap();
        let mut x = b.clone();
        bt.solve(n, &mut x);
        for i in 0..n {
            for k in 0..3 {
                assert!((x[i][k] - xd[3 * i + k]).abs() < 1e-12);
            }
        }
    }

    /// The grouped solve gives each system exactly what its own solve gives, for systems of
    /// different sizes (1 to 9 blocks) in groups of one to four, with empty slots.
    #[test]
    fn grouped_solve_is_each_solve_to_the_bit() {
        let f = |i: usize, j: usize, k: usize| ((i * 7 + j * 3 + k * 5) % 11) as f64 / 11.0 - 0.5;
        let system = |n: usize, seed: usize| {
            let diag: Vec<Mat3> = (0..n)
                .map(|i| Mat3::from_fn(|r, c| f(i + seed, r, c)) + Mat3::identity() * 6.0)
                .collect();
            let off = |shift: usize| -> Vec<Mat3> {
                (0..n.saturating_sub(1))
                    .map(|i| Mat3::from_fn(|r, c| f(i + seed + shift, r, c)))
                    .collect()
            };
            let mut bt = BlockTridiagonal::with_capacity(n);
            bt.factor(&diag, &off(20), &off(40)).unwrap();
            let b: Vec<Vec3> = (0..n)
                .map(|i| Vec3::new((i + seed) as f64, 1.0, -0.3 * i as f64))
                .collect();
            (bt, b)
        };
        for sizes in [vec![5], vec![9, 1], vec![3, 7, 2], vec![4, 9, 1, 6]] {
            let systems: Vec<_> = sizes
                .iter()
                .enumerate()
                .map(|(k, &n)| system(n, k))
                .collect();
            let alone: Vec<Vec<Vec3>> = systems
                .iter()
                .zip(&sizes)
                .map(|((bt, b), &n)| {
                    let mut x = b.clone();
                    bt.solve(n, &mut x);
                    x
                })
                .collect();
            let mut grouped: Vec<Vec<Vec3>> = systems.iter().map(|(_, b)| b.clone()).collect();
            let mut group: [Option<(&BlockTridiagonal, usize, &mut [Vec3])>; 5] =
                Default::default();
            // An empty slot first, then the systems.
            for (slot, ((bt, _), x)) in group[1..].iter_mut().zip(systems.iter().zip(&mut grouped))
            {
                *slot = Some((bt, x.len(), x.as_mut_slice()));
            }
            BlockTridiagonal::solve_group(&mut group);
            for (a, g) in alone.iter().zip(&grouped) {
                for (u, v) in a.iter().zip(g) {
                    for k in 0..3 {
                        assert_eq!(u[k].to_bits(), v[k].to_bits(), "sizes {sizes:?}");
                    }
                }
            }
        }
    }
}
