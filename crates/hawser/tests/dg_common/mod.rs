//! Shared builders of the `dg` tests.
#![allow(dead_code)]

use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use hawser::model::LineType;
use hawser::physics::environment::Environment;
use hawser::physics::hydrodynamics::DragModel;
use hawser::physics::material::{AxialDamping, AxialStiffness};

/// A line type without fluid loading: γ0 [kg/m], EA [N], EI [N·m²], carrying compression.
pub fn beam_type(gamma: Real, ea: Real, ei: Real) -> LineType {
    LineType {
        name: "beam".into(),
        diameter: 0.01,
        mass_per_length: gamma,
        axial_stiffness: AxialStiffness::Linear(ea),
        axial_damping: AxialDamping::Coefficient(0.0),
        compression: true,
        bending_stiffness: ei,
        bending_damping: 0.0,
        drag: DragModel::Morison {
            normal: 0.0,
            tangential: 0.0,
        },
        normal_added_mass: 0.0,
        tangential_added_mass: 0.0,
        minimum_breaking_load: None,
        design_safety_factor: None,
    }
}

/// No gravity, no fluid loading at z ≥ 0.
pub fn vacuum() -> Environment {
    Environment {
        gravity: 0.0,
        ..Default::default()
    }
}

/// A single-section line.
pub fn single(
    t: LineType,
    length: Real,
    elements: usize,
    order: usize,
    ends: [EndCondition; 2],
) -> DgLine {
    DgLine::new(
        &[DgSectionSpec {
            line_type: t,
            length,
            elements,
            order,
        }],
        ends,
    )
}

/// Ends at rest at `a` and `b`, clamped (when clamped) along +x.
pub fn fixed_ends(a: Vec3, b: Vec3) -> [EndState; 2] {
    [EndState::fixed(a, Vec3::x()), EndState::fixed(b, Vec3::x())]
}

/// Time at which `f` first crosses `level` going up, linearly interpolated between samples.
pub fn crossing(times: &[Real], values: &[Real], level: Real) -> Option<Real> {
    for k in 1..values.len() {
        if values[k - 1] < level && values[k] >= level {
            let w = (level - values[k - 1]) / (values[k] - values[k - 1]);
            return Some(times[k - 1] + w * (times[k] - times[k - 1]));
        }
    }
    None
}

/// Ring-shaped beam of the DG paper (§4.1): L = 2π, EA = 100 N, γ0 = 10 kg/m, EI = 1 N·m²,
/// clamped at s = 0 along +x, end moment M_y = 1 N·m at s = L. The static shape is the circle
/// r(s) = (sin s, 0, cos s − 1) of radius 1 centred at (x, z) = (0, −1).
///
/// Solved as the steady state of the DG equations by Newton ([`steady_state`]) from the
/// projected circle, instead of the paper's 500 s moment ramp: the steady state of the
/// dynamics is the same discrete solution. Returns the L2 error of eq. 34 (positions
/// r = ∫q ds from the clamped end, 16 Gauss points per element) and the Newton iterations.
pub fn ring_error(order: usize, elements: usize, beta: Real) -> (Real, usize) {
    let (e, _, it) = ring_errors(order, elements, beta);
    (e, it)
}

/// [`ring_error`] with the L2 error of q = ∂r/∂s as well: (position error, q error,
/// iterations).
pub fn ring_errors(order: usize, elements: usize, beta: Real) -> (Real, Real, usize) {
    ring_errors_with(order, elements, beta, |_| {})
}

/// [`ring_errors`] on a line adjusted by `setup` (flux settings) before the solve.
pub fn ring_errors_with(
    order: usize,
    elements: usize,
    beta: Real,
    setup: impl Fn(&mut DgLine),
) -> (Real, Real, usize) {
    let mut line = single(
        beam_type(10.0, 100.0, 1.0),
        2.0 * std::f64::consts::PI,
        elements,
        order,
        [EndCondition::CLAMPED, EndCondition::FREE],
    );
    line.beta = beta;
    setup(&mut line);
    let env = vacuum();
    let mut state = vec![0.0; line.state_len()];
    let circle = |s: Real| Vec3::new(s.sin(), 0.0, s.cos() - 1.0);
    line.project(&mut state, |s| {
        (circle(s), Vec3::new(s.cos(), 0.0, -s.sin()), Vec3::zeros())
    });
    let mut ends = fixed_ends(Vec3::zeros(), circle(2.0 * std::f64::consts::PI));
    ends[1].moment = Vec3::new(0.0, 1.0, 0.0);
    let out = steady_state(&line, &env, 0.0, &mut state, &ends, 1e-13, 100)
        .unwrap_or_else(|e| panic!("ring P {order} N {elements}: Newton failed {e:?}"));
    let (x, w) = hawser::formulation::dg::basis::gauss_legendre(16);
    let (mut num, mut den, mut qnum) = (0.0, 0.0, 0.0);
    for el in &line.elements {
        for (xi, wq) in x.iter().zip(&w) {
            let s = el.start + 0.5 * (xi + 1.0) * el.length;
            let r = line.position_from_tangent(&state, Vec3::zeros(), s);
            let ra = circle(s);
            num += 0.5 * el.length * wq * (r - ra).norm_squared();
            den += 0.5 * el.length * wq * ra.norm_squared();
            let qa = Vec3::new(s.cos(), 0.0, -s.sin());
            qnum += 0.5 * el.length * wq * (line.tangent_vector(&state, s) - qa).norm_squared();
        }
    }
    (
        (num / den).sqrt(),
        (qnum / (2.0 * std::f64::consts::PI)).sqrt(),
        out.iterations,
    )
}

/// The vibrating cantilever of the DG paper (§4.2).
pub mod cantilever {
    use super::*;

    /// Roots Ω_i L of 1 + cos x cosh x = 0 (eq. 44).
    pub const ROOTS: [Real; 5] = [
        1.875_104_068_711_961,
        4.694_091_132_974_175,
        7.854_757_438_237_613,
        10.995_540_734_875_467,
        14.137_168_391_046_47,
    ];

    pub const M: Real = 10.0;
    pub const EI: Real = 1.0e5;
    pub const EA: Real = 1.0e5;
    pub const L: Real = 100.0;
    pub const A: Real = 1.0e-3;

    /// Mode shape Φ_i and its first three derivatives at s (eqs. 41–42), normalised to Φ(L) = 1.
    pub fn mode(i: usize, s: Real) -> [Real; 4] {
        let om = ROOTS[i] / L;
        let d = (ROOTS[i].cos() + ROOTS[i].cosh()) / (ROOTS[i].sin() + ROOTS[i].sinh());
        let raw = |s: Real| {
            let x = om * s;
            let (c, ch, sn, sh) = (x.cos(), x.cosh(), x.sin(), x.sinh());
            [
                0.5 * (c - ch + d * (sh - sn)),
                0.5 * om * (-sn - sh + d * (ch - c)),
                0.5 * om * om * (-c - ch + d * (sh + sn)),
                0.5 * om.powi(3) * (sn - sh + d * (ch + c)),
            ]
        };
        let tip = raw(L)[0];
        raw(s).map(|v| v / tip)
    }

    /// Analytic period [s] (eq. 45).
    pub fn period(i: usize) -> Real {
        2.0 * std::f64::consts::PI / (ROOTS[i] * ROOTS[i] * (EI / (M * L.powi(4))).sqrt())
    }

    /// Outcome of [`cantilever`].
    pub struct Outcome {
        pub period: Real,
        pub moment_error: Real,
        pub shear_error: Real,
        pub amplitude: Real,
    }

    /// The cantilever released from mode i: period from tip zero crossings over
    /// `half_periods`, moment and shear errors at t = 0.
    pub fn cantilever(i: usize, elements: usize, order: usize, half_periods: usize) -> Outcome {
        let line = single(
            beam_type(M, EA, EI),
            L,
            elements,
            order,
            [EndCondition::CLAMPED, EndCondition::FREE],
        );
        let env = vacuum();
        let mut state = vec![0.0; line.state_len()];
        line.project(&mut state, |s| {
            let f = mode(i, s);
            let q = Vec3::new(1.0, 0.0, A * f[1]);
            (Vec3::new(s, 0.0, A * f[0]), q / q.norm(), Vec3::zeros())
        });
        let ends = fixed_ends(Vec3::zeros(), Vec3::new(L, 0.0, 0.0));
        let mut ws = DgWorkspace::new(&line);
        let mut rate = vec![0.0; line.state_len()];
        line.rhs(&env, 0.0, &state, &ends, &mut rate, &mut ws);
        // Moment and shear at t = 0 against A EI Φ'' and −A EI Φ''' (y along +z: M = EI y'' ŷ·(−1)
        // for a deflection in z, see below), relative to their largest values.
        let (mut em, mut es, mut mmax, mut smax) =
            (0.0 as Real, 0.0 as Real, 0.0 as Real, 0.0 as Real);
        for k in 0..=200 {
            let s = L * k as Real / 200.0;
            let c = line.channels(&state, &rate, &ws, s);
            let f = mode(i, s);
            // î = x̂, κ = y'' ẑ: M = î × EI κ = −EI y'' ŷ; T_s = î × ∂M/∂s = EI y''' ... × = −EI y''' ẑ.
            let m_exact = -A * EI * f[2];
            let s_exact = -A * EI * f[3];
            em = em.max((c.moment.y - m_exact).abs());
            es = es.max((c.shear.z - s_exact).abs());
            mmax = mmax.max(m_exact.abs());
            smax = smax.max(s_exact.abs());
        }
        let mut stepper = DgStepper::new(&line);
        let dt = stable_step(&line, 0.8);
        let mut t = 0.0;
        let mut prev = line.position(&state, &ends, L).z;
        let mut crossings = Vec::new();
        let mut amplitude: Real = 0.0;
        while crossings.len() < half_periods + 1 {
            stepper.step(&line, &env, t, dt, &mut state, &mut ws, |_| ends);
            t += dt;
            let z = line.position(&state, &ends, L).z;
            if (prev > 0.0) != (z > 0.0) {
                crossings.push(t - dt * z / (z - prev));
            }
            if crossings.len() == half_periods {
                amplitude = amplitude.max(z.abs());
            }
            prev = z;
            assert!(z.is_finite() && t < 10.0 * period(i) * half_periods as Real);
        }
        let n = crossings.len() - 1;
        Outcome {
            period: 2.0 * (crossings[n] - crossings[0]) / n as Real,
            moment_error: em / mmax,
            shear_error: es / smax,
            amplitude,
        }
    }
}

/// Meshes N0, 2N0, 4N0 for order P.
pub fn meshes(order: usize) -> [usize; 3] {
    match order {
        1 => [32, 64, 128],
        2 => [16, 32, 64],
        _ => [8, 16, 32],
    }
}

/// Errors and rates for order P: (errors, rates).
pub fn convergence(order: usize) -> (Vec<Real>, Vec<Real>) {
    convergence_with(order, |_| {})
}

/// [`convergence`] on lines adjusted by `setup` (see [`ring_errors_with`]).
pub fn convergence_with(order: usize, setup: impl Fn(&mut DgLine)) -> (Vec<Real>, Vec<Real>) {
    let errors: Vec<Real> = meshes(order)
        .iter()
        .map(|&n| ring_errors_with(order, n, 0.0, &setup).0)
        .collect();
    let rates = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
    (errors, rates)
}
