//! Cable formulations (SPEC §3). Each line of a [`crate::system::System`] is discretised by
//! one of them; all share the physics of [`crate::physics`], the mesh of elements along the
//! unstretched arc length ([`Mesh`]) and the end coupling of [`crate::linalg::CoupledSystem`]:
//! a line owns its interior unknowns, its ends belong to the points (later bodies) they are
//! attached to, which gather the line's end forces and end masses.
//!
//! A line's unknowns are a sequence of 3-vectors ("vectors" below), the first and last being
//! the positions of its two ends:
//! - `fe`: the node positions r_0 … r_N (N + 1 vectors, block bandwidth 1);
//! - `hermite`: positions and tangents r_0, t_0, r_1, t_1, …, r_{N−1}, t_{N−1}, t_N, r_N
//!   (2N + 2 vectors, block bandwidth 3; the last two are swapped so that both end positions
//!   sit at the ends), see [`hermite::vector_index`].

pub mod dg;
pub mod fe;
pub mod hermite;

use crate::linalg::LineBlocks;
use crate::math::{Real, Vec3};
use crate::model::{LineType, MassMatrix};
use crate::physics::environment::Environment;
use crate::physics::hydrodynamics::{drag_force, fluid_inertia_force};
use crate::physics::material::AxialLaw;
use crate::physics::static_kinematics::FluidPoints;

pub use crate::model::StrainMeasure;
pub use hermite::HermiteOptions;

/// Properties of one section of a line, resolved from its line type for its element length.
#[derive(Clone, Debug)]
pub struct SectionProperties {
    /// The line type (diameter, mass, drag, added mass, bending).
    pub line_type: LineType,
    /// Unstretched element length L0 [m].
    pub element_length: Real,
    /// Cross-section area A = π d²/4 [m²].
    pub area: Real,
    /// Axial law with the damping coefficient resolved for this element length.
    pub law: AxialLaw,
    /// 1 / L0 [1/m].
    pub inverse_length: Real,
}

impl SectionProperties {
    /// The properties of elements of unstretched length `element_length` [m] of line type
    /// `line_type`: area, and the axial law with its damping resolved for that length (a
    /// damping ratio is a fraction of one element's critical damping).
    pub fn new(line_type: &LineType, element_length: Real) -> Self {
        let t = line_type;
        Self {
            line_type: t.clone(),
            element_length,
            area: t.area(),
            law: AxialLaw {
                stiffness: t.axial_stiffness.clone(),
                damping: t.axial_damping.coefficient(
                    element_length,
                    &t.axial_stiffness,
                    t.mass_per_length,
                ),
                compression: t.compression,
            },
            inverse_length: 1.0 / element_length,
        }
    }
}

/// The elements of a line along its unstretched arc length: sections and the section of each
/// element. Shared by every formulation.
#[derive(Clone, Debug)]
pub struct Mesh {
    /// Sections in order from end A.
    pub sections: Vec<SectionProperties>,
    /// Section index of each element.
    pub element_section: Vec<usize>,
    /// Relative rate of change σ = L̇/L [1/s] of the unstretched length of a line on a winch
    /// (0 otherwise). Every element length scales with L(t) (docs/winches.md), so at fixed
    /// nodes the strain rate gains −σ (1 + ε): ε̇ = d/dt (ℓ/l₀) = ℓ̇/l₀ − σ ℓ/l₀.
    pub length_rate: Real,
}

impl Mesh {
    /// Builds the mesh from its sections: (line type, length [m], elements).
    pub fn new(sections: &[(LineType, Real, usize)]) -> Self {
        let mut out = Vec::new();
        let mut element_section = Vec::new();
        for (k, (t, length, n)) in sections.iter().enumerate() {
            out.push(SectionProperties::new(t, length / *n as Real));
            element_section.extend(std::iter::repeat_n(k, *n));
        }
        Self {
            sections: out,
            element_section,
            length_rate: 0.0,
        }
    }

    /// Makes this mesh (a copy of `base`) the mesh of `base`'s line rescaled to `factor`
    /// [-] times its unstretched length, changing at the relative rate `length_rate` σ
    /// [1/s]: every element length l₀ = factor · l₀(base). The mass per unit unstretched
    /// length, the axial law and its damping coefficient [N·s] stay those of the line type
    /// (MoorDyn v2 rescales its segments the same way and keeps the damping). No allocation:
    /// the winch's mesh is updated in place at every right-hand side.
    pub fn rescale(&mut self, base: &Mesh, factor: Real, length_rate: Real) {
        for (s, b) in self.sections.iter_mut().zip(&base.sections) {
            s.element_length = b.element_length * factor;
            s.inverse_length = 1.0 / s.element_length;
        }
        self.length_rate = length_rate;
    }

    /// Number of elements N.
    pub fn elements(&self) -> usize {
        self.element_section.len()
    }

    /// The section properties of an element.
    #[inline]
    pub fn section(&self, element: usize) -> &SectionProperties {
        &self.sections[self.element_section[element]]
    }

    /// Unstretched length of cable node i carries [m]: half of each adjacent element.
    #[inline]
    pub fn node_length(&self, node: usize) -> Real {
        let half = |e: usize| 0.5 * self.section(e).element_length;
        let n = self.elements();
        (if node > 0 { half(node - 1) } else { 0.0 }) + (if node < n { half(node) } else { 0.0 })
    }

    /// Unstretched arc length of node i from end A [m].
    pub fn arc_length(&self, node: usize) -> Real {
        self.element_section[..node]
            .iter()
            .map(|&s| self.sections[s].element_length)
            .sum()
    }

    /// Unstretched length of the line [m].
    pub fn length(&self) -> Real {
        self.arc_length(self.elements())
    }

    /// Shortest element [m].
    pub fn shortest_element(&self) -> Real {
        self.sections
            .iter()
            .map(|s| s.element_length)
            .fold(Real::INFINITY, Real::min)
    }

    /// The axial law of an element.
    #[inline]
    pub fn law(&self, element: usize) -> &AxialLaw {
        &self.section(element).law
    }
}

/// How a line is discretised: its formulation with its own options, and for `dg` the whole
/// discretisation (sections, bases, elements, end conditions). The one enum every
/// formulation-dependent operation of an assembled line matches on
/// ([`crate::system::SystemLine`]: state length, gather, evaluation, shape, energy, end
/// force, node tension, location; [`crate::system::System::stable_step`]: the stable rate).
#[derive(Clone, Debug)]
pub enum Discretisation {
    /// Position-vector finite elements (linear, two nodes; [`fe`]).
    Fe {
        /// Consistent or lumped mass.
        mass_matrix: MassMatrix,
    },
    /// Cubic Hermite elements with positions and tangents ([`hermite`]).
    Hermite(HermiteOptions),
    /// High-order discontinuous Galerkin ([`dg`]). Its unknowns are the modal coefficients of
    /// q and v per element held by the [`dg::DgLine`], not 3-vectors; its 3-vectors are its
    /// outputs (positions at the N + 1 element ends) and its two end attachments, which
    /// receive the flux tractions as forces and no mass.
    Dg(Box<dg::DgLine>),
}

impl Discretisation {
    /// Number of 3-vectors of a line of `elements` elements, ends included: its unknowns
    /// for `fe` and `hermite`, its node outputs for `dg`.
    pub fn vectors(&self, elements: usize) -> usize {
        match self {
            Discretisation::Fe { .. } | Discretisation::Dg(_) => elements + 1,
            Discretisation::Hermite(_) => 2 * elements + 2,
        }
    }

    /// Block bandwidth of the line's matrices.
    pub fn bandwidth(&self) -> usize {
        match self {
            Discretisation::Fe { .. } | Discretisation::Dg(_) => 1,
            Discretisation::Hermite(_) => 3,
        }
    }

    /// Index of node i's position among the line's vectors (N elements).
    #[inline]
    pub fn node_vector(&self, node: usize, elements: usize) -> usize {
        match self {
            Discretisation::Fe { .. } | Discretisation::Dg(_) => node,
            Discretisation::Hermite(_) => hermite::vector_index(node, false, elements),
        }
    }

    /// Whether vector j is a tangent (dimensionless) rather than a position [m].
    #[inline]
    pub fn is_tangent(&self, j: usize, elements: usize) -> bool {
        match self {
            Discretisation::Fe { .. } | Discretisation::Dg(_) => false,
            Discretisation::Hermite(_) => {
                j != 0 && j != 2 * elements + 1 && (j % 2 == 1 || j == 2 * elements)
            }
        }
    }

    /// Whether the mass couples neighbouring vectors (not lumped).
    pub fn consistent_mass(&self) -> bool {
        match self {
            Discretisation::Fe { mass_matrix } => *mass_matrix == MassMatrix::Consistent,
            Discretisation::Hermite(_) => true,
            Discretisation::Dg(_) => false,
        }
    }

    /// Short name as in scenario files.
    pub fn name(&self) -> &'static str {
        match self {
            Discretisation::Fe { .. } => "fe",
            Discretisation::Hermite(_) => "hermite",
            Discretisation::Dg(_) => "dg",
        }
    }

    /// The `dg` discretisation, `None` for the element formulations.
    #[inline]
    pub fn dg(&self) -> Option<&dg::DgLine> {
        match self {
            Discretisation::Dg(line) => Some(line),
            Discretisation::Fe { .. } | Discretisation::Hermite(_) => None,
        }
    }
}

/// Per-element results of a force evaluation.
#[derive(Clone, Debug)]
pub struct ElementState {
    /// Axial tension [N] (with damping): `fe` uniform over the element, `hermite` at its
    /// midpoint.
    pub tension: Vec<Real>,
    /// Axial strain ε = |∂r/∂s| − 1 [-] (at the midpoint for `hermite`).
    pub strain: Vec<Real>,
    /// Curvature κ [1/m] at the element midpoint (zero for `fe`).
    pub curvature: Vec<Real>,
    /// Bending moment M = EI κ (+ ζ_b κ̇) [N·m] at the element midpoint (zero for `fe`).
    pub bending_moment: Vec<Real>,
    /// Shear force magnitude |dM/ds| [N] in the element (zero for `fe`).
    pub shear_force: Vec<Real>,
}

impl ElementState {
    /// Storage for `n` elements.
    pub fn new(n: usize) -> Self {
        Self {
            tension: vec![0.0; n],
            strain: vec![0.0; n],
            curvature: vec![0.0; n],
            bending_moment: vec![0.0; n],
            shear_force: vec![0.0; n],
        }
    }
}

/// Fluid load per unit unstretched length [N/m] at a point of a line at `r` [m] moving at
/// `v` [m/s], with unit tangent τ and √(1+ε) (SPEC §1): Morison drag on the velocity relative
/// to the water (the current scaled by `current_factor`), and, in moving water, the
/// Froude–Krylov and added-mass force of the water's acceleration. `still_water` skips the
/// fluid kinematics where there is no current and no wave. Shared by every formulation at its
/// own quadrature points: `fluid` and `point` say which of the line's points this is, for
/// wave kinematics at the static position ([`FluidPoints`]).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn fluid_load(
    env: &Environment,
    fluid: &FluidPoints,
    point: usize,
    line_type: &LineType,
    area: Real,
    time: Real,
    r: &Vec3,
    v: &Vec3,
    tau: &Vec3,
    root_stretch: Real,
    current_factor: Real,
    still_water: bool,
) -> Vec3 {
    let lt = line_type;
    let rho = env.fluid_density(r.z);
    if still_water {
        return drag_force(&lt.drag, rho, lt.diameter, root_stretch, tau, &-v);
    }
    let (velocity, acceleration) = fluid.kinematics(env, point, r, time);
    let relative = velocity * current_factor - v;
    drag_force(&lt.drag, rho, lt.diameter, root_stretch, tau, &relative)
        + fluid_inertia_force(
            rho,
            area,
            lt.normal_added_mass,
            lt.tangential_added_mass,
            tau,
            &acceleration,
        )
}

/// Mechanical energy [J] of an element, a line or a state ([`crate::system::System::mechanical_energy`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energy {
    /// Kinetic energy [J].
    pub kinetic: Real,
    /// Potential energy of weight in air, relative to z = 0 [J].
    pub gravity: Real,
    /// Elastic strain energy [J].
    pub elastic: Real,
}

impl Energy {
    /// The sum [J].
    pub fn total(&self) -> Real {
        self.kinetic + self.gravity + self.elastic
    }
}

impl std::ops::AddAssign for Energy {
    fn add_assign(&mut self, o: Energy) {
        self.kinetic += o.kinetic;
        self.gravity += o.gravity;
        self.elastic += o.elastic;
    }
}

/// Load scaling for statics continuation (the mass blocks are assembled when the caller
/// passes them), and where the line's quadrature points take the fluid kinematics.
#[derive(Clone, Copy, Debug)]
pub struct LoadOptions<'a> {
    /// Multiplies the current velocity seen by drag [-].
    pub current_factor: Real,
    /// Direct summation, or the line's points in the static-position cache.
    pub fluid: FluidPoints<'a>,
}

impl LoadOptions<'_> {
    /// The full current, direct wave kinematics.
    pub fn direct(current_factor: Real) -> Self {
        Self {
            current_factor,
            fluid: FluidPoints::Direct,
        }
    }
}

/// Evaluates the generalized forces of a line on its vectors (see the module doc) at
/// coordinates `q` and rates `qdot`, its element results, and, if asked, its mass blocks.
#[allow(clippy::too_many_arguments)]
pub fn line_forces(
    mesh: &Mesh,
    kind: &Discretisation,
    env: &Environment,
    time: Real,
    q: &[Vec3],
    qdot: &[Vec3],
    forces: &mut [Vec3],
    elements: &mut ElementState,
    blocks: Option<&mut LineBlocks>,
    options: LoadOptions,
) {
    match kind {
        Discretisation::Fe { mass_matrix } => fe::line_forces(
            mesh,
            *mass_matrix,
            env,
            time,
            q,
            qdot,
            forces,
            elements,
            blocks,
            options,
        ),
        Discretisation::Hermite(h) => hermite::line_forces(
            mesh, h, env, time, q, qdot, forces, elements, blocks, options,
        ),
        Discretisation::Dg(_) => {
            unreachable!("dg lines are evaluated by SystemLine::evaluate through DgLine::rhs")
        }
    }
}
