//! Linear-algebra aliases. No other module names the linear-algebra crate directly.

/// Floating-point type of every physical quantity.
pub type Real = f64;
/// A 3-vector (position [m], velocity [m/s], force [N], ...).
pub type Vec3 = nalgebra::Vector3<Real>;
/// A 3×3 matrix (mass blocks [kg], stiffness blocks [N/m], ...).
pub type Mat3 = nalgebra::Matrix3<Real>;

/// Unit vector along global z (up).
#[inline]
pub fn z_hat() -> Vec3 {
    Vec3::new(0.0, 0.0, 1.0)
}

/// Reads the 3-vector stored at `data[3*i .. 3*i+3]`.
#[inline(always)]
pub fn get3(data: &[Real], i: usize) -> Vec3 {
    Vec3::new(data[3 * i], data[3 * i + 1], data[3 * i + 2])
}

/// Writes a 3-vector into `data[3*i .. 3*i+3]`.
#[inline(always)]
pub fn set3(data: &mut [Real], i: usize, v: &Vec3) {
    data[3 * i] = v.x;
    data[3 * i + 1] = v.y;
    data[3 * i + 2] = v.z;
}

/// Adds a 3-vector into `data[3*i .. 3*i+3]`.
#[inline(always)]
pub fn add3(data: &mut [Real], i: usize, v: &Vec3) {
    data[3 * i] += v.x;
    data[3 * i + 1] += v.y;
    data[3 * i + 2] += v.z;
}

/// Inverse of a 3×3 matrix by cofactors; `None` when it is singular to working precision.
#[inline]
pub fn inverse3(m: &Mat3) -> Option<Mat3> {
    let c00 = m[(1, 1)] * m[(2, 2)] - m[(1, 2)] * m[(2, 1)];
    let c01 = m[(1, 2)] * m[(2, 0)] - m[(1, 0)] * m[(2, 2)];
    let c02 = m[(1, 0)] * m[(2, 1)] - m[(1, 1)] * m[(2, 0)];
    let det = m[(0, 0)] * c00 + m[(0, 1)] * c01 + m[(0, 2)] * c02;
    let scale = m.abs().max();
    if !(det.abs() > 1e-300) || det.abs() <= 1e-14 * scale * scale * scale {
        return None;
    }
    let inv_det = 1.0 / det;
    Some(
        Mat3::new(
            c00,
            m[(0, 2)] * m[(2, 1)] - m[(0, 1)] * m[(2, 2)],
            m[(0, 1)] * m[(1, 2)] - m[(0, 2)] * m[(1, 1)],
            c01,
            m[(0, 0)] * m[(2, 2)] - m[(0, 2)] * m[(2, 0)],
            m[(0, 2)] * m[(1, 0)] - m[(0, 0)] * m[(1, 2)],
            c02,
            m[(0, 1)] * m[(2, 0)] - m[(0, 0)] * m[(2, 1)],
            m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)],
        ) * inv_det,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn inverse3_matches_nalgebra() {
        let m = Mat3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
        let inv = inverse3(&m).unwrap();
        let err = (inv * m - Mat3::identity()).abs().max();
        assert!(err < 1e-14, "{err}");
        assert!(inverse3(&Mat3::zeros()).is_none());
    }
}
