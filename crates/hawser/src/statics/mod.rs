//! Static equilibrium of lines and free points under weight, buoyancy, current drag and point
//! loads: Newton with line search and load continuation from a catenary seed, with dynamic
//! relaxation as fallback.

pub mod catenary;
mod dynamic_relaxation;
mod newton;

pub use newton::{StaticOptions, StaticSolution, catenary_seed, evaluate, residual, solve};
