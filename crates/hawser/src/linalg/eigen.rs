//! Symmetric generalized eigenproblems K φ = λ M φ (K symmetric, M symmetric positive
//! (semi-)definite): a dense solver for small systems and cross-checks, and shift-invert
//! subspace iteration for the lowest modes of large sparse systems.

use crate::math::Real;
use nalgebra::{DMatrix, SymmetricEigen};

/// Eigenvalues in increasing order of |λ − σ| and their M-orthonormal vectors (columns).
#[derive(Clone, Debug)]
pub struct EigenPairs {
    /// Eigenvalues λ.
    pub values: Vec<Real>,
    /// Eigenvectors, one column each, with φᵀ M φ = 1.
    pub vectors: DMatrix<Real>,
    /// Subspace iterations used (0 for the dense solver).
    pub iterations: usize,
}

/// Why an eigen solve failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EigenFailure {
    /// The mass matrix (or a projection of it) is not positive definite.
    #[error("the mass matrix is not positive definite")]
    MassNotDefinite,
    /// The shifted operator K − σM is singular at the shift.
    #[error("the shifted stiffness K − σM is singular")]
    SingularShift,
    /// Subspace iteration did not reach the tolerance.
    #[error(
        "subspace iteration did not converge: residual {residual:.2e} after {iterations} \
         iterations"
    )]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Largest relative residual of the wanted pairs.
        residual: Real,
    },
}

/// All eigenpairs of K φ = λ M φ, dense: M = L Lᵀ (Cholesky), then the standard symmetric
/// problem L⁻¹ K L⁻ᵀ y = λ y, φ = L⁻ᵀ y. O(n³); needs M positive definite. Sorted by λ.
pub fn dense_generalized(k: &DMatrix<Real>, m: &DMatrix<Real>) -> Result<EigenPairs, EigenFailure> {
    let l = m
        .clone()
        .cholesky()
        .ok_or(EigenFailure::MassNotDefinite)?
        .l();
    let b = l
        .solve_lower_triangular(k)
        .ok_or(EigenFailure::MassNotDefinite)?;
    let a = l
        .solve_lower_triangular(&b.transpose())
        .ok_or(EigenFailure::MassNotDefinite)?;
    let a = (&a + a.transpose()) * 0.5;
    let eig = SymmetricEigen::new(a);
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
    let y = DMatrix::from_fn(k.nrows(), order.len(), |r, c| {
        eig.eigenvectors[(r, order[c])]
    });
    let vectors = l
        .tr_solve_lower_triangular(&y)
        .ok_or(EigenFailure::MassNotDefinite)?;
    Ok(EigenPairs {
        values: order.iter().map(|&i| eig.eigenvalues[i]).collect(),
        vectors,
        iterations: 0,
    })
}

/// Settings of [`subspace_iteration`].
#[derive(Clone, Copy, Debug)]
pub struct SubspaceOptions {
    /// Backward error ‖Kφ − λMφ‖ / ((‖K‖ + |λ| ‖M‖) ‖φ‖) every wanted pair must reach [-].
    pub tolerance: Real,
    /// Iteration limit.
    pub max_iterations: usize,
}

impl Default for SubspaceOptions {
    /// 1e-11: a backward error a thousand times machine precision, reachable whatever the
    /// ratio of axial to transverse stiffness (a residual relative to ‖Kφ‖ alone is not: its
    /// round-off floor is ε ‖K‖/λ‖M‖, 10⁻⁸ for a stiff chain); the eigenvalue error of a
    /// Rayleigh quotient is of the order of the squared residual over the gap, so frequencies
    /// are exact to round-off. 300 iterations is far beyond what a subspace twice the wanted
    /// size needs (convergence factor λ_i/λ_{q+1} per iteration).
    fn default() -> Self {
        Self {
            tolerance: 1e-11,
            max_iterations: 300,
        }
    }
}

/// The `count` eigenpairs of K φ = λ M φ nearest to the shift σ, by subspace iteration on the
/// shift-inverted operator (K − σM)⁻¹ M (Bathe's method with a subspace of
/// q = max(2·count, count + 8) vectors and a Rayleigh–Ritz step per iteration).
///
/// Each iteration solves (K − σM) X̄ = M X for the q columns (`solve`, O(nodes) each with
/// the block solver), projects K_r = X̄ᵀ (K − σM) X̄ = X̄ᵀ M X and M_r = X̄ᵀ M X̄, solves the
/// small dense problem and rotates X = X̄ Q. Eigenvalue i converges with the factor
/// |λ_i − σ| / |λ_{q+1} − σ| per iteration. A subspace (rather than a single Lanczos vector)
/// finds repeated eigenvalues — the two transverse directions of a straight cable, identical
/// lines of a symmetric mooring — with their full multiplicity. Starting vectors are
/// deterministic pseudo-random, so results are reproducible.
///
/// `apply_k` and `apply_m` compute y = K x and y = M x; `solve` computes x = (K − σM)⁻¹ b or
/// fails (singular shift); `norms` are ‖K‖ and ‖M‖ (any consistent norm, e.g. the largest
/// absolute row sum) for the backward error.
#[allow(clippy::too_many_arguments)]
pub fn subspace_iteration<S, A, B>(
    n: usize,
    count: usize,
    sigma: Real,
    norms: (Real, Real),
    mut solve: S,
    apply_k: A,
    apply_m: B,
    options: SubspaceOptions,
) -> Result<EigenPairs, EigenFailure>
where
    S: FnMut(&[Real], &mut [Real]) -> bool,
    A: Fn(&[Real], &mut [Real]),
    B: Fn(&[Real], &mut [Real]),
{
    let count = count.min(n);
    let q = (2 * count).max(count + 8).min(n);
    let mut x = DMatrix::<Real>::zeros(n, q);
    let mut seed: u64 = 0x5DEE_CE66_D1CE_4E5B;
    for v in x.iter_mut() {
        seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        *v = (z >> 11) as Real / (1u64 << 53) as Real - 0.5;
    }
    let mut mx = DMatrix::<Real>::zeros(n, q);
    let mut xbar = DMatrix::<Real>::zeros(n, q);
    let mut mxbar = DMatrix::<Real>::zeros(n, q);
    let mut kx = vec![0.0; n];
    let mut mxi = vec![0.0; n];
    let mut worst = Real::INFINITY;
    for iteration in 1..=options.max_iterations {
        for c in 0..q {
            apply_m(x.column(c).as_slice(), mx.column_mut(c).as_mut_slice());
            if !solve(mx.column(c).as_slice(), xbar.column_mut(c).as_mut_slice()) {
                return Err(EigenFailure::SingularShift);
            }
            apply_m(
                xbar.column(c).as_slice(),
                mxbar.column_mut(c).as_mut_slice(),
            );
        }
        // Rayleigh–Ritz on span(X̄): (K − σM) X̄ = M X.
        let kr = xbar.transpose() * &mx;
        let mr = xbar.transpose() * &mxbar;
        let kr = (&kr + kr.transpose()) * 0.5;
        let mr = (&mr + mr.transpose()) * 0.5;
        let small = dense_generalized(&kr, &mr)?;
        // Order by distance from the shift, |λ − σ| = |μ|.
        let mut order: Vec<usize> = (0..q).collect();
        order.sort_by(|&i, &j| small.values[i].abs().total_cmp(&small.values[j].abs()));
        let qm = DMatrix::from_fn(q, q, |r, c| small.vectors[(r, order[c])]);
        x = &xbar * qm;
        let values: Vec<Real> = order.iter().map(|&i| small.values[i] + sigma).collect();
        // Backward errors of the wanted pairs.
        worst = 0.0;
        for (i, &lambda) in values.iter().enumerate().take(count) {
            let xi = x.column(i);
            apply_k(xi.as_slice(), &mut kx);
            apply_m(xi.as_slice(), &mut mxi);
            let r = kx
                .iter()
                .zip(&mxi)
                .map(|(k, m)| (k - lambda * m).powi(2))
                .sum::<Real>()
                .sqrt();
            let scale = (norms.0 + lambda.abs() * norms.1) * xi.norm();
            worst = worst.max(if scale > 0.0 { r / scale } else { 0.0 });
        }
        if worst <= options.tolerance {
            return Ok(EigenPairs {
                values: values[..count].to_vec(),
                vectors: x.columns(0, count).into_owned(),
                iterations: iteration,
            });
        }
    }
    Err(EigenFailure::NotConverged {
        iterations: options.max_iterations,
        residual: worst,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fixed–fixed spring–mass chain with known eigenvalues: both solvers agree with
    /// λ_j = (k/m) 4 sin²(jπ/(2(n+1))), and the subspace solver finds a doubled spectrum
    /// (two uncoupled copies) with its full multiplicity.
    #[test]
    fn solvers_agree_with_the_spring_chain_and_find_repeated_eigenvalues() {
        let n = 40;
        let (k, m) = (3.0, 2.0);
        let mut kk = DMatrix::<Real>::zeros(2 * n, 2 * n);
        let mut mm = DMatrix::<Real>::zeros(2 * n, 2 * n);
        for copy in 0..2 {
            let o = copy * n;
            for i in 0..n {
                kk[(o + i, o + i)] = 2.0 * k;
                mm[(o + i, o + i)] = m;
                if i + 1 < n {
                    kk[(o + i, o + i + 1)] = -k;
                    kk[(o + i + 1, o + i)] = -k;
                }
            }
        }
        let exact = |j: usize| {
            let s = (j as Real * std::f64::consts::PI / (2.0 * (n + 1) as Real)).sin();
            4.0 * k / m * s * s
        };
        let dense = dense_generalized(&kk, &mm).unwrap();
        for j in 0..10 {
            assert!((dense.values[j] - exact(j / 2 + 1)).abs() < 1e-12);
        }
        let sigma = -0.01;
        let shifted = &kk - &mm * sigma;
        let lu = shifted.clone().lu();
        let sub = subspace_iteration(
            2 * n,
            6,
            sigma,
            (4.0 * k, m),
            |b, x| {
                let v = lu.solve(&nalgebra::DVector::from_column_slice(b)).unwrap();
                x.copy_from_slice(v.as_slice());
                true
            },
            |x, y| y.copy_from_slice((&kk * nalgebra::DVector::from_column_slice(x)).as_slice()),
            |x, y| y.copy_from_slice((&mm * nalgebra::DVector::from_column_slice(x)).as_slice()),
            SubspaceOptions::default(),
        )
        .unwrap();
        for j in 0..6 {
            let e = exact(j / 2 + 1);
            assert!(
                (sub.values[j] - e).abs() < 1e-12 * e.max(1.0),
                "{j}: {} vs {e}",
                sub.values[j]
            );
            let phi = sub.vectors.column(j);
            let norm = (phi.transpose() * &mm * phi)[(0, 0)];
            assert!((norm - 1.0).abs() < 1e-10);
        }
    }
}
