//! Linear-algebra aliases and small helpers, and the instruction-set dispatch of the hot loops
//! ([`wide_simd_fn`]). No other module names the linear-algebra crate directly.

/// Floating-point type of every physical quantity.
pub type Real = f64;
/// A 3-vector (position [m], velocity [m/s], force [N], ...).
pub type Vec3 = nalgebra::Vector3<Real>;
/// A 3×3 matrix (mass blocks [kg], stiffness blocks [N/m], ...).
pub type Mat3 = nalgebra::Matrix3<Real>;
/// A 6-vector of a rigid body: [force; moment], [velocity; angular velocity], ...
pub type Vec6 = nalgebra::Vector6<Real>;
/// A 6×6 matrix of a rigid body (mass about a reference point, added mass, ...).
pub type Mat6 = nalgebra::Matrix6<Real>;
/// A 3×6 matrix (the map from a rigid body's 6 accelerations to a body point's 3).
pub type Mat3x6 = nalgebra::Matrix3x6<Real>;
/// C columns of 3 rows: the right-hand sides of the block solves (C = 1, a 3-vector; C = 3,
/// a 3×3 block of three columns).
pub type Mat3xC<const C: usize> = nalgebra::SMatrix<Real, 3, C>;
/// A rotation as a unit quaternion (body axes to global axes).
pub type Quat = nalgebra::UnitQuaternion<Real>;

/// The unit quaternion with coordinates `[i, j, k, w]` as [`Quat::coords`] gives them, taken
/// as they are (a saved orientation, restored bit for bit).
pub fn quat_from_coords(c: [Real; 4]) -> Quat {
    Quat::new_unchecked(nalgebra::Quaternion::new(c[3], c[0], c[1], c[2]))
}

/// The cross-product matrix [a]× with [a]× b = a × b.
#[inline]
pub fn skew(a: &Vec3) -> Mat3 {
    Mat3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

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

/// The 3-vectors `v` as their 3 `v.len()` coordinates in order, `v[i]` at `3*i .. 3*i+3`:
/// the layout of a state block's nodes, so a block copies to or from nodes in one move.
#[inline(always)]
pub fn coordinates(v: &[Vec3]) -> &[Real] {
    bytemuck::cast_slice(v)
}

/// [`coordinates`], writable.
#[inline(always)]
pub fn coordinates_mut(v: &mut [Vec3]) -> &mut [Real] {
    bytemuck::cast_slice_mut(v)
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

/// Solves m x = b for a 3×3 matrix by Cramer's rule; `None` when m is singular relative to its
/// diagonal (the fast path of block-diagonal mass solves).
#[inline]
pub fn solve3(m: &Mat3, b: &Vec3) -> Option<Vec3> {
    let c0 = m.column(0);
    let c1 = m.column(1);
    let c2 = m.column(2);
    let c12 = c1.cross(&c2);
    let det = c0.dot(&c12);
    let d = (m[(0, 0)].abs() + m[(1, 1)].abs() + m[(2, 2)].abs()) / 3.0;
    if !(det.abs() > 1e-14 * d * d * d) {
        return None;
    }
    let inv = 1.0 / det;
    Some(Vec3::new(
        b.dot(&c12) * inv,
        c0.dot(&b.cross(&c2)) * inv,
        c0.dot(&c1.cross(b)) * inv,
    ))
}

/// The instruction set the loops written lane by lane ([`wide_simd_fn`]) run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SimdLevel {
    /// The target's baseline: SSE2 on x86-64 (two lanes a register).
    Baseline,
    /// AVX2 (four lanes a register).
    Avx2,
    /// AVX-512 F, VL and DQ (eight lanes a register).
    Avx512,
}

/// The widest instruction set of the processor, capped by the environment variable
/// `HAWSER_SIMD` (`baseline` or `avx2`; read once per process), so that a result can be
/// checked not to depend on it. Always [`SimdLevel::Baseline`] off x86-64.
pub fn simd_level() -> SimdLevel {
    #[cfg(target_arch = "x86_64")]
    {
        static LEVEL: std::sync::LazyLock<SimdLevel> = std::sync::LazyLock::new(|| {
            let cap = match std::env::var("HAWSER_SIMD").as_deref() {
                Ok("baseline") => SimdLevel::Baseline,
                Ok("avx2") => SimdLevel::Avx2,
                _ => SimdLevel::Avx512,
            };
            let found = if std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512vl")
                && std::arch::is_x86_feature_detected!("avx512dq")
            {
                SimdLevel::Avx512
            } else if std::arch::is_x86_feature_detected!("avx2") {
                SimdLevel::Avx2
            } else {
                SimdLevel::Baseline
            };
            found.min(cap)
        });
        *LEVEL
    }
    #[cfg(not(target_arch = "x86_64"))]
    SimdLevel::Baseline
}

/// The widest instruction set the lane-by-lane loops run on ([`simd_level`]): "avx512"
/// (the `fe` element loop in batches of eight on lines of 16 elements or more, loops of four
/// lanes on AVX2), "avx2", "sse2" (x86-64 without AVX2 or with `HAWSER_SIMD=baseline`) or
/// "baseline" (other targets). `hawser bench` reports it.
pub fn instruction_set() -> &'static str {
    match simd_level() {
        SimdLevel::Avx512 => "avx512",
        SimdLevel::Avx2 => "avx2",
        SimdLevel::Baseline if cfg!(target_arch = "x86_64") => "sse2",
        SimdLevel::Baseline => "baseline",
    }
}

/// Defines a function whose body is compiled for AVX2 and for the target's baseline (SSE2 on
/// x86-64), and with `avx512;` before it for AVX-512 too, and runs the widest of them the
/// processor has ([`simd_level`]). For the hot loops written lane by lane (the `fe` element
/// batches, the lumped mass solve), whose lanes the compiler packs two, four or eight to a
/// register: loops of four lanes are left to AVX2 (compiled for AVX-512 they run slower),
/// loops of eight take AVX-512. The wider sets bring wider registers, not other arithmetic
/// (no fused multiply-add is formed: Rust never contracts a product and a sum), so every
/// version gives the same bits (a test runs them all); one binary runs on any x86-64
/// processor at the speed of the one it runs on.
///
/// The body must not name generic parameters (it is compiled into inner functions).
macro_rules! wide_simd_fn {
    (avx512; $(#[$m:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? $body:block) => {
        $(#[$m])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx512f,avx512vl,avx512dq")]
            #[allow(clippy::too_many_arguments)]
            fn avx512($($arg: $ty),*) $(-> $ret)? $body
            #[cfg(target_arch = "x86_64")]
            if $crate::math::simd_level() == $crate::math::SimdLevel::Avx512 {
                // SAFETY: the processor has the features `avx512` is compiled for
                // (`simd_level` detects them).
                return unsafe { avx512($($arg),*) };
            }
            $crate::math::wide_simd_fn! {
                #[inline(always)]
                #[allow(clippy::too_many_arguments)]
                fn narrower($($arg: $ty),*) $(-> $ret)? $body
            }
            narrower($($arg),*)
        }
    };
    ($(#[$m:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? $body:block) => {
        $(#[$m])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            #[allow(clippy::too_many_arguments)]
            fn avx2($($arg: $ty),*) $(-> $ret)? $body
            #[inline(always)]
            #[allow(clippy::too_many_arguments)]
            fn baseline($($arg: $ty),*) $(-> $ret)? $body
            #[cfg(target_arch = "x86_64")]
            if $crate::math::simd_level() >= $crate::math::SimdLevel::Avx2 {
                // SAFETY: the processor has AVX2 (`simd_level` detects it), the one feature
                // `avx2` is compiled for.
                return unsafe { avx2($($arg),*) };
            }
            baseline($($arg),*)
        }
    };
}
pub(crate) use wide_simd_fn;

#[cfg(test)]
mod tests {
    #[test]
    fn solve3_matches_inverse() {
        let m = Mat3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
        let b = Vec3::new(1.0, -2.0, 0.5);
        let x = solve3(&m, &b).unwrap();
        assert!((m * x - b).norm() < 1e-14);
    }
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
