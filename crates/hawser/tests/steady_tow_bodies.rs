//! Steady towing as a static problem in the frame moving with the vessel
//! (`initial_condition = SteadyTow`, the elastic-link paper's "solution-setting mode", §5; issue
//! 6 item 6): the tow velocity comes from the vessel's constant-velocity motion, the statics
//! evaluate every load with every material point moving at it, and the run starts from that
//! shape with everything moving at it.
//!
//! (a) a tether and a vehicle as a free point, (b) the vehicle as a free rigid body: the steady
//! tow against the end of a dynamic run started from rest with the ship moving at V, within
//! 0.5 % (the number); (c) a run started from the steady tow stays there; (d) a rigid
//! body against the independent integration of the steady cable equations
//! (`analysis::steady_cable`), the body entering as an end force, and its pitch against the
//! body's own moment balance.
//!
//! `cargo test -p hawser --release --test steady_tow_bodies -- --nocapture` prints the numbers
//! quoted in docs/towing.md.

use hawser::analysis::steady_cable::{CableSegment, SteadyTow, TowedBody};
use hawser::math::{Mat3, Quat, Real, Vec3, Vec6};
use hawser::model::*;
use hawser::physics::environment::Current;
use hawser::physics::hydrodynamics::DragModel;
use hawser::simulation::Simulation;
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::System;
use hawser::verification::{fixed, free, line_type, single_line};

/// Tow speed [m/s] (the elastic-link paper's system 2).
const SPEED: Real = 0.8;
/// Tether length [m].
const LENGTH: Real = 100.0;
/// Elements of the tether.
const ELEMENTS: usize = 20;

/// System 2's tether (docs/towing.md): 12 mm, 0.2288 kg/m, EA 1.08e7 N, C_dn 1.35, C_dt 0.04.
fn tether() -> LineType {
    let mut lt = line_type(0.012, 0.2288, 1.08e7);
    lt.drag = DragModel::Morison {
        normal: 1.35,
        tangential: 0.04,
    };
    lt
}

/// The ship: a prescribed point at the origin moving at `SPEED` along +x.
fn ship() -> Point {
    Point {
        kind: PointKind::Prescribed(Motion::ConstantVelocity {
            start: Vec3::zeros(),
            velocity: Vec3::new(SPEED, 0.0, 0.0),
        }),
        ..fixed("ship", Vec3::zeros())
    }
}

/// System 2's vehicle at thrust 100 N, 30° below the horizontal, as a free point: 250 kg,
/// neutrally buoyant, drag area 0.8 m².
fn point_tow(initial: InitialCondition) -> Model {
    let mut body = free("vehicle", Vec3::new(-90.0, 0.0, -35.0), 250.0, 0.243902);
    if let PointKind::Free {
        drag_area,
        force,
        added_mass_coefficient,
        ..
    } = &mut body.kind
    {
        *drag_area = 0.8;
        *added_mass_coefficient = 1.0;
        let a: Real = 30f64.to_radians();
        *force = Vec3::new(100.0 * a.cos(), 0.0, -100.0 * a.sin());
    }
    let mut m = single_line(
        tether(),
        LENGTH,
        ELEMENTS,
        (ship(), body),
        Formulation::Fe,
        MassMatrix::Consistent,
    );
    m.settings.initial_condition = initial;
    m
}

/// Body origin at the centre of buoyancy; tether at `BRIDLE` (body axes).
const BRIDLE: Vec3 = Vec3::new(0.5, 0.0, 0.2);
/// Centre of gravity below the centre of buoyancy [m] (body axes).
const COG: Vec3 = Vec3::new(0.0, 0.0, -0.1);

/// The vehicle as a rigid body (the values of examples/towing_system2_body.toml): 250 kg,
/// neutral, its centre of gravity 0.1 m below its centre of buoyancy; drag areas 0.8 m² in
/// surge (the point model's), 1.2 m² in sway and 1.5 m² in heave; thrust (86.6, 0, −50) N in
/// body axes (100 N, 30° below the body's x axis); the tether at the bridle 0.5 m forward and
/// 0.2 m up.
fn vehicle_body() -> Body {
    let a: Real = 30f64.to_radians();
    Body {
        position: Vec3::new(-90.0, 0.0, -35.0),
        centre_of_gravity: COG,
        displacement: Displacement::Submerged { volume: 0.243902 },
        added_mass: Vec6::new(100.0, 250.0, 300.0, 10.0, 30.0, 30.0),
        quadratic_drag: Vec6::new(0.8, 1.2, 1.5, 0.2, 0.3, 0.3),
        thrust: Thrust::Constant {
            force: Vec3::new(100.0 * a.cos(), 0.0, -100.0 * a.sin()),
            moment: Vec3::zeros(),
        },
        ..Body::new(
            "vehicle",
            250.0,
            Mat3::from_diagonal(&Vec3::new(25.0, 50.0, 50.0)),
        )
    }
}

fn body_tow(body: Body, line: LineType, elements: usize, initial: InitialCondition) -> Model {
    let bridle = Point {
        name: "bridle".into(),
        position: Vec3::zeros(),
        kind: PointKind::Body {
            body: 0,
            offset: BRIDLE,
        },
    };
    let mut m = single_line(
        line,
        LENGTH,
        elements,
        (ship(), bridle),
        Formulation::Fe,
        MassMatrix::Consistent,
    );
    m.bodies.push(body);
    m.settings.initial_condition = initial;
    m
}

/// What is compared: the tensions at the ship and at the body [N], the body's place relative to
/// the ship [m] (the free point, or the body origin), and the body's pitch [rad] (0 for a
/// point).
#[derive(Clone, Copy, Debug)]
struct TowState {
    ship_tension: Real,
    body_tension: Real,
    offset: Vec3,
    pitch: Real,
}

impl TowState {
    /// The largest of the tensions' relative differences and the offset's difference relative
    /// to its length.
    fn difference(&self, other: &TowState) -> Real {
        let t = |a: Real, b: Real| (a - b).abs() / b.abs();
        t(self.ship_tension, other.ship_tension)
            .max(t(self.body_tension, other.body_tension))
            .max((self.offset - other.offset).norm() / other.offset.norm())
    }
}

fn tow_state(system: &System, ws: &hawser::system::Workspace) -> TowState {
    let ship = ws.points[0].position;
    let (offset, pitch) = match system.free_bodies.first() {
        Some(&b) => {
            let k = &ws.bodies[b];
            (k.position - ship, k.orientation.euler_angles().1)
        }
        None => (ws.points[1].position - ship, 0.0),
    };
    TowState {
        ship_tension: system.end_force(ws, 0, false).norm(),
        body_tension: system.end_force(ws, 0, true).norm(),
        offset,
        pitch,
    }
}

/// The steady tow of `model` (whose initial condition is `SteadyTow`), its state and what is
/// compared.
fn steady(model: &Model) -> (System, Vec<Real>, TowState) {
    let system = System::new(model).unwrap();
    assert_eq!(system.tow_velocity, Vec3::new(SPEED, 0.0, 0.0));
    let sol = solve(&system, None, &StaticOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let mut ws = system.workspace();
    let residual = evaluate(&system, &sol.state, &mut ws);
    eprintln!(
        "steady tow: {} ({} iterations), residual {residual:.2e} N",
        sol.method, sol.iterations
    );
    let s = tow_state(&system, &ws);
    (system, sol.state, s)
}

/// Runs `system` from `y0` for `duration` [s]; returns the state every `every` seconds.
fn run(system: &System, y0: Vec<Real>, duration: Real, every: Real) -> Vec<(Real, TowState)> {
    let settings = Settings {
        output_interval: every,
        ..Default::default()
    };
    let mut sim = Simulation::new(system, &settings, y0).unwrap();
    let mut out = vec![(0.0, tow_state(system, sim.evaluate().unwrap()))];
    let per = (every / sim.step_size()).round() as usize;
    while sim.time() < duration - 1e-9 {
        for _ in 0..per {
            sim.step().unwrap();
        }
        let t = sim.time();
        out.push((t, tow_state(system, sim.evaluate().unwrap())));
    }
    out
}

/// The dynamic run from rest: the ordinary statics with the ship at its t = 0 place (the tether
/// hanging under the vehicle's weight and thrust, no flow), then the ship moves at V.
fn from_rest(model: &Model, duration: Real) -> Vec<(Real, TowState)> {
    let mut m = model.clone();
    m.settings.initial_condition = InitialCondition::Statics;
    let system = System::new(&m).unwrap();
    assert_eq!(system.tow_velocity, Vec3::zeros());
    let y0 = solve(&system, None, &StaticOptions::default())
        .unwrap_or_else(|e| panic!("{e}"))
        .state;
    run(&system, y0, duration, 10.0)
}

/// The dynamic run from the positions as given ("as-defined": the tether a catenary from the
/// ship to the bridle, the body at its initial pose, at rest), then the ship moves at V. (The
/// ordinary statics of the thrusting rigid vehicle at rest has no equilibrium: its thrust turns
/// with it, a follower force with nothing to balance it but the tether.)
fn from_as_defined(model: &Model, duration: Real) -> Vec<(Real, TowState)> {
    let mut m = model.clone();
    m.settings.initial_condition = InitialCondition::AsDefined;
    let system = System::new(&m).unwrap();
    let mut ws = system.workspace();
    let mut y0 = system.straight_state();
    hawser::statics::catenary_seed(&system, &mut y0, &mut ws);
    run(&system, y0, duration, 10.0)
}

fn report(name: &str, steady: &TowState, history: &[(Real, TowState)]) -> Real {
    eprintln!(
        "{name}: steady tow T_ship {:.4} N, T_body {:.4} N, offset [{:.4}, {:.4}, {:.4}] m, pitch {:.4}°",
        steady.ship_tension,
        steady.body_tension,
        steady.offset.x,
        steady.offset.y,
        steady.offset.z,
        steady.pitch.to_degrees()
    );
    for (t, s) in history.iter().filter(|(t, _)| (*t as usize) % 100 == 0) {
        eprintln!(
            "  t = {t:6.0} s: T_ship {:.4}, T_body {:.4}, offset [{:.4}, {:.4}, {:.4}], pitch {:.4}°: difference {:.2e}",
            s.ship_tension,
            s.body_tension,
            s.offset.x,
            s.offset.y,
            s.offset.z,
            s.pitch.to_degrees(),
            s.difference(steady)
        );
    }
    history.last().unwrap().1.difference(steady)
}

/// (a) A tether and a vehicle as a free point: the steady tow against the end of a run from
/// rest. The issue asks 0.5 %; the run is long enough for the transient to die out (the
/// difference printed every 100 s shows it falling), so the end state is the steady one to far
/// better than that.
#[test]
fn point_body_steady_tow_is_the_end_of_the_dynamic_run() {
    let model = point_tow(InitialCondition::SteadyTow);
    let (_, _, s) = steady(&model);
    let history = from_rest(&model, 1500.0);
    let d = report("point vehicle", &s, &history);
    eprintln!("point vehicle: end of the run against the steady tow: {d:.2e}");
    assert!(d < 5e-3, "{d:.3e}");
}

/// (b) The vehicle as a free rigid body, with its attitude: the steady tow (Newton on the
/// body's pose around the tether's statics, all in the moving frame) against the end of a run
/// from rest (as defined). Tensions and place within 0.5 % (the number); the pitch within 0.5 % of
/// itself.
#[test]
fn rigid_body_steady_tow_is_the_end_of_the_dynamic_run() {
    let model = body_tow(
        vehicle_body(),
        tether(),
        ELEMENTS,
        InitialCondition::SteadyTow,
    );
    let (_, _, s) = steady(&model);
    let history = from_as_defined(&model, 1000.0);
    let d = report("rigid vehicle", &s, &history);
    let end = history.last().unwrap().1;
    let dp = (end.pitch - s.pitch).abs() / s.pitch.abs();
    eprintln!("rigid vehicle: end of the run against the steady tow: {d:.2e}, pitch {dp:.2e}");
    assert!(s.pitch.to_degrees().abs() > 1.0, "the vehicle pitches");
    assert!(d < 5e-3, "{d:.3e}");
    assert!(dp < 5e-3, "{dp:.3e}");
}

/// (c) A run started from the steady tow stays there: every node, point and body starts moving
/// at V and the forces balance, so nothing changes. The statics converge to a residual of about
/// 1e-9 of the weights; the state then moves by that residual over the stiffness, far below
/// 1e-6. A physics term that the moving-frame statics left out or got wrong (the drag on u − V
/// of line, point or body, the body's attitude, a velocity not set) is at least 1e-3 of the
/// loads and would show at that level.
#[test]
fn a_run_from_the_steady_tow_stays_steady() {
    for (name, model) in [
        ("point vehicle", point_tow(InitialCondition::SteadyTow)),
        (
            "rigid vehicle",
            body_tow(
                vehicle_body(),
                tether(),
                ELEMENTS,
                InitialCondition::SteadyTow,
            ),
        ),
    ] {
        let (system, y, s) = steady(&model);
        let history = run(&system, y, 60.0, 1.0);
        let mut worst: Real = 0.0;
        let mut pitch: Real = 0.0;
        for (_, h) in &history {
            worst = worst.max(h.difference(&s));
            pitch = pitch.max((h.pitch - s.pitch).abs());
        }
        let end = history.last().unwrap().1;
        eprintln!(
            "{name}: 60 s from the steady tow: largest change {worst:.2e} (tensions, place), pitch \
             {pitch:.2e} rad; the ship moved {:.3} m",
            SPEED * 60.0
        );
        assert!(worst < 1e-6, "{name}: {worst:.3e}");
        assert!(pitch < 1e-6, "{name}: pitch {pitch:.3e} rad");
        assert!((end.offset - s.offset).norm() < 1e-6 * LENGTH);
    }
}

/// The depressor of (d): 300 kg displacing 0.2 m³, drag areas `DEPRESSOR_DRAG` per body axis.
const DEPRESSOR: (Real, Real) = (300.0, 0.2);
const DEPRESSOR_DRAG: [Real; 3] = [0.8, 1.2, 1.5];

/// The body's own static load f_b [N] in the tow at pitch θ [rad] (R = R_y(θ)), written out
/// here from docs/bodies.md and not taken from hawser: weight and buoyancy, and the quadratic
/// drag per body axis on the body's velocity V relative to the still water,
/// F_b,i = −½ ρ Q_i |u_i| u_i with u = Rᵀ V, acting at the centre of buoyancy (the origin).
fn depressor_load(theta: Real, rho: Real, g: Real) -> Vec3 {
    let (mass, volume) = DEPRESSOR;
    let r = Quat::from_axis_angle(&Vec3::y_axis(), theta);
    let u = r.inverse() * Vec3::new(SPEED, 0.0, 0.0);
    let drag_b = Vec3::from_fn(|i, _| -0.5 * rho * DEPRESSOR_DRAG[i] * u[i].abs() * u[i]);
    Vec3::new(0.0, 0.0, (rho * volume - mass) * g) + r * drag_b
}

/// The pitch θ [rad] at which the moments about the body origin balance, for the depressor
/// pitched by R_y(θ) in the x–z plane: the cable's pull −f_b(θ) at `BRIDLE` and the weight at
/// `COG` (buoyancy and drag act at the origin). Bisection on the root in (−60°, 60°).
fn pitch_balance(rho: Real, g: Real) -> Real {
    let weight = DEPRESSOR.0 * g;
    let moment = |theta: Real| {
        let r = Quat::from_axis_angle(&Vec3::y_axis(), theta);
        let pull = -depressor_load(theta, rho, g);
        let m = (r * BRIDLE).cross(&pull) + (r * COG).cross(&Vec3::new(0.0, 0.0, -weight));
        m.y
    };
    let (mut lo, mut hi) = (-60f64.to_radians(), 60f64.to_radians());
    assert!(moment(lo) * moment(hi) < 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if moment(mid) * moment(lo) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// (d) A heavy towed body (a depressor: 300 kg displacing 0.2 m³, drag areas 0.8, 1.2 and
/// 1.5 m² in surge, sway and heave) against an independent solution: its pitch from its own
/// moment balance (`pitch_balance`, the pull being −f_b), then the integration of the steady
/// cable equations with the body as the end force f_b(θ) (`analysis::steady_cable`). The
/// bridle's place relative to the ship and the ship-end tension agree within the `fe`
/// discretisation error, 2C/N² with C = 0.075 (the largest constant of the towing refinement
/// study, docs/towing.md); the body-end tension equals |f_b| and the pitch the balanced one
/// within the tolerance of the body statics (1e-6 of the weight, over the stiffnesses: 1e-5
/// relative, 1e-5 rad), neither depending on the cable's discretisation.
#[test]
fn rigid_body_steady_tow_matches_the_steady_cable_integration() {
    let (mass, volume) = DEPRESSOR;
    let d = DEPRESSOR_DRAG;
    let body = Body {
        displacement: Displacement::Submerged { volume },
        quadratic_drag: Vec6::new(d[0], d[1], d[2], 0.2, 0.3, 0.3),
        thrust: Thrust::None,
        ..Body {
            mass,
            inertia: Mat3::from_diagonal(&Vec3::new(30.0, 60.0, 60.0)),
            ..vehicle_body()
        }
    };
    let n = 40;
    let model = body_tow(body, tether(), n, InitialCondition::SteadyTow);
    let (system, y, s) = steady(&model);
    let env = &model.environment;
    let (rho, g) = (env.water_density, env.gravity);
    let theta = pitch_balance(rho, g);
    let f_b = depressor_load(theta, rho, g);
    let reference = SteadyTow {
        gravity: g,
        water_density: rho,
        current: Vec3::new(-SPEED, 0.0, 0.0),
        ship_end: Vec3::zeros(),
        seabed_z: Real::NEG_INFINITY,
        segments: vec![CableSegment {
            length: LENGTH,
            diameter: 0.012,
            mass_per_length: 0.2288,
            axial_stiffness: 1.08e7,
            normal_drag: 1.35,
            tangential_drag: 0.04,
        }],
        // The body enters as its end force: (ρV − m) g ẑ from mass and volume, the drag as
        // `force`.
        body: TowedBody {
            mass,
            volume,
            drag_area: 0.0,
            force: f_b - Vec3::new(0.0, 0.0, (rho * volume - mass) * g),
        },
        relative_tolerance: 1e-11,
    }
    .solve(&[])
    .unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &y, &mut ws);
    let bridle = ws.points[1].position - ws.points[0].position;
    let expected = reference.body_position();
    let place = (bridle - expected).norm() / LENGTH;
    let ship = (s.ship_tension - reference.ship_tension()).abs() / reference.ship_tension();
    let body_end = (s.body_tension - f_b.norm()).abs() / f_b.norm();
    eprintln!(
        "depressor, {n} elements: bridle [{:.4}, {:.4}, {:.4}] m against [{:.4}, {:.4}, {:.4}] m \
         ({place:.2e} of L); ship tension {:.4} against {:.4} N ({ship:.2e}); body end {:.4} \
         against |f_b| {:.4} N ({body_end:.2e}); pitch {:.4}° against the moment balance {:.4}°",
        bridle.x,
        bridle.y,
        bridle.z,
        expected.x,
        expected.y,
        expected.z,
        s.ship_tension,
        reference.ship_tension(),
        s.body_tension,
        f_b.norm(),
        s.pitch.to_degrees(),
        theta.to_degrees()
    );
    let bound = 2.0 * 0.075 / (n * n) as Real;
    assert!(place < bound, "{place:.3e}");
    assert!(ship < bound, "{ship:.3e}");
    assert!(body_end < 1e-5, "{body_end:.3e}");
    assert!((s.pitch - theta).abs() < 1e-5, "{} {}", s.pitch, theta);
    assert!(theta.to_degrees().abs() > 1.0);
}

/// A tow whose prescribed motions differ, or are not constant velocities, is refused with the
/// reason; an as-defined or statics start is unaffected.
#[test]
fn steady_tow_needs_one_constant_velocity() {
    let mut m = point_tow(InitialCondition::SteadyTow);
    m.points.push(fixed("anchor", Vec3::new(0.0, 0.0, -200.0)));
    let e = System::new(&m).unwrap_err().to_string();
    assert!(
        e.contains("anchor") && e.contains("one constant velocity"),
        "{e}"
    );
    let mut m = point_tow(InitialCondition::SteadyTow);
    m.points[0].kind = PointKind::Prescribed(Motion::Sinusoid {
        centre: Vec3::zeros(),
        amplitude: Vec3::new(1.0, 0.0, 0.0),
        frequency: Vec3::new(0.1, 0.0, 0.0),
        phase: Vec3::zeros(),
        ramp: 0.0,
    });
    let e = System::new(&m).unwrap_err().to_string();
    assert!(e.contains("sinusoid"), "{e}");
    let mut m = point_tow(InitialCondition::SteadyTow);
    m.points[0].kind = PointKind::Prescribed(Motion::ConstantVelocity {
        start: Vec3::zeros(),
        velocity: Vec3::new(0.8, 0.0, -0.1),
    });
    let e = System::new(&m).unwrap_err().to_string();
    assert!(e.contains("horizontal"), "{e}");
    let mut m = point_tow(InitialCondition::SteadyTow);
    m.environment.current = Current::Uniform(Vec3::new(0.1, 0.0, 0.0));
    assert!(System::new(&m).is_ok(), "a current is steady too");
    let m = point_tow(InitialCondition::Statics);
    assert_eq!(System::new(&m).unwrap().tow_velocity, Vec3::zeros());
}

/// Body statics from a slack start: the depressor of (d) placed 30 m from the ship on its 100 m
/// tether, which hangs slack between them. Newton on the pose has no slope along the slack line;
/// the pseudo-dynamic relaxation (`statics::relax_with_bodies`) brings the body to the tow
/// first. The result is the steady tow found from a taut start, to the statics tolerance
/// (1e-6 relative).
#[test]
fn body_statics_from_a_slack_start() {
    let (mass, volume) = DEPRESSOR;
    let d = DEPRESSOR_DRAG;
    let body = |position: Vec3| Body {
        position,
        displacement: Displacement::Submerged { volume },
        quadratic_drag: Vec6::new(d[0], d[1], d[2], 0.2, 0.3, 0.3),
        thrust: Thrust::None,
        ..Body {
            mass,
            inertia: Mat3::from_diagonal(&Vec3::new(30.0, 60.0, 60.0)),
            ..vehicle_body()
        }
    };
    let taut = body_tow(
        body(Vec3::new(-45.0, 0.0, -88.0)),
        tether(),
        ELEMENTS,
        InitialCondition::SteadyTow,
    );
    let slack = body_tow(
        body(Vec3::new(-20.0, 0.0, -22.0)),
        tether(),
        ELEMENTS,
        InitialCondition::SteadyTow,
    );
    let (_, _, a) = steady(&taut);
    let (_, _, b) = steady(&slack);
    let diff = b.difference(&a);
    eprintln!(
        "slack start: {diff:.2e} from the taut start's steady tow, pitch {:.2e} rad",
        (a.pitch - b.pitch).abs()
    );
    assert!(diff < 1e-6, "{diff:.3e}");
    assert!((a.pitch - b.pitch).abs() < 1e-6);
}
