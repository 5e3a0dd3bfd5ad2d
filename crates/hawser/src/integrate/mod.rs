//! Time integration: explicit Runge–Kutta schemes as Butcher tableaux, and the elastic-link
//! paper's three-time-level predictor–corrector with variable steps.

pub mod explicit_rk;
pub mod three_level;

pub use explicit_rk::{ExplicitRk, RK4, SSP_RK3, Tableau};
pub use three_level::ThreeLevel;

use crate::math::Real;
use crate::model::Scheme;

impl Scheme {
    /// The smallest radius R of the scheme's stability region over the left half-plane, for
    /// the stable step R/|λ|max ([`crate::system::System::stable_step`]): RK4 2.6 (2.615
    /// computed), SSP-RK3 1.7 (1.732); the three-level predictor–corrector 1.0: on
    /// ẍ = −ω²x it gives x^{n+1} = (2 − 2h² + h⁴) x^n − (1 − h²) x^{n−1}, h = ωΔt, whose
    /// roots stay in the unit disc for h ≤ 1 (derived in [`three_level`]), half the central
    /// difference's limit.
    pub fn stability_radius(self) -> Real {
        match self {
            Scheme::Rk4 => 2.6,
            Scheme::SspRk3 => 1.7,
            Scheme::ThreeLevel => 1.0,
        }
    }
}
