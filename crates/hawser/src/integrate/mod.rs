//! Time integration: explicit Runge–Kutta schemes as Butcher tableaux.

pub mod explicit_rk;

pub use explicit_rk::{ExplicitRk, RK4, SSP_RK3, Tableau};
