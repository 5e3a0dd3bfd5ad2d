//! The implicit generalized-α method of Chung and Hulbert (J. Appl. Mech. 60:371, 1993) for
//! the second-order equations M(q) q̈ = F(q, q̇, t) of `fe` and `hermite` lines, free points
//! and free rigid bodies, with Newton iterations on the block-banded Jacobian
//! (docs/implicit.md).
//!
//! **Parameters.** From the spectral radius at infinite frequency ρ∞ ∈ [0, 1] (Chung and
//! Hulbert eqs. 25 and 17, 20):
//!
//!   α_m = (2ρ∞ − 1)/(ρ∞ + 1),  α_f = ρ∞/(ρ∞ + 1),  γ = ½ − α_m + α_f,
//!   β = ¼ (1 − α_m + α_f)²,
//!
//! the choice that makes the method second-order accurate, unconditionally stable for linear
//! problems, and of the least low-frequency dissipation for a given high-frequency one.
//!
//! **The step** (the form of Arnold and Brüls, Multibody Syst. Dyn. 18:185, 2007, eqs. 7–9,
//! which is Chung and Hulbert's with the equations of motion satisfied at the step's end). With
//! q̈ the true accelerations and a the algorithmic ("pseudo-") accelerations,
//!
//!   M(q_{n+1}) q̈_{n+1} = F(q_{n+1}, v_{n+1}, t_{n+1}),
//!   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) q̈_{n+1} + α_f q̈_n,
//!   q_{n+1} = q_n + h v_n + h² ((½ − β) a_n + β a_{n+1}),
//!   v_{n+1} = v_n + h ((1 − γ) a_n + γ a_{n+1}),
//!
//! started with a_0 = q̈_0 = M⁻¹F at t_0. Equilibrium at t_{n+1} means that every output of a
//! step (tensions, end forces, accelerations) is the right-hand side's own evaluation at the
//! state, as for the explicit schemes. The unknowns of the Newton iteration are q̈_{n+1}:
//! ∂q_{n+1}/∂q̈_{n+1} = β' = h² β (1 − α_f)/(1 − α_m) and ∂v_{n+1}/∂q̈_{n+1} = γ' =
//! h γ (1 − α_f)/(1 − α_m), so the iteration matrix is
//!
//!   S = M + γ' C + β' K  =  β' [M (1 − α_m)/(β h² (1 − α_f)) + C γ/(β h) + K],
//!
//! K = −∂F/∂q and C = −∂F/∂v ([`crate::linearise::dynamic_force_jacobian`] in the block
//! structure: an `fe` line's in closed form, [`crate::formulation::fe::jacobian`], where it
//! covers the forces, coloured finite differences otherwise; the body's own loads by
//! [`crate::model::Body::load_jacobian`]), M the mass blocks. S has the block structure of the
//! mass matrix, lines coupled through free points and bodies, so
//! [`crate::linalg::CoupledSystem`] solves it in O(nodes). The residual F − M q̈ is exact at
//! each iterate; the Jacobian is reused over iterations and steps (modified Newton) and
//! formed again when an iteration contracts by less than [`REFRESH_RATIO`] (docs/implicit.md
//! measures the choice). The iterations start from the linear extrapolation
//! q̈_n + (h/h_{n−1}) (q̈_n − q̈_{n−1}) and stop when the error the contraction rate predicts
//! is left is within [`NEWTON_FRACTION`] of the allowance, so most steps take one iteration.
//!
//! **Rigid bodies.** A free body's state is its origin's position and velocity, a unit
//! quaternion and the angular velocity ω in global axes ([`crate::bodies`]). Translation
//! follows the scheme above. Rotation is integrated on the rotation group (Brüls and Cardona,
//! J. Comput. Nonlinear Dyn. 5:031002, 2010): ω and the angular acceleration take the place of
//! v and q̈ in the formulas above, and the orientation is updated by the exponential map of the
//! rotation vector the position formula gives,
//!
//!   Θ = h ω_n + h² ((½ − β) a^ω_n + β a^ω_{n+1}),   q_{n+1} = exp(Θ) ⊗ q_n
//!
//! (Θ in global axes multiplies from the left, as q̇ = ½ (0, ω) ⊗ q). Θ approximates the
//! rotation ∫ω dt over the step to the same order as the position formula; the commutator
//! terms of a rotating ω are O(h³) per step, so the scheme is second order in the orientation
//! and angular velocity by this argument (not yet measured on a tumbling body; the ROV example
//! runs with it and resumes bit for bit). The quaternion keeps unit norm to round-off. In the Newton iteration the rotation
//! increment is the small rotation β' δα; the body's own loads are differentiated by rotations
//! about the global axes, and a line end on the body moves by δr = δx_o + δθ × ρ (the map of
//! [`crate::linalg::CoupledSystem`]); the rotation of ρ under the end forces (a geometric
//! stiffness) and of ω in ω × ρ are left out of the Jacobian, which changes the convergence
//! rate of the iteration, not what it converges to.
//!
//! **Error estimate** (after Zienkiewicz and Xie, Earthquake Eng. Struct. Dyn. 20:871, 1991).
//! With exact starting values the position update's local error is
//! (β + (α_m − α_f)/2 − 1/6) h³ q⃛ + O(h⁴) (a_n approximates q̈ at t_n + (α_m − α_f) h), and
//! h q⃛ ≈ q̈_{n+1} − q̈_n, so each vector's error is estimated as
//! e = (β + (α_m − α_f)/2 − 1/6) h² (q̈_{n+1} − q̈_n). The estimate that the step controls is the
//! tension error it makes in every element, EA_t |e_b − e_a| / l₀ (and EA_t |e_t| for a
//! `hermite` tangent), relative to the line's reference tension ([`reference_tension`]); a step
//! is accepted when the largest is within the tolerance. Before it is compared the estimate is
//! filtered through the iteration matrix, S⁻¹ M e ([`GeneralizedAlpha`]'s `error`): a stiff
//! degree of freedom follows its quasi-static equilibrium and its error is its inertia's share.
//! The next step is 0.9 h E^(−1/3) for the normalised error E (the local error is O(h³)),
//! between 0.2 and 2 times the last nominal step, and the nominal step is kept unless the
//! controller asks for less or for [`HYSTERESIS`] times more, so that one iteration matrix
//! serves several steps ([`GeneralizedAlpha::next_step`]).

use crate::linalg::{CoupledSystem, EndKind, LineBlocks};
use crate::linearise::{JacobianScratch, dynamic_force_jacobian};
use crate::math::{Mat3, Mat6, Quat, Real, Vec3, Vec6, get3};
use crate::system::{Location, System, Workspace};

/// The parameters of the generalized-α method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parameters {
    /// ρ∞, the spectral radius at infinite frequency [-].
    pub spectral_radius: Real,
    /// α_m [-].
    pub alpha_m: Real,
    /// α_f [-].
    pub alpha_f: Real,
    /// β [-].
    pub beta: Real,
    /// γ [-].
    pub gamma: Real,
}

impl Parameters {
    /// Chung and Hulbert's parameters for ρ∞ (their eqs. 25, 17 and 20).
    pub fn chung_hulbert(spectral_radius: Real) -> Self {
        let rho = spectral_radius;
        let alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
        let alpha_f = rho / (rho + 1.0);
        Self {
            spectral_radius: rho,
            alpha_m,
            alpha_f,
            gamma: 0.5 - alpha_m + alpha_f,
            beta: 0.25 * (1.0 - alpha_m + alpha_f).powi(2),
        }
    }

    /// The constant c of the local position error c h³ q⃛ [-]: β + (α_m − α_f)/2 − 1/6
    /// (module doc; 1/12 for ρ∞ = 1, the trapezoidal rule's).
    pub fn error_constant(&self) -> Real {
        self.beta + 0.5 * (self.alpha_m - self.alpha_f) - 1.0 / 6.0
    }

    /// (β', γ') for a step h [s]: the derivatives of q_{n+1} [s²] and v_{n+1} [s] with respect
    /// to q̈_{n+1}.
    pub fn derivatives(&self, h: Real) -> (Real, Real) {
        let ratio = (1.0 - self.alpha_f) / (1.0 - self.alpha_m);
        (h * h * self.beta * ratio, h * self.gamma * ratio)
    }
}

/// The Newton iterations stop when the position error left after a correction, η ‖β' δ‖
/// with η = θ/(1 − θ) from the contraction rate θ ([`ETA_FLOOR`]), or the correction itself,
/// is this fraction of the strain error the step's tolerance allows in each line,
/// tol · T_ref / EA_max (an error below the step's own, as Hairer and Wanner's κ ∈
/// [0.01, 0.1] for stiff integrators, Solving ODEs II §IV.8, eqs. 8.10–8.11): a line vector's
/// correction relative to its line's shortest element (a tangent's itself), a point's and a
/// body's relative to the system's shortest element, with the strictest line's allowance.
pub const NEWTON_FRACTION: Real = 0.1;

/// The smallest strain tolerance of the Newton iterations [-] (round-off of positions a
/// thousand element lengths from the origin).
const NEWTON_FLOOR: Real = 1e-12;

/// An iteration whose correction is more than this fraction of the last one's forms the
/// Jacobian again at the current iterate (once per step).
pub const REFRESH_RATIO: Real = 0.5;

/// The smallest η = θ/(1 − θ) the convergence test takes [-]: the error left after a
/// correction is taken as at least this fraction of it. A rate measured on one step (or
/// iteration) need not hold at the next, across the seabed contact of a touchdown node least:
/// on OC3 at tolerance 1e-3 (docs/implicit.md) a floor of 0.01 took 11153 steps and moved a
/// fairlead maximum by 1.5 %, 0.1, 0.15 and 0.2 kept the steps (7482, 7391, 7386 against 7390)
/// and the extremes (within 0.002 % of the iterations to a tenth of the allowance).
pub const ETA_FLOOR: Real = 0.15;

/// Steps that differ by less than this fraction share an iteration matrix [-]: only
/// round-off, as S affects how fast the iterations converge, not what to.
const STEP_MATCH: Real = 1e-9;

/// Newton iterations of one attempt.
pub const MAX_ITERATIONS: usize = 12;

/// Largest growth and shrinking of the adaptive step from one step to the next [-].
const GROWTH: (Real, Real) = (0.2, 2.0);

/// The step after Newton iterations that failed, relative to the failed one [-]: halved, as
/// RADAU5 does (Hairer and Wanner, Solving ODEs II §IV.8; radau5.f, label 78). The failures
/// are nonlinearity (a seabed contact switching on within the step), not an error estimate
/// to scale by the order; on OC3 at tolerance 1e-3 (docs/implicit.md) a retry at a fifth of
/// the step was mostly accepted at 0.01–0.13 of the tolerance, and the controller then took
/// several steps to grow back.
pub const NEWTON_RETRY: Real = 0.5;

/// The adaptive step grows only when the controller asks for this factor or more [-].
pub const HYSTERESIS: Real = 1.25;

/// What one attempt of a step gave.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Attempt {
    /// The step was taken; its normalised error estimate E [-] (≤ 1 for an adaptive step).
    Accepted {
        /// Error estimate over the tolerance.
        error: Real,
    },
    /// An adaptive step refused: its error estimate E over the tolerance (infinite when the
    /// Newton iterations did not converge). The state and history are unchanged.
    Rejected {
        /// Error estimate over the tolerance.
        error: Real,
    },
}

/// Why a fixed step could not be taken.
#[derive(Clone, Debug, PartialEq)]
pub struct StepFailure {
    /// Where the largest correction or the singular block is.
    pub location: Location,
    /// What happened.
    pub reason: String,
}

/// The iteration matrix's ingredients in the block structure, kept between steps.
#[derive(Clone, Debug, Default, PartialEq)]
struct Jacobian {
    /// Per line, its blocks in [`LineBlocks::blocks`] order: mass M [kg], ∂F/∂q [N/m],
    /// ∂F/∂v [N·s/m].
    line_mass: Vec<Vec<Mat3>>,
    line_position: Vec<Vec<Mat3>>,
    line_velocity: Vec<Vec<Mat3>>,
    /// Per free point: its own mass and load derivatives.
    point_mass: Vec<Mat3>,
    point_position: Vec<Mat3>,
    point_velocity: Vec<Mat3>,
    /// Per free body: its 6×6 mass and own-load derivatives.
    body_mass: Vec<Mat6>,
    body_position: Vec<Mat6>,
    body_velocity: Vec<Mat6>,
}

impl Jacobian {
    fn new(system: &System, ws: &Workspace) -> Self {
        let lines: Vec<Vec<Mat3>> = ws
            .blocks
            .iter()
            .map(|b| b.blocks().copied().collect())
            .collect();
        let np = system.free_points.len();
        let nb = system.free_bodies.len();
        Self {
            line_mass: lines.clone(),
            line_position: lines.clone(),
            line_velocity: lines,
            point_mass: vec![Mat3::zeros(); np],
            point_position: vec![Mat3::zeros(); np],
            point_velocity: vec![Mat3::zeros(); np],
            body_mass: vec![Mat6::zeros(); nb],
            body_position: vec![Mat6::zeros(); nb],
            body_velocity: vec![Mat6::zeros(); nb],
        }
    }

    /// Every number, in a fixed order (checkpoints).
    fn numbers(&self) -> impl Iterator<Item = Real> + '_ {
        let lines = self
            .line_mass
            .iter()
            .chain(&self.line_position)
            .chain(&self.line_velocity)
            .flatten()
            .chain(&self.point_mass)
            .chain(&self.point_position)
            .chain(&self.point_velocity)
            .flat_map(|m| m.iter().copied());
        let bodies = self
            .body_mass
            .iter()
            .chain(&self.body_position)
            .chain(&self.body_velocity)
            .flat_map(|m| m.iter().copied());
        lines.chain(bodies)
    }

    /// Sets every number from `numbers` (in [`Jacobian::numbers`] order); false when they are
    /// too few.
    fn set_numbers(&mut self, numbers: &mut impl Iterator<Item = Real>) -> bool {
        for m in self
            .line_mass
            .iter_mut()
            .chain(&mut self.line_position)
            .chain(&mut self.line_velocity)
            .flatten()
            .chain(&mut self.point_mass)
            .chain(&mut self.point_position)
            .chain(&mut self.point_velocity)
        {
            for x in m.iter_mut() {
                let Some(v) = numbers.next() else {
                    return false;
                };
                *x = v;
            }
        }
        for m in self
            .body_mass
            .iter_mut()
            .chain(&mut self.body_position)
            .chain(&mut self.body_velocity)
        {
            for x in m.iter_mut() {
                let Some(v) = numbers.next() else {
                    return false;
                };
                *x = v;
            }
        }
        true
    }

    fn len(&self) -> usize {
        self.numbers().count()
    }
}

/// Counts of what the scheme did, for benchmarks and the docs' measurements.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Statistics {
    /// Steps taken.
    pub steps: u64,
    /// Adaptive steps refused (error estimate or Newton iterations).
    pub rejected: u64,
    /// Newton iterations (each one evaluation of the forces and mass and one block solve).
    pub iterations: u64,
    /// Jacobians formed (each 2 (2w + 1)·3 + 2 line evaluations, w the block bandwidth).
    pub jacobians: u64,
}

/// The generalized-α integrator: its parameters, history and the iteration matrix, sized once.
#[derive(Clone, Debug)]
pub struct GeneralizedAlpha {
    params: Parameters,
    /// Tolerance of the adaptive step [-] ([`crate::model::Settings::tolerance`]).
    tolerance: Real,
    /// q̈_n, at the velocity entries of the state layout (their rates).
    acceleration: Vec<Real>,
    /// a_n, likewise.
    pseudo: Vec<Real>,
    /// q̈_{n−1}, likewise, and the step h_{n−1} [s] from t_{n−1} to t_n (0: no previous step,
    /// the predictor is then q̈_n): the predictor's extrapolation.
    previous: Vec<Real>,
    previous_step: Real,
    /// The Newton iterations' last contraction rate θ [-] (the ratio of successive corrections;
    /// NaN before the first measured): the convergence test's η = θ/(1 − θ).
    contraction: Real,
    /// Whether the history holds the run's values (false before the first step).
    started: bool,
    /// Each line's reference tension [N] for the error estimate ([`reference_tension`]).
    reference: Vec<Real>,
    /// The Jacobian's ingredients.
    jacobian: Jacobian,
    /// Whether `jacobian` holds a Jacobian (false before the first).
    formed: bool,
    /// The next attempt forms the Jacobian at its first iterate.
    refresh: bool,
    /// The iteration matrix S, per line, and the solver of its shared part.
    matrix: Vec<LineBlocks>,
    solver: CoupledSystem,
    /// The step S was formed for [s] (NaN: not formed).
    matrix_step: Real,
    /// The step S had been formed for when the history was saved [s] (NaN: none): a restored
    /// run forms S again at this step when its next step matches it within [`STEP_MATCH`],
    /// as the saved run would have kept those factors, so that it iterates bit for bit alike.
    restored_matrix_step: Real,
    /// Whether `solver` holds the factors of S (its next solve can reuse them).
    factored: bool,
    /// Whether `weights` are those of `reference` (false after a restore).
    weights_ready: bool,
    /// Scratch: the finite-difference Jacobians, the iterate q̈_{n+1}, the state at n+1, each
    /// line's node accelerations, the weights of the Newton norm, the first rate.
    fd_lines: [Vec<LineBlocks>; 2],
    fd_points: [Vec<Mat3>; 2],
    fd_scratch: JacobianScratch,
    trial: Vec<Real>,
    next: Vec<Real>,
    nodes: Vec<Vec<Vec3>>,
    weights: Vec<Real>,
    rate: Vec<Real>,
    /// Counts.
    pub statistics: Statistics,
}

impl GeneralizedAlpha {
    /// Integrator for `system` (state of length `n`) with ρ∞ = `spectral_radius` and the
    /// adaptive step's `tolerance`.
    pub fn new(system: &System, n: usize, spectral_radius: Real, tolerance: Real) -> Self {
        let ws = system.workspace();
        let fd_lines: Vec<LineBlocks> = ws
            .blocks
            .iter()
            .map(|b| {
                let mut b = b.clone();
                b.coupled = true;
                b
            })
            .collect();
        let mut solver = ws.coupled.clone();
        solver
            .body_slots
            .iter_mut()
            .for_each(|s| s.bias = Vec3::zeros());
        Self {
            params: Parameters::chung_hulbert(spectral_radius),
            tolerance,
            acceleration: vec![0.0; n],
            pseudo: vec![0.0; n],
            previous: vec![0.0; n],
            previous_step: 0.0,
            contraction: Real::NAN,
            started: false,
            reference: vec![0.0; system.lines.len()],
            jacobian: Jacobian::new(system, &ws),
            formed: false,
            refresh: true,
            matrix: fd_lines.clone(),
            solver,
            matrix_step: Real::NAN,
            restored_matrix_step: Real::NAN,
            factored: false,
            weights_ready: false,
            fd_lines: [fd_lines.clone(), fd_lines],
            fd_points: [(); 2].map(|_| vec![Mat3::zeros(); system.free_points.len()]),
            fd_scratch: JacobianScratch::new(system),
            trial: vec![0.0; n],
            next: vec![0.0; n],
            nodes: system
                .lines
                .iter()
                .map(|l| vec![Vec3::zeros(); l.block_vectors()])
                .collect(),
            weights: vec![0.0; n],
            rate: vec![0.0; n],
            statistics: Statistics::default(),
        }
    }

    /// The parameters.
    pub fn parameters(&self) -> &Parameters {
        &self.params
    }

    /// The accelerations q̈ [m/s², rad/s²] of the last accepted step, in the layout of the
    /// state (each at its velocity's place): they satisfy M q̈ = F at the step's end to the
    /// Newton tolerance ([`System::rhs_with_accelerations`] reads them).
    pub fn accelerations(&self) -> &[Real] {
        &self.acceleration
    }

    /// Force evaluations of a Newton iteration.
    pub fn evaluations(&self) -> usize {
        1
    }

    /// Everything the next step needs of the past, as numbers: the accelerations q̈_n, a_n and
    /// q̈_{n−1} (state layout), the reference tensions, the flags, the previous step and the
    /// last contraction rate (the predictor and the convergence test), the step the iteration
    /// matrix was formed for with its body points' offsets (a restored run forms the same
    /// matrix where the saved run would have kept its factors), and the Jacobian's
    /// ingredients (the modified Newton iteration reuses them, so a restored run iterates
    /// exactly as the saved one would have), and the counts of [`Statistics`] (exact as f64
    /// below 2⁵³), so that a resumed run reports what the whole run would have.
    pub fn history(&self, out: &mut Vec<Real>) {
        out.clear();
        out.extend_from_slice(&self.acceleration);
        out.extend_from_slice(&self.pseudo);
        out.extend_from_slice(&self.previous);
        out.extend_from_slice(&self.reference);
        out.push(if self.started { 1.0 } else { 0.0 });
        out.push(if self.formed { 1.0 } else { 0.0 });
        out.push(if self.refresh { 1.0 } else { 0.0 });
        out.push(self.previous_step);
        out.push(self.contraction);
        out.push(self.matrix_step);
        let c = self.statistics;
        out.extend([c.steps, c.rejected, c.iterations, c.jacobians].map(|n| n as Real));
        for slot in &self.solver.body_slots {
            out.extend_from_slice(slot.offset.as_slice());
        }
        out.extend(self.jacobian.numbers());
    }

    /// Sets the history ([`GeneralizedAlpha::history`]) of a saved run; false when the numbers
    /// do not fit this system.
    pub fn set_history(&mut self, history: &[Real]) -> bool {
        let n = self.acceleration.len();
        let lines = self.reference.len();
        let slots = 3 * self.solver.body_slots.len();
        // Three flags, the previous step, the contraction and the matrix step, then the four
        // counts of `Statistics`.
        const SCALARS: usize = 6 + 4;
        if history.len() != 3 * n + lines + SCALARS + slots + self.jacobian.len() {
            return false;
        }
        self.acceleration.copy_from_slice(&history[..n]);
        self.pseudo.copy_from_slice(&history[n..2 * n]);
        self.previous.copy_from_slice(&history[2 * n..3 * n]);
        self.reference
            .copy_from_slice(&history[3 * n..3 * n + lines]);
        let flags = &history[3 * n + lines..3 * n + lines + SCALARS];
        self.started = flags[0] != 0.0;
        self.formed = flags[1] != 0.0;
        self.refresh = flags[2] != 0.0;
        self.previous_step = flags[3];
        self.contraction = flags[4];
        self.matrix_step = Real::NAN;
        self.restored_matrix_step = flags[5];
        let count = |x: Real| x as u64;
        self.statistics = Statistics {
            steps: count(flags[6]),
            rejected: count(flags[7]),
            iterations: count(flags[8]),
            jacobians: count(flags[9]),
        };
        self.factored = false;
        self.weights_ready = false;
        // The body points' offsets the saved matrix was formed with (its ρ_f), which a matrix
        // formed again at `restored_matrix_step` takes instead of the iterate's.
        let offsets = &history[3 * n + lines + SCALARS..3 * n + lines + SCALARS + slots];
        for (slot, o) in self
            .solver
            .body_slots
            .iter_mut()
            .zip(offsets.chunks_exact(3))
        {
            slot.offset = Vec3::new(o[0], o[1], o[2]);
        }
        let mut rest = history[3 * n + lines + SCALARS + slots..].iter().copied();
        self.jacobian.set_numbers(&mut rest)
    }

    /// Makes the next step start as the first one does, from the state it is given: after a
    /// line failure, whose release moves a line end from its attachment onto a free point of
    /// its own ([`crate::session`]'s failures), the accelerations q̈_n and a_n, the Jacobian
    /// and the iteration matrix belong to the system before the release. The next step then
    /// takes the consistent accelerations q̈ = a = M⁻¹F of the new state and forms a fresh
    /// Jacobian there ([`GeneralizedAlpha::start`]); the iteration matrix follows the line
    /// ends' new kinds in `ws` (a free end's slot instead of a known end). The reference
    /// tensions of the error estimate are the run's, from its start: a scale of each line,
    /// not history. Allocates nothing.
    pub fn restart(&mut self, ws: &Workspace) {
        self.follow_ends(ws);
        self.started = false;
        self.refresh = true;
        self.previous_step = 0.0;
        self.contraction = Real::NAN;
        self.matrix_step = Real::NAN;
        self.restored_matrix_step = Real::NAN;
        self.factored = false;
    }

    /// Gives the iteration matrix's line blocks the end kinds of `ws`'s (which line ends are
    /// known and which sit on which free slot): after a release, and after a restore that took
    /// releases back or made them again. Allocates nothing.
    pub fn follow_ends(&mut self, ws: &Workspace) {
        let [fd_position, fd_velocity] = &mut self.fd_lines;
        for (((m, fp), fv), b) in self
            .matrix
            .iter_mut()
            .zip(fd_position)
            .zip(fd_velocity)
            .zip(&ws.blocks)
        {
            if (m.end_a, m.end_b) != (b.end_a, b.end_b) {
                (m.end_a, m.end_b) = (b.end_a, b.end_b);
                (fp.end_a, fp.end_b) = (b.end_a, b.end_b);
                (fv.end_a, fv.end_b) = (b.end_a, b.end_b);
                self.factored = false;
            }
        }
    }

    /// The first step's start: q̈_0 = a_0 = M⁻¹F at (t, y), the reference tensions (at the
    /// run's first start only: a restart after a release keeps them), and the Jacobian there.
    fn start(
        &mut self,
        system: &System,
        ws: &mut Workspace,
        t: Real,
        y: &[Real],
    ) -> Result<(), StepFailure> {
        system
            .rhs(t, y, &mut self.rate, ws)
            .map_err(|location| StepFailure {
                location,
                reason: "singular mass matrix".into(),
            })?;
        self.acceleration.copy_from_slice(&self.rate);
        self.pseudo.copy_from_slice(&self.rate);
        self.previous_step = 0.0;
        // Every reference tension is positive once set (its floor is 10⁻⁶ EA): all zero
        // means this is the run's first start.
        if self.reference.iter().all(|&r| r == 0.0) {
            for (li, r) in self.reference.iter_mut().enumerate() {
                *r = reference_tension(system, ws, li);
            }
            self.weights_ready = false;
        }
        // `rhs` formed only the ends' blocks of a lumped line; the Jacobian reads them all.
        ws.blocks
            .iter_mut()
            .for_each(crate::linalg::LineBlocks::form_lumped_diagonal);
        self.form_jacobian(system, ws, t, y);
        self.started = true;
        Ok(())
    }

    /// Forms the Jacobian's ingredients at (t, y), where `ws` holds an evaluation with every
    /// mass block formed ([`System::assemble`]'s; [`GeneralizedAlpha::start`] forms a lumped
    /// line's interior blocks after [`System::rhs`]).
    fn form_jacobian(&mut self, system: &System, ws: &mut Workspace, t: Real, y: &[Real]) {
        let j = &mut self.jacobian;
        for (li, b) in ws.blocks.iter().enumerate() {
            for (m, x) in j.line_mass[li].iter_mut().zip(b.blocks()) {
                *m = *x;
            }
        }
        j.point_mass.copy_from_slice(&ws.coupled.point_diag);
        j.body_mass.copy_from_slice(&ws.coupled.body_diag);
        let [fd_position, fd_velocity] = &mut self.fd_lines;
        let [fd_point_position, fd_point_velocity] = &mut self.fd_points;
        dynamic_force_jacobian(
            system,
            t,
            y,
            ws,
            [fd_position, fd_velocity],
            [fd_point_position, fd_point_velocity],
            &mut self.fd_scratch,
        );
        for (fd, lines) in [
            (&self.fd_lines[0], &mut j.line_position),
            (&self.fd_lines[1], &mut j.line_velocity),
        ] {
            for (li, b) in fd.iter().enumerate() {
                for (m, x) in lines[li].iter_mut().zip(b.blocks()) {
                    *m = *x;
                }
            }
        }
        j.point_position.copy_from_slice(&self.fd_points[0]);
        j.point_velocity.copy_from_slice(&self.fd_points[1]);
        for (f, &b) in system.free_bodies.iter().enumerate() {
            let (k, c) = system.bodies[b]
                .body
                .load_jacobian(&ws.bodies[b], &system.environment, t);
            // Stored as derivatives of the loads, like the lines'.
            j.body_position[f] = -k;
            j.body_velocity[f] = -c;
        }
        self.formed = true;
        self.refresh = false;
        self.matrix_step = Real::NAN;
        self.restored_matrix_step = Real::NAN;
        self.statistics.jacobians += 1;
    }

    /// S = M − γ' ∂F/∂v − β' ∂F/∂q for the step h, with the clamps of `hermite` lines, and
    /// the body points' offsets of the iterate in `ws` (S's rotation-to-point map); without
    /// `ws`, the offsets S already has (a restored run forming its saved matrix again).
    fn form_matrix(&mut self, system: &System, ws: Option<&Workspace>, h: Real) {
        if let Some(ws) = ws {
            for (s, slot) in self
                .solver
                .body_slots
                .iter_mut()
                .zip(&ws.coupled.body_slots)
            {
                s.body = slot.body;
                s.offset = slot.offset;
                s.bias = Vec3::zeros();
            }
        }
        let (bp, gp) = self.params.derivatives(h);
        let j = &self.jacobian;
        for (li, s) in self.matrix.iter_mut().enumerate() {
            for (((x, m), k), c) in s
                .blocks_mut()
                .zip(&j.line_mass[li])
                .zip(&j.line_position[li])
                .zip(&j.line_velocity[li])
            {
                *x = m - c * gp - k * bp;
            }
            system.lines[li].apply_clamps(s);
        }
        for (f, d) in self.solver.point_diag.iter_mut().enumerate() {
            *d = j.point_mass[f] - j.point_velocity[f] * gp - j.point_position[f] * bp;
        }
        for (f, d) in self.solver.body_diag.iter_mut().enumerate() {
            *d = j.body_mass[f] - j.body_velocity[f] * gp - j.body_position[f] * bp;
        }
        self.matrix_step = h;
        self.factored = false;
    }

    /// Solves S x = the right-hand sides in `self.matrix` and `self.solver`, factoring S once
    /// per formation.
    fn solve(&mut self, system: &System) -> Result<(), StepFailure> {
        let solved = if self.factored {
            self.solver.solve_again(&mut self.matrix)
        } else {
            self.solver.solve(&mut self.matrix)
        };
        solved.map_err(|s| StepFailure {
            location: system.singular_location(s),
            reason: "singular Newton iteration matrix".into(),
        })?;
        self.factored = true;
        Ok(())
    }

    /// The predictor of q̈_{n+1} for a step h [s], into `self.trial`: the linear extrapolation
    /// q̈_n + r (q̈_n − q̈_{n−1}) with r = h / h_{n−1} (at most [`GROWTH`]'s largest factor, so a
    /// short step before a long one does not amplify the difference's noise), or q̈_n without
    /// a previous step.
    fn predict(&mut self, h: Real) {
        if self.previous_step > 0.0 {
            let r = (h / self.previous_step).min(GROWTH.1);
            for ((t, q), p) in self
                .trial
                .iter_mut()
                .zip(&self.acceleration)
                .zip(&self.previous)
            {
                *t = q + r * (q - p);
            }
        } else {
            self.trial.copy_from_slice(&self.acceleration);
        }
    }

    /// The state at t + h from `y` (at t) and the iterate q̈_{n+1} in `self.trial`, into
    /// `self.next` (positions, velocities, body orientations).
    fn update(&mut self, system: &System, y: &[Real], h: Real) {
        let p = self.params;
        let c_new = (1.0 - p.alpha_f) / (1.0 - p.alpha_m);
        let c_old = p.alpha_f / (1.0 - p.alpha_m);
        let c_pseudo = p.alpha_m / (1.0 - p.alpha_m);
        let (acc, pseudo, trial, next) = (
            &self.acceleration,
            &self.pseudo,
            &self.trial,
            &mut self.next,
        );
        // a_{n+1} at velocity entry v.
        let a_next = |v: usize| c_new * trial[v] + c_old * acc[v] - c_pseudo * pseudo[v];
        let position = |x: Real, v: Real, a_old: Real, a_new: Real| {
            x + h * v + h * h * ((0.5 - p.beta) * a_old + p.beta * a_new)
        };
        let velocity =
            |v: Real, a_old: Real, a_new: Real| v + h * ((1.0 - p.gamma) * a_old + p.gamma * a_new);
        next.copy_from_slice(y);
        for (o, count) in system.layout.blocks() {
            for k in 0..3 * count {
                let (x, v) = (o + k, o + 3 * count + k);
                let a = a_next(v);
                next[x] = position(y[x], y[v], pseudo[v], a);
                next[v] = velocity(y[v], pseudo[v], a);
            }
        }
        for &b in &system.free_bodies {
            let o = system.layout.body_offset[b].expect("free body");
            let mut theta = Vec3::zeros();
            for k in 0..3 {
                // Translation: entries 0..3 with velocities 7..10.
                let (x, v) = (o + k, o + 7 + k);
                let a = a_next(v);
                next[x] = position(y[x], y[v], pseudo[v], a);
                next[v] = velocity(y[v], pseudo[v], a);
                // Rotation: ω at 10..13.
                let w = o + 10 + k;
                let a = a_next(w);
                theta[k] = position(0.0, y[w], pseudo[w], a);
                next[w] = velocity(y[w], pseudo[w], a);
            }
            let q = nalgebra::Quaternion::new(y[o + 3], y[o + 4], y[o + 5], y[o + 6]);
            let q = Quat::from_scaled_axis(theta) * Quat::new_normalize(q);
            next[o + 3] = q.w;
            next[o + 4] = q.i;
            next[o + 5] = q.j;
            next[o + 6] = q.k;
        }
    }

    /// The residual F − M q̈ of every equation at the iterate (`ws` holds the assembly at the
    /// state `self.next`), into the iteration matrix's right-hand sides: line rows (known ends:
    /// zero, their motion is given), free points' and free bodies' own rows.
    fn residual(&mut self, system: &System, ws: &Workspace) {
        let np = system.free_points.len();
        let trial = &self.trial;
        // The acceleration of slot s (a free point or a point on a free body).
        let slot_acceleration = |s: usize| -> Vec3 {
            if s < np {
                let o = system.layout.point_offset[system.free_points[s]].expect("free point");
                get3(&trial[o + 3..], 0)
            } else {
                let slot = ws.coupled.body_slots[s - np];
                let o =
                    system.layout.body_offset[system.free_bodies[slot.body]].expect("free body");
                let (a, alpha) = (get3(&trial[o + 7..], 0), get3(&trial[o + 10..], 0));
                a + alpha.cross(&slot.offset) + slot.bias
            }
        };
        for (li, l) in system.lines.iter().enumerate() {
            let b = &ws.blocks[li];
            let n = b.nodes() - 1;
            let o = system.layout.line_offset[li];
            let m = system.layout.line_interior[li];
            let nodes = &mut self.nodes[li];
            for (i, node) in nodes.iter_mut().enumerate() {
                *node = if i == 0 || i == n {
                    let (kind, p) = if i == 0 {
                        (b.end_a, l.end_a)
                    } else {
                        (b.end_b, l.end_b)
                    };
                    match kind {
                        EndKind::Known => ws.points[p].acceleration,
                        EndKind::Free(s) => slot_acceleration(s),
                    }
                } else {
                    get3(&trial[o + 3 * m..], i - 1)
                };
            }
            mass_rows(b, nodes, &mut self.matrix[li].x, true);
        }
        for (f, &p) in system.free_points.iter().enumerate() {
            let o = system.layout.point_offset[p].expect("free point");
            let a = get3(&trial[o + 3..], 0);
            self.solver.point_x[f] = ws.coupled.point_x[f] - ws.coupled.point_diag[f] * a;
        }
        for (f, &b) in system.free_bodies.iter().enumerate() {
            let o = system.layout.body_offset[b].expect("free body");
            let u = Vec6::from_fn(|r, _| trial[o + 7 + r]);
            self.solver.body_x[f] = ws.coupled.body_x[f] - ws.coupled.body_diag[f] * u;
            // A pinned body's translations: the correction that puts them on the pin.
            self.solver.body_pin[f] = ws.coupled.body_pin[f].map(|a| a - get3(&trial[o + 7..], 0));
            // A body pinned to a body: the correction that puts it on the parent's point,
            // c + J u_p − a_o at the iterate.
            self.solver.body_parent[f] = ws.coupled.body_parent[f].map(|pin| {
                let op =
                    system.layout.body_offset[system.free_bodies[pin.body]].expect("free body");
                let point =
                    get3(&trial[op + 7..], 0) + get3(&trial[op + 10..], 0).cross(&pin.offset);
                crate::linalg::ParentPin {
                    bias: pin.bias + point - get3(&trial[o + 7..], 0),
                    ..pin
                }
            });
        }
        // The solve moves a line end's row onto its body's rows with the offsets the
        // iteration matrix was formed with (ρ_f, `self.solver.body_slots`), which the body's
        // rotation since then has made stale: the end's moment ρ × r is the residual's, so
        // (ρ − ρ_f) × r goes to the body's moment rows here, and the iteration converges to
        // the equations at the iterate whatever the age of the matrix.
        for (li, b) in ws.blocks.iter().enumerate() {
            let n = b.nodes() - 1;
            for (kind, i) in [(b.end_a, 0), (b.end_b, n)] {
                let EndKind::Free(s) = kind else { continue };
                if s < np {
                    continue;
                }
                let (now, formed) = (
                    ws.coupled.body_slots[s - np],
                    self.solver.body_slots[s - np],
                );
                let moment = (now.offset - formed.offset).cross(&self.matrix[li].x[i]);
                for k in 0..3 {
                    self.solver.body_x[now.body][3 + k] += moment[k];
                }
            }
        }
    }

    /// Solves S δ = r, adds δ to the iterate, and returns the Newton norm of the position
    /// correction β' δ (≤ 1: converged) and the state index where it is largest.
    fn correct(&mut self, system: &System, bp: Real) -> Result<(Real, usize), StepFailure> {
        self.solve(system)?;
        let mut worst = (0.0, 0);
        let mut add = |trial: &mut [Real], v: usize, d: Real| {
            trial[v] += d;
            let size = (d * bp).abs() * self.weights[v];
            if !(size <= worst.0) {
                worst = (if size.is_nan() { Real::INFINITY } else { size }, v);
            }
        };
        for (li, s) in self.matrix.iter().enumerate() {
            let o = system.layout.line_offset[li];
            let m = system.layout.line_interior[li];
            for i in 1..=m {
                for k in 0..3 {
                    add(&mut self.trial, o + 3 * m + 3 * (i - 1) + k, s.x[i][k]);
                }
            }
        }
        for (f, &p) in system.free_points.iter().enumerate() {
            let o = system.layout.point_offset[p].expect("free point");
            for k in 0..3 {
                add(&mut self.trial, o + 3 + k, self.solver.point_x[f][k]);
            }
        }
        for (f, &b) in system.free_bodies.iter().enumerate() {
            let o = system.layout.body_offset[b].expect("free body");
            for k in 0..6 {
                add(&mut self.trial, o + 7 + k, self.solver.body_x[f][k]);
            }
        }
        Ok(worst)
    }

    /// The error estimate of the step h over the tolerance (module doc), from q̈_{n+1} in
    /// `self.trial` and q̈_n; `ws` holds the last iterate's assembly (mass blocks, body-point
    /// offsets). The raw estimate e = c h² (q̈_{n+1} − q̈_n) is filtered through the iteration
    /// matrix, e_f = S⁻¹ M e: a stiff degree of freedom (a node held by a stiff element to a
    /// prescribed end, a resting node pressed into the seabed) follows its quasi-static
    /// equilibrium, and its error is its inertia's share of the raw one, not the raw one
    /// (Shampine's filtered estimate for stiff problems, as in Hairer and Wanner, Solving ODEs
    /// II, §IV.8, eq. 8.20, with (I − hγJ) replaced by the second-order iteration matrix).
    fn error(&mut self, system: &System, ws: &Workspace, h: Real) -> Result<Real, StepFailure> {
        let c = self.params.error_constant().abs() * h * h;
        let np = system.free_points.len();
        let (trial, acceleration) = (&self.trial, &self.acceleration);
        let at = |v: usize| c * (get3(&trial[v..], 0) - get3(&acceleration[v..], 0));
        let slot_error = |s: usize| -> Vec3 {
            if s < np {
                let o = system.layout.point_offset[system.free_points[s]].expect("free point");
                at(o + 3)
            } else {
                let slot = ws.coupled.body_slots[s - np];
                let o =
                    system.layout.body_offset[system.free_bodies[slot.body]].expect("free body");
                at(o + 7) + at(o + 10).cross(&slot.offset)
            }
        };
        // Right-hand side M e, row by row as the residual.
        for li in 0..system.lines.len() {
            let b = &ws.blocks[li];
            let n = b.nodes() - 1;
            let o = system.layout.line_offset[li];
            let m = system.layout.line_interior[li];
            let nodes = &mut self.nodes[li];
            for (i, node) in nodes.iter_mut().enumerate() {
                *node = if i == 0 || i == n {
                    match if i == 0 { b.end_a } else { b.end_b } {
                        EndKind::Known => Vec3::zeros(),
                        EndKind::Free(s) => slot_error(s),
                    }
                } else {
                    at(o + 3 * m + 3 * (i - 1))
                };
            }
            mass_rows(b, nodes, &mut self.matrix[li].x, false);
        }
        for (f, &p) in system.free_points.iter().enumerate() {
            let o = system.layout.point_offset[p].expect("free point");
            self.solver.point_x[f] = ws.coupled.point_diag[f] * at(o + 3);
        }
        for (f, &b) in system.free_bodies.iter().enumerate() {
            let o = system.layout.body_offset[b].expect("free body");
            let u = Vec6::from_fn(|r, _| c * (trial[o + 7 + r] - acceleration[o + 7 + r]));
            self.solver.body_x[f] = ws.coupled.body_diag[f] * u;
            // A pinned body's translations follow its pin exactly.
            self.solver.body_pin[f] = ws.coupled.body_pin[f].map(|_| Vec3::zeros());
            self.solver.body_parent[f] =
                ws.coupled.body_parent[f].map(|pin| crate::linalg::ParentPin {
                    bias: Vec3::zeros(),
                    ..pin
                });
        }
        self.solve(system)?;
        let mut worst: Real = 0.0;
        for (li, l) in system.lines.iter().enumerate() {
            if l.dg().is_some() {
                continue;
            }
            let x = &self.matrix[li].x;
            let mesh = system.line_mesh(ws, li);
            let scale = 1.0 / self.reference[li];
            for e in 0..mesh.elements() {
                let sec = mesh.section(e);
                let ([a, b], tangents) = l.element_vectors(e);
                let mut strain = (x[b] - x[a]).norm() * sec.inverse_length;
                if let Some([ta, tb]) = tangents {
                    strain = strain.max(x[ta].norm()).max(x[tb].norm());
                }
                let v = sec.law.stiffness.max_tangent() * strain * scale;
                worst = worst.max(v);
            }
        }
        Ok(worst / self.tolerance)
    }

    /// The nominal step [s] after a step of h [s] accepted with normalised error `error` [-]
    /// (the run's nominal step was `nominal`; h is shorter when it landed on an output time):
    /// the controller's 0.9 h E^(−1/3) (the local error is O(h³)), taken when it is below
    /// `nominal` or at least [`HYSTERESIS`] times it, at most twice `nominal`; otherwise
    /// `nominal` is kept, so that the iteration matrix and its factors serve several steps.
    pub fn next_step(&self, nominal: Real, h: Real, error: Real) -> Real {
        let wanted = if error > 0.0 {
            0.9 * h * error.powf(-1.0 / 3.0)
        } else {
            Real::INFINITY
        };
        if wanted < nominal {
            wanted.max(GROWTH.0 * nominal)
        } else if wanted >= HYSTERESIS * nominal {
            wanted.min(GROWTH.1 * nominal)
        } else {
            nominal
        }
    }

    /// The step [s] to try again after a step of h [s] refused with normalised error `error`
    /// [-]: h · clamp(0.9 E^(−1/3), 0.2, 0.9) (0.2 h for a NaN estimate), or
    /// h · [`NEWTON_RETRY`] when the Newton iterations failed (`error` infinite).
    pub fn retry_step(&self, h: Real, error: Real) -> Real {
        if error == Real::INFINITY {
            return h * NEWTON_RETRY;
        }
        let factor = if error.is_finite() {
            0.9 * error.powf(-1.0 / 3.0)
        } else {
            0.0
        };
        h * factor.clamp(GROWTH.0, 0.9)
    }

    /// Attempts the step from (t, y) to t + h. With `adaptive`, a step whose error estimate
    /// exceeds the tolerance, or whose Newton iterations do not converge, is refused (the
    /// state and history unchanged) for the caller to retry with a shorter step; without, the
    /// step is taken whatever its error, and iterations that do not converge are a
    /// [`StepFailure`]. On acceptance `y` becomes the state at t + h.
    pub fn step(
        &mut self,
        system: &System,
        ws: &mut Workspace,
        t: Real,
        h: Real,
        y: &mut [Real],
        adaptive: bool,
    ) -> Result<Attempt, StepFailure> {
        if !self.started {
            self.start(system, ws, t, y)?;
        }
        if !self.weights_ready {
            newton_weights(system, &self.reference, self.tolerance, &mut self.weights);
            self.weights_ready = true;
        }
        let (bp, _) = self.params.derivatives(h);
        self.predict(h);
        // The convergence test's η at the first iteration: the last step's, raised to 0.8
        // (larger: it need not hold for this step; Hairer and Wanner §IV.8, RADAU5).
        let mut eta = if self.contraction < 1.0 {
            (self.contraction / (1.0 - self.contraction))
                .max(ETA_FLOOR)
                .powf(0.8)
        } else {
            1.0
        };
        let mut last = Real::INFINITY;
        let mut fresh = false;
        let mut converged = false;
        let mut worst = 0;
        for iteration in 0..MAX_ITERATIONS {
            self.update(system, y, h);
            system.assemble(t + h, &self.next, ws);
            self.statistics.iterations += 1;
            if self.refresh || !self.formed {
                let next = std::mem::take(&mut self.next);
                self.form_jacobian(system, ws, t + h, &next);
                self.next = next;
                fresh = true;
                // The finite differences perturbed only the lines' scratch: the assembled
                // forces and mass blocks the residual reads are intact.
            }
            // A step equal to the matrix's but for round-off (steps landing on output times
            // k Δt_out differ in their last bits) keeps the factors.
            if !((h - self.matrix_step).abs() <= STEP_MATCH * h) {
                // After a restore, the saved run's matrix step if this step would have kept it.
                if (h - self.restored_matrix_step).abs() <= STEP_MATCH * h {
                    self.form_matrix(system, None, self.restored_matrix_step);
                } else {
                    self.form_matrix(system, Some(ws), h);
                }
            }
            self.restored_matrix_step = Real::NAN;
            self.residual(system, ws);
            let (norm, at) = self.correct(system, bp)?;
            worst = at;
            // Contraction of this iteration (NaN at the first, or after a restart).
            let ratio = if last.is_finite() {
                norm / last
            } else {
                Real::NAN
            };
            if ratio < 1.0 {
                self.contraction = ratio;
                eta = (ratio / (1.0 - ratio)).max(ETA_FLOOR);
            }
            // Converged when the correction, or the error left after it, η ‖δ‖ (the
            // geometric series of the remaining corrections), is within the allowance.
            if norm <= 1.0 || (!(ratio >= 1.0) && eta * norm <= 1.0) {
                converged = true;
                break;
            }
            if last.is_finite() {
                // Iterations still needed at this contraction (Hairer and Wanner §IV.8).
                let needed = if ratio < 1.0 {
                    (-norm.ln() / ratio.ln()).max(0.0)
                } else {
                    Real::INFINITY
                };
                let hopeless = iteration as Real + 1.0 + needed > MAX_ITERATIONS as Real;
                if ratio >= 1.0 && !fresh {
                    // Diverging on an old Jacobian: start again from the predictor with one
                    // formed there (the iterate itself may be far off).
                    self.predict(h);
                    eta = 1.0;
                    self.refresh = true;
                    last = Real::INFINITY;
                    continue;
                } else if ratio >= 1.0 || (hopeless && fresh) {
                    // Diverging, or too slow, with a Jacobian of this step: give up.
                    break;
                } else if (ratio > REFRESH_RATIO || hopeless) && !fresh {
                    self.refresh = true;
                }
            }
            last = norm;
        }
        if !converged {
            // A Jacobian formed in this attempt (at an iterate of this step, from the same
            // state) serves the shorter retry, whose iterates lie closer; the retry forms one
            // of its own when its iterations diverge on it or contract too slowly (as RADAU5
            // after a Newton failure: Hairer and Wanner's radau5.f, label 78).
            self.refresh = !fresh;
            if adaptive {
                self.statistics.rejected += 1;
                return Ok(Attempt::Rejected {
                    error: Real::INFINITY,
                });
            }
            return Err(StepFailure {
                location: system.locate(worst),
                reason: format!(
                    "the Newton iterations of the generalized-α step did not converge in {} \
                     iterations (step {h:.3e} s)",
                    MAX_ITERATIONS
                ),
            });
        }
        self.update(system, y, h);
        let error = self.error(system, ws, h)?;
        if adaptive && !(error <= 1.0) {
            self.statistics.rejected += 1;
            return Ok(Attempt::Rejected { error });
        }
        // Commit: a_{n+1}, q̈_{n+1}, the state.
        let p = self.params;
        let c_new = (1.0 - p.alpha_f) / (1.0 - p.alpha_m);
        let c_old = p.alpha_f / (1.0 - p.alpha_m);
        let c_pseudo = p.alpha_m / (1.0 - p.alpha_m);
        for (((a, q), t), r) in self
            .pseudo
            .iter_mut()
            .zip(self.acceleration.iter_mut())
            .zip(&self.trial)
            .zip(self.previous.iter_mut())
        {
            *a = c_new * t + c_old * *q - c_pseudo * *a;
            *r = *q;
            *q = *t;
        }
        self.previous_step = h;
        y.copy_from_slice(&self.next);
        self.statistics.steps += 1;
        Ok(Attempt::Accepted { error })
    }
}

/// The reference tension of line `li` [N] for the error estimate, from the evaluation in `ws`
/// at the start of the run: the largest of its largest element tension, its weight in water
/// and in air over its length, and 10⁻⁶ of its axial stiffness (a floor for a slack,
/// weightless line).
pub fn reference_tension(system: &System, ws: &Workspace, li: usize) -> Real {
    let l = &system.lines[li];
    let env = &system.environment;
    let mesh = &l.mesh;
    let (mut wet, mut dry, mut stiffness) = (0.0, 0.0, Real::INFINITY);
    for e in 0..mesh.elements() {
        let s = mesh.section(e);
        let lt = &s.line_type;
        wet += (lt.mass_per_length - env.water_density * s.area) * env.gravity * s.element_length;
        dry += lt.mass_per_length * env.gravity * s.element_length;
        stiffness = stiffness.min(s.law.stiffness.max_tangent());
    }
    let tension = ws.lines[li]
        .elements
        .tension
        .iter()
        .fold(0.0, |m: Real, t| m.max(t.abs()));
    tension.max(wet.abs()).max(dry).max(1e-6 * stiffness)
}

/// Row i of the mass blocks `b` times the node vectors `nodes` into `out[i]` (with `residual`,
/// the force row minus it: F − M q̈), zero at the rows of known (prescribed or fixed) ends.
/// A block-tridiagonal line (an `fe` line's) sums each row in the order of
/// [`LineBlocks::row_times`] (i − 1, i, i + 1, from zero), so the same numbers to the bit, in
/// one pass over its interior rows without the band lookup or a test per row.
fn mass_rows(b: &LineBlocks, nodes: &[Vec3], out: &mut [Vec3], residual: bool) {
    let n = b.nodes() - 1;
    let finish = |f: &Vec3, row: Vec3| if residual { f - row } else { row };
    if b.width() > 1 {
        for (i, x) in out.iter_mut().enumerate().take(n + 1) {
            *x = finish(&b.x[i], b.row_times(i, nodes));
        }
    } else {
        let (x, f) = (&nodes[..=n], &b.x[..=n]);
        let (diag, lower, upper) = (&b.diag[..=n], &b.lower[..n], &b.upper[..n]);
        let out = &mut out[..=n];
        let mut first = Vec3::zeros();
        first += diag[0] * x[0];
        first += upper[0] * x[1];
        out[0] = finish(&f[0], first);
        let interior = out[1..n]
            .iter_mut()
            .zip(x.windows(3))
            .zip(lower.iter().zip(&diag[1..n]).zip(&upper[1..]))
            .zip(&f[1..n]);
        for (((o, x), ((l, d), u)), f) in interior {
            let mut row = Vec3::zeros();
            row += l * x[0];
            row += d * x[1];
            row += u * x[2];
            *o = finish(f, row);
        }
        let mut last = Vec3::zeros();
        last += lower[n - 1] * x[n - 1];
        last += diag[n] * x[n];
        out[n] = finish(&f[n], last);
    }
    if b.end_a == EndKind::Known {
        out[0] = Vec3::zeros();
    }
    if b.end_b == EndKind::Known {
        out[n] = Vec3::zeros();
    }
}

/// Weights of the Newton norm per state entry ([`NEWTON_FRACTION`]): at each velocity
/// entry, 1/(strain tolerance · length) for the length that makes its correction a strain,
/// with each line's strain tolerance from its reference tension; zero at the position
/// entries. Into `w` (the state's length); allocates nothing.
fn newton_weights(system: &System, reference: &[Real], tolerance: Real, w: &mut [Real]) {
    w.iter_mut().for_each(|x| *x = 0.0);
    let allowance = |li: usize| {
        let l = &system.lines[li];
        let stiffness = (0..l.mesh.elements())
            .map(|e| l.mesh.section(e).law.stiffness.max_tangent())
            .fold(0.0, Real::max);
        (NEWTON_FRACTION * tolerance * reference[li] / stiffness).max(NEWTON_FLOOR)
    };
    let strictest = (0..system.lines.len())
        .map(allowance)
        .fold(Real::INFINITY, Real::min);
    let strictest = if strictest.is_finite() {
        strictest
    } else {
        1e-8
    };
    let shortest = system
        .lines
        .iter()
        .map(|l| l.mesh.shortest_element())
        .fold(Real::INFINITY, Real::min);
    let shortest = if shortest.is_finite() { shortest } else { 1.0 };
    for (li, l) in system.lines.iter().enumerate() {
        let o = system.layout.line_offset[li];
        let m = system.layout.line_interior[li];
        let element = l.mesh.shortest_element();
        let strain = allowance(li);
        for i in 1..=m {
            let length = if l.is_tangent(i) { 1.0 } else { element };
            for k in 0..3 {
                w[o + 3 * m + 3 * (i - 1) + k] = 1.0 / (strain * length);
            }
        }
    }
    for &p in &system.free_points {
        let o = system.layout.point_offset[p].expect("free point");
        for k in 0..3 {
            w[o + 3 + k] = 1.0 / (strictest * shortest);
        }
    }
    for &b in &system.free_bodies {
        let o = system.layout.body_offset[b].expect("free body");
        // A rotation moves the body's farthest attachment by its offset.
        let reach = system
            .points
            .iter()
            .filter_map(|p| match &p.kind {
                crate::model::PointKind::Body { body, offset } if *body == b => Some(offset.norm()),
                _ => None,
            })
            .fold(0.0, Real::max)
            .max(shortest);
        for k in 0..3 {
            w[o + 7 + k] = 1.0 / (strictest * shortest);
            w[o + 10 + k] = reach / (strictest * shortest);
        }
    }
}
