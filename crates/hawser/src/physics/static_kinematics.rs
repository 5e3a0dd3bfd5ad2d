//! Wave kinematics at the static position: each quadrature point of a line takes the wave
//! velocity, acceleration and surface elevation of the point where it was at the start of the
//! run, interpolated in time (OrcaFlex's "kinematics at the static position"; docs/waves.md,
//! "Kinematics at the static position").
//!
//! Direct summation ([`crate::physics::environment::Environment::fluid_kinematics`]) costs
//! one sine–cosine pair and one exponential per component, per quadrature point and per
//! right-hand-side evaluation: 7.3 evaluations per `fe` node-step with RK4. Here:
//!
//! - at a point's static position (x₀, y₀, z₀), the fields u(t), ∂u/∂t(t) and η(t) are
//!   sampled at t_m = m h (h the sample interval) by the same linear theory, stretching and
//!   ramp as direct summation ([`WaveField::kinematics_from_phases`]): the time part
//!   (sin, cos)(φ_j − ω_j t_m) of every component is computed once per sample for all points,
//!   the space part (sin, cos)(k_j·x₀) once per run for each point, and θ_j by angle addition,
//!   so a sample costs one exponential per component and point and no sine or cosine;
//! - between samples, each field is the cubic Lagrange interpolant of samples m − 1 … m + 2
//!   (t_m ≤ t < t_{m+1}); its four weights are computed once per evaluation time, so a point
//!   costs 28 multiply-adds. For a component of frequency ω the interpolation error is at most
//!   (3/128) (ω h)⁴ of its amplitude (the Lagrange remainder at mid-interval);
//! - samples live in a ring of [`RING`] per point, filled as time advances: memory does not
//!   grow with the record, and a sample's value depends only on its index m (never on the
//!   order in which samples were filled), so a run is bit-identical however it is stepped or
//!   restarted.
//!
//! A point is in the water when its current height z is at or below the interpolated η(t) at
//! its static (x₀, y₀); the tabulated fields are those at min(z₀, η(t)), the surface values
//! once the surface drops below the static point. What is left out is the change of the wave
//! field over the point's displacement δ from its static position: a relative error of about
//! k |δ| for a component of wavenumber k (docs/waves.md gives its measured effect).

use crate::math::{Real, Vec3};
use crate::physics::environment::Environment;
use crate::physics::waves::WaveField;
use std::cell::Cell;

/// Default number of samples per period of the highest-frequency component [-]: with the
/// cubic interpolation the error bound (3/128)(2π/25)⁴ = 9.4e-5 of that component's amplitude
/// (less for every longer component, as the fourth power of its frequency).
pub const DEFAULT_SAMPLES_PER_PERIOD: Real = 25.0;

/// Samples kept per point: the four the interpolation needs and four ahead, so that the
/// stages of a step up to 4 intervals long are served without refilling behind.
pub const RING: usize = 8;

/// Fields per sample: velocity (3) [m/s], acceleration (3) [m/s²], elevation η [m].
const CHANNELS: usize = 7;

/// How line quadrature points take their wave kinematics (scenario key
/// `environment.waves.kinematics`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum WaveKinematicsMethod {
    /// Summed over every component at the point's current position, at every evaluation: the
    /// reference.
    #[default]
    Direct,
    /// Summed at the point's static position (its position at the start of the run) every
    /// `sample_interval` [s] and interpolated in time ([`StaticPositionKinematics`]).
    StaticPosition {
        /// Sample interval h [s], > 0.
        sample_interval: Real,
    },
}

impl WaveKinematicsMethod {
    /// The default sample interval for `field` [s]: [`DEFAULT_SAMPLES_PER_PERIOD`] samples
    /// per period of its highest-frequency component.
    pub fn default_sample_interval(field: &WaveField) -> Real {
        let w = field.highest_frequency();
        if w > 0.0 {
            2.0 * std::f64::consts::PI / w / DEFAULT_SAMPLES_PER_PERIOD
        } else {
            1.0
        }
    }
}

/// The per-run cache of the static-position kinematics: every line quadrature point's static
/// position, its space phases, and a ring of time samples. Built once at the start of a run
/// ([`crate::system::System::start_wave_tables`]), advanced by [`Self::prepare`] at each
/// evaluation time, read by [`Self::at`]. No allocation after construction.
#[derive(Clone, Debug)]
pub struct StaticPositionKinematics {
    field: WaveField,
    interval: Real,
    components: usize,
    /// Static position of every point [m].
    positions: Vec<Vec3>,
    /// First point of each line.
    line_first: Vec<usize>,
    /// (sin, cos) of k_j·x₀ per point and component (points × components).
    spatial: Vec<(Real, Real)>,
    /// (sin, cos) of φ_j − ω_j t_m of the sample being computed (scratch).
    temporal: Vec<(Real, Real)>,
    /// θ_j of the point being sampled (scratch).
    phases: Vec<(Real, Real)>,
    /// Samples, [`RING`] per point; sample m at slot m mod RING.
    samples: Vec<[Real; CHANNELS]>,
    /// Indices of the first and last valid sample (`hi < lo`: none).
    lo: i64,
    hi: i64,
    /// The prepared evaluation: time [s], base sample m and the four weights of samples
    /// m − 1 … m + 2.
    time: Real,
    base: i64,
    weights: [Real; 4],
}

impl StaticPositionKinematics {
    /// The cache for the points `lines[l][i]` (static positions [m], by line and quadrature
    /// point) of `field`, sampled every `interval` [s] (> 0).
    pub fn new(field: &WaveField, interval: Real, lines: &[Vec<Vec3>]) -> Self {
        assert!(interval > 0.0, "the sample interval must be > 0 s");
        let components = field.components().len();
        let mut positions = Vec::new();
        let mut line_first = Vec::with_capacity(lines.len());
        for l in lines {
            line_first.push(positions.len());
            positions.extend_from_slice(l);
        }
        let mut spatial = vec![(0.0, 1.0); positions.len() * components];
        for (p, x) in positions.iter().enumerate() {
            field.spatial_phases(x.x, x.y, &mut spatial[p * components..(p + 1) * components]);
        }
        Self {
            field: field.clone(),
            interval,
            components,
            samples: vec![[0.0; CHANNELS]; positions.len() * RING],
            positions,
            line_first,
            spatial,
            temporal: vec![(0.0, 1.0); components],
            phases: vec![(0.0, 1.0); components],
            lo: 0,
            hi: -1,
            time: Real::NAN,
            base: 0,
            weights: [0.0; 4],
        }
    }

    /// Sample interval h [s].
    pub fn interval(&self) -> Real {
        self.interval
    }

    /// Number of points.
    pub fn points(&self) -> usize {
        self.positions.len()
    }

    /// Static position of point `p` [m].
    pub fn position(&self, p: usize) -> Vec3 {
        self.positions[p]
    }

    /// Index of the first point of line `l`.
    pub fn line_first(&self, l: usize) -> usize {
        self.line_first[l]
    }

    /// Memory of the cache [bytes]: per point 16 per component (its space phases) plus
    /// 8·7·[`RING`] = 448 (its samples) and 24 (its position), plus 32 per component of
    /// scratch and the copy of the components.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        self.spatial.len() * size_of::<(Real, Real)>()
            + self.samples.len() * size_of::<[Real; CHANNELS]>()
            + self.positions.len() * size_of::<Vec3>()
            + (self.temporal.len() + self.phases.len()) * size_of::<(Real, Real)>()
            + self.components * 15 * size_of::<Real>()
    }

    /// Makes the fields at time t [s] readable by [`Self::at`]: fills the samples
    /// m − 1 … m + 2 around t (m = ⌊t/h⌋) that the ring does not hold yet, and the
    /// interpolation weights. Nothing to do when t is the prepared time.
    pub fn prepare(&mut self, t: Real) {
        if t == self.time {
            return;
        }
        let s = t / self.interval;
        let m = s.floor();
        let base = m as i64;
        let (need_lo, need_hi) = (base - 1, base + 2);
        if need_lo < self.lo || need_lo > self.hi + 1 {
            // Behind the window or past a gap: start afresh.
            self.lo = need_lo;
            self.hi = need_lo - 1;
        }
        while self.hi < need_hi {
            let next = self.hi + 1;
            self.fill(next);
            self.hi = next;
            self.lo = self.lo.max(self.hi - RING as i64 + 1);
        }
        // Cubic Lagrange weights on the nodes −1, 0, 1, 2 at x = s − m ∈ [0, 1).
        let x = s - m;
        let (xp, xm, xm2) = (x + 1.0, x - 1.0, x - 2.0);
        self.weights = [
            -x * xm * xm2 / 6.0,
            xp * xm * xm2 / 2.0,
            -xp * x * xm2 / 2.0,
            xp * x * xm / 6.0,
        ];
        self.base = base;
        self.time = t;
    }

    /// Computes sample m of every point into its ring slot.
    fn fill(&mut self, m: i64) {
        let t = m as Real * self.interval;
        let ramp = self.field.ramp(t);
        self.field.temporal_phases(t, &mut self.temporal);
        let slot = m.rem_euclid(RING as i64) as usize;
        let n = self.components;
        for (p, x) in self.positions.iter().enumerate() {
            let (eta, k) = self.field.kinematics_from_phases(
                x.z,
                ramp,
                &self.spatial[p * n..(p + 1) * n],
                &self.temporal,
                &mut self.phases,
            );
            let (u, a) = (k.velocity, k.acceleration);
            self.samples[p * RING + slot] = [u.x, u.y, u.z, a.x, a.y, a.z, eta];
        }
    }

    /// Wave kinematics of point `p` at the prepared time, for the point now at height `z`
    /// [m]: whether it is in the water (z ≤ η at its static x, y), the wave velocity [m/s] and
    /// local acceleration [m/s²] (zero out of the water).
    #[inline]
    pub fn at(&self, p: usize, z: Real) -> (bool, Vec3, Vec3) {
        let mut f = [0.0; CHANNELS];
        for (k, w) in self.weights.iter().enumerate() {
            let slot = (self.base - 1 + k as i64).rem_euclid(RING as i64) as usize;
            let s = &self.samples[p * RING + slot];
            for c in 0..CHANNELS {
                f[c] += w * s[c];
            }
        }
        if z > f[6] {
            return (false, Vec3::zeros(), Vec3::zeros());
        }
        (
            true,
            Vec3::new(f[0], f[1], f[2]),
            Vec3::new(f[3], f[4], f[5]),
        )
    }

    /// The prepared time [s] (NaN before the first [`Self::prepare`]).
    pub fn time(&self) -> Real {
        self.time
    }
}

/// Where the quadrature points of one line take their fluid kinematics: the argument by which
/// a formulation tells [`crate::formulation::fluid_load`] which of its points it evaluates.
/// A line numbers its points from 0 in its own order (`fe`: 2 per element, `hermite`: 4, `dg`:
/// its Gauss points), and only has to keep that order from one evaluation to the next.
#[derive(Clone, Copy, Debug, Default)]
pub enum FluidPoints<'a> {
    /// Direct summation at the point's current position.
    #[default]
    Direct,
    /// From the static-position cache, the line's points starting at `first`.
    Static {
        /// The cache, prepared at the evaluation time.
        table: &'a StaticPositionKinematics,
        /// Index of the line's point 0 in the cache.
        first: usize,
    },
    /// Direct summation, recording each point's position (how the static positions are
    /// found: one evaluation of the initial state).
    Record {
        /// One slot per point of the line.
        positions: &'a [Cell<Vec3>],
    },
}

impl<'a> FluidPoints<'a> {
    /// The line `line`'s points in `table`, or direct summation without one.
    pub fn of_line(table: Option<&'a StaticPositionKinematics>, line: usize) -> Self {
        match table {
            Some(table) => FluidPoints::Static {
                table,
                first: table.line_first(line),
            },
            None => FluidPoints::Direct,
        }
    }

    /// Fluid velocity [m/s] and local acceleration [m/s²] at the line's point `point`, now at
    /// `position` [m], at time t [s] (the table's prepared time): the current (at the
    /// current position) plus the waves.
    #[inline]
    pub fn kinematics(
        &self,
        env: &Environment,
        point: usize,
        position: &Vec3,
        t: Real,
    ) -> (Vec3, Vec3) {
        match self {
            FluidPoints::Direct => env.fluid_kinematics(position, t),
            FluidPoints::Static { table, first } => {
                debug_assert!(table.time() == t, "static kinematics not prepared at t");
                env.fluid_kinematics_with_waves(table.at(first + point, position.z), position, t)
            }
            FluidPoints::Record { positions } => {
                if let Some(c) = positions.get(point) {
                    c.set(*position);
                }
                env.fluid_kinematics(position, t)
            }
        }
    }
}
