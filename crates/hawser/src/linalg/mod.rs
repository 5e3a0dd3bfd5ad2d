//! Structured linear solves: block-tridiagonal lines coupled through shared points.

mod block_tridiagonal;
mod coupled;
mod dense;

pub use block_tridiagonal::BlockTridiagonal;
pub use coupled::{CoupledSystem, EndKind, LineBlocks, Singular};
pub use dense::DenseLu;
