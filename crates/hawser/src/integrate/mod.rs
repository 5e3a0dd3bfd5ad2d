//! Time integration: explicit Runge–Kutta schemes as Butcher tableaux, and the elastic-link
//! paper's three-time-level predictor–corrector with variable steps.

pub mod explicit_rk;
pub mod three_level;

pub use explicit_rk::{ExplicitRk, RK4, SSP_RK3, Tableau};
pub use three_level::ThreeLevel;
