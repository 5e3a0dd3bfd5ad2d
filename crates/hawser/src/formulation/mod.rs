//! Cable formulations (SPEC §3). Each line of a [`crate::system::System`] is discretised by
//! one of them; all share the physics of [`crate::physics`] and the end coupling of
//! [`crate::linalg::CoupledSystem`]: a line owns its interior unknowns, its ends belong to
//! the points (later bodies) they are attached to, which gather the line's end forces and
//! end masses.

pub mod fe;
