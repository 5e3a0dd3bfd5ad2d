//! The largest stable time step of an explicit scheme, and the wave-speed step of the
//! elastic-link paper's eq. 48.

use super::*;
use crate::formulation::Discretisation;
use crate::math::Real;
use crate::model::{PointKind, Scheme};

/// Gershgorin row sums of one node's linearised mass, damping and stiffness, by direction.
#[derive(Clone, Copy, Debug, Default)]
struct NodeRows {
    mass: Real,
    axial_damping: Real,
    axial_stiffness: Real,
    contact_damping: Real,
    contact_stiffness: Real,
    friction_damping: Real,
    bending_damping: Real,
    bending_stiffness: Real,
    obstacle_damping: Real,
    obstacle_stiffness: Real,
}

impl NodeRows {
    fn add(&mut self, o: &NodeRows) {
        self.mass += o.mass;
        self.axial_damping += o.axial_damping;
        self.axial_stiffness += o.axial_stiffness;
        self.contact_damping += o.contact_damping;
        self.contact_stiffness += o.contact_stiffness;
        self.friction_damping += o.friction_damping;
        self.bending_damping += o.bending_damping;
        self.bending_stiffness += o.bending_stiffness;
        self.obstacle_damping += o.obstacle_damping;
        self.obstacle_stiffness += o.obstacle_stiffness;
    }

    /// Bound on |λ| [1/s] and the term that sets it.
    fn bound(&self) -> (Real, &'static str) {
        let m = self.mass;
        [
            (
                (self.axial_damping + self.friction_damping) / m,
                if self.friction_damping > 0.0 {
                    "axial damping and seabed friction"
                } else {
                    "axial damping"
                },
            ),
            ((self.axial_stiffness / m).sqrt(), "axial stiffness"),
            (self.contact_damping / m, "seabed contact damping"),
            (
                (self.contact_stiffness / m).sqrt(),
                "seabed contact stiffness",
            ),
            (self.bending_damping / m, "bending damping"),
            ((self.bending_stiffness / m).sqrt(), "bending stiffness"),
            (self.obstacle_damping / m, "obstacle contact damping"),
            (
                (self.obstacle_stiffness / m).sqrt(),
                "obstacle contact stiffness",
            ),
        ]
        .into_iter()
        .fold((0.0, "nothing"), |a, b| if b.0 > a.0 { b } else { a })
    }
}

impl System {
    /// The time step of the elastic-link paper's condition Δt ≤ C_k l / c (eq. 48) over every
    /// element [s], at the strains in `ws` (from the last evaluation), with c the faster of the
    /// axial wave √(EA_t/γ0) (EA_t the tangent stiffness) and the transverse wave √(T/γ0)
    /// (the paper's eq. 49), and l the unstretched element length (the waves travel
    /// √(EA/γ0) metres of unstretched cable per second); and the line and element that set it.
    pub fn wave_step(&self, ws: &Workspace, c_k: Real) -> (Real, usize, usize) {
        let mut best = (Real::INFINITY, 0, 0);
        for li in 0..self.lines.len() {
            let el = &ws.lines[li].elements;
            let mesh = self.line_mesh(ws, li);
            for (e, &k) in mesh.element_section.iter().enumerate() {
                let s = &mesh.sections[k];
                let gamma = s.line_type.mass_per_length;
                let axial = s.law.stiffness.max_tangent() / gamma;
                let transverse = el.tension[e].max(0.0) / gamma;
                let c = axial.max(transverse).sqrt();
                let dt = c_k * s.element_length / c;
                if dt < best.0 {
                    best = (dt, li, e);
                }
            }
        }
        best
    }

    /// Largest stable time step [s] of `scheme` for this system, and what sets it.
    ///
    /// The linearised equations at a node are M ẍ + C ẋ + K x = 0. For an eigenvector, with
    /// the Rayleigh quotients m, c, k, λ² m + λ c + k = 0, so |λ| ≤ max(c/m, √(k/m)) (the
    /// larger root is √(k/m) when underdamped and below c/m when overdamped). We bound c and k
    /// by Gershgorin row sums at every node, and m by the node's smallest mass: the lumped
    /// mass (γ0 + ρA·min(C_an, C_at)) L_node, a third of it for the consistent mass matrix
    /// (whose top mode has that mass), plus a free point's own mass and added mass.
    ///
    /// Rows per adjacent element: axial stiffness 2·EA_max/L0 and damping 2·c/L0. Where the
    /// line can reach the seabed, the contact spring K_g d L0/2 and damper 2ζ√(K_g d γ0) L0/2
    /// act vertically and the friction, linearised about rest, μ|w|π/v_μ · L0/2, horizontally
    /// (DG paper eqs. 15–16). A line resting on the bed is horizontal, so the vertical bound
    /// takes the contact terms alone and the horizontal bound the axial terms plus friction.
    /// The step is R/|λ|max with R the smallest radius of the scheme's stability region over
    /// the left half-plane ([`Scheme::stability_radius`]).
    pub fn stable_step(&self, scheme: Scheme) -> (Real, String) {
        let radius = scheme.stability_radius();
        let env = &self.environment;
        let rho = env.water_density;
        let seabed = &env.seabed;
        let mut point_rows = vec![NodeRows::default(); self.points.len()];
        for (i, p) in self.points.iter().enumerate() {
            if let PointKind::Free {
                mass,
                volume,
                added_mass_coefficient,
                ..
            } = &p.kind
            {
                point_rows[i].mass = mass + rho * volume * added_mass_coefficient;
            }
        }
        let mut worst = 0.0;
        let mut culprit = String::from("nothing (no elements)");
        let (lambda_axial, lambda_bending) =
            crate::formulation::hermite::element_eigenvalue_bounds();
        for l in &self.lines {
            match &l.discretisation {
                Discretisation::Dg(dg) => {
                    // The DG CFL limit (calibrated for SSP-RK3, whose stability region RK4's
                    // contains on both axes, so it serves RK4 too), as a rate for this scheme.
                    let lambda = radius / crate::formulation::dg::stable_step(dg, 1.0);
                    if lambda > worst {
                        worst = lambda;
                        culprit = format!(
                            "the dg CFL limit (axial waves, bending and damping at orders {}) of line {}",
                            dg.sections
                                .iter()
                                .map(|s| s.basis.order.to_string())
                                .collect::<Vec<_>>()
                                .join(", "),
                            l.name
                        );
                    }
                    // A free point at a dg end feels the flux's axial impedance Z = γ0 c as a
                    // damper (T̂ = T⁺ + Z (ν_point − ν⁺)).
                    let n = dg.elements.len();
                    for (p, e) in [(l.end_a, 0), (l.end_b, n - 1)] {
                        let sec = dg.section(e);
                        point_rows[p].axial_damping +=
                            sec.properties.line_type.mass_per_length * sec.wave_speed;
                    }
                }
                Discretisation::Fe { .. } | Discretisation::Hermite(_) => {
                    // A line on a winch: its shortest elements (at its shortest length over the
                    // schedule) give the largest stiffness and damping rows, 2 EA/l₀ and 2c/l₀ over a
                    // mass ∝ l₀ (the rate grows as 1/l₀); its longest reaches the seabed first.
                    let scaled;
                    let (mesh, longest) = match &l.winch {
                        Some(w) => {
                            let ((low, _), (high, _)) = w.payout_range();
                            let length = l.mesh.length();
                            let mut m = l.mesh.clone();
                            m.rescale(&l.mesh, (length + low) / length, 0.0);
                            scaled = m;
                            (&scaled, length + high)
                        }
                        None => (&l.mesh, l.mesh.length()),
                    };
                    let n = mesh.elements();
                    let hermite = matches!(l.discretisation, Discretisation::Hermite(_));
                    let mass_factor = if l.discretisation.consistent_mass() {
                        1.0 / 3.0
                    } else {
                        1.0
                    };
                    // Can this line touch the seabed? Its lowest possible point is its lower end minus
                    // its length.
                    let low = self.points[l.end_a]
                        .position
                        .z
                        .min(self.points[l.end_b].position.z);
                    let reaches_bed = env.depth.is_finite()
                        && seabed.stiffness > 0.0
                        && low - longest <= env.seabed_z();
                    // The obstacles this line may touch, as the seabed: a fixed one within its length
                    // of an end (its bounding ball), a moving one always. Each adds its contact
                    // stiffness k and damping c per unit length over a node's share of the line;
                    // several add (a node wedged between two). Friction is left out: its slope
                    // μ N π / v_μ grows with the normal force N, which here is the tension's pull
                    // round the obstacle, unknown before the run (the seabed's is the wet weight).
                    let touching: Vec<&crate::physics::obstacles::Obstacle> = env
                        .obstacles
                        .iter()
                        .filter(|o| {
                            !matches!(o.motion, crate::model::Motion::Fixed { .. })
                                || [l.end_a, l.end_b].iter().any(|&p| {
                                    let centre = o.kinematics(0.0).centre;
                                    (self.points[p].position - centre).norm() - o.bounding_radius()
                                        <= longest
                                })
                        })
                        .collect();
                    let mut rows = vec![NodeRows::default(); n + 1];
                    let describe =
                        |what: &str, at: String, s: &crate::formulation::SectionProperties| {
                            format!(
                                "{what} at line {} {at} (element length {:.4} m, axial wave speed {:.1} m/s)",
                                l.name,
                                s.element_length,
                                (s.law.stiffness.max_tangent() / s.line_type.mass_per_length)
                                    .sqrt()
                            )
                        };
                    for e in 0..n {
                        let s = mesh.section(e);
                        let lt = &s.line_type;
                        let l0 = s.element_length;
                        let gamma = lt.mass_per_length
                            + rho
                                * s.area
                                * lt.normal_added_mass.min(lt.tangential_added_mass).max(0.0);
                        let mut add = NodeRows {
                            mass: gamma * 0.5 * l0 * mass_factor,
                            axial_damping: 2.0 * s.law.damping / l0,
                            axial_stiffness: 2.0 * s.law.stiffness.max_tangent() / l0,
                            ..Default::default()
                        };
                        if reaches_bed {
                            let kd = seabed.stiffness * lt.diameter;
                            add.contact_stiffness = kd * 0.5 * l0;
                            add.contact_damping = seabed
                                .damping_per_length(lt.diameter, lt.mass_per_length)
                                * 0.5
                                * l0;
                            let wet = (lt.mass_per_length - rho * s.area) * env.gravity;
                            if seabed.friction_coefficient > 0.0 && wet > 0.0 {
                                // per node: the node carries at least half this element
                                add.friction_damping =
                                    seabed.friction_slope(wet, 0.5 * l0) * 0.5 * l0;
                            }
                        }
                        for o in &touching {
                            add.obstacle_stiffness += o.stiffness * 0.5 * l0;
                            add.obstacle_damping +=
                                o.damping_per_length(lt.mass_per_length) * 0.5 * l0;
                        }
                        if hermite {
                            // Element bound (Irons): the assembled line's frequencies are below the
                            // element's, whose pencils scale as λ EA/(γ l²) and λ_b EI/(γ l⁴); the
                            // contact, integrated with the mass's own quadrature, as K_g d/γ.
                            let element = NodeRows {
                                mass: gamma * l0,
                                axial_damping: lambda_axial * s.law.damping / l0,
                                axial_stiffness: lambda_axial * s.law.stiffness.max_tangent() / l0,
                                bending_stiffness: lambda_bending * lt.bending_stiffness
                                    / (l0 * l0 * l0),
                                bending_damping: lambda_bending * lt.bending_damping
                                    / (l0 * l0 * l0),
                                contact_stiffness: 2.0 * add.contact_stiffness,
                                contact_damping: 2.0 * add.contact_damping,
                                friction_damping: 2.0 * add.friction_damping,
                                obstacle_damping: 2.0 * add.obstacle_damping,
                                obstacle_stiffness: 2.0 * add.obstacle_stiffness,
                            };
                            let (lambda, what) = element.bound();
                            if lambda > worst {
                                worst = lambda;
                                culprit = describe(what, format!("element {e}"), s);
                            }
                        }
                        rows[e].add(&add);
                        rows[e + 1].add(&add);
                    }
                    for (node, row) in rows.iter().enumerate() {
                        let end = if node == 0 {
                            Some(l.end_a)
                        } else if node == n {
                            Some(l.end_b)
                        } else {
                            None
                        };
                        if let Some(p) = end {
                            // End nodes move with their point: only free points are unknowns.
                            if self.points[p].free_index.is_some() || self.point_slot[p].is_some() {
                                point_rows[p].add(row);
                            }
                            continue;
                        }
                        if hermite {
                            continue;
                        }
                        let (lambda, what) = row.bound();
                        if lambda > worst {
                            worst = lambda;
                            culprit = describe(
                                what,
                                format!("node {node}"),
                                mesh.section(node.min(n - 1)),
                            );
                        }
                    }
                }
            }
        }
        // A point on a free body moves the body: its line ends act on the body's mass (its
        // smallest translational mass, mass plus the smallest added mass).
        for (p, slot) in self.point_slot.iter().enumerate() {
            if slot.is_some()
                && let PointKind::Body { body, .. } = self.points[p].kind
            {
                let b = &self.bodies[body].body;
                point_rows[p].mass += b.mass + b.added_mass.fixed_rows::<3>(0).min().max(0.0);
            }
        }
        for &b in &self.free_bodies {
            let (lambda, what) = self.bodies[b]
                .body
                .own_rate(self.environment.water_density, self.environment.gravity);
            if lambda > worst {
                worst = lambda;
                culprit = format!("{what} of body {}", self.bodies[b].body.name);
            }
        }
        for (p, row) in point_rows.iter().enumerate() {
            if (self.points[p].free_index.is_some() || self.point_slot[p].is_some())
                && row.mass > 0.0
            {
                let (lambda, what) = row.bound();
                if lambda > worst {
                    worst = lambda;
                    culprit = format!(
                        "{what} at free point {} and its line ends",
                        self.points[p].name
                    );
                }
            }
        }
        if worst == 0.0 {
            return (Real::INFINITY, culprit);
        }
        (radius / worst, culprit)
    }
}
