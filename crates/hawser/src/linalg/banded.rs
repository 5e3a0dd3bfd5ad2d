//! Banded LU without pivoting on preallocated storage: the interior of a line whose element
//! couples more than two neighbouring 3-vectors (Hermite elements: r_a, t_a, r_b, t_b).

use crate::math::Real;

/// An n×n matrix with `kd` sub- and super-diagonals, stored by rows of width 2·kd + 1, and
/// its LU factors in place (Doolittle, no pivoting: the mass matrices are symmetric positive
/// definite and the stiffness Jacobians of taut cables diagonally dominant enough; Newton
/// regularises slack ones, as for the block-tridiagonal solver).
#[derive(Clone, Debug, Default)]
pub struct BandedLu {
    n: usize,
    kd: usize,
    a: Vec<Real>,
}

impl BandedLu {
    /// Storage for an n×n matrix of half-bandwidth `kd`.
    pub fn new(n: usize, kd: usize) -> Self {
        Self {
            n,
            kd,
            a: vec![0.0; n * (2 * kd + 1)],
        }
    }

    /// Sets every entry to zero.
    pub fn clear(&mut self) {
        self.a.iter_mut().for_each(|x| *x = 0.0);
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> usize {
        i * (2 * self.kd + 1) + (j + self.kd - i)
    }

    /// Sets entry (i, j), |i − j| ≤ kd.
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, v: Real) {
        debug_assert!(i.abs_diff(j) <= self.kd);
        let k = self.at(i, j);
        self.a[k] = v;
    }

    /// Factorises in place; `Err(k)` on a zero (or non-finite) pivot in row k.
    ///
    /// Row by row on the band's storage: the update of row i by row k is one pass over the
    /// columns k + 1 … k + kd, which lie side by side in both rows.
    pub fn factor(&mut self) -> Result<(), usize> {
        let (n, kd) = (self.n, self.kd);
        let width = 2 * kd + 1;
        for k in 0..n {
            let pivot = self.a[k * width + kd];
            if pivot == 0.0 || !pivot.is_finite() {
                return Err(k);
            }
            let last = (k + kd).min(n - 1);
            // Row k's columns k + 1 ..= last, and the rows below it.
            let (head, below) = self.a.split_at_mut((k + 1) * width);
            let row_k = &head[k * width + kd + 1..k * width + kd + 1 + (last - k)];
            for (i, row_i) in (k + 1..=last).zip(below.chunks_exact_mut(width)) {
                // Column j of row i is at j + kd − i.
                let ik = k + kd - i;
                let l = row_i[ik] / pivot;
                row_i[ik] = l;
                if l == 0.0 {
                    continue;
                }
                for (x, &kj) in row_i[ik + 1..ik + 1 + row_k.len()].iter_mut().zip(row_k) {
                    *x -= l * kj;
                }
            }
        }
        Ok(())
    }

    /// Solves A x = b in place after [`BandedLu::factor`].
    pub fn solve(&self, b: &mut [Real]) {
        let (n, kd) = (self.n, self.kd);
        let width = 2 * kd + 1;
        let b = &mut b[..n];
        for (i, row) in self.a.chunks_exact(width).enumerate().take(n) {
            let first = i.saturating_sub(kd);
            let (done, rest) = b.split_at_mut(i);
            let mut s = rest[0];
            for (a, bj) in row[first + kd - i..kd].iter().zip(&done[first..]) {
                s -= a * bj;
            }
            rest[0] = s;
        }
        // By index: `take(n).rev()` over the rows would divide for each row (`nth_back`).
        for i in (0..n).rev() {
            let row = &self.a[i * width..(i + 1) * width];
            let last = (i + kd).min(n - 1);
            let (head, after) = b.split_at_mut(i + 1);
            let mut s = head[i];
            for (a, bj) in row[kd + 1..kd + 1 + (last - i)]
                .iter()
                .zip(&after[..last - i])
            {
                s -= a * bj;
            }
            head[i] = s / row[kd];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    #[test]
    fn matches_dense_lu() {
        // Bands narrower and wider than the matrix, and a 1×1.
        for (n, kd) in [(17, 5), (8, 1), (3, 5), (1, 2)] {
            let mut band = BandedLu::new(n, kd);
            let mut dense = DMatrix::<f64>::zeros(n, n);
            for i in 0..n {
                for j in i.saturating_sub(kd)..=(i + kd).min(n - 1) {
                    let v =
                        ((i * 7 + j * 3) % 11) as f64 / 11.0 - 0.5 + if i == j { 6.0 } else { 0.0 };
                    band.set(i, j, v);
                    dense[(i, j)] = v;
                }
            }
            let b = DVector::from_fn(n, |i, _| (i as f64).sin() + 1.0);
            let xd = dense.lu().solve(&b).unwrap();
            band.factor().unwrap();
            let mut x: Vec<f64> = b.iter().copied().collect();
            band.solve(&mut x);
            for i in 0..n {
                assert!(
                    (x[i] - xd[i]).abs() < 1e-13,
                    "n {n} kd {kd}, {i}: {} vs {}",
                    x[i],
                    xd[i]
                );
            }
        }
    }
}
