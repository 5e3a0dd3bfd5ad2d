//! `dg` elastic catenary: the steady state of a line hanging in water between two anchors
//! (Newton on the DG equations, [`steady_state`]) has the end tensions of the closed form
//! within 0.1 % (SPEC §7), and is a rest state of the dynamics.
//!
//! Line: 110 m, γ0 = 50 kg/m, d = 0.1 m, EA = 10 MN, from A = (0, 0, −100) to
//! B = (80, 0, −50); N = 8, P = 3; Morison drag Cdn 1.2, Cdt 0.01 and added mass 1 / 0.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use hawser::physics::environment::Environment;
use hawser::physics::hydrodynamics::DragModel;
use hawser::statics::catenary;

#[test]
fn catenary_end_tensions_match_the_closed_form() {
    let mut lt = beam_type(50.0, 1.0e7, 0.0);
    lt.diameter = 0.1;
    lt.compression = false;
    lt.drag = DragModel::Morison {
        normal: 1.2,
        tangential: 0.01,
    };
    lt.normal_added_mass = 1.0;
    let env = Environment::default();
    let w = (lt.mass_per_length - env.water_density * lt.area()) * env.gravity;
    let (length, a, b) = (
        110.0,
        Vec3::new(0.0, 0.0, -100.0),
        Vec3::new(80.0, 0.0, -50.0),
    );
    let cat = catenary::solve(b.x - a.x, b.z - a.z, length, w, 1.0e7, false).unwrap();
    for (elements, order) in [(8, 3), (4, 6)] {
        let line = single(
            lt.clone(),
            length,
            elements,
            order,
            [EndCondition::PINNED_JOINT, EndCondition::PINNED_JOINT],
        );
        let mut state = vec![0.0; line.state_len()];
        // Initial guess: the closed-form catenary of a 20 % heavier line.
        let guess = catenary::solve(b.x - a.x, b.z - a.z, length, 1.2 * w, 1.0e7, false).unwrap();
        line.project(&mut state, |s| {
            let (x, z) = guess.position(s);
            let v = guess.vertical_a + 1.2 * w * s;
            let t = guess.horizontal.hypot(v);
            let q = Vec3::new(guess.horizontal, 0.0, v) * ((1.0 + t / 1.0e7) / t);
            (a + Vec3::new(x, 0.0, z), q, Vec3::zeros())
        });
        let ends = fixed_ends(a, b);
        let out = steady_state(&line, &env, 0.0, &mut state, &ends, 1e-12, 40).unwrap();
        let mut ws = DgWorkspace::new(&line);
        let mut rate = vec![0.0; line.state_len()];
        let loads = line.rhs(&env, 0.0, &state, &ends, &mut rate, &mut ws);
        let (ta, tb) = (loads[0].force.norm(), loads[1].force.norm());
        let (ea, eb) = (ta / cat.tension_a() - 1.0, tb / cat.tension_b() - 1.0);
        // Shape: the positions against the closed form.
        let mut shape: Real = 0.0;
        for k in 0..=50 {
            let s = length * k as Real / 50.0;
            let (x, z) = cat.position(s);
            shape =
                shape.max((line.position(&state, &ends, s) - (a + Vec3::new(x, 0.0, z))).norm());
        }
        println!(
            "N {elements} P {order}: {} Newton iterations; T_A {ta:.3} N vs {:.3} ({:+.2e}), \
             T_B {tb:.3} N vs {:.3} ({:+.2e}); shape error {shape:.2e} m",
            out.iterations,
            cat.tension_a(),
            ea,
            cat.tension_b(),
            eb
        );
        assert!(ea.abs() < 1e-3 && eb.abs() < 1e-3);
        assert!(shape < 1e-3);
        let speed0 = (0..=20)
            .map(|k| line.velocity(&state, length * k as Real / 20.0).norm())
            .fold(0.0, Real::max);
        println!(
            "  largest speed of the steady state: {speed0:.2e} m/s; residual {:.2e}",
            out.residual
        );
        // A rest state of the dynamics: one second of SSP-RK3 leaves it in place. (Its ν is
        // not zero: the steady state of the Lax–Friedrichs q equation balances the q jumps
        // by ν = O(λ [q]); see docs/dg.md.)
        let steady = state.clone();
        let dt = stable_step(&line, 0.8);
        let mut stepper = DgStepper::new(&line);
        let mut t = 0.0;
        while t < 1.0 {
            stepper.step(&line, &env, t, dt, &mut state, &mut ws, |_| ends);
            t += dt;
        }
        let moved = (0..=20)
            .map(|k| {
                let s = length * k as Real / 20.0;
                (line.position(&state, &ends, s) - line.position(&steady, &ends, s)).norm()
            })
            .fold(0.0, Real::max);
        println!("  largest displacement after 1 s of dynamics: {moved:.2e} m");
        assert!(moved < 1e-6, "{moved}");
    }
}
