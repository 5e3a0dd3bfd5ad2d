//! Static equilibrium of free rigid bodies: Newton on their poses around the lines' statics.
//!
//! For given poses the lines (and free points) are solved with the bodies held
//! ([`System::statics_twin_at`]); the residual of a body is its own static load (weight,
//! buoyancy, current drag, thrust, wind, about its origin; [`crate::model::Body::loads`] at
//! rest) plus the loads of the lines at the points on it. Newton updates the 6 pose unknowns
//! per body (origin position and a rotation vector applied on the left of the orientation)
//! with a forward-difference Jacobian and a Levenberg–Marquardt shift, so that a direction
//! without static stiffness (a cage's yaw on a single bridle) stays where it is. Rotations
//! move at most 0.2 rad per iteration (to the nearby stable pose, not an inverted one).
//!
//! Start the bodies where their lines are taut: where a line is slack the residual has no
//! slope along it and Newton cannot move the body (reported as not converged, with a hint).

use super::newton::{StaticOptions, StaticSolution, evaluate, solve};
use crate::error::StaticsError;
use crate::math::{Quat, Real, Vec3};
use crate::model::{PointKind, RigidKinematics};
use crate::system::System;
use nalgebra::{DMatrix, DVector};

/// Net static load [force; moment about the origin] on each free body with the lines solved
/// for the bodies held at `poses`, and the twin's solution.
fn residual(
    system: &System,
    poses: &[RigidKinematics],
    options: &StaticOptions,
) -> Result<(DVector<Real>, System, StaticSolution), StaticsError> {
    let twin = system.statics_twin_at(poses);
    let sol = solve(&twin, None, options)?;
    let mut ws = twin.workspace();
    evaluate(&twin, &sol.state, &mut ws);
    let mut r = DVector::zeros(6 * system.free_bodies.len());
    for (f, &b) in system.free_bodies.iter().enumerate() {
        let k = RigidKinematics::at_rest(poses[b].position, poses[b].orientation);
        let own = system.bodies[b].body.loads(&k, &system.environment, 0.0);
        let (mut force, mut moment) = (own.force, own.moment);
        for (li, l) in twin.lines.iter().enumerate() {
            for (end_b, p) in [(false, l.end_a), (true, l.end_b)] {
                if matches!(twin.points[p].kind, PointKind::Body { body, .. } if body == b) {
                    let fl = twin.end_force(&ws, li, end_b);
                    force += fl;
                    moment += (ws.points[p].position - k.position).cross(&fl);
                }
            }
        }
        for i in 0..3 {
            r[6 * f + i] = force[i];
            r[6 * f + 3 + i] = moment[i];
        }
    }
    Ok((r, twin, sol))
}

/// Poses moved by `delta` (per free body: translation [m], rotation vector [rad]).
fn moved(
    system: &System,
    poses: &[RigidKinematics],
    delta: &DVector<Real>,
) -> Vec<RigidKinematics> {
    let mut out = poses.to_vec();
    for (f, &b) in system.free_bodies.iter().enumerate() {
        let d = |i| Vec3::new(delta[6 * f + i], delta[6 * f + i + 1], delta[6 * f + i + 2]);
        out[b].position += d(0);
        out[b].orientation = Quat::from_scaled_axis(d(3)) * out[b].orientation;
    }
    out
}

/// Solves the statics of a system with free bodies (see the module docs). Starts from the
/// bodies' initial poses; each iteration costs 6 + 1 line statics per body.
pub fn solve_with_bodies(
    system: &System,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    let mut poses: Vec<RigidKinematics> = system
        .bodies
        .iter()
        .map(|b| b.initial_kinematics())
        .collect();
    let n = 6 * system.free_bodies.len();
    // Scales: the bodies' weights [N] and sizes [m] (for moments).
    let g = system.environment.gravity.max(1e-3);
    let weight: Real = system
        .free_bodies
        .iter()
        .map(|&b| system.bodies[b].body.mass * g)
        .sum::<Real>()
        .max(1.0);
    let tolerance = 1e-6 * weight;
    let (mut r, mut twin, mut sol) = residual(system, &poses, options)?;
    let mut iterations = sol.iterations;
    for _ in 0..30 {
        if r.amax() <= tolerance {
            break;
        }
        let mut jac = DMatrix::zeros(n, n);
        for c in 0..n {
            let step = if c % 6 < 3 { 1e-4 } else { 1e-5 };
            let mut delta = DVector::zeros(n);
            delta[c] = step;
            let (rc, _, s) = residual(system, &moved(system, &poses, &delta), options)?;
            iterations += s.iterations;
            jac.set_column(c, &((rc - &r) / step));
        }
        // Levenberg–Marquardt: a shift of 1e-6 of the largest stiffness keeps directions
        // without stiffness (free yaw) in place.
        let shift = 1e-6 * jac.amax();
        let mut a = jac.transpose() * &jac;
        for i in 0..n {
            a[(i, i)] += shift * shift;
        }
        let Some(mut step) = a.lu().solve(&(-jac.transpose() * &r)) else {
            break;
        };
        // Trust region on the rotations: at most 0.2 rad per iteration, so that Newton
        // follows the body to the nearby stable pose instead of jumping to an inverted one.
        for f in 0..system.free_bodies.len() {
            let turn = step.rows(6 * f + 3, 3).norm();
            if turn > 0.2 {
                step.rows_mut(6 * f + 3, 3).scale_mut(0.2 / turn);
            }
        }
        // Backtrack on the residual norm.
        let mut lambda = 1.0;
        loop {
            let trial = moved(system, &poses, &(&step * lambda));
            let (rt, tt, st) = residual(system, &trial, options)?;
            iterations += st.iterations;
            if rt.norm() < r.norm() || lambda < 1e-3 {
                poses = trial;
                (r, twin, sol) = (rt, tt, st);
                break;
            }
            lambda *= 0.5;
        }
    }
    if r.amax() > tolerance * 1e3 {
        let worst = r.iamax();
        let body = &system.bodies[system.free_bodies[worst / 6]].body.name;
        return Err(StaticsError::NotConverged {
            iterations,
            residual: r.amax(),
            tolerance,
            location: format!("body {body}"),
            relaxation_residual: r.amax(),
            hint: "the body may have no static equilibrium (it floats away or sinks without a \
                   line to hold it): check its buoyancy and attachments, or start the run from \
                   the positions as given (initial_condition = \"as-defined\")"
                .into(),
        });
    }
    Ok(StaticSolution {
        state: system.state_from_twin_at(&twin, &sol.state, true, &poses),
        iterations,
        residual: sol.residual.max(r.amax()),
        method: "newton on the bodies' poses around the lines' statics",
    })
}
