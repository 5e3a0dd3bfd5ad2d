//! The submerged part of a body's shape: volume and centroid of a right prism (a box, or a
//! vertical cylinder as a many-sided prism) below a plane free surface, by exact clipping.
//!
//! The shape is a right prism in body axes, centred at the body's centre of buoyancy B: its
//! section is a convex polygon in the body x–y plane, extruded over z ∈ [−H/2, H/2]. The free
//! surface is a plane; a point y (body axes, from B) is under water where
//!
//! ```text
//! h(y) = m·y + h₀ < 0,    m = Rᵀ n,   h₀ = n·(x_B − x_s)
//! ```
//!
//! with n the surface's upward normal (not necessarily unit) and x_s a point of the surface, both
//! in global axes. Every face of the prism is clipped to h < 0 (Sutherland–Hodgman against one
//! plane) and the clipped polyhedron is split into tetrahedra with a common apex **on the
//! plane**: the cap (the waterplane section, which clipping creates) then contributes nothing,
//! so it is never built. With the faces oriented outward the signed tetrahedra add up to the
//! submerged volume and its first moment exactly, whatever the orientation of the body
//! (upright, heeled, lying on its side, upside down).
//!
//! A circular cylinder of radius r is represented by a regular polygon of
//! [`CYLINDER_SIDES`] sides whose area is π r² (circumradius r·√(2π / (N sin(2π/N)))): the
//! volume, the waterplane area (hence the heave stiffness ρ g A_wp) and the centroid of an
//! upright cylinder are exact; the second moment of its waterplane (hence the metacentric
//! radius BM) differs from the circle's by the factor 1 + θ⁴/180, θ = 2π/N, which is 5·10⁻⁷
//! for N = 64. When the surface cuts an end face the polygon's segments differ from the
//! circle's by O(θ²) of the cut region.

use crate::math::{Real, Vec3};
use std::sync::OnceLock;

/// Number of sides of the polygon that stands for a circular cylinder's section.
pub const CYLINDER_SIDES: usize = 64;
/// Largest number of vertices of a clipped face: an N-gon cut by a line gains one vertex.
const MAX_FACE: usize = CYLINDER_SIDES + 2;

/// The submerged part of a shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wetted {
    /// Submerged volume [m³].
    pub volume: Real,
    /// Volume of the whole shape [m³].
    pub total_volume: Real,
    /// Centroid of the submerged volume in body axes, from the shape's centre [m] (zero when
    /// nothing is submerged).
    pub centroid: Vec3,
}

/// The section of a right prism: a convex polygon, counter-clockwise seen from body +z.
#[derive(Clone, Copy, Debug)]
pub enum Section {
    /// A rectangle of half-sides (a, b) along body x and y [m].
    Rectangle {
        /// Half-length along body x [m].
        half_length: Real,
        /// Half-breadth along body y [m].
        half_breadth: Real,
    },
    /// The regular [`CYLINDER_SIDES`]-gon with the area of a circle of this radius [m].
    Circle {
        /// Radius of the circle [m].
        radius: Real,
    },
}

/// Unit circle's [`CYLINDER_SIDES`] vertices (cos, sin), computed once.
fn unit_polygon() -> &'static [[Real; 2]; CYLINDER_SIDES] {
    static TABLE: OnceLock<[[Real; 2]; CYLINDER_SIDES]> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = [[0.0; 2]; CYLINDER_SIDES];
        for (k, v) in t.iter_mut().enumerate() {
            let a = 2.0 * std::f64::consts::PI * k as Real / CYLINDER_SIDES as Real;
            *v = [a.cos(), a.sin()];
        }
        t
    })
}

/// Circumradius factor of the regular N-gon with the area of the unit circle:
/// √(2π / (N sin(2π/N))).
fn area_matched_circumradius() -> Real {
    let n = CYLINDER_SIDES as Real;
    let theta = 2.0 * std::f64::consts::PI / n;
    (2.0 * std::f64::consts::PI / (n * theta.sin())).sqrt()
}

impl Section {
    /// Number of vertices.
    fn len(&self) -> usize {
        match self {
            Section::Rectangle { .. } => 4,
            Section::Circle { .. } => CYLINDER_SIDES,
        }
    }

    /// Vertex k (counter-clockwise) [m].
    fn vertex(&self, k: usize) -> [Real; 2] {
        match *self {
            Section::Rectangle {
                half_length: a,
                half_breadth: b,
            } => [[a, -b], [a, b], [-a, b], [-a, -b]][k],
            Section::Circle { radius } => {
                let [c, s] = unit_polygon()[k];
                let r = radius * area_matched_circumradius();
                [r * c, r * s]
            }
        }
    }

    /// Area [m²]: 4ab, or π r² (the polygon's, equal by construction).
    fn area(&self) -> Real {
        match *self {
            Section::Rectangle {
                half_length: a,
                half_breadth: b,
            } => 4.0 * a * b,
            Section::Circle { radius } => std::f64::consts::PI * radius * radius,
        }
    }
}

/// Sums signed tetrahedra (apex, face triangle) over the clipped faces.
struct Tetrahedra {
    apex: Vec3,
    volume: Real,
    moment: Vec3,
}

impl Tetrahedra {
    /// Adds the fan of a planar face given counter-clockwise seen from outside.
    fn face(&mut self, poly: &[Vec3]) {
        if poly.len() < 3 {
            return;
        }
        let a = self.apex;
        let p0 = poly[0] - a;
        for i in 1..poly.len() - 1 {
            let p1 = poly[i] - a;
            let p2 = poly[i + 1] - a;
            let v = p0.dot(&p1.cross(&p2)) / 6.0;
            self.volume += v;
            self.moment += v * (a + (p0 + p1 + p2) / 4.0);
        }
    }
}

/// Clips the polygon `input` (with heights `h`) to h < 0 into `out`; returns its length.
fn clip(input: &[Vec3], h: &[Real], out: &mut [Vec3; MAX_FACE]) -> usize {
    let n = input.len();
    let mut len = 0;
    for i in 0..n {
        let j = (i + 1) % n;
        let (a, b, ha, hb) = (input[i], input[j], h[i], h[j]);
        if ha < 0.0 {
            out[len] = a;
            len += 1;
        }
        if (ha < 0.0) != (hb < 0.0) {
            let s = ha / (ha - hb);
            out[len] = a + (b - a) * s;
            len += 1;
        }
    }
    len
}

/// Volume and centroid of the part of the prism (section × [−H/2, H/2], body axes from its
/// centre) where m·y + h₀ < 0. `half_height` is H/2 [m].
pub fn wetted_prism(section: &Section, half_height: Real, m: &Vec3, h0: Real) -> Wetted {
    let n = section.len();
    let total_volume = section.area() * 2.0 * half_height;
    let mut bottom = [Vec3::zeros(); CYLINDER_SIDES];
    let mut top = [Vec3::zeros(); CYLINDER_SIDES];
    let mut hb = [0.0; CYLINDER_SIDES];
    let mut ht = [0.0; CYLINDER_SIDES];
    let (mut wet, mut dry) = (0, 0);
    for k in 0..n {
        let [x, y] = section.vertex(k);
        bottom[k] = Vec3::new(x, y, -half_height);
        top[k] = Vec3::new(x, y, half_height);
        hb[k] = m.dot(&bottom[k]) + h0;
        ht[k] = m.dot(&top[k]) + h0;
        for h in [hb[k], ht[k]] {
            if h < 0.0 {
                wet += 1;
            } else {
                dry += 1;
            }
        }
    }
    if dry == 0 {
        return Wetted {
            volume: total_volume,
            total_volume,
            centroid: Vec3::zeros(),
        };
    }
    if wet == 0 {
        return Wetted {
            volume: 0.0,
            total_volume,
            centroid: Vec3::zeros(),
        };
    }
    let mut tets = Tetrahedra {
        apex: -h0 * m / m.norm_squared(),
        volume: 0.0,
        moment: Vec3::zeros(),
    };
    let mut out = [Vec3::zeros(); MAX_FACE];
    // Side faces (b_k, b_k+1, t_k+1, t_k): outward for a counter-clockwise section.
    for k in 0..n {
        let j = (k + 1) % n;
        let face = [bottom[k], bottom[j], top[j], top[k]];
        let h = [hb[k], hb[j], ht[j], ht[k]];
        let len = clip(&face, &h, &mut out);
        tets.face(&out[..len]);
    }
    // Top face counter-clockwise seen from +z; bottom face reversed.
    let len = clip(&top[..n], &ht[..n], &mut out);
    tets.face(&out[..len]);
    let mut rev = [Vec3::zeros(); CYLINDER_SIDES];
    let mut hrev = [0.0; CYLINDER_SIDES];
    for k in 0..n {
        rev[k] = bottom[n - 1 - k];
        hrev[k] = hb[n - 1 - k];
    }
    let len = clip(&rev[..n], &hrev[..n], &mut out);
    tets.face(&out[..len]);
    let volume = tets.volume.clamp(0.0, total_volume);
    Wetted {
        volume,
        total_volume,
        centroid: if tets.volume > 0.0 {
            tets.moment / tets.volume
        } else {
            Vec3::zeros()
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint-rule volume and centroid of the wet part of a box, on an n³ grid.
    fn brute_force(a: Real, b: Real, c: Real, m: &Vec3, h0: Real, n: usize) -> (Real, Vec3) {
        let (mut v, mut mom) = (0.0, Vec3::zeros());
        let dv = 8.0 * a * b * c / (n * n * n) as Real;
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let y = Vec3::new(
                        -a + 2.0 * a * (i as Real + 0.5) / n as Real,
                        -b + 2.0 * b * (j as Real + 0.5) / n as Real,
                        -c + 2.0 * c * (k as Real + 0.5) / n as Real,
                    );
                    if m.dot(&y) + h0 < 0.0 {
                        v += dv;
                        mom += dv * y;
                    }
                }
            }
        }
        (v, mom / v)
    }

    /// A box cut by an oblique plane: the clipped volume and centroid agree with a 200³
    /// midpoint sum. The sum's error comes from the cells the plane cuts: O(1/n) = 5e-3 of the
    /// volume if their errors added up, but they cancel for a plane that does not line up with
    /// the grid (measured 9e-7 in volume and 6e-6 of the half-length in the centroid);
    /// asserted 1e-5 and 5e-5, far below what a wrong face orientation or apex would give.
    #[test]
    fn oblique_cut_of_a_box_matches_a_grid_sum() {
        let (a, b, c) = (2.0, 1.0, 0.5);
        let m = Vec3::new(0.3, -0.5, 0.8);
        let h0 = 0.2;
        let w = wetted_prism(
            &Section::Rectangle {
                half_length: a,
                half_breadth: b,
            },
            c,
            &m,
            h0,
        );
        let (v, centroid) = brute_force(a, b, c, &m, h0, 200);
        assert!(
            (w.volume - v).abs() < 1e-5 * w.total_volume,
            "{} {v}",
            w.volume
        );
        assert!((w.centroid - centroid).norm() < 5e-5 * a, "{centroid}");
    }

    /// Any plane through the centre of a centrally symmetric prism wets half of it
    /// (to rounding, 1e-12), whatever its tilt.
    #[test]
    fn planes_through_the_centre_wet_half() {
        for section in [
            Section::Rectangle {
                half_length: 1.5,
                half_breadth: 0.7,
            },
            Section::Circle { radius: 0.8 },
        ] {
            for m in [
                Vec3::new(0.0, 0.0, 1.0),
                Vec3::new(0.2, 0.9, 0.1),
                Vec3::new(-1.0, 0.3, -0.4),
                Vec3::new(1.0, 0.0, 0.0),
            ] {
                let w = wetted_prism(&section, 1.1, &m, 0.0);
                assert!(
                    (w.volume / w.total_volume - 0.5).abs() < 1e-12,
                    "{section:?} {m}"
                );
                // The wet half lies on the −m side.
                assert!(w.centroid.dot(&m) < 0.0);
            }
        }
    }

    /// A cylinder lying on its side, half submerged: the centroid of a half disc is 4r/(3π)
    /// below the axis. The 64-gon with the circle's area places it within O(θ⁴)·r,
    /// θ = 2π/64 (its first moment of area is that of the circle to the same order as its
    /// second moment): measured 8e-8 r; asserted 1e-6 r.
    #[test]
    fn half_submerged_horizontal_cylinder() {
        let r = 1.0;
        let m = Vec3::new(0.0, 1.0, 0.0); // global up is body +y
        let w = wetted_prism(&Section::Circle { radius: r }, 3.0, &m, 0.0);
        let expected = -4.0 * r / (3.0 * std::f64::consts::PI);
        assert!(
            (w.centroid.y - expected).abs() < 1e-6 * r,
            "{} {expected}",
            w.centroid.y
        );
        assert!(w.centroid.x.abs() < 1e-12 && w.centroid.z.abs() < 1e-12);
    }

    /// Fully under and fully above the plane.
    #[test]
    fn all_or_nothing() {
        let s = Section::Circle { radius: 0.5 };
        let m = Vec3::new(0.1, 0.0, 1.0);
        let under = wetted_prism(&s, 1.0, &m, -5.0);
        assert_eq!(under.volume, under.total_volume);
        assert!((under.total_volume - std::f64::consts::PI * 0.25 * 2.0).abs() < 1e-15);
        let above = wetted_prism(&s, 1.0, &m, 5.0);
        assert_eq!(above.volume, 0.0);
    }
}
