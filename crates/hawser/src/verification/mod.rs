//! The verification suite: reference problems with known answers (SPEC §7 "Analytic checks",
//! each built in code for a chosen [`Formulation`], run through the public
//! model, system, statics and simulation API, and compared with its reference.
//!
//! A case returns rows ([`Check`]): quantity with unit, expected and computed value, error,
//! tolerance and outcome, and plot series ([`Plot`]) for the report. A case that a formulation
//! cannot run (refused by [`crate::Model::validate`], or needing bending that the
//! formulation lacks) returns one row marked [`Outcome::NotAvailable`] with the reason: not a
//! failure. Cases never look inside a formulation: they set shapes with
//! [`System::set_line_shape`], read nodes through [`crate::analysis::Channel`], points from the
//! state's free-point blocks and energy from [`System::mechanical_energy`], so a formulation
//! that [`crate::Model::validate`] accepts runs every case unchanged.
//!
//! No I/O here: `hawser-io` writes the report and `hawser validate` prints the table.

mod catenary;
mod conservation;
mod towing;
mod vibration;
mod wave_speed;

pub use catenary::{
    ConvergenceSample, DG_ORDER, catenary_convergence, catenary_errors, catenary_errors_of_order,
    expected_order, grounded_catenary, grounded_chain, sloped_catenary, sloped_chain,
    suspended_catenary, suspended_line,
};
pub use conservation::{
    EnergyRun, ObjectivityRun, energy, energy_drift, free_free, pendulum, rigid_motion_objectivity,
    rigid_rotation,
};
pub use towing::steady_towed_cable;
pub use vibration::{
    HangingMassRun, StringRun, beam_bending, hanging, hanging_mass, hanging_mass_model,
    hanging_mass_period, rod_beta, taut_string, taut_string_frequency, taut_string_model,
};
pub use wave_speed::{WaveArrival, axial_pulse, pulse_arrivals, pulse_speeds};

use crate::analysis::Channel;
use crate::error::{SimulationError, StaticsError};
use crate::math::{Real, Vec3};
use crate::model::{
    Formulation, InitialCondition, Line, LineEnd, LineType, MassMatrix, Model, Point, PointKind,
    Scheme, Section, Settings, TimeStep,
};
use crate::physics::environment::{Current, Environment};
use crate::physics::hydrodynamics::DragModel;
use crate::physics::material::{AxialDamping, AxialStiffness};
use crate::system::{System, Workspace};

/// How much of each case to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fidelity {
    /// The CI subset: the same checks on the meshes and durations the tests use, well under a
    /// minute in release mode for every case together.
    Quick,
    /// The whole suite: finer meshes, longer runs, more samples (under 10 minutes in release
    /// on 2 cores).
    Full,
}

/// How a computed value is judged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// |computed/expected − 1| ≤ the value.
    Relative(Real),
    /// |computed − expected| ≤ the value (in the quantity's unit).
    Absolute(Real),
    /// computed ≤ the value (a bound; `expected` is the ideal value, usually 0).
    AtMost(Real),
    /// computed ≥ the value (a bound; `expected` is the theoretical value).
    AtLeast(Real),
}

/// Result of one check.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Within tolerance.
    Pass,
    /// Outside tolerance, or the run failed (the reason).
    Fail(Option<String>),
    /// The formulation cannot run this case (the reason); not a failure.
    NotAvailable(String),
}

/// One row of the verification table.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// Case name.
    pub case: &'static str,
    /// Formulation run.
    pub formulation: Formulation,
    /// Time-integration scheme of a case that steps in time ([`Case::steps_in_time`]);
    /// `None` for the others, whose rows no scheme changes.
    pub scheme: Option<Scheme>,
    /// What is compared, e.g. "end A tension".
    pub quantity: String,
    /// Unit of expected and computed ("-" for none).
    pub unit: &'static str,
    /// Reference value.
    pub expected: Real,
    /// Computed value.
    pub computed: Real,
    /// The error the tolerance judges: relative for [`Tolerance::Relative`], absolute in the
    /// unit otherwise (the computed value itself for bounds).
    pub error: Real,
    /// Tolerance.
    pub tolerance: Tolerance,
    /// Outcome.
    pub outcome: Outcome,
}

impl Check {
    /// A check of `computed` against `expected`; NaN fails.
    pub fn new(
        quantity: impl Into<String>,
        unit: &'static str,
        expected: Real,
        computed: Real,
        tolerance: Tolerance,
    ) -> Self {
        let (error, pass) = match tolerance {
            Tolerance::Relative(t) => {
                let e = (computed / expected - 1.0).abs();
                (e, e <= t)
            }
            Tolerance::Absolute(t) => {
                let e = (computed - expected).abs();
                (e, e <= t)
            }
            Tolerance::AtMost(t) => (computed, computed <= t),
            Tolerance::AtLeast(t) => ((computed - expected).abs(), computed >= t),
        };
        Self {
            case: "",
            formulation: Formulation::Fe,
            scheme: None,
            quantity: quantity.into(),
            unit,
            expected,
            computed,
            error,
            tolerance,
            outcome: if pass {
                Outcome::Pass
            } else {
                Outcome::Fail(None)
            },
        }
    }

    /// A row for a case that did not produce its numbers.
    fn without_numbers(outcome: Outcome) -> Self {
        Self {
            case: "",
            formulation: Formulation::Fe,
            scheme: None,
            quantity: "(whole case)".into(),
            unit: "-",
            expected: Real::NAN,
            computed: Real::NAN,
            error: Real::NAN,
            tolerance: Tolerance::Absolute(Real::NAN),
            outcome,
        }
    }

    /// Whether this row is a failure.
    pub fn failed(&self) -> bool {
        matches!(self.outcome, Outcome::Fail(_))
    }
}

/// One curve of a plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Abscissae.
    pub x: Vec<Real>,
    /// Ordinates.
    pub y: Vec<Real>,
    /// Draw markers only (computed samples) instead of a line (references).
    pub markers: bool,
}

/// A plot for the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Plot {
    /// File stem, unique in a run (the case and formulation are prefixed by the writer).
    pub name: String,
    /// Title.
    pub title: String,
    /// x axis label with unit.
    pub x_label: String,
    /// y axis label with unit.
    pub y_label: String,
    /// Logarithmic axes (convergence plots).
    pub log: bool,
    /// Curves.
    pub series: Vec<Series>,
}

/// Everything one case produced for one formulation.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseResult {
    /// Case name.
    pub case: &'static str,
    /// Formulation.
    pub formulation: Formulation,
    /// Scheme, for a case that steps in time.
    pub scheme: Option<Scheme>,
    /// Rows.
    pub checks: Vec<Check>,
    /// Plots.
    pub plots: Vec<Plot>,
}

/// Why a case produced no rows of numbers.
#[derive(Clone, Debug, PartialEq)]
pub enum CaseError {
    /// The formulation cannot run the case (the reason).
    NotAvailable(String),
    /// The run failed (statics did not converge, the simulation diverged, ...).
    Failed(String),
}

impl From<StaticsError> for CaseError {
    fn from(e: StaticsError) -> Self {
        CaseError::Failed(format!("statics: {e}"))
    }
}

impl From<SimulationError> for CaseError {
    fn from(e: SimulationError) -> Self {
        CaseError::Failed(format!("simulation: {e}"))
    }
}

/// Rows and plots of a case that ran.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Findings {
    /// Rows.
    pub checks: Vec<Check>,
    /// Plots.
    pub plots: Vec<Plot>,
}

/// A verification case.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// Short name (table and file names).
    pub name: &'static str,
    /// One line on what is compared with what.
    pub description: &'static str,
    /// Whether the case integrates in time, so that its rows depend on the scheme (the others
    /// are statics, steady solutions or evaluations of the forces, and ignore it).
    pub steps_in_time: bool,
    /// Runs the case with a formulation, a fidelity and, for a case that steps in time, the
    /// scheme ([`Scheme::Rk4`] or [`Scheme::GeneralizedAlpha`]; each such case states the
    /// step it takes with each and why its tolerances hold for both).
    pub run: fn(Formulation, Fidelity, Scheme) -> Result<Findings, CaseError>,
}

/// The schemes a case that steps in time runs with in the suite: RK4, the explicit default,
/// and generalized-α, the implicit one.
pub const SCHEMES: [Scheme; 2] = [Scheme::Rk4, Scheme::GeneralizedAlpha];

/// Every case, in report order.
pub const CASES: &[Case] = &[
    Case {
        name: "catenary_suspended",
        description: "suspended elastic catenary: statics end tensions and shape against the \
                      closed form (statics::catenary)",
        steps_in_time: false,
        run: |f, fidelity, _| suspended_catenary(f, fidelity),
    },
    Case {
        name: "catenary_seabed",
        description: "elastic catenary resting on a frictionless seabed (OC3 chain): end \
                      tensions against the closed form",
        steps_in_time: false,
        run: |f, fidelity, _| grounded_catenary(f, fidelity),
    },
    Case {
        name: "catenary_slope",
        description: "elastic catenary resting on a frictionless sloping seabed (OC3 chain, \
                      the bed rising and falling at 5 %): end tensions against the closed form",
        steps_in_time: false,
        run: |f, fidelity, _| sloped_catenary(f, fidelity),
    },
    Case {
        name: "hanging_mass",
        description: "mass on an elastic line: period against rod theory (β tan β = γ0 L/m)",
        steps_in_time: true,
        run: hanging_mass,
    },
    Case {
        name: "axial_wave_speed",
        description: "axial pulse: arrival speed against √(EA/γ0)",
        steps_in_time: true,
        run: axial_pulse,
    },
    Case {
        name: "taut_string",
        description: "taut-string fundamental transverse frequency against \
                      1/(2 L0) √(T/(γ0 (1 + ε)))",
        steps_in_time: true,
        run: taut_string,
    },
    Case {
        name: "beam_bending",
        description: "bending frequencies: tensioned pinned–pinned beam against \
                      (nπ/L) √((EI (nπ/L)² + T)/γ0); the clamped cantilever",
        steps_in_time: true,
        run: beam_bending,
    },
    Case {
        name: "rigid_rotation",
        description: "zero strain under rigid rotation: strains and tensions unchanged by \
                      random rigid motions",
        steps_in_time: false,
        run: |f, fidelity, _| rigid_rotation(f, fidelity),
    },
    Case {
        name: "energy",
        description: "energy conservation without damping or drag: pendulum on an elastic \
                      line, drift and its order in dt",
        steps_in_time: true,
        run: energy,
    },
    Case {
        name: "steady_towed_cable",
        description: "steady towed cable against an independent integration of the steady \
                      cable equations",
        steps_in_time: false,
        run: |f, fidelity, _| steady_towed_cable(f, fidelity),
    },
    Case {
        name: "convergence_order",
        description: "observed order in h of node positions and end tensions of the \
                      suspended catenary against the closed form",
        steps_in_time: false,
        run: |f, fidelity, _| catenary_convergence(f, fidelity),
    },
];

/// Runs one case for one formulation (and `scheme`, if the case steps in time; the others
/// ignore it and their rows carry no scheme): rows labelled with the case, formulation and
/// scheme; a case that did not run gives one row saying why.
pub fn run_case(
    case: &Case,
    formulation: Formulation,
    fidelity: Fidelity,
    scheme: Scheme,
) -> CaseResult {
    let scheme = case.steps_in_time.then_some(scheme);
    let outcome = if scheme == Some(Scheme::GeneralizedAlpha) && formulation == Formulation::Dg {
        Err(CaseError::NotAvailable(
            "dg lines step explicitly: generalized-α refuses them".into(),
        ))
    } else {
        (case.run)(formulation, fidelity, scheme.unwrap_or_default())
    };
    let (mut checks, plots) = match outcome {
        Ok(f) => (f.checks, f.plots),
        Err(CaseError::NotAvailable(why)) => (
            vec![Check::without_numbers(Outcome::NotAvailable(why))],
            vec![],
        ),
        Err(CaseError::Failed(why)) => (
            vec![Check::without_numbers(Outcome::Fail(Some(why)))],
            vec![],
        ),
    };
    for c in &mut checks {
        c.case = case.name;
        c.formulation = formulation;
        c.scheme = scheme;
    }
    CaseResult {
        case: case.name,
        formulation,
        scheme,
        checks,
        plots,
    }
}

/// Lower-case name of a formulation as in scenario files (`fe`, `dg`, `hermite`).
pub fn formulation_name(f: Formulation) -> &'static str {
    match f {
        Formulation::Fe => "fe",
        Formulation::Dg => "dg",
        Formulation::Hermite => "hermite",
    }
}

/// How the report names a run of `formulation` with `scheme`: the formulation alone for the
/// explicit default (RK4) and for cases that do not step in time, `fe (generalized-alpha)`
/// for a case run with another scheme.
pub fn run_label(formulation: Formulation, scheme: Option<Scheme>) -> String {
    match scheme {
        None | Some(Scheme::Rk4) => formulation_name(formulation).to_string(),
        Some(s) => format!("{} ({})", formulation_name(formulation), s.name()),
    }
}

/// Whether a formulation carries bending stiffness (SPEC §3: `fe` has none).
pub fn has_bending(f: Formulation) -> bool {
    !matches!(f, Formulation::Fe)
}

// ---------------------------------------------------------------------------------------------
// Building blocks of the cases: models and formulation-neutral probes.
// ---------------------------------------------------------------------------------------------

/// A run of `model` under `settings` from `state` (of `assemble(model)`'s layout), with no
/// initial statics.
pub fn session_from(
    model: &Model,
    settings: Settings,
    state: Vec<Real>,
) -> Result<crate::Session, CaseError> {
    let mut model = model.clone();
    model.settings = settings;
    Ok(crate::Session::from_state(
        model,
        state,
        crate::session::SessionOptions::default(),
    )?)
}

/// Assembles a model. A refusal is "not available" for a formulation other than `fe` (it is
/// not implemented, or not for this model) and a failure for `fe` (every case is built to
/// run with it).
pub fn assemble(model: &Model) -> Result<System, CaseError> {
    System::new(model).map_err(|e| {
        let fe = model.lines.iter().all(|l| l.formulation == Formulation::Fe);
        if fe {
            CaseError::Failed(format!("model refused: {e}"))
        } else {
            CaseError::NotAvailable(format!("model refused: {e}"))
        }
    })
}

/// A line type with Morison drag (Cdn 1.2), normal added mass 1, no damping, no bending.
pub fn line_type(diameter: Real, mass_per_length: Real, axial_stiffness: Real) -> LineType {
    LineType {
        name: "t".into(),
        diameter,
        mass_per_length,
        axial_stiffness: AxialStiffness::Linear(axial_stiffness),
        axial_damping: AxialDamping::Coefficient(0.0),
        compression: false,
        bending_stiffness: 0.0,
        bending_damping: 0.0,
        drag: DragModel::Morison {
            normal: 1.2,
            tangential: 0.0,
        },
        normal_added_mass: 1.0,
        tangential_added_mass: 0.0,
        minimum_breaking_load: None,
        design_safety_factor: None,
    }
}

/// A line type without any fluid loading: no drag, no added mass (buoyancy remains below
/// z = 0).
pub fn dry_line_type(diameter: Real, mass_per_length: Real, axial_stiffness: Real) -> LineType {
    LineType {
        drag: DragModel::Morison {
            normal: 0.0,
            tangential: 0.0,
        },
        normal_added_mass: 0.0,
        tangential_added_mass: 0.0,
        ..line_type(diameter, mass_per_length, axial_stiffness)
    }
}

/// One line of `formulation` (and `mass_matrix`, for `fe`) between points `a` and `b`, in
/// water without current.
pub fn single_line(
    line_type: LineType,
    length: Real,
    elements: usize,
    (a, b): (Point, Point),
    formulation: Formulation,
    mass_matrix: MassMatrix,
) -> Model {
    Model {
        environment: Environment {
            current: Current::None,
            ..Default::default()
        },
        line_types: vec![line_type],
        lines: vec![Line {
            name: "L".into(),
            sections: vec![Section {
                line_type: 0,
                length,
                elements,
                order: 4,
            }],
            formulation,
            mass_matrix,
            strain_measure: Default::default(),
            modal_filter: crate::formulation::dg::line::DEFAULT_MODAL_FILTER,
            shock_filter: 0.0,
            clamp: [None; 2],
            end_a: LineEnd::Point(0),
            end_b: LineEnd::Point(1),
            winch: None,
        }],
        points: vec![a, b],
        bodies: Vec::new(),
        settings: Settings::default(),
        outputs: Vec::new(),
        failures: Vec::new(),
    }
}

/// A fixed point.
pub fn fixed(name: &str, position: Vec3) -> Point {
    Point {
        name: name.into(),
        position,
        kind: PointKind::Fixed,
    }
}

/// A free point mass without drag or added mass.
pub fn free(name: &str, position: Vec3, mass: Real, volume: Real) -> Point {
    Point {
        name: name.into(),
        position,
        kind: PointKind::Free {
            mass,
            volume,
            drag_area: 0.0,
            added_mass_coefficient: 0.0,
            force: Vec3::zeros(),
        },
    }
}

/// An environment without any medium effect above the water: air of zero density, no
/// current, and the given gravity [m/s²].
pub fn vacuum_environment(gravity: Real) -> Environment {
    Environment {
        gravity,
        air_density: 0.0,
        current: Current::None,
        ..Default::default()
    }
}

/// Settings for a run with exactly `dt` per step [s] (the output interval is one step).
pub fn fixed_step_settings(dt: Real, scheme: Scheme) -> Settings {
    Settings {
        time_step: TimeStep::Fixed(dt),
        output_interval: dt,
        scheme,
        initial_condition: InitialCondition::AsDefined,
        ..Default::default()
    }
}

/// `wanted` [s], or `fraction` of the system's RK4 stability limit when that is smaller: a
/// step chosen for one formulation stays stable, and as far inside RK4's asymptotic range,
/// for another whose fastest element mode is faster.
pub fn rk4_step(system: &System, wanted: Real, fraction: Real) -> Real {
    wanted.min(fraction * system.stable_step(Scheme::Rk4).0)
}

/// Position [m] of node `node` (0 at end A) of line `line` from a workspace holding an
/// evaluation at the state of interest.
pub fn node_position(system: &System, ws: &Workspace, line: usize, node: usize) -> Vec3 {
    Vec3::from_fn(|axis, _| Channel::NodePosition { line, node, axis }.value(system, ws))
}

/// Position [m] and velocity [m/s] of free point `point` in state `y`.
pub fn point_state(system: &System, y: &[Real], point: usize) -> (Vec3, Vec3) {
    let o = system.layout.point_offset[point].expect("a free point");
    (
        Vec3::new(y[o], y[o + 1], y[o + 2]),
        Vec3::new(y[o + 3], y[o + 4], y[o + 5]),
    )
}

/// Sets position and velocity of free point `point` in state `y`.
pub fn set_point_state(system: &System, y: &mut [Real], point: usize, r: Vec3, v: Vec3) {
    let o = system.layout.point_offset[point].expect("a free point");
    y[o..o + 3].copy_from_slice(r.as_slice());
    y[o + 3..o + 6].copy_from_slice(v.as_slice());
}

/// Times [s] at which the sampled signal `x` crosses `level` upwards, by linear interpolation
/// between samples `dt` apart starting at t = 0.
pub fn upward_crossings(x: &[Real], level: Real, dt: Real) -> Vec<Real> {
    let times: Vec<Real> = (0..x.len()).map(|i| i as Real * dt).collect();
    upward_crossings_at(&times, x, level)
}

/// Times [s] at which the samples `x` taken at `times` (increasing; steps of any length, as an
/// adaptive scheme takes them) cross `level` upward, interpolated linearly between samples.
pub fn upward_crossings_at(times: &[Real], x: &[Real], level: Real) -> Vec<Real> {
    let mut out = Vec::new();
    for i in 1..x.len() {
        let (a, b) = (x[i - 1] - level, x[i] - level);
        if a < 0.0 && b >= 0.0 {
            out.push(times[i - 1] + (times[i] - times[i - 1]) * a / (a - b));
        }
    }
    out
}

/// Mean period [s] from successive crossing times: (last − first)/(count − 1); NaN with
/// fewer than two crossings.
pub fn mean_period(crossings: &[Real]) -> Real {
    if crossings.len() < 2 {
        return Real::NAN;
    }
    (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as Real
}

/// Observed orders log2(e_N / e_2N) of a sequence of errors at N, 2N, 4N, ...
pub fn observed_orders(errors: &[Real]) -> Vec<Real> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// At most `count` evenly spread samples of (x, y) for a plot.
pub(crate) fn thin(x: &[Real], y: &[Real], count: usize) -> (Vec<Real>, Vec<Real>) {
    let stride = x.len().div_ceil(count.max(1)).max(1);
    (
        x.iter().step_by(stride).copied().collect(),
        y.iter().step_by(stride).copied().collect(),
    )
}

/// A small deterministic generator (SplitMix64) for reproducible random checks.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> Real {
        (self.next_u64() >> 11) as Real / (1u64 << 53) as Real
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, a: Real, b: Real) -> Real {
        a + (b - a) * self.uniform()
    }
    /// A uniformly distributed rotation matrix (from a random unit quaternion, Shoemake).
    pub fn rotation(&mut self) -> crate::math::Mat3 {
        let (u1, u2, u3) = (self.uniform(), self.uniform(), self.uniform());
        let tau = std::f64::consts::TAU;
        let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
        let (w, x, y, z) = (
            a * (tau * u2).sin(),
            a * (tau * u2).cos(),
            b * (tau * u3).sin(),
            b * (tau * u3).cos(),
        );
        crate::math::Mat3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        )
    }
}
