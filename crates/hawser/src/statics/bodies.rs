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
//! A pinned body ([`crate::model::BodyKind::Pinned`]) keeps its origin on its pin: its three
//! rotations are unknowns, its translations are not (their residual, the pin's force, is
//! left out). A body pinned to a body ([`crate::model::Pin::Body`]) sits at its parent's
//! point (it moves with the parent's pose) and pushes on the parent there: its net force F
//! [N] adds to the parent's force rows and ρ × F [N·m] to its moment rows (ρ the pin from the
//! parent's origin), so the parent's equilibrium carries the child's weight and line loads.
//!
//! Start the bodies where their lines are taut: where a line is slack the residual has no
//! slope along it and Newton cannot move the body (reported as not converged, with a hint).

use super::newton::{StaticOptions, StaticSolution, evaluate, solve_unchecked};
use crate::error::StaticsError;
use crate::math::{Quat, Real, Vec3};
use crate::model::{PointKind, RigidKinematics};
use crate::system::System;
use nalgebra::{DMatrix, DVector};

/// Net static load [force; moment about the origin] on each free body with the lines solved
/// for the bodies held at `poses`, the twin and its solution, and the sum of the magnitudes of
/// the loads on the bodies [N] (their own load and each line's end force).
fn residual(
    system: &System,
    poses: &[RigidKinematics],
    warm: Option<&[Real]>,
    options: &StaticOptions,
) -> Result<(DVector<Real>, System, StaticSolution, Real), StaticsError> {
    let twin = system.statics_twin_at(poses);
    // Warm start from a nearby twin state (same layout: the bodies are not in it); from the
    // catenary seed when that fails or there is none.
    let sol = match warm.map(|y| solve_unchecked(&twin, Some(y), options)) {
        Some(Ok(s)) => s,
        _ => solve_unchecked(&twin, None, options)?,
    };
    let mut loads = 0.0;
    let mut ws = twin.workspace();
    evaluate(&twin, &sol.state, &mut ws);
    let mut r = DVector::zeros(6 * system.free_bodies.len());
    let mut net = vec![(Vec3::zeros(), Vec3::zeros()); system.free_bodies.len()];
    for (f, &b) in system.free_bodies.iter().enumerate() {
        // In a steady tow the body moves at the tow velocity (its drag and wind see it).
        let k = RigidKinematics {
            velocity: system.tow_velocity,
            ..RigidKinematics::at_rest(poses[b].position, poses[b].orientation)
        };
        let own = system.bodies[b].body.loads(&k, &system.environment, 0.0);
        let (mut force, mut moment) = (own.force, own.moment);
        loads += own.force.norm();
        for (li, l) in twin.lines.iter().enumerate() {
            for (end_b, p) in [(false, l.end_a), (true, l.end_b)] {
                if matches!(twin.points[p].kind, PointKind::Body { body, .. } if body == b) {
                    let fl = twin.end_force(&ws, li, end_b);
                    loads += fl.norm();
                    force += fl;
                    moment += (ws.points[p].position - k.position).cross(&fl);
                }
            }
        }
        net[f] = (force, moment);
    }
    // A body pinned to a free or pinned body pushes on its parent at the pin with its net
    // force (the pin's force on it is R = −F at rest): the parent's rows take F and the moment
    // ρ × F about the parent's origin.
    for (f, &b) in system.free_bodies.iter().enumerate() {
        let Some((p, _)) = system.pin_parent(b) else {
            continue;
        };
        let Some(fp) = system.bodies[p].free_index else {
            continue;
        };
        let force = net[f].0;
        let rho = poses[b].position - poses[p].position;
        net[fp].0 += force;
        net[fp].1 += rho.cross(&force);
    }
    for (f, &b) in system.free_bodies.iter().enumerate() {
        // A pinned body's pin takes the force: only its moment about the pin is unbalanced.
        let pinned = system.bodies[b].body.kind.pin().is_some();
        let (force, moment) = net[f];
        for i in 0..3 {
            r[6 * f + i] = if pinned { 0.0 } else { force[i] };
            r[6 * f + 3 + i] = moment[i];
        }
    }
    Ok((r, twin, sol, loads))
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
        // A pinned body turns about its pin, which stays where the pin is at t = 0.
        if system.bodies[b].body.kind.pin().is_none() {
            out[b].position += d(0);
        }
        out[b].orientation = Quat::from_scaled_axis(d(3)) * out[b].orientation;
    }
    place_on_parents(system, &mut out);
    out
}

/// Puts each body pinned to a body at its parent's point, o = o_p + R_p ρ₀ (at rest).
fn place_on_parents(system: &System, poses: &mut [RigidKinematics]) {
    for b in 0..poses.len() {
        if let Some((p, point)) = system.pin_parent(b) {
            poses[b].position = poses[p].position + poses[p].orientation * point;
        }
    }
}

/// Solves the statics of a system with free bodies (see the module docs). Starts from the
/// bodies' initial poses; each iteration costs 6 + 1 line statics per body. When that fails
/// (a line that starts slack, a drag-loaded line whose statics do not converge from the
/// catenary seed), it starts again from the end of a pseudo-dynamic relaxation
/// ([`relax_with_bodies`]).
pub fn solve_with_bodies(
    system: &System,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    let poses: Vec<RigidKinematics> = system
        .bodies
        .iter()
        .map(|b| b.initial_kinematics())
        .collect();
    match newton_on_poses(system, poses, None, options) {
        Ok(s) => Ok(s),
        Err(first) => {
            let Some(y) = relax_with_bodies(system) else {
                return Err(first);
            };
            let mut poses: Vec<RigidKinematics> = (0..system.bodies.len())
                .map(|b| match system.layout.body_offset[b] {
                    Some(o) => {
                        let k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
                        RigidKinematics::at_rest(k.position, k.orientation)
                    }
                    None => system.bodies[b].initial_kinematics(),
                })
                .collect();
            place_on_parents(system, &mut poses);
            let twin = system.statics_twin_at(&poses);
            let warm = twin_state(system, &twin, &y);
            let mut sol = newton_on_poses(system, poses, Some(warm), options)?;
            sol.method = "pseudo-dynamic relaxation, then newton on the bodies' poses";
            sol.fallback = Some(format!("newton on the bodies' poses failed: {first}"));
            Ok(sol)
        }
    }
}

/// The state of `twin` (the system with its bodies held) that holds the lines and free points
/// of the system state `y`.
fn twin_state(system: &System, twin: &System, y: &[Real]) -> Vec<Real> {
    let mut out = vec![0.0; twin.layout.len];
    for li in 0..system.lines.len() {
        let (o, len) = (system.layout.line_offset[li], system.layout.line_len[li]);
        let ot = twin.layout.line_offset[li];
        out[ot..ot + len].copy_from_slice(&y[o..o + len]);
    }
    for (p, off) in system.layout.point_offset.iter().enumerate() {
        if let (Some(o), Some(ot)) = (off, twin.layout.point_offset[p]) {
            out[ot..ot + 6].copy_from_slice(&y[*o..o + 6]);
        }
    }
    out
}

/// Pseudo-dynamic relaxation of the whole system, bodies included, toward its static
/// equilibrium (in a steady tow, the equilibrium in the frame moving at
/// [`System::tow_velocity`] V): the system's own equations of motion at t = 0 (prescribed
/// points and bodies held at their t = 0 places, everything else moving at V plus a relative
/// velocity u), integrated by RK4 at half the stable step with kinetic damping (Barnes): the
/// relative velocities are zeroed whenever the relative kinetic energy peaks. The equilibria
/// of this flow are the static ones (u = 0 and no acceleration). Starts from the catenary seed
/// with the bodies at their initial poses, so a line may start slack. Stops when the largest
/// acceleration times its mass is below 1e-4 of the weight scale, or after 200 000 steps;
/// returns `None` if the state is no longer finite.
pub fn relax_with_bodies(system: &System) -> Option<Vec<Real>> {
    use crate::math::{get3, set3};
    let v = system.tow_velocity;
    let n = system.layout.len;
    let mut ws = system.workspace();
    let mut y = system.straight_state();
    super::newton::catenary_seed(system, &mut y, &mut ws);
    super::newton::set_tow_velocities(system, &mut y);
    // Weights of the kinetic energy and of the residual force: per line vector the mass of its
    // element (times l² for a tangent), per free point its mass, per body its mass and its
    // largest moment of inertia.
    let g = system.environment.gravity.max(1e-3);
    let mut weight_scale: Real = 0.0;
    let mut mass = vec![0.0; n / 3];
    for (li, l) in system.lines.iter().enumerate() {
        if l.dg().is_some() {
            return None;
        }
        let o = system.layout.line_offset[li] / 3;
        let m = system.layout.line_interior[li];
        let elements = l.mesh.elements();
        for j in 1..l.vectors() - 1 {
            let e = (j * elements / (l.vectors() - 1)).min(elements - 1);
            let sec = l.mesh.section(e);
            let me = sec.line_type.mass_per_length * sec.element_length;
            weight_scale += me * g;
            let w = if l.is_tangent(j) {
                me * sec.element_length * sec.element_length
            } else {
                me
            };
            mass[o + m + j - 1] = w;
        }
    }
    for &p in &system.free_points {
        let o = system.layout.point_offset[p].expect("free point") / 3;
        if let crate::model::PointKind::Free { mass: mp, .. } = system.points[p].kind {
            mass[o + 1] = mp;
            weight_scale += mp * g;
        }
    }
    for &b in &system.free_bodies {
        weight_scale += system.bodies[b].body.mass * g;
    }
    let tolerance = 1e-4 * weight_scale.max(1e-9);
    let relative_energy = |y: &[Real]| {
        let mut e = 0.0;
        for (li, l) in system.lines.iter().enumerate() {
            let o = system.layout.line_offset[li] / 3;
            let m = system.layout.line_interior[li];
            for j in 1..l.vectors() - 1 {
                let u = get3(y, o + m + j - 1) - if l.is_tangent(j) { Vec3::zeros() } else { v };
                e += mass[o + m + j - 1] * u.norm_squared();
            }
        }
        for &p in &system.free_points {
            let o = system.layout.point_offset[p].expect("free point") / 3;
            e += mass[o + 1] * (get3(y, o + 1) - v).norm_squared();
        }
        for &b in &system.free_bodies {
            let o = system.layout.body_offset[b].expect("free body");
            let k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
            let body = &system.bodies[b].body;
            e += body.mass * (k.velocity - v).norm_squared()
                + body.inertia.abs().max() * k.angular_velocity.norm_squared();
        }
        e
    };
    // The rate in the frame moving at V: positions change at the relative velocity.
    let rate = |y: &[Real], out: &mut [Real], ws: &mut crate::system::Workspace| -> bool {
        if system.rhs(0.0, y, out, ws).is_err() {
            return false;
        }
        for (li, l) in system.lines.iter().enumerate() {
            let o = system.layout.line_offset[li] / 3;
            for j in 1..l.vectors() - 1 {
                if !l.is_tangent(j) {
                    let r = get3(out, o + j - 1) - v;
                    set3(out, o + j - 1, &r);
                }
            }
        }
        for &p in &system.free_points {
            let o = system.layout.point_offset[p].expect("free point") / 3;
            let r = get3(out, o) - v;
            set3(out, o, &r);
        }
        for &b in &system.free_bodies {
            let o = system.layout.body_offset[b].expect("free body") / 3;
            let r = get3(out, o) - v;
            set3(out, o, &r);
        }
        true
    };
    let dt = 0.5 * system.stable_step(crate::model::Scheme::Rk4).0;
    let (mut k1, mut k2, mut k3, mut k4, mut tmp) = (
        vec![0.0; n],
        vec![0.0; n],
        vec![0.0; n],
        vec![0.0; n],
        vec![0.0; n],
    );
    let mut last = 0.0;
    for step in 0..200_000 {
        if !rate(&y, &mut k1, &mut ws) {
            return None;
        }
        if step % 50 == 0 {
            // The largest unbalanced force: mass times acceleration.
            let mut worst: Real = 0.0;
            for (i, m) in mass.iter().enumerate() {
                if *m > 0.0 {
                    worst = worst.max(m * get3(&k1, i).norm());
                }
            }
            for &b in &system.free_bodies {
                let k = &ws.bodies[b];
                let body = &system.bodies[b].body;
                worst = worst.max(body.mass * k.acceleration.norm());
                worst = worst.max(body.inertia.abs().max() * k.angular_acceleration.norm());
            }
            if worst < tolerance && relative_energy(&y) < 1e-12 * weight_scale {
                break;
            }
        }
        let stage = |k: &[Real], h: Real, tmp: &mut Vec<Real>| {
            for i in 0..n {
                tmp[i] = y[i] + h * k[i];
            }
        };
        stage(&k1, 0.5 * dt, &mut tmp);
        if !rate(&tmp, &mut k2, &mut ws) {
            return None;
        }
        stage(&k2, 0.5 * dt, &mut tmp);
        if !rate(&tmp, &mut k3, &mut ws) {
            return None;
        }
        stage(&k3, dt, &mut tmp);
        if !rate(&tmp, &mut k4, &mut ws) {
            return None;
        }
        for i in 0..n {
            y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        for &b in &system.free_bodies {
            let o = system.layout.body_offset[b].expect("free body");
            let k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
            crate::bodies::write_state(&k, &mut y[o..o + crate::bodies::STATE_LEN]);
        }
        system.hold_pins(0.0, &mut y, &ws);
        if !y.iter().all(|x| x.is_finite()) {
            return None;
        }
        let e = relative_energy(&y);
        if e < last {
            super::newton::set_tow_velocities(system, &mut y);
            last = 0.0;
        } else {
            last = e;
        }
    }
    Some(y)
}

/// Per free body: its group (the free bodies joined to it through lines and points), its rank
/// within the group, and the largest group size.
fn body_groups(system: &System) -> (Vec<usize>, Vec<usize>, usize) {
    let nb = system.free_bodies.len();
    let mut parent: Vec<usize> = (0..nb).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    // Each point's free body, or the lines joining them through free points: join every body
    // reached from a line's ends, spreading through free points (a few sweeps suffice for the
    // chains of lines met in practice; bodies left apart only cost more columns).
    let body_of = |p: usize| match system.points[p].kind {
        PointKind::Body { body, .. } => system.bodies[body].free_index,
        _ => None,
    };
    let mut point_group: Vec<Option<usize>> = (0..system.points.len()).map(body_of).collect();
    for _ in 0..system.lines.len().max(1) {
        let mut changed = false;
        for l in &system.lines {
            let free = |p: usize| system.points[p].free_index.is_some() || body_of(p).is_some();
            match (point_group[l.end_a], point_group[l.end_b]) {
                (Some(a), Some(b)) => {
                    let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                    if ra != rb {
                        parent[ra] = rb;
                        changed = true;
                    }
                }
                (Some(a), None) if free(l.end_b) => {
                    point_group[l.end_b] = Some(a);
                    changed = true;
                }
                (None, Some(b)) if free(l.end_a) => {
                    point_group[l.end_a] = Some(b);
                    changed = true;
                }
                _ => {}
            }
        }
        if !changed {
            break;
        }
    }
    // A body pinned to a body loads its parent through the pin.
    for (f, &b) in system.free_bodies.iter().enumerate() {
        if let Some(fp) = system
            .pin_parent(b)
            .and_then(|(p, _)| system.bodies[p].free_index)
        {
            let (ra, rb) = (find(&mut parent, f), find(&mut parent, fp));
            parent[ra] = rb;
        }
    }
    let group: Vec<usize> = (0..nb).map(|f| find(&mut parent, f)).collect();
    let mut count = vec![0; nb];
    let mut rank = vec![0; nb];
    for f in 0..nb {
        rank[f] = count[group[f]];
        count[group[f]] += 1;
    }
    (group, rank, count.into_iter().max().unwrap_or(0))
}

/// Newton on the free bodies' poses from `poses`, the twin's lines warm-started from `warm`.
fn newton_on_poses(
    system: &System,
    mut poses: Vec<RigidKinematics>,
    warm: Option<Vec<Real>>,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    let n = 6 * system.free_bodies.len();
    let (group, rank, colours) = body_groups(system);
    let nb = system.free_bodies.len();
    let (mut r, mut twin, mut sol, loads) = residual(system, &poses, warm.as_deref(), options)?;
    // The force scale [N]: the bodies' weights, or the loads on them at the start when those
    // are larger (in zero gravity the weights vanish; thrust and line tensions do not).
    let g = system.environment.gravity;
    let weight: Real = system
        .free_bodies
        .iter()
        .map(|&b| system.bodies[b].body.mass * g)
        .sum::<Real>();
    let scale = if weight >= 1.0 {
        weight
    } else {
        loads.max(weight).max(1e-9)
    };
    // Newton aims at 1e-6 of the scale and accepts 1e-3 of it (the lines' statics inside each
    // residual converge to 1e-9 and the finite-difference Jacobian limits the bodies' own).
    let tolerance = 1e-6 * scale;
    let accepted = 1e3 * tolerance;
    let mut iterations = sol.iterations;
    for _ in 0..30 {
        if r.amax() <= tolerance {
            break;
        }
        // Bodies in different groups (joined by no line) do not load each other: one line
        // statics perturbs a degree of freedom of one body in every group at once.
        let mut jac = DMatrix::zeros(n, n);
        for colour in 0..colours {
            for dof in 0..6 {
                let step = if dof < 3 { 1e-4 } else { 1e-5 };
                let mut delta = DVector::zeros(n);
                for f in 0..nb {
                    if rank[f] == colour {
                        delta[6 * f + dof] = step;
                    }
                }
                let (rc, _, s, _) = residual(
                    system,
                    &moved(system, &poses, &delta),
                    Some(&sol.state),
                    options,
                )?;
                iterations += s.iterations;
                for f in (0..nb).filter(|&f| rank[f] == colour) {
                    for g in (0..nb).filter(|&g| group[g] == group[f]) {
                        for i in 0..6 {
                            jac[(6 * g + i, 6 * f + dof)] = (rc[6 * g + i] - r[6 * g + i]) / step;
                        }
                    }
                }
            }
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
            let (rt, tt, st, _) = residual(system, &trial, Some(&sol.state), options)?;
            iterations += st.iterations;
            if rt.norm() < r.norm() || lambda < 1e-3 {
                poses = trial;
                (r, twin, sol) = (rt, tt, st);
                break;
            }
            lambda *= 0.5;
        }
    }
    let worst = r
        .iter()
        .position(|x| !x.is_finite())
        .unwrap_or_else(|| r.iamax());
    let largest = r[worst].abs();
    if !(largest <= accepted) {
        let body = &system.bodies[system.free_bodies[worst / 6]].body.name;
        return Err(StaticsError::NotConverged {
            iterations,
            residual: largest,
            tolerance: accepted,
            location: format!("body {body}"),
            relaxation_residual: largest,
            hint: "the body may have no static equilibrium (it floats away or sinks without a \
                   line to hold it): check its buoyancy and attachments, or start the run from \
                   the positions as given (initial_condition = \"as-defined\")"
                .into(),
        });
    }
    let state = system.state_from_twin_at(&twin, &sol.state, true, &poses);
    Ok(StaticSolution {
        warnings: super::checks::twin_warnings(system, &state, &twin, &sol.state),
        state,
        iterations,
        residual: sol.residual.max(largest),
        tolerance: sol.tolerance.max(accepted),
        method: "newton on the bodies' poses around the lines' statics",
        log: sol.log,
        fallback: sol.fallback,
    })
}
