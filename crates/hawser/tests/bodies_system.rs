//! Rigid bodies coupled to lines in a system: the 6-DOF bodies enter the coupled
//! solve through the points fixed on them (`linalg::CoupledSystem`'s body slots).

use hawser::math::{Mat3, Quat, Real, Vec3, Vec6};
use hawser::model::*;
use hawser::simulation::Simulation;
use hawser::system::System;
use hawser::verification::{
    dry_line_type, fixed, fixed_step_settings, single_line, vacuum_environment,
};

/// A body without fluid loads (above the water, no displacement, no drag).
fn dry_body(position: Vec3, mass: Real, inertia: Vec3, cog: Vec3) -> Body {
    Body {
        position,
        centre_of_gravity: cog,
        ..Body::new("body", mass, Mat3::from_diagonal(&inertia))
    }
}

/// A line from a fixed point at (0, 0, 50) down to a point on a body, in a vacuum.
fn hanging_body(
    formulation: Formulation,
    elements: usize,
    body: Body,
    attach: Vec3,
    length: Real,
    ea: Real,
    gamma: Real,
) -> Model {
    let top = Vec3::new(0.0, 0.0, 50.0);
    let mut model = single_line(
        dry_line_type(0.01, gamma, ea),
        length,
        elements,
        (
            fixed("top", top),
            Point {
                name: "bridle".into(),
                position: Vec3::zeros(),
                kind: PointKind::Body {
                    body: 0,
                    offset: attach,
                },
            },
        ),
        formulation,
        MassMatrix::Consistent,
    );
    model.environment = vacuum_environment(9.81);
    model.bodies.push(body);
    model
}

/// Energy of the whole system over a run at step `dt`: the largest |E − E0| relative to the
/// swing energy.
fn drift(model: &Model, y: Vec<Real>, dt: Real, duration: Real, scale: Real) -> Real {
    let system = System::new(model).unwrap();
    let mut sim = Simulation::new(&system, &fixed_step_settings(dt, Scheme::Rk4), y).unwrap();
    let mut ws = system.workspace();
    let e0 = system.mechanical_energy(0.0, &sim.state(), &mut ws).total();
    let mut worst: Real = 0.0;
    let steps = (duration / dt).round() as usize;
    for _ in 0..steps {
        sim.step().unwrap();
        let e = system
            .mechanical_energy(sim.time(), &sim.state(), &mut ws)
            .total();
        worst = worst.max((e - e0).abs());
    }
    worst / scale
}

/// A body with its centre of gravity off the bridle point and off its origin, swinging and
/// tumbling on an elastic line in a vacuum: the whole system (line, body translation and
/// rotation, coupled through the bridle's J = [I, −[ρ]×] and the centripetal term) conserves
/// its mechanical energy up to RK4's error, which falls by ≥ 2^3.5 when the step halves. A
/// wrong moment arm, a missing centripetal term or a wrong added inertia breaks conservation at
/// first order in dt (no convergence), which the order check catches.
#[test]
fn body_on_a_line_conserves_energy() {
    let body = dry_body(
        Vec3::zeros(),
        200.0,
        Vec3::new(30.0, 50.0, 40.0),
        Vec3::new(0.3, -0.2, -0.4),
    );
    let attach = Vec3::new(0.5, 0.2, 0.6);
    let model = hanging_body(Formulation::Fe, 8, body, attach, 10.0, 1.0e6, 1.0);
    let system = System::new(&model).unwrap();
    // Start: the line straight from the top at 30° in x–z, the body rotated so that its
    // bridle sits at the line's end, moving sideways and spinning.
    let angle: Real = 30f64.to_radians();
    let q = Quat::from_euler_angles(0.3, -0.2, 0.5);
    let top = Vec3::new(0.0, 0.0, 50.0);
    let end = top + Vec3::new(angle.sin(), 0.0, -angle.cos()) * 10.0 * (1.0 + 2e-3);
    let mut y = system.straight_state();
    let o = system.layout.body_offset[0].unwrap();
    let k = RigidKinematics {
        position: end - q * attach,
        orientation: q,
        velocity: Vec3::new(0.0, 1.0, 0.0),
        angular_velocity: Vec3::new(0.2, -0.4, 0.3),
        ..RigidKinematics::default()
    };
    hawser::bodies::write_state(&k, &mut y[o..o + hawser::bodies::STATE_LEN]);
    system.set_line_shape(&mut y, 0, |s| {
        (
            top + (end - top) * (s / 10.0),
            Vec3::new(0.0, 1.0, 0.0) * (s / 10.0),
        )
    });
    let scale = 200.0 * 9.81 * 10.0 * (1.0 - angle.cos());
    // A tenth of the stable step: the line starts with its interior velocities off the
    // bridle's, so axial waves ring, and RK4's error on them sets the drift.
    let dt = 0.1 * system.stable_step(Scheme::Rk4).0;
    let coarse = drift(&model, y.clone(), dt, 2.0, scale);
    let fine = drift(&model, y, 0.5 * dt, 2.0, scale);
    let order = (coarse / fine).log2();
    eprintln!(
        "body on a line: energy drift {coarse:.3e} at dt {dt:.3e} s, {fine:.3e} at dt/2: order {order:.2}"
    );
    assert!(fine < 1e-6, "energy drift {fine:.3e} of the swing energy");
    assert!(order > 3.5, "drift order {order:.2}");
}

/// A compact body (its centre of gravity at the bridle, tiny inertia) on a stiff light line is
/// a pendulum: small-angle period 2π/ω with ω² = g (M + m/2) / (L (M + m/3)) for a rigid line
/// of mass m and tip mass M (L the stretched length). Within 2e-3: the line's stretch is 1e-3
/// (accounted for) and its elasticity and the 3° amplitude (θ²/16 = 1.7e-4) perturb the
/// period by a few 1e-4; a body whose line force acted at the wrong point or with the wrong
/// mass would be off by the mass ratio (percent).
#[test]
fn compact_body_swings_as_a_pendulum() {
    let (mass, gamma, length, ea) = (100.0, 0.5, 10.0, 1.0e6);
    let body = dry_body(Vec3::zeros(), mass, Vec3::repeat(1e-3), Vec3::zeros());
    let model = hanging_body(Formulation::Fe, 10, body, Vec3::zeros(), length, ea, gamma);
    let system = System::new(&model).unwrap();
    let stretch = 1.0 + (mass + 0.5 * gamma * length) * 9.81 / ea;
    let l = length * stretch;
    let angle: Real = 3f64.to_radians();
    let top = Vec3::new(0.0, 0.0, 50.0);
    let end = top + Vec3::new(angle.sin(), 0.0, -angle.cos()) * l;
    let mut y = system.straight_state();
    let o = system.layout.body_offset[0].unwrap();
    let k = RigidKinematics::at_rest(end, Quat::identity());
    hawser::bodies::write_state(&k, &mut y[o..o + hawser::bodies::STATE_LEN]);
    system.set_line_shape(&mut y, 0, |s| {
        (top + (end - top) * (s / length), Vec3::zeros())
    });
    let dt = 0.5 * system.stable_step(Scheme::Rk4).0;
    let mut sim = Simulation::new(&system, &fixed_step_settings(dt, Scheme::Rk4), y).unwrap();
    let (mut last_x, mut crossings) = (Real::NAN, Vec::new());
    while sim.time() < 20.0 {
        sim.step().unwrap();
        let x = sim.state()[o];
        if last_x > 0.0 && x <= 0.0 {
            crossings.push(sim.time() - dt * x / (x - last_x));
        }
        last_x = x;
    }
    let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as Real;
    let m = gamma * length;
    let omega = (9.81 * (mass + 0.5 * m) / (l * (mass + m / 3.0))).sqrt();
    let expected = std::f64::consts::TAU / omega * (1.0 + angle * angle / 16.0);
    eprintln!(
        "pendulum: period {period:.6} s, expected {expected:.6} s, error {:.2e}",
        period / expected - 1.0
    );
    assert!((period / expected - 1.0).abs() < 2e-3);
}

/// A submerged cage on a vertical tether, started 3 m sideways and 2 m low: the statics find
/// its equilibrium pose (Newton on the pose around the line statics), where the tether's lower
/// end carries the cage's wet weight to 1e-6, the bridle hangs straight below the fairlead
/// (1e-6 m), the cage tilts until weight at the CoG (offset sideways in body axes) and
/// buoyancy at the origin balance in moment about the bridle (1e-6 of W times the offset),
/// and a dynamic run started there stays put (the cage moves < 1 mm in 2 s; a start 1 % of the
/// stretch off would bounce by centimetres).
#[test]
fn hanging_cage_statics_and_rest() {
    let mut body = dry_body(
        Vec3::new(3.0, 1.0, -102.0),
        4995.0,
        Vec3::new(19e3, 19e3, 5.7e3),
        Vec3::new(0.4, 0.0, 0.0),
    );
    body.displacement = Displacement::Submerged { volume: 0.5913 };
    body.added_mass = Vec6::new(9200.0, 9200.0, 9200.0, 0.0, 0.0, 0.0);
    body.quadratic_drag = Vec6::new(16.4, 16.4, 19.2, 0.0, 0.0, 0.0);
    let attach = Vec3::new(0.0, 0.0, 2.1);
    let mut model = hanging_body(Formulation::Fe, 20, body, attach, 100.0, 45.5e6, 3.01);
    model.environment = hawser::physics::environment::Environment {
        current: hawser::physics::environment::Current::None,
        ..Default::default()
    };
    model.points[0].position = Vec3::new(0.0, 0.0, 0.0);
    model.points[0].kind = PointKind::Fixed;
    model.settings = Settings {
        duration: 2.0,
        output_interval: 0.1,
        scheme: Scheme::Rk4,
        ..Default::default()
    };
    let system = System::new(&model).unwrap();
    let sol = match hawser::statics::solve(&system, None, &Default::default()) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    };
    let o = system.layout.body_offset[0].unwrap();
    let k = hawser::bodies::read_state(&sol.state[o..o + hawser::bodies::STATE_LEN]);
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    let wet = (4995.0 - 1025.0 * 0.5913) * model.environment.gravity;
    let bottom = system.end_force(&ws, 0, true).norm();
    let (bridle, _, _) = k.point(&attach);
    let (cog, _, _) = k.point(&Vec3::new(0.4, 0.0, 0.0));
    eprintln!(
        "cage statics ({}): bridle {bridle:?}, CoG {cog:?}, lower tension {bottom:.3} N vs wet weight {wet:.3} N",
        sol.method
    );
    assert!((bottom / wet - 1.0).abs() < 1e-6);
    assert!(
        bridle.x.abs() < 1e-6 && bridle.y.abs() < 1e-6,
        "under the fairlead: {bridle:?}"
    );
    let weight = 4995.0 * model.environment.gravity;
    let buoyancy = 1025.0 * 0.5913 * model.environment.gravity;
    let (cob, _, _) = k.point(&Vec3::zeros());
    for axis in 0..2 {
        let m = weight * (cog[axis] - bridle[axis]) - buoyancy * (cob[axis] - bridle[axis]);
        assert!(
            m.abs() < 1e-6 * weight * 0.4,
            "moment about the bridle {m:.3e} N·m (axis {axis})"
        );
    }
    let mut sim = Simulation::new(&system, &model.settings, sol.state.clone()).unwrap();
    let start = k.position;
    let mut worst: Real = 0.0;
    while sim.time() < 2.0 {
        sim.step().unwrap();
        let kk = hawser::bodies::read_state(&sim.state()[o..o + hawser::bodies::STATE_LEN]);
        worst = worst.max((kk.position - start).norm());
    }
    eprintln!("cage moves {worst:.3e} m in 2 s from statics");
    assert!(worst < 1e-3);
}
