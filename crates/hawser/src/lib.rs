//! # hawser — marine cable dynamics
//!
//! The core library: the model of a cable system, the physics shared by every formulation,
//! the formulations, time integration, statics and result analysis. It does no file I/O;
//! scenario files and writers live in `hawser-io`, the command line in `hawser-cli`.
//!
//! Conventions (SPEC §1): SI units, z up, z = 0 at the still water level, seabed at
//! z = −depth; strain ε = |∂r/∂s| − 1 from current positions.
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN, which `x <= 0.0` would let through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod analysis;
pub mod bodies;
pub mod error;
pub mod formulation;
pub mod integrate;
pub mod linalg;
pub mod linearise;
pub mod math;
pub mod model;
pub mod physics;
pub mod session;
pub mod simulation;
pub mod statics;
pub mod system;
pub mod validation;
pub mod verification;
pub mod warning;

pub use error::{ModalError, ModelError, SimulationError, StaticsError};
pub use model::Model;
pub use session::Session;
pub use system::System;
pub use warning::Warning;
