//! Steady towing: an independent integration of the steady three-dimensional cable equations
//! for a cable towed at constant velocity in still water, from the towed body to the ship.
//!
//! This is the reference against which hawser's steady-towing statics (the equilibrium in the
//! frame moving with the ship, the elastic-link paper's "solution-setting mode") is checked. It
//! shares no code with the finite-element statics: it integrates the ordinary differential
//! equations of a continuous cable with an adaptive Runge–Kutta method. Its inputs are the same
//! physical data, read from a [`Model`] by [`SteadyTow::from_model`] or given directly.
//!
//! # Frame and loads
//!
//! In the frame moving with the ship (SPEC §4), the ship's tow point is fixed and the water
//! streams past at U = −V (V the ship's velocity [m/s]): a uniform current. The cable is at rest
//! in this frame, so the fluid velocity relative to it is U everywhere. Per unit *unstretched*
//! length s0 [m], with the conventions and drag form of SPEC §1 (those of hawser's `fe` lines,
//! so that the comparison is like for like), the cable carries
//!
//! - wet weight f_w = (ρ A − γ0) g ẑ [N/m], A = π d²/4, everywhere below z = 0;
//! - drag f_d = ½ ρ d √(1+ε) (C_dn |U_n| U_n + C_dt |U_t| U_t) [N/m], with t the unit tangent,
//!   U_t = (U·t) t, U_n = U − U_t, and C_dt on the area d (not π d);
//!
//! and the towed body (a point: mass m [kg], displaced volume V_b [m³], drag area C_dA [m²],
//! constant force F_ext [N] for thrust, stabilisers or depressors) carries
//!
//! - f_b = (ρ V_b − m) g ẑ + ½ ρ C_dA |U| U + F_ext [N].
//!
//! # Equations
//!
//! Let F(s0) = T t be the tension vector [N] at unstretched arc length s0 from the body: the
//! force the ship-side part of the cable exerts on the body-side part. The balance of the piece
//! [s0, s0 + ds0] is F(s0 + ds0) − F(s0) + f ds0 = 0 with f = f_w + f_d, and the piece's length
//! is ds = (1 + ε) ds0 with the linear elastic strain ε = T/EA. Hence the six first-order
//! equations
//!
//!   dF/ds0 = −f(F),            dr/ds0 = (1 + T/EA) F/T,                                    (1)
//!
//! with T = |F|. Projected on the tangent and the normal they are the classical tension–angle
//! equations of a steady cable (Ablow & Schechter 1983, Ocean Eng. 10(6), 443–457, without the
//! time derivatives; Pode 1951, DTMB report 687, for the inextensible planar case):
//!
//!   dT/ds0 = −f·t,             T dt/ds0 = −(f − (f·t) t)   (T |dt/ds0| = T κ (1+ε): curvature).
//!
//! In the vertical plane of the tow (U = −V x̂, t = (cos φ, 0, sin φ), φ the angle of the cable
//! above the horizontal, w = (γ0 − ρ A) g the wet weight per length, q = ½ ρ d √(1+ε) V²) they
//! read, for 0 < φ < π/2,
//!
//!   dT/ds0 = w sin φ + q C_dt cos² φ,      T dφ/ds0 = w cos φ − q C_dn sin² φ,            (2)
//!
//! the familiar form whose second equation vanishes at the critical angle
//! w cos φ_c = q C_dn sin² φ_c. The integration uses the vector form (1), which has no angle
//! singularity and covers any current direction.
//!
//! # Boundary conditions
//!
//! At the body end (s0 = 0) the cable pulls the body with T t(0); the body is in equilibrium, so
//!
//!   F(0) = −f_b,    r(0) = r_body,
//!
//! which makes the problem an initial-value problem: integrate (1) from the body to the ship end
//! (s0 = L) with r(0) = 0 and place the body at r_ship − r(L). No shooting is needed because, in
//! a uniform current and fully under water, f depends on F alone, not on the position. The
//! tension at the ship end is |F(L)|; the force on the ship is −F(L).
//!
//! The paper leaves all of this out: it states only that the steady modes were found as the end
//! of a transient run "reversing the exposure" (a still system in a stream at −V).
//!
//! # Numerics
//!
//! Dormand–Prince 5(4) with local error control (Hairer, Nørsett & Wanner, *Solving ODEs I*,
//! §II.4–5), the fifth-order solution propagated, on the mixed error norm
//! max_i |e_i| / (rtol (|y_i| + scale_i)) with the force scale |F(0)| + Σ|f| L and the length
//! scale L. Steps end exactly at segment boundaries (where the loads jump) and at requested
//! stations. The default rtol = 1e-11 puts the integration error far below the finite-element
//! discretisation error it is compared with (the unit tests check 1e-9 against closed forms).
//!
//! # Scope
//!
//! Uniform current (or none), no waves, linear EA, Morison drag coefficients; cable and body
//! wholly under water and off the seabed (checked at every step; an error otherwise). The body
//! is a point: its drag area is that of the towing direction, which is all the steady problem
//! needs. The tension must stay positive (a cable pushed into compression has no steady towed
//! shape here).

use crate::math::{Real, Vec3, z_hat};
use crate::model::{Formulation, LineEnd, Model, PointKind, StrainMeasure};
use crate::physics::environment::Current;
use crate::physics::hydrodynamics::DragModel;
use crate::physics::material::AxialStiffness;

/// A run of uniform cable in the steady-cable integration.
#[derive(Clone, Debug, PartialEq)]
pub struct CableSegment {
    /// Unstretched length [m].
    pub length: Real,
    /// Hydrodynamic diameter d [m] (drag on d, buoyancy on π d²/4).
    pub diameter: Real,
    /// Mass per unit unstretched length γ0 [kg/m].
    pub mass_per_length: Real,
    /// Axial stiffness EA [N].
    pub axial_stiffness: Real,
    /// Normal drag coefficient C_dn [-] on d.
    pub normal_drag: Real,
    /// Tangential drag coefficient C_dt [-] on d (SPEC §1; MoorDyn's CdAx is C_dt/π).
    pub tangential_drag: Real,
}

/// The towed body, a point load at the cable's lower end.
#[derive(Clone, Debug, PartialEq)]
pub struct TowedBody {
    /// Mass [kg].
    pub mass: Real,
    /// Displaced volume [m³].
    pub volume: Real,
    /// Drag area C_d·A [m²] in the towing direction.
    pub drag_area: Real,
    /// Constant external force [N]: thrust, stabiliser, depressor.
    pub force: Vec3,
}

/// A towed cable and body in steady motion, in the frame of the ship.
#[derive(Clone, Debug, PartialEq)]
pub struct SteadyTow {
    /// Gravitational acceleration [m/s²].
    pub gravity: Real,
    /// Water density ρ [kg/m³].
    pub water_density: Real,
    /// Water velocity relative to the ship [m/s]: −(ship velocity) in still water.
    pub current: Vec3,
    /// Position of the tow point on the ship [m] (z ≤ 0).
    pub ship_end: Vec3,
    /// Seabed height [m] under the tow point (−depth on a flat bed; −∞ for deep water). The
    /// integration stops with an error if the cable reaches it.
    pub seabed_z: Real,
    /// Cable segments in order from the body end to the ship end.
    pub segments: Vec<CableSegment>,
    /// The towed body.
    pub body: TowedBody,
    /// Relative tolerance of the Runge–Kutta error control [-]; default 1e-11.
    pub relative_tolerance: Real,
}

/// A point of the steady cable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Station {
    /// Unstretched arc length from the body end [m].
    pub arc_length: Real,
    /// Position [m].
    pub position: Vec3,
    /// Tension vector F = T t [N], t pointing towards the ship end.
    pub tension: Vec3,
}

/// The steady towed shape.
#[derive(Clone, Debug, PartialEq)]
pub struct SteadyProfile {
    /// Stations from the body end (first) to the ship end (last): both ends and every
    /// requested station.
    pub stations: Vec<Station>,
    /// Accepted Runge–Kutta steps.
    pub steps: usize,
    /// Rejected Runge–Kutta steps.
    pub rejected: usize,
}

impl SteadyProfile {
    /// Position of the body [m].
    pub fn body_position(&self) -> Vec3 {
        self.stations[0].position
    }
    /// Tension at the body end [N].
    pub fn body_tension(&self) -> Real {
        self.stations[0].tension.norm()
    }
    /// Tension at the ship end [N].
    pub fn ship_tension(&self) -> Real {
        self.stations[self.stations.len() - 1].tension.norm()
    }
    /// Position of the ship end [m].
    pub fn ship_position(&self) -> Vec3 {
        self.stations[self.stations.len() - 1].position
    }
}

/// Why the steady-cable integration cannot give a shape.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum SteadyCableError {
    /// An input is out of range or not supported.
    #[error("steady cable: {what}: {why}")]
    Invalid {
        /// What is wrong.
        what: String,
        /// Why, with the expected range or the supported cases.
        why: String,
    },
    /// The tension vanished: no steady shape with a taut cable.
    #[error(
        "steady cable: the tension falls to {tension:.3e} N at {arc_length:.3} m from the body; \
         a towed cable needs positive tension everywhere; hint: the body's loads (weight, \
         buoyancy, drag, thrust) must not balance out, and the cable must not be pushed"
    )]
    Slack {
        /// Unstretched arc length from the body [m].
        arc_length: Real,
        /// The tension there [N].
        tension: Real,
    },
    /// The step size fell below round-off: the solution is not smooth there.
    #[error(
        "steady cable: the Runge–Kutta step fell to {step:.3e} m at {arc_length:.3} m from \
         the body (tension {tension:.3e} N)"
    )]
    StepUnderflow {
        /// Unstretched arc length from the body [m].
        arc_length: Real,
        /// Step [m].
        step: Real,
        /// Tension there [N].
        tension: Real,
    },
    /// The cable or body leaves the water or meets the seabed, which the integration does not
    /// model.
    #[error(
        "steady cable: at {arc_length:.3} m from the body the cable is at z = {z:.3} m, {where_}; \
         the steady-cable integration assumes a wholly submerged cable clear of the seabed"
    )]
    OutOfWater {
        /// Unstretched arc length from the body [m].
        arc_length: Real,
        /// Height there [m].
        z: Real,
        /// "above the water" or "below the seabed".
        where_: &'static str,
    },
}

fn invalid(what: impl Into<String>, why: impl Into<String>) -> SteadyCableError {
    SteadyCableError::Invalid {
        what: what.into(),
        why: why.into(),
    }
}

/// Dormand–Prince 5(4) tableau (Hairer, Nørsett & Wanner, Table II.5.2): nodes c, stage
/// coefficients a (lower triangle, row i for stage i), fifth-order weights b and the
/// difference e = b − b̂ to the embedded fourth-order weights.
mod dopri {
    use crate::math::Real;
    pub const C: [Real; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
    pub const A: [[Real; 6]; 7] = [
        [0.0; 6],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
        ],
        FIFTH_ORDER,
    ];
    /// The fifth-order weights of stages 1–6; the last stage is evaluated at them
    /// ("first same as last").
    const FIFTH_ORDER: [Real; 6] = [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ];
    pub const B: [Real; 7] = [
        FIFTH_ORDER[0],
        FIFTH_ORDER[1],
        FIFTH_ORDER[2],
        FIFTH_ORDER[3],
        FIFTH_ORDER[4],
        FIFTH_ORDER[5],
        0.0,
    ];
    pub const E: [Real; 7] = [
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ];
}

/// The ODE state: tension vector F [N] and position relative to the body r [m].
#[derive(Clone, Copy, Debug)]
struct Y {
    f: Vec3,
    r: Vec3,
}

impl Y {
    fn axpy(&self, h: Real, k: &[Y], w: &[Real]) -> Y {
        let mut out = *self;
        for (ki, &wi) in k.iter().zip(w) {
            if wi != 0.0 {
                out.f += ki.f * (h * wi);
                out.r += ki.r * (h * wi);
            }
        }
        out
    }
}

impl SteadyTow {
    /// Reads a steady tow from a model: line `line` runs between a fixed point (the ship's tow
    /// point) and a free point (the body) attached to nothing else; the current (uniform, or
    /// none) is the water velocity relative to the ship. Every section needs linear EA and
    /// Morison drag coefficients.
    pub fn from_model(model: &Model, line: usize) -> Result<Self, SteadyCableError> {
        let l = model
            .lines
            .get(line)
            .ok_or_else(|| invalid(format!("line #{line}"), "does not exist"))?;
        let point = |end: &LineEnd| {
            let LineEnd::Point(p) = end;
            model.points.get(*p).map(|pt| (*p, pt)).ok_or_else(|| {
                invalid(format!("line {}", l.name), "is attached to a missing point")
            })
        };
        let (a, b) = (point(&l.end_a)?, point(&l.end_b)?);
        let (ship, body, body_is_b) = match (&a.1.kind, &b.1.kind) {
            (PointKind::Fixed, PointKind::Free { .. }) => (a, b, true),
            (PointKind::Free { .. }, PointKind::Fixed) => (b, a, false),
            _ => {
                return Err(invalid(
                    format!("line {}", l.name),
                    "needs a fixed point (the ship's tow point) at one end and a free point \
                     (the towed body) at the other",
                ));
            }
        };
        for (li, other) in model.lines.iter().enumerate() {
            if li != line && [other.end_a, other.end_b].contains(&LineEnd::Point(body.0)) {
                return Err(invalid(
                    format!("point {}", body.1.name),
                    format!(
                        "is also attached to line {}: only a single towed cable is supported",
                        other.name
                    ),
                ));
            }
        }
        let PointKind::Free {
            mass,
            volume,
            drag_area,
            force,
            ..
        } = &body.1.kind
        else {
            unreachable!("matched as free above");
        };
        let env = &model.environment;
        let current = match &env.current {
            Current::None => Vec3::zeros(),
            Current::Uniform(u) => *u,
            Current::Profile { .. } => {
                return Err(invalid(
                    "environment.current",
                    "a current profile is not supported (uniform current only)",
                ));
            }
            Current::Table { .. } => {
                return Err(invalid(
                    "environment.current",
                    "a current that varies in time is not supported (steady towing in a \
                     uniform current only)",
                ));
            }
        };
        if env.waves.field().is_some() {
            return Err(invalid(
                "environment.waves",
                "waves are not supported (steady towing in calm water)",
            ));
        }
        // The integration has neither bending nor the small-strain measure: a `hermite` or
        // `dg` line with either models other physics (`fe` ignores bending).
        if l.formulation == Formulation::Hermite && l.strain_measure != StrainMeasure::Exact {
            return Err(invalid(
                format!("line {}", l.name),
                "uses the small-strain measure; the steady-cable integration uses the exact \
                 strain ε = |r'| − 1",
            ));
        }
        let mut segments = Vec::with_capacity(l.sections.len());
        for s in &l.sections {
            let lt = model.line_types.get(s.line_type).ok_or_else(|| {
                invalid(format!("line {}", l.name), "refers to a missing line type")
            })?;
            if l.formulation != Formulation::Fe && lt.bending_stiffness > 0.0 {
                return Err(invalid(
                    format!("line type {}", lt.name),
                    "has bending stiffness, which a `hermite` or `dg` line carries and the \
                     steady-cable integration does not",
                ));
            }
            let AxialStiffness::Linear(ea) = lt.axial_stiffness else {
                return Err(invalid(
                    format!("line type {}", lt.name),
                    "a tension–strain table is not supported (linear EA only)",
                ));
            };
            let DragModel::Morison { normal, tangential } = lt.drag else {
                return Err(invalid(
                    format!("line type {}", lt.name),
                    "drag loading functions are not supported (Morison coefficients only)",
                ));
            };
            segments.push(CableSegment {
                length: s.length,
                diameter: lt.diameter,
                mass_per_length: lt.mass_per_length,
                axial_stiffness: ea,
                normal_drag: normal,
                tangential_drag: tangential,
            });
        }
        // Sections run from end A to end B; segments from the body to the ship.
        if body_is_b {
            segments.reverse();
        }
        Ok(Self {
            gravity: env.gravity,
            water_density: env.water_density,
            current,
            ship_end: ship.1.position,
            seabed_z: env.seabed_at(ship.1.position.x, ship.1.position.y).z,
            segments,
            body: TowedBody {
                mass: *mass,
                volume: *volume,
                drag_area: *drag_area,
                force: *force,
            },
            relative_tolerance: 1e-11,
        })
    }

    /// Total unstretched length [m].
    pub fn length(&self) -> Real {
        self.segments.iter().map(|s| s.length).sum()
    }

    /// The body's own load f_b [N] under water: weight, buoyancy, drag and external force.
    pub fn body_load(&self) -> Vec3 {
        let b = &self.body;
        let rho = self.water_density;
        let u = self.current;
        z_hat() * ((rho * b.volume - b.mass) * self.gravity)
            + u * (0.5 * rho * b.drag_area * u.norm())
            + b.force
    }

    /// Distributed load f [N per m of unstretched cable] on a segment with tension vector `f`
    /// (the cable under water, at rest in the current).
    pub fn distributed_load(&self, segment: &CableSegment, tension: &Vec3) -> Vec3 {
        let rho = self.water_density;
        let area = std::f64::consts::PI * segment.diameter * segment.diameter / 4.0;
        let wet = z_hat() * ((rho * area - segment.mass_per_length) * self.gravity);
        let t_mag = tension.norm();
        let t = tension / t_mag;
        let strain = t_mag / segment.axial_stiffness;
        let q = 0.5 * rho * segment.diameter * (1.0 + strain).sqrt();
        let u = self.current;
        let ut = t * u.dot(&t);
        let un = u - ut;
        wet + (un * (segment.normal_drag * un.norm()) + ut * (segment.tangential_drag * ut.norm()))
            * q
    }

    fn derivative(&self, segment: &CableSegment, y: &Y) -> Y {
        let t_mag = y.f.norm();
        Y {
            f: -self.distributed_load(segment, &y.f),
            r: y.f * ((1.0 + t_mag / segment.axial_stiffness) / t_mag),
        }
    }

    fn validate(&self, stations: &[Real]) -> Result<(), SteadyCableError> {
        let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
        if !(self.gravity >= 0.0 && self.gravity.is_finite()) {
            return Err(invalid("gravity", "must be finite and ≥ 0 m/s²"));
        }
        if !(self.water_density > 0.0 && self.water_density.is_finite()) {
            return Err(invalid("water density", "must be finite and > 0 kg/m³"));
        }
        if !finite(&self.current) || !finite(&self.body.force) {
            return Err(invalid("current or body force", "must be finite"));
        }
        if !finite(&self.ship_end) || self.ship_end.z > 0.0 {
            return Err(invalid(
                "ship end",
                "must be finite and at or below the water surface (z ≤ 0)",
            ));
        }
        let b = &self.body;
        let sum = b.mass + b.volume + b.drag_area;
        if !(b.mass >= 0.0 && b.volume >= 0.0 && b.drag_area >= 0.0 && sum.is_finite()) {
            return Err(invalid(
                "body",
                "mass [kg], volume [m³] and drag area [m²] must be finite and ≥ 0",
            ));
        }
        if self.segments.is_empty() {
            return Err(invalid("cable", "has no segments"));
        }
        for (i, s) in self.segments.iter().enumerate() {
            let ok = s.length > 0.0
                && s.diameter > 0.0
                && s.mass_per_length > 0.0
                && s.axial_stiffness > 0.0
                && s.normal_drag >= 0.0
                && s.tangential_drag >= 0.0
                && (s.length
                    + s.diameter
                    + s.mass_per_length
                    + s.axial_stiffness
                    + s.normal_drag
                    + s.tangential_drag)
                    .is_finite();
            if !ok {
                return Err(invalid(
                    format!("segment {i}"),
                    "length [m], diameter [m], mass per length [kg/m] and EA [N] must be \
                     finite and > 0, drag coefficients finite and ≥ 0",
                ));
            }
        }
        if !(self.relative_tolerance > 0.0 && self.relative_tolerance < 1e-2) {
            return Err(invalid("relative tolerance", "must lie in (0, 0.01)"));
        }
        let length = self.length();
        if let Some(s) = stations.iter().find(|s| !(**s >= 0.0 && **s <= length)) {
            return Err(invalid(
                format!("station {s}"),
                format!("must lie between 0 and the cable length {length} m"),
            ));
        }
        Ok(())
    }

    /// Integrates the steady cable from the body to the ship. `stations` are unstretched arc
    /// lengths from the body [m] at which to record the cable (in any order; the ends are
    /// always recorded).
    pub fn solve(&self, stations: &[Real]) -> Result<SteadyProfile, SteadyCableError> {
        self.validate(stations)?;
        let length = self.length();
        // Every place a step must end at: segment boundaries and stations.
        let mut marks: Vec<Real> = stations.to_vec();
        let mut acc = 0.0;
        for s in &self.segments {
            acc += s.length;
            marks.push(acc);
        }
        marks.push(length);
        marks.sort_by(Real::total_cmp);
        marks.dedup_by(|a, b| (*a - *b).abs() <= 1e-14 * length);
        // The body end is recorded before the loop.
        marks.retain(|&m| m > 0.0);
        let mut y = Y {
            f: -self.body_load(),
            r: Vec3::zeros(),
        };
        let body_tension = y.f.norm();
        // Scales of the error norm: the largest force the loads can make and the length.
        let load_scale: Real = self
            .segments
            .iter()
            .map(|s| {
                let u = self.current.norm();
                let area = std::f64::consts::PI * s.diameter * s.diameter / 4.0;
                let wet = (s.mass_per_length - self.water_density * area) * self.gravity;
                let drag = 0.5 * self.water_density * s.diameter * u * u;
                (wet.abs() + drag * (s.normal_drag + s.tangential_drag)) * s.length
            })
            .sum();
        let force_scale = body_tension + load_scale;
        let slack_limit = 1e-12 * force_scale;
        if !(body_tension > slack_limit) {
            return Err(SteadyCableError::Slack {
                arc_length: 0.0,
                tension: body_tension,
            });
        }
        let rtol = self.relative_tolerance;
        let mut out = vec![Station {
            arc_length: 0.0,
            position: y.r,
            tension: y.f,
        }];
        // Highest and lowest points relative to the body, for the submergence checks.
        let (mut top, mut bottom) = ((0.0, 0.0), (0.0, 0.0));
        let (mut s, mut segment_start, mut seg) = (0.0, 0.0, 0usize);
        let mut h = 0.01 * length.min(self.segments[0].length);
        let (mut steps, mut rejected) = (0usize, 0usize);
        let mut k = [y; 7];
        for &mark in &marks {
            while s < mark {
                // Segment of this step: the one that holds (s, mark).
                while seg + 1 < self.segments.len()
                    && s >= segment_start + self.segments[seg].length - 1e-14 * length
                {
                    segment_start += self.segments[seg].length;
                    seg += 1;
                }
                let segment = &self.segments[seg];
                let last = mark - s <= h * (1.0 + 1e-12);
                let step = if last { mark - s } else { h };
                k[0] = self.derivative(segment, &y);
                for i in 1..7 {
                    let yi = y.axpy(step, &k[..i], &dopri::A[i][..i]);
                    if !(yi.f.norm() > slack_limit) {
                        return Err(SteadyCableError::Slack {
                            arc_length: s + dopri::C[i] * step,
                            tension: yi.f.norm(),
                        });
                    }
                    k[i] = self.derivative(segment, &yi);
                }
                let new = y.axpy(step, &k, &dopri::B);
                let err = Y {
                    f: Vec3::zeros(),
                    r: Vec3::zeros(),
                }
                .axpy(step, &k, &dopri::E);
                let mut norm: Real = 0.0;
                for i in 0..3 {
                    let sf = rtol * (y.f[i].abs().max(new.f[i].abs()) + force_scale);
                    let sr = rtol * (y.r[i].abs().max(new.r[i].abs()) + length);
                    norm = norm.max(err.f[i].abs() / sf).max(err.r[i].abs() / sr);
                }
                if !norm.is_finite() {
                    norm = 1e10;
                }
                let factor = if norm == 0.0 {
                    5.0
                } else {
                    (0.9 * norm.powf(-0.2)).clamp(0.2, 5.0)
                };
                if norm <= 1.0 {
                    if !(new.f.norm() > slack_limit) {
                        return Err(SteadyCableError::Slack {
                            arc_length: s + step,
                            tension: new.f.norm(),
                        });
                    }
                    s = if last { mark } else { s + step };
                    y = new;
                    steps += 1;
                    if y.r.z > top.0 {
                        top = (y.r.z, s);
                    }
                    if y.r.z < bottom.0 {
                        bottom = (y.r.z, s);
                    }
                    if !last || factor > 1.0 {
                        h = step * factor;
                    }
                } else {
                    rejected += 1;
                    h = step * factor;
                    if h < 1e-13 * length {
                        return Err(SteadyCableError::StepUnderflow {
                            arc_length: s,
                            step: h,
                            tension: y.f.norm(),
                        });
                    }
                }
            }
            out.push(Station {
                arc_length: mark,
                position: y.r,
                tension: y.f,
            });
        }
        // Place the body so that the ship end lands on the tow point.
        let shift = self.ship_end - y.r;
        for st in &mut out {
            st.position += shift;
        }
        out.retain(|st| {
            st.arc_length == 0.0
                || st.arc_length == length
                || stations
                    .iter()
                    .any(|x| (x - st.arc_length).abs() <= 1e-14 * length)
        });
        let surface_tolerance = 1e-9 * length;
        if shift.z + top.0 > surface_tolerance || shift.z >= 0.0 {
            let (z, arc_length) = if shift.z >= 0.0 {
                (shift.z, 0.0)
            } else {
                (shift.z + top.0, top.1)
            };
            return Err(SteadyCableError::OutOfWater {
                arc_length,
                z,
                where_: "above the water",
            });
        }
        if shift.z + bottom.0 < self.seabed_z {
            return Err(SteadyCableError::OutOfWater {
                arc_length: bottom.1,
                z: shift.z + bottom.0,
                where_: "below the seabed",
            });
        }
        Ok(SteadyProfile {
            stations: out,
            steps,
            rejected,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statics::catenary;

    fn segment(length: Real, cdn: Real, cdt: Real) -> CableSegment {
        CableSegment {
            length,
            diameter: 0.03,
            mass_per_length: 1.43,
            axial_stiffness: 6.75e7,
            normal_drag: cdn,
            tangential_drag: cdt,
        }
    }

    fn tow(segments: Vec<CableSegment>, current: Vec3, body: TowedBody) -> SteadyTow {
        SteadyTow {
            gravity: 9.80665,
            water_density: 1025.0,
            current,
            ship_end: Vec3::new(0.0, 0.0, -10.0),
            seabed_z: Real::NEG_INFINITY,
            segments,
            body,
            relative_tolerance: 1e-11,
        }
    }

    fn neutral_area(d: Real) -> Real {
        1025.0 * std::f64::consts::PI * d * d / 4.0
    }

    /// Without drag the cable is an elastic catenary: hawser's closed form
    /// (`statics::catenary`) with the horizontal and vertical tension of the body end gives
    /// the same positions and tensions along the line, and solving the closed form for the
    /// integrated span recovers the end tensions. Tolerance 1e-9 relative: the Runge–Kutta
    /// tolerance is 1e-11, and the catenary's own Newton stops at 1e-12.
    #[test]
    fn without_drag_the_cable_is_the_elastic_catenary() {
        // A 400 m cable in two segments (a stiffer, lighter upper part) would not be one
        // catenary, so one segment; a heavy body pulled aft by 3 kN.
        let body = TowedBody {
            mass: 500.0,
            volume: 0.2,
            drag_area: 0.0,
            force: Vec3::new(-3000.0, 0.0, 0.0),
        };
        let seg = segment(400.0, 0.0, 0.0);
        let w = (seg.mass_per_length - neutral_area(seg.diameter)) * 9.80665;
        let t = tow(vec![seg.clone()], Vec3::zeros(), body);
        let stations: Vec<Real> = (0..=40).map(|i| 10.0 * i as Real).collect();
        let p = t.solve(&stations).expect("solves");
        // One station per request, ends included once, in order.
        let recorded: Vec<Real> = p.stations.iter().map(|s| s.arc_length).collect();
        assert_eq!(recorded, stations);
        let f0 = p.stations[0].tension;
        let cat = catenary::Catenary {
            horizontal: f0.x,
            vertical_a: f0.z,
            vertical_b: f0.z + w * 400.0,
            grounded_length: 0.0,
            length: 400.0,
            weight: w,
            ea: seg.axial_stiffness,
            slope: 0.0,
        };
        let scale = 400.0;
        for st in &p.stations {
            let (x, z) = cat.position(st.arc_length);
            let r = st.position - p.body_position();
            assert!(
                (r.x - x).abs() < 1e-9 * scale && (r.z - z).abs() < 1e-9 * scale && r.y == 0.0,
                "s = {}: {r:?} vs ({x}, {z})",
                st.arc_length
            );
            let tc = cat.tension(st.arc_length);
            assert!((st.tension.norm() - tc).abs() < 1e-9 * tc);
        }
        let span = p.ship_position() - p.body_position();
        let c = catenary::solve(span.x, span.z, 400.0, w, seg.axial_stiffness, false)
            .expect("catenary");
        assert!((c.horizontal - f0.x).abs() < 1e-9 * f0.x);
        assert!((c.tension_b() - p.ship_tension()).abs() < 1e-9 * p.ship_tension());
    }

    /// A neutrally buoyant cable towed straight along the flow feels tangential drag only:
    /// dT/ds0 = k √(1 + T/EA), k = ½ ρ d C_dt V², so with u = 1 + T/EA,
    /// √u = √u0 + k s0/(2 EA) and the stretched length is ∫u ds0 = [(√u)³ − (√u0)³]·2EA/(3k).
    /// A soft EA makes the stretch matter. Tolerance 1e-9 relative (Runge–Kutta 1e-11).
    #[test]
    fn tangential_drag_alone_matches_the_closed_form() {
        let (v, d, cdt, ea, cda, l) = (3.0, 0.03, 0.2, 2.0e4, 0.5, 300.0);
        let seg = CableSegment {
            length: l,
            diameter: d,
            mass_per_length: neutral_area(d),
            axial_stiffness: ea,
            normal_drag: 1.2,
            tangential_drag: cdt,
        };
        let body = TowedBody {
            mass: 100.0,
            volume: 100.0 / 1025.0,
            drag_area: cda,
            force: Vec3::zeros(),
        };
        let t = tow(vec![seg], Vec3::new(-v, 0.0, 0.0), body);
        let p = t.solve(&[100.0, 200.0]).expect("solves");
        let k = 0.5 * 1025.0 * d * cdt * v * v;
        let t0 = 0.5 * 1025.0 * cda * v * v;
        let a = (1.0 + t0 / ea).sqrt();
        for st in &p.stations {
            let s = st.arc_length;
            let root = a + k * s / (2.0 * ea);
            let tension = ea * (root * root - 1.0);
            let x = (root.powi(3) - a.powi(3)) * 2.0 * ea / (3.0 * k);
            let r = st.position - p.body_position();
            assert!((st.tension.norm() - tension).abs() < 1e-9 * tension);
            assert!((r.x - x).abs() < 1e-9 * l && r.y.abs() < 1e-12 && r.z.abs() < 1e-9 * l);
            assert!(st.tension.y.abs() < 1e-12 && st.tension.z.abs() < 1e-9 * tension);
        }
        // The stretch is real: the span exceeds the unstretched length by several percent.
        assert!(p.ship_position().x - p.body_position().x > 1.05 * l);
    }

    /// A weightless cable with normal drag only keeps its tension, and its angle φ above the
    /// flow direction obeys T dφ/ds0 = −q sin²φ (q = ½ ρ d √(1+ε) C_dn V²), so
    /// cot φ = cot φ0 + q s0/T and x = (1+ε)(T/q)(√(1+cot²φ) − √(1+cot²φ0)),
    /// z = (1+ε)(T/q)(asinh cot φ − asinh cot φ0). This checks the curvature's sign and size
    /// in three dimensions: the tow is rotated 30° about z. Tolerance 1e-9 relative.
    #[test]
    fn normal_drag_alone_matches_the_closed_form_in_any_heading() {
        let (v, d, cdn, ea, l, tension) = (2.0, 0.02, 1.5, 1.0e5, 150.0, 2000.0);
        let heading: Real = 30f64.to_radians();
        let (c, s) = (heading.cos(), heading.sin());
        let rot = |x: Real, z: Real| Vec3::new(x * c, x * s, z);
        let phi0: Real = 60f64.to_radians();
        let seg = CableSegment {
            length: l,
            diameter: d,
            mass_per_length: neutral_area(d),
            axial_stiffness: ea,
            normal_drag: cdn,
            tangential_drag: 0.0,
        };
        // A neutral, dragless body held by a force whose reaction sets F(0) = T (cos φ0, sin φ0).
        let body = TowedBody {
            mass: 10.0,
            volume: 10.0 / 1025.0,
            drag_area: 0.0,
            force: -rot(phi0.cos(), phi0.sin()) * tension,
        };
        let t = tow(vec![seg], rot(-v, 0.0), body);
        let p = t.solve(&[37.5, 75.0, 112.5]).expect("solves");
        let strain = tension / ea;
        let q = 0.5 * 1025.0 * d * (1.0 + strain).sqrt() * cdn * v * v;
        let c0 = phi0.cos() / phi0.sin();
        for st in &p.stations {
            let cot = c0 + q * st.arc_length / tension;
            let x =
                (1.0 + strain) * tension / q * ((1.0 + cot * cot).sqrt() - (1.0 + c0 * c0).sqrt());
            let z = (1.0 + strain) * tension / q * (cot.asinh() - c0.asinh());
            let r = st.position - p.body_position();
            let expected = rot(x, z);
            assert!(
                (r - expected).norm() < 1e-9 * l,
                "s = {}: {r:?} vs {expected:?}",
                st.arc_length
            );
            assert!((st.tension.norm() - tension).abs() < 1e-9 * tension);
        }
    }

    /// Cable drag holds the body up: the same tow with drag rides shallower than without,
    /// and the shape approaches the critical angle w cos φ_c = q C_dn sin² φ_c far from the
    /// body (eq. 2); here the cable is long enough to reach it within 1e-3 rad.
    #[test]
    fn cable_drag_lifts_the_body_toward_the_critical_angle() {
        let body = TowedBody {
            mass: 1030.44,
            volume: std::f64::consts::PI * 0.16 * 2.0,
            drag_area: 0.77 * std::f64::consts::PI * 0.16,
            force: Vec3::new(-1000.0, 0.0, 0.0),
        };
        let u = Vec3::new(-3.0, 0.0, 0.0);
        let with = tow(vec![segment(400.0, 1.35, 0.04)], u, body.clone())
            .solve(&[])
            .unwrap();
        let without = tow(vec![segment(400.0, 0.0, 0.0)], u, body)
            .solve(&[])
            .unwrap();
        assert!(with.body_position().z > without.body_position().z);
        let seg = segment(400.0, 1.35, 0.04);
        let w = (seg.mass_per_length - neutral_area(0.03)) * 9.80665;
        let ft = with.stations[1].tension;
        let q = 0.5 * 1025.0 * 0.03 * (1.0 + ft.norm() / seg.axial_stiffness).sqrt() * 9.0 * 1.35;
        // Solve w cos φ = q sin² φ: with c = cos φ, q c² + w c − q = 0.
        let cos_c = (-w + (w * w + 4.0 * q * q).sqrt()) / (2.0 * q);
        let phi = ft.z.atan2(ft.x);
        assert!(
            (phi - cos_c.acos()).abs() < 1e-3,
            "{phi} vs {}",
            cos_c.acos()
        );
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let body = TowedBody {
            mass: 100.0,
            volume: 0.0,
            drag_area: 0.1,
            force: Vec3::zeros(),
        };
        let good = tow(
            vec![segment(100.0, 1.2, 0.02)],
            Vec3::new(-1.0, 0.0, 0.0),
            body,
        );
        assert!(good.solve(&[]).is_ok());
        let mut t = good.clone();
        t.segments[0].axial_stiffness = 0.0;
        assert!(matches!(
            t.solve(&[]),
            Err(SteadyCableError::Invalid { .. })
        ));
        let mut t = good.clone();
        t.segments[0].length = Real::NAN;
        assert!(matches!(
            t.solve(&[]),
            Err(SteadyCableError::Invalid { .. })
        ));
        let mut t = good.clone();
        t.segments.clear();
        assert!(matches!(
            t.solve(&[]),
            Err(SteadyCableError::Invalid { .. })
        ));
        assert!(matches!(
            good.solve(&[150.0]),
            Err(SteadyCableError::Invalid { .. })
        ));
        assert!(matches!(
            good.solve(&[Real::NAN]),
            Err(SteadyCableError::Invalid { .. })
        ));
        // A body whose loads cancel leaves the cable slack at the body.
        let mut t = good.clone();
        t.body = TowedBody {
            mass: 0.0,
            volume: 0.0,
            drag_area: 0.0,
            force: Vec3::zeros(),
        };
        assert!(matches!(t.solve(&[]), Err(SteadyCableError::Slack { .. })));
        // A buoyant body floats above the tow point: out of the water.
        let mut t = good.clone();
        t.body.volume = 1.0;
        t.current = Vec3::zeros();
        assert!(matches!(
            t.solve(&[]),
            Err(SteadyCableError::OutOfWater { .. })
        ));
        // A seabed 20 m down is hit by a body hanging 100 m below the ship.
        let mut t = good.clone();
        t.current = Vec3::zeros();
        t.seabed_z = -20.0;
        assert!(matches!(
            t.solve(&[]),
            Err(SteadyCableError::OutOfWater { .. })
        ));
    }
}
