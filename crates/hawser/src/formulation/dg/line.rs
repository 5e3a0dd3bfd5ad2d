//! Discretisation of a `dg` line: sections, elements, the state layout, end conditions
//! (DG paper Table 1), projections of initial shapes, positions and channels.

use super::basis::{Basis, legendre};
use crate::formulation::SectionProperties;
use crate::math::{Real, Vec3, get3, set3};
use crate::model::LineType;

/// Extra Gauss points beyond P + 1 used by the right-hand side: Q = P + 1 + this = P + 2,
/// exact for polynomial integrands of degree 2P + 3, which keeps the aliasing of the
/// nonlinear fluxes (î = q/|q|, T(ε)) small.
pub const EXTRA_POINTS: usize = 1;

/// Default strength c_f of the modal velocity filter ([`DgLine::modal_filter`]): the smallest
/// of 0.01, 0.05, 0.1 that brings a rope started compressed to rest on its anchors for every
/// order P = 2..8 (tests/dg_system.rs); 0.01 does not for P ≥ 4.
pub const DEFAULT_MODAL_FILTER: Real = 0.05;

/// Exponent of the modal filter's profile φ_k = ((k − 1)/(P − 1))^s ([`DgLine::modal_filter`]).
pub const FILTER_EXPONENT: i32 = 4;

/// Shift of the shock sensor's threshold s0 = −4 log10 P + this ([`DgLine::shock_filter`]):
/// of 0 and −1 on the undamped snapping cable, −1 gave peaks that settle with the mesh.
pub const SHOCK_SENSOR_SHIFT: Real = -1.0;

/// Half-width κ (decades) of the shock sensor's ramp ([`DgLine::shock_filter`]).
pub const SHOCK_SENSOR_WIDTH: Real = 1.0;

/// Strain floor of the shock sensor ([`DgLine::shock_filter`]): an element whose strain is
/// smaller than this everywhere does not count as a front.
pub const SHOCK_SENSOR_FLOOR: Real = 1e-6;

/// A section of a `dg` line as the user gives it.
#[derive(Clone, Debug)]
pub struct DgSectionSpec {
    /// Line type (diameter, γ0, EA, EI, ζb, drag, added mass).
    pub line_type: LineType,
    /// Unstretched length [m].
    pub length: Real,
    /// Number of equal elements.
    pub elements: usize,
    /// Polynomial order P of the Legendre basis (1..=[`super::basis::MAX_ORDER`]).
    pub order: usize,
}

/// A section resolved for computation.
#[derive(Clone, Debug)]
pub struct DgSection {
    /// Line type, element length h, area and the axial law with its damping resolved for h
    /// (DG paper eq. 22), as every formulation resolves them.
    pub properties: SectionProperties,
    /// Basis tables of the section's order.
    pub basis: Basis,
    /// Largest axial wave speed √(max T'/γ0) [m/s] (DG paper eq. 25).
    pub wave_speed: Real,
    /// Modal filter profile per mode, φ_k = ((k − 1)/(P − 1))^[`FILTER_EXPONENT`] for k ≥ 2
    /// and 0 for k < 2 ([`DgLine::modal_filter`]); all 0 when P < 2.
    pub filter_profile: Vec<Real>,
}

/// One element: where it is on the line, in the state and in the scratch arrays.
#[derive(Clone, Copy, Debug)]
pub struct Element {
    /// Section index.
    pub section: usize,
    /// Unstretched length h [m].
    pub length: Real,
    /// Arc length of its left end from end A [m].
    pub start: Real,
    /// Offset of its coefficients in the line state.
    pub state: usize,
    /// Offset of its quadrature points in the point scratch.
    pub point: usize,
    /// Offset of its modes in the modal scratch.
    pub mode: usize,
}

/// How an end is held in translation (columns v̂ and T̂ of DG paper Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Translation {
    /// The attachment's velocity is imposed: v̂ = γ0 ν_BC, T̂ = T⁺ (a reaction) plus the
    /// Lax–Friedrichs penalty of the mirrored ghost state. Fixed anchors, pinned joints,
    /// prescribed motion, free point masses and rigid bodies: the attachment receives the
    /// traction T̂ as the line's force on it.
    Velocity,
    /// A force is imposed: T̂ = T_BC, v̂ = v⁺ (free end: T_BC = 0; point force).
    Force,
}

/// How an end is held in rotation (columns î, î̇ and M̂* of DG paper Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rotation {
    /// No moment transferred: î̂ = î⁺, î̇̂ = î̇⁺, M̂* = 0 (pinned joints, free ends, prescribed
    /// pinned motion, a pin on a rigid body).
    Pinned,
    /// The tangent is imposed: î̂ = î_BC, î̇̂ = î̇_BC, M̂* = M*⁺ (a reaction).
    Clamped,
    /// A moment is imposed: î̂ = î⁺, î̇̂ = î̇⁺, M̂* = M_BC / l_ε².
    Moment,
}

/// The boundary condition of one line end (DG paper Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EndCondition {
    /// Translation.
    pub translation: Translation,
    /// Rotation (used only when the line has bending stiffness or bending damping).
    pub rotation: Rotation,
}

impl EndCondition {
    /// Prescribed motion, pinned (Table 1 row 1): v̂ = v_BC, T̂ = T⁺, M̂* = 0.
    pub const PRESCRIBED_PINNED: Self = Self {
        translation: Translation::Velocity,
        rotation: Rotation::Pinned,
    };
    /// Pinned joint (Table 1 row 2): v̂ = 0 (the attachment's velocity, zero for an anchor),
    /// T̂ = T⁺. Table 1 prints M̂* = M*⁺ for this row; a pin transfers no moment (the paper's
    /// own definition of "pinned", §3.1) and with î̂ = î⁺ as well that row would impose no
    /// rotational condition at all, so we take M̂* = 0 as in row 1.
    pub const PINNED_JOINT: Self = Self::PRESCRIBED_PINNED;
    /// Free cable end (Table 1 row 3): v̂ = v⁺, T̂ = 0, M̂* = 0 (a [`Translation::Force`] end
    /// with zero force and a [`Rotation::Moment`] end with zero moment).
    pub const FREE: Self = Self {
        translation: Translation::Force,
        rotation: Rotation::Moment,
    };
    /// Clamped fixed end (Table 1 row 4): v̂ = 0, T̂ = T⁺, î̂ = î_BC, î̇̂ = 0, M̂* = M*⁺.
    pub const CLAMPED: Self = Self {
        translation: Translation::Velocity,
        rotation: Rotation::Clamped,
    };
    /// Point force and moment (Table 1 row 5): v̂ = v⁺, T̂ = T_BC, M̂* = M*_BC.
    pub const POINT_LOAD: Self = Self::FREE;
    /// Rigid body connection at a point (Table 1 row 6): v̂ = v_RB, T̂ = T⁺, M̂* = 0.
    pub const RIGID_BODY: Self = Self::PRESCRIBED_PINNED;
}

/// What the attachment of an end supplies at each right-hand-side evaluation (RK stage).
/// Fields that the end's [`EndCondition`] does not use are ignored.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EndState {
    /// Position of the attachment [m] (used by the statics' span condition and to seed
    /// positions; the fluxes do not need it).
    pub position: Vec3,
    /// Velocity of the attachment [m/s] ([`Translation::Velocity`]).
    pub velocity: Vec3,
    /// Acceleration of the attachment [m/s²]. Not used by the fluxes (the DG end has no
    /// lumped mass); carried so that a host passes the full kinematics in one value.
    pub acceleration: Vec3,
    /// Force applied on the line end by its attachment [N] ([`Translation::Force`]).
    pub force: Vec3,
    /// Moment applied on the line end by its attachment [N·m] ([`Rotation::Moment`]).
    pub moment: Vec3,
    /// Imposed tangent direction î_BC pointing into the line at end A and out of it at end
    /// B [-] ([`Rotation::Clamped`]; normalised on use).
    pub direction: Vec3,
    /// Imposed rate of the tangent î̇_BC [1/s] ([`Rotation::Clamped`]; zero when fixed).
    pub direction_rate: Vec3,
}

impl EndState {
    /// An attachment at rest at `position`, clamped (when clamped) along `direction`.
    pub fn fixed(position: Vec3, direction: Vec3) -> Self {
        Self {
            position,
            velocity: Vec3::zeros(),
            acceleration: Vec3::zeros(),
            force: Vec3::zeros(),
            moment: Vec3::zeros(),
            direction,
            direction_rate: Vec3::zeros(),
        }
    }
}

/// The loads a line puts on the attachment of one end: the traction of the numerical flux
/// T̂ (the DG line end has no lumped mass) and the bending moment M = l_ε² M̂*.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EndLoad {
    /// Force on the attachment [N].
    pub force: Vec3,
    /// Moment on the attachment [N·m].
    pub moment: Vec3,
}

/// A `dg` line: sections, elements, end conditions and the state layout.
///
/// State layout (one contiguous slice per line): element after element from end A; in each
/// element of order P, with m = P + 1 modes, 3m coefficients of q, then 3m of v = γ0 ν, then
/// 3m of the position field r, mode-major (`[3k + c]` for mode k, component c).
#[derive(Clone, Debug)]
pub struct DgLine {
    /// Sections from end A.
    pub sections: Vec<DgSection>,
    /// Elements from end A.
    pub elements: Vec<Element>,
    /// Boundary condition of end A (s = 0) and end B (s = L).
    pub ends: [EndCondition; 2],
    /// LDG flux parameter β ∈ [−½, ½] (DG paper eqs. 29–30); 0 is centred.
    pub beta: Real,
    /// Whether any section has bending stiffness or bending damping.
    pub bending: bool,
    /// Strength c_f [-] of the modal velocity filter (0: none; [`DEFAULT_MODAL_FILTER`] by
    /// default). In each element of order P ≥ 2 the velocity modes k ≥ 2 decay at the rate
    /// σ_e φ_k, σ_e = c_f λ (2P + 1)/h, φ_k = ((k − 1)/(P − 1))^[`FILTER_EXPONENT`], added
    /// to dv_k/dt (a spectral-vanishing-viscosity form of the modal filter of Hesthaven &
    /// Warburton, *Nodal DG methods*, 2008, §5.3; not in the DG paper). Why: with the
    /// bilinear (tension-only) law a slack stretch lets the aliasing of the nonlinear flux
    /// T(ε) î feed a velocity pattern in the highest modes which the Lax–Friedrichs flux
    /// cannot see (its values at the element ends match across interfaces while the q
    /// jumps cancel their flux); left alone it settles into a steady state whose drag holds
    /// part of the line's weight (a rope 40 % light on its anchors, docs/dg.md). Modes 0 and
    /// 1 (momentum, and the rotation of a straight element) are never damped, nor is a line at
    /// rest; the smooth verification cases move by less than their tolerances.
    pub modal_filter: Real,
    /// Extra strength c_s [-] of the modal filter at fronts (0, the default: off). In each
    /// element of order P ≥ 2 a Persson–Peraire smoothness sensor on the strain ε = |q| − 1,
    /// S_e = log10(ε̂_P² /(2P + 1) / (Σ_k ε̂_k² /(2k + 1) + [`SHOCK_SENSOR_FLOOR`]²)) (the
    /// share of the mean square of the strain in its highest Legendre mode), raises the
    /// filter strength from c_f to c_f + c_s ramp(S_e): 0 below s0 − κ, 1 above s0 + κ and
    /// ½(1 + sin(π(S_e − s0)/(2κ))) between, s0 = −4 log10 P + [`SHOCK_SENSOR_SHIFT`],
    /// κ = [`SHOCK_SENSOR_WIDTH`]. Elements where the sensor is off keep the filter of
    /// [`DgLine::modal_filter`] exactly. For undamped snaps (docs/dg.md, "Shock sensor");
    /// 0.25 is the value measured there. The stable step counts c_f + c_s.
    pub shock_filter: Real,
    /// Scale [-] of the Lax–Friedrichs dissipation of the axial q–v fluxes (DG paper eqs.
    /// 24–25): the jump terms ½λ[q] of the q flux and ½Z[ν] of the v flux, interior and at
    /// velocity ends (T̂ = T⁺ ± s Z (ν_BC − ν⁺)), are multiplied by it. 1 (the default) is
    /// the paper's Lax–Friedrichs flux; 0 leaves the centred fluxes {ν} and {T î + T_s}.
    /// For verification only (tests/dg_ring.rs): the dynamics need the dissipation, and the
    /// impedance a system's free point sees stays Z.
    pub axial_dissipation: Real,
    state_len: usize,
    point_len: usize,
    mode_len: usize,
}

impl DgLine {
    /// Builds a line from its sections and end conditions, with centred LDG fluxes (β = 0).
    pub fn new(sections: &[DgSectionSpec], ends: [EndCondition; 2]) -> Self {
        let mut out = Vec::new();
        let mut elements = Vec::new();
        let (mut state, mut point, mut mode, mut start) = (0, 0, 0, 0.0);
        let mut bending = false;
        for (k, spec) in sections.iter().enumerate() {
            assert!(spec.elements > 0 && spec.length > 0.0);
            let t = &spec.line_type;
            let h = spec.length / spec.elements as Real;
            let basis = Basis::new(spec.order, spec.order + 1 + EXTRA_POINTS);
            let m = basis.modes();
            for _ in 0..spec.elements {
                elements.push(Element {
                    section: k,
                    length: h,
                    start,
                    state,
                    point,
                    mode,
                });
                state += 9 * m;
                point += basis.points;
                mode += m;
                start += h;
            }
            bending |= t.bending_stiffness > 0.0 || t.bending_damping > 0.0;
            let p = spec.order as Real;
            let filter_profile = (0..m)
                .map(|k| {
                    if k < 2 {
                        0.0
                    } else {
                        ((k - 1) as Real / (p - 1.0)).powi(FILTER_EXPONENT)
                    }
                })
                .collect();
            out.push(DgSection {
                properties: SectionProperties::new(t, h),
                wave_speed: (t.axial_stiffness.max_tangent() / t.mass_per_length).sqrt(),
                basis,
                filter_profile,
            });
        }
        Self {
            sections: out,
            elements,
            ends,
            beta: 0.0,
            bending,
            modal_filter: DEFAULT_MODAL_FILTER,
            shock_filter: 0.0,
            axial_dissipation: 1.0,
            state_len: state,
            point_len: point,
            mode_len: mode,
        }
    }

    /// Length of the line state.
    pub fn state_len(&self) -> usize {
        self.state_len
    }
    /// Number of quadrature points over the line.
    pub fn point_len(&self) -> usize {
        self.point_len
    }
    /// Number of modes over the line (Σ (P + 1)).
    pub fn mode_len(&self) -> usize {
        self.mode_len
    }
    /// Total unstretched length [m].
    pub fn length(&self) -> Real {
        self.elements.last().map_or(0.0, |e| e.start + e.length)
    }
    /// Nodal degrees of freedom: Σ (P + 1) per element (the count of the benchmarks).
    pub fn nodal_dofs(&self) -> usize {
        self.mode_len
    }

    /// The section of an element.
    #[inline]
    pub fn section(&self, e: usize) -> &DgSection {
        &self.sections[self.elements[e].section]
    }

    /// Element index and local coordinate ξ ∈ [−1, 1] of arc length s [m] (clamped to the
    /// line).
    pub fn locate(&self, s: Real) -> (usize, Real) {
        let n = self.elements.len();
        let e = self
            .elements
            .partition_point(|el| el.start + el.length <= s)
            .min(n - 1);
        let el = &self.elements[e];
        let xi = (2.0 * (s - el.start) / el.length - 1.0).clamp(-1.0, 1.0);
        (e, xi)
    }

    /// Coefficient slices of element `e`: (q, v, r), each 3(P + 1) long.
    #[inline]
    pub fn fields<'a>(&self, state: &'a [Real], e: usize) -> (&'a [Real], &'a [Real], &'a [Real]) {
        let m3 = 3 * self.section(e).basis.modes();
        let o = self.elements[e].state;
        (
            &state[o..o + m3],
            &state[o + m3..o + 2 * m3],
            &state[o + 2 * m3..o + 3 * m3],
        )
    }

    /// Evaluates a modal vector field of element `e` (coefficients `c`) at ξ.
    pub fn eval_modes(&self, e: usize, c: &[Real], xi: Real) -> Vec3 {
        let m = self.section(e).basis.modes();
        let mut p = [0.0; super::basis::MAX_ORDER + 2];
        let mut dp = [0.0; super::basis::MAX_ORDER + 2];
        legendre(m - 1, xi, &mut p, &mut dp);
        (0..m).fold(Vec3::zeros(), |acc, k| acc + get3(c, k) * p[k])
    }

    /// q = ∂r/∂s [-] at arc length s [m].
    pub fn tangent_vector(&self, state: &[Real], s: Real) -> Vec3 {
        let (e, xi) = self.locate(s);
        self.eval_modes(e, self.fields(state, e).0, xi)
    }

    /// Velocity ν = v/γ0 [m/s] at arc length s [m].
    pub fn velocity(&self, state: &[Real], s: Real) -> Vec3 {
        let (e, xi) = self.locate(s);
        self.eval_modes(e, self.fields(state, e).1, xi)
            / self.section(e).properties.line_type.mass_per_length
    }

    /// Strain ε = |q| − 1 [-] at arc length s [m] (DG paper eq. 7).
    pub fn strain(&self, state: &[Real], s: Real) -> Real {
        self.tangent_vector(state, s).norm() - 1.0
    }

    /// Elastic tension T(ε, 0) [N] at arc length s [m] (the damping part needs ε̇: see
    /// [`super::DgWorkspace`]'s channels after a right-hand-side evaluation).
    pub fn elastic_tension(&self, state: &[Real], s: Real) -> Real {
        let (e, _) = self.locate(s);
        self.section(e)
            .properties
            .law
            .tension(self.strain(state, s), 0.0)
    }

    /// Position [m] at arc length s [m] from the evolved position field r (ṙ = v/γ0).
    /// External loads use [`DgLine::position_from_tangent`] instead (see the module doc).
    pub fn evolved_position(&self, state: &[Real], s: Real) -> Vec3 {
        let (e, xi) = self.locate(s);
        self.eval_modes(e, self.fields(state, e).2, xi)
    }

    /// Position [m] at arc length s [m]: r = r_base + ∫₀ˢ q ds with the base of
    /// [`DgLine::position_base`] (the positions the external loads see).
    pub fn position(&self, state: &[Real], ends: &[EndState; 2], s: Real) -> Vec3 {
        let base = self.position_base(state, ends);
        self.position_from_tangent(state, base, s)
    }

    /// Position [m] at arc length s [m] integrated from end A's position `r_a` along q:
    /// r(s) = r_A + ∫₀ˢ q ds (exact for the modal q: ∫₋₁^ξ P_k = (P_{k+1} − P_{k−1})/(2k+1)).
    pub fn position_from_tangent(&self, state: &[Real], r_a: Vec3, s: Real) -> Vec3 {
        let (e_s, xi) = self.locate(s);
        let mut r = r_a;
        for e in 0..=e_s {
            let q = self.fields(state, e).0;
            let half = 0.5 * self.elements[e].length;
            if e < e_s {
                r += get3(q, 0) * (2.0 * half);
            } else {
                r += self.integral_modes(e, q, xi) * half;
            }
        }
        r
    }

    /// ∫₋₁^ξ of a modal field of element `e` (in ξ units).
    fn integral_modes(&self, e: usize, c: &[Real], xi: Real) -> Vec3 {
        let m = self.section(e).basis.modes();
        let mut p = [0.0; super::basis::MAX_ORDER + 2];
        let mut dp = [0.0; super::basis::MAX_ORDER + 2];
        legendre(m, xi, &mut p, &mut dp);
        let mut acc = get3(c, 0) * (xi + 1.0);
        for k in 1..m {
            acc += get3(c, k) * ((p[k + 1] - p[k - 1]) / (2 * k + 1) as Real);
        }
        acc
    }

    /// Sets the state by L2 projection of a shape: `f(s)` returns the position r [m], the
    /// tangent vector q = ∂r/∂s [-] and the velocity ν [m/s] at arc length s [m].
    /// Allocates (initialisation only).
    pub fn project(&self, state: &mut [Real], f: impl Fn(Real) -> (Vec3, Vec3, Vec3)) {
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            let m = sec.basis.modes();
            let fine = Basis::new(m - 1, m + 8);
            let gamma = sec.properties.line_type.mass_per_length;
            let o = el.state;
            state[o..o + 9 * m].iter_mut().for_each(|x| *x = 0.0);
            for qp in 0..fine.points {
                let s = el.start + 0.5 * (fine.xi[qp] + 1.0) * el.length;
                let (r, q, nu) = f(s);
                for k in 0..m {
                    let w = fine.weight[qp] * fine.phi[qp * m + k] * fine.inverse_mass[k];
                    for c in 0..3 {
                        state[o + 3 * k + c] += w * q[c];
                        state[o + 3 * m + 3 * k + c] += w * gamma * nu[c];
                        state[o + 6 * m + 3 * k + c] += w * r[c];
                    }
                }
            }
        }
    }

    /// Sets a straight line at rest from `a` to `b` [m] (uniform strain).
    pub fn straight(&self, state: &mut [Real], a: Vec3, b: Vec3) {
        let l = self.length();
        let q = (b - a) / l;
        self.project(state, |s| (a + q * s, q, Vec3::zeros()));
    }

    /// Replaces the position field by r_A + ∫q (after a statics solve, or to re-synchronise).
    pub fn positions_from_tangent(&self, state: &mut [Real], r_a: Vec3) {
        let mut ra = r_a;
        for (e, el) in self.elements.iter().enumerate() {
            let m = self.section(e).basis.modes();
            let o = el.state;
            let half = 0.5 * el.length;
            // r(ξ) = r_a + half ∫₋₁^ξ Σ q_k P_k: in modes, ∫₋₁^ξ P_0 = P_1 + P_0 and
            // ∫₋₁^ξ P_k = (P_{k+1} − P_{k−1})/(2k+1); the P_{m} term (degree P + 1) is dropped,
            // which is the L2 projection of the integral onto order P.
            let mut r = vec![Vec3::zeros(); m];
            r[0] = ra;
            for k in 0..m {
                let qk = get3(&state[o..], k) * half;
                if k == 0 {
                    r[0] += qk;
                    if m > 1 {
                        r[1] += qk;
                    }
                } else {
                    let c = 1.0 / (2 * k + 1) as Real;
                    if k + 1 < m {
                        r[k + 1] += qk * c;
                    }
                    r[k - 1] -= qk * c;
                }
            }
            for (k, rk) in r.iter().enumerate() {
                set3(&mut state[o + 6 * m..], k, rk);
            }
            ra += get3(&state[o..], 0) * el.length;
        }
    }
}
