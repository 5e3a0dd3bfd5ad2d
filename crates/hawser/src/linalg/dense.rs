//! Small dense LU with partial pivoting on preallocated storage (the shared-point system).

use crate::math::Real;

/// In-place LU factorisation of an n×n row-major matrix, sized once.
#[derive(Clone, Debug, Default)]
pub struct DenseLu {
    n: usize,
    /// Row-major matrix, then its factors.
    pub a: Vec<Real>,
    perm: Vec<usize>,
}

impl DenseLu {
    /// Storage for an n×n system.
    pub fn new(n: usize) -> Self {
        Self {
            n,
            a: vec![0.0; n * n],
            perm: (0..n).collect(),
        }
    }
    /// Dimension.
    pub fn dim(&self) -> usize {
        self.n
    }
    /// Sets every entry to zero.
    pub fn clear(&mut self) {
        self.a.iter_mut().for_each(|x| *x = 0.0);
    }
    /// Adds `v` to entry (i, j).
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, v: Real) {
        self.a[i * self.n + j] += v;
    }
    /// Replaces row i by the identity's (the equation x_i = b_i).
    pub fn identity_row(&mut self, i: usize) {
        let n = self.n;
        self.a[i * n..(i + 1) * n].iter_mut().for_each(|x| *x = 0.0);
        self.a[i * n + i] = 1.0;
    }
    /// Adds s times row j to row i (i ≠ j).
    pub fn add_scaled_row(&mut self, i: usize, j: usize, s: Real) {
        let n = self.n;
        for c in 0..n {
            self.a[i * n + c] += s * self.a[j * n + c];
        }
    }
    /// Factorises in place; `Err(k)` on a zero pivot in column k.
    pub fn factor(&mut self) -> Result<(), usize> {
        let n = self.n;
        for (i, p) in self.perm.iter_mut().enumerate() {
            *p = i;
        }
        let scale = self
            .a
            .iter()
            .fold(0.0, |m: Real, x| m.max(x.abs()))
            .max(Real::MIN_POSITIVE);
        for k in 0..n {
            let mut piv = k;
            for i in k + 1..n {
                if self.a[i * n + k].abs() > self.a[piv * n + k].abs() {
                    piv = i;
                }
            }
            if !(self.a[piv * n + k].abs() > 1e-14 * scale) {
                return Err(k);
            }
            if piv != k {
                for j in 0..n {
                    self.a.swap(k * n + j, piv * n + j);
                }
                self.perm.swap(k, piv);
            }
            let d = self.a[k * n + k];
            for i in k + 1..n {
                let m = self.a[i * n + k] / d;
                self.a[i * n + k] = m;
                if m != 0.0 {
                    for j in k + 1..n {
                        self.a[i * n + j] -= m * self.a[k * n + j];
                    }
                }
            }
        }
        Ok(())
    }
    /// Solves in place with the factors (`b` is overwritten by x; `tmp` has length n).
    pub fn solve(&self, b: &mut [Real], tmp: &mut [Real]) {
        let n = self.n;
        for i in 0..n {
            tmp[i] = b[self.perm[i]];
        }
        for i in 0..n {
            let mut s = tmp[i];
            for j in 0..i {
                s -= self.a[i * n + j] * tmp[j];
            }
            tmp[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = tmp[i];
            for j in i + 1..n {
                s -= self.a[i * n + j] * tmp[j];
            }
            tmp[i] = s / self.a[i * n + i];
        }
        b[..n].copy_from_slice(&tmp[..n]);
    }
}
