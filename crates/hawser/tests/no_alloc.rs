//! No allocation inside the time loop (SPEC: "all scratch of the right-hand side, sized once").
//!
//! A counting global allocator wraps the system allocator. It counts allocations (alloc,
//! alloc_zeroed, realloc) made by the current thread while a thread-local flag is on, so the
//! test harness's other threads cannot disturb the count. After a few warm-up steps, 1000
//! calls of `Simulation::step` and 1000 of `Simulation::evaluate` must allocate nothing, for:
//! a consistent-mass line with a free point mass; the same with lumped mass; and two lines
//! sharing a free point (the dense shared-point solve) with a prescribed, time-series end, in
//! water with current, an irregular sea, drag, added mass and seabed contact, under each
//! scheme (generalized-α with adaptive steps); the same with a fixed sphere and a moving cylinder in contact with a line; and the
//! same with one `hermite` line with bending (and the obstacles), the same with both lines on
//! winches, and with one `dg` line; the same over a sloping bed and over a grid of depths,
//! with a box body resting on the bed (dg and fe). And a `Session` with a coupled fairlead, an
//! observer that reads every channel and line sample (and keeps range graphs), and repeated
//! coupling intervals: 290 intervals of a
//! step the interval does not divide, allocation-free (RK4 and the three-level scheme).

mod alloc_count;
mod common;
use alloc_count::allocations_in;
use common::*;
use hawser::analysis::obstacles::{ObstacleLoad, obstacle_forces};
use hawser::math::Vec3;
use hawser::model::*;
use hawser::physics::environment::Current;
use hawser::physics::obstacles::{Obstacle, ObstacleDamping, ObstacleShape};
use hawser::physics::seabed::{Bathymetry, SeabedGrid};
use hawser::physics::waves::{IrregularSea, SeaState, Spectrum, Stretching, WaveSpec, Waves};
use hawser::simulation::Simulation;
use hawser::system::System;

fn check(name: &str, model: &Model, scheme: Scheme) {
    let system = System::new(model).unwrap();
    let y = system.straight_state();
    // Generalized-α has no stability limit: its steps are sized from RK4's.
    let dt = 0.5
        * system
            .stable_step(scheme)
            .0
            .min(system.stable_step(Scheme::Rk4).0);
    let mut settings = Settings {
        scheme,
        ..fixed_step_settings(dt, scheme)
    };
    if scheme == Scheme::ThreeLevel {
        // Automatic, variable steps: the step is chosen again every output interval.
        settings.time_step = TimeStep::Auto;
        settings.output_interval = 20.0 * dt;
    }
    if scheme == Scheme::GeneralizedAlpha {
        // Adaptive steps (error estimate, refused steps, landing on output times) with a
        // tolerance tight enough that the controller and the Jacobian refreshes both act.
        settings.time_step = TimeStep::Auto;
        settings.tolerance = 1e-6;
        settings.output_interval = 20.0 * dt;
    }
    let mut sim = Simulation::new(&system, &settings, y).unwrap();
    for _ in 0..10 {
        sim.step().unwrap();
        sim.evaluate().unwrap();
    }
    // The counter itself must work: a Vec allocates.
    assert_eq!(
        allocations_in(|| drop(std::hint::black_box(vec![1u8; 16]))),
        1
    );
    let steps = allocations_in(|| {
        for _ in 0..1000 {
            sim.step().unwrap();
        }
    });
    // An evaluation at an unchanged state is a no-op: step between them so that each one
    // evaluates (the count then includes 1000 more steps).
    let evaluations = allocations_in(|| {
        for _ in 0..1000 {
            sim.step().unwrap();
            sim.evaluate().unwrap();
        }
    });
    eprintln!(
        "{name} ({scheme:?}): {steps} allocations in 1000 steps, {evaluations} in 1000 evaluations (t = {:.4} s)",
        sim.time()
    );
    // Zero exactly: the time loop is specified to allocate nothing, whatever the count.
    assert_eq!(steps, 0, "{name}: Simulation::step allocated");
    assert_eq!(evaluations, 0, "{name}: Simulation::evaluate allocated");
}

#[test]
fn time_loop_does_not_allocate() {
    let top = Vec3::new(0.0, 0.0, -10.0);
    for mass_matrix in [MassMatrix::Consistent, MassMatrix::Lumped] {
        let mut model = single_line(
            line_type(0.05, 20.0, 1.0e7),
            50.0,
            20,
            fixed("top", top),
            free("weight", top + Vec3::new(5.0, 0.0, -49.0), 200.0, 0.01),
            mass_matrix,
        );
        model.environment.current = Current::Uniform(Vec3::new(0.5, 0.2, 0.0));
        for scheme in [Scheme::Rk4, Scheme::ThreeLevel, Scheme::GeneralizedAlpha] {
            check(
                &format!("{mass_matrix:?} line + free point, {scheme:?}"),
                &model,
                scheme,
            );
        }
    }

    // Two lines meeting at a free buoy: an anchor on the seabed, a fairlead moving by a time
    // series; current profile, waves, drag and added mass in water.
    let mut model = single_line(
        line_type(0.08, 40.0, 3.0e8),
        120.0,
        30,
        fixed("anchor", Vec3::new(-100.0, 0.0, -60.0)),
        free("buoy", Vec3::new(0.0, 0.0, -20.0), 500.0, 1.0),
        MassMatrix::Consistent,
    );
    model.environment.depth = 60.0;
    model.environment.current = Current::Profile {
        z: vec![-60.0, 0.0],
        velocity: vec![Vec3::zeros(), Vec3::new(1.0, 0.0, 0.0)],
    };
    model.environment.waves = Waves::new(
        &WaveSpec {
            sea: SeaState::Irregular(IrregularSea {
                spectrum: Spectrum::Jonswap {
                    significant_height: 2.0,
                    peak_period: 8.0,
                    peak_enhancement: 3.3,
                },
                direction: 0.5,
                spreading: Some(4.0),
                seed: 3,
                components: 50,
                frequency_range: (0.4, 4.0),
            }),
            ramp_time: 0.0,
            stretching: Stretching::Wheeler,
        },
        60.0,
        model.environment.gravity,
    )
    .unwrap();
    model.points.push(Point {
        name: "fairlead".into(),
        position: Vec3::new(30.0, 0.0, -5.0),
        kind: PointKind::Prescribed(Motion::TimeSeries {
            times: vec![0.0, 1.0, 2.0, 100.0],
            positions: vec![
                Vec3::new(30.0, 0.0, -5.0),
                Vec3::new(30.5, 0.0, -5.0),
                Vec3::new(30.0, 0.2, -5.0),
                Vec3::new(30.0, 0.0, -5.0),
            ],
        }),
    });
    model.lines.push(Line {
        name: "upper".into(),
        sections: vec![Section {
            line_type: 0,
            length: 33.0,
            elements: 10,
            order: 4,
        }],
        formulation: Formulation::Fe,
        mass_matrix: MassMatrix::Lumped,
        strain_measure: Default::default(),
        modal_filter: hawser::formulation::dg::line::DEFAULT_MODAL_FILTER,
        shock_filter: 0.0,
        clamp: [None; 2],
        end_a: LineEnd::Point(1),
        end_b: LineEnd::Point(2),
        winch: None,
    });
    for scheme in [
        Scheme::Rk4,
        Scheme::SspRk3,
        Scheme::ThreeLevel,
        Scheme::GeneralizedAlpha,
    ] {
        check("two lines on a shared buoy", &model, scheme);
    }
    // The same with the waves at the static position (the cache's ring refilled as time
    // advances) and a current table against time.
    let mut tabled = model.clone();
    tabled.environment.wave_kinematics =
        hawser::physics::static_kinematics::WaveKinematicsMethod::StaticPosition {
            sample_interval: 0.01,
        };
    tabled.environment.current = Current::Table {
        z: vec![-60.0, 0.0],
        time: vec![0.0, 0.05, 10.0],
        velocity: vec![
            Vec3::zeros(),
            Vec3::new(0.2, 0.0, 0.0),
            Vec3::zeros(),
            Vec3::new(1.0, 0.3, 0.0),
            Vec3::new(0.1, 0.0, 0.0),
            Vec3::new(0.5, 0.0, 0.0),
        ],
    };
    for scheme in [Scheme::Rk4, Scheme::SspRk3] {
        check(
            "two lines, static-position waves, current table",
            &tabled,
            scheme,
        );
    }

    // Obstacles in contact with the lower line: a fixed sphere under its middle and a
    // horizontal cylinder moving by a time series under its eighth node, with friction.
    let sphere = Obstacle {
        name: "rock".into(),
        shape: ObstacleShape::Sphere { radius: 1.0 },
        motion: Motion::Fixed {
            position: Vec3::new(-50.0, 0.0, -41.0),
        },
        stiffness: 1.0e4,
        damping: ObstacleDamping::Ratio(1.0),
        friction_coefficient: 0.3,
        friction_velocity: 0.1,
    };
    let pipe = Obstacle {
        name: "pipe".into(),
        shape: ObstacleShape::Cylinder {
            radius: 0.6,
            axis: Vec3::y(),
            length: Some(4.0),
        },
        motion: Motion::TimeSeries {
            times: vec![0.0, 1.0, 100.0],
            positions: vec![
                Vec3::new(-73.3, 0.0, -49.8),
                Vec3::new(-73.1, 0.0, -49.8),
                Vec3::new(-72.0, 0.0, -49.8),
            ],
        },
        damping: ObstacleDamping::PerLength(100.0),
        ..sphere.clone()
    };
    model.environment.obstacles = vec![sphere, pipe];
    {
        // Both touch the line's straight start.
        let system = System::new(&model).unwrap();
        let mut ws = system.workspace();
        let y = system.straight_state();
        let mut dydt = vec![0.0; y.len()];
        system.rhs(0.0, &y, &mut dydt, &mut ws).unwrap();
        let mut loads = [ObstacleLoad::default(); 2];
        obstacle_forces(&system, &ws, 0.0, &mut loads);
        assert!(loads.iter().all(|l| l.contact_length > 0.0), "{loads:?}");
    }
    for scheme in [
        Scheme::Rk4,
        Scheme::SspRk3,
        Scheme::ThreeLevel,
        Scheme::GeneralizedAlpha,
    ] {
        check("two lines on a shared buoy, with obstacles", &model, scheme);
    }

    // The lower line in cubic Hermite elements with bending: the banded solve with a free
    // end and the three-level scheme's exact mass stages.
    model.lines[0].formulation = Formulation::Hermite;
    model.line_types[0].bending_stiffness = 1.0e3;
    for scheme in [
        Scheme::Rk4,
        Scheme::SspRk3,
        Scheme::ThreeLevel,
        Scheme::GeneralizedAlpha,
    ] {
        check("hermite and fe lines on a shared buoy", &model, scheme);
    }

    // Both lines on winches (hauling in, then paying out, with ramps within the steps
    // checked): the rescaled meshes are updated in place at every evaluation.
    let winch = Winch {
        end: WinchEnd::A,
        stages: vec![
            WinchStage {
                duration: 0.02,
                payout_rate: -0.5,
            },
            WinchStage {
                duration: 0.02,
                payout_rate: 0.5,
            },
        ],
        ramp_time: 0.01,
        minimum_length: 0.0,
    };
    model.lines[0].winch = Some(winch.clone());
    model.lines[1].winch = Some(winch);
    for scheme in [
        Scheme::Rk4,
        Scheme::SspRk3,
        Scheme::ThreeLevel,
        Scheme::GeneralizedAlpha,
    ] {
        check("hermite and fe lines on winches", &model, scheme);
    }
    model.lines[0].winch = None;
    model.lines[1].winch = None;

    // The lower line in discontinuous Galerkin (P = 4) with bending: its end traction on
    // the shared buoy (explicit coupling) and the outputs it fills. Runge–Kutta only (the
    // three-level scheme refuses dg).
    model.lines[0].formulation = Formulation::Dg;
    for scheme in [Scheme::Rk4, Scheme::SspRk3] {
        check("dg and fe lines on a shared buoy", &model, scheme);
    }

    // The same over a sloping bed and over a grid of depths (the bed's height and normal
    // looked up at every contact), with a box body resting on the bed (its contact summed
    // over its surface patches): the dg line, then both lines in fe.
    let mut sloped = model.clone();
    sloped.environment.bathymetry = Bathymetry::Plane {
        gradient: [0.02, 0.01],
    };
    let mut crate_body = Body::new(
        "crate",
        8000.0,
        hawser::math::Mat3::from_diagonal(&Vec3::new(3000.0, 3000.0, 5300.0)),
    );
    crate_body.displacement = Displacement::Box {
        length: 2.0,
        breadth: 2.0,
        height: 1.0,
    };
    // Its base 2 cm into the bed at (20, 10), where the plane is at −60 + 0.4 + 0.1.
    crate_body.position = Vec3::new(20.0, 10.0, -59.5 + 0.5 - 0.02);
    sloped.bodies.push(crate_body);
    let mut grid = sloped.clone();
    grid.environment.bathymetry = Bathymetry::Grid(
        SeabedGrid::new(
            vec![-150.0, 0.0, 150.0],
            vec![-50.0, 50.0],
            vec![-61.0, -59.0, -59.0, -61.0, -59.5, -59.5],
        )
        .unwrap(),
    );
    // Its base 2 cm into the grid's bed at (20, 10).
    let bed = grid.environment.seabed_at(20.0, 10.0).z;
    grid.bodies[0].position.z = bed + 0.5 - 0.02;
    for line in [Formulation::Dg, Formulation::Fe] {
        sloped.lines[0].formulation = line;
        grid.lines[0].formulation = line;
        check(
            &format!("{line:?} and fe lines, sloping bed"),
            &sloped,
            Scheme::Rk4,
        );
        check(
            &format!("{line:?} and fe lines, grid bed"),
            &grid,
            Scheme::Rk4,
        );
    }
}

/// A pinned body (its pin on a prescribed 6-DOF table, turning freely) holding a line to an
/// anchor: the pin's kinematics read at every stage, its rows held in the coupled solve and in
/// generalized-α's Newton iterations, the pin put back into the state after every step.
#[test]
fn pinned_body_time_loop_does_not_allocate() {
    let top = Vec3::new(0.0, 0.0, -10.0);
    let mut model = single_line(
        line_type(0.05, 20.0, 1.0e7),
        50.0,
        20,
        fixed("anchor", top + Vec3::new(30.0, 0.0, -42.0)),
        Point {
            name: "lug".into(),
            position: Vec3::zeros(),
            kind: PointKind::Body {
                body: 0,
                offset: Vec3::new(0.0, 0.0, -2.0),
            },
        },
        MassMatrix::Consistent,
    );
    let times: Vec<f64> = (0..=200).map(|i| -1.0 + 0.05 * i as f64).collect();
    let positions: Vec<Vec3> = times
        .iter()
        .map(|t| top + Vec3::new(0.5 * (1.3 * t).sin(), 0.0, 0.2 * (0.7 * t).sin()))
        .collect();
    let motion = RigidMotion::TimeSeries(
        RigidTimeSeries::new(times.clone(), &positions, &vec![[0.0; 3]; times.len()]).unwrap(),
    );
    model.bodies.push(Body {
        position: top,
        centre_of_gravity: Vec3::new(0.0, 0.0, -1.0),
        kind: BodyKind::Pinned(Pin::Prescribed(motion)),
        ..Body::new(
            "arm",
            500.0,
            hawser::math::Mat3::from_diagonal(&Vec3::new(200.0, 200.0, 50.0)),
        )
    });
    for scheme in [Scheme::Rk4, Scheme::GeneralizedAlpha] {
        check("a pinned body on a prescribed pin", &model, scheme);
    }
    // The same arm pinned to a point 1 m below the origin of a free float.
    model.bodies[0].kind = BodyKind::Pinned(Pin::Body {
        body: 1,
        point: Vec3::new(0.0, 0.0, -1.0),
    });
    model.bodies.push(Body {
        position: top + Vec3::new(0.0, 0.0, 1.0),
        ..Body::new(
            "float",
            2000.0,
            hawser::math::Mat3::from_diagonal(&Vec3::new(800.0, 800.0, 400.0)),
        )
    });
    // (generalized-α refuses a body pinned to a body: SchemeCannotStepPinOnBody)
    for scheme in [Scheme::Rk4, Scheme::SspRk3] {
        check("a body pinned to a free body", &model, scheme);
    }
}

/// Reads every output channel and every line's samples at each sample, into buffers sized
/// once: what a writer does.
struct Reader {
    values: Vec<f64>,
    tension: f64,
    ranges: Vec<hawser::analysis::range_graph::RangeGraph>,
}

impl hawser::session::Observer for Reader {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        for (i, v) in self.values.iter_mut().enumerate() {
            *v = view.channel(i);
        }
        for l in 0..view.system.lines.len() {
            for n in view.line_samples(l) {
                self.tension = self.tension.max(n.tension);
            }
            self.ranges[l].push(view, l, view.time);
        }
        Ok(())
    }

    fn rewind(&mut self, _: f64) -> Result<(), hawser::session::ObserverError> {
        Ok(())
    }
}

#[test]
fn session_stepping_coupling_and_observers_do_not_allocate() {
    let top = Vec3::new(0.0, 0.0, -10.0);
    let mut model = single_line(
        line_type(0.05, 20.0, 1.0e7),
        50.0,
        20,
        fixed("anchor", top + Vec3::new(30.0, 0.0, -35.0)),
        Point {
            name: "fairlead".into(),
            position: top,
            kind: PointKind::Coupled,
        },
        MassMatrix::Consistent,
    );
    model.settings.output_interval = 0.01;
    for scheme in [Scheme::Rk4, Scheme::ThreeLevel] {
        model.settings.scheme = scheme;
        let mut session = hawser::Session::new(model.clone()).unwrap();
        let channels = session.channels().len();
        let ranges = (session.system().lines.iter())
            .map(|l| hawser::analysis::range_graph::RangeGraph::new(l.nodes()))
            .collect();
        session.attach(Reader {
            values: vec![0.0; channels],
            tension: 0.0,
            ranges,
        });
        let p = session.coupled_points()[0];
        let dt_c = 0.013;
        let position = |t: f64| top + Vec3::new(0.5 * (1.3 * t).sin(), 0.0, 0.0);
        let velocity = |t: f64| Vec3::new(0.65 * (1.3 * t).cos(), 0.0, 0.0);
        let interval = |session: &mut hawser::Session, k: usize| {
            let t1 = k as f64 * dt_c;
            session
                .set_point_kinematics(p, t1, position(t1), velocity(t1), None)
                .unwrap();
            session.advance_to(t1).unwrap();
            if k % 7 == 0 {
                // A host correcting its prediction: the interval again.
                session
                    .set_point_kinematics(p, t1, position(t1), velocity(t1), None)
                    .unwrap();
                session.advance_to(t1).unwrap();
            }
            std::hint::black_box(session.point_reaction(p).unwrap());
        };
        for k in 1..=10 {
            interval(&mut session, k);
        }
        let count = allocations_in(|| {
            for k in 11..=300 {
                interval(&mut session, k);
            }
        });
        eprintln!(
            "{scheme:?}: {count} allocations in 290 coupling intervals to t = {:.3} s",
            session.time()
        );
        assert_eq!(count, 0, "{scheme:?}: the coupled session allocated");
    }
}

/// A session with line failures steps, releases and repeats coupling intervals across the
/// release without allocating: a tension trigger that stays pending (the end's tension is
/// evaluated after every step) and a time trigger at 2 s, inside the counted intervals, some
/// of which a host repeats (the release is taken back and made again). Under RK4, the
/// three-level scheme and generalized-α (adaptive), whose history restarts at the release.
#[test]
fn session_with_failures_does_not_allocate() {
    for scheme in [Scheme::Rk4, Scheme::ThreeLevel, Scheme::GeneralizedAlpha] {
        session_with_failures(scheme);
    }
}

fn session_with_failures(scheme: Scheme) {
    let top = Vec3::new(0.0, 0.0, -10.0);
    let mut model = single_line(
        line_type(0.05, 20.0, 1.0e7),
        50.0,
        20,
        fixed("anchor", top + Vec3::new(30.0, 0.0, -35.0)),
        Point {
            name: "fairlead".into(),
            position: top,
            kind: PointKind::Coupled,
        },
        MassMatrix::Consistent,
    );
    model.settings.output_interval = 0.01;
    model.settings.scheme = scheme;
    model.failures = vec![
        LineFailure {
            line: 0,
            end: End::A,
            joined: vec![],
            time: None,
            tension: Some(1e9),
        },
        LineFailure {
            line: 0,
            end: End::B,
            joined: vec![],
            time: Some(2.0),
            tension: None,
        },
    ];
    let mut session = hawser::Session::new(model).unwrap();
    let p = session.coupled_points()[0];
    let dt_c = 0.013;
    let position = |t: f64| top + Vec3::new(0.5 * (1.3 * t).sin(), 0.0, 0.0);
    let velocity = |t: f64| Vec3::new(0.65 * (1.3 * t).cos(), 0.0, 0.0);
    let interval = |session: &mut hawser::Session, k: usize| {
        let t1 = k as f64 * dt_c;
        session
            .set_point_kinematics(p, t1, position(t1), velocity(t1), None)
            .unwrap();
        session.advance_to(t1).unwrap();
        if k.is_multiple_of(7) {
            session
                .set_point_kinematics(p, t1, position(t1), velocity(t1), None)
                .unwrap();
            session.advance_to(t1).unwrap();
        }
        std::hint::black_box(session.point_reaction(p).unwrap());
    };
    for k in 1..=10 {
        interval(&mut session, k);
    }
    let count = allocations_in(|| {
        for k in 11..=300 {
            interval(&mut session, k);
        }
    });
    let events = session.failure_events();
    eprintln!("{scheme:?}: {count} allocations in 290 coupling intervals, releases {events:?}");
    assert_eq!(events.len(), 1);
    assert!(session.time() > events[0].release.time);
    assert_eq!(count, 0, "{scheme:?}: the session with failures allocated");
}
