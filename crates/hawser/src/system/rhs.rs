//! The right-hand side of the equations of motion: point and body kinematics, line forces and
//! mass blocks, the coupled solve, and dy/dt.

use super::*;
use crate::linalg::EndKind;
use crate::math::{Mat3, Real, Vec3, get3, set3};
use crate::model::PointKind;
use crate::physics::environment::Environment;

/// Seabed contact of a free point: a sphere of the point's displaced volume pressing on the
/// bed with the ground stiffness K_g over its projected area, k = K_g π r² [N/m], damped at
/// the seabed's damping ratio of the point's own critical damping, with sliding friction
/// μ N tanh(π|v_t|/v_μ) (the line contact of DG paper eqs. 15–16 applied to a sphere), all
/// along the bed's normal n and in its tangent plane.
#[derive(Clone, Copy, Debug)]
pub(super) struct SphereContact {
    /// Radius of the sphere of the point's volume [m].
    pub(super) radius: Real,
    /// Contact stiffness K_g π r² [N/m].
    pub(super) stiffness: Real,
    /// Contact damping [N·s/m].
    pub(super) damping: Real,
}

impl SphereContact {
    /// The contact of a free point with a volume V (mass with added mass m), modelled as a
    /// sphere of that volume; `None` for other points, without a seabed, or without a volume
    /// (a joint or a point mass has no extent to rest on).
    pub(super) fn new(env: &Environment, kind: &PointKind) -> Option<Self> {
        let PointKind::Free {
            mass,
            volume,
            added_mass_coefficient,
            ..
        } = kind
        else {
            return None;
        };
        let m = mass + env.water_density * volume * added_mass_coefficient;
        if !(env.has_seabed() && env.seabed.stiffness > 0.0 && *volume > 0.0 && *mass > 0.0) {
            return None;
        }
        let radius = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
        let stiffness = env.seabed.stiffness * std::f64::consts::PI * radius * radius;
        Some(Self {
            radius,
            stiffness,
            damping: env.seabed.damping_of_area(
                std::f64::consts::PI * radius * radius,
                stiffness,
                m,
            ),
        })
    }

    /// The contact force [N] on the sphere centred at `position` [m] moving at `velocity`
    /// [m/s]: (k δ − c v·n) n with δ the depth of its lowest point below the bed's tangent
    /// plane along the normal n, and friction against v_t = v − (v·n) n.
    pub(super) fn force(&self, env: &Environment, position: &Vec3, velocity: &Vec3) -> Vec3 {
        let bed = env.seabed_at(position.x, position.y);
        let n = bed.normal;
        // The lowest point along −n: (z_bed − (z − r/n_z)) n_z = (z_bed − z) n_z + r.
        let penetration = (bed.z - (position.z - self.radius / n.z)) * n.z;
        if penetration <= 0.0 {
            return Vec3::zeros();
        }
        let vn = velocity.dot(&n);
        let normal = self.stiffness * penetration - self.damping * vn;
        let mut f = n * normal;
        let vt = velocity - n * vn;
        let speed = vt.norm();
        let seabed = &env.seabed;
        if seabed.friction_coefficient > 0.0 && speed > 0.0 && normal > 0.0 {
            f -= vt * (seabed.friction(speed, normal, 1.0) / speed);
        }
        f
    }
}

impl System {
    /// Updates the point kinematics at time t from the state (positions and velocities).
    /// The free end of a `dg` line keeps the kinematics its line gave it in the last
    /// evaluation ([`SystemLine::evaluate`]).
    /// Bodies first: free ones from the state (accelerations from the last solve are kept
    /// only by [`System::rhs`]), prescribed ones from their motion, coupled ones from the
    /// host's track in `ws.coupling`, pinned ones turned as the state says about their pin's
    /// position, velocity and acceleration at t; points on bodies follow.
    pub fn point_kinematics(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        // Parents first: a body pinned to a body follows its parent's point.
        for b in 0..self.bodies.len() {
            if self.pin_parent(b).is_none() {
                ws.bodies[b] = self.body_kinematics(b, t, y, &ws.coupling, None);
            }
        }
        for b in 0..self.bodies.len() {
            if let Some((parent, _)) = self.pin_parent(b) {
                let host = ws.bodies[parent];
                ws.bodies[b] = self.body_kinematics(b, t, y, &ws.coupling, Some(&host));
            }
        }
        for (i, p) in self.points.iter().enumerate() {
            if p.line_end.is_some() {
                continue;
            }
            ws.points[i] = match &p.kind {
                PointKind::Fixed => PointKinematics {
                    position: p.position,
                    ..Default::default()
                },
                PointKind::Prescribed(crate::model::Motion::Rigid { motion, offset }) => {
                    // The same numbers as `Motion::kinematics`, the motion evaluated once at
                    // each time for all the points it moves (`Workspace::rigid_motions`).
                    let source = self.rigid_motion_source[i].unwrap_or(i);
                    let body = match ws.rigid_motions[source] {
                        Some((time, body)) if time.to_bits() == t.to_bits() => body,
                        _ => {
                            let body = motion.kinematics(t);
                            ws.rigid_motions[source] = Some((t, body));
                            body
                        }
                    };
                    let (position, velocity, acceleration) = body.point(offset);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
                PointKind::Prescribed(m) => {
                    let (position, velocity, acceleration) = m.kinematics(t);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
                PointKind::Coupled => {
                    let track = ws.coupling.points[i]
                        .as_ref()
                        .expect("a coupled point has a track");
                    let (position, velocity, acceleration) = track.at(t);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
                PointKind::Free { .. } => {
                    let o = self.layout.point_offset[i].expect("free point has a state block");
                    PointKinematics {
                        position: get3(y, o / 3),
                        velocity: get3(y, o / 3 + 1),
                        acceleration: Vec3::zeros(),
                    }
                }
                PointKind::Body { body, offset } => {
                    let (position, velocity, acceleration) = ws.bodies[*body].point(offset);
                    PointKinematics {
                        position,
                        velocity,
                        acceleration,
                    }
                }
            };
        }
    }

    /// The parent body and its point [m, parent's body axes] of body `b` when it is pinned to
    /// a body ([`crate::model::Pin::Body`]).
    #[inline]
    pub fn pin_parent(&self, b: usize) -> Option<(usize, Vec3)> {
        self.bodies[b]
            .body
            .kind
            .pin()
            .and_then(crate::model::Pin::parent)
    }

    /// Kinematics of body `b` at (t, y): a free body from the state, a prescribed one from its
    /// motion, a coupled one from the host's track in `tracks`, a pinned one turned as the
    /// state says about its pin's position, velocity and acceleration at t (a pin on a body:
    /// the point of `parent`, the parent's kinematics at t).
    fn body_kinematics(
        &self,
        b: usize,
        t: Real,
        y: &[Real],
        tracks: &super::workspace::CouplingTracks,
        parent: Option<&crate::model::RigidKinematics>,
    ) -> crate::model::RigidKinematics {
        let body = &self.bodies[b];
        match (&body.body.kind, self.layout.body_offset[b]) {
            (crate::model::BodyKind::Pinned(pin), Some(o)) => {
                let mut k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
                let track = tracks.bodies[b].as_ref();
                crate::bodies::follow_pin(
                    &mut k,
                    crate::bodies::pin_kinematics(pin, &body.body.position, track, parent, t),
                );
                k
            }
            (_, Some(o)) => crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]),
            (crate::model::BodyKind::Prescribed(m), None) => m.kinematics(t),
            (crate::model::BodyKind::Free | crate::model::BodyKind::Pinned(_), None) => {
                body.initial_kinematics()
            }
            (crate::model::BodyKind::Coupled, None) => tracks.bodies[b]
                .as_ref()
                .expect("a coupled body has a track")
                .at(t),
        }
    }

    /// Puts the position [m] and velocity [m/s] of each pinned body's pin at time t [s] into
    /// the body's translational state entries, which the integrator carries along the pin's
    /// velocity and acceleration only up to its error (and from whatever velocity the state
    /// started with): the stepper calls it after every step, so the state holds the pin exactly
    /// (the physics reads the pin's motion anyway, [`System::point_kinematics`]).
    ///
    /// A body pinned to a body is held after its parent (whose own pin is held first): its
    /// origin on the parent's point, o = o_p + R_p ρ₀, moving at v_p + ω_p × ρ.
    pub fn hold_pins(&self, t: Real, y: &mut [Real], ws: &Workspace) {
        for children in [false, true] {
            for &b in &self.free_bodies {
                let body = &self.bodies[b].body;
                let Some(pin) = body.kind.pin() else {
                    continue;
                };
                let parent = self.pin_parent(b);
                if parent.is_some() != children {
                    continue;
                }
                let host = parent.map(|(p, _)| self.body_kinematics(p, t, y, &ws.coupling, None));
                let o = self.layout.body_offset[b].expect("a pinned body has a state block");
                let track = ws.coupling.bodies[b].as_ref();
                let (x, v, _) =
                    crate::bodies::pin_kinematics(pin, &body.position, track, host.as_ref(), t);
                y[o..o + 3].copy_from_slice(x.as_slice());
                y[o + 7..o + 10].copy_from_slice(v.as_slice());
            }
        }
    }

    /// Fills each line's node positions and velocities from the state and its ends
    /// ([`SystemLine::gather`]; `dg` lines fill theirs when evaluated).
    pub fn gather_lines(&self, y: &[Real], ws: &mut Workspace) {
        for (li, l) in self.lines.iter().enumerate() {
            l.gather(
                &y[self.layout.line_range(li)],
                &ws.points[l.end_a],
                &ws.points[l.end_b],
                &mut ws.lines[li],
            );
        }
    }

    /// Forces of a free point's own physics [N] (weight, buoyancy, drag, external force) and
    /// its own mass matrix [kg] (mass plus added mass when submerged).
    pub fn point_own_load(
        &self,
        p: usize,
        k: &PointKinematics,
        t: Real,
        load_factor: Real,
    ) -> (Vec3, Mat3) {
        let PointKind::Free {
            mass,
            volume,
            drag_area,
            added_mass_coefficient,
            force,
        } = &self.points[p].kind
        else {
            return (Vec3::zeros(), Mat3::zeros());
        };
        let env = &self.environment;
        let rho = env.fluid_density(k.position.z);
        let submerged = k.position.z < 0.0;
        let mut f = Vec3::new(0.0, 0.0, -mass * env.gravity) + force * load_factor;
        let mut m = *mass;
        let (uw, aw) = env.fluid_kinematics(&k.position, t);
        if submerged {
            f.z += rho * volume * env.gravity;
            m += rho * volume * added_mass_coefficient;
            f += aw * (rho * volume * (1.0 + added_mass_coefficient));
        }
        let rel = uw * load_factor - k.velocity;
        f += rel * (0.5 * rho * drag_area * rel.norm());
        if let Some(contact) = &self.points[p].seabed_contact {
            f += contact.force(env, &k.position, &k.velocity);
        }
        (f, Mat3::identity() * m)
    }

    /// Right-hand side of the equations of motion: dy/dt at (t, y).
    ///
    /// Lines: M a = F with M block-tridiagonal (consistent) or block-diagonal (lumped); free
    /// points: (m_p + added mass + the line ends' mass) a_p = F_p + Σ line end forces. Solved
    /// together in O(nodes) by [`CoupledSystem`]. `dg` lines are evaluated with their ends'
    /// kinematics at t and write their own rate: their flux tractions enter the points' forces
    /// and their ends add no mass (explicit coupling, DG paper §3.3).
    pub fn rhs(
        &self,
        t: Real,
        y: &[Real],
        dydt: &mut [Real],
        ws: &mut Workspace,
    ) -> Result<(), Location> {
        self.assemble_for_rates(t, y, dydt, ws);
        ws.coupled
            .solve(&mut ws.blocks)
            .map_err(|s| self.singular_location(s))?;
        for (li, l) in self.lines.iter().enumerate() {
            l.write_rate(
                &ws.lines[li],
                &ws.blocks[li],
                &mut dydt[self.layout.line_range(li)],
            );
        }
        for (f, &p) in self.free_points.iter().enumerate() {
            let o = self.layout.point_offset[p].expect("free point");
            set3(&mut dydt[o..], 0, &ws.points[p].velocity);
            set3(&mut dydt[o..], 1, &ws.coupled.point_x[f]);
            ws.points[p].acceleration = ws.coupled.point_x[f];
        }
        for (f, &b) in self.free_bodies.iter().enumerate() {
            let o = self.layout.body_offset[b].expect("free body");
            let u = ws.coupled.body_x[f];
            let k = &mut ws.bodies[b];
            k.acceleration = Vec3::new(u[0], u[1], u[2]);
            k.angular_acceleration = Vec3::new(u[3], u[4], u[5]);
            crate::bodies::write_rate(
                k,
                &k.acceleration,
                &k.angular_acceleration,
                &mut dydt[o..o + crate::bodies::STATE_LEN],
            );
        }
        for (p, slot) in self.point_slot.iter().enumerate() {
            if let Some(s) = slot {
                ws.points[p].acceleration = ws.coupled.slot_x[*s];
            }
        }
        Ok(())
    }

    /// [`System::rhs`] with the line nodes' accelerations given instead of solved for: the
    /// loads, tensions and mass blocks are evaluated at (t, y) as by `rhs`, the interior
    /// nodes take their accelerations from `accelerations` (a vector in the layout of the
    /// state, each acceleration at its velocity's place), and the end forces
    /// F_end − (M_ee a_e + M_en a_n) read them ([`SystemLine::end_force`]). For an implicit
    /// scheme's converged step, whose accelerations satisfy M q̈ = F at (t, y) to its Newton
    /// tolerance: the mass solve of `rhs` is skipped. Returns false, having done nothing,
    /// unless every line is an `fe` line without a winch whose two ends are known (fixed,
    /// prescribed or coupled points) and there are no free points or bodies: the cases where
    /// the interior accelerations are all the solve gives.
    pub fn rhs_with_accelerations(
        &self,
        t: Real,
        y: &[Real],
        accelerations: &[Real],
        dydt: &mut [Real],
        ws: &mut Workspace,
    ) -> bool {
        let known_ends = self.free_points.is_empty()
            && self.free_bodies.is_empty()
            && self.point_slot.iter().all(Option::is_none)
            && self.lines.iter().enumerate().all(|(li, l)| {
                matches!(l.discretisation, Discretisation::Fe { .. })
                    && ws.winches[li].is_none()
                    && ws.blocks[li].end_a == EndKind::Known
                    && ws.blocks[li].end_b == EndKind::Known
            });
        if !known_ends {
            return false;
        }
        self.assemble_for_rates(t, y, dydt, ws);
        for (li, l) in self.lines.iter().enumerate() {
            let (o, m) = (self.layout.line_offset[li], self.layout.line_interior[li]);
            // x holds the ends' known accelerations (assemble_loads put them there) and the
            // interior forces, which the given accelerations replace.
            let given = &accelerations[o + 3 * m..o + 6 * m];
            crate::math::coordinates_mut(&mut ws.blocks[li].x[1..=m]).copy_from_slice(given);
            l.write_rate(
                &ws.lines[li],
                &ws.blocks[li],
                &mut dydt[self.layout.line_range(li)],
            );
        }
        true
    }

    /// What [`System::rhs`] and [`System::rhs_with_accelerations`] assemble before the
    /// accelerations: wave tables, point kinematics and loads at (t, y), `dg` lines writing
    /// their rate into `dydt`; a lumped line's interior mass stays in its factored form (the
    /// solve reads only that; the given accelerations need only the ends' blocks).
    fn assemble_for_rates(&self, t: Real, y: &[Real], dydt: &mut [Real], ws: &mut Workspace) {
        self.prepare_wave_tables(t, ws);
        self.point_kinematics(t, y, ws);
        ws.blocks.iter_mut().for_each(|b| b.lumped.ends_only = true);
        self.assemble_loads(t, y, Some(dydt), ws);
        ws.blocks
            .iter_mut()
            .for_each(|b| b.lumped.ends_only = false);
    }

    /// The equations of motion at (t, y), assembled but not solved: point kinematics (free
    /// points from the state, others from their motion, with their accelerations), node
    /// positions and velocities, node forces `ws.lines[l].force` and mass blocks
    /// `ws.blocks[l]` (whose `x` holds the forces, with the known accelerations at ends on
    /// fixed or prescribed points), and each free point's own load and mass in
    /// `ws.coupled.point_x`, `ws.coupled.point_diag`. A `dg` line is not evaluated (it has no
    /// rate to write here): its blocks pass on its last end tractions.
    pub fn assemble(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        self.prepare_wave_tables(t, ws);
        self.point_kinematics(t, y, ws);
        self.assemble_loads(t, y, None, ws);
    }

    /// [`System::assemble`] after [`System::point_kinematics`] at the same (t, y): every line
    /// evaluated ([`SystemLine::evaluate`]; `dg` lines write their rate into `dydt` when it
    /// is given), then the free points' and bodies' own loads.
    fn assemble_loads(
        &self,
        t: Real,
        y: &[Real],
        mut dydt: Option<&mut [Real]>,
        ws: &mut Workspace,
    ) {
        self.update_winches(t, ws);
        for (li, l) in self.lines.iter().enumerate() {
            let range = self.layout.line_range(li);
            let force = |p: usize| match &self.points[p].kind {
                PointKind::Free { force, .. } => *force,
                _ => Vec3::zeros(),
            };
            let ends = LineEnds {
                kinematics: [&ws.points[l.end_a], &ws.points[l.end_b]],
                force: [force(l.end_a), force(l.end_b)],
            };
            let mesh = match &ws.winches[li] {
                Some(w) => &w.mesh,
                None => &l.mesh,
            };
            l.evaluate(
                &self.environment,
                t,
                mesh,
                ws.wave_points.of_line(li),
                &y[range.clone()],
                dydt.as_deref_mut().map(|d| &mut d[range]),
                &ends,
                &mut ws.lines[li],
                &mut ws.blocks[li],
                ws.dg[li].as_mut(),
            );
            // The free end of a `dg` line moves with the line's end node.
            for (side, p) in [(0, l.end_a), (1, l.end_b)] {
                if self.points[p].line_end.is_some() {
                    let lw = &ws.lines[li];
                    let node = if side == 0 { 0 } else { lw.position.len() - 1 };
                    ws.points[p] = PointKinematics {
                        position: lw.position[node],
                        velocity: lw.velocity[node],
                        acceleration: Vec3::zeros(),
                    };
                }
            }
        }
        for (f, &p) in self.free_points.iter().enumerate() {
            // A failure's reserved free end rests until its release: a unit mass and no force
            // give it zero acceleration (no line end is attached to it yet).
            let (force, mass) = if self.points[p].dormant {
                (Vec3::zeros(), Mat3::identity())
            } else {
                self.point_own_load(p, &ws.points[p], t, 1.0)
            };
            ws.coupled.point_x[f] = force;
            ws.coupled.point_diag[f] = mass;
        }
        self.assemble_bodies(t, ws);
    }

    /// Each free body's own loads and 6×6 mass as its block of the coupled system (a pinned
    /// body's translations held at its pin's acceleration), and the offsets and centripetal
    /// accelerations of its points' slots. (A prescribed body's own
    /// loads do not enter the equations: its points are known ends.)
    fn assemble_bodies(&self, t: Real, ws: &mut Workspace) {
        for (f, &b) in self.free_bodies.iter().enumerate() {
            let loads = self.bodies[b]
                .body
                .loads(&ws.bodies[b], &self.environment, t);
            ws.coupled.body_diag[f] = loads.mass;
            ws.coupled.body_x[f] = loads.generalized();
            // A pin on an integrated parent is the constraint a_o = J u_p + ω_p × (ω_p × ρ);
            // on a prescribed or coupled parent the pin's acceleration is known.
            let on_parent = self.pin_parent(b).and_then(|(p, point)| {
                let host = &ws.bodies[p];
                let offset = host.orientation * point;
                let w = host.angular_velocity;
                self.bodies[p]
                    .free_index
                    .map(|body| crate::linalg::ParentPin {
                        body,
                        offset,
                        bias: w.cross(&w.cross(&offset)),
                    })
            });
            ws.coupled.body_parent[f] = on_parent;
            ws.coupled.body_pin[f] = match (self.bodies[b].body.kind.pin(), on_parent) {
                (Some(_), None) => Some(ws.bodies[b].acceleration),
                _ => None,
            };
        }
        let np = self.free_points.len();
        for (p, slot) in self.point_slot.iter().enumerate() {
            let (Some(s), PointKind::Body { body, offset }) = (slot, &self.points[p].kind) else {
                continue;
            };
            let k = &ws.bodies[*body];
            let rho = k.orientation * offset;
            let w = k.angular_velocity;
            ws.coupled.body_slots[s - np] = crate::linalg::BodySlot {
                body: self.bodies[*body]
                    .free_index
                    .expect("a slot is on a free body"),
                offset: rho,
                bias: w.cross(&w.cross(&rho)),
            };
        }
    }
}
