//! Warnings: an answer exists, but a number in it may not be what it looks like (it depends on
//! the mesh, lies outside the material's range, or the run will not end in any useful time).
//! The core returns them as data ([`crate::statics::StaticSolution::warnings`],
//! [`crate::Session::warnings`]); the command line prints them and writes them into
//! `summary.json` and `status.json`. Each carries its numbers, and its `Display` is the message
//! an engineer reads.

use crate::math::Real;
use std::fmt;

/// Something an engineer must know before signing a number hawser printed.
#[derive(Clone, Debug, PartialEq)]
pub enum Warning {
    /// Elements of a line that carries no compression are shorter than their unstretched
    /// length at the static equilibrium: the cable there holds no tension and lies folded
    /// inside the element (typically more line on the seabed than the span leaves room for),
    /// which straight elements cannot represent, so the shape and the loads next to it depend
    /// on the mesh.
    CompressedElements {
        /// Line name.
        line: String,
        /// How many elements are compressed beyond [`COMPRESSED_RATIO`].
        elements: usize,
        /// The most compressed element (0 at end A).
        element: usize,
        /// Its length over its unstretched length [-].
        ratio: Real,
    },
    /// A strain beyond what the line's axial law describes: past the last point of its
    /// tension–strain table (extrapolated), or above [`LINEAR_STRAIN_LIMIT`] for a linear law.
    /// Usually a line too short for the distance between its ends.
    StrainBeyondMaterial {
        /// Line name.
        line: String,
        /// The most strained element (0 at end A).
        element: usize,
        /// Its strain [-].
        strain: Real,
        /// Its tension [N].
        tension: Real,
        /// The largest strain the law describes [-].
        limit: Real,
    },
    /// A free point or body at rest below the seabed, which does not hold it (bodies and
    /// points without a volume have no seabed contact).
    BelowSeabed {
        /// "point NAME" or "body NAME".
        object: String,
        /// Depth of its position (a body: its centre of gravity) below the seabed [m].
        depth: Real,
    },
    /// The touchdown of a line on the seabed falls in an element too long to resolve it:
    /// longer than [`TOUCHDOWN_ELEMENTS`]⁻¹ of the suspended length, or than the length in
    /// contact. The fairlead tension and the touchdown point then depend on the mesh.
    TouchdownUnresolved {
        /// Line name.
        line: String,
        /// Length of the element holding the touchdown [m].
        element_length: Real,
        /// Unstretched length from the touchdown to the line's suspended end [m].
        suspended: Real,
        /// Unstretched length lying on the seabed [m].
        contact: Real,
    },
    /// A `dg` line's own forces at its static state differ from those of the `hermite` twin
    /// its statics were solved on ([`crate::System::statics_twin`]): the dg mesh does not
    /// resolve the static shape (a touchdown, a kink at a point) and its Newton refinement
    /// did not converge, so the run starts from a state that is not the dg line's equilibrium.
    DgTwinMismatch {
        /// Line name.
        line: String,
        /// Where the difference is largest ("end A", "end B" or "node K").
        place: String,
        /// The dg line's tension there [N].
        dg: Real,
        /// The twin's tension there [N].
        twin: Real,
    },
    /// The run needs so many node-steps that it will not end in useful time.
    LongRun {
        /// Time step [s].
        step: Real,
        /// Steps to the end of the duration.
        steps: Real,
        /// Nodes stepped (lines' nodes).
        nodes: usize,
        /// What sets the step.
        culprit: String,
    },
}

/// Elements shorter than this fraction of their unstretched length raise
/// [`Warning::CompressedElements`] (a strain below −1 %). Round-off and the seabed's
/// penetration shorten an element by far less (below 1e-6 in the examples); a compressed
/// element's length is otherwise arbitrary, and below 99 % its cable lies visibly folded.
pub const COMPRESSED_RATIO: Real = 0.99;

/// The largest strain a linear axial law is taken to describe [-]: steel wire and chain
/// yield below 1 %, polyester breaks at 10–15 % and its stiffness is strain-dependent long
/// before; above 10 % a line needs a tension–strain table, or is too short for its ends.
pub const LINEAR_STRAIN_LIMIT: Real = 0.1;

/// Elements per suspended length needed at the touchdown: with fewer, the element holding
/// the touchdown carries a share of weight that belongs to the bed or to the span. On the
/// catenary-mooring example (175 m suspended, 505 m on a 3 MPa/m bed) the `fe` fairlead
/// tension is off by −14 % at 2 elements per suspended length, −2.3 % at 4, −0.28 % at 9 and
/// within 0.01 % at 35: 8 keeps it within about 0.5 %.
pub const TOUCHDOWN_ELEMENTS: Real = 8.0;

/// Relative difference of a `dg` line's tensions from its statics twin's above which
/// [`Warning::DgTwinMismatch`] is raised: where the dg mesh resolves the shape the two agree
/// within 1e-4 (catenary mooring, 136 elements: 8e-5), and a coarse mesh on a stiff bed
/// differs by tens of percent.
pub const DG_TWIN_MISMATCH: Real = 0.01;

/// Node-steps above which a run raises [`Warning::LongRun`]: 1e11 is about 6.5 hours of CPU at
/// the 4.3e6 node-steps/s `fe` lines reach on one core (BENCHMARKS.md).
pub const LONG_RUN_NODE_STEPS: Real = 1e11;

impl Warning {
    /// A short name of the kind, for machine-read files (`summary.json`).
    pub fn kind(&self) -> &'static str {
        match self {
            Warning::CompressedElements { .. } => "compressed-elements",
            Warning::StrainBeyondMaterial { .. } => "strain-beyond-material",
            Warning::BelowSeabed { .. } => "below-seabed",
            Warning::TouchdownUnresolved { .. } => "touchdown-unresolved",
            Warning::DgTwinMismatch { .. } => "dg-twin-mismatch",
            Warning::LongRun { .. } => "long-run",
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::CompressedElements {
                line,
                elements,
                element,
                ratio,
            } => write!(
                f,
                "line {line}: {elements} element(s) shorter than {:.0} % of their unstretched \
                 length at equilibrium (element {element} at {:.1} %): the cable there holds \
                 no tension and lies folded, which the elements cannot represent, so the \
                 shape and the loads near it depend on the mesh; hint: check the line's \
                 length against the distance between its ends (more line on the seabed than \
                 the span leaves room for?)",
                COMPRESSED_RATIO * 100.0,
                ratio * 100.0
            ),
            Warning::StrainBeyondMaterial {
                line,
                element,
                strain,
                tension,
                limit,
            } => write!(
                f,
                "line {line}: strain {:.2} % in element {element} (tension {tension:.4e} N) is \
                 beyond the {:.2} % its axial law describes; hint: check the line's length \
                 against the distance between its ends, and its stiffness",
                strain * 100.0,
                limit * 100.0
            ),
            Warning::BelowSeabed { object, depth } => write!(
                f,
                "{object}: rests {depth:.4} m below the seabed, which does not hold it \
                 (bodies and points without a volume have no seabed contact); hint: shorten \
                 its lines, give it buoyancy, or give a point a volume"
            ),
            Warning::TouchdownUnresolved {
                line,
                element_length,
                suspended,
                contact,
            } => write!(
                f,
                "line {line}: the touchdown lies in an element of {element_length:.4} m, \
                 against {suspended:.4} m suspended and {contact:.4} m on the seabed: the \
                 fairlead tension and the touchdown depend on the mesh; hint: use elements \
                 no longer than {:.4} m near the touchdown (at least {TOUCHDOWN_ELEMENTS} per \
                 suspended length, and shorter than the length on the seabed)",
                (suspended / TOUCHDOWN_ELEMENTS).min(*contact)
            ),
            Warning::DgTwinMismatch {
                line,
                place,
                dg,
                twin,
            } => write!(
                f,
                "line {line}: its dg tension at {place} is {dg:.4e} N where the statics \
                 (solved on a hermite twin) give {twin:.4e} N ({:+.1} %): the dg mesh does \
                 not resolve the static shape, and the run starts away from its equilibrium; \
                 hint: use more dg elements (a touchdown on a stiff seabed needs several \
                 elements across it)",
                (dg / twin - 1.0) * 100.0
            ),
            Warning::LongRun {
                step,
                steps,
                nodes,
                culprit,
            } => write!(
                f,
                "the time step {step:.4e} s ({culprit}) needs {steps:.3e} steps of {nodes} \
                 nodes ({:.3e} node-steps): the run will not end in useful time; hint: check \
                 the property that sets the step",
                steps * *nodes as Real
            ),
        }
    }
}
