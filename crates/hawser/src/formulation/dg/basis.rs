//! Legendre modal basis on the reference element ξ ∈ [−1, 1], Gauss–Legendre and
//! Gauss–Lobatto quadrature, and the tables one element order needs (DG paper §3).
//!
//! The trial and test functions are the Legendre polynomials φ_k = P_k(ξ), k = 0..=P. Their
//! mass matrix is diagonal, (φ_k, φ_l)_Ωe = h/(2k + 1) δ_kl, so the DG mass solve is a scaling.
//! Values at the element ends are P_k(1) = 1 and P_k(−1) = (−1)^k.

use crate::math::Real;

/// Highest polynomial order supported (the tables are built for any order; 16 bounds the
/// quadrature's Newton iterations to well-conditioned cases).
pub const MAX_ORDER: usize = 16;

/// Legendre polynomials P_0..P_n at ξ and their derivatives, by the three-term recurrence
/// (k+1) P_{k+1} = (2k+1) ξ P_k − k P_{k−1} and P'_{k+1} = P'_{k−1} + (2k+1) P_k.
pub fn legendre(n: usize, xi: Real, p: &mut [Real], dp: &mut [Real]) {
    p[0] = 1.0;
    dp[0] = 0.0;
    if n == 0 {
        return;
    }
    p[1] = xi;
    dp[1] = 1.0;
    for k in 1..n {
        let kf = k as Real;
        p[k + 1] = ((2.0 * kf + 1.0) * xi * p[k] - kf * p[k - 1]) / (kf + 1.0);
        dp[k + 1] = dp[k - 1] + (2.0 * kf + 1.0) * p[k];
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1] with `n` points (exact for degree 2n − 1).
pub fn gauss_legendre(n: usize) -> (Vec<Real>, Vec<Real>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let mut p = vec![0.0; n + 1];
    let mut dp = vec![0.0; n + 1];
    for i in 0..n {
        // Chebyshev-like initial guess, then Newton on P_n.
        let mut xi = -(std::f64::consts::PI * (i as Real + 0.75) / (n as Real + 0.5)).cos();
        for _ in 0..100 {
            legendre(n, xi, &mut p, &mut dp);
            let dx = p[n] / dp[n];
            xi -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        legendre(n, xi, &mut p, &mut dp);
        x[i] = xi;
        w[i] = 2.0 / ((1.0 - xi * xi) * dp[n] * dp[n]);
    }
    (x, w)
}

/// Gauss–Lobatto–Legendre nodes and weights on [−1, 1] with `n` ≥ 2 points, ends included
/// (exact for degree 2n − 3): the ends and the roots of P'_{n−1}.
pub fn gauss_lobatto(n: usize) -> (Vec<Real>, Vec<Real>) {
    assert!(n >= 2);
    let m = n - 1;
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let mut p = vec![0.0; n + 1];
    let mut dp = vec![0.0; n + 1];
    x[0] = -1.0;
    x[m] = 1.0;
    for (i, xo) in x.iter_mut().enumerate().take(m).skip(1) {
        // Roots of P'_m: Newton on (1 − ξ²) P'_m = m (P_{m−1} − ξ P_m) from Chebyshev–Lobatto.
        let mut xi = -(std::f64::consts::PI * i as Real / m as Real).cos();
        for _ in 0..100 {
            legendre(m, xi, &mut p, &mut dp);
            // f = P'_m, f' = (2ξ P'_m − m(m+1) P_m) / (1 − ξ²).
            let f = dp[m];
            let df = (2.0 * xi * dp[m] - (m * (m + 1)) as Real * p[m]) / (1.0 - xi * xi);
            let dx = f / df;
            xi -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        *xo = xi;
    }
    for (xi, wi) in x.iter().zip(w.iter_mut()) {
        legendre(m, *xi, &mut p, &mut dp);
        *wi = 2.0 / ((m * (m + 1)) as Real * p[m] * p[m]);
    }
    (x, w)
}

/// The tables of one element order P: Legendre values and derivatives at the Gauss points,
/// weights, and the inverse mass factors (2k + 1)/2 of the reference element.
#[derive(Clone, Debug)]
pub struct Basis {
    /// Polynomial order P.
    pub order: usize,
    /// Quadrature points Q.
    pub points: usize,
    /// Gauss points ξ_q.
    pub xi: Vec<Real>,
    /// Gauss weights w_q (sum 2).
    pub weight: Vec<Real>,
    /// φ_k(ξ_q), row-major `[q * (P+1) + k]`.
    pub phi: Vec<Real>,
    /// dφ_k/dξ(ξ_q), row-major `[q * (P+1) + k]`.
    pub dphi: Vec<Real>,
    /// ∫₋₁^ξ_q φ_k dξ, row-major `[q * (P+1) + k]` (positions from q).
    pub integral: Vec<Real>,
    /// φ_k(−1) = (−1)^k.
    pub left: Vec<Real>,
    /// (2k + 1)/2: the inverse of the reference mass matrix.
    pub inverse_mass: Vec<Real>,
}

impl Basis {
    /// Tables for order `order` with `points` Gauss points (at least P + 1; the right-hand
    /// side uses P + 2 by default so that the nonlinear fluxes are integrated with little
    /// aliasing).
    pub fn new(order: usize, points: usize) -> Self {
        assert!((1..=MAX_ORDER).contains(&order) || order == 0);
        assert!(points > order);
        let n = order + 1;
        let (xi, weight) = gauss_legendre(points);
        let mut phi = vec![0.0; points * n];
        let mut dphi = vec![0.0; points * n];
        let mut integral = vec![0.0; points * n];
        let mut p = vec![0.0; n + 1];
        let mut dp = vec![0.0; n + 1];
        for q in 0..points {
            legendre(order + 1, xi[q], &mut p, &mut dp);
            phi[q * n..(q + 1) * n].copy_from_slice(&p[..n]);
            dphi[q * n..(q + 1) * n].copy_from_slice(&dp[..n]);
            // ∫₋₁^ξ P_0 = ξ + 1, ∫₋₁^ξ P_k = (P_{k+1} − P_{k−1})/(2k + 1).
            integral[q * n] = xi[q] + 1.0;
            for k in 1..n {
                integral[q * n + k] = (p[k + 1] - p[k - 1]) / (2 * k + 1) as Real;
            }
        }
        Self {
            order,
            points,
            xi,
            weight,
            phi,
            dphi,
            integral,
            left: (0..n)
                .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 })
                .collect(),
            inverse_mass: (0..n).map(|k| (2 * k + 1) as Real / 2.0).collect(),
        }
    }

    /// Number of modes P + 1.
    #[inline]
    pub fn modes(&self) -> usize {
        self.order + 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn gauss_rules_integrate_polynomials_exactly() {
        for n in 1..=12 {
            let (x, w) = gauss_legendre(n);
            for d in 0..2 * n {
                let exact = if d % 2 == 0 {
                    2.0 / (d as Real + 1.0)
                } else {
                    0.0
                };
                let s: Real = x.iter().zip(&w).map(|(x, w)| w * x.powi(d as i32)).sum();
                assert!((s - exact).abs() < 1e-13, "GL n {n} d {d}: {s} vs {exact}");
            }
        }
        for n in 2..=12 {
            let (x, w) = gauss_lobatto(n);
            for d in 0..=2 * n - 3 {
                let exact = if d % 2 == 0 {
                    2.0 / (d as Real + 1.0)
                } else {
                    0.0
                };
                let s: Real = x.iter().zip(&w).map(|(x, w)| w * x.powi(d as i32)).sum();
                assert!((s - exact).abs() < 1e-13, "GLL n {n} d {d}: {s} vs {exact}");
            }
        }
    }

    #[test]
    fn legendre_is_orthogonal_with_diagonal_mass() {
        for order in 1..=8 {
            let b = Basis::new(order, order + 2);
            let n = b.modes();
            for k in 0..n {
                for l in 0..n {
                    let m: Real = (0..b.points)
                        .map(|q| b.weight[q] * b.phi[q * n + k] * b.phi[q * n + l])
                        .sum();
                    let exact = if k == l { 1.0 / b.inverse_mass[k] } else { 0.0 };
                    assert!((m - exact).abs() < 1e-13);
                }
            }
        }
    }
}
