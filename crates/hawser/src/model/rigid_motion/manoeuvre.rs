//! The ship manoeuvre: straight, turn on a radius with clothoid transitions, straight (docs/motions.md).

use super::*;

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
