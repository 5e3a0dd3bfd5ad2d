//! Reference problems shared by the integration tests.
#![allow(dead_code, unused_imports)]

use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::verification as v;

pub use hawser::verification::{
    SplitMix, dry_line_type, fixed, fixed_step_settings, free, line_type, mean_period,
    upward_crossings, vacuum_environment,
};

/// One `fe` line between two points.
pub fn single_line(
    lt: LineType,
    length: Real,
    elements: usize,
    a: Point,
    b: Point,
    mass: MassMatrix,
) -> Model {
    v::single_line(lt, length, elements, (a, b), Formulation::Fe, mass)
}

// ---------------------------------------------------------------------------------------------
// Helpers of the verification tests that read or set `fe` nodes directly (rigid rotation,
// allocation, three-level); the formulation-neutral cases live in `hawser::verification`.
// ---------------------------------------------------------------------------------------------

use hawser::system::System;

/// Position and velocity of node `node` (0..=N, ends included) of line `line` in state `y`.
/// End nodes take their point's position (fixed and free points; prescribed points at t = 0
/// are not supported here and panic).
pub fn node_state(system: &System, y: &[Real], line: usize, node: usize) -> (Vec3, Vec3) {
    let l = &system.lines[line];
    let n = l.mesh.elements();
    if node == 0 || node == n {
        let p = if node == 0 { l.end_a } else { l.end_b };
        return match system.layout.point_offset[p] {
            Some(o) => (
                Vec3::new(y[o], y[o + 1], y[o + 2]),
                Vec3::new(y[o + 3], y[o + 4], y[o + 5]),
            ),
            None => match &system.points[p].kind {
                PointKind::Fixed => (system.points[p].position, Vec3::zeros()),
                _ => panic!("node_state: end on a prescribed point"),
            },
        };
    }
    let o = system.layout.line_offset[line];
    let m = system.layout.line_interior[line];
    let i = 3 * (node - 1);
    let v = o + 3 * m + i;
    (
        Vec3::new(y[o + i], y[o + i + 1], y[o + i + 2]),
        Vec3::new(y[v], y[v + 1], y[v + 2]),
    )
}

/// Sets position and velocity of node `node` of line `line` in state `y`; an end node sets its
/// free point (panics for a fixed or prescribed end).
pub fn set_node_state(
    system: &System,
    y: &mut [Real],
    line: usize,
    node: usize,
    position: Vec3,
    velocity: Vec3,
) {
    let l = &system.lines[line];
    let n = l.mesh.elements();
    let (po, vo) = if node == 0 || node == n {
        let p = if node == 0 { l.end_a } else { l.end_b };
        let o = system.layout.point_offset[p].expect("set_node_state: end is not a free point");
        (o, o + 3)
    } else {
        let o = system.layout.line_offset[line];
        let m = system.layout.line_interior[line];
        (o + 3 * (node - 1), o + 3 * m + 3 * (node - 1))
    };
    for k in 0..3 {
        y[po + k] = position[k];
        y[vo + k] = velocity[k];
    }
}

/// Element strains ε = |r_{i+1} − r_i|/L0 − 1 of line `line` computed from the state alone.
pub fn strains_from_state(system: &System, y: &[Real], line: usize, out: &mut [Real]) {
    let fe = &system.lines[line].mesh;
    let mut prev = node_state(system, y, line, 0).0;
    for (e, s) in out.iter_mut().enumerate().take(fe.elements()) {
        let next = node_state(system, y, line, e + 1).0;
        *s = (next - prev).norm() / fe.sections[fe.element_section[e]].element_length - 1.0;
        prev = next;
    }
}

/// The OC3 chain of the grounded-catenary case ([`v::grounded_chain`]) with `fe`.
pub fn oc3_chain(elements: usize, fairlead: Vec3) -> Model {
    v::grounded_chain(Formulation::Fe, elements, fairlead)
}

/// The taut string of [`v::taut_string_model`] with `fe`: unstretched length `l0` [m], γ0
/// `gamma` [kg/m], EA `ea` [N], stretched by `strain`.
pub fn taut_string(
    l0: Real,
    gamma: Real,
    ea: Real,
    strain: Real,
    elements: usize,
    mass: MassMatrix,
) -> Model {
    v::taut_string_model(Formulation::Fe, mass, (l0, gamma, ea, strain), elements)
}

/// The hanging mass of the verification suite ([`v::hanging`]) with `fe`.
pub mod hanging_mass {
    use super::*;
    pub use hawser::verification::hanging::*;
    pub use hawser::verification::rod_beta;

    /// The model with the given mass matrix.
    pub fn model(mass_matrix: MassMatrix) -> Model {
        v::hanging_mass_model(Formulation::Fe, mass_matrix, 0.0)
    }

    /// The static equilibrium displaced downward by `amplitude` [m] at the mass, linearly in
    /// s (the shape of the fundamental), at rest; and the mass's equilibrium height [m].
    ///
    /// Element e (from the top) carries the weight below its midpoint,
    /// T_e = m g + γ0 g (L − (e + ½) L0) (exact for the lumped and consistent weight alike).
    pub fn displaced_state(system: &System, amplitude: Real) -> (Vec<Real>, Real) {
        let l0 = LENGTH / ELEMENTS as Real;
        let mut y = system.straight_state();
        let mut z = 20.0;
        for e in 0..ELEMENTS {
            let tension = MASS * G + GAMMA * G * (LENGTH - (e as Real + 0.5) * l0);
            z -= l0 * (1.0 + tension / EA);
            let s = (e + 1) as Real * l0;
            let displaced = Vec3::new(0.0, 0.0, z - amplitude * s / LENGTH);
            set_node_state(system, &mut y, 0, e + 1, displaced, Vec3::zeros());
        }
        (y, z)
    }
}

/// Prints the rows of a verification case run with `fe` and asserts that each passed.
pub fn assert_case_passes(
    findings: Result<hawser::verification::Findings, hawser::verification::CaseError>,
) {
    let findings = findings.expect("the case runs");
    assert!(!findings.checks.is_empty());
    for c in &findings.checks {
        eprintln!(
            "{}: expected {:.8e} {}, computed {:.8e} (error {:.3e}, tolerance {:?}): {:?}",
            c.quantity, c.expected, c.unit, c.computed, c.error, c.tolerance, c.outcome
        );
    }
    for c in &findings.checks {
        assert_eq!(
            c.outcome,
            hawser::verification::Outcome::Pass,
            "{}: expected {} {}, computed {} (error {:.3e}, tolerance {:?})",
            c.quantity,
            c.expected,
            c.unit,
            c.computed,
            c.error,
            c.tolerance
        );
    }
}
