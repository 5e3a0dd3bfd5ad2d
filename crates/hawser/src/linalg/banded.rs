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
    pub fn factor(&mut self) -> Result<(), usize> {
        let (n, kd) = (self.n, self.kd);
        for k in 0..n {
            let pivot = self.a[self.at(k, k)];
            if pivot == 0.0 || !pivot.is_finite() {
                return Err(k);
            }
            let last = (k + kd).min(n - 1);
            for i in k + 1..=last {
                let ik = self.at(i, k);
                let l = self.a[ik] / pivot;
                self.a[ik] = l;
                if l == 0.0 {
                    continue;
                }
                for j in k + 1..=last {
                    let kj = self.a[self.at(k, j)];
                    let ij = self.at(i, j);
                    self.a[ij] -= l * kj;
                }
            }
        }
        Ok(())
    }

    /// Solves A x = b in place after [`BandedLu::factor`].
    pub fn solve(&self, b: &mut [Real]) {
        let (n, kd) = (self.n, self.kd);
        for i in 0..n {
            let first = i.saturating_sub(kd);
            let mut s = b[i];
            for (j, bj) in b.iter().enumerate().take(i).skip(first) {
                s -= self.a[self.at(i, j)] * bj;
            }
            b[i] = s;
        }
        for i in (0..n).rev() {
            let last = (i + kd).min(n - 1);
            let mut s = b[i];
            for (j, bj) in b.iter().enumerate().take(last + 1).skip(i + 1) {
                s -= self.a[self.at(i, j)] * bj;
            }
            b[i] = s / self.a[self.at(i, i)];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    #[test]
    fn matches_dense_lu() {
        let (n, kd) = (17, 5);
        let mut band = BandedLu::new(n, kd);
        let mut dense = DMatrix::<f64>::zeros(n, n);
        for i in 0..n {
            for j in i.saturating_sub(kd)..=(i + kd).min(n - 1) {
                let v = ((i * 7 + j * 3) % 11) as f64 / 11.0 - 0.5 + if i == j { 6.0 } else { 0.0 };
                band.set(i, j, v);
                dense[(i, j)] = v;
            }
        }
        let b = DVector::from_fn(n, |i, _| (i as f64).sin());
        let xd = dense.lu().solve(&b).unwrap();
        band.factor().unwrap();
        let mut x: Vec<f64> = b.iter().copied().collect();
        band.solve(&mut x);
        for i in 0..n {
            assert!((x[i] - xd[i]).abs() < 1e-13, "{i}: {} vs {}", x[i], xd[i]);
        }
    }
}
