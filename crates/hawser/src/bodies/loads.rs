//! Loads and mass matrix of one rigid body about its origin, in global axes.

use super::hydrostatics::{Section, Wetted, wetted_prism};
use crate::math::{Mat3, Mat6, Real, Vec3, Vec6, skew};
use crate::model::{Body, Displacement, DragSpeed, RigidKinematics};
use crate::physics::environment::Environment;

/// The loads on a body and its mass matrix, in global axes, about the body origin: the body
/// alone obeys `mass · [a_o; α] = [force; moment]`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyLoads {
    /// Resultant force [N]: weight, buoyancy, fluid inertia, drag, thrust, wind and the rigid
    /// body's centripetal term −m ω × (ω × c).
    pub force: Vec3,
    /// Resultant moment about the body origin [N·m], including −ω × (I_o ω).
    pub moment: Vec3,
    /// Mass matrix about the origin [kg, kg·m, kg·m²]: rigid body plus added mass.
    pub mass: Mat6,
}

impl BodyLoads {
    /// The generalized force [force; moment] [N, N·m], the right-hand side of
    /// `mass · [a_o; α]`.
    pub fn generalized(&self) -> Vec6 {
        Vec6::new(
            self.force.x,
            self.force.y,
            self.force.z,
            self.moment.x,
            self.moment.y,
            self.moment.z,
        )
    }
}

/// Where the water is and what is under it.
struct Immersion {
    /// Submerged volume [m³].
    volume: Real,
    /// Submerged fraction V_sub / V of a shaped displacement; 1 for `Submerged` and `None`.
    fraction: Real,
    /// Where buoyancy acts: the centroid of the submerged volume (the centre of buoyancy
    /// when fully submerged, and for `Submerged` and `None`), from the body origin in global
    /// axes [m].
    buoyancy_centre: Vec3,
    /// Hydrodynamic centre P, where added mass, fluid inertia and drag act: the buoyancy
    /// centre, or the body's `hydrodynamic_centre` when it gives one, from the body origin in
    /// global axes [m].
    centre: Vec3,
}

impl Body {
    /// The loads on the body and its mass matrix at kinematics `k` (pose and velocities; the
    /// accelerations in `k` are not used), in `env` at time `t` [s]. Everything is in global
    /// axes, moments about the body origin; the equations of motion of the body alone are
    /// `mass · [a_o; α] = [force; moment]`. Allocates nothing.
    ///
    /// With R the rotation of `k.orientation`, c = R c_b the centre of gravity, b the centroid
    /// of the submerged volume (the centre of buoyancy when fully submerged), p the
    /// hydrodynamic centre P (b, or the body's `hydrodynamic_centre` when a `Submerged` body
    /// or one without displacement gives it), from the origin:
    ///
    /// ```text
    /// M = [[m 1,      −m [c]× ],      + Jᵀ f blockdiag(R A_t Rᵀ, R A_r Rᵀ) J,
    ///      [m [c]×,   I_o     ]]        J = [[1, −[p]×], [0, 1]],
    /// I_o = R I_G Rᵀ − m [c]× [c]×
    ///
    /// F   = −m g ẑ + ρ g V_s ẑ + (ρ V_s 1 + f A_t) a_w − f A_t ω×(ω×p) + F_drag
    ///       + R F_thrust + F_wind − m ω×(ω×c) + F_bed
    /// M_o = c × (−m g ẑ) + b × ρ g V_s ẑ + p × ((ρ V_s + f A_t) a_w − f A_t ω×(ω×p) + F_drag)
    ///       + R M_drag + R M_thrust + c_w × F_wind − ω × (I_o ω) + M_bed
    /// ```
    ///
    /// - A_t = diag(A₁, A₂, A₃) [kg], A_r = diag(A₄, A₅, A₆) [kg·m²]: the added mass in body
    ///   axes about P, scaled by the submerged fraction f = V_s / V of a `Cylinder` or `Box`
    ///   (f = 1 for `Submerged` and `None`). J moves the added mass from P to the origin:
    ///   the velocity of P is v_o + ω × p, so ½ νᵀ Jᵀ A J ν is the fluid's kinetic energy.
    /// - V_s: the displaced volume, below the local free surface for a `Cylinder` or `Box`
    ///   ([`super::wetted_prism`]); the surface is the plane through η(x_B, y_B, t) with the
    ///   mean slope of η over the body's half-size around B.
    /// - a_w, u_w: the fluid acceleration and velocity at P (`env.fluid_acceleration`,
    ///   `env.fluid_velocity`): the Froude–Krylov force ρ V_s a_w plus the added-mass part
    ///   f A_t a_w, i.e. ρ V_s (1 + C_a,i) a_w,i per body axis.
    /// - F_drag = R F_b with F_b,i = −f (L_i u_i + ½ ρ Q_i s_i u_i), u = Rᵀ (v_o + ω × p −
    ///   u_w) the velocity relative to the water in body axes and s_i = |u_i|, or s_i = |u|
    ///   with [`crate::model::DragSpeed::Magnitude`]; M_drag likewise with Ω = Rᵀ ω and the
    ///   coefficients L₄..₆, Q₄..₆.
    /// - F_wind = ½ ρ_air (C_d A) |u| u, u = U_wind − (v_o + ω × c_w) at the wind centre
    ///   c_w = R c_w,b.
    /// - −m ω×(ω×c) and −ω×(I_o ω) are the rigid body's velocity-dependent inertial terms about
    ///   the moving origin: the body's momentum is m (v_o + ω × c) and its angular momentum
    ///   about the origin m c × v_o + I_o ω.
    ///
    /// - F_bed, M_bed: the seabed's contact force and its moment about the origin over the
    ///   body's shape ([`Body::seabed_contact`]), when the body reaches the bed.
    ///
    /// Members (MoorDyn's rods) add their lumped loads and added mass
    /// ([`super::member_loads`]).
    ///
    /// Left out (docs/bodies.md): the velocity-dependent added-mass terms of Kirchhoff's
    /// equations (Munk moment), the rate of change of the added mass with submergence,
    /// radiation damping and memory, second-order wave loads.
    pub fn loads(&self, k: &RigidKinematics, env: &Environment, t: Real) -> BodyLoads {
        let r = *k.orientation.to_rotation_matrix().matrix();
        let w = k.angular_velocity;
        let m = self.mass;
        let g = env.gravity;
        let z = Vec3::z();

        // Rigid body about the origin.
        let c = r * self.centre_of_gravity;
        let cx = skew(&c);
        let i_o = r * self.inertia * r.transpose() - m * cx * cx;
        let mut mass = Mat6::zeros();
        mass.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&(Mat3::identity() * m));
        mass.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-m * cx));
        mass.fixed_view_mut::<3, 3>(3, 0).copy_from(&(m * cx));
        mass.fixed_view_mut::<3, 3>(3, 3).copy_from(&i_o);
        let weight = -m * g * z;
        let mut force = weight - m * w.cross(&w.cross(&c));
        let mut moment = c.cross(&weight) - w.cross(&(i_o * w));

        // Water: buoyancy at the wet centroid; added mass, fluid inertia and drag at the
        // hydrodynamic centre.
        let wet = self.immersion(k, &r, env, t);
        let p = wet.centre;
        let rho = env.water_density;
        let buoyancy = rho * g * wet.volume * z;
        // Buoyancy joins the loads at P when it acts there (the sum keeps the results of
        // runs bit for bit as before hydrodynamic centres existed), else acts on its own.
        let mut at_p = if wet.buoyancy_centre == p {
            buoyancy
        } else {
            force += buoyancy;
            moment += wet.buoyancy_centre.cross(&buoyancy);
            Vec3::zeros()
        };
        let f = wet.fraction;
        if f > 0.0 {
            let a = &self.added_mass;
            let a_t =
                f * r * Mat3::from_diagonal(&a.fixed_rows::<3>(0).into_owned()) * r.transpose();
            let a_r =
                f * r * Mat3::from_diagonal(&a.fixed_rows::<3>(3).into_owned()) * r.transpose();
            let px = skew(&p);
            // Jᵀ blockdiag(A_t, A_r) J with J = [[1, −[p]×], [0, 1]].
            let a_t_px = a_t * px;
            let mut added = Mat6::zeros();
            added.fixed_view_mut::<3, 3>(0, 0).copy_from(&a_t);
            added.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-a_t_px));
            added.fixed_view_mut::<3, 3>(3, 0).copy_from(&(px * a_t));
            added
                .fixed_view_mut::<3, 3>(3, 3)
                .copy_from(&(a_r - px * a_t_px));
            mass += added;
            // The added mass resists the absolute acceleration of P, whose velocity-dependent
            // part ω × (ω × p) is not in M.
            at_p -= a_t * w.cross(&w.cross(&p));

            let (u_w, a_w) = if env.is_still_at(t) {
                (Vec3::zeros(), Vec3::zeros())
            } else {
                let x_p = k.position + p;
                env.fluid_kinematics(&x_p, t)
            };
            at_p += rho * wet.volume * a_w + a_t * a_w;

            let u = r.transpose() * (k.velocity + w.cross(&p) - u_w);
            let omega = r.transpose() * w;
            let (lin, quad) = (&self.linear_drag, &self.quadratic_drag);
            let mut drag_force = Vec3::zeros();
            let mut drag_moment = Vec3::zeros();
            let (speed, spin) = (u.norm(), omega.norm());
            for i in 0..3 {
                let (s, w) = match self.drag_speed {
                    DragSpeed::Component => (u[i].abs(), omega[i].abs()),
                    DragSpeed::Magnitude => (speed, spin),
                };
                drag_force[i] = -f * (lin[i] * u[i] + 0.5 * rho * quad[i] * s * u[i]);
                drag_moment[i] =
                    -f * (lin[3 + i] * omega[i] + 0.5 * rho * quad[3 + i] * w * omega[i]);
            }
            at_p += r * drag_force;
            moment += r * drag_moment;
        }
        force += at_p;
        moment += p.cross(&at_p);

        // Thrust in body axes, about the origin.
        let (thrust, thrust_moment) = self.thrust.at(t);
        force += r * thrust;
        moment += r * thrust_moment;

        // Wind at its centre.
        if let Some(wind) = &self.wind {
            let cw = r * wind.centre;
            let u = wind.velocity - (k.velocity + w.cross(&cw));
            let fw = 0.5 * env.air_density * wind.drag_area * u.norm() * u;
            force += fw;
            moment += cw.cross(&fw);
        }

        if let Some(c) = self.seabed_contact(k, &r, env) {
            force += c.force;
            moment += c.moment;
        }

        let mut out = BodyLoads {
            force,
            moment,
            mass,
        };
        for member in &self.members {
            super::members::member_loads(member, k, &r, env, t, &mut out);
        }
        out
    }

    /// Submerged volume, fraction and hydrodynamic centre at pose `k` (rotation matrix `r`).
    fn immersion(&self, k: &RigidKinematics, r: &Mat3, env: &Environment, t: Real) -> Immersion {
        let b = r * self.centre_of_buoyancy;
        let centre = r * self.hydrodynamic_centre.unwrap_or(self.centre_of_buoyancy);
        let (section, half_height) = match self.displacement {
            Displacement::None => {
                return Immersion {
                    volume: 0.0,
                    fraction: 1.0,
                    buoyancy_centre: b,
                    centre,
                };
            }
            Displacement::Submerged { volume } => {
                return Immersion {
                    volume,
                    fraction: 1.0,
                    buoyancy_centre: b,
                    centre,
                };
            }
            Displacement::Cylinder { radius, height } => (Section::Circle { radius }, 0.5 * height),
            Displacement::Box {
                length,
                breadth,
                height,
            } => (
                Section::Rectangle {
                    half_length: 0.5 * length,
                    half_breadth: 0.5 * breadth,
                },
                0.5 * height,
            ),
        };
        // The free surface as a plane z = η₀ + s_x (x − x_B) + s_y (y − y_B); under water where
        // n·(x − x_B) + z_B − η₀ < 0 with n = (−s_x, −s_y, 1).
        let x_b = k.position + b;
        let (eta, sx, sy) = if env.waves.is_none() {
            (0.0, 0.0, 0.0)
        } else {
            let d = match section {
                Section::Circle { radius } => radius,
                Section::Rectangle {
                    half_length,
                    half_breadth,
                } => half_length.max(half_breadth),
            };
            let e = |dx: Real, dy: Real| env.surface_elevation(x_b.x + dx, x_b.y + dy, t);
            (
                e(0.0, 0.0),
                (e(d, 0.0) - e(-d, 0.0)) / (2.0 * d),
                (e(0.0, d) - e(0.0, -d)) / (2.0 * d),
            )
        };
        let n = Vec3::new(-sx, -sy, 1.0);
        let wetted: Wetted = wetted_prism(&section, half_height, &(r.transpose() * n), x_b.z - eta);
        let wet_centroid = b + r * wetted.centroid;
        Immersion {
            volume: wetted.volume,
            fraction: wetted.volume / wetted.total_volume,
            buoyancy_centre: wet_centroid,
            centre: wet_centroid,
        }
    }
}
