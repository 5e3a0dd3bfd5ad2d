//! Time integration: explicit Runge–Kutta schemes as Butcher tableaux, the elastic-link
//! paper's three-time-level predictor–corrector with variable steps, the implicit
//! generalized-α method, and the automatic choice between RK4 and generalized-α.

pub mod choice;
pub mod explicit_rk;
pub mod generalized_alpha;
pub mod three_level;

pub use choice::{SchemeChoice, choose_scheme};
pub use explicit_rk::{ExplicitRk, RK4, SSP_RK3, Tableau};
pub use generalized_alpha::GeneralizedAlpha;
pub use three_level::ThreeLevel;

use crate::math::Real;
use crate::model::Scheme;

/// What the time integration of a run did, as its results record it (`summary.json`'s
/// `integrator`; the Python package's results and session).
#[derive(Clone, Debug, PartialEq)]
pub struct IntegratorReport {
    /// The scheme the run started with (`scheme = "auto"` resolved) and why.
    pub choice: SchemeChoice,
    /// Steps taken by every scheme [-].
    pub steps: u64,
    /// The step now [s]: the fixed or automatic step, or adaptive generalized-α's nominal step
    /// (the one it would take next).
    pub time_step: Real,
    /// What generalized-α did (`None` if it never stepped).
    pub generalized_alpha: Option<generalized_alpha::Statistics>,
    /// `scheme = "auto"` handing stretches to RK4 while the run goes (`None` unless `auto`
    /// started the run with adaptive generalized-α).
    pub switching: Option<SwitchingReport>,
}

/// `scheme = "auto"`'s switching over a run ([`choice::SchemeSwitch`] in results' terms).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SwitchingReport {
    /// Switches between generalized-α and RK4, either way [-].
    pub switches: u64,
    /// Simulated time stepped by RK4 [s].
    pub rk4_time: Real,
    /// Whether RK4 steps now (at the end of the run).
    pub rk4_now: bool,
}

impl Scheme {
    /// The smallest radius R of the scheme's stability region over the left half-plane, for
    /// the stable step R/|λ|max ([`crate::system::System::stable_step`]): RK4 2.6 (2.615
    /// computed), SSP-RK3 1.7 (1.732); the three-level predictor–corrector 1.0: on
    /// ẍ = −ω²x it gives x^{n+1} = (2 − 2h² + h⁴) x^n − (1 − h²) x^{n−1}, h = ωΔt, whose
    /// roots stay in the unit disc for h ≤ 1 (derived in [`three_level`]), half the central
    /// difference's limit. Generalized-α is unconditionally stable for linear problems
    /// (infinite radius). [`Scheme::Auto`] takes RK4's, the limit of its explicit choice.
    pub fn stability_radius(self) -> Real {
        match self {
            Scheme::Rk4 | Scheme::Auto => 2.6,
            Scheme::SspRk3 => 1.7,
            Scheme::ThreeLevel => 1.0,
            Scheme::GeneralizedAlpha => Real::INFINITY,
        }
    }

    /// The name as in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Rk4 => "rk4",
            Scheme::SspRk3 => "ssp-rk3",
            Scheme::ThreeLevel => "three-level",
            Scheme::GeneralizedAlpha => "generalized-alpha",
            Scheme::Auto => "auto",
        }
    }
}
