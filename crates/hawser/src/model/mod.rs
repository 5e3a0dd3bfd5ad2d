//! The system description: immutable during a run. Built in code or by `hawser-io` from a
//! scenario file, validated by [`Model::validate`], then assembled into a
//! [`crate::system::System`] for time integration and statics.

mod body;
mod coupled;
mod failure;
mod line;
mod motion;
mod point;
mod rigid_motion;
mod steady_tow;
mod winch;

pub use body::{Body, BodyKind, Displacement, DragSpeed, Member, Pin, Thrust, Wind};
pub use coupled::{BodyTrack, PointTrack, couple_prescribed_points};
pub use failure::LineFailure;
pub use line::{End, Formulation, Line, LineEnd, LineType, MassMatrix, Section, StrainMeasure};
pub use motion::{Motion, ramp};
pub use point::{Point, PointKind};
pub use rigid_motion::{
    Manoeuvre, ManoeuvreSpec, RaoMotion, RaoTable, RigidKinematics, RigidMotion, RigidTimeSeries,
    euler_kinematics,
};
pub use steady_tow::{steady_point_velocity, steady_rigid_velocity, tow_velocity};
pub use winch::{Winch, WinchEnd, WinchStage, WinchState};

use crate::error::ModelError;
use crate::math::Real;
use crate::physics::environment::Environment;

/// Time-integration scheme.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Scheme {
    /// Classical 4th-order Runge–Kutta (position-vector paper §3).
    Rk4,
    /// Strong-stability-preserving 3rd-order Runge–Kutta (DG paper eqs. 31–33).
    SspRk3,
    /// The elastic-link paper's explicit three-time-level scheme with variable steps and a
    /// predictor–corrector (eqs. 35–48), [`crate::integrate::ThreeLevel`].
    ThreeLevel,
    /// The implicit generalized-α method of Chung and Hulbert (1993) with Newton iterations
    /// on the block-banded Jacobian, [`crate::integrate::GeneralizedAlpha`]; its high-frequency
    /// spectral radius is [`Settings::spectral_radius`].
    GeneralizedAlpha,
    /// The cheapest of RK4 and generalized-α at the accuracy the settings ask for, chosen when
    /// the run starts ([`crate::integrate::choose_scheme`]); a run started with adaptive
    /// generalized-α hands stretches to RK4 where that does less work
    /// ([`crate::integrate::choice::SchemeSwitch`]). The default.
    #[default]
    Auto,
}

/// Time step of a dynamic run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TimeStep {
    /// Explicit schemes: the largest stable step from the CFL limit of every element and
    /// point, times the safety factor. Generalized-α: adaptive steps that keep the local error
    /// estimate within [`Settings::tolerance`].
    Auto,
    /// A fixed step [s]; refused when above the stability limit.
    Fixed(Real),
}

/// What a fixed time step above the stability limit does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StepAboveLimit {
    /// The run is refused with the limit and what sets it (hawser scenarios: the user chose
    /// the step for this integrator).
    #[default]
    Refuse,
    /// The automatic step is taken instead, with a note (MoorDyn decks: their `dtM` was
    /// chosen for MoorDyn's integrator).
    UseAuto,
}

/// How a dynamic run starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum InitialCondition {
    /// From the static equilibrium (default).
    #[default]
    Statics,
    /// From the positions as given (catenary seed for lines), at rest.
    AsDefined,
    /// From the steady tow: the equilibrium in the frame moving with the towing vessel at its
    /// constant velocity V ([`tow_velocity`]), with every node, free point and free body
    /// moving at V (the elastic-link paper's "solution-setting mode", §5).
    SteadyTow,
}

/// Default ρ∞ of the generalized-α scheme ([`Settings::spectral_radius`]).
pub const DEFAULT_SPECTRAL_RADIUS: Real = 0.8;

/// Default accuracy of a run ([`Settings::tolerance`]).
pub const DEFAULT_TOLERANCE: Real = 1e-6;

/// Settings of a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Simulated duration [s].
    pub duration: Real,
    /// Time step.
    pub time_step: TimeStep,
    /// Safety factor applied to the stability limit by [`TimeStep::Auto`] [-]; default 0.8.
    pub safety_factor: Real,
    /// Integration scheme; default [`Scheme::Auto`] (RK4 or generalized-α, whichever is the
    /// cheaper at [`Settings::tolerance`]; docs/implicit.md).
    pub scheme: Scheme,
    /// ρ∞ of the generalized-α scheme [-], in [0, 1]: the spectral radius of its amplification
    /// matrix as ωΔt → ∞, i.e. the factor by which an unresolved mode's amplitude is multiplied
    /// per step (Chung and Hulbert 1993). 1 dissipates nothing (the trapezoidal rule); 0 damps
    /// unresolved modes in one step. Default 0.8 (docs/implicit.md): a mode of ωΔt = 3.9 loses
    /// 2.1 % of its amplitude per step, a mode of ωΔt = 0.31 (20 steps per period) 0.014 % per
    /// period (tests/generalized_alpha.rs).
    pub spectral_radius: Real,
    /// Accuracy a run asks for [-]: the largest local error per step of the adaptive
    /// generalized-α step ([`TimeStep::Auto`]), in each element's tension relative to its line's
    /// reference tension, and the accuracy [`Scheme::Auto`] chooses a scheme for. Default 1e-6:
    /// the bundled examples' extremes within 0.05 % of a converged reference (docs/implicit.md).
    pub tolerance: Real,
    /// What a fixed `time_step` above the stability limit does.
    pub step_above_limit: StepAboveLimit,
    /// Interval between time-series samples [s].
    pub output_interval: Real,
    /// Interval between whole-line shape snapshots [s]; `None` for none.
    pub snapshot_interval: Option<Real>,
    /// Initial condition.
    pub initial_condition: InitialCondition,
    /// Free points held fixed at their `position` while the initial static equilibrium is
    /// solved, and free from t = 0 (indices into [`Model::points`]): a release test, such as
    /// the swinging cable of the DG paper (§5), whose second pin is pulled at t = 0. See
    /// [`crate::statics::solve_with_release`]. Empty by default.
    pub release: Vec<usize>,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            duration: 10.0,
            time_step: TimeStep::Auto,
            safety_factor: 0.8,
            scheme: Scheme::Auto,
            spectral_radius: DEFAULT_SPECTRAL_RADIUS,
            tolerance: DEFAULT_TOLERANCE,
            step_above_limit: StepAboveLimit::Refuse,
            output_interval: 0.1,
            snapshot_interval: None,
            initial_condition: InitialCondition::Statics,
            release: Vec::new(),
        }
    }
}

/// A whole cable system: environment, line types, lines, points and settings.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Water, air, seabed and current.
    pub environment: Environment,
    /// Line types referenced by line sections.
    pub line_types: Vec<LineType>,
    /// Lines.
    pub lines: Vec<Line>,
    /// Connection points: anchors, fairleads, free point masses, points on bodies.
    pub points: Vec<Point>,
    /// Rigid bodies.
    pub bodies: Vec<Body>,
    /// Simulation settings.
    pub settings: Settings,
    /// Time-series channels a run records, in column order; empty: the default channels
    /// ([`crate::analysis::channels::default_channels`]).
    pub outputs: Vec<crate::analysis::OutputChannel>,
    /// Line ends that may release from their attachments during a run ([`LineFailure`]):
    /// at a time, above a tension, or on the host's call ([`crate::Session::release`]).
    pub failures: Vec<LineFailure>,
}

impl Model {
    /// Index of the point named `name`.
    pub fn point_index(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p.name == name)
    }

    /// Index of the line named `name`.
    pub fn line_index(&self, name: &str) -> Option<usize> {
        self.lines.iter().position(|l| l.name == name)
    }

    /// The model without its [`Model::failures`]: the intact system that statics, modes and
    /// the initial condition of a run analyse (a failure is an event of a dynamic run).
    pub fn intact(&self) -> std::borrow::Cow<'_, Model> {
        if self.failures.is_empty() {
            return std::borrow::Cow::Borrowed(self);
        }
        let mut m = self.clone();
        m.failures.clear();
        std::borrow::Cow::Owned(m)
    }

    /// Checks references and physical ranges. The scenario reader gives richer messages with
    /// file positions; this is the last line of defence for models built in code.
    pub fn validate(&self) -> Result<(), ModelError> {
        let bad = |what: String, why: &str| {
            Err(ModelError::Invalid {
                what,
                why: why.to_string(),
            })
        };
        let env = &self.environment;
        if !(env.gravity >= 0.0) {
            return bad("environment.gravity".into(), "must be ≥ 0 m/s²");
        }
        if !(env.water_density > 0.0) || !(env.air_density >= 0.0) {
            return bad("environment density".into(), "must be > 0 kg/m³");
        }
        if !(env.depth > 0.0) {
            return bad("environment.depth".into(), "must be > 0 m");
        }
        if let crate::physics::seabed::Bathymetry::Plane { gradient } = &env.bathymetry {
            if !env.depth.is_finite() {
                return bad(
                    "environment.bathymetry".into(),
                    "is a sloping plane through (0, 0, −depth): it needs a finite depth",
                );
            }
            if !gradient.iter().all(|g| g.is_finite()) {
                return bad(
                    "environment.bathymetry".into(),
                    "has a gradient that is not finite",
                );
            }
        }
        if let Some(w) = env.waves.field()
            && (w.depth() != env.depth || w.gravity() != env.gravity)
        {
            return bad(
                "environment.waves".into(),
                "were built for another depth or gravity: build them with Waves::new for the \
                 environment's depth and gravity (the wavenumbers depend on both)",
            );
        }
        for o in &env.obstacles {
            if let Err(why) = o.validate() {
                return bad(format!("obstacle {}", o.name), &why);
            }
        }
        for t in &self.line_types {
            if !(t.diameter > 0.0) {
                return bad(format!("line type {}: diameter", t.name), "must be > 0 m");
            }
            if !(t.mass_per_length > 0.0) {
                return bad(
                    format!("line type {}: mass_per_length", t.name),
                    "must be > 0 kg/m",
                );
            }
            if !(t.axial_stiffness.max_tangent() > 0.0) {
                return bad(
                    format!("line type {}: axial stiffness", t.name),
                    "must be > 0 N",
                );
            }
        }
        for (li, l) in self.lines.iter().enumerate() {
            if l.sections.is_empty() {
                return bad(format!("line {}", l.name), "has no sections");
            }
            for s in &l.sections {
                if s.line_type >= self.line_types.len() {
                    return bad(
                        format!("line {}: section type", l.name),
                        "refers to no line type",
                    );
                }
                if !(s.length > 0.0) || s.elements == 0 {
                    return bad(
                        format!("line {}: section", l.name),
                        "needs length > 0 m and ≥ 1 element",
                    );
                }
            }
            for end in [&l.end_a, &l.end_b] {
                match end {
                    LineEnd::Point(p) if *p >= self.points.len() => {
                        return bad(
                            format!("line {}", l.name),
                            "is attached to a point that does not exist",
                        );
                    }
                    _ => {}
                }
            }
            for d in l.clamp.iter().flatten() {
                if l.formulation == Formulation::Fe {
                    return bad(
                        format!("line {} (#{li}): clamp", l.name),
                        "needs a formulation with bending and end tangents (`hermite` or `dg`)",
                    );
                }
                if !(d.norm() > 0.0) || !d.iter().all(|x| x.is_finite()) {
                    return bad(
                        format!("line {} (#{li}): clamp", l.name),
                        "must be a non-zero direction",
                    );
                }
            }
            if let Some(w) = &l.winch {
                let what = format!("line {} (#{li}): winch", l.name);
                if l.formulation == Formulation::Dg {
                    return bad(
                        what,
                        "is not available on `dg` lines (their element lengths are built into \
                         the modal operators): use `formulation = \"fe\"` or `\"hermite\"`",
                    );
                }
                if l.sections.len() != 1 {
                    return bad(
                        what,
                        "needs a line of one section (a winch rescales the whole line): put \
                         the winch on a single-section line joined to the rest by a free point",
                    );
                }
                if let Err(why) = w.check(l.length()) {
                    return bad(what, &why);
                }
            }
            if l.formulation == Formulation::Dg {
                let max = crate::formulation::dg::basis::MAX_ORDER;
                if let Some(s) = l.sections.iter().find(|s| !(1..=max).contains(&s.order)) {
                    return bad(
                        format!("line {} (#{li}): section order", l.name),
                        &format!(
                            "is {}; a dg section needs an order P from 1 to {max}",
                            s.order
                        ),
                    );
                }
            }
        }
        for (bi, b) in self.bodies.iter().enumerate() {
            let name = |what: &str| format!("body {} (#{bi}): {what}", b.name);
            if let Err((what, why)) = b.check() {
                return bad(name(what), &why);
            }
            if self.bodies[..bi].iter().any(|o| o.name == b.name) {
                return bad(name("name"), "is used by another body");
            }
            if let Some((parent, point)) = b.kind.pin().and_then(Pin::parent) {
                let Some(host) = self.bodies.get(parent) else {
                    return bad(name("pin"), "is on a body that does not exist");
                };
                if parent == bi {
                    return bad(name("pin"), "is on the body itself: pin it to another body");
                }
                if host.kind.pin().and_then(Pin::parent).is_some() {
                    return bad(
                        name("pin"),
                        &format!(
                            "is on body {}, which is itself pinned to a body: a pin on a body \
                             takes a free, pinned, prescribed or coupled parent (one level)",
                            host.name
                        ),
                    );
                }
                if !point.iter().all(|x| x.is_finite()) {
                    return bad(name("pin point"), "must be finite");
                }
                let at = host.initial_kinematics().point(&point).0;
                if (at - b.position).norm() > 1e-6 * at.norm().max(1.0) {
                    return bad(
                        name("position"),
                        &format!(
                            "is ({:.6}, {:.6}, {:.6}) m where its pin on body {} is at \
                             ({:.6}, {:.6}, {:.6}) m at t = 0: put the body's origin on the pin",
                            b.position.x, b.position.y, b.position.z, host.name, at.x, at.y, at.z
                        ),
                    );
                }
            }
        }
        for p in &self.points {
            if let PointKind::Body { body, offset } = &p.kind {
                if *body >= self.bodies.len() {
                    return bad(
                        format!("point {}", p.name),
                        "is on a body that does not exist",
                    );
                }
                if !offset.iter().all(|x| x.is_finite()) {
                    return bad(format!("point {}: offset", p.name), "must be finite");
                }
            }
        }
        for (k, f) in self.failures.iter().enumerate() {
            if let Err((what, why)) = f.check(self, k) {
                return bad(what, &why);
            }
        }
        self.statics_frame_velocity()?;
        let s = &self.settings;
        if !(s.duration >= 0.0) || !(s.output_interval > 0.0) {
            return bad(
                "simulation".into(),
                "duration must be ≥ 0 s and output_interval > 0 s",
            );
        }
        if !(0.0..=1.0).contains(&s.spectral_radius) {
            return bad(
                "simulation.spectral_radius".into(),
                "must be in [0, 1] (ρ∞ of the generalized-α scheme)",
            );
        }
        if !(s.tolerance > 0.0 && s.tolerance < 1.0) {
            return bad("simulation.tolerance".into(), "must be in (0, 1)");
        }
        for (k, &p) in s.release.iter().enumerate() {
            let what = format!("simulation.release[{k}]");
            match self.points.get(p) {
                None => return bad(what, "refers to a point that does not exist"),
                Some(pt) if !matches!(pt.kind, PointKind::Free { .. }) => {
                    return bad(
                        format!("{what} (point {})", pt.name),
                        "is not a free point: only free points can be released",
                    );
                }
                _ => {}
            }
            if s.release[..k].contains(&p) {
                return bad(what, "names a point released twice");
            }
        }
        Ok(())
    }
}
