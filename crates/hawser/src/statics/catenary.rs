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
//!
//! On a frictionless bed that slopes at angle α (tan α = `slope`, rising from A toward B) the
//! grounded length lies straight along the bed with tension T(s) = T_A + w s sin α (its
//! weight's component along the bed), and the suspended part leaves the bed tangentially at
//! the touchdown, where V_TD = H tan α ([`solve_on_slope`]; docs/seabed.md derives it).

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
    /// Slope tan α of the frictionless bed under the grounded length, rising from A toward B
    /// [-] (0: flat).
    pub slope: Real,
}

impl Catenary {
    /// Tension at the upper end B [N].
    pub fn tension_b(&self) -> Real {
        self.horizontal.hypot(self.vertical_b)
    }
    /// Tension at the lower end A [N].
    pub fn tension_a(&self) -> Real {
        if self.slope != 0.0 && self.grounded_length > 0.0 {
            return self.tension(0.0);
        }
        self.horizontal.hypot(self.vertical_a)
    }

    /// (cos α, sin α) of the bed under the grounded length.
    fn bed_direction(&self) -> (Real, Real) {
        let c = 1.0 / self.slope.hypot(1.0);
        (c, self.slope * c)
    }

    /// Tension at the anchor T_A = H/cos α − w L_B sin α of a line grounded on a sloping bed
    /// [N].
    fn anchor_tension_on_slope(&self) -> Real {
        let (c, sn) = self.bed_direction();
        self.horizontal / c - self.weight * self.grounded_length * sn
    }

    /// Horizontal and vertical offsets (x, z) [m] from A of the point at unstretched arc
    /// length s from A.
    pub fn position(&self, s: Real) -> (Real, Real) {
        let (h, w, ea) = (self.horizontal, self.weight, self.ea);
        let lb = self.grounded_length;
        if lb > 0.0 && self.slope != 0.0 {
            // Along the bed, stretched by T(s) = T_A + w s sin α; then the catenary from the
            // touchdown with V_TD = H tan α.
            let (c, sn) = self.bed_direction();
            let ta = self.anchor_tension_on_slope();
            let along = |s: Real| s + (ta * s + 0.5 * w * sn * s * s) / ea;
            if s <= lb {
                let l = along(s);
                return (l * c, l * sn);
            }
            let l = along(lb);
            let (sigma, vt) = (s - lb, h * self.slope);
            let v = vt + w * sigma;
            let x = l * c + (h / w) * ((v / h).asinh() - (vt / h).asinh()) + h * sigma / ea;
            let z = l * sn
                + (h / w) * ((1.0 + (v / h).powi(2)).sqrt() - (1.0 + (vt / h).powi(2)).sqrt())
                + (vt * sigma + 0.5 * w * sigma * sigma) / ea;
            return (x, z);
        }
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
        if self.slope != 0.0 && self.grounded_length > 0.0 {
            let lb = self.grounded_length;
            if s <= lb {
                return self.anchor_tension_on_slope() + self.weight * s * self.bed_direction().1;
            }
            return self
                .horizontal
                .hypot(self.horizontal * self.slope + self.weight * (s - lb));
        }
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
    let (h, vb) = newton(
        x,
        z,
        length,
        weight,
        ea,
        |h, vb| {
            let (rx, rz, _) = residual(x, z, length, weight, ea, seabed, h, vb);
            (rx, rz)
        },
        |hn, vn| hn > 0.0 && (!seabed || vn > 0.0),
    )?;
    let va = vb - weight * length;
    let grounded = if seabed && va < 0.0 {
        length - vb / weight
    } else {
        0.0
    };
    Some(Catenary {
        horizontal: h,
        vertical_b: vb,
        vertical_a: if grounded > 0.0 { 0.0 } else { va },
        grounded_length: grounded,
        length,
        weight,
        ea,
        slope: 0.0,
    })
}

/// Residual (x, z) [m] of the catenary of H = `h`, V_B = `vb` from its lower end on a
/// frictionless bed of slope tan α = `m` (rising toward B), and whether it is grounded: a
/// grounded length L_B = L − (V_B − H tan α)/w along the bed, then the suspended catenary from
/// V_TD = H tan α; fully suspended when V_A = V_B − w L ≥ V_TD.
#[allow(clippy::too_many_arguments)]
fn residual_on_slope(
    x: Real,
    z: Real,
    l: Real,
    w: Real,
    ea: Real,
    m: Real,
    h: Real,
    vb: Real,
) -> (Real, Real, bool) {
    let vt = h * m;
    let va = vb - w * l;
    if va >= vt {
        let (rx, rz, _) = residual(x, z, l, w, ea, false, h, vb);
        return (rx, rz, false);
    }
    let (c, sn) = {
        let c = 1.0 / m.hypot(1.0);
        (c, m * c)
    };
    let ls = (vb - vt) / w;
    let lb = l - ls;
    let ta = h / c - w * lb * sn;
    let along = lb + (ta * lb + 0.5 * w * sn * lb * lb) / ea;
    let rx = along * c + (h / w) * ((vb / h).asinh() - (vt / h).asinh()) + h * ls / ea - x;
    let rz = along * sn
        + (h / w) * ((1.0 + (vb / h).powi(2)).sqrt() - (1.0 + (vt / h).powi(2)).sqrt())
        + (vt * ls + 0.5 * w * ls * ls) / ea
        - z;
    (rx, rz, true)
}

/// Solves the elastic catenary from a lower end A on a frictionless bed of slope tan α =
/// `slope` [-] (rising from A toward B; negative when it falls) to B at horizontal span `x` > 0
/// [m] and height `z` [m] above A, in the vertical plane through A and B, for unstretched length
/// `length` [m], wet weight `weight` > 0 [N/m] and stiffness `ea` [N]. The bed is the line
/// through A at that slope; the line lies on it from A to the touchdown and hangs from there.
/// `None` when Newton does not converge, or when the grounded length would need a negative
/// tension at A (a chain on a steep bed slides down and piles up at its anchor).
pub fn solve_on_slope(
    x: Real,
    z: Real,
    length: Real,
    weight: Real,
    ea: Real,
    slope: Real,
) -> Option<Catenary> {
    if !(x > 0.0 && length > 0.0 && weight > 0.0 && ea > 0.0 && slope.is_finite()) {
        return None;
    }
    let (h, vb) = newton(
        x,
        z,
        length,
        weight,
        ea,
        |h, vb| {
            let (rx, rz, _) = residual_on_slope(x, z, length, weight, ea, slope, h, vb);
            (rx, rz)
        },
        |hn, vn| hn > 0.0 && vn > hn * slope,
    )?;
    let (_, _, grounded) = residual_on_slope(x, z, length, weight, ea, slope, h, vb);
    let lb = if grounded {
        length - (vb - h * slope) / weight
    } else {
        0.0
    };
    let c = Catenary {
        horizontal: h,
        vertical_b: vb,
        vertical_a: vb - weight * length,
        grounded_length: lb,
        length,
        weight,
        ea,
        slope,
    };
    if grounded {
        let ta = c.anchor_tension_on_slope();
        if !(ta >= 0.0) {
            return None;
        }
        return Some(Catenary {
            vertical_a: ta * c.bed_direction().1,
            ..c
        });
    }
    Some(c)
}

/// Damped Newton on (H, V_B) for the catenary residual `residual(h, vb)` [m] from the
/// Peyrot–Goulois guess, with a finite-difference Jacobian and steps kept where
/// `admissible(h, vb)` (H > 0, and a bed's branch conditions) and backtracked until the
/// residual falls. `Some((H, V_B))` once both residuals are below 1e-12 of max(L, X).
fn newton(
    x: Real,
    z: Real,
    length: Real,
    weight: Real,
    ea: Real,
    residual: impl Fn(Real, Real) -> (Real, Real),
    admissible: impl Fn(Real, Real) -> bool,
) -> Option<(Real, Real)> {
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
        let (rx, rz) = residual(h, vb);
        if rx.abs() < 1e-12 * length.max(x) && rz.abs() < 1e-12 * length.max(x) {
            return Some((h, vb));
        }
        let dh = 1e-7 * h.max(1e-9 * scale);
        let dv = 1e-7 * vb.abs().max(1e-6 * scale);
        let (rxh, rzh) = residual(h + dh, vb);
        let (rxv, rzv) = residual(h, vb + dv);
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
            if admissible(hn, vn) {
                let (rxn, rzn) = residual(hn, vn);
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
mod slope {
    use super::*;

    /// The OC3 chain on a bed rising (falling) at 5 %: B is reached, the line leaves the bed
    /// tangentially (tension continuous, V = H tan α at the touchdown), the grounded length
    /// carries its weight's component along the bed, and the forces on the whole line balance:
    /// T_B − T_A (cos α, sin α) − w L ẑ + w cos α L_B n = 0 with n = (−sin α, cos α).
    #[test]
    fn closed_form_reaches_b_and_balances() {
        let (l, w, ea) = (902.2, 700.0, 3.84e8);
        for m in [0.05, -0.05, 0.2] {
            let z = 250.0;
            let c = solve_on_slope(848.67, z, l, w, ea, m).expect("converges");
            assert!(c.grounded_length > 10.0, "{c:?}");
            let (x, zb) = c.position(l);
            assert!((x - 848.67).abs() < 1e-8 * l && (zb - z).abs() < 1e-8 * l);
            let lb = c.grounded_length;
            let (cos, sin) = (1.0 / m.hypot(1.0), m / m.hypot(1.0));
            let (below, above) = (c.tension(lb * (1.0 - 1e-12)), c.tension(lb * (1.0 + 1e-12)));
            assert!((below - above).abs() < 1e-6 * above, "{below} {above}");
            assert!((c.tension(lb) - c.horizontal / cos).abs() < 1e-9 * c.horizontal);
            // The touchdown lies on the bed, at the slope's height.
            let (xt, zt) = c.position(lb);
            assert!((zt - m * xt).abs() < 1e-9 * l);
            let ta = c.tension_a();
            let fx = c.horizontal - ta * cos - w * cos * lb * sin;
            let fz = c.vertical_b - ta * sin - w * l + w * cos * lb * cos;
            assert!(
                fx.abs() < 1e-6 * w * l && fz.abs() < 1e-6 * w * l,
                "{fx} {fz}"
            );
        }
    }

    /// A vanishing slope is the flat bed's closed form.
    #[test]
    fn small_slope_tends_to_the_flat_bed() {
        let flat = solve(850.0, 250.0, 902.2, 700.0, 3.84e8, true).unwrap();
        let tilted = solve_on_slope(850.0, 250.0, 902.2, 700.0, 3.84e8, 1e-10).unwrap();
        assert!((flat.tension_a() / tilted.tension_a() - 1.0).abs() < 1e-7);
        assert!((flat.tension_b() / tilted.tension_b() - 1.0).abs() < 1e-7);
        assert!((flat.grounded_length - tilted.grounded_length).abs() < 1e-5);
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
