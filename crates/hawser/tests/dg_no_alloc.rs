//! No allocation in the `dg` time loop: after warm-up, 200 SSP-RK3 steps and 200 right-hand
//! sides of a two-section line with bending, bending damping, axial damping, drag, added
//! mass, current, seabed contact, a moving obstacle and mixed orders allocate nothing.

mod alloc_count;
mod dg_common;
use alloc_count::allocations_in;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use hawser::model::Motion;
use hawser::physics::environment::{Current, Environment};
use hawser::physics::hydrodynamics::DragModel;
use hawser::physics::material::AxialDamping;
use hawser::physics::obstacles::{Obstacle, ObstacleShape};

#[test]
fn dg_time_loop_does_not_allocate() {
    let mut a = beam_type(50.0, 1.0e7, 1.0e3);
    a.diameter = 0.1;
    a.bending_damping = 1.0;
    a.axial_damping = AxialDamping::Coefficient(1.0e4);
    a.drag = DragModel::Morison {
        normal: 1.2,
        tangential: 0.02,
    };
    a.normal_added_mass = 1.0;
    a.tangential_added_mass = 0.1;
    a.compression = false;
    let mut b = a.clone();
    b.mass_per_length = 20.0;
    let mut line = DgLine::new(
        &[
            DgSectionSpec {
                line_type: a,
                length: 60.0,
                elements: 4,
                order: 4,
            },
            DgSectionSpec {
                line_type: b,
                length: 60.0,
                elements: 3,
                order: 6,
            },
        ],
        [EndCondition::CLAMPED, EndCondition::PRESCRIBED_PINNED],
    );
    // The shock sensor's path as well (docs/dg.md, Discretisation item 7).
    line.shock_filter = 0.25;
    // A moving sphere pressing on the line's middle (contact and friction at its points).
    let env = Environment {
        depth: 100.0,
        current: Current::Uniform(Vec3::new(0.5, 0.0, 0.0)),
        obstacles: vec![Obstacle {
            name: "rock".into(),
            shape: ObstacleShape::Sphere { radius: 2.0 },
            motion: Motion::ConstantVelocity {
                start: Vec3::new(50.0, 0.0, -62.0),
                velocity: Vec3::new(0.0, 0.1, 0.0),
            },
            stiffness: 1.0e4,
            friction_coefficient: 0.3,
            friction_velocity: 0.1,
            ..Default::default()
        }],
        ..Default::default()
    };
    let (pa, pb) = (Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 0.0, -20.0));
    let mut state = vec![0.0; line.state_len()];
    line.straight(&mut state, pa, pb);
    let ends = |t: Real| {
        let mut e = fixed_ends(pa, pb);
        e[1].velocity = Vec3::new(0.0, 0.0, 0.5 * t.cos());
        e
    };
    let mut ws = DgWorkspace::new(&line);
    let mut st = DgStepper::new(&line);
    let mut rate = vec![0.0; line.state_len()];
    let dt = stable_step(&line, 0.8);
    let mut t = 0.0;
    for _ in 0..5 {
        st.step(&line, &env, t, dt, &mut state, &mut ws, ends);
        t += dt;
    }
    let n = allocations_in(|| {
        for _ in 0..200 {
            st.step(&line, &env, t, dt, &mut state, &mut ws, ends);
            t += dt;
            line.rhs(&env, t, &state, &ends(t), &mut rate, &mut ws);
        }
    });
    assert!(state.iter().all(|x| x.is_finite()));
    assert_eq!(n, 0, "{n} allocations in the dg time loop");
}
