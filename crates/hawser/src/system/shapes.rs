//! Starting shapes and states: straight lines, a line set from a continuous shape, the statics
//! twin of systems with `dg` lines or free bodies, and the mechanical energy of a state.

use super::*;
use crate::formulation::Energy;
use crate::formulation::dg::{EndState, Translation};
use crate::formulation::{Discretisation, Mesh};
use crate::math::{Real, Vec3, set3};
use crate::model::PointKind;

impl System {
    /// The system with every `dg` line replaced by a `hermite` line over the same sections,
    /// with ⌈(P + 1)/2⌉ cubic elements per dg element of order P (about as many unknowns),
    /// the same ends and clamps, and every free body held at its initial pose: the statics of
    /// such systems are solved on it ([`crate::statics::solve`]) and carried over by
    /// [`System::state_from_twin`] (free bodies start at their initial pose, at rest).
    pub fn statics_twin(&self) -> System {
        let poses: Vec<_> = self.bodies.iter().map(|b| b.initial_kinematics()).collect();
        self.statics_twin_at(&poses)
    }

    /// [`System::statics_twin`] with the free bodies held at `poses` (one per body; entries
    /// of prescribed bodies are not used).
    pub fn statics_twin_at(&self, poses: &[crate::model::RigidKinematics]) -> System {
        let lines = self
            .lines
            .iter()
            .map(|l| match &l.discretisation {
                Discretisation::Fe { .. } | Discretisation::Hermite(_) => l.clone(),
                Discretisation::Dg(dg) => {
                    let sections: Vec<_> = dg
                        .sections
                        .iter()
                        .enumerate()
                        .map(|(k, sec)| {
                            let count = dg.elements.iter().filter(|e| e.section == k).count();
                            (
                                sec.properties.line_type.clone(),
                                count as Real * sec.properties.element_length,
                                count * sec.basis.order.div_ceil(2).max(1),
                            )
                        })
                        .collect();
                    SystemLine {
                        mesh: Mesh::new(&sections),
                        discretisation: Discretisation::Hermite(Default::default()),
                        ..l.clone()
                    }
                }
            })
            .collect();
        let points = self
            .points
            .iter()
            .map(|p| SystemPoint {
                free_index: None,
                line_end: None,
                ..p.clone()
            })
            .collect();
        // Free bodies are held at their initial pose.
        let bodies = self
            .bodies
            .iter()
            .zip(poses)
            .map(|(b, k)| {
                let mut body = b.body.clone();
                if b.free_index.is_none() {
                    return SystemBody {
                        body,
                        free_index: None,
                    };
                }
                body.kind = crate::model::BodyKind::Prescribed(crate::model::RigidMotion::Fixed {
                    position: k.position,
                    orientation: k.orientation,
                });
                SystemBody {
                    body,
                    free_index: None,
                }
            })
            .collect();
        let mut twin = Self::from_parts(self.environment.clone(), lines, points, bodies)
            .expect("a system without dg lines has no dg end to refuse");
        twin.tow_velocity = self.tow_velocity;
        twin
    }

    /// This system's state from a state `y_twin` of its [`System::statics_twin`]: free points
    /// and `fe`/`hermite` lines copied, each `dg` line the L2 projection of its twin's cubic
    /// shape (positions and tangents ∂r/∂s, at rest), then, when `refine` and the line has at
    /// most 3000 modal unknowns, Newton on the dg line's own steady equations with its ends
    /// held where the twin put them ([`crate::formulation::dg::steady_state`]), so that the
    /// run starts in the dg discretisation's own equilibrium (a failed refinement keeps the
    /// projection). The free points keep the twin's equilibrium: their residual is the
    /// difference of the two discretisations' end forces.
    pub fn state_from_twin(&self, twin: &System, y_twin: &[Real], refine: bool) -> Vec<Real> {
        let poses: Vec<_> = self.bodies.iter().map(|b| b.initial_kinematics()).collect();
        self.state_from_twin_at(twin, y_twin, refine, &poses)
    }

    /// [`System::state_from_twin`] with the free bodies at rest at `poses`.
    pub fn state_from_twin_at(
        &self,
        twin: &System,
        y_twin: &[Real],
        refine: bool,
        poses: &[crate::model::RigidKinematics],
    ) -> Vec<Real> {
        let mut y = vec![0.0; self.layout.len];
        let mut tws = twin.workspace();
        twin.point_kinematics(0.0, y_twin, &mut tws);
        twin.gather_lines(y_twin, &mut tws);
        for (p, off) in self.layout.point_offset.iter().enumerate() {
            if let (Some(o), Some(ot)) = (off, twin.layout.point_offset[p]) {
                y[*o..o + 6].copy_from_slice(&y_twin[ot..ot + 6]);
            }
        }
        for (b, off) in self.layout.body_offset.iter().enumerate() {
            if let Some(o) = off {
                let k =
                    crate::model::RigidKinematics::at_rest(poses[b].position, poses[b].orientation);
                crate::bodies::write_state(&k, &mut y[*o..o + crate::bodies::STATE_LEN]);
            }
        }
        for (li, l) in self.lines.iter().enumerate() {
            let (o, len) = (self.layout.line_offset[li], self.layout.line_len[li]);
            let dg = match &l.discretisation {
                Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                    let ot = twin.layout.line_offset[li];
                    y[o..o + len].copy_from_slice(&y_twin[ot..ot + len]);
                    continue;
                }
                Discretisation::Dg(dg) => dg,
            };
            let tl = &twin.lines[li];
            let q = &tws.lines[li].position;
            let nodes: Vec<Real> = (0..=tl.mesh.elements())
                .map(|i| tl.mesh.arc_length(i))
                .collect();
            let state = &mut y[o..o + len];
            dg.project(state, |s| {
                let e = (nodes.partition_point(|&x| x <= s).max(1) - 1).min(nodes.len() - 2);
                let xi = ((s - nodes[e]) / (nodes[e + 1] - nodes[e])).clamp(0.0, 1.0);
                let (r, t) = crate::formulation::hermite::point_on_element(&tl.mesh, q, e, xi);
                (r, t, Vec3::zeros())
            });
            if refine && 2 * dg.state_len() / 3 <= 3000 {
                let end = |side: usize, p: usize| {
                    let mut end = EndState::fixed(
                        tws.points[p].position,
                        l.clamp[side].unwrap_or_else(Vec3::zeros),
                    );
                    if let PointKind::Free { force, .. } = &self.points[p].kind
                        && dg.ends[side].translation == Translation::Force
                    {
                        end.force = *force;
                    }
                    end
                };
                let ends = [end(0, l.end_a), end(1, l.end_b)];
                let mut trial = state.to_vec();
                if crate::formulation::dg::steady_state(
                    dg,
                    &self.environment,
                    0.0,
                    &mut trial,
                    &ends,
                    1e-10,
                    30,
                )
                .is_ok()
                {
                    state.copy_from_slice(&trial);
                }
            }
        }
        y
    }

    /// A state with every line straight between its ends, free bodies at their initial pose,
    /// and everything at rest.
    pub fn straight_state(&self) -> Vec<Real> {
        let mut y = vec![0.0; self.layout.len];
        for (b, off) in self.layout.body_offset.iter().enumerate() {
            if let Some(o) = off {
                let k = self.bodies[b].initial_kinematics();
                crate::bodies::write_state(&k, &mut y[*o..o + crate::bodies::STATE_LEN]);
            }
        }
        for (i, p) in self.points.iter().enumerate() {
            if let Some(o) = self.layout.point_offset[i] {
                set3(&mut y[o..], 0, &p.position);
            }
        }
        for (li, l) in self.lines.iter().enumerate() {
            let a = self.points[l.end_a].position;
            let b = self.points[l.end_b].position;
            l.set_straight(&mut y[self.layout.line_range(li)], a, b);
        }
        y
    }

    /// Sets line `line`'s unknowns in `y` from a continuous configuration: `shape(s)` gives the
    /// position [m] and velocity [m/s] at unstretched arc length s [m] from end A. The ends
    /// stay with their points (set free points through [`Layout::point_range`]). This is the
    /// formulation-neutral way to start a line from a given shape ([`SystemLine::set_shape`]:
    /// the nodes take it at their arc lengths and the other unknowns follow, `hermite`
    /// tangents and their rates by finite differences, exact for straight lines and linear in
    /// the shape, so a rigidly moved shape gives rigidly moved unknowns; a `dg` line takes the
    /// L2 projection of the shape).
    pub fn set_line_shape(
        &self,
        y: &mut [Real],
        line: usize,
        shape: impl Fn(Real) -> (Vec3, Vec3),
    ) {
        self.lines[line].set_shape(&mut y[self.layout.line_range(line)], shape);
    }

    /// Mechanical energy of the state `y` at time t [J]: kinetic energy ½ q̇ᵀ M q̇ of the lines
    /// (with the mass matrix of their formulation, without added mass) and of the free points
    /// (their own mass) and free bodies (½ m |v_G|² + ½ ωᵀ I ω), the potential of weight in air (γ0 g z integrated along the lines,
    /// m g z of the points: buoyancy and fluid forces are not conservative in general and are
    /// left out, so the sum is conserved only in air or vacuum without drag or damping), and
    /// the strain energy: axial ∫ ∫₀^ε T_e(e) de ds and, for `hermite`, bending ∫ ½ EI |r''|² ds.
    /// Each integral uses the formulation's own quadrature, so the potential is the one whose
    /// gradient the formulation's forces are. Fills `ws`'s line vectors and point kinematics.
    pub fn mechanical_energy(&self, t: Real, y: &[Real], ws: &mut Workspace) -> Energy {
        self.update_winches(t, ws);
        self.point_kinematics(t, y, ws);
        self.gather_lines(y, ws);
        let g = self.environment.gravity;
        let mut energy = Energy::default();
        for (li, l) in self.lines.iter().enumerate() {
            energy += l.energy(
                self.line_mesh(ws, li),
                &y[self.layout.line_range(li)],
                &ws.lines[li],
                ws.points[l.end_a].position,
                ws.points[l.end_b].position,
                g,
            );
        }
        for (p, point) in self.points.iter().enumerate() {
            if let PointKind::Free { mass, .. } = point.kind {
                let k = &ws.points[p];
                energy.kinetic += 0.5 * mass * k.velocity.norm_squared();
                energy.gravity += mass * g * k.position.z;
            }
        }
        for &b in &self.free_bodies {
            let (body, k) = (&self.bodies[b].body, &ws.bodies[b]);
            let (cg, v_cg, _) = k.point(&body.centre_of_gravity);
            let r = k.orientation.to_rotation_matrix();
            let inertia = r * body.inertia * r.transpose();
            let w = k.angular_velocity;
            energy.kinetic += 0.5 * body.mass * v_cg.norm_squared() + 0.5 * w.dot(&(inertia * w));
            energy.gravity += body.mass * g * cg.z;
        }
        energy
    }
}
