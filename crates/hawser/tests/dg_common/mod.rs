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
    let mut line = single(
        beam_type(10.0, 100.0, 1.0),
        2.0 * std::f64::consts::PI,
        elements,
        order,
        [EndCondition::CLAMPED, EndCondition::FREE],
    );
    line.beta = beta;
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
