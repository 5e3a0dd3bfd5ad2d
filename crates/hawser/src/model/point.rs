//! Connection points: anchors, fairleads and free point masses.

use super::Motion;
use crate::math::{Real, Vec3};

/// A connection point that line ends attach to.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Name used by lines and channels.
    pub name: String,
    /// Initial position [m].
    pub position: Vec3,
    /// Kind.
    pub kind: PointKind,
}

/// How a point moves.
#[derive(Clone, Debug, PartialEq)]
pub enum PointKind {
    /// Fixed in space (anchor).
    Fixed,
    /// Moves as prescribed (fairlead on a vessel, test rig).
    Prescribed(Motion),
    /// Moves as a host program sets it at each coupling step (a fairlead on a vessel modelled
    /// by the host, MoorDyn's `Coupled`/`Vessel` points): it starts at `position`, and the
    /// force of the lines on it is read back ([`crate::Session::point_reaction`]).
    Coupled,
    /// Free point mass: clump weight, buoy, payload, or a massless joint between lines.
    Free {
        /// Mass [kg].
        mass: Real,
        /// Displaced volume [m³]: buoyancy ρ V g when its centre is below z = 0.
        volume: Real,
        /// Drag area C_d·A [m²]: drag ½ ρ C_dA |v*| v*.
        drag_area: Real,
        /// Added-mass coefficient C_a [-] on the displaced volume: added mass ρ C_a V.
        added_mass_coefficient: Real,
        /// Constant external force [N] (thrust, a float's net lift, a load).
        force: Vec3,
    },
    /// Fixed on a rigid body (a fairlead on a vessel, a bridle point on a towed body): moves
    /// with the body; the lines' end forces act on the body at this point.
    Body {
        /// Index into [`crate::model::Model::bodies`].
        body: usize,
        /// Offset from the body origin in body axes [m].
        offset: Vec3,
    },
}
