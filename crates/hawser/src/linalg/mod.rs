//! Structured linear solves: block-tridiagonal lines coupled through shared points; symmetric
//! generalized eigenproblems (dense, and shift-invert subspace iteration on the block solver).

mod block_banded;
mod block_tridiagonal;
mod coupled;
mod dense;
pub mod eigen;

pub use block_banded::{BlockBandedLdl, BlockBandedLu};
pub use block_tridiagonal::BlockTridiagonal;
pub use coupled::{BodySlot, CoupledSystem, EndKind, LineBlocks, LumpedMass, ParentPin, Singular};
pub use dense::DenseLu;
