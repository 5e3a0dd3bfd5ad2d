//! The scenario file format (TOML): plain serde types that mirror the file, with the source
//! span of every value kept for error messages. [`super::build`] turns them into a
//! [`hawser::Model`]; docs/scenario.md documents every key, and `hawser schema` prints the
//! JSON Schema generated from these types.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use toml::Spanned;

/// A number (the same for every axis) or one number per axis.
#[derive(Clone, Debug, Deserialize, Serialize, JsonSchema, PartialEq)]
#[serde(untagged)]
pub enum ScalarOrVec3 {
    /// One value for x, y and z.
    Scalar(f64),
    /// [x, y, z].
    Vector([f64; 3]),
}

impl ScalarOrVec3 {
    /// As a 3-array.
    pub fn as_array(&self) -> [f64; 3] {
        match self {
            ScalarOrVec3::Scalar(s) => [*s; 3],
            ScalarOrVec3::Vector(v) => *v,
        }
    }
}

/// `time_step`: `"auto"` or a step in seconds.
#[derive(Clone, Debug, Deserialize, Serialize, JsonSchema, PartialEq)]
#[serde(untagged)]
pub enum TimeStepSpec {
    /// A fixed step [s].
    Value(f64),
    /// `"auto"`: the CFL limit times the safety factor.
    Keyword(String),
}

/// A whole scenario file.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Duration, time step, outputs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simulation: Option<SimulationSpec>,
    /// Gravity, water, air, seabed and current.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub environment: Option<EnvironmentSpec>,
    /// Cable properties, referenced by name from line sections.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub line_types: Vec<LineTypeSpec>,
    /// Anchors, fairleads, free point masses.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<PointSpec>,
    /// Lines between points.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub lines: Vec<LineSpec>,
    /// Rigid bodies.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bodies: Vec<BodySpec>,
    /// Spheres and cylinders, fixed or moving, that lines touch.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub obstacles: Vec<ObstacleSpec>,
    /// Line ends at one point that release together and stay joined (docs/failure.md); a
    /// single line end's failure is `[lines.failure]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub failures: Vec<JoinedFailureSpec>,
    /// The window, storm duration and linked channels of the design statistics a run
    /// reports in `summary.json`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub statistics: Option<StatisticsSpec>,
}

/// `[statistics]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema, Default)]
#[serde(deny_unknown_fields)]
pub struct StatisticsSpec {
    /// Samples before this time are left out of the statistics and the range graphs (the
    /// build-up) [s], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub start: Option<Spanned<f64>>,
    /// Storm duration of the most probable maximum [s], default 10800 (3 h).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub storm_duration: Option<Spanned<f64>>,
    /// Channels whose values are reported at the time of every channel's minimum and
    /// maximum, e.g. `"L1.end_b.tension"`, `"buoy.z"`, or a column name of
    /// `simulation.channels`; recorded if they are not already.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[schemars(with = "Vec<String>")]
    pub linked_channels: Vec<Spanned<String>>,
}

/// Integration scheme.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum SchemeSpec {
    /// Classical 4th-order Runge–Kutta.
    Rk4,
    /// Third-order SSP Runge–Kutta.
    SspRk3,
    /// The elastic-link paper's explicit three-time-level predictor–corrector with variable
    /// steps.
    ThreeLevel,
    /// The implicit generalized-α method (Chung and Hulbert 1993) with Newton iterations:
    /// adaptive steps with `time_step = "auto"`, far above the explicit stability limit.
    GeneralizedAlpha,
    /// RK4 or generalized-α, whichever the rule of docs/implicit.md finds cheaper at the
    /// `tolerance` asked (the default).
    Auto,
}

/// A result format written besides CSV and JSON (which every run writes).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum FormatSpec {
    /// `timeseries.parquet` beside `timeseries.csv` (always written): the time series for
    /// pandas, polars and pyarrow.
    Parquet,
    /// `vtk/run.pvd` and its `.vtp` files: lines, bodies and points at every snapshot, for
    /// ParaView (with `snapshot_interval`).
    Vtk,
}

/// What a fixed `time_step` above the stability limit does.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum StepAboveLimitSpec {
    /// The run is refused with the limit and what sets it (default).
    Refuse,
    /// The automatic step is taken instead, with a warning (what MoorDyn decks and their
    /// conversions use: a deck's `dtM` was chosen for MoorDyn's integrator).
    Auto,
}

/// Initial condition of a dynamic run.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum InitialConditionSpec {
    /// Start from static equilibrium.
    Statics,
    /// Start from the catenary seed, at rest.
    AsDefined,
    /// Start from the steady tow: the equilibrium in the frame moving with the towing vessel
    /// (the prescribed points and bodies, all at one constant velocity V), everything moving
    /// at V.
    SteadyTow,
}

/// `[simulation]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SimulationSpec {
    /// Simulated duration [s].
    #[schemars(with = "f64")]
    pub duration: Spanned<f64>,
    /// `"auto"` (default) or a fixed step [s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<TimeStepSpec>")]
    pub time_step: Option<Spanned<TimeStepSpec>>,
    /// Fraction of the stability limit used by `time_step = "auto"` [-], default 0.8.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub safety_factor: Option<Spanned<f64>>,
    /// `"auto"` (default: RK4 or generalized-α, whichever is the cheaper at `tolerance`),
    /// `"rk4"`, `"ssp-rk3"`, `"three-level"` or `"generalized-alpha"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scheme: Option<SchemeSpec>,
    /// ρ∞ of the generalized-α scheme [-], in [0, 1]: the amplitude factor per step of a mode
    /// far above what the step resolves (1: no numerical dissipation), default 0.8.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub spectral_radius: Option<Spanned<f64>>,
    /// Accuracy asked [-]: the largest local error per step of the adaptive generalized-α
    /// step, in element tension relative to the line's reference tension; also what
    /// `scheme = "auto"` chooses for. Default 1e-6.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub tolerance: Option<Spanned<f64>>,
    /// A fixed `time_step` above the stability limit: `"refuse"` the run (default) or take
    /// the `"auto"` step instead.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step_above_limit: Option<StepAboveLimitSpec>,
    /// Interval between time-series samples [s], default 0.1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub output_interval: Option<Spanned<f64>>,
    /// Interval between line shape snapshots [s]; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub snapshot_interval: Option<Spanned<f64>>,
    /// Result formats written besides CSV and JSON: `"parquet"`, `"vtk"` (ParaView files at
    /// each snapshot); both by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<FormatSpec>>")]
    pub formats: Option<Spanned<Vec<FormatSpec>>>,
    /// `"statics"` (default), `"as-defined"` or `"steady-tow"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<InitialConditionSpec>")]
    pub initial_condition: Option<Spanned<InitialConditionSpec>>,
    /// Free points held fixed at their `position` in the initial static equilibrium and
    /// released at t = 0 (a release test, e.g. the DG paper's swinging cable).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[schemars(with = "Vec<String>")]
    pub release: Vec<Spanned<String>>,
    /// Extra channels, e.g. `"L1.node10.tension"`, `"buoy.z"`; `"NAME = CHANNEL"` names the
    /// column (`"FairTen1 = L1.end_b.node_force"`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[schemars(with = "Vec<String>")]
    pub channels: Vec<Spanned<String>>,
}

/// `[environment]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema, Default)]
#[serde(deny_unknown_fields)]
pub struct EnvironmentSpec {
    /// Gravitational acceleration [m/s²], default 9.80665.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub gravity: Option<Spanned<f64>>,
    /// Water density [kg/m³], default 1025.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub water_density: Option<Spanned<f64>>,
    /// Air density [kg/m³], default 1.225.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub air_density: Option<Spanned<f64>>,
    /// Water depth [m]: flat seabed at z = −depth (the depth at the origin of a sloping
    /// seabed, the waves' depth over a grid). Omit for deep water without a seabed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub depth: Option<Spanned<f64>>,
    /// Seabed contact.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seabed: Option<SeabedSpec>,
    /// Current.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub current: Option<CurrentSpec>,
    /// Waves; a calm sea by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub waves: Option<WavesSpec>,
}

/// `[environment.seabed]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeabedSpec {
    /// Contact stiffness per unit area [Pa/m], default 3e6.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub stiffness: Option<Spanned<f64>>,
    /// Damping ratio of the vertical contact [-], default 1 (critical).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub damping_ratio: Option<Spanned<f64>>,
    /// Vertical contact damping per unit contact area [Pa·s/m], instead of `damping_ratio`
    /// (MoorDyn's `cBot`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub damping: Option<Spanned<f64>>,
    /// Dynamic friction coefficient [-], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub friction_coefficient: Option<Spanned<f64>>,
    /// Sliding speed over which friction builds up [m/s], default 0.01.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub friction_velocity: Option<Spanned<f64>>,
    /// Friction damping per node c [N·s/m]: MoorDyn's friction law, min(μ·c·|v|, μ·|F_z|)
    /// per node, instead of μ·tanh(π|v|/v_μ) (MoorDyn's `FricDamp`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub friction_damping: Option<Spanned<f64>>,
    /// Ratio of static to dynamic friction with `friction_damping` [-], default 1 (MoorDyn's
    /// `StatDynFricScale`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub static_friction_scale: Option<Spanned<f64>>,
    /// A sloping plane through (0, 0, −depth): its rise per metre [∂z/∂x, ∂z/∂y] [-]; flat by
    /// default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 2]>")]
    pub gradient: Option<Spanned<[f64; 2]>>,
    /// A sloping plane through (0, 0, −depth) given by its upward normal [nx, ny, nz] [-]
    /// (any length, nz > 0), instead of `gradient`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub normal: Option<Spanned<[f64; 3]>>,
    /// A grid of bed heights, interpolated bilinearly: a MoorDyn `SeafloorFile` (C or F
    /// format) or a CSV with columns `x,y,z` (or `depth`), relative to the scenario file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub grid: Option<Spanned<String>>,
}

/// Kind of current.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum CurrentKind {
    /// The same velocity at every depth.
    Uniform,
    /// A table of velocity against height z.
    Profile,
    /// Profiles against time: velocity at heights `z` and `times`, interpolated in both.
    ProfileTable,
}

/// `[environment.current]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CurrentSpec {
    /// `"uniform"` or `"profile"`.
    #[serde(rename = "type")]
    #[schemars(with = "CurrentKind")]
    pub kind: Spanned<CurrentKind>,
    /// Uniform current velocity [m/s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub velocity: Option<Spanned<[f64; 3]>>,
    /// Profile rows `[z, ux, uy, uz]` [m, m/s], z increasing (negative below the surface).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<[f64; 4]>>")]
    pub profile: Option<Spanned<Vec<[f64; 4]>>>,
    /// Heights z [m] of a `profile-table`, strictly increasing (negative below the surface).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<f64>>")]
    pub z: Option<Spanned<Vec<f64>>>,
    /// Times t [s] of a `profile-table`, strictly increasing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<f64>>")]
    pub times: Option<Spanned<Vec<f64>>>,
    /// x velocity [m/s] of a `profile-table`: one row per time, one value per height.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<Vec<f64>>>")]
    pub ux: Option<Spanned<Vec<Vec<f64>>>>,
    /// y velocity [m/s] of a `profile-table` (rows as `ux`); zero if not given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<Vec<f64>>>")]
    pub uy: Option<Spanned<Vec<Vec<f64>>>>,
    /// z velocity [m/s] of a `profile-table` (rows as `ux`); zero if not given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<Vec<f64>>>")]
    pub uz: Option<Spanned<Vec<Vec<f64>>>>,
}

/// Kind of waves.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum WaveKind {
    /// One regular Airy wave.
    Regular,
    /// An irregular sea from a JONSWAP spectrum.
    Jonswap,
    /// An irregular sea from a Pierson–Moskowitz spectrum.
    PiersonMoskowitz,
    /// The Fourier components of a recorded surface elevation η(t) at the origin.
    ElevationRecord,
}

/// How line quadrature points take the wave kinematics.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum WaveKinematicsSpec {
    /// Summed over every component at each point's current position (the reference).
    Direct,
    /// Summed at each point's static position at intervals and interpolated in time.
    StaticPosition,
}

/// Continuation of the linear wave profiles above the mean water level.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum StretchingSpec {
    /// Stretching of the whole water column to the instantaneous surface (Wheeler).
    Wheeler,
    /// Linear profiles below z = 0, the z = 0 value held up to the surface.
    Vertical,
}

/// `[environment.waves]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WavesSpec {
    /// `"regular"`, `"jonswap"` or `"pierson-moskowitz"`.
    #[serde(rename = "type")]
    #[schemars(with = "WaveKind")]
    pub kind: Spanned<WaveKind>,
    /// Regular wave height H, crest to trough [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub height: Option<Spanned<f64>>,
    /// Regular wave period T [s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub period: Option<Spanned<f64>>,
    /// Significant wave height Hs [m] of an irregular sea.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub significant_height: Option<Spanned<f64>>,
    /// Peak period Tp [s] of an irregular sea.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub peak_period: Option<Spanned<f64>>,
    /// JONSWAP peak enhancement factor γ [-], default 3.3.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub gamma: Option<Spanned<f64>>,
    /// Direction the waves travel toward [deg], from +x toward +y; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub direction: Option<Spanned<f64>>,
    /// Exponent s of cos-2s directional spreading [-]; long-crested by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub spreading: Option<Spanned<f64>>,
    /// Seed of the random frequencies, phases and directions; default 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub seed: Option<Spanned<i64>>,
    /// Number of wave components [-], default 200.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub components: Option<Spanned<i64>>,
    /// Lowest and highest component frequency [Hz], default 0.5 and 5 times the peak
    /// frequency 1/Tp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 2]>")]
    pub frequency_range: Option<Spanned<[f64; 2]>>,
    /// Build-up time [s] over which the sea grows from calm; default two (peak) periods, 0 for
    /// none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub ramp_time: Option<Spanned<f64>>,
    /// `"wheeler"` (default) or `"vertical"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stretching: Option<StretchingSpec>,
    /// `"direct"` (default) or `"static-position"`: how lines take the wave kinematics.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<WaveKinematicsSpec>")]
    pub kinematics: Option<Spanned<WaveKinematicsSpec>>,
    /// Sample interval of `static-position` kinematics [s]; default 1/25 of the period of the
    /// highest-frequency component.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub sample_interval: Option<Spanned<f64>>,
    /// Elevation record rows `[t, η]` [s, m] of an `elevation-record` (or `elevation_file`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<[f64; 2]>>")]
    pub elevation: Option<Spanned<Vec<[f64; 2]>>>,
    /// File of an `elevation-record`, relative to the scenario file: rows `t η` [s, m]
    /// (MoorDyn's `wave_elevation.txt`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub elevation_file: Option<Spanned<String>>,
    /// Interval [s] at which an `elevation-record` is resampled (linearly) before its Fourier
    /// transform; default its smallest time step (MoorDyn's `dtWave`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub resample_interval: Option<Spanned<f64>>,
    /// Components of an `elevation-record` above this frequency [Hz] are dropped; default
    /// none (up to the Nyquist frequency).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub cutoff_frequency: Option<Spanned<f64>>,
}

/// Fourier coefficients of a drag loading function.
#[derive(Debug, Deserialize, Serialize, JsonSchema, Default, Clone)]
#[serde(deny_unknown_fields)]
pub struct FourierSpec {
    /// Cosine coefficients a_0, a_1, ... [-].
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cos: Vec<f64>,
    /// Sine coefficients b_0, b_1, ... [-].
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sin: Vec<f64>,
}

/// `[line_types.loading_functions]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadingFunctionsSpec {
    /// Normal loading function C_n(φ).
    pub normal: FourierSpec,
    /// Tangential loading function C_t(φ).
    pub tangential: FourierSpec,
}

/// `[[line_types]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LineTypeSpec {
    /// Name, referenced by line sections.
    #[schemars(with = "String")]
    pub name: Spanned<String>,
    /// Nominal (hydrodynamic) diameter [m].
    #[schemars(with = "f64")]
    pub diameter: Spanned<f64>,
    /// Mass per unit unstretched length [kg/m].
    #[schemars(with = "f64")]
    pub mass_per_length: Spanned<f64>,
    /// Axial stiffness EA [N] (or give `tension_strain`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub axial_stiffness: Option<Spanned<f64>>,
    /// Tension–strain table rows `[strain, tension]` [-, N], from `[0, 0]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<[f64; 2]>>")]
    pub tension_strain: Option<Spanned<Vec<[f64; 2]>>>,
    /// Axial damping coefficient [N·s], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub axial_damping: Option<Spanned<f64>>,
    /// Axial damping as a fraction of critical damping of one element's axial mode [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub axial_damping_ratio: Option<Spanned<f64>>,
    /// Normal drag coefficient C_dn [-] on the area d per length.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub normal_drag: Option<Spanned<f64>>,
    /// Tangential drag coefficient C_dt [-] on the area d per length.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub tangential_drag: Option<Spanned<f64>>,
    /// Drag loading functions instead of `normal_drag`/`tangential_drag`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub loading_functions: Option<LoadingFunctionsSpec>,
    /// Normal added-mass coefficient C_an [-], default 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub normal_added_mass: Option<Spanned<f64>>,
    /// Tangential added-mass coefficient C_at [-], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub tangential_added_mass: Option<Spanned<f64>>,
    /// Whether the line carries compression, default false.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compression: Option<bool>,
    /// Bending stiffness EI [N·m²], default 0 (used by formulations with bending).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub bending_stiffness: Option<Spanned<f64>>,
    /// Bending damping [N·m²·s], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub bending_damping: Option<Spanned<f64>>,
    /// Minimum breaking load MBL [N]: runs and statics report the utilisation T_max / MBL.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub minimum_breaking_load: Option<Spanned<f64>>,
    /// Design safety factor SF [-] (≥ 1; needs `minimum_breaking_load`): the permissible
    /// tension is MBL / SF.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub design_safety_factor: Option<Spanned<f64>>,
}

/// Kind of point.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum PointKindSpec {
    /// Fixed in space (anchor).
    Fixed,
    /// Free point mass, buoy, clump weight or joint.
    Free,
    /// Prescribed motion (fairlead).
    Prescribed,
    /// Fixed on a rigid body (`body`), at `position` in body axes from the body origin.
    Body,
    /// Moved by a host program at each coupling step (the Python session, the C ABI, the
    /// MoorDyn-compatible library); it starts at `position`, and the lines' reaction force on
    /// it is read back. Run alone (the CLI), it stays at `position`.
    Coupled,
}

/// `[[points]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    /// Name, referenced by lines and channels.
    #[schemars(with = "String")]
    pub name: Spanned<String>,
    /// `"fixed"`, `"free"`, `"prescribed"`, `"body"` or `"coupled"`.
    #[serde(rename = "type")]
    #[schemars(with = "PointKindSpec")]
    pub kind: Spanned<PointKindSpec>,
    /// Position [m] (fixed; initial for free points; start of a prescribed motion)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub position: Option<Spanned<[f64; 3]>>,
    /// Mass [kg] (free points), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub mass: Option<Spanned<f64>>,
    /// Displaced volume [m³] (free points), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub volume: Option<Spanned<f64>>,
    /// Drag coefficient times area C_d·A [m²] (free points), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub drag_area: Option<Spanned<f64>>,
    /// Added-mass coefficient on the displaced volume [-] (free points), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub added_mass_coefficient: Option<Spanned<f64>>,
    /// Constant external force [N] (free points), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub force: Option<Spanned<[f64; 3]>>,
    /// Prescribed motion (prescribed points).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSpec>,
    /// The body the point is fixed on (`type = "body"`); its `position` is then the offset
    /// from the body origin in body axes [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub body: Option<Spanned<String>>,
}

/// Kind of prescribed motion.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum MotionKind {
    /// Stays at `position`.
    Fixed,
    /// `position + velocity·t`.
    ConstantVelocity,
    /// Sinusoid per axis, starting at `position`.
    Sinusoid,
    /// Circular orbit in a coordinate plane, starting at `position`.
    CircularOrbit,
    /// Piecewise-linear positions from a table or a CSV file.
    TimeSeries,
    /// The point rides on a vessel whose motion (t, x, y, z, roll, pitch, yaw) is read from a
    /// file: the point's `position` is its place on the vessel at rest.
    VesselMotion,
    /// The point rides on a vessel doing a manoeuvre: straight run, turn, straight run; the
    /// point's `position` is its place on the vessel (vessel axes, from the vessel origin).
    Manoeuvre,
    /// The point rides on a vessel moving in the waves as its RAO table says, on a mean
    /// motion; the point's `position` is its place on the vessel.
    Rao,
}

/// Coordinate plane of a circular orbit.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum PlaneSpec {
    /// x–y (horizontal).
    Xy,
    /// x–z (vertical, along x).
    Xz,
    /// y–z (vertical, along y).
    Yz,
}

/// `[points.motion]` (and `[obstacles.motion]`).
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    /// Kind of motion.
    #[serde(rename = "type")]
    #[schemars(with = "MotionKind")]
    pub kind: Spanned<MotionKind>,
    /// Velocity [m/s] (`constant-velocity`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub velocity: Option<Spanned<[f64; 3]>>,
    /// Amplitude per axis [m] (`sinusoid`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ScalarOrVec3>")]
    pub amplitude: Option<Spanned<ScalarOrVec3>>,
    /// Period [s], one or per axis (`sinusoid`; or give `frequency`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ScalarOrVec3>")]
    pub period: Option<Spanned<ScalarOrVec3>>,
    /// Frequency [Hz], one or per axis (`sinusoid`, `circular-orbit`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ScalarOrVec3>")]
    pub frequency: Option<Spanned<ScalarOrVec3>>,
    /// Phase [deg], one or per axis (`sinusoid`, `circular-orbit`), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ScalarOrVec3>")]
    pub phase: Option<Spanned<ScalarOrVec3>>,
    /// Build-up time [s] over which the amplitude ramps smoothly from zero (`sinusoid`, `circular-orbit`), default 0 (none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub ramp_time: Option<Spanned<f64>>,
    /// Orbit radius [m] (`circular-orbit`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub radius: Option<Spanned<f64>>,
    /// Orbit plane, default `"xz"` (`circular-orbit`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plane: Option<PlaneSpec>,
    /// Rows `[t, x, y, z]` [s, m] (`time-series`), or give `file`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<[f64; 4]>>")]
    pub table: Option<Spanned<Vec<[f64; 4]>>>,
    /// File relative to the scenario file: columns t, x, y, z [s, m] (`time-series`),
    /// t, x, y, z, roll, pitch, yaw [s, m, deg] (`vessel-motion`), or the RAO table (`rao`,
    /// docs/motions.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub file: Option<Spanned<String>>,
    /// Added to the file's times [s] (`vessel-motion`), default 0: a file that starts at
    /// t = −10 s with `time_offset = 10` starts at the beginning of the run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub time_offset: Option<Spanned<f64>>,
    /// Position of the vessel origin at t = 0 [m] (`manoeuvre`; `fixed` and
    /// `constant-velocity` as a vessel's mean motion), default [0, 0, 0].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub start: Option<Spanned<[f64; 3]>>,
    /// Vessel heading at t = 0 [deg], from +x toward +y (`manoeuvre`; `fixed` and
    /// `constant-velocity` as a mean motion), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub heading: Option<Spanned<f64>>,
    /// Speed along the track [m/s] (`manoeuvre`; or give `speed_knots`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub speed: Option<Spanned<f64>>,
    /// Speed along the track [kn] (`manoeuvre`; or give `speed`), 1 kn = 1852/3600 m/s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub speed_knots: Option<Spanned<f64>>,
    /// Length of the straight run before the turn [m] (`manoeuvre`), default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub straight_before: Option<Spanned<f64>>,
    /// Radius of the turn's circular arc [m] (`manoeuvre`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub turn_radius: Option<Spanned<f64>>,
    /// Heading change of the turn [deg], positive to port (counter-clockwise seen from
    /// above), negative to starboard (`manoeuvre`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub turn_angle: Option<Spanned<f64>>,
    /// Length of the straight run after the turn [m], at whose end the vessel comes to rest
    /// (`manoeuvre`); omitted, it goes on for ever.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub straight_after: Option<Spanned<f64>>,
    /// Time over which the speed builds up smoothly from rest [s] (`manoeuvre`), default 0
    /// (impulsive start).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub build_up_time: Option<Spanned<f64>>,
    /// Length of each curvature transition (clothoid) into and out of the turn [m]
    /// (`manoeuvre`), default 0 (the curvature jumps to 1/R).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub transition_length: Option<Spanned<f64>>,
    /// The vessel's mean motion (`rao`): a table of type `fixed`, `constant-velocity` or
    /// `manoeuvre`; default fixed at `start` with `heading`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean: Option<Box<MotionSpec>>,
}

/// Line formulation.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum FormulationSpec {
    /// Position-vector finite elements.
    Fe,
    /// High-order discontinuous Galerkin (bending; snap loads).
    Dg,
    /// Cubic Hermite elements (positions and tangents; bending).
    Hermite,
}

/// Axial strain measure of `hermite` lines.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum StrainSpec {
    /// ε = |∂r/∂s| − 1 (default).
    Exact,
    /// ε = ½(|∂r/∂s|² − 1), the elastic-link paper's eq. 12.
    SmallStrain,
}

/// Mass matrix of `fe` lines.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum MassMatrixSpec {
    /// Consistent (default).
    Consistent,
    /// Lumped.
    Lumped,
}

/// `[[lines.sections]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SectionSpec {
    /// Line type name.
    #[serde(rename = "type")]
    #[schemars(with = "String")]
    pub line_type: Spanned<String>,
    /// Unstretched length [m].
    #[schemars(with = "f64")]
    pub length: Spanned<f64>,
    /// Number of elements.
    #[schemars(with = "i64")]
    pub elements: Spanned<i64>,
    /// Polynomial order P of the elements (`dg`), 1 to 16; default 4.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub order: Option<Spanned<i64>>,
}

/// `[[lines]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LineSpec {
    /// Name, used for channels and results.
    #[schemars(with = "String")]
    pub name: Spanned<String>,
    /// Point at end A (arc length 0).
    #[schemars(with = "String")]
    pub end_a: Spanned<String>,
    /// Point at end B.
    #[schemars(with = "String")]
    pub end_b: Spanned<String>,
    /// `"fe"` (default), `"dg"` or `"hermite"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<FormulationSpec>")]
    pub formulation: Option<Spanned<FormulationSpec>>,
    /// `"consistent"` (default) or `"lumped"` (`fe`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_matrix: Option<MassMatrixSpec>,
    /// `"exact"` (default) or `"small-strain"` (`hermite`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strain: Option<StrainSpec>,
    /// Strength of the modal velocity filter of a `dg` line [-], 0 to 1; default 0.05; 0
    /// switches it off (docs/dg.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub modal_filter: Option<Spanned<f64>>,
    /// Extra modal filter strength of a `dg` line at fronts [-], 0 to 1; default 0 (off);
    /// a smoothness sensor per element switches it on (docs/dg.md, shock sensor).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub shock_filter: Option<Spanned<f64>>,
    /// Clamped end A: the direction [-] of the line's tangent there, held fixed (`hermite`);
    /// default pinned.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub clamp_a: Option<Spanned<[f64; 3]>>,
    /// Clamped end B: the direction [-] of the line's tangent there (pointing from A toward
    /// B), held fixed (`hermite`); default pinned.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub clamp_b: Option<Spanned<[f64; 3]>>,
    /// Line type of a single-section line (or give `sections`).
    #[serde(default, rename = "type", skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub line_type: Option<Spanned<String>>,
    /// Unstretched length [m] of a single-section line.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub length: Option<Spanned<f64>>,
    /// Elements of a single-section line.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub elements: Option<Spanned<i64>>,
    /// Polynomial order P of a single-section `dg` line, 1 to 16; default 4.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub order: Option<Spanned<i64>>,
    /// Sections from end A to end B.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sections: Vec<SectionSpec>,
    /// A winch paying the line out or hauling it in on a schedule (`fe` and `hermite` lines
    /// of one section; docs/winches.md); none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub winch: Option<WinchSpec>,
    /// One end of the line releases from its attachment during a run, at a time, above a
    /// tension or on a host's call (docs/failure.md); none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failure: Option<FailureSpec>,
}

/// `[lines.failure]`: one end of the line releases from the point it is attached to at the
/// first step end where `time` is reached or the end's tension reaches `tension` (or the line
/// type's minimum breaking load with `at_breaking_load`), whichever comes first. Without
/// either trigger the end releases only on a host's call (Python `Session.release`). The end
/// then moves freely with the line; the run goes on (docs/failure.md).
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FailureSpec {
    /// `"A"` or `"B"`: the end that releases.
    #[schemars(with = "LineEndSpec")]
    pub end: Spanned<LineEndSpec>,
    /// Release time [s], ≥ 0; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub time: Option<Spanned<f64>>,
    /// Release tension [N], > 0: the end releases when the force it exerts on its attachment
    /// reaches it; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub tension: Option<Spanned<f64>>,
    /// `true`: the release tension is the `minimum_breaking_load` of the line type of the
    /// section at that end (instead of `tension`); default false.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<bool>")]
    pub at_breaking_load: Option<Spanned<bool>>,
}

/// `[[failures]]`: the ends of two or more lines at one point release together at the first
/// step end where `time` is reached or their tension (the magnitude of the vector sum of
/// their forces on the point) reaches `tension`, whichever comes first, onto one new
/// massless free point at the point's place and velocity, which keeps them joined (MoorDyn's
/// FAILURE row listing several lines). Without either trigger they release only on a host's
/// call. A single line end's failure is `[lines.failure]` (docs/failure.md).
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct JoinedFailureSpec {
    /// The point the line ends release from.
    #[schemars(with = "String")]
    pub point: Spanned<String>,
    /// The lines whose ends at `point` release together (two or more, each with one end at
    /// `point`).
    #[schemars(with = "Vec<String>")]
    pub lines: Vec<Spanned<String>>,
    /// Release time [s], ≥ 0; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub time: Option<Spanned<f64>>,
    /// Release tension [N], > 0: the ends release when the magnitude of the vector sum of
    /// their forces on the point reaches it; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub tension: Option<Spanned<f64>>,
}

/// A line end (a winch's, a failure's).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
pub enum LineEndSpec {
    /// End A (`end_a`).
    A,
    /// End B (`end_b`).
    B,
}

/// `[lines.winch]`: the line's unstretched length follows a schedule of stages from t = 0,
/// its length at t = 0 being the line's `length`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WinchSpec {
    /// `"A"` or `"B"`: the end the winch is at; `LINE.winch_tension` is the tension there.
    #[schemars(with = "LineEndSpec")]
    pub end: Spanned<LineEndSpec>,
    /// Stages from t = 0, each `{ duration = s, payout_rate = m/s }` (> 0 pays out, < 0
    /// hauls in); the winch holds after the last.
    pub stages: Vec<WinchStageSpec>,
    /// Time over which the rate changes at the start of each stage and after the last, by a
    /// half-cosine [s]; default 0 (at once). No longer than any stage.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub ramp_time: Option<Spanned<f64>>,
    /// Shortest unstretched length the schedule may reach [m]; default 0 (the length must
    /// stay > 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub minimum_length: Option<Spanned<f64>>,
}

/// One stage of a winch schedule.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WinchStageSpec {
    /// Duration [s], > 0.
    #[schemars(with = "f64")]
    pub duration: Spanned<f64>,
    /// Payout rate of unstretched line [m/s]: > 0 pays out, < 0 hauls in, 0 holds.
    #[schemars(with = "f64")]
    pub payout_rate: Spanned<f64>,
}

/// How a body moves.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum BodyKindSpec {
    /// Six degrees of freedom, integrated with the lines.
    Free,
    /// Held at its `position` and `orientation`.
    Fixed,
    /// Moves as its `motion` table says (a vessel, a test rig): any rigid motion of
    /// `[points.motion]` that a vessel takes.
    Prescribed,
    /// Moved by a host program at each coupling step (a floating platform in OpenFAST or
    /// WEC-Sim); it starts at `position` and `orientation`, and the loads of the lines on it
    /// are read back. Run alone (the CLI), it stays at its starting pose.
    Coupled,
    /// Pinned at its origin: the origin moves as its `pin` says (fixed at `position`, on a
    /// prescribed `motion`, or set by a coupling host), the three rotations are free and
    /// integrated with the lines (MoorDyn's `CoupledPinned` bodies, `Pinned` rods). Needs
    /// `mass` and `inertia` like a free body.
    Pinned,
}

/// How the pin of a `pinned` body moves.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq, Default)]
#[serde(rename_all = "kebab-case")]
pub enum PinSpec {
    /// Held at the body's `position` (the default).
    #[default]
    Fixed,
    /// On the body's `motion` (any rigid motion a prescribed body takes): the pin follows the
    /// motion's origin; the motion's orientation is not used.
    Prescribed,
    /// Set by a host program at each coupling step (three translations), starting at
    /// `position`; the force the body puts on its pin is read back. Run alone (the CLI), the
    /// pin stays at `position`.
    Coupled,
    /// On a point of another body (`pin_body`, at `pin_point` in its body axes), which the
    /// body pushes on through the pin (MoorDyn's `Body#Pinned` rods); the body's `position`
    /// is that point at t = 0, so it is not given. The parent is free, fixed, prescribed,
    /// coupled or pinned (but not itself pinned to a body).
    Body,
}

/// `[[bodies.members]]`: a rigid cylinder on the body with side drag and added mass along it,
/// drag and added mass at its wet ends, the buoyancy of its wet part and seabed contact
/// (MoorDyn's rods); its mass is part of the body's.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MemberSpec {
    /// End A in body axes from the body origin [m].
    #[schemars(with = "[f64; 3]")]
    pub end_a: Spanned<[f64; 3]>,
    /// End B in body axes from the body origin [m].
    #[schemars(with = "[f64; 3]")]
    pub end_b: Spanned<[f64; 3]>,
    /// Diameter [m].
    #[schemars(with = "f64")]
    pub diameter: Spanned<f64>,
    /// Segments (lumped nodes at the ends and between them); default 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<i64>")]
    pub segments: Option<Spanned<i64>>,
    /// Normal drag coefficient on the diameter [-]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub normal_drag: Option<Spanned<f64>>,
    /// Normal added-mass coefficient [-]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub normal_added_mass: Option<Spanned<f64>>,
    /// Drag coefficient of each wet end on its area π d²/4 [-]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub end_drag: Option<Spanned<f64>>,
    /// Axial added-mass coefficient of each wet end on (2/3) π (d/2)³ [-]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub end_added_mass: Option<Spanned<f64>>,
}

/// Which speed scales a body's quadratic drag.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum DragSpeedSpec {
    /// Each axis by its own velocity component: F_i = −½ ρ (C A)_i |u_i| u_i.
    Component,
    /// Each axis by the magnitude of the relative velocity: F_i = −½ ρ (C A)_i |u| u_i (and
    /// |Ω| for the rotations), as MoorDyn's bodies.
    Magnitude,
}

/// An inertia tensor: principal moments or a full matrix.
#[derive(Clone, Debug, Deserialize, Serialize, JsonSchema, PartialEq)]
#[serde(untagged)]
pub enum InertiaSpec {
    /// [I_xx, I_yy, I_zz] about body axes through the centre of gravity.
    Principal([f64; 3]),
    /// The full symmetric tensor [[I_xx, I_xy, I_xz], [I_xy, I_yy, I_yz], [I_xz, I_yz, I_zz]]
    /// with I_xy = −∫ x y dm (the tensor, not the products of inertia).
    Matrix([[f64; 3]; 3]),
}

/// Shape of the volume a body displaces.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum DisplacementKind {
    /// Always fully submerged: buoyancy ρ g V at the centre of buoyancy.
    Submerged,
    /// A circular cylinder along body z, centred at the centre of buoyancy, submerged below
    /// the local free surface.
    Cylinder,
    /// A box along the body axes, centred at the centre of buoyancy, submerged below the local
    /// free surface.
    Box,
}

/// `[bodies.displacement]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DisplacementSpec {
    /// `"submerged"`, `"cylinder"` or `"box"`.
    #[serde(rename = "type")]
    #[schemars(with = "DisplacementKind")]
    pub kind: Spanned<DisplacementKind>,
    /// Displaced volume [m³] (`submerged`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub volume: Option<Spanned<f64>>,
    /// Radius [m] (`cylinder`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub radius: Option<Spanned<f64>>,
    /// Height along body z [m] (`cylinder`, `box`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub height: Option<Spanned<f64>>,
    /// Length along body x [m] (`box`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub length: Option<Spanned<f64>>,
    /// Breadth along body y [m] (`box`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub breadth: Option<Spanned<f64>>,
}

/// `[bodies.thrust]`: a constant force and moment, or a schedule.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ThrustSpec {
    /// Constant force in body axes [N], applied at the body origin; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub force: Option<Spanned<[f64; 3]>>,
    /// Constant moment in body axes [N·m]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub moment: Option<Spanned<[f64; 3]>>,
    /// Schedule rows `[t, Fx, Fy, Fz, Mx, My, Mz]` [s, N, N·m] in body axes, t strictly
    /// increasing; interpolated linearly, held outside (instead of `force`/`moment`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<Vec<[f64; 7]>>")]
    pub table: Option<Spanned<Vec<[f64; 7]>>>,
}

/// `[bodies.wind]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WindSpec {
    /// Wind velocity in global axes [m/s] (uniform, constant).
    #[schemars(with = "[f64; 3]")]
    pub velocity: Spanned<[f64; 3]>,
    /// Drag coefficient times area C_d·A of the superstructure [m²].
    #[schemars(with = "f64")]
    pub drag_area: Spanned<f64>,
    /// Centre of wind pressure in body axes [m]; default the body origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub centre: Option<Spanned<[f64; 3]>>,
}

/// `[[bodies]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Name, used for channels and results.
    #[schemars(with = "String")]
    pub name: Spanned<String>,
    /// `"free"`, `"fixed"`, `"prescribed"`, `"coupled"` or `"pinned"`.
    #[serde(rename = "type")]
    #[schemars(with = "BodyKindSpec")]
    pub kind: Spanned<BodyKindSpec>,
    /// The pin of a `pinned` body: `"fixed"` (default, at `position`), `"prescribed"` (on
    /// `motion`), `"coupled"` (set by a coupling host) or `"body"` (on a point of
    /// `pin_body`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<PinSpec>")]
    pub pin: Option<Spanned<PinSpec>>,
    /// The parent body of a body with `pin = "body"` (its name).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub pin_body: Option<Spanned<String>>,
    /// The pin's point on `pin_body`, in the parent's body axes from its origin [m]; default
    /// the parent's origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub pin_point: Option<Spanned<[f64; 3]>>,
    /// The motion of a `prescribed` body: `fixed`, `constant-velocity`, `manoeuvre`,
    /// `vessel-motion` or `rao`, with the keys of `[points.motion]`; it places the body
    /// origin (`start`, `heading` or the file), so `position` and `orientation` are not given.
    /// The motion of the pin of a `pinned` body with `pin = "prescribed"`: it places the pin
    /// (so `position` is not given); `orientation` gives the body's initial orientation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSpec>,
    /// Position of the body origin [m] (at t = 0 for free bodies; not for prescribed ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub position: Option<Spanned<[f64; 3]>>,
    /// Orientation [roll, pitch, yaw] [deg]: R = Rz(yaw)·Ry(pitch)·Rx(roll), body to global;
    /// default [0, 0, 0].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub orientation: Option<Spanned<[f64; 3]>>,
    /// Mass [kg]: required for a free or pinned body; a fixed, prescribed or coupled body may
    /// leave it out (its own loads are not computed; default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub mass: Option<Spanned<f64>>,
    /// Centre of gravity in body axes [m]; default the origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub centre_of_gravity: Option<Spanned<[f64; 3]>>,
    /// Inertia about the centre of gravity in body axes [kg·m²]: [Ixx, Iyy, Izz] or a full
    /// symmetric 3×3 tensor; required for a free or pinned body, default 0 for the others.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<InertiaSpec>")]
    pub inertia: Option<Spanned<InertiaSpec>>,
    /// Displaced volume; none by default (no buoyancy).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub displacement: Option<DisplacementSpec>,
    /// Centre of buoyancy in body axes [m]: the centre of a cylinder or box; default the
    /// origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub centre_of_buoyancy: Option<Spanned<[f64; 3]>>,
    /// Added mass per body axis [kg, kg, kg, kg·m², kg·m², kg·m²] (surge, sway, heave, roll,
    /// pitch, yaw) of the fully submerged shape; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 6]>")]
    pub added_mass: Option<Spanned<[f64; 6]>>,
    /// Linear drag per body axis [N·s/m ×3, N·m·s/rad ×3]; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 6]>")]
    pub linear_drag: Option<Spanned<[f64; 6]>>,
    /// Quadratic drag per body axis: C·A [m²] for surge, sway, heave and C·A·L³ [m⁵] for
    /// roll, pitch, yaw; default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 6]>")]
    pub quadratic_drag: Option<Spanned<[f64; 6]>>,
    /// Drag coefficients [-] along body x, y, z, with `drag_areas` (instead of
    /// `quadratic_drag`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub drag_coefficients: Option<Spanned<[f64; 3]>>,
    /// Reference areas [m²] of `drag_coefficients` along body x, y, z.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub drag_areas: Option<Spanned<[f64; 3]>>,
    /// Which speed scales the quadratic drag: `"component"` (default, each axis its own
    /// |u_i|) or `"magnitude"` (|u|, MoorDyn's bodies).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<DragSpeedSpec>")]
    pub drag_speed: Option<Spanned<DragSpeedSpec>>,
    /// Where added mass, fluid inertia and drag act, in body axes [m], for a `submerged`
    /// displacement or none; default the centre of buoyancy.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub hydrodynamic_centre: Option<Spanned<[f64; 3]>>,
    /// Cylindrical members with their own lumped hydrodynamics (MoorDyn's rods).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<MemberSpec>,
    /// Thrust or control force; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thrust: Option<ThrustSpec>,
    /// Wind on a vessel's superstructure; none by default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wind: Option<WindSpec>,
}

/// Shape of an obstacle.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum ObstacleShapeSpec {
    /// A sphere of `radius` about `position`.
    Sphere,
    /// A circular cylinder of `radius` along `axis` through `position`, finite or infinite.
    Cylinder,
}

/// `[[obstacles]]`.
#[derive(Debug, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ObstacleSpec {
    /// Name, used by channels (`NAME.force_x`, `NAME.contact_length`).
    #[schemars(with = "String")]
    pub name: Spanned<String>,
    /// `"sphere"` or `"cylinder"`.
    #[schemars(with = "ObstacleShapeSpec")]
    pub shape: Spanned<ObstacleShapeSpec>,
    /// Radius [m].
    #[schemars(with = "f64")]
    pub radius: Spanned<f64>,
    /// Direction of a cylinder's axis [-] (normalised; it keeps its direction).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub axis: Option<Spanned<[f64; 3]>>,
    /// Length of a cylinder along its axis, centred on `position` [m]; infinite if omitted.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub length: Option<Spanned<f64>>,
    /// Centre [m] (fixed; start of a `motion`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[f64; 3]>")]
    pub position: Option<Spanned<[f64; 3]>>,
    /// Prescribed motion of the centre, as a point's `motion`; fixed if omitted.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSpec>,
    /// Contact stiffness per unit length of cable [N/m²] (load per length per metre sunk in).
    #[schemars(with = "f64")]
    pub stiffness: Spanned<f64>,
    /// Damping ratio of the normal contact [-], default 1 (critical, with the cable's mass).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub damping_ratio: Option<Spanned<f64>>,
    /// Normal contact damping per unit length of cable [N·s/m²], instead of `damping_ratio`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub damping: Option<Spanned<f64>>,
    /// Coulomb friction coefficient [-], default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub friction_coefficient: Option<Spanned<f64>>,
    /// Sliding speed over which friction builds up [m/s], default 0.01.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<f64>")]
    pub friction_velocity: Option<Spanned<f64>>,
}
