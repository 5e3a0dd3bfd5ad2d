//! Hydrodynamic loads on a cable per unit unstretched length (SPEC §1; DG paper eqs. 13, 17;
//! position-vector paper eq. 16).

use crate::math::{Mat3, Real, Vec3};

/// A drag loading function C(φ) of the angle of attack φ [rad] between the cable tangent and
/// the relative flow, as a Fourier series C(φ) = Σ_k a_k cos(kφ) + b_k sin(kφ), k = 0, 1, ...
/// (position-vector paper eqs. 16, 28, 29).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct LoadingFunction {
    /// Cosine coefficients a_0, a_1, ... [-].
    pub cos: Vec<Real>,
    /// Sine coefficients b_0, b_1, ... [-] (b_0 has no effect).
    pub sin: Vec<Real>,
}

impl LoadingFunction {
    /// C(φ) [-].
    #[inline]
    pub fn eval(&self, phi: Real) -> Real {
        let mut c = 0.0;
        for (k, a) in self.cos.iter().enumerate() {
            c += a * (k as Real * phi).cos();
        }
        for (k, b) in self.sin.iter().enumerate() {
            c += b * (k as Real * phi).sin();
        }
        c
    }
}

/// How the drag on a line type is computed.
#[derive(Clone, Debug, PartialEq)]
pub enum DragModel {
    /// Morison drag (DG paper eq. 17):
    /// f_d = ½ ρ d √(1+ε) (C_dn |v*_n| v*_n + C_dt |v*_t| v*_t).
    Morison {
        /// Normal drag coefficient C_dn [-] on the projected area d per unit length.
        normal: Real,
        /// Tangential drag coefficient C_dt [-] on the projected area d per unit length
        /// (MoorDyn's CdAx acts on π·d: C_dt = π·CdAx).
        tangential: Real,
    },
    /// Drag loading functions (position-vector paper eq. 16):
    /// f_n = ½ ρ d √(1+ε) |v*|² C_n(φ) along v*_n, f_t = ½ ρ d √(1+ε) |v*|² C_t(φ) along v*_t,
    /// with φ ∈ [0, π/2] the acute angle between the tangent and the relative flow.
    LoadingFunctions {
        /// Normal loading function C_n(φ).
        normal: LoadingFunction,
        /// Tangential loading function C_t(φ).
        tangential: LoadingFunction,
    },
}

/// Drag force per unit unstretched length [N/m] on a cable with unit tangent `t`.
///
/// `relative_velocity` is v* = fluid velocity − cable velocity [m/s]; `root_stretch` is
/// √(1 + ε) (the volume-preserving factor of DG paper eq. 17).
#[inline]
pub fn drag_force(
    model: &DragModel,
    density: Real,
    diameter: Real,
    root_stretch: Real,
    tangent: &Vec3,
    relative_velocity: &Vec3,
) -> Vec3 {
    drag_force_with_factor(
        model,
        0.5 * density * diameter,
        root_stretch,
        tangent,
        relative_velocity,
    )
}

/// [`drag_force`] with its dynamic-pressure factor ½ ρ d [kg/m²] given (computed once per
/// line type by a caller that evaluates many points).
#[inline(always)]
pub fn drag_force_with_factor(
    model: &DragModel,
    factor: Real,
    root_stretch: Real,
    tangent: &Vec3,
    relative_velocity: &Vec3,
) -> Vec3 {
    let vt_scalar = relative_velocity.dot(tangent);
    let vt = tangent * vt_scalar;
    let vn = relative_velocity - vt;
    let q = factor * root_stretch;
    match model {
        DragModel::Morison { normal, tangential } => {
            q * (normal * vn.norm() * vn + tangential * vt_scalar.abs() * vt)
        }
        DragModel::LoadingFunctions { normal, tangential } => {
            let vn_norm = vn.norm();
            let speed2 = vn_norm * vn_norm + vt_scalar * vt_scalar;
            if speed2 == 0.0 {
                return Vec3::zeros();
            }
            let phi = vn_norm.atan2(vt_scalar.abs());
            let mut f = Vec3::zeros();
            if vn_norm > 0.0 {
                f += vn * (q * speed2 * normal.eval(phi) / vn_norm);
            }
            if vt_scalar != 0.0 {
                f += tangent * (q * speed2 * tangential.eval(phi) * vt_scalar.signum());
            }
            f
        }
    }
}

/// Added-mass matrix per unit unstretched length [kg/m] (DG paper eq. 13):
/// m_a = ρ A (C_an (I − t tᵀ) + C_at t tᵀ), with A = π d²/4, evaluated as
/// ρ A C_an I + ρ A (C_at − C_an) t tᵀ (symmetric: six products).
#[inline]
pub fn added_mass_matrix(
    density: Real,
    area: Real,
    normal: Real,
    tangential: Real,
    tangent: &Vec3,
) -> Mat3 {
    let (alpha, beta) = added_mass_coefficients(density, area, normal, tangential);
    added_mass_of(alpha, beta, tangent)
}

/// The two coefficients of [`added_mass_matrix`] [kg/m]: α = ρ A C_an of its isotropic part
/// and β = ρ A (C_at − C_an) of its part along the tangent, m_a = α I + β t tᵀ.
#[inline(always)]
pub fn added_mass_coefficients(
    density: Real,
    area: Real,
    normal: Real,
    tangential: Real,
) -> (Real, Real) {
    (
        density * area * normal,
        density * area * (tangential - normal),
    )
}

/// α I + β t tᵀ [kg/m] for the unit tangent t: [`added_mass_matrix`] with its two
/// coefficients α = ρ A C_an and β = ρ A (C_at − C_an) given.
#[inline(always)]
pub fn added_mass_of(alpha: Real, beta: Real, tangent: &Vec3) -> Mat3 {
    let (t, bx, by) = (tangent, beta * tangent.x, beta * tangent.y);
    let (xy, xz, yz) = (bx * t.y, bx * t.z, by * t.z);
    Mat3::new(
        alpha + bx * t.x,
        xy,
        xz,
        xy,
        alpha + by * t.y,
        yz,
        xz,
        yz,
        alpha + beta * t.z * t.z,
    )
}

/// Froude–Krylov plus added-mass force from the fluid acceleration a_w per unit unstretched
/// length [N/m] (DG paper eq. 13, the a_w terms): ρ A ((1 + C_an) a_w,n + C_at a_w,t).
#[inline]
pub fn fluid_inertia_force(
    density: Real,
    area: Real,
    normal: Real,
    tangential: Real,
    tangent: &Vec3,
    fluid_acceleration: &Vec3,
) -> Vec3 {
    let at = tangent * fluid_acceleration.dot(tangent);
    let an = fluid_acceleration - at;
    density * area * ((1.0 + normal) * an + tangential * at)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn added_mass_splits_normal_and_tangential() {
        let t = Vec3::new(0.6, 0.0, 0.8);
        let m = added_mass_matrix(1025.0, 0.01, 1.0, 0.2, &t);
        let n = Vec3::new(0.8, 0.0, -0.6);
        assert!((m * t - t * (1025.0 * 0.01 * 0.2)).norm() < 1e-12);
        assert!((m * n - n * (1025.0 * 0.01 * 1.0)).norm() < 1e-12);
        assert!((m * Vec3::y() - Vec3::y() * (1025.0 * 0.01)).norm() < 1e-12);
    }

    #[test]
    fn morison_splits_normal_and_tangential() {
        let m = DragModel::Morison {
            normal: 1.2,
            tangential: 0.01,
        };
        let t = Vec3::new(1.0, 0.0, 0.0);
        let f = drag_force(&m, 1000.0, 0.1, 1.0, &t, &Vec3::new(2.0, 1.0, 0.0));
        assert!((f.x - 0.5 * 1000.0 * 0.1 * 0.01 * 4.0).abs() < 1e-12);
        assert!((f.y - 0.5 * 1000.0 * 0.1 * 1.2 * 1.0).abs() < 1e-12);
    }
    #[test]
    fn loading_function_sin_squared_equals_morison_normal() {
        // C_n(φ) = C_d sin²φ = C_d (1 − cos 2φ)/2 reproduces Morison normal drag.
        let cd = 1.2;
        let lf = DragModel::LoadingFunctions {
            normal: LoadingFunction {
                cos: vec![cd / 2.0, 0.0, -cd / 2.0],
                sin: vec![],
            },
            tangential: LoadingFunction::default(),
        };
        let mor = DragModel::Morison {
            normal: cd,
            tangential: 0.0,
        };
        let t = Vec3::new(0.6, 0.0, 0.8);
        let v = Vec3::new(0.3, -1.1, 0.7);
        let a = drag_force(&lf, 1025.0, 0.04, 1.001f64.sqrt(), &t, &v);
        let b = drag_force(&mor, 1025.0, 0.04, 1.001f64.sqrt(), &t, &v);
        assert!((a - b).norm() < 1e-12 * b.norm(), "{a} vs {b}");
    }
}
