//! Line types, lines and their sections.

use crate::math::Real;
use crate::physics::hydrodynamics::DragModel;
use crate::physics::material::{AxialDamping, AxialStiffness};

/// Cable properties shared by the sections that use them (SPEC §1).
#[derive(Clone, Debug, PartialEq)]
pub struct LineType {
    /// Name used by line sections.
    pub name: String,
    /// Nominal (hydrodynamic) diameter d [m]; sets the drag, buoyancy and added-mass area.
    pub diameter: Real,
    /// Mass per unit unstretched length γ0 [kg/m].
    pub mass_per_length: Real,
    /// Elastic axial law: EA [N] or a tension–strain table.
    pub axial_stiffness: AxialStiffness,
    /// Axial damping: a coefficient [N·s] or a fraction of critical damping.
    pub axial_damping: AxialDamping,
    /// Whether the cable carries compression (default false: T = EA·max(ε, 0) + c·ε̇).
    pub compression: bool,
    /// Bending stiffness EI [N·m²] (formulations with bending; ignored by `fe`).
    pub bending_stiffness: Real,
    /// Bending damping ζ_b [N·m²·s] (formulations with bending; ignored by `fe`).
    pub bending_damping: Real,
    /// Drag model.
    pub drag: DragModel,
    /// Normal added-mass coefficient C_an [-].
    pub normal_added_mass: Real,
    /// Tangential added-mass coefficient C_at [-].
    pub tangential_added_mass: Real,
    /// Minimum breaking load MBL [N]: the strength the line's utilisation is measured
    /// against ([`crate::analysis::strength`]); `None`: not given, no utilisation.
    pub minimum_breaking_load: Option<Real>,
    /// Design safety factor SF [-] (≥ 1): the permissible tension is MBL / SF (the
    /// elastic-link paper's "permissible tension at each point"); `None`: not given.
    pub design_safety_factor: Option<Real>,
}

impl LineType {
    /// Cross-section area A = π d²/4 [m²] used for buoyancy and added mass.
    pub fn area(&self) -> Real {
        std::f64::consts::PI * self.diameter * self.diameter / 4.0
    }

    /// Permissible tension MBL / SF [N] (MBL alone without a safety factor); `None` without
    /// a minimum breaking load.
    pub fn permissible_tension(&self) -> Option<Real> {
        self.minimum_breaking_load
            .map(|mbl| mbl / self.design_safety_factor.unwrap_or(1.0))
    }
}

/// A run of one line type along a line.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// Index into [`crate::model::Model::line_types`].
    pub line_type: usize,
    /// Unstretched length [m].
    pub length: Real,
    /// Number of equal elements.
    pub elements: usize,
    /// Polynomial order P of the Legendre basis of a `dg` line in this section (1 to
    /// [`crate::formulation::dg::basis::MAX_ORDER`]); ignored by `fe` and `hermite`.
    pub order: usize,
}

/// Mass matrix of the `fe` formulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MassMatrix {
    /// Consistent mass matrix γ0 L0/6 [2I I; I 2I] (position-vector paper eq. 12), solved
    /// in O(N) per step by block-tridiagonal elimination.
    #[default]
    Consistent,
    /// Lumped (diagonal) mass: half of each element's mass at each node.
    Lumped,
}

/// Strain measure of the axial energy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StrainMeasure {
    /// ε = |r'| − 1 (SPEC §1): exact for any stretch.
    #[default]
    Exact,
    /// ε = ½ (r'·r' − 1) (elastic-link paper eq. 12): within ε²/2 of the exact strain. Its
    /// energy ½∫EA ε² makes the force along the line EA ε |r'|, so the same load stretches
    /// the line less (λ³ − λ = 2T/EA against λ = 1 + T/EA).
    SmallStrain,
}

/// Cable formulation of a line (SPEC §3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Formulation {
    /// Position-vector finite elements.
    Fe,
    /// High-order discontinuous Galerkin with bending (DG paper,
    /// [`crate::formulation::dg`]).
    Dg,
    /// Cubic Hermite elements with positions and tangents (elastic-link paper §4,
    /// [`crate::formulation::hermite`]).
    Hermite,
}

/// One of the two ends of a line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum End {
    /// End A (arc length 0).
    A,
    /// End B (arc length the full length).
    B,
}

impl End {
    /// 0 for end A, 1 for end B (the index of [`Line::ends`]).
    pub fn index(self) -> usize {
        match self {
            End::A => 0,
            End::B => 1,
        }
    }

    /// `"a"` or `"b"`, as in scenario keys and channel names.
    pub fn name(self) -> &'static str {
        match self {
            End::A => "a",
            End::B => "b",
        }
    }
}

/// What an end of a line is attached to. The attachment owns the end node: it supplies the
/// end's kinematics and gathers the line's end force and mass (MoorDyn's rule).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineEnd {
    /// A connection point (fixed, prescribed or free), by index.
    Point(usize),
}

/// A cable between two attachments: end A at arc length s = 0, end B at the full length.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// Name used for channels and results.
    pub name: String,
    /// Sections from end A to end B.
    pub sections: Vec<Section>,
    /// Formulation.
    pub formulation: Formulation,
    /// Mass matrix (for `fe`).
    pub mass_matrix: MassMatrix,
    /// Axial strain measure (for `hermite`; `fe` always uses the exact ε = L/L0 − 1).
    pub strain_measure: StrainMeasure,
    /// Strength c_f [-] of the modal velocity filter of a `dg` line
    /// ([`crate::formulation::dg::DgLine::modal_filter`]; 0 switches it off); ignored by `fe`
    /// and `hermite`.
    pub modal_filter: Real,
    /// Extra modal filter strength c_s [-] of a `dg` line at fronts, switched on per element
    /// by a smoothness sensor ([`crate::formulation::dg::DgLine::shock_filter`]; 0, the
    /// default, switches it off); ignored by `fe` and `hermite`.
    pub shock_filter: Real,
    /// Clamped ends (A, B): the direction of the line's tangent ∂r/∂s held fixed in space at
    /// that end, pointing from A toward B (formulations with bending); `None`: pinned.
    pub clamp: [Option<crate::math::Vec3>; 2],
    /// Attachment of end A.
    pub end_a: LineEnd,
    /// Attachment of end B.
    pub end_b: LineEnd,
    /// A winch changing the line's unstretched length on a schedule (`fe` and `hermite`
    /// lines of one section; [`crate::model::Winch`]); `None`: fixed length.
    pub winch: Option<crate::model::Winch>,
}

impl Line {
    /// Total unstretched length [m].
    pub fn length(&self) -> Real {
        self.sections.iter().map(|s| s.length).sum()
    }
    /// The attachments of ends A and B.
    pub fn ends(&self) -> [LineEnd; 2] {
        [self.end_a, self.end_b]
    }
    /// Total element count.
    pub fn elements(&self) -> usize {
        self.sections.iter().map(|s| s.elements).sum()
    }
}
