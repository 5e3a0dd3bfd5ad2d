//! The right-hand side of a `dg` line: du/dt for u = [q, v] (and ṙ for the position field),
//! and the loads on the end attachments (DG paper eqs. 10–30, Table 1).
//!
//! Per element of order P, with Legendre modes φ_k, diagonal mass h/(2k + 1) and Q = P + 2
//! Gauss points, every derivative is taken in the weak form
//!
//!   d_k = (2k + 1)/h · [ φ_k(1) F̂_R − φ_k(−1) F̂_L − Σ_q w_q φ_k'(ξ_q) F(ξ_q) ],
//!
//! which is eq. 23 integrated by parts once (the strong form of the paper and this weak form
//! are the same scheme), and sources are projected, (2k + 1)/2 Σ_q w_q φ_k(ξ_q) G(ξ_q).

use super::basis::Basis;
use super::line::{
    DgLine, EndLoad, EndState, Rotation, SHOCK_SENSOR_FLOOR, SHOCK_SENSOR_SHIFT,
    SHOCK_SENSOR_WIDTH, Translation,
};
use crate::formulation::fluid_load;
use crate::math::{Real, Vec3, add3, get3, set3, solve3};
use crate::physics::environment::Environment;
use crate::physics::hydrodynamics::added_mass_matrix;
use crate::physics::obstacles::total_force_at;
use crate::physics::static_kinematics::FluidPoints;

/// Scratch of a line's right-hand side, sized once by [`DgWorkspace::new`]: values at the
/// quadrature points, at the two ends of every element, at the interfaces, and the modes of
/// the LDG auxiliary variables. After [`DgLine::rhs`] it holds the fields of that state,
/// which the channel accessors read.
#[derive(Clone, Debug)]
pub struct DgWorkspace {
    /// Position of end A [m] from which the positions were integrated in the last evaluation.
    pub(crate) base: Vec3,
    // At quadrature points.
    pub(crate) pos: Vec<Vec3>,
    pub(crate) q: Vec<Vec3>,
    pub(crate) nu: Vec<Vec3>,
    pub(crate) qdot: Vec<Vec3>,
    pub(crate) ihat: Vec<Vec3>,
    pub(crate) idot: Vec<Vec3>,
    pub(crate) stretch: Vec<Real>,
    pub(crate) tension: Vec<Real>,
    pub(crate) kappa: Vec<Vec3>,
    pub(crate) kdot: Vec<Vec3>,
    pub(crate) mstar: Vec<Vec3>,
    pub(crate) tau: Vec<Vec3>,
    pub(crate) shear: Vec<Vec3>,
    pub(crate) flux: Vec<Vec3>,
    pub(crate) source: Vec<Vec3>,
    pub(crate) accel: Vec<Vec3>,
    // At element ends: 2e left, 2e + 1 right.
    pub(crate) end_q: Vec<Vec3>,
    pub(crate) end_nu: Vec<Vec3>,
    pub(crate) end_qdot: Vec<Vec3>,
    pub(crate) end_ihat: Vec<Vec3>,
    pub(crate) end_idot: Vec<Vec3>,
    pub(crate) end_stretch: Vec<Real>,
    pub(crate) end_tension: Vec<Real>,
    pub(crate) end_kappa: Vec<Vec3>,
    pub(crate) end_kdot: Vec<Vec3>,
    pub(crate) end_mstar: Vec<Vec3>,
    pub(crate) end_shear: Vec<Vec3>,
    pub(crate) end_flux: Vec<Vec3>,
    // At interfaces 0..=N (0 is end A, N is end B).
    pub(crate) flux_q: Vec<Vec3>,
    pub(crate) flux_v: Vec<Vec3>,
    pub(crate) flux_i: Vec<Vec3>,
    pub(crate) flux_idot: Vec<Vec3>,
    pub(crate) flux_m: Vec<Vec3>,
    pub(crate) impedance: Vec<Real>,
    // Modes of the auxiliary variables, 3 per mode.
    pub(crate) modes_kappa: Vec<Real>,
    pub(crate) modes_kdot: Vec<Real>,
    pub(crate) modes_tau: Vec<Real>,
}

impl DgWorkspace {
    /// Scratch for `line`.
    pub fn new(line: &DgLine) -> Self {
        let np = line.point_len();
        let ne = 2 * line.elements.len();
        let ni = line.elements.len() + 1;
        let nm = 3 * line.mode_len();
        let v = |n| vec![Vec3::zeros(); n];
        Self {
            base: Vec3::zeros(),
            pos: v(np),
            q: v(np),
            nu: v(np),
            qdot: v(np),
            ihat: v(np),
            idot: v(np),
            stretch: vec![1.0; np],
            tension: vec![0.0; np],
            kappa: v(np),
            kdot: v(np),
            mstar: v(np),
            tau: v(np),
            shear: v(np),
            flux: v(np),
            source: v(np),
            accel: v(np),
            end_q: v(ne),
            end_nu: v(ne),
            end_qdot: v(ne),
            end_ihat: v(ne),
            end_idot: v(ne),
            end_stretch: vec![1.0; ne],
            end_tension: vec![0.0; ne],
            end_kappa: v(ne),
            end_kdot: v(ne),
            end_mstar: v(ne),
            end_shear: v(ne),
            end_flux: v(ne),
            flux_q: v(ni),
            flux_v: v(ni),
            flux_i: v(ni),
            flux_idot: v(ni),
            flux_m: v(ni),
            impedance: vec![0.0; ni],
            modes_kappa: vec![0.0; nm],
            modes_kdot: vec![0.0; nm],
            modes_tau: vec![0.0; nm],
        }
    }
}

/// Evaluates a modal vector field at the Gauss points; returns its values at ξ = −1 and 1.
#[inline]
fn eval(b: &Basis, c: &[Real], pts: &mut [Vec3]) -> (Vec3, Vec3) {
    let m = b.modes();
    for (qp, out) in pts.iter_mut().enumerate() {
        let row = &b.phi[qp * m..(qp + 1) * m];
        let mut s = Vec3::zeros();
        for (k, p) in row.iter().enumerate() {
            s += get3(c, k) * *p;
        }
        *out = s;
    }
    let (mut left, mut right) = (Vec3::zeros(), Vec3::zeros());
    for k in 0..m {
        let ck = get3(c, k);
        right += ck;
        left += ck * b.left[k];
    }
    (left, right)
}

/// Weak derivative d/ds of a field known at the Gauss points, with numerical fluxes at the
/// element's left and right ends, into modes `out` (3 per mode).
#[inline]
fn weak_derivative(b: &Basis, h: Real, f: &[Vec3], left: Vec3, right: Vec3, out: &mut [Real]) {
    let m = b.modes();
    for k in 0..m {
        let mut acc = right - left * b.left[k];
        for (qp, fq) in f.iter().enumerate() {
            acc -= fq * (b.weight[qp] * b.dphi[qp * m + k]);
        }
        set3(out, k, &(acc * (2.0 * b.inverse_mass[k] / h)));
    }
}

/// Adds the projection of a source known at the Gauss points into modes `out`.
#[inline]
fn add_projection(b: &Basis, g: &[Vec3], out: &mut [Real]) {
    let m = b.modes();
    for k in 0..m {
        let mut acc = Vec3::zeros();
        for (qp, gq) in g.iter().enumerate() {
            acc += gq * (b.weight[qp] * b.phi[qp * m + k]);
        }
        add3(out, k, &(acc * b.inverse_mass[k]));
    }
}

/// Stretch l_ε = |q|, unit tangent î, strain rate ε̇ = î·q̇ and tangent rate
/// î̇ = (q̇ − î ε̇)/l_ε (the paper's "(q̇ − q ε̇)/l_ε" under eq. 19 lost a factor 1/l_ε on its
/// second term: this is d/dt (q/|q|)).
#[inline]
fn kinematics(q: &Vec3, qdot: &Vec3) -> (Real, Vec3, Real, Vec3) {
    let l = q.norm().max(1e-12);
    let i = q / l;
    let rate = i.dot(qdot);
    (l, i, rate, (qdot - i * rate) / l)
}

impl DgLine {
    /// Position of end A [m] from which positions are integrated along q: end A's attachment
    /// when it imposes velocity; else end B's attachment minus ∫₀ᴸ q when B imposes
    /// velocity; else (both ends loaded by forces) the evolved position field at s = 0.
    pub fn position_base(&self, state: &[Real], ends: &[EndState; 2]) -> Vec3 {
        if self.ends[0].translation == Translation::Velocity {
            return ends[0].position;
        }
        if self.ends[1].translation == Translation::Velocity {
            let span = self.elements.iter().fold(Vec3::zeros(), |acc, el| {
                acc + get3(&state[el.state..], 0) * el.length
            });
            return ends[1].position - span;
        }
        let (_, _, r) = self.fields(state, 0);
        let m = self.section(0).basis.modes();
        (0..m).fold(Vec3::zeros(), |acc, k| {
            acc + get3(r, k) * if k % 2 == 0 { 1.0 } else { -1.0 }
        })
    }

    /// Axial wave speed λ = √(T'(ε)/γ0) [m/s] at strain ε of element `e` (DG paper eq. 25),
    /// with the tangent of the elastic law taken at max(ε, 0): a slack (or compressed)
    /// interface keeps the taut wave speed, so the Lax–Friedrichs flux stays dissipative in
    /// slack, where the bilinear law's tangent would vanish.
    #[inline]
    fn wave_speed_at(&self, e: usize, strain: Real) -> Real {
        let sec = self.section(e);
        let k = sec
            .properties
            .law
            .stiffness
            .tension_and_tangent(strain.max(0.0))
            .1;
        (k / sec.properties.line_type.mass_per_length).sqrt()
    }

    /// Time derivative of the line state and the loads on the end attachments.
    ///
    /// `ends[0]` and `ends[1]` are what the attachments of ends A and B supply at time `time`
    /// [s] (see [`EndState`]); `dstate` receives d/dt of `state` (same layout); the returned
    /// loads are the force and moment the line puts on each attachment. Allocation-free.
    pub fn rhs(
        &self,
        env: &Environment,
        time: Real,
        state: &[Real],
        ends: &[EndState; 2],
        dstate: &mut [Real],
        ws: &mut DgWorkspace,
    ) -> [EndLoad; 2] {
        self.rhs_with(env, FluidPoints::Direct, time, state, ends, dstate, ws)
    }

    /// [`DgLine::rhs`] with the fluid kinematics of the line's Gauss points taken as `fluid`
    /// says (point p of the line is its p-th Gauss point, element by element).
    #[allow(clippy::too_many_arguments)]
    pub fn rhs_with(
        &self,
        env: &Environment,
        fluid: FluidPoints,
        time: Real,
        state: &[Real],
        ends: &[EndState; 2],
        dstate: &mut [Real],
        ws: &mut DgWorkspace,
    ) -> [EndLoad; 2] {
        let n = self.elements.len();

        // 1. q, ν and r at the Gauss points and element ends; positions r = r_A + ∫q ds.
        let mut base = self.position_base(state, ends);
        ws.base = base;
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            let b = &sec.basis;
            let m = b.modes();
            let inv_gamma = 1.0 / sec.properties.line_type.mass_per_length;
            let (q, v, _) = self.fields(state, e);
            let pts = el.point..el.point + b.points;
            let half = 0.5 * el.length;
            for (qp, out) in ws.pos[pts.clone()].iter_mut().enumerate() {
                let row = &b.integral[qp * m..(qp + 1) * m];
                let mut s = Vec3::zeros();
                for (k, w) in row.iter().enumerate() {
                    s += get3(q, k) * *w;
                }
                *out = base + s * half;
            }
            base += get3(q, 0) * el.length;
            let (l, rr) = eval(b, q, &mut ws.q[pts.clone()]);
            ws.end_q[2 * e] = l;
            ws.end_q[2 * e + 1] = rr;
            let (l, rr) = eval(b, v, &mut ws.nu[pts.clone()]);
            ws.end_nu[2 * e] = l * inv_gamma;
            ws.end_nu[2 * e + 1] = rr * inv_gamma;
            ws.nu[pts].iter_mut().for_each(|x| *x *= inv_gamma);
        }

        // 2. Fluxes of the q equation (F = v/γ0, DG paper eqs. 24–25).
        let diss = self.axial_dissipation;
        for i in 1..n {
            let (l, r) = (2 * i - 1, 2 * i);
            let (ql, qr) = (ws.end_q[l], ws.end_q[r]);
            let lam_l = self.wave_speed_at(i - 1, ql.norm() - 1.0);
            let lam_r = self.wave_speed_at(i, qr.norm() - 1.0);
            let lam = lam_l.max(lam_r);
            let (gl, gr) = (
                self.section(i - 1).properties.line_type.mass_per_length,
                self.section(i).properties.line_type.mass_per_length,
            );
            let z = lam * 0.5 * (gl + gr);
            ws.impedance[i] = z;
            let jump = if self.elements[i - 1].section == self.elements[i].section {
                (qr - ql) * lam
            } else {
                // Between sections of different line types q jumps physically (different
                // strains at equal tension): penalise the jump of the elastic tension vector
                // instead, scaled by the impedance; within a section the two agree to first
                // order (T' = γ0 λ²).
                let tv = |e: usize, q: Vec3| {
                    let l = q.norm().max(1e-12);
                    q * (self.section(e).properties.law.tension(l - 1.0, 0.0) / l)
                };
                (tv(i, qr) - tv(i - 1, ql)) / z
            };
            ws.flux_q[i] = (ws.end_nu[l] + ws.end_nu[r]) * 0.5 + jump * (0.5 * diss);
        }
        for (side, (i, p, e)) in [(0, 0, 0), (n, 2 * n - 1, n - 1)].into_iter().enumerate() {
            let lam = self.wave_speed_at(e, ws.end_q[p].norm() - 1.0);
            ws.impedance[i] = lam * self.section(e).properties.line_type.mass_per_length;
            ws.flux_q[i] = match self.ends[side].translation {
                Translation::Velocity => ends[side].velocity,
                Translation::Force => ws.end_nu[p],
            };
        }

        // 3. dq/dt, and q̇ at the points and ends.
        for (e, el) in self.elements.iter().enumerate() {
            let b = &self.section(e).basis;
            let m3 = 3 * b.modes();
            let pts = el.point..el.point + b.points;
            let out = &mut dstate[el.state..el.state + m3];
            weak_derivative(
                b,
                el.length,
                &ws.nu[pts.clone()],
                ws.flux_q[e],
                ws.flux_q[e + 1],
                out,
            );
            let (l, r) = eval(b, out, &mut ws.qdot[pts]);
            ws.end_qdot[2 * e] = l;
            ws.end_qdot[2 * e + 1] = r;
        }

        // 4. Stretch, tangent, rates and tension (eqs. 7, 8, 22).
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            for p in el.point..el.point + sec.basis.points {
                let (l, i, rate, idot) = kinematics(&ws.q[p], &ws.qdot[p]);
                ws.stretch[p] = l;
                ws.ihat[p] = i;
                ws.idot[p] = idot;
                ws.tension[p] = sec.properties.law.tension(l - 1.0, rate);
            }
            for p in [2 * e, 2 * e + 1] {
                let (l, i, rate, idot) = kinematics(&ws.end_q[p], &ws.end_qdot[p]);
                ws.end_stretch[p] = l;
                ws.end_ihat[p] = i;
                ws.end_idot[p] = idot;
                ws.end_tension[p] = sec.properties.law.tension(l - 1.0, rate);
            }
        }

        // 5. Bending: nested LDG for κ, κ̇, M* and τ (eqs. 18–20, 26–30).
        if self.bending {
            self.bending_shear(ends, ws);
        }

        // 6. Flux of the v equation at points and ends: T î + T_s (eq. 5).
        for p in 0..ws.flux.len() {
            ws.flux[p] = ws.ihat[p] * ws.tension[p] + ws.shear[p];
        }
        for p in 0..ws.end_flux.len() {
            ws.end_flux[p] = ws.end_ihat[p] * ws.end_tension[p] + ws.end_shear[p];
        }
        for i in 1..n {
            let (l, r) = (2 * i - 1, 2 * i);
            ws.flux_v[i] = (ws.end_flux[l] + ws.end_flux[r]) * 0.5
                + (ws.end_nu[r] - ws.end_nu[l]) * (0.5 * diss * ws.impedance[i]);
        }
        for (side, (i, p, sign)) in [(0, 0, -1.0), (n, 2 * n - 1, 1.0)].into_iter().enumerate() {
            ws.flux_v[i] = match self.ends[side].translation {
                // Mirrored ghost ν⁻ = 2ν_BC − ν⁺, q⁻ = q⁺: T̂ = T⁺ ± Z (ν_BC − ν⁺).
                Translation::Velocity => {
                    ws.end_flux[p]
                        + (ends[side].velocity - ws.end_nu[p]) * (sign * diss * ws.impedance[i])
                }
                // The force on the line end: T̂(L) = F_B, T̂(0) = −F_A.
                Translation::Force => ends[side].force * sign,
            };
        }

        // 7. External forces at the points (eqs. 12–17) and dv/dt, dr/dt.
        let still = env.is_still_water();
        let bed_top = env.seabed_top();
        let g = env.gravity;
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            let lt = &sec.properties.line_type;
            let b = &sec.basis;
            let m = b.modes();
            let gamma = lt.mass_per_length;
            let pts = el.point..el.point + b.points;
            for (qp, p) in pts.clone().enumerate() {
                let r = ws.pos[p];
                let nu = ws.nu[p];
                let i = ws.ihat[p];
                let l = ws.stretch[p];
                let buoyancy = if r.z < 0.0 {
                    env.water_density * sec.properties.area * g
                } else {
                    0.0
                };
                let net_weight = buoyancy - gamma * g;
                let mut f = Vec3::new(0.0, 0.0, net_weight);
                f += fluid_load(
                    env,
                    &fluid,
                    p,
                    lt,
                    sec.properties.area,
                    time,
                    &r,
                    &nu,
                    &i,
                    l.sqrt(),
                    1.0,
                    still,
                );
                if r.z < bed_top + lt.diameter {
                    f += env.seabed_contact_force(
                        &r,
                        &nu,
                        lt.diameter,
                        gamma,
                        l,
                        net_weight,
                        0.5 * el.length * b.weight[qp],
                    );
                }
                if !env.obstacles.is_empty() {
                    f += total_force_at(&env.obstacles, time, &r, &nu, lt.diameter, gamma, l);
                }
                ws.source[p] = f;
            }
            let m3 = 3 * m;
            let (dv, dr) = dstate[el.state + m3..el.state + 3 * m3].split_at_mut(m3);
            weak_derivative(
                b,
                el.length,
                &ws.flux[pts.clone()],
                ws.flux_v[e],
                ws.flux_v[e + 1],
                dv,
            );
            add_projection(b, &ws.source[pts.clone()], dv);
            // Added mass (eq. 13, the cable-acceleration terms): (γ0 I + m_a) ν̇ = f, applied
            // pointwise at the Gauss points and projected back: v̇ ← P[γ0 (γ0 I + m_a)⁻¹ v̇].
            if lt.normal_added_mass != 0.0 || lt.tangential_added_mass != 0.0 {
                eval(b, dv, &mut ws.accel[pts.clone()]);
                for p in pts.clone() {
                    let rho = env.fluid_density(ws.pos[p].z);
                    let mut mm = added_mass_matrix(
                        rho,
                        sec.properties.area,
                        lt.normal_added_mass,
                        lt.tangential_added_mass,
                        &ws.ihat[p],
                    );
                    for k in 0..3 {
                        mm[(k, k)] += gamma;
                    }
                    ws.accel[p] = solve3(&mm, &ws.accel[p]).unwrap_or(ws.accel[p] / gamma) * gamma;
                }
                dv.iter_mut().for_each(|x| *x = 0.0);
                add_projection(b, &ws.accel[pts], dv);
            }
            let v = &state[el.state + m3..el.state + 2 * m3];
            // The modal velocity filter (see [`DgLine::modal_filter`]): modes k ≥ 2 of v decay
            // at σ_e φ_k, leaving the mean (momentum) and linear (rigid rotation of a straight
            // element) modes alone; the shock sensor ([`DgLine::shock_filter`]) raises its
            // strength at fronts (exactly c_f where it is off).
            let strength = self.modal_filter + self.shock_strength(e, ws);
            if strength > 0.0 && m > 2 {
                let p = (m - 1) as Real;
                let sigma = strength * sec.wave_speed * (2.0 * p + 1.0) / el.length;
                for (k, phi) in sec.filter_profile.iter().enumerate().skip(2) {
                    for c in 3 * k..3 * k + 3 {
                        dv[c] -= sigma * phi * v[c];
                    }
                }
            }
            for (d, v) in dr.iter_mut().zip(v) {
                *d = v / gamma;
            }
        }

        // 8. Loads on the attachments: the traction of the flux and the moment M = l² M̂*.
        let (la, lb) = (ws.end_stretch[0], ws.end_stretch[2 * n - 1]);
        let moment = |m: Vec3, l: Real| {
            if self.bending {
                m * (l * l)
            } else {
                Vec3::zeros()
            }
        };
        [
            EndLoad {
                force: ws.flux_v[0],
                moment: moment(ws.flux_m[0], la),
            },
            EndLoad {
                force: -ws.flux_v[n],
                moment: -moment(ws.flux_m[n], lb),
            },
        ]
    }

    /// The shock sensor's extra filter strength c_s ramp(S_e) of element `e` (see
    /// [`DgLine::shock_filter`]), from the strain at its Gauss points (`ws.stretch`).
    fn shock_strength(&self, e: usize, ws: &DgWorkspace) -> Real {
        if self.shock_filter <= 0.0 {
            return 0.0;
        }
        let el = &self.elements[e];
        let b = &self.section(e).basis;
        let m = b.modes();
        if m < 3 {
            return 0.0;
        }
        let stretch = &ws.stretch[el.point..el.point + b.points];
        // Legendre modes ε̂_k of the strain; the mean square over the element is
        // Σ_k ε̂_k²/(2k + 1).
        let (mut top, mut all) = (0.0, 0.0);
        for k in 0..m {
            let mut c = 0.0;
            for (qp, l) in stretch.iter().enumerate() {
                c += b.weight[qp] * b.phi[qp * m + k] * (l - 1.0);
            }
            c *= b.inverse_mass[k];
            let e2 = c * c / (2 * k + 1) as Real;
            all += e2;
            if k == m - 1 {
                top = e2;
            }
        }
        let s = (top / (all + SHOCK_SENSOR_FLOOR * SHOCK_SENSOR_FLOOR))
            .max(1e-300)
            .log10();
        let s0 = -4.0 * ((m - 1) as Real).log10() + SHOCK_SENSOR_SHIFT;
        let kappa = SHOCK_SENSOR_WIDTH;
        if s <= s0 - kappa {
            0.0
        } else if s >= s0 + kappa {
            self.shock_filter
        } else {
            0.5 * self.shock_filter * (1.0 + (0.5 * std::f64::consts::PI * (s - s0) / kappa).sin())
        }
    }

    /// The nested LDG chain (DG paper eqs. 18–20, 26–30): κ = ∂î/∂s and κ̇ = ∂î̇/∂s with
    /// the flux î̂ = (½ − β) î_left + (½ + β) î_right (eq. 29); M* = î × (EI κ + ζb κ̇)/l_ε²
    /// (eqs. 19–20); τ = ∂M*/∂s with M̂* = (½ + β) M*_left + (½ − β) M*_right (eq. 30); and
    /// T_s = î × τ / l_ε (eq. 20). Eqs. 26 and 27 are printed identically in the paper; the
    /// second is the same derivative applied to î̇ (the curvature rate under eq. 19), with the
    /// flux of the fourth column of Table 1.
    fn bending_shear(&self, ends: &[EndState; 2], ws: &mut DgWorkspace) {
        let n = self.elements.len();
        let beta = self.beta;
        for i in 1..n {
            let (l, r) = (2 * i - 1, 2 * i);
            ws.flux_i[i] = ws.end_ihat[l] * (0.5 - beta) + ws.end_ihat[r] * (0.5 + beta);
            ws.flux_idot[i] = ws.end_idot[l] * (0.5 - beta) + ws.end_idot[r] * (0.5 + beta);
        }
        for (side, (i, p)) in [(0, 0), (n, 2 * n - 1)].into_iter().enumerate() {
            if self.ends[side].rotation == Rotation::Clamped {
                let d = ends[side].direction;
                ws.flux_i[i] = d / d.norm().max(1e-300);
                ws.flux_idot[i] = ends[side].direction_rate;
            } else {
                ws.flux_i[i] = ws.end_ihat[p];
                ws.flux_idot[i] = ws.end_idot[p];
            }
        }
        for (e, el) in self.elements.iter().enumerate() {
            let sec = self.section(e);
            let b = &sec.basis;
            let (ei, zb) = (
                sec.properties.line_type.bending_stiffness,
                sec.properties.line_type.bending_damping,
            );
            let pts = el.point..el.point + b.points;
            let modes = 3 * el.mode..3 * (el.mode + b.modes());
            let h = el.length;
            weak_derivative(
                b,
                h,
                &ws.ihat[pts.clone()],
                ws.flux_i[e],
                ws.flux_i[e + 1],
                &mut ws.modes_kappa[modes.clone()],
            );
            let (l, r) = eval(
                b,
                &ws.modes_kappa[modes.clone()],
                &mut ws.kappa[pts.clone()],
            );
            ws.end_kappa[2 * e] = l;
            ws.end_kappa[2 * e + 1] = r;
            if zb != 0.0 {
                weak_derivative(
                    b,
                    h,
                    &ws.idot[pts.clone()],
                    ws.flux_idot[e],
                    ws.flux_idot[e + 1],
                    &mut ws.modes_kdot[modes.clone()],
                );
                let (l, r) = eval(b, &ws.modes_kdot[modes], &mut ws.kdot[pts.clone()]);
                ws.end_kdot[2 * e] = l;
                ws.end_kdot[2 * e + 1] = r;
            }
            for p in pts {
                let l = ws.stretch[p];
                let k = if zb != 0.0 {
                    ws.kappa[p] * ei + ws.kdot[p] * zb
                } else {
                    ws.kappa[p] * ei
                };
                ws.mstar[p] = ws.ihat[p].cross(&k) / (l * l);
            }
            for p in [2 * e, 2 * e + 1] {
                let l = ws.end_stretch[p];
                let k = if zb != 0.0 {
                    ws.end_kappa[p] * ei + ws.end_kdot[p] * zb
                } else {
                    ws.end_kappa[p] * ei
                };
                ws.end_mstar[p] = ws.end_ihat[p].cross(&k) / (l * l);
            }
        }
        for i in 1..n {
            let (l, r) = (2 * i - 1, 2 * i);
            ws.flux_m[i] = ws.end_mstar[l] * (0.5 + beta) + ws.end_mstar[r] * (0.5 - beta);
        }
        for (side, (i, p, sign)) in [(0, 0, -1.0), (n, 2 * n - 1, 1.0)].into_iter().enumerate() {
            ws.flux_m[i] = match self.ends[side].rotation {
                Rotation::Pinned => Vec3::zeros(),
                Rotation::Clamped => ws.end_mstar[p],
                Rotation::Moment => {
                    let l = ws.end_stretch[p];
                    ends[side].moment * (sign / (l * l))
                }
            };
        }
        for (e, el) in self.elements.iter().enumerate() {
            let b = &self.section(e).basis;
            let pts = el.point..el.point + b.points;
            let modes = 3 * el.mode..3 * (el.mode + b.modes());
            weak_derivative(
                b,
                el.length,
                &ws.mstar[pts.clone()],
                ws.flux_m[e],
                ws.flux_m[e + 1],
                &mut ws.modes_tau[modes.clone()],
            );
            let (l, r) = eval(b, &ws.modes_tau[modes], &mut ws.tau[pts.clone()]);
            for p in pts {
                ws.shear[p] = ws.ihat[p].cross(&ws.tau[p]) / ws.stretch[p];
            }
            for (p, t) in [(2 * e, l), (2 * e + 1, r)] {
                ws.end_shear[p] = ws.end_ihat[p].cross(&t) / ws.end_stretch[p];
            }
        }
    }
}
