//! Static equilibrium of lines and free points under weight, buoyancy, current drag and point
//! loads: Newton with line search and load continuation from a catenary seed, with dynamic
//! relaxation as fallback.

mod bodies;
pub mod catenary;
mod checks;
mod dynamic_relaxation;
mod newton;
mod release;

pub use bodies::solve_with_bodies;
pub use checks::state_warnings;
pub use newton::{
    StaticOptions, StaticSolution, as_defined_shape, catenary_seed, evaluate, residual,
    set_tow_velocities, solve,
};
pub use release::solve_with_release;
