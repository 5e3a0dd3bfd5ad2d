//! End loads of `dg` lines (DG paper Table 1): a point force at a free end is carried as
//! uniform tension to the anchor, and the moment applied at the end of the ring beam comes
//! back as the clamped end's reaction.

mod dg_common;
use dg_common::*;
use hawser::formulation::dg::*;
use hawser::math::Vec3;

#[test]
fn point_force_is_carried_to_the_anchor() {
    let (ea, force) = (1.0e5, 1.0e3);
    let line = single(
        beam_type(5.0, ea, 10.0),
        20.0,
        4,
        3,
        [EndCondition::PINNED_JOINT, EndCondition::POINT_LOAD],
    );
    let env = vacuum();
    let mut state = vec![0.0; line.state_len()];
    // Initial guess stretched by half the expected strain: at zero tension a line pinned at one
    // end turns freely about the pin and the Jacobian is singular.
    let guess = 20.0 * (1.0 + 0.5 * force / ea);
    line.straight(&mut state, Vec3::zeros(), Vec3::new(guess, 0.0, 0.0));
    let mut ends = fixed_ends(Vec3::zeros(), Vec3::zeros());
    ends[1].force = Vec3::new(force, 0.0, 0.0);
    steady_state(&line, &env, 0.0, &mut state, &ends, 1e-13, 20).unwrap();
    let mut ws = DgWorkspace::new(&line);
    let mut rate = vec![0.0; line.state_len()];
    let loads = line.rhs(&env, 0.0, &state, &ends, &mut rate, &mut ws);
    let tip = line.position(&state, &ends, 20.0);
    let mid = line.channels(&state, &rate, &ws, 10.0);
    println!(
        "anchor force {:?}, tip {tip:?}, mid tension {}",
        loads[0].force, mid.tension
    );
    // On the anchor: pulled towards +x by the line.
    assert!((loads[0].force - Vec3::new(force, 0.0, 0.0)).norm() < 1e-6 * force);
    assert!((mid.tension - force).abs() < 1e-6 * force);
    assert!((tip.x - 20.0 * (1.0 + force / ea)).abs() < 1e-9);
}

#[test]
fn ring_beam_clamp_takes_the_end_moment() {
    let line = single(
        beam_type(10.0, 100.0, 1.0),
        2.0 * std::f64::consts::PI,
        8,
        4,
        [EndCondition::CLAMPED, EndCondition::FREE],
    );
    let env = vacuum();
    let mut state = vec![0.0; line.state_len()];
    line.project(&mut state, |s| {
        (
            Vec3::new(s.sin(), 0.0, s.cos() - 1.0),
            Vec3::new(s.cos(), 0.0, -s.sin()),
            Vec3::zeros(),
        )
    });
    let mut ends = fixed_ends(Vec3::zeros(), Vec3::zeros());
    ends[1].moment = Vec3::new(0.0, 1.0, 0.0);
    steady_state(&line, &env, 0.0, &mut state, &ends, 1e-13, 30).unwrap();
    let mut ws = DgWorkspace::new(&line);
    let mut rate = vec![0.0; line.state_len()];
    let loads = line.rhs(&env, 0.0, &state, &ends, &mut rate, &mut ws);
    let mid = line.channels(&state, &rate, &ws, 2.0);
    println!(
        "clamp: force {:?}, moment {:?}; at s = 2: curvature {:.6}, moment {:?}, shear {:?}",
        loads[0].force,
        loads[0].moment,
        mid.curvature.norm(),
        mid.moment,
        mid.shear
    );
    // The line turns the clamp with the applied moment and does not pull it.
    assert!((loads[0].moment - Vec3::new(0.0, 1.0, 0.0)).norm() < 1e-4);
    assert!(loads[0].force.norm() < 1e-4);
    // Uniform curvature 1/R = 1, moment EI κ = 1, no shear.
    assert!((mid.curvature.norm() - 1.0).abs() < 1e-4);
    assert!((mid.moment - Vec3::new(0.0, 1.0, 0.0)).norm() < 1e-4);
    assert!(mid.shear.norm() < 1e-3);
}
