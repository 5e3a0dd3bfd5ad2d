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
