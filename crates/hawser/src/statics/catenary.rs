//! The elastic catenary in closed form, with and without a frictionless seabed under the
//! lower end: the reference of the catenary tests and the seed of Newton statics.
//!
//! A line of unstretched length L, wet weight w [N/m] per unstretched length (w > 0 sinks)
//! and axial stiffness EA [N] hangs from its lower end A to its upper end B, B lying a
//! horizontal distance X and a height Z above A. With H the horizontal tension and V_B the
//! vertical tension at B (V_A = V_B − wL at A), the fully suspended line satisfies
//!
//!   X = (H/w)[asinh(V_B/H) − asinh(V_A/H)] + H L/EA,
//!   Z = (H/w)[√(1 + (V_B/H)²) − √(1 + (V_A/H)²)] + (V_B² − V_A²)/(2 EA w),
//!
//! and, when A rests on a frictionless seabed and V_A would be negative, a length
//! L_B = L − V_B/w lies on the bed and
//!
//!   X = L_B + (H/w) asinh(V_B/H) + H L/EA,   Z = (H/w)[√(1 + (V_B/H)²) − 1] + V_B²/(2 EA w).

use crate::math::Real;

/// Solution of the elastic catenary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Catenary {
    /// Horizontal tension H [N].
    pub horizontal: Real,
    /// Vertical tension at the upper end B [N].
    pub vertical_b: Real,
    /// Vertical tension at the lower end A [N] (0 when part of the line rests on the bed).
    pub vertical_a: Real,
    /// Unstretched length resting on the seabed [m].
    pub grounded_length: Real,
    /// Line length L [m], wet weight w [N/m] and EA [N] it was solved for.
    pub length: Real,
    /// Wet weight per length w [N/m].
    pub weight: Real,
    /// Axial stiffness EA [N].
    pub ea: Real,
}

impl Catenary {
    /// Tension at the upper end B [N].
    pub fn tension_b(&self) -> Real {
        self.horizontal.hypot(self.vertical_b)
    }
    /// Tension at the lower end A [N].
    pub fn tension_a(&self) -> Real {
        self.horizontal.hypot(self.vertical_a)
    }

    /// Horizontal and vertical offsets (x, z) [m] from A of the point at unstretched arc
    /// length s from A.
    pub fn position(&self, s: Real) -> (Real, Real) {
        let (h, w, ea) = (self.horizontal, self.weight, self.ea);
        let lb = self.grounded_length;
        if lb > 0.0 {
            if s <= lb {
                return (s + h * s / ea, 0.0);
            }
            let sp = s - lb;
            let v = w * sp;
            let x = lb + h * lb / ea + (h / w) * (v / h).asinh() + h * sp / ea;
            let z = (h / w) * ((1.0 + (v / h).powi(2)).sqrt() - 1.0) + w * sp * sp / (2.0 * ea);
            (x, z)
        } else {
            let va = self.vertical_a;
            let v = va + w * s;
            let x = (h / w) * ((v / h).asinh() - (va / h).asinh()) + h * s / ea;
            let z = (h / w) * ((1.0 + (v / h).powi(2)).sqrt() - (1.0 + (va / h).powi(2)).sqrt())
                + (va * s + 0.5 * w * s * s) / ea;
            (x, z)
        }
    }

    /// Tension [N] at unstretched arc length s from A.
    pub fn tension(&self, s: Real) -> Real {
        if self.grounded_length > 0.0 && s <= self.grounded_length {
            return self.horizontal;
        }
        let v = if self.grounded_length > 0.0 {
            self.weight * (s - self.grounded_length)
        } else {
            self.vertical_a + self.weight * s
        };
        self.horizontal.hypot(v)
    }
}

fn residual(
    x: Real,
    z: Real,
    l: Real,
    w: Real,
    ea: Real,
    seabed: bool,
    h: Real,
    vb: Real,
) -> (Real, Real, bool) {
    let va = vb - w * l;
    if seabed && va < 0.0 {
        let lb = l - vb / w;
        let rx = lb + (h / w) * (vb / h).asinh() + h * l / ea - x;
        let rz = (h / w) * ((1.0 + (vb / h).powi(2)).sqrt() - 1.0) + vb * vb / (2.0 * ea * w) - z;
        (rx, rz, true)
    } else {
        let rx = (h / w) * ((vb / h).asinh() - (va / h).asinh()) + h * l / ea - x;
        let rz = (h / w) * ((1.0 + (vb / h).powi(2)).sqrt() - (1.0 + (va / h).powi(2)).sqrt())
            + (vb * vb - va * va) / (2.0 * ea * w)
            - z;
        (rx, rz, false)
    }
}

/// Solves the elastic catenary for a horizontal span `x` > 0 [m], height `z` [m] of B above A,
/// unstretched length `length` [m], wet weight `weight` > 0 [N/m] and stiffness `ea` [N];
/// `seabed` lets the lower end rest on a frictionless bed. `None` when Newton does not converge.
pub fn solve(
    x: Real,
    z: Real,
    length: Real,
    weight: Real,
    ea: Real,
    seabed: bool,
) -> Option<Catenary> {
    if !(x > 0.0 && length > 0.0 && weight > 0.0 && ea > 0.0) {
        return None;
    }
    // Initial guess (Peyrot & Goulois, as used by MoorDyn and FAST).
    let chord = (x * x + z * z).sqrt();
    let lambda = if length <= chord {
        0.2
    } else {
        (3.0 * ((length * length - z * z) / (x * x) - 1.0)).sqrt()
    };
    let mut h = (weight * x / (2.0 * lambda))
        .abs()
        .max(1e-6 * weight * length);
    let mut vb = 0.5 * weight * (z / lambda.tanh() + length);
    let scale = weight * length + ea * 1e-12;
    for _ in 0..200 {
        let (rx, rz, _) = residual(x, z, length, weight, ea, seabed, h, vb);
        if rx.abs() < 1e-12 * length.max(x) && rz.abs() < 1e-12 * length.max(x) {
            let va = vb - weight * length;
            let grounded = if seabed && va < 0.0 {
                length - vb / weight
            } else {
                0.0
            };
            return Some(Catenary {
                horizontal: h,
                vertical_b: vb,
                vertical_a: if grounded > 0.0 { 0.0 } else { va },
                grounded_length: grounded,
                length,
                weight,
                ea,
            });
        }
        let dh = 1e-7 * h.max(1e-9 * scale);
        let dv = 1e-7 * vb.abs().max(1e-6 * scale);
        let (rxh, rzh, _) = residual(x, z, length, weight, ea, seabed, h + dh, vb);
        let (rxv, rzv, _) = residual(x, z, length, weight, ea, seabed, h, vb + dv);
        let (a, b, c, d) = (
            (rxh - rx) / dh,
            (rxv - rx) / dv,
            (rzh - rz) / dh,
            (rzv - rz) / dv,
        );
        let det = a * d - b * c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let step_h = -(d * rx - b * rz) / det;
        let step_v = -(-c * rx + a * rz) / det;
        // Damped step: keep H > 0 (and V_B > 0 with a seabed), and backtrack until the
        // residual falls; the seabed branch is not smooth at V_A = 0.
        let norm0 = rx.hypot(rz);
        let mut alpha = 1.0;
        let mut accepted = false;
        for _ in 0..40 {
            let hn = h + alpha * step_h;
            let vn = vb + alpha * step_v;
            if hn > 0.0 && (!seabed || vn > 0.0) {
                let (rxn, rzn, _) = residual(x, z, length, weight, ea, seabed, hn, vn);
                if rxn.hypot(rzn) < norm0 {
                    h = hn;
                    vb = vn;
                    accepted = true;
                    break;
                }
            }
            alpha *= 0.5;
        }
        if !accepted {
            return None;
        }
        if !(h.is_finite() && vb.is_finite()) {
            return None;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn profile_ends_at_fairlead_and_tension_balances() {
        for (seabed, x, z) in [
            (false, 80.0, 60.0),
            (true, 850.0, 250.0),
            (false, 99.0, 1.0),
        ] {
            let l = if seabed { 902.2 } else { 110.0 };
            let c = solve(x, z, l, 700.0, 3.84e8, seabed).expect("converges");
            let (xe, ze) = c.position(l);
            assert!(
                (xe - x).abs() < 1e-8 * l && (ze - z).abs() < 1e-8 * l,
                "{xe} {ze}"
            );
            // Vertical balance: V_B − V_A = w × suspended length.
            let suspended = l - c.grounded_length;
            assert!((c.vertical_b - c.vertical_a - 700.0 * suspended).abs() < 1e-6 * c.vertical_b);
        }
    }
}
#[cfg(test)]
mod regression {
    /// A suspended line's tension at end A is √(H² + V_A²), not H (the grounded branch once
    /// caught s = 0 when nothing was grounded).
    #[test]
    fn suspended_tension_at_end_a_includes_its_vertical_part() {
        let c = super::solve(80.0, 60.0, 110.0, 700.0, 3.84e8, false).expect("converges");
        assert!(c.vertical_a.abs() > 1.0);
        assert_eq!(c.tension(0.0), c.tension_a());
    }

    /// A long grounded chain whose first undamped Newton step overshot to V_B = 0.
    #[test]
    fn grounded_mooring_with_long_touchdown_converges() {
        let c = super::solve(600.0, 135.0, 680.0, 1088.0, 5.8e8, true).expect("converges");
        let (x, z) = c.position(680.0);
        assert!((x - 600.0).abs() < 1e-6 && (z - 135.0).abs() < 1e-6);
        assert!(c.grounded_length > 0.0);
    }
}
