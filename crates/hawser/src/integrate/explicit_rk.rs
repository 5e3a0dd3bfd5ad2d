//! Explicit Runge–Kutta integration with stage storage sized once.

use crate::math::Real;
use crate::model::Scheme;
use crate::system::{Location, System, Workspace};

/// A Butcher tableau of an explicit scheme with `S` stages.
#[derive(Debug)]
pub struct Tableau {
    /// Name.
    pub name: &'static str,
    /// Stage count.
    pub stages: usize,
    /// Lower-triangular coefficients a_ij, row-major, `stages × stages`.
    pub a: &'static [Real],
    /// Weights b_i.
    pub b: &'static [Real],
    /// Nodes c_i.
    pub c: &'static [Real],
}

/// Classical 4th-order Runge–Kutta (position-vector paper §3).
pub const RK4: Tableau = Tableau {
    name: "RK4",
    stages: 4,
    a: &[
        0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
    ],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    c: &[0.0, 0.5, 0.5, 1.0],
};

/// Third-order strong-stability-preserving Runge–Kutta of Shu and Osher (DG paper eqs. 31–33)
/// in Butcher form.
pub const SSP_RK3: Tableau = Tableau {
    name: "SSP-RK3",
    stages: 3,
    a: &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.25, 0.25, 0.0],
    b: &[1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0],
    c: &[0.0, 1.0, 0.5],
};

impl Scheme {
    /// The tableau of this scheme, if it is a Runge–Kutta scheme.
    pub fn tableau(self) -> Option<&'static Tableau> {
        match self {
            Scheme::Rk4 => Some(&RK4),
            Scheme::SspRk3 => Some(&SSP_RK3),
            Scheme::ThreeLevel | Scheme::GeneralizedAlpha | Scheme::Auto => None,
        }
    }
}

/// An explicit RK integrator: the tableau and its stage storage.
#[derive(Clone, Debug)]
pub struct ExplicitRk {
    tableau: &'static Tableau,
    k: Vec<Vec<Real>>,
    stage: Vec<Real>,
}

impl ExplicitRk {
    /// Integrator of `tableau` for a state of length `n`.
    pub fn new(tableau: &'static Tableau, n: usize) -> Self {
        Self {
            tableau,
            k: vec![vec![0.0; n]; tableau.stages],
            stage: vec![0.0; n],
        }
    }

    /// Right-hand-side evaluations per step.
    pub fn stages(&self) -> usize {
        self.tableau.stages
    }

    /// Advances y from t to t + dt in place.
    pub fn step(
        &mut self,
        system: &System,
        ws: &mut Workspace,
        t: Real,
        dt: Real,
        y: &mut [Real],
    ) -> Result<(), Location> {
        let tab = self.tableau;
        let s = tab.stages;
        for i in 0..s {
            // Stage i: y + Σ_j (dt a_ij) k_j over the non-zero a_ij, the first of them fused
            // with the copy of y (the same sums in the same order); y itself without them.
            let mut terms = (0..i).filter(|&j| tab.a[i * s + j] != 0.0);
            let stage: &[Real] = match terms.next() {
                Some(j) => {
                    shifted(&mut self.stage, y, dt * tab.a[i * s + j], &self.k[j]);
                    for j in terms {
                        add_scaled(&mut self.stage, dt * tab.a[i * s + j], &self.k[j]);
                    }
                    &self.stage
                }
                None => y,
            };
            let (ki, _) = self.k.split_at_mut(i + 1);
            system.rhs(t + tab.c[i] * dt, stage, &mut ki[i], ws)?;
        }
        // y += Σ_i (b_i dt) k_i, summed in stage order per entry.
        if let [k0, k1, k2, k3] = &self.k[..] {
            let b = [0, 1, 2, 3].map(|i| tab.b[i] * dt);
            add_four_scaled(y, b, [k0, k1, k2, k3]);
        } else {
            for i in 0..s {
                add_scaled(y, tab.b[i] * dt, &self.k[i]);
            }
        }
        Ok(())
    }
}

// The stage sums, compiled for AVX2 and SSE2 (`crate::math::wide_simd_fn`): each entry's
// products and sums in the same order whatever the instruction set, so the same bits.

crate::math::wide_simd_fn! {
    /// stage = y + a k.
    fn shifted(stage: &mut [Real], y: &[Real], a: Real, k: &[Real]) {
        for ((st, yv), k) in stage.iter_mut().zip(y).zip(k) {
            *st = yv + a * k;
        }
    }
}

crate::math::wide_simd_fn! {
    /// y += a k.
    fn add_scaled(y: &mut [Real], a: Real, k: &[Real]) {
        for (yv, k) in y.iter_mut().zip(k) {
            *yv += a * k;
        }
    }
}

crate::math::wide_simd_fn! {
    /// y += b₀ k₀ + b₁ k₁ + b₂ k₂ + b₃ k₃, summed in stage order per entry.
    fn add_four_scaled(y: &mut [Real], b: [Real; 4], k: [&[Real]; 4]) {
        let [k0, k1, k2, k3] = k;
        let stages = k0.iter().zip(k1).zip(k2).zip(k3);
        for (yv, (((k0, k1), k2), k3)) in y.iter_mut().zip(stages) {
            *yv = (((*yv + b[0] * k0) + b[1] * k1) + b[2] * k2) + b[3] * k3;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn tableaux_are_consistent() {
        for t in [&RK4, &SSP_RK3] {
            let sb: Real = t.b.iter().sum();
            assert!((sb - 1.0).abs() < 1e-15);
            for i in 0..t.stages {
                let row: Real = t.a[i * t.stages..(i + 1) * t.stages].iter().sum();
                assert!((row - t.c[i]).abs() < 1e-15, "{} row {i}", t.name);
            }
        }
    }
}
