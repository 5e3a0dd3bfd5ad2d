//! Prescribed motions of rigid bodies (vessels, test rigs): pose, velocity and acceleration of
//! the body origin and the body's rotation, at any time (issue 6 item 2).
//!
//! Axes: global x, y horizontal, z up; body axes x forward, y to port, z up (as
//! [`crate::model::Body`]). A heading ψ is the yaw of the body x axis, measured from global +x
//! toward +y (counter-clockwise seen from above). Euler angles are roll φ, pitch θ, yaw ψ with
//! R = R_z(ψ) R_y(θ) R_x(φ) (body to global): positive roll lowers the starboard side, positive
//! pitch lowers the bow.
//!
//! Every motion gives exact derivatives: analytic ones for the manoeuvre and the RAO motion,
//! the derivatives of the interpolant for tables. Evaluation allocates nothing; everything a
//! motion needs is built by its constructor.
//!
//! docs/motions.md states the conventions and the manoeuvre geometry.

use crate::error::ModelError;
use crate::math::{Quat, Real, Vec3};
use crate::model::ramp;
use crate::physics::waves::Waves;
use std::f64::consts::TAU;

/// Kinematics of a rigid body at one instant, all in global axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidKinematics {
    /// Position of the body origin [m].
    pub position: Vec3,
    /// Rotation from body axes to global axes.
    pub orientation: Quat,
    /// Velocity of the body origin [m/s].
    pub velocity: Vec3,
    /// Angular velocity ω in global axes [rad/s].
    pub angular_velocity: Vec3,
    /// Acceleration of the body origin [m/s²].
    pub acceleration: Vec3,
    /// Angular acceleration dω/dt in global axes [rad/s²].
    pub angular_acceleration: Vec3,
}

impl Default for RigidKinematics {
    fn default() -> Self {
        Self::at_rest(Vec3::zeros(), Quat::identity())
    }
}

impl RigidKinematics {
    /// A body at rest at `position` with `orientation`.
    pub fn at_rest(position: Vec3, orientation: Quat) -> Self {
        Self {
            position,
            orientation,
            velocity: Vec3::zeros(),
            angular_velocity: Vec3::zeros(),
            acceleration: Vec3::zeros(),
            angular_acceleration: Vec3::zeros(),
        }
    }

    /// Position [m], velocity [m/s] and acceleration [m/s²] of the body-fixed point at
    /// `offset` (body axes, from the body origin [m]): ρ = R offset, r = r_o + ρ,
    /// v = v_o + ω × ρ, a = a_o + α × ρ + ω × (ω × ρ).
    #[inline]
    pub fn point(&self, offset: &Vec3) -> (Vec3, Vec3, Vec3) {
        let rho = self.orientation * offset;
        let w = self.angular_velocity;
        (
            self.position + rho,
            self.velocity + w.cross(&rho),
            self.acceleration + self.angular_acceleration.cross(&rho) + w.cross(&w.cross(&rho)),
        )
    }
}

/// A prescribed rigid-body trajectory; t in [s].
#[derive(Clone, Debug, PartialEq)]
pub enum RigidMotion {
    /// Held at a pose.
    Fixed {
        /// Position of the body origin [m].
        position: Vec3,
        /// Orientation.
        orientation: Quat,
    },
    /// r(t) = start + velocity·t, constant orientation.
    ConstantVelocity {
        /// Position of the body origin at t = 0 [m].
        start: Vec3,
        /// Orientation.
        orientation: Quat,
        /// Velocity [m/s].
        velocity: Vec3,
    },
    /// A ship manoeuvre: straight run, turn of constant radius, straight run ([`Manoeuvre`]).
    Manoeuvre(Box<Manoeuvre>),
    /// A 6-DOF table interpolated by cubic splines ([`RigidTimeSeries`]).
    TimeSeries(RigidTimeSeries),
    /// Wave-frequency motion from RAO tables on a mean motion ([`RaoMotion`]).
    Rao(Box<RaoMotion>),
}

impl RigidMotion {
    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        match self {
            RigidMotion::Fixed {
                position,
                orientation,
            } => RigidKinematics::at_rest(*position, *orientation),
            RigidMotion::ConstantVelocity {
                start,
                orientation,
                velocity,
            } => RigidKinematics {
                velocity: *velocity,
                ..RigidKinematics::at_rest(start + velocity * t, *orientation)
            },
            RigidMotion::Manoeuvre(m) => m.kinematics(t),
            RigidMotion::TimeSeries(s) => s.kinematics(t),
            RigidMotion::Rao(r) => r.kinematics(t),
        }
    }
}

fn invalid(what: &str, why: impl Into<String>) -> ModelError {
    ModelError::Invalid {
        what: what.to_string(),
        why: why.into(),
    }
}

fn check(ok: bool, what: &str, why: &str) -> Result<(), ModelError> {
    if ok { Ok(()) } else { Err(invalid(what, why)) }
}

// ---------------------------------------------------------------------------------------------
// Euler angles

/// Orientation, angular velocity ω and angular acceleration dω/dt (in the parent frame) of
/// the rotation R = R_z(ψ) R_y(θ) R_x(φ) from the Euler angles [φ, θ, ψ] [rad], their rates
/// [rad/s] and their second derivatives [rad/s²].
///
/// The kinematic map: ω = ψ̇ ẑ + θ̇ e_y' + φ̇ e_x'', with e_y' = R_z(ψ) ŷ the pitch axis and
/// e_x'' = R_z(ψ) R_y(θ) x̂ the roll axis (the body x axis); differentiating, with
/// de_y'/dt = ψ̇ ẑ × e_y' and de_x''/dt = (ψ̇ ẑ + θ̇ e_y') × e_x'',
/// dω/dt = ψ̈ ẑ + θ̈ e_y' + θ̇ ψ̇ ẑ × e_y' + φ̈ e_x'' + φ̇ (ψ̇ ẑ + θ̇ e_y') × e_x''.
#[inline]
pub fn euler_kinematics(
    angles: [Real; 3],
    rates: [Real; 3],
    accels: [Real; 3],
) -> (Quat, Vec3, Vec3) {
    let [_, theta, psi] = angles;
    let [roll_rate, pitch_rate, yaw_rate] = rates;
    let (sp, cp) = psi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let z = Vec3::z();
    let ey = Vec3::new(-sp, cp, 0.0);
    let ex = Vec3::new(cp * ct, sp * ct, -st);
    let omega = z * yaw_rate + ey * pitch_rate + ex * roll_rate;
    let yaw_pitch = z * yaw_rate + ey * pitch_rate;
    let alpha = z * accels[2]
        + ey * accels[1]
        + z.cross(&ey) * (pitch_rate * yaw_rate)
        + ex * accels[0]
        + yaw_pitch.cross(&ex) * roll_rate;
    (
        Quat::from_euler_angles(angles[0], angles[1], angles[2]),
        omega,
        alpha,
    )
}

// ---------------------------------------------------------------------------------------------
// Manoeuvre

/// What a [`Manoeuvre`] is built from.
#[derive(Clone, Debug, PartialEq)]
pub struct ManoeuvreSpec {
    /// Position of the vessel origin at t = 0 [m]; its z is kept throughout.
    pub start: Vec3,
    /// Initial heading ψ0 [rad], from global +x toward +y.
    pub heading: Real,
    /// Speed U along the track once built up [m/s], > 0.
    pub speed: Real,
    /// Length of the first straight run, from the start to the beginning of the turn [m]
    /// (the build-up happens on it).
    pub straight_before: Real,
    /// Radius R of the circular part of the turn [m], > 0.
    pub turn_radius: Real,
    /// Heading change Θ of the turn [rad]: positive to port (counter-clockwise seen from
    /// above, heading increasing), negative to starboard.
    pub turn_angle: Real,
    /// Length of the straight run after the turn [m]: `Some(L)` stops the vessel at its end
    /// (the speed ramps down over `build_up_time`, ending at rest exactly there), `None` goes
    /// on at speed U on the exit heading for ever.
    pub straight_after: Option<Real>,
    /// Duration T_b of the smooth speed build-up from rest [s] (and of the ramp-down when the
    /// vessel stops); 0 for an impulsive start at full speed.
    pub build_up_time: Real,
    /// Length L_c of each of the two curvature transitions (clothoids) at the ends of the
    /// circular arc [m]; 0 for a curvature that jumps from 0 to 1/R (and an acceleration that
    /// jumps by U²/R).
    pub transition_length: Real,
}

/// One piece of the track: heading ψ(σ) = ψ_0 + κ_0 σ + ½ κ' σ² along its arc length σ.
#[derive(Clone, Copy, Debug, PartialEq)]
struct TrackPiece {
    /// Arc length of the track at the start of the piece [m].
    s0: Real,
    /// Horizontal position (x, y) at its start [m].
    x0: Real,
    y0: Real,
    /// Heading ψ_0 at its start [rad].
    heading: Real,
    /// Curvature κ_0 at its start [1/m] (signed: positive turning to port).
    curvature: Real,
    /// Rate of change of curvature κ' [1/m²] (non-zero on clothoids only).
    curvature_rate: Real,
}

impl TrackPiece {
    /// Position (x, y), heading, curvature and curvature rate at σ [m] from the start.
    #[inline]
    fn at(&self, sigma: Real) -> (Real, Real, Real, Real, Real) {
        let k = self.curvature + self.curvature_rate * sigma;
        let psi = self.heading + (self.curvature + 0.5 * self.curvature_rate * sigma) * sigma;
        let (dx, dy) = if self.curvature_rate != 0.0 {
            clothoid_displacement(self.heading, self.curvature, self.curvature_rate, sigma)
        } else if self.curvature != 0.0 {
            // Circular arc: closed form.
            let (s1, c1) = psi.sin_cos();
            let (s0, c0) = self.heading.sin_cos();
            ((s1 - s0) / self.curvature, (c0 - c1) / self.curvature)
        } else {
            let (s0, c0) = self.heading.sin_cos();
            (sigma * c0, sigma * s0)
        };
        (self.x0 + dx, self.y0 + dy, psi, k, self.curvature_rate)
    }
}

/// Nodes and weights of 8-point Gauss–Legendre quadrature on [−1, 1] (positive half).
const GAUSS8: [(Real, Real); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// ∫₀^σ (cos ψ(u), sin ψ(u)) du with ψ(u) = ψ0 + κ0 u + ½ κ' u² (a clothoid, Fresnel
/// integrals), by composite 8-point Gauss–Legendre quadrature on panels over which ψ changes
/// by at most 0.5 rad: the rule is exact for polynomials of degree 15, and the Taylor
/// remainder of cos over 0.5 rad at that degree is below 0.5¹⁶/16! ≈ 7e-19, so the result is
/// exact to rounding.
fn clothoid_displacement(psi0: Real, k0: Real, kr: Real, sigma: Real) -> (Real, Real) {
    let turn = k0.abs() * sigma + 0.5 * kr.abs() * sigma * sigma;
    let panels = clothoid_panels(turn);
    let h = sigma / panels as Real;
    let (mut x, mut y) = (0.0, 0.0);
    for p in 0..panels {
        let mid = (p as Real + 0.5) * h;
        for (node, weight) in GAUSS8 {
            for u in [mid - 0.5 * h * node, mid + 0.5 * h * node] {
                let (s, c) = (psi0 + (k0 + 0.5 * kr * u) * u).sin_cos();
                x += weight * c;
                y += weight * s;
            }
        }
    }
    (0.5 * h * x, 0.5 * h * y)
}

/// Most quadrature panels of one clothoid evaluation: a clothoid of [`Manoeuvre`] turns by at
/// most L_c/(2R) ≤ |Θ|/2 ≤ [`Manoeuvre::MAX_TURN_ANGLE`]/2, which takes 629 panels of 0.5 rad;
/// the cap only bounds the work for a turn no valid manoeuvre has (∞ or NaN from an
/// overflowing curvature rate).
const MAX_CLOTHOID_PANELS: usize = 1024;

/// Panels of 0.5 rad for a clothoid that turns by `turn` [rad]: at least 1, at most
/// [`MAX_CLOTHOID_PANELS`] (NaN counts as one panel).
fn clothoid_panels(turn: Real) -> usize {
    if turn.is_nan() {
        return 1;
    }
    ((turn / 0.5).ceil().min(MAX_CLOTHOID_PANELS as Real) as usize).max(1)
}

/// A ship manoeuvre (position-vector paper §3.2, the sea trial's 270° turn): a straight run
/// at speed U on the initial heading, a turn through the signed angle Θ whose middle part is
/// a circular arc of radius R, then a straight run on the heading ψ0 + Θ. The vessel's yaw
/// follows the track tangent; roll and pitch stay zero and z stays at the start's.
///
/// Track (arc length s from the start): straight of length L1; entry clothoid of length L_c
/// (curvature rising linearly from 0 to κ = sign(Θ)/R); circular arc of length R|Θ| − L_c
/// (heading change Θ − sign(Θ) L_c/R); exit clothoid of length L_c (κ back to 0); straight.
/// Each clothoid turns the heading by L_c/(2R), so the heading change is Θ exactly, whatever
/// L_c. With L_c = 0 the turn is one circular arc and the acceleration jumps by U²/R at its
/// ends; with L_c > 0 the curvature, hence the acceleration, is continuous (only the angular
/// acceleration jumps). The arc is exactly circular either way.
///
/// Speed: ṡ(t) = U [B(t) − B(t − t_stop)], with B(t) = b(t/T_b) the quintic smoothstep
/// b = 10τ³ − 15τ⁴ + 6τ⁵ (the build-up ramp of prescribed motions, [`crate::model::ramp`]): the
/// vessel starts from rest with zero acceleration and reaches U at T_b with zero acceleration
/// (b' = b'' = 0 at both ends), so a towed cable gets no impulsive start. The distance covered during the build-up is
/// U T_b / 2: s(t) = U T_b (5τ⁴/2 − 3τ⁵ + τ⁶) for t < T_b, U (t − T_b/2) after. With a
/// `straight_after`, the vessel stops at the end of the track: t_stop = s_end / U, and the
/// ramp-down mirrors the build-up, ending at rest at s_end.
///
/// Kinematics: with T = (cos ψ, sin ψ, 0), N = ẑ × T, v = ṡ T, a = s̈ T + κ ṡ² N,
/// ω = κ ṡ ẑ, dω/dt = (κ' ṡ² + κ s̈) ẑ.
#[derive(Clone, Debug, PartialEq)]
pub struct Manoeuvre {
    spec: ManoeuvreSpec,
    pieces: [TrackPiece; 5],
    /// Arc length at the end of the track (end of `straight_after`) [m], or ∞.
    end: Real,
    /// Time the ramp-down starts [s] (∞: never).
    stop_time: Real,
}

impl Manoeuvre {
    /// Largest heading change |Θ| of a turn [rad]: 100 full turns (36 000°). A clothoid is
    /// integrated by quadrature at a cost proportional to the heading it turns (up to |Θ|/2),
    /// so the bound keeps every evaluation of the track to at most 629 panels.
    pub const MAX_TURN_ANGLE: Real = 200.0 * std::f64::consts::PI;

    /// Shortest curvature transition L_c, as a fraction of the turn radius R (other than 0):
    /// a clothoid shorter than 10⁻⁶ R has a curvature rate κ/L_c that the arc lengths of the
    /// track cannot resolve (it overflows for a subnormal L_c), and no vessel turns that way.
    pub const MIN_TRANSITION_RATIO: Real = 1e-6;

    /// Builds the track; refuses non-finite values, a speed or radius ≤ 0, negative lengths or
    /// build-up time, a turn beyond [`Self::MAX_TURN_ANGLE`], transitions shorter than
    /// [`Self::MIN_TRANSITION_RATIO`] R (other than 0) or longer than the turn (2 L_c ≤ 2 R|Θ|
    /// is needed so that the arc is not negative: L_c ≤ R|Θ|), and a stopping track shorter
    /// than the build-up and ramp-down distances U T_b.
    pub fn new(spec: ManoeuvreSpec) -> Result<Self, ModelError> {
        let s = &spec;
        check(
            s.start.iter().all(|x| x.is_finite()) && s.heading.is_finite(),
            "manoeuvre start",
            "the start position and heading must be finite",
        )?;
        check(
            s.speed.is_finite() && s.speed > 0.0,
            "manoeuvre speed",
            "the speed must be > 0 m/s",
        )?;
        check(
            s.turn_radius.is_finite() && s.turn_radius > 0.0,
            "manoeuvre turn_radius",
            "the turn radius must be > 0 m",
        )?;
        check(
            s.turn_angle.is_finite(),
            "manoeuvre turn_angle",
            "the turn angle must be finite",
        )?;
        check(
            s.turn_angle.abs() <= Self::MAX_TURN_ANGLE,
            "manoeuvre turn_angle",
            "the turn angle must be at most 100 full turns (36000°) either way",
        )?;
        for (v, what) in [
            (s.straight_before, "manoeuvre straight_before"),
            (s.build_up_time, "manoeuvre build_up_time"),
            (s.transition_length, "manoeuvre transition_length"),
            (s.straight_after.unwrap_or(0.0), "manoeuvre straight_after"),
        ] {
            check(v.is_finite() && v >= 0.0, what, "must be finite and ≥ 0")?;
        }
        let r = s.turn_radius;
        let turn = s.turn_angle;
        let lc = if turn == 0.0 {
            0.0
        } else {
            s.transition_length
        };
        check(
            lc == 0.0 || lc >= Self::MIN_TRANSITION_RATIO * r,
            "manoeuvre transition_length",
            "a curvature transition must be 0 or at least 1e-6 of the turn radius",
        )?;
        check(
            lc <= r * turn.abs() * (1.0 + 1e-12),
            "manoeuvre transition_length",
            "the curvature transitions turn the heading by L_c/(2R) each: L_c must be ≤ R |Θ| \
             (the turn's arc length)",
        )?;
        let k = if turn == 0.0 { 0.0 } else { turn.signum() / r };
        let arc = (r * turn.abs() - lc).max(0.0);
        let mut pieces = [TrackPiece {
            s0: 0.0,
            x0: s.start.x,
            y0: s.start.y,
            heading: s.heading,
            curvature: 0.0,
            curvature_rate: 0.0,
        }; 5];
        // (length, curvature at start, curvature rate) of pieces 0..4.
        let plan = [
            (s.straight_before, 0.0, 0.0),
            (lc, 0.0, if lc > 0.0 { k / lc } else { 0.0 }),
            (arc, k, 0.0),
            (lc, k, if lc > 0.0 { -k / lc } else { 0.0 }),
        ];
        for i in 0..plan.len() {
            let (x, y, psi, _, _) = pieces[i].at(plan[i].0);
            let (_, curvature, curvature_rate) =
                plan.get(i + 1).copied().unwrap_or((0.0, 0.0, 0.0));
            pieces[i + 1] = TrackPiece {
                s0: pieces[i].s0 + plan[i].0,
                x0: x,
                y0: y,
                heading: psi,
                curvature,
                curvature_rate,
            };
        }
        // The exit heading is ψ0 + Θ exactly (the pieces' sum differs by rounding).
        pieces[4].heading = s.heading + turn;
        let (end, stop_time) = match s.straight_after {
            Some(l) => {
                let end = pieces[4].s0 + l;
                check(
                    end >= s.speed * s.build_up_time,
                    "manoeuvre straight_after",
                    "the track (straight_before + turn + straight_after) must be at least as long \
                     as the build-up and ramp-down distance U·T_b",
                )?;
                (end, end / s.speed)
            }
            None => (Real::INFINITY, Real::INFINITY),
        };
        Ok(Self {
            spec,
            pieces,
            end,
            stop_time,
        })
    }

    /// What it was built from.
    pub fn spec(&self) -> &ManoeuvreSpec {
        &self.spec
    }

    /// Arc lengths [m] at the start of the turn (end of the first straight), the start and end
    /// of its circular arc, and its end (start of the second straight).
    pub fn turn_arc_lengths(&self) -> [Real; 4] {
        [
            self.pieces[1].s0,
            self.pieces[2].s0,
            self.pieces[3].s0,
            self.pieces[4].s0,
        ]
    }

    /// Centre (x, y) of the circular arc of the turn [m] (`None` without a turn).
    pub fn turn_centre(&self) -> Option<(Real, Real)> {
        let p = &self.pieces[2];
        if p.curvature == 0.0 {
            return None;
        }
        let (s, c) = p.heading.sin_cos();
        let r = 1.0 / p.curvature;
        Some((p.x0 - r * s, p.y0 + r * c))
    }

    /// Arc length at which the vessel comes to rest [m] (∞ when it goes on for ever).
    pub fn track_end(&self) -> Real {
        self.end
    }

    /// Arc length s [m], speed ṡ [m/s] and its rate s̈ [m/s²] along the track at time t [s].
    pub fn arc_length(&self, t: Real) -> (Real, Real, Real) {
        let u = self.spec.speed;
        let (s1, v1, a1) = build_up(t, self.spec.build_up_time);
        let (s2, v2, a2) = build_up(t - self.stop_time, self.spec.build_up_time);
        if self.stop_time.is_finite() && t >= self.stop_time + self.spec.build_up_time {
            return (self.end, 0.0, 0.0);
        }
        (u * (s1 - s2), u * (v1 - v2), u * (a1 - a2))
    }

    /// Pose of the track at arc length s [m]: (x, y) [m], heading [rad], curvature [1/m] and
    /// its rate along the track [1/m²].
    pub fn track(&self, s: Real) -> (Real, Real, Real, Real, Real) {
        let s = s.max(0.0);
        let i = self.pieces[1..].iter().take_while(|p| p.s0 <= s).count();
        let p = &self.pieces[i];
        p.at(s - p.s0)
    }

    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        let (s, sd, sdd) = self.arc_length(t);
        let (x, y, psi, k, kr) = self.track(s);
        let (sn, cs) = psi.sin_cos();
        let tangent = Vec3::new(cs, sn, 0.0);
        let normal = Vec3::new(-sn, cs, 0.0);
        RigidKinematics {
            position: Vec3::new(x, y, self.spec.start.z),
            orientation: Quat::from_axis_angle(&Vec3::z_axis(), psi),
            velocity: tangent * sd,
            angular_velocity: Vec3::new(0.0, 0.0, k * sd),
            acceleration: tangent * sdd + normal * (k * sd * sd),
            angular_acceleration: Vec3::new(0.0, 0.0, kr * sd * sd + k * sdd),
        }
    }
}

/// The integral S(t) = ∫₀ᵗ b(t'/T) dt' [s] of the build-up ramp b (the quintic smoothstep of
/// [`crate::model::ramp`]), with b and db/dt: 0 before t = 0, T (5τ⁴/2 − 3τ⁵ + τ⁶) during the
/// build-up (τ = t/T), t − T/2 after. With T = 0, a step at t = 0 (full speed from t = 0 on).
fn build_up(t: Real, duration: Real) -> (Real, Real, Real) {
    if duration <= 0.0 {
        // An impulsive start: full speed from t = 0 on.
        return if t < 0.0 {
            (0.0, 0.0, 0.0)
        } else {
            (t, 1.0, 0.0)
        };
    }
    if t <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    if t >= duration {
        return (t - 0.5 * duration, 1.0, 0.0);
    }
    let x = t / duration;
    let x4 = x * x * x * x;
    let (b, db, _) = ramp(t, duration);
    (duration * x4 * (2.5 - 3.0 * x + x * x), b, db)
}

// ---------------------------------------------------------------------------------------------
// 6-DOF time series

/// A 6-DOF motion table: times and, per channel (x, y, z [m], roll, pitch, yaw [rad]), a cubic
/// spline with not-a-knot end conditions (the third derivative continuous at the second and
/// the last-but-one times): position, velocity and acceleration are continuous (C²), and for
/// a smooth motion sampled every h the interpolant's errors are O(h⁴), O(h³) and O(h²).
/// With three rows a channel is the interpolating parabola, with two a straight line, with one
/// a constant. Outside the table the motion is held at the first or last pose, at rest.
///
/// Angles are unwrapped by the constructor (multiples of 2π added so that consecutive values
/// differ by less than π), so a yaw going through ±180° does not spin the vessel round. The
/// orientation is R = R_z(ψ) R_y(θ) R_x(φ), and the angular velocity and acceleration follow
/// from the splines' rates through the kinematic map of [`euler_kinematics`].
#[derive(Clone, Debug, PartialEq)]
pub struct RigidTimeSeries {
    times: Vec<Real>,
    /// x, y, z, roll, pitch, yaw at each time.
    values: Vec<[Real; 6]>,
    /// Second derivatives of the splines at each time.
    second: Vec<[Real; 6]>,
}

impl RigidTimeSeries {
    /// Builds the splines from strictly increasing `times` [s], `positions` of the body origin
    /// [m] and `angles` [roll, pitch, yaw] [rad] at each time.
    pub fn new(
        times: Vec<Real>,
        positions: &[Vec3],
        angles: &[[Real; 3]],
    ) -> Result<Self, ModelError> {
        let n = times.len();
        check(
            n >= 1 && positions.len() == n && angles.len() == n,
            "time series",
            "needs at least one row, and as many positions and angles as times",
        )?;
        check(
            times.windows(2).all(|w| w[1] > w[0]) && times.iter().all(|t| t.is_finite()),
            "time series",
            "the times must be finite and strictly increasing",
        )?;
        check(
            positions
                .iter()
                .flatten()
                .chain(angles.iter().flatten())
                .all(|x| x.is_finite()),
            "time series",
            "positions and angles must be finite",
        )?;
        let mut values: Vec<[Real; 6]> = positions
            .iter()
            .zip(angles)
            .map(|(p, a)| [p.x, p.y, p.z, a[0], a[1], a[2]])
            .collect();
        for i in 1..n {
            let previous = values[i - 1];
            for (angle, before) in values[i][3..].iter_mut().zip(&previous[3..]) {
                *angle -= TAU * ((*angle - before) / TAU).round();
            }
        }
        let mut second = vec![[0.0; 6]; n];
        let mut channel = vec![0.0; n];
        let mut m = vec![0.0; n];
        for c in 0..6 {
            for i in 0..n {
                channel[i] = values[i][c];
            }
            not_a_knot_second_derivatives(&times, &channel, &mut m);
            for i in 0..n {
                second[i][c] = m[i];
            }
        }
        Ok(Self {
            times,
            values,
            second,
        })
    }

    /// Times of the table [s].
    pub fn times(&self) -> &[Real] {
        &self.times
    }

    /// Channel values [x, y, z, roll, pitch, yaw] (m, rad; angles unwrapped), their rates and
    /// their second derivatives at time t [s].
    pub fn channels(&self, t: Real) -> ([Real; 6], [Real; 6], [Real; 6]) {
        let n = self.times.len();
        if n == 1 || t <= self.times[0] {
            return (self.values[0], [0.0; 6], [0.0; 6]);
        }
        if t >= self.times[n - 1] {
            return (self.values[n - 1], [0.0; 6], [0.0; 6]);
        }
        let k = self.times.partition_point(|&tk| tk <= t).clamp(1, n - 1) - 1;
        let h = self.times[k + 1] - self.times[k];
        let a = (self.times[k + 1] - t) / h;
        let b = 1.0 - a;
        let (y0, y1) = (&self.values[k], &self.values[k + 1]);
        let (m0, m1) = (&self.second[k], &self.second[k + 1]);
        let mut y = [0.0; 6];
        let mut dy = [0.0; 6];
        let mut ddy = [0.0; 6];
        for c in 0..6 {
            y[c] = a * y0[c]
                + b * y1[c]
                + ((a * a * a - a) * m0[c] + (b * b * b - b) * m1[c]) * h * h / 6.0;
            dy[c] = (y1[c] - y0[c]) / h - (3.0 * a * a - 1.0) / 6.0 * h * m0[c]
                + (3.0 * b * b - 1.0) / 6.0 * h * m1[c];
            ddy[c] = a * m0[c] + b * m1[c];
        }
        (y, dy, ddy)
    }

    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        let (y, dy, ddy) = self.channels(t);
        let (orientation, angular_velocity, angular_acceleration) = euler_kinematics(
            [y[3], y[4], y[5]],
            [dy[3], dy[4], dy[5]],
            [ddy[3], ddy[4], ddy[5]],
        );
        RigidKinematics {
            position: Vec3::new(y[0], y[1], y[2]),
            orientation,
            velocity: Vec3::new(dy[0], dy[1], dy[2]),
            angular_velocity,
            acceleration: Vec3::new(ddy[0], ddy[1], ddy[2]),
            angular_acceleration,
        }
    }
}

/// Second derivatives M_i of the not-a-knot cubic spline through (t_i, y_i) into `m`.
///
/// Interior equations h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (d_i − d_{i−1}),
/// d_i = (y_{i+1} − y_i)/h_i; not-a-knot: (M_1 − M_0)/h_0 = (M_2 − M_1)/h_1 and likewise at the
/// other end, substituted into the first and last interior equations, leaving a tridiagonal
/// system in M_1 … M_{n−2} solved by the Thomas algorithm. Three points give the parabola
/// (M constant), two or one a straight line or constant (M = 0).
fn not_a_knot_second_derivatives(t: &[Real], y: &[Real], m: &mut [Real]) {
    let n = t.len();
    m.iter_mut().for_each(|v| *v = 0.0);
    if n < 3 {
        return;
    }
    let h: Vec<Real> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let d: Vec<Real> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
    if n == 3 {
        let c = 2.0 * (d[1] - d[0]) / (h[0] + h[1]);
        m.iter_mut().for_each(|v| *v = c);
        return;
    }
    // Unknowns M_1 .. M_{n-2}: rows i = 1 .. n-2 with sub, diag, sup, rhs.
    let k = n - 2;
    let mut sub = vec![0.0; k];
    let mut diag = vec![0.0; k];
    let mut sup = vec![0.0; k];
    let mut rhs = vec![0.0; k];
    for r in 0..k {
        let i = r + 1;
        sub[r] = h[i - 1];
        diag[r] = 2.0 * (h[i - 1] + h[i]);
        sup[r] = h[i];
        rhs[r] = 6.0 * (d[i] - d[i - 1]);
    }
    // M_0 = M_1 (1 + h0/h1) − M_2 h0/h1.
    let (h0, h1) = (h[0], h[1]);
    diag[0] += h0 * (1.0 + h0 / h1);
    sup[0] -= h0 * h0 / h1;
    // M_{n-1} = M_{n-2} (1 + h_{n-2}/h_{n-3}) − M_{n-3} h_{n-2}/h_{n-3}.
    let (ha, hb) = (h[n - 3], h[n - 2]);
    diag[k - 1] += hb * (1.0 + hb / ha);
    sub[k - 1] -= hb * hb / ha;
    // Thomas.
    for r in 1..k {
        let w = sub[r] / diag[r - 1];
        diag[r] -= w * sup[r - 1];
        rhs[r] -= w * rhs[r - 1];
    }
    m[k] = rhs[k - 1] / diag[k - 1];
    for r in (0..k - 1).rev() {
        m[r + 1] = (rhs[r] - sup[r] * m[r + 2]) / diag[r];
    }
    m[0] = m[1] * (1.0 + h0 / h1) - m[2] * h0 / h1;
    m[n - 1] = m[n - 2] * (1.0 + hb / ha) - m[n - 3] * hb / ha;
}

// ---------------------------------------------------------------------------------------------
// RAO motion

/// Displacement RAOs of a vessel: for each wave frequency and heading, the complex response
/// per unit wave amplitude of surge, sway, heave [m/m] and roll, pitch, yaw [rad/m], in the
/// vessel's axes about its origin (the RAO origin, also the phase origin).
///
/// Convention (docs/motions.md): a wave component η = a cos(ωt − k·x_ref − φ) at the RAO
/// origin x_ref produces the response ξ_k = a |RAO_k| cos(ωt − k·x_ref − φ − lag_k): the
/// phase is a **lag** behind the wave crest at the RAO origin. The heading is the direction of
/// propagation relative to the vessel x axis, positive toward the vessel's +y (port): 0 =
/// following seas (waves travelling from stern to bow), 90° = waves travelling toward port.
/// Stored as complex numbers H = |RAO| e^{−i lag}, so that ξ = a Re[H e^{i(ωt − k·x_ref − φ)}].
///
/// Interpolation: linear in the angular frequency and in the heading, of the real and
/// imaginary parts of H (not of amplitude and phase, which would need phase unwrapping).
/// Headings are periodic: the table's headings are taken modulo 360° and a heading between the
/// last and the first (+360°) is interpolated across the gap, so give the full circle (hawser
/// applies no port–starboard symmetry). Frequencies below the lowest tabulated one take the
/// lowest one's RAO (long waves: the responses tend to finite limits, e.g. heave → 1); above
/// the highest one the response is zero (short waves do not move a vessel).
#[derive(Clone, Debug, PartialEq)]
pub struct RaoTable {
    /// Angular frequencies [rad/s], strictly increasing.
    frequencies: Vec<Real>,
    /// Headings [rad] in [0, 2π), strictly increasing.
    headings: Vec<Real>,
    /// H per (frequency, heading), frequency-major: [re, im] for surge, sway, heave, roll,
    /// pitch, yaw.
    values: Vec<[[Real; 2]; 6]>,
}

impl RaoTable {
    /// A table from angular `frequencies` [rad/s] (strictly increasing, > 0), `headings` [rad]
    /// (any order; distinct modulo 2π, except that a heading repeated modulo 2π with the same
    /// RAOs — 0° and 360°, −180° and 180° — is dropped), and per (frequency, heading),
    /// frequency-major, the amplitudes (surge, sway, heave [m/m]; roll, pitch, yaw [rad/m]) and
    /// phase lags [rad] of the six DOFs.
    pub fn new(
        frequencies: Vec<Real>,
        headings: &[Real],
        amplitudes: &[[Real; 6]],
        phases: &[[Real; 6]],
    ) -> Result<Self, ModelError> {
        let (nf, nh) = (frequencies.len(), headings.len());
        check(
            nf >= 1 && nh >= 1 && amplitudes.len() == nf * nh && phases.len() == nf * nh,
            "RAO table",
            "needs at least one frequency and one heading, and one row per frequency and heading",
        )?;
        check(
            frequencies.iter().all(|w| w.is_finite() && *w > 0.0)
                && frequencies.windows(2).all(|w| w[1] > w[0]),
            "RAO table",
            "the frequencies must be > 0 and strictly increasing",
        )?;
        check(
            headings.iter().all(|h| h.is_finite())
                && amplitudes
                    .iter()
                    .chain(phases)
                    .flatten()
                    .all(|x| x.is_finite()),
            "RAO table",
            "headings, amplitudes and phases must be finite",
        )?;
        // Headings in [0, 2π), sorted, duplicates merged.
        let mut order: Vec<(Real, usize)> = headings
            .iter()
            .enumerate()
            .map(|(j, h)| {
                let mut w = h.rem_euclid(TAU);
                if w >= TAU - 1e-12 {
                    w = 0.0;
                }
                (w, j)
            })
            .collect();
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        let complex = |f: usize, j: usize| -> [[Real; 2]; 6] {
            let mut h = [[0.0; 2]; 6];
            for d in 0..6 {
                let (s, c) = phases[f * nh + j][d].sin_cos();
                let a = amplitudes[f * nh + j][d];
                h[d] = [a * c, -a * s];
            }
            h
        };
        let mut kept: Vec<(Real, usize)> = Vec::with_capacity(nh);
        for &(w, j) in &order {
            if let Some(&(w0, j0)) = kept.last()
                && (w - w0).abs() < 1e-9
            {
                let same = (0..nf).all(|f| {
                    let (a, b) = (complex(f, j), complex(f, j0));
                    a.iter()
                        .flatten()
                        .zip(b.iter().flatten())
                        .all(|(x, y)| (x - y).abs() <= 1e-9 * (1.0 + x.abs()))
                });
                if !same {
                    return Err(invalid(
                        "RAO table",
                        format!(
                            "headings {:.6}° and {:.6}° are the same direction but have \
                             different RAOs",
                            headings[j0].to_degrees(),
                            headings[j].to_degrees()
                        ),
                    ));
                }
                continue;
            }
            kept.push((w, j));
        }
        let mut values = Vec::with_capacity(nf * kept.len());
        for f in 0..nf {
            for &(_, j) in &kept {
                values.push(complex(f, j));
            }
        }
        Ok(Self {
            frequencies,
            headings: kept.iter().map(|k| k.0).collect(),
            values,
        })
    }

    /// Angular frequencies [rad/s].
    pub fn frequencies(&self) -> &[Real] {
        &self.frequencies
    }

    /// Headings [rad] in [0, 2π).
    pub fn headings(&self) -> &[Real] {
        &self.headings
    }

    /// Frequency bracket (index, weight of the next) of ω [rad/s]; `None` above the table.
    fn frequency_bracket(&self, omega: Real) -> Option<(usize, Real)> {
        let f = &self.frequencies;
        let n = f.len();
        if omega > f[n - 1] {
            return None;
        }
        if omega <= f[0] || n == 1 {
            return Some((0, 0.0));
        }
        let i = f.partition_point(|&w| w <= omega).clamp(1, n - 1) - 1;
        Some((i, (omega - f[i]) / (f[i + 1] - f[i])))
    }

    /// Heading bracket of β [rad]: (index j, index of the next, weight of the next, the
    /// bracket's width [rad]; 0 with a single heading).
    #[inline]
    fn heading_bracket(&self, beta: Real) -> (usize, usize, Real, Real) {
        let h = &self.headings;
        let n = h.len();
        if n == 1 {
            return (0, 0, 0.0, 0.0);
        }
        let b = beta.rem_euclid(TAU);
        let i = h.partition_point(|&x| x <= b);
        if i == 0 || i == n {
            // Across the gap from the last heading to the first + 2π.
            let width = h[0] + TAU - h[n - 1];
            let from_last = (b - h[n - 1]).rem_euclid(TAU);
            return (n - 1, 0, from_last / width, width);
        }
        let width = h[i] - h[i - 1];
        (i - 1, i, (b - h[i - 1]) / width, width)
    }

    /// The complex RAOs H [m/m or rad/m] of the six DOFs at ω [rad/s] and heading β [rad]
    /// (interpolated as the type's documentation says).
    pub fn at(&self, omega: Real, heading: Real) -> [[Real; 2]; 6] {
        match self.frequency_bracket(omega) {
            None => [[0.0; 2]; 6],
            Some((i, wf)) => self.interpolate(i, wf, heading).0,
        }
    }

    /// H and dH/dβ [per rad] at frequency bracket (i, wf) and heading β [rad].
    #[inline]
    fn interpolate(&self, i: usize, wf: Real, beta: Real) -> ([[Real; 2]; 6], [[Real; 2]; 6]) {
        let nh = self.headings.len();
        let (j0, j1, wh, width) = self.heading_bracket(beta);
        let i1 = (i + 1).min(self.frequencies.len() - 1);
        let (a, b, c, d) = (
            &self.values[i * nh + j0],
            &self.values[i * nh + j1],
            &self.values[i1 * nh + j0],
            &self.values[i1 * nh + j1],
        );
        let mut h = [[0.0; 2]; 6];
        let mut dh = [[0.0; 2]; 6];
        for k in 0..6 {
            for p in 0..2 {
                let lo = a[k][p] + wh * (b[k][p] - a[k][p]);
                let hi = c[k][p] + wh * (d[k][p] - c[k][p]);
                h[k][p] = lo + wf * (hi - lo);
                if width > 0.0 {
                    let slope_lo = b[k][p] - a[k][p];
                    let slope_hi = d[k][p] - c[k][p];
                    dh[k][p] = (slope_lo + wf * (slope_hi - slope_lo)) / width;
                }
            }
        }
        (h, dh)
    }
}

/// One wave component as the RAO motion needs it.
#[derive(Clone, Debug, PartialEq)]
struct RaoWave {
    amplitude: Real,
    omega: Real,
    kx: Real,
    ky: Real,
    phase: Real,
    direction: Real,
    /// Frequency bracket in the RAO table.
    bracket: (usize, Real),
}

/// Wave-frequency motion of a vessel from displacement RAOs ([`RaoTable`]), driven by the same
/// wave field as the lines, superposed on a mean motion (fixed, constant velocity or a
/// manoeuvre).
///
/// With the sea's components (a_j, ω_j, k_j, β_j, φ_j) and θ_j = k_j·x̄(t) − ω_j t + φ_j the
/// wave phase at the vessel's **mean** position x̄(t), the response of DOF k is
///
///   ξ_k(t) = r(t) Σ_j a_j Re[H_k(ω_j, β_j − ψ̄(t)) e^{−iθ_j}]
///          = r(t) Σ_j a_j |H_k| cos(ω_j t − k_j·x̄ − φ_j − lag_k),
///
/// r the sea's build-up ramp ([`crate::physics::waves::WaveSpec::ramp_time`]) and ψ̄ the mean
/// heading (the yaw of the mean orientation). Taking the phase at the moving mean position
/// gives a moving vessel the encounter frequency ω_j − k_j·v̄ in its response; the RAO itself
/// is taken at the wave's absolute frequency ω_j (the table is assumed to be for the vessel's
/// speed). Derivatives are exact: with E = e^{−iθ}, dθ/dt = k·v̄ − ω, d²θ/dt² = k·ā and
/// dH/dt = −(∂H/∂β) dψ̄/dt (the heading interpolation is linear, so ∂²H/∂β² = 0 inside a
/// bracket), ξ̇ = a Re[Ḣ E + H Ė], ξ̈ = a Re[Ḧ E + 2 Ḣ Ė + H Ë]. The mean heading rate is the
/// mean angular velocity's z component (exact for mean motions without roll and pitch).
///
/// Surge, sway and heave are displacements of the origin along the mean body axes; roll, pitch
/// and yaw are Euler angles R_e = R_z(ξ6) R_y(ξ5) R_x(ξ4) relative to the mean orientation R̄:
/// R = R̄ R_e, and with ρ = R̄ d the kinematics compose as those of a body moving in a moving
/// frame: v = v̄ + ω̄ × ρ + R̄ ḋ, a = ā + α̅ × ρ + ω̄ × (ω̄ × ρ) + 2 ω̄ × R̄ ḋ + R̄ d̈,
/// ω = ω̄ + R̄ ω_e, dω/dt = α̅ + R̄ α_e + ω̄ × R̄ ω_e.
#[derive(Clone, Debug, PartialEq)]
pub struct RaoMotion {
    mean: RigidMotion,
    table: RaoTable,
    waves: Vec<RaoWave>,
    ramp_time: Real,
}

impl RaoMotion {
    /// The RAO motion of a vessel with displacement RAOs `table` in the sea `waves` (the one
    /// built for the environment: a clone of its components is kept), on the `mean` motion. A
    /// calm sea leaves the vessel on its mean motion.
    pub fn new(table: RaoTable, waves: &Waves, mean: RigidMotion) -> Result<Self, ModelError> {
        if matches!(mean, RigidMotion::Rao(_)) {
            return Err(invalid(
                "RAO motion",
                "the mean motion cannot itself be an RAO motion",
            ));
        }
        let (components, ramp_time) = match waves.field() {
            Some(f) => (f.components(), f.spec().ramp_time),
            None => (&[][..], 0.0),
        };
        let waves = components
            .iter()
            .filter_map(|c| {
                table
                    .frequency_bracket(c.angular_frequency())
                    .map(|bracket| {
                        let (s, co) = c.direction().sin_cos();
                        RaoWave {
                            amplitude: c.amplitude(),
                            omega: c.angular_frequency(),
                            kx: c.wavenumber() * co,
                            ky: c.wavenumber() * s,
                            phase: c.phase(),
                            direction: c.direction(),
                            bracket,
                        }
                    })
            })
            .collect();
        Ok(Self {
            mean,
            table,
            waves,
            ramp_time,
        })
    }

    /// The mean motion.
    pub fn mean(&self) -> &RigidMotion {
        &self.mean
    }

    /// The RAO table.
    pub fn table(&self) -> &RaoTable {
        &self.table
    }

    /// The wave-frequency responses at t [s]: [surge, sway, heave (m), roll, pitch, yaw (rad)]
    /// in the mean body axes, their rates and second derivatives, with the mean kinematics.
    pub fn responses(&self, t: Real) -> ([Real; 6], [Real; 6], [Real; 6], RigidKinematics) {
        let m = self.mean.kinematics(t);
        let mut xi = [0.0; 6];
        let mut xid = [0.0; 6];
        let mut xidd = [0.0; 6];
        let (r, dr, ddr) = ramp(t, self.ramp_time);
        if r == 0.0 && dr == 0.0 || self.waves.is_empty() {
            return (xi, xid, xidd, m);
        }
        let (_, _, psi) = m.orientation.euler_angles();
        let (psi_d, psi_dd) = (m.angular_velocity.z, m.angular_acceleration.z);
        let (x, v, a) = (m.position, m.velocity, m.acceleration);
        for w in &self.waves {
            let theta = w.kx * x.x + w.ky * x.y - w.omega * t + w.phase;
            let theta_d = w.kx * v.x + w.ky * v.y - w.omega;
            let theta_dd = w.kx * a.x + w.ky * a.y;
            let (s, c) = theta.sin_cos();
            // E = e^{−iθ}, Ė = −i θ̇ E, Ë = (−i θ̈ − θ̇²) E.
            let e = [c, -s];
            let ed = [theta_d * e[1], -theta_d * e[0]];
            let edd = [
                theta_dd * e[1] - theta_d * theta_d * e[0],
                -theta_dd * e[0] - theta_d * theta_d * e[1],
            ];
            let (h, dh) = self
                .table
                .interpolate(w.bracket.0, w.bracket.1, w.direction - psi);
            for k in 0..6 {
                let hd = [-dh[k][0] * psi_d, -dh[k][1] * psi_d];
                let hdd = [-dh[k][0] * psi_dd, -dh[k][1] * psi_dd];
                let re = |p: [Real; 2], q: [Real; 2]| p[0] * q[0] - p[1] * q[1];
                xi[k] += w.amplitude * re(h[k], e);
                xid[k] += w.amplitude * (re(hd, e) + re(h[k], ed));
                xidd[k] += w.amplitude * (re(hdd, e) + 2.0 * re(hd, ed) + re(h[k], edd));
            }
        }
        for k in 0..6 {
            xidd[k] = r * xidd[k] + 2.0 * dr * xid[k] + ddr * xi[k];
            xid[k] = r * xid[k] + dr * xi[k];
            xi[k] *= r;
        }
        (xi, xid, xidd, m)
    }

    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        let (xi, xid, xidd, m) = self.responses(t);
        let rm = m.orientation;
        let rho = rm * Vec3::new(xi[0], xi[1], xi[2]);
        let rel_v = rm * Vec3::new(xid[0], xid[1], xid[2]);
        let rel_a = rm * Vec3::new(xidd[0], xidd[1], xidd[2]);
        let (w, al) = (m.angular_velocity, m.angular_acceleration);
        let (qe, we, ae) = euler_kinematics(
            [xi[3], xi[4], xi[5]],
            [xid[3], xid[4], xid[5]],
            [xidd[3], xidd[4], xidd[5]],
        );
        let we_g = rm * we;
        RigidKinematics {
            position: m.position + rho,
            orientation: rm * qe,
            velocity: m.velocity + w.cross(&rho) + rel_v,
            angular_velocity: w + we_g,
            acceleration: m.acceleration
                + al.cross(&rho)
                + w.cross(&w.cross(&rho))
                + 2.0 * w.cross(&rel_v)
                + rel_a,
            angular_acceleration: al + rm * ae + w.cross(&we_g),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A clothoid whose turn overflows (a curvature rate κ/L_c of ∞ from a subnormal L_c) or
    /// is NaN is integrated on a bounded number of panels: the loop count once was
    /// ⌈∞/0.5⌉ as usize = usize::MAX, and the loader never returned.
    #[test]
    fn clothoid_panels_are_bounded() {
        assert_eq!(clothoid_panels(Real::INFINITY), MAX_CLOTHOID_PANELS);
        assert_eq!(clothoid_panels(1e300), MAX_CLOTHOID_PANELS);
        assert_eq!(clothoid_panels(Real::NAN), 1);
        assert_eq!(clothoid_panels(0.0), 1);
        assert_eq!(clothoid_panels(1.2), 3);
        // The largest clothoid a valid manoeuvre has: L_c = R|Θ| with |Θ| the largest turn
        // turns by |Θ|/2, within the cap.
        assert!(clothoid_panels(0.5 * Manoeuvre::MAX_TURN_ANGLE) < MAX_CLOTHOID_PANELS);
        // It returns (with a non-finite answer) rather than looping for ever.
        let (x, _) = clothoid_displacement(0.0, 0.0, Real::INFINITY, 1.0);
        assert!(!x.is_finite());
    }
}
