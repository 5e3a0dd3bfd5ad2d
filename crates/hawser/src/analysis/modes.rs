//! Natural frequencies and mode shapes about the static state, labelled in the field's words.
//!
//! The undamped modes solve K φ = λ M φ, λ = ω² [rad²/s²], with K the symmetric part of the
//! tangent stiffness and M the mass with added mass from [`crate::linearise`]. Current drag
//! (a follower load) and the √(1+ε) factor of seabed contact make K slightly non-symmetric;
//! its skew part is dropped, as every undamped modal analysis does, and its relative size is
//! reported ([`Modes::stiffness_asymmetry`]). Damping is not in the modes.
//!
//! The lowest modes come from shift-invert subspace iteration on (K − σM)⁻¹ M, each
//! application an O(nodes) solve with the dynamics' block solver; the shift σ sits at zero or
//! just below it, so slack and soft systems (small or zero stiffness) are found first. A dense
//! solve (Cholesky of M and a symmetric eigen decomposition, O(n³)) serves small systems and
//! is the fallback.
//!
//! Each mode is labelled by where its kinetic energy ½ φᵀ M φ sits: the share of each line
//! (its interior vectors' rows: node positions, and a `hermite` line's tangents), of each free
//! point and of each free body, and within them the share along the static tangent (axial),
//! in the plane of the line's static shape (in-plane: the vertical plane of a catenary),
//! normal to it (out-of-plane), or, for a straight vertical line with no plane, transverse;
//! for a point, vertical or horizontal; for a body, surge, sway, heave, roll, pitch or yaw in
//! its own axes. The owners with at least half the largest share take part in the label, and
//! the ordinal counts the modes with the same direction and owners: "first in-plane mode of
//! line L1", "second axial mode of lines L2 and L3", "first vertical mode of point buoy",
//! "first surge mode of body spar and lines L1 and L2".
//!
//! `dg` lines are not linearised (their unknowns are modal coefficients of q and v): their
//! modes are those of the model's hermite twin ([`modal_twin`]), the same twin the statics
//! solves first.

use crate::error::ModalError;
use crate::linalg::eigen::{EigenFailure, EigenPairs, SubspaceOptions, dense_generalized};
use crate::linearise::{BlockSolver, DofMap, DofOwner, Linearisation};
use crate::math::{Real, Vec3, get3};
use crate::system::System;
use std::f64::consts::TAU;

/// How to solve the eigenproblem.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum EigenMethod {
    /// Dense for small systems (≤ 150 degrees of freedom or a third of them wanted),
    /// shift-invert otherwise, dense as fallback up to 2000 degrees of freedom.
    #[default]
    Auto,
    /// Shift-invert subspace iteration with the block solver (O(nodes) per iteration).
    ShiftInvert,
    /// Dense generalized eigen decomposition (O(n³)).
    Dense,
}

/// Settings of a modal analysis.
#[derive(Clone, Copy, Debug)]
pub struct ModalOptions {
    /// Number of modes wanted (the lowest).
    pub count: usize,
    /// Solver.
    pub method: EigenMethod,
    /// Shift σ [rad²/s²]; `None` for 0, moved below zero if K is singular there.
    pub shift: Option<Real>,
    /// Convergence settings of the subspace iteration.
    pub subspace: SubspaceOptions,
}

impl Default for ModalOptions {
    /// Ten modes, automatic method, shift at zero.
    fn default() -> Self {
        Self {
            count: 10,
            method: EigenMethod::Auto,
            shift: None,
            subspace: SubspaceOptions::default(),
        }
    }
}

/// Dominant direction of a mode's motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModeDirection {
    /// Along the static tangent of the line (stretching).
    Axial,
    /// Normal to the tangent, in the plane of the line's static shape.
    InPlane,
    /// Normal to the plane of the line's static shape.
    OutOfPlane,
    /// Normal to the tangent of a straight vertical line (no plane defined).
    Transverse,
    /// A point moving vertically.
    Vertical,
    /// A point moving horizontally.
    Horizontal,
    /// A body moving along its x axis.
    Surge,
    /// A body moving along its y axis.
    Sway,
    /// A body moving along its z axis.
    Heave,
    /// A body turning about its x axis.
    Roll,
    /// A body turning about its y axis.
    Pitch,
    /// A body turning about its z axis.
    Yaw,
}

/// Every direction, in the order of the per-owner energy arrays of [`build_modes`].
const DIRECTIONS: [ModeDirection; 12] = [
    ModeDirection::Axial,
    ModeDirection::InPlane,
    ModeDirection::OutOfPlane,
    ModeDirection::Transverse,
    ModeDirection::Vertical,
    ModeDirection::Horizontal,
    ModeDirection::Surge,
    ModeDirection::Sway,
    ModeDirection::Heave,
    ModeDirection::Roll,
    ModeDirection::Pitch,
    ModeDirection::Yaw,
];

impl ModeDirection {
    /// The word used in labels.
    pub fn name(&self) -> &'static str {
        match self {
            ModeDirection::Axial => "axial",
            ModeDirection::InPlane => "in-plane",
            ModeDirection::OutOfPlane => "out-of-plane",
            ModeDirection::Transverse => "transverse",
            ModeDirection::Vertical => "vertical",
            ModeDirection::Horizontal => "horizontal",
            ModeDirection::Surge => "surge",
            ModeDirection::Sway => "sway",
            ModeDirection::Heave => "heave",
            ModeDirection::Roll => "roll",
            ModeDirection::Pitch => "pitch",
            ModeDirection::Yaw => "yaw",
        }
    }
}

/// What carries a mode's kinetic energy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModeOwner {
    /// A line (its interior nodes).
    Line(usize),
    /// A free point.
    Point(usize),
    /// A free body.
    Body(usize),
}

/// A mode's label.
#[derive(Clone, Debug, PartialEq)]
pub struct ModeLabel {
    /// Dominant direction.
    pub direction: ModeDirection,
    /// Owners with at least half the largest kinetic-energy share, largest first.
    pub owners: Vec<ModeOwner>,
    /// 1 for the lowest mode with this direction and these owners, 2 for the next, ...
    pub ordinal: usize,
    /// The label in words, e.g. "first axial mode of line L1".
    pub text: String,
}

/// One natural mode.
#[derive(Clone, Debug)]
pub struct Mode {
    /// Eigenvalue λ = ω² [rad²/s²] (negative: statically unstable direction).
    pub eigenvalue: Real,
    /// Natural frequency f = √λ / 2π [Hz] (0 when λ ≤ 0).
    pub frequency: Real,
    /// Period 1/f [s] (infinite when f = 0).
    pub period: Real,
    /// Shape over the degrees of freedom, mass-normalised (φᵀ M φ = 1 [kg·m²] for a shape in
    /// metres per unit modal coordinate), its largest component positive.
    pub shape: Vec<Real>,
    /// Kinetic-energy share of each line [-] (sums with the points' to 1).
    pub line_shares: Vec<Real>,
    /// Kinetic-energy share of each free point, by point index [-] (0 for other points).
    pub point_shares: Vec<Real>,
    /// Kinetic-energy share of each free body, by body index [-] (0 for other bodies).
    pub body_shares: Vec<Real>,
    /// Kinetic-energy shares by direction over the label's owners [-].
    pub direction_shares: Vec<(ModeDirection, Real)>,
    /// Label.
    pub label: ModeLabel,
}

impl Mode {
    /// Displacement of node `node` (0..=N) of line `line` in this mode's shape [m per unit
    /// modal coordinate] (zero at ends on fixed or prescribed points; δr + δθ × ρ at an end on
    /// a free body).
    pub fn node_displacement(&self, dofs: &DofMap, line: usize, node: usize) -> Vec3 {
        dofs.displacement(&self.shape, dofs.node_target(line, node))
    }

    /// Displacement of a point (zero for fixed and prescribed points).
    pub fn point_displacement(&self, dofs: &DofMap, point: usize) -> Vec3 {
        dofs.displacement(&self.shape, dofs.point_target(point))
    }

    /// Translation of a free body's origin [m] and its small rotation [rad] about the global
    /// axes in this mode's shape; `None` for other bodies.
    pub fn body_motion(&self, dofs: &DofMap, body: usize) -> Option<(Vec3, Vec3)> {
        let g = dofs.body_group(body)?;
        Some((get3(&self.shape, g), get3(&self.shape, g + 1)))
    }

    /// Largest displacement magnitude of the shape's positions (line nodes, free points,
    /// body origins; not tangents or rotations), to scale it for display.
    pub fn largest_displacement(&self, dofs: &DofMap) -> Real {
        dofs.owners
            .iter()
            .enumerate()
            .filter(|(_, o)| {
                !matches!(
                    o,
                    DofOwner::LineNode { tangent: true, .. } | DofOwner::BodyRotation { .. }
                )
            })
            .map(|(g, _)| get3(&self.shape, g).norm())
            .fold(0.0, Real::max)
    }
}

/// The result of a modal analysis.
#[derive(Clone, Debug)]
pub struct Modes {
    /// Modes by increasing frequency.
    pub modes: Vec<Mode>,
    /// Solver used.
    pub method: EigenMethod,
    /// Shift used by shift-invert [rad²/s²] (0 for dense).
    pub shift: Real,
    /// Subspace iterations (0 for dense).
    pub iterations: usize,
    /// max|K − Kᵀ| / max|K| of the tangent stiffness before symmetrisation [-].
    pub stiffness_asymmetry: Real,
    /// Number of degrees of freedom.
    pub degrees_of_freedom: usize,
    /// Why the automatic method fell back to the dense solver, if it did.
    pub fallback: Option<String>,
}

/// Whether the modes of this system can be computed and labelled: no `dg` line (its unknowns
/// are modal coefficients, not linearised; compute the modes of [`modal_twin`] instead). `fe`
/// and `hermite` lines, free points, free bodies and pinned bodies are (a pinned body turns
/// about its pin, whose motion is given: its three rotations are degrees of freedom, its
/// translations are held, [`DofMap::held`]); a body pinned to another body is not (its pin
/// moves with the parent). Call it before linearising.
pub fn supported(system: &System) -> Result<(), ModalError> {
    for b in &system.bodies {
        if let Some((parent, _)) = b.body.kind.pin().and_then(|p| p.parent()) {
            return Err(ModalError::PinnedToBody {
                body: b.body.name.clone(),
                parent: system.bodies[parent].body.name.clone(),
            });
        }
    }
    match system.lines.iter().find(|l| l.dg().is_some()) {
        Some(l) => Err(ModalError::Unsupported {
            line: l.name.clone(),
            formulation: l.discretisation.name(),
        }),
        None => Ok(()),
    }
}

/// The model whose modes stand for those of `model`'s `dg` lines: each `dg` line becomes a
/// `hermite` line over the same sections with ⌈P/2⌉ (at least one) cubic elements per `dg`
/// element of order P, the hermite twin that `dg` statics solves first
/// (`System::statics_twin`); `None` when no line is `dg`. Its static state and modes converge
/// to the `dg` line's as both meshes are refined.
pub fn modal_twin(model: &crate::model::Model) -> Option<crate::model::Model> {
    use crate::model::Formulation;
    if !model.lines.iter().any(|l| l.formulation == Formulation::Dg) {
        return None;
    }
    let mut twin = model.clone();
    for l in twin.lines.iter_mut() {
        if l.formulation == Formulation::Dg {
            l.formulation = Formulation::Hermite;
            for s in l.sections.iter_mut() {
                s.elements *= s.order.div_ceil(2).max(1);
            }
        }
    }
    Some(twin)
}

/// The lowest `options.count` natural modes of the linearised system, labelled.
pub fn natural_modes(
    system: &System,
    lin: &Linearisation,
    options: &ModalOptions,
) -> Result<Modes, ModalError> {
    supported(system)?;
    let n = lin.dofs.len();
    // A pinned body's translations are held by its pin: the eigenproblem is the one on the
    // other degrees of freedom (the held rows and columns removed, or projected out of the
    // subspace iteration), and the held components of every shape are zero.
    let held = lin.dofs.held();
    let free = n - held.len();
    if free == 0 {
        return Err(ModalError::NoDegreesOfFreedom);
    }
    let count = options.count.clamp(1, free);
    let k = lin.stiffness.symmetric_part();
    let m = &lin.mass;
    let dense = |k: &crate::linearise::BlockMatrix| {
        let kept = without_held(&k.to_dense(&lin.dofs), &held);
        dense_generalized(&kept, &without_held(&m.to_dense(&lin.dofs), &held)).map(|mut p| {
            p.values.truncate(count);
            p.vectors = with_held(&p.vectors.columns(0, count).into_owned(), &held, n);
            p
        })
    };
    let method = match options.method {
        EigenMethod::Auto if free <= 150 || 3 * count >= free => EigenMethod::Dense,
        other => other,
    };
    let mut fallback = None;
    let (pairs, method, shift) = match method {
        EigenMethod::Dense => (dense(&k).map_err(failure)?, EigenMethod::Dense, 0.0),
        _ => match shift_invert(lin, &k, count, &held, options) {
            Ok((p, s)) => (p, EigenMethod::ShiftInvert, s),
            Err(e) if options.method == EigenMethod::Auto && n <= 2000 => {
                let p = dense(&k).map_err(|_| e.clone())?;
                fallback = Some(format!("shift-invert failed ({e}); solved dense"));
                (p, EigenMethod::Dense, 0.0)
            }
            Err(e) => return Err(e),
        },
    };
    let mut modes = build_modes(system, lin, &pairs);
    modes.sort_by(|a, b| a.eigenvalue.total_cmp(&b.eigenvalue));
    label_ordinals(system, &mut modes);
    Ok(Modes {
        modes,
        method,
        shift,
        iterations: pairs.iterations,
        stiffness_asymmetry: lin.stiffness.asymmetry(),
        degrees_of_freedom: n,
        fallback,
    })
}

fn failure(e: EigenFailure) -> ModalError {
    match e {
        EigenFailure::MassNotDefinite => ModalError::MassNotDefinite,
        EigenFailure::SingularShift => ModalError::Singular {
            location: "the stiffness matrix".into(),
        },
        EigenFailure::NotConverged {
            iterations,
            residual,
        } => ModalError::NotConverged {
            iterations,
            residual,
        },
    }
}

/// Shift-invert subspace iteration; tries σ = 0 (or the user's shift), then shifts below zero
/// of 10⁻⁸, 10⁻⁶ and 10⁻⁴ of the mean diagonal ratio K_ii/M_ii when K − σM is singular.
fn shift_invert(
    lin: &Linearisation,
    k: &crate::linearise::BlockMatrix,
    count: usize,
    held: &[usize],
    options: &ModalOptions,
) -> Result<(EigenPairs, Real), ModalError> {
    let map = &lin.dofs;
    let n = map.len();
    let m = &lin.mass;
    let kd = k.to_diagonal(map);
    let md = m.to_diagonal(map);
    let mean_ratio =
        kd.iter().sum::<Real>().abs() / md.iter().sum::<Real>().max(Real::MIN_POSITIVE);
    let mut shifts = vec![options.shift.unwrap_or(0.0)];
    if options.shift.is_none() {
        shifts.extend([1e-8, 1e-6, 1e-4].map(|f| -f * mean_ratio));
    }
    let mut last = ModalError::Singular {
        location: "the stiffness matrix".into(),
    };
    for sigma in shifts {
        let mut solver = BlockSolver::new(&k.shifted(sigma, m));
        let result = crate::linalg::eigen::subspace_iteration(
            n,
            count,
            sigma,
            (k.row_sum_norm(map), m.row_sum_norm(map)),
            |b, x| solver.solve(map, b, x).is_ok() && x.iter().all(|v| v.is_finite()),
            // K and M projected onto the free degrees of freedom (the solver holds the
            // others at zero): the reactions in the held rows are no part of the residual.
            |x, y| {
                k.apply(map, x, y);
                held.iter().for_each(|&i| y[i] = 0.0);
            },
            |x, y| {
                m.apply(map, x, y);
                held.iter().for_each(|&i| y[i] = 0.0);
            },
            options.subspace,
        );
        match result {
            Ok(p) => return Ok((p, sigma)),
            Err(EigenFailure::SingularShift) => {
                last = ModalError::Singular {
                    location: format!("the shifted stiffness K − σM at σ = {sigma:.3e} rad²/s²"),
                };
            }
            Err(e) => return Err(failure(e)),
        }
    }
    Err(last)
}

/// `a` without the rows and columns `held` (increasing indices).
fn without_held(a: &nalgebra::DMatrix<Real>, held: &[usize]) -> nalgebra::DMatrix<Real> {
    if held.is_empty() {
        return a.clone();
    }
    let kept: Vec<usize> = (0..a.nrows())
        .filter(|i| held.binary_search(i).is_err())
        .collect();
    nalgebra::DMatrix::from_fn(kept.len(), kept.len(), |r, c| a[(kept[r], kept[c])])
}

/// The vectors `v` over the kept degrees of freedom back on all `n`, zero in the rows `held`.
fn with_held(v: &nalgebra::DMatrix<Real>, held: &[usize], n: usize) -> nalgebra::DMatrix<Real> {
    if held.is_empty() {
        return v.clone();
    }
    let mut out = nalgebra::DMatrix::zeros(n, v.ncols());
    let kept = (0..n).filter(|i| held.binary_search(i).is_err());
    for (r, i) in kept.enumerate() {
        out.row_mut(i).copy_from(&v.row(r));
    }
    out
}

/// Frame of a line's static shape for labelling: node positions and the plane normal.
struct LineFrame {
    position: Vec<Vec3>,
    normal: Option<Vec3>,
}

/// The lines' static frames and the bodies' static orientations (rotation matrices) at
/// `state`.
fn static_frames(system: &System, state: &[Real]) -> (Vec<LineFrame>, Vec<crate::math::Mat3>) {
    let mut ws = system.workspace();
    system.point_kinematics(0.0, state, &mut ws);
    system.gather_lines(state, &mut ws);
    let frames = ws
        .lines
        .iter()
        .zip(&system.lines)
        .map(|(lw, l)| {
            let r: Vec<Vec3> = (0..l.nodes())
                .map(|i| lw.position[l.node_vector(i)])
                .collect();
            let n = r.len() - 1;
            let chord = r[n] - r[0];
            let length: Real = r.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
            let c = chord.try_normalize(1e-12 * length.max(1e-300));
            // The node farthest from the chord line spans the plane with it.
            let (far, dev) = r
                .iter()
                .map(|p| match c {
                    Some(c) => (p - r[0]).cross(&c).norm(),
                    None => (p - r[0]).norm(),
                })
                .enumerate()
                .fold((0, 0.0), |a, (i, d)| if d > a.1 { (i, d) } else { a });
            let normal = match c {
                Some(c) if dev > 1e-4 * length => c.cross(&(r[far] - r[0])).try_normalize(0.0),
                Some(c) => c.cross(&Vec3::z()).try_normalize(1e-6),
                None => None,
            };
            LineFrame {
                position: r,
                normal,
            }
        })
        .collect();
    let orientations = ws
        .bodies
        .iter()
        .map(|k| *k.orientation.to_rotation_matrix().matrix())
        .collect();
    (frames, orientations)
}

/// The node a vector of line `l` belongs to (its position or, for `hermite`, its tangent).
fn vector_node(l: &crate::system::SystemLine, j: usize) -> usize {
    let n = l.mesh.elements();
    if l.vectors() == n + 1 {
        j
    } else if j >= 2 * n {
        n
    } else {
        j / 2
    }
}

fn build_modes(system: &System, lin: &Linearisation, pairs: &EigenPairs) -> Vec<Mode> {
    let map = &lin.dofs;
    let n = map.len();
    let (frames, orientations) = static_frames(system, &lin.state);
    let mut mphi = vec![0.0; n];
    let mut out = Vec::new();
    for (c, &lambda) in pairs.values.iter().enumerate() {
        let mut shape: Vec<Real> = pairs.vectors.column(c).iter().copied().collect();
        let biggest = shape
            .iter()
            .copied()
            .fold(0.0, |a: Real, x| if x.abs() > a.abs() { x } else { a });
        if biggest < 0.0 {
            shape.iter_mut().for_each(|x| *x = -*x);
        }
        lin.mass.apply(map, &shape, &mut mphi);
        let total: Real = shape.iter().zip(&mphi).map(|(a, b)| a * b).sum();
        let total = if total > 0.0 { total } else { 1.0 };
        // Energies by owner and by direction (per owner), in the order of DIRECTIONS.
        let mut line_shares = vec![0.0; system.lines.len()];
        let mut point_shares = vec![0.0; system.points.len()];
        let mut body_shares = vec![0.0; system.bodies.len()];
        let mut line_dirs = vec![[0.0; 12]; system.lines.len()];
        let mut point_dirs = vec![[0.0; 12]; system.points.len()];
        let mut body_dirs = vec![[0.0; 12]; system.bodies.len()];
        for (g, owner) in map.owners.iter().enumerate() {
            let u = get3(&shape, g);
            let p = get3(&mphi, g);
            let e = u.dot(&p) / total;
            match *owner {
                DofOwner::LineNode { line, node, .. } => {
                    line_shares[line] += e;
                    let f = &frames[line];
                    // A tangent's energy is classified by the tangent it turns, a position's
                    // by its node's.
                    let k = vector_node(&system.lines[line], node);
                    let last = f.position.len() - 1;
                    let t = (f.position[(k + 1).min(last)] - f.position[k.saturating_sub(1)])
                        .try_normalize(0.0)
                        .unwrap_or_else(Vec3::z);
                    let axial = t.dot(&u) * t.dot(&p) / total;
                    let d = &mut line_dirs[line];
                    d[0] += axial;
                    match f
                        .normal
                        .and_then(|nv| (nv - t * nv.dot(&t)).try_normalize(1e-9))
                    {
                        Some(nv) => {
                            let out_of_plane = nv.dot(&u) * nv.dot(&p) / total;
                            d[2] += out_of_plane;
                            d[1] += e - axial - out_of_plane;
                        }
                        None => d[3] += e - axial,
                    }
                }
                DofOwner::Point { point } => {
                    point_shares[point] += e;
                    let vertical = u.z * p.z / total;
                    point_dirs[point][4] += vertical;
                    point_dirs[point][5] += e - vertical;
                }
                DofOwner::BodyTranslation { body } | DofOwner::BodyRotation { body } => {
                    body_shares[body] += e;
                    // Split along the body's own axes: R ᵀu · Rᵀp per axis.
                    let r = &orientations[body];
                    let (ub, pb) = (r.transpose() * u, r.transpose() * p);
                    let first = match owner {
                        DofOwner::BodyTranslation { .. } => 6,
                        _ => 9,
                    };
                    for i in 0..3 {
                        body_dirs[body][first + i] += ub[i] * pb[i] / total;
                    }
                }
            }
        }
        let mut owners: Vec<(ModeOwner, Real)> = line_shares
            .iter()
            .enumerate()
            .map(|(i, &s)| (ModeOwner::Line(i), s))
            .chain(
                system
                    .free_points
                    .iter()
                    .map(|&p| (ModeOwner::Point(p), point_shares[p])),
            )
            .chain(
                system
                    .free_bodies
                    .iter()
                    .map(|&b| (ModeOwner::Body(b), body_shares[b])),
            )
            .collect();
        owners.sort_by(|a, b| b.1.total_cmp(&a.1));
        let top = owners.first().map(|o| o.1).unwrap_or(0.0);
        let owners: Vec<ModeOwner> = owners
            .into_iter()
            .filter(|o| o.1 >= 0.5 * top)
            .map(|o| o.0)
            .collect();
        let mut dirs = [0.0; 12];
        for o in &owners {
            let d = match *o {
                ModeOwner::Line(l) => line_dirs[l],
                ModeOwner::Point(p) => point_dirs[p],
                ModeOwner::Body(b) => body_dirs[b],
            };
            for k in 0..12 {
                dirs[k] += d[k];
            }
        }
        let mut direction_shares: Vec<(ModeDirection, Real)> = DIRECTIONS
            .iter()
            .zip(dirs)
            .filter(|(_, s)| *s != 0.0)
            .map(|(d, s)| (*d, s))
            .collect();
        direction_shares.sort_by(|a, b| b.1.total_cmp(&a.1));
        let direction = direction_shares
            .first()
            .map(|d| d.0)
            .unwrap_or(ModeDirection::Transverse);
        let frequency = lambda.max(0.0).sqrt() / TAU;
        out.push(Mode {
            eigenvalue: lambda,
            frequency,
            period: 1.0 / frequency,
            shape,
            line_shares,
            point_shares,
            body_shares,
            direction_shares,
            label: ModeLabel {
                direction,
                owners,
                ordinal: 0,
                text: String::new(),
            },
        });
    }
    out
}

/// "first", "second", ... "tenth", then "11th", "12th", "21st", ...
pub fn ordinal_word(k: usize) -> String {
    const WORDS: [&str; 10] = [
        "first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth",
        "tenth",
    ];
    if (1..=10).contains(&k) {
        return WORDS[k - 1].to_string();
    }
    let suffix = match (k % 10, k % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{k}{suffix}")
}

fn label_ordinals(system: &System, modes: &mut [Mode]) {
    let mut seen: Vec<(ModeDirection, Vec<ModeOwner>)> = Vec::new();
    for mode in modes.iter_mut() {
        let key = (mode.label.direction, mode.label.owners.clone());
        let ordinal = seen.iter().filter(|k| **k == key).count() + 1;
        seen.push(key);
        let names = |kind: &str, plural: &str, list: Vec<&str>| -> Option<String> {
            match list.len() {
                0 => None,
                1 => Some(format!("{kind} {}", list[0])),
                k => Some(format!(
                    "{plural} {} and {}",
                    list[..k - 1].join(", "),
                    list[k - 1]
                )),
            }
        };
        let lines: Vec<&str> = mode
            .label
            .owners
            .iter()
            .filter_map(|o| match o {
                ModeOwner::Line(l) => Some(system.lines[*l].name.as_str()),
                _ => None,
            })
            .collect();
        let points: Vec<&str> = mode
            .label
            .owners
            .iter()
            .filter_map(|o| match o {
                ModeOwner::Point(p) => Some(system.points[*p].name.as_str()),
                _ => None,
            })
            .collect();
        let bodies: Vec<&str> = mode
            .label
            .owners
            .iter()
            .filter_map(|o| match o {
                ModeOwner::Body(b) => Some(system.bodies[*b].body.name.as_str()),
                _ => None,
            })
            .collect();
        let whom: Vec<String> = [
            names("body", "bodies", bodies),
            names("line", "lines", lines),
            names("point", "points", points),
        ]
        .into_iter()
        .flatten()
        .collect();
        mode.label.ordinal = ordinal;
        mode.label.text = format!(
            "{} {} mode of {}",
            ordinal_word(ordinal),
            mode.label.direction.name(),
            whom.join(" and ")
        );
    }
}
