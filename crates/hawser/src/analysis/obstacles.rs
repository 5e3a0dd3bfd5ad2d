//! The loads obstacles receive from the lines: the obstacle channels `NAME.force_x|y|z` and
//! `NAME.contact_length`.
//!
//! They are recomputed from the node positions and velocities in a workspace by the very
//! functions the dynamics adds to the node forces ([`crate::formulation::fe::obstacle_contacts`],
//! [`crate::formulation::hermite::obstacle_contacts`]; for `dg` lines the contact law at the
//! Gauss points of the last right-hand side, as its source term), at the same quadrature
//! points:
//!
//! - force: the sum over every line and every contact point of −f·w [N], f [N/m] the contact
//!   force per unit unstretched length on the cable there and w [m] its quadrature weight (for
//!   `fe` half of each adjacent element at each node; for `hermite` the four Gauss points of
//!   each element; for `dg` its P + 2 Gauss points, weight h/2 w_q). It is minus the total
//!   contact force the lines receive, exactly (to round-off) the sum of the obstacle terms in
//!   the node forces.
//! - contact length: the sum of w over the contact points that penetrate, the unstretched
//!   length of cable in contact [m] as the quadrature sees it (it moves in steps of a node's
//!   share of an element).

use crate::formulation::{Discretisation, fe, hermite};
use crate::math::{Real, Vec3};
use crate::physics::obstacles::Obstacle;
use crate::system::{System, Workspace};

/// What an obstacle receives from the lines at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ObstacleLoad {
    /// Total contact force the lines exert on the obstacle [N].
    pub force: Vec3,
    /// Unstretched length of cable in contact [m] (sum of the quadrature weights of the
    /// contact points).
    pub contact_length: Real,
}

/// The load on every obstacle of the system's environment at time `time` [s], from the node
/// positions and velocities in `ws` (a workspace that holds a right-hand-side or static
/// evaluation), into `out` (one entry per obstacle). Allocation-free.
pub fn obstacle_forces(system: &System, ws: &Workspace, time: Real, out: &mut [ObstacleLoad]) {
    out.iter_mut().for_each(|o| *o = ObstacleLoad::default());
    let obstacles = &system.environment.obstacles;
    contacts(system, ws, time, obstacles, |k, f, w| {
        out[k].force -= f * w;
        out[k].contact_length += w;
    });
}

/// The load on obstacle `obstacle` alone (as [`obstacle_forces`]).
pub fn obstacle_load(system: &System, ws: &Workspace, time: Real, obstacle: usize) -> ObstacleLoad {
    let mut load = ObstacleLoad::default();
    let obstacles = &system.environment.obstacles[obstacle..=obstacle];
    contacts(system, ws, time, obstacles, |_, f, w| {
        load.force -= f * w;
        load.contact_length += w;
    });
    load
}

/// Every contact point of every line with `obstacles`: `visit(obstacle, f, w)` with f [N/m]
/// the force per unit length on the cable and w [m] the quadrature weight.
fn contacts(
    system: &System,
    ws: &Workspace,
    time: Real,
    obstacles: &[Obstacle],
    mut visit: impl FnMut(usize, Vec3, Real),
) {
    if obstacles.is_empty() {
        return;
    }
    for (li, (l, lw)) in system.lines.iter().zip(&ws.lines).enumerate() {
        let (q, qdot) = (&lw.position[..], &lw.velocity[..]);
        let mesh = system.line_mesh(ws, li);
        match l.discretisation {
            Discretisation::Fe { .. } => {
                fe::obstacle_contacts(mesh, obstacles, time, q, qdot, |k, _, f, w| visit(k, f, w))
            }
            Discretisation::Hermite(_) => {
                hermite::obstacle_contacts(mesh, obstacles, time, q, qdot, |k, _, _, f, w| {
                    visit(k, f, w)
                })
            }
            Discretisation::Dg(_) => {
                let (Some(line), Some(dws)) = (l.dg(), &ws.dg[li]) else {
                    continue;
                };
                // The source term of the dg right-hand side at its Gauss points, with the
                // quadrature weight h/2 w_q of its projection.
                for (k, obstacle) in obstacles.iter().enumerate() {
                    let kin = obstacle.kinematics(time);
                    for (e, el) in line.elements.iter().enumerate() {
                        let sec = line.section(e);
                        let lt = &sec.properties.line_type;
                        for qp in 0..sec.basis.points {
                            let p = el.point + qp;
                            if let Some(pen) = obstacle.penetration(&kin, &dws.pos[p], lt.diameter)
                            {
                                let f = obstacle.contact_force(
                                    &kin,
                                    &pen,
                                    &dws.nu[p],
                                    lt.mass_per_length,
                                    dws.stretch[p],
                                );
                                visit(k, f, 0.5 * el.length * sec.basis.weight[qp]);
                            }
                        }
                    }
                }
            }
        }
    }
}
