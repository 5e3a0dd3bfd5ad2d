//! Physics shared by every cable formulation (SPEC §1): the water, waves, seabed and obstacles
//! around a line, the hydrodynamic loads on it and the constitutive law of its material.

pub mod environment;
pub mod hydrodynamics;
pub mod material;
pub mod obstacles;
pub mod seabed;
pub mod static_kinematics;
pub mod waves;
