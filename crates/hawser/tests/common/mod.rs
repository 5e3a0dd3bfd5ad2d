//! Reference problems shared by the integration tests.
#![allow(dead_code)]

use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::physics::environment::{Current, Environment};
use hawser::physics::hydrodynamics::DragModel;
use hawser::physics::material::{AxialDamping, AxialStiffness};

/// A chain-like line type.
pub fn line_type(d: Real, mass: Real, ea: Real) -> LineType {
    LineType {
        name: "t".into(),
        diameter: d,
        mass_per_length: mass,
        axial_stiffness: AxialStiffness::Linear(ea),
        axial_damping: AxialDamping::Coefficient(0.0),
        compression: false,
        bending_stiffness: 0.0,
        bending_damping: 0.0,
        drag: DragModel::Morison {
            normal: 1.2,
            tangential: 0.0,
        },
        normal_added_mass: 1.0,
        tangential_added_mass: 0.0,
    }
}

/// One line between two points.
pub fn single_line(
    lt: LineType,
    length: Real,
    elements: usize,
    a: Point,
    b: Point,
    mass: MassMatrix,
) -> Model {
    Model {
        environment: Environment {
            current: Current::None,
            ..Default::default()
        },
        line_types: vec![lt],
        lines: vec![Line {
            name: "L".into(),
            sections: vec![Section {
                line_type: 0,
                length,
                elements,
            }],
            formulation: Formulation::Fe,
            mass_matrix: mass,
            strain_measure: Default::default(),
            end_a: LineEnd::Point(0),
            end_b: LineEnd::Point(1),
        }],
        points: vec![a, b],
        settings: Settings::default(),
    }
}

/// A fixed point.
pub fn fixed(name: &str, p: Vec3) -> Point {
    Point {
        name: name.into(),
        position: p,
        kind: PointKind::Fixed,
    }
}

/// A free point mass.
pub fn free(name: &str, p: Vec3, mass: Real, volume: Real) -> Point {
    Point {
        name: name.into(),
        position: p,
        kind: PointKind::Free {
            mass,
            volume,
            drag_area: 0.0,
            added_mass_coefficient: 0.0,
            force: Vec3::zeros(),
        },
    }
}

// ---------------------------------------------------------------------------------------------
// Helpers of the verification tests (rigid rotation, energy, wave speed, mass–spring,
// convergence, allocation).
// ---------------------------------------------------------------------------------------------

use hawser::math::Mat3;
use hawser::system::System;

/// A line type without any fluid loading: no drag, no added mass (the medium may still have a
/// density; with these coefficients it exerts nothing but buoyancy below z = 0).
pub fn dry_line_type(d: Real, mass: Real, ea: Real) -> LineType {
    LineType {
        drag: DragModel::Morison {
            normal: 0.0,
            tangential: 0.0,
        },
        normal_added_mass: 0.0,
        tangential_added_mass: 0.0,
        ..line_type(d, mass, ea)
    }
}

/// An environment without any medium effect above the water: air of zero density, no current,
/// no seabed, and the given gravity.
pub fn vacuum_environment(gravity: Real) -> Environment {
    Environment {
        gravity,
        air_density: 0.0,
        current: Current::None,
        ..Default::default()
    }
}

/// Settings for a run with exactly `dt` per step (the output interval is one step).
pub fn fixed_step_settings(dt: Real, scheme: Scheme) -> Settings {
    Settings {
        time_step: TimeStep::Fixed(dt),
        output_interval: dt,
        scheme,
        initial_condition: InitialCondition::AsDefined,
        ..Default::default()
    }
}

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

/// A small deterministic generator (SplitMix64) for reproducible random tests.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> Real {
        (self.next_u64() >> 11) as Real / (1u64 << 53) as Real
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, a: Real, b: Real) -> Real {
        a + (b - a) * self.uniform()
    }
    /// A uniformly distributed rotation matrix (from a random unit quaternion, Shoemake).
    pub fn rotation(&mut self) -> Mat3 {
        let (u1, u2, u3) = (self.uniform(), self.uniform(), self.uniform());
        let tau = std::f64::consts::TAU;
        let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
        let (w, x, y, z) = (
            a * (tau * u2).sin(),
            a * (tau * u2).cos(),
            b * (tau * u3).sin(),
            b * (tau * u3).cos(),
        );
        Mat3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        )
    }
}

/// Times [s] at which the sampled signal `x` crosses `level` upwards, by linear interpolation
/// between samples `dt` apart starting at t = 0.
pub fn upward_crossings(x: &[Real], level: Real, dt: Real) -> Vec<Real> {
    let mut out = Vec::new();
    for i in 1..x.len() {
        let (a, b) = (x[i - 1] - level, x[i] - level);
        if a < 0.0 && b >= 0.0 {
            out.push(dt * ((i - 1) as Real + a / (a - b)));
        }
    }
    out
}

/// Mean period [s] from successive crossing times: (last − first)/(count − 1).
pub fn mean_period(crossings: &[Real]) -> Real {
    assert!(
        crossings.len() >= 2,
        "need two crossings, got {crossings:?}"
    );
    (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as Real
}

/// The OC3 chain (902.2 m, d 0.09 m, 77.7066 kg/m, EA 384.243 MN) from an anchor on the bed
/// at (−848.67, 0, −320) to a fixed fairlead at `fairlead` ((0, 0, −70) in the deck), in
/// 320 m of water on a stiff, frictionless bed (3e7 Pa/m: penetration w/(K_g d) ≈ 0.3 mm).
pub fn oc3_chain(elements: usize, fairlead: Vec3) -> Model {
    let mut model = single_line(
        line_type(0.09, 77.7066, 384.243e6),
        902.2,
        elements,
        fixed("anchor", Vec3::new(-848.67, 0.0, -320.0)),
        fixed("fairlead", fairlead),
        MassMatrix::Consistent,
    );
    model.environment.depth = 320.0;
    model.environment.seabed.stiffness = 3.0e7;
    model
}

/// A taut string in vacuum and zero gravity: unstretched length `l0` [m], γ0 `gamma` [kg/m],
/// EA `ea` [N], `elements` elements, stretched by `strain` between fixed points along x at
/// z = 10 m (tension EA·strain).
pub fn taut_string(
    l0: Real,
    gamma: Real,
    ea: Real,
    strain: Real,
    elements: usize,
    mass: MassMatrix,
) -> Model {
    let span = l0 * (1.0 + strain);
    let mut model = single_line(
        dry_line_type(0.01, gamma, ea),
        l0,
        elements,
        fixed("A", Vec3::new(0.0, 0.0, 10.0)),
        fixed("B", Vec3::new(span, 0.0, 10.0)),
        mass,
    );
    model.environment = vacuum_environment(0.0);
    model
}

/// The hanging mass of tests/mass_spring.rs: a 100 kg point mass in a vacuum at the end of a
/// 10 m line of 20 elements (γ0 = 1 kg/m, EA = 1e6 N) fixed at z = 20 m, gravity on.
pub mod hanging_mass {
    use super::*;
    use hawser::system::System;

    /// Line length [m].
    pub const LENGTH: Real = 10.0;
    /// Elements.
    pub const ELEMENTS: usize = 20;
    /// Mass per length [kg/m].
    pub const GAMMA: Real = 1.0;
    /// Axial stiffness [N].
    pub const EA: Real = 1.0e6;
    /// The hanging mass [kg].
    pub const MASS: Real = 100.0;
    /// Gravity [m/s²].
    pub const G: Real = 9.80665;

    /// The model with the given mass matrix.
    pub fn model(mass_matrix: MassMatrix) -> Model {
        let top = Vec3::new(0.0, 0.0, 20.0);
        let mut model = single_line(
            dry_line_type(0.02, GAMMA, EA),
            LENGTH,
            ELEMENTS,
            fixed("top", top),
            free("mass", top - Vec3::new(0.0, 0.0, LENGTH), MASS, 0.0),
            mass_matrix,
        );
        model.environment = vacuum_environment(G);
        model
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

    /// Root of β tan β = μ in (0, π/2) by bisection: the fundamental of the rod with an end
    /// mass is ω = β c/L, μ = γ0 L/m, c = √(EA/γ0).
    pub fn rod_beta(mu: Real) -> Real {
        let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2 - 1e-12);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid * mid.tan() < mu {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}
