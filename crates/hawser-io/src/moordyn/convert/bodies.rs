//! BODIES: MoorDyn's 6-DOF bodies into `[[bodies]]`, and the mass and volume of the points
//! fixed on them (`Body#` points) folded into the free ones.
//!
//! MoorDyn-C 2.7's body (`Body::setup`, `Body::doRHS`) in hawser's terms:
//!
//! - weight −M g at the centre of gravity `CG`, buoyancy ρ V g at the same point, whatever
//!   the depth: a `submerged` displacement with `centre_of_buoyancy` = `CG`;
//! - added mass ρ V Ca_i along the body's x, y, z (none in rotation) and drag
//!   ½ ρ R diag(CdA) Rᵀ v |v| (v the velocity of the body origin relative to the water, |v| its
//!   magnitude; the rotations likewise on ω): `added_mass`, `quadratic_drag`,
//!   `drag_speed = "magnitude"` and `hydrodynamic_centre` at the origin;
//! - the orientation R = R_x(r0) R_y(p0) R_z(y0) (`Euler2Quat`), which hawser's
//!   [roll, pitch, yaw] with R = R_z R_y R_x give after conversion;
//! - a point on a body adds its mass and its buoyancy ρ V g at its place.

use super::{Converter, VesselFile, rigid_motion_spec, spanned};
use crate::moordyn::deck::{Section, Token};
use crate::scenario::schema::*;
use crate::scenario::tables::parse_number;
use hawser::math::{Mat3, Quat, Vec3};
use std::ops::Range;
use toml::Spanned;

/// The columns of MoorDyn-C 2.7's BODIES table.
pub(super) const BODY_COLUMNS: &[&str] = &[
    "ID",
    "Attachment",
    "X0",
    "Y0",
    "Z0",
    "r0",
    "p0",
    "y0",
    "Mass",
    "CG",
    "I",
    "Volume",
    "CdA",
    "Ca",
];

const S: &str = "BODIES";

/// How a deck body moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum DeckBodyKind {
    /// `Free`: six degrees of freedom.
    Free,
    /// `Fixed`, `Fix`, `Anchor`.
    Fixed,
    /// `Coupled`, `Vessel`, `Ves`, `Cpld`: moved by the host program.
    Coupled,
    /// `CoupledPinned`, `VesselPinned`, `VesPin`, `CpldPin`: its origin moved by the host
    /// program (three translations), its rotations free (MoorDyn's `CPLDPIN`).
    CoupledPinned,
    /// A rod's `Pinned` (`Pin`): its end A held where it is, its rotations free.
    Pinned,
    /// A rod's `Body#Pinned`: its end A on a point of body `B#`, its rotations free.
    PinnedToBody,
}

impl DeckBodyKind {
    /// The pin of a pinned body: fixed (a rod's `Pinned`), coupled (`CoupledPinned`), or on
    /// the vessel's motion (`CoupledPinned` with `--vessel-motion`); `None` for other kinds.
    pub(super) fn pin(self, on_motion: bool) -> Option<PinSpec> {
        match self {
            DeckBodyKind::Pinned => Some(PinSpec::Fixed),
            DeckBodyKind::PinnedToBody => Some(PinSpec::Body),
            DeckBodyKind::CoupledPinned if on_motion => Some(PinSpec::Prescribed),
            DeckBodyKind::CoupledPinned => Some(PinSpec::Coupled),
            _ => None,
        }
    }

    /// Whether the body moves under its own loads (in some degrees of freedom): a free or a
    /// pinned body, whose mass, inertia, volume and hydrodynamics count (MoorDyn keeps them
    /// for `FREE` and `CPLDPIN` bodies and zeroes them for the others).
    pub(super) fn moves(self) -> bool {
        matches!(
            self,
            DeckBodyKind::Free
                | DeckBodyKind::CoupledPinned
                | DeckBodyKind::Pinned
                | DeckBodyKind::PinnedToBody
        )
    }
}

/// A body of the scenario with its name, kind, motion and pose, and no mass, hydrodynamics or
/// members yet (the deck's body and rod rows fill them in).
pub(super) fn bare_body(
    name: Spanned<String>,
    kind: Spanned<BodyKindSpec>,
    motion: Option<MotionSpec>,
    position: Option<Spanned<[f64; 3]>>,
    orientation: Option<Spanned<[f64; 3]>>,
) -> BodySpec {
    BodySpec {
        name,
        kind,
        pin: None,
        pin_body: None,
        pin_point: None,
        motion,
        position,
        orientation,
        mass: None,
        centre_of_gravity: None,
        inertia: None,
        displacement: None,
        centre_of_buoyancy: None,
        added_mass: None,
        linear_drag: None,
        quadratic_drag: None,
        drag_coefficients: None,
        drag_areas: None,
        drag_speed: None,
        hydrodynamic_centre: None,
        members: Vec::new(),
        thrust: None,
        wind: None,
    }
}

/// A body's name in the scenario: `B` and its MoorDyn ID.
pub(super) fn body_name(id: &str) -> String {
    format!("B{id}")
}

/// A rigid part folded into a free body: a point's mass and volume, a rod's mass and
/// inertia, or the body's own.
pub(super) struct Part {
    /// Its centre of gravity, and of its volume, in body axes [m].
    pub centre: Vec3,
    /// Mass [kg].
    pub mass: f64,
    /// Inertia about its centre of gravity in body axes [kg·m²].
    pub inertia: Mat3,
    /// Displaced volume [m³] (always submerged, as MoorDyn's bodies and points).
    pub volume: f64,
}

/// A deck body (from BODIES, or a rod that is a body of its own), before the points and
/// rods on it are folded into it.
pub(super) struct DeckBody {
    /// Scenario name (`B1`, `R2`).
    pub name: String,
    /// How it moves.
    pub kind: DeckBodyKind,
    /// The scenario body (mass, inertia and displacement of a free body filled in by
    /// [`finish_bodies`]).
    pub spec: BodySpec,
    /// The deck's word for its type.
    pub type_word: String,
    /// Deck line of its row.
    pub line: usize,
    /// Spans of the deck words for its mass, centre of gravity, inertia and volume.
    pub spans: [Range<usize>; 4],
    /// Its own mass and volume, and those folded in.
    pub parts: Vec<Part>,
}

impl DeckBody {
    /// The deck's word for its type (`Coupled`, `Fixed`, …).
    pub(super) fn type_word(&self) -> &str {
        &self.type_word
    }

    /// Adds a rigid part (a point's mass and volume, a rod's mass and inertia) to a free body.
    pub(super) fn fold(&mut self, part: Part) {
        self.parts.push(part);
    }
}

/// Numbers separated by `|` in one cell (MoorDyn's `CG`, `I`, `CdA`, `Ca`): one of the
/// counts in `counts`, or an error naming the column.
fn numbers(
    c: &mut Converter,
    t: &Token,
    id: &str,
    column: &str,
    counts: &[usize],
    unit: &str,
) -> Option<Vec<f64>> {
    let parts: Vec<Option<f64>> = t.text.split('|').map(parse_number).collect();
    if parts.iter().all(Option::is_some) && counts.contains(&parts.len()) {
        return Some(parts.into_iter().flatten().collect());
    }
    let forms: Vec<String> = counts.iter().map(|n| n.to_string()).collect();
    let forms = match forms.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => forms.join(""),
    };
    let d = c
        .diag(
            Some(t.span.clone()),
            &format!("{S} › {id} › {column}"),
            format!("`{column}` of body {id} is not {forms} numbers separated by `|`"),
        )
        .value(t.text.clone())
        .expected(format!("{forms} numbers in {unit}, e.g. 0|0|-5"))
        .hint("MoorDyn gives several values in one column separated by `|` without spaces");
    c.errors.push(d);
    None
}

/// MoorDyn's orientation R = R_x(r) R_y(p) R_z(y) (degrees) as hawser's [roll, pitch, yaw]
/// in degrees with R = R_z(yaw) R_y(pitch) R_x(roll).
pub(super) fn hawser_angles(moordyn: [f64; 3]) -> [f64; 3] {
    let [r, p, y] = moordyn.map(f64::to_radians);
    let q = Quat::from_axis_angle(&Vec3::x_axis(), r)
        * Quat::from_axis_angle(&Vec3::y_axis(), p)
        * Quat::from_axis_angle(&Vec3::z_axis(), y);
    let (roll, pitch, yaw) = q.euler_angles();
    [roll, pitch, yaw].map(f64::to_degrees)
}

/// BODIES rows into deck bodies; `rho` is the water density [kg/m³] (the added mass ρ V Ca).
pub(super) fn convert_bodies(
    c: &mut Converter,
    s: &Section,
    rho: f64,
    vessel: Option<&VesselFile>,
) -> Vec<DeckBody> {
    let mut out: Vec<DeckBody> = Vec::new();
    for row in &s.rows {
        if !c.check_columns(S, row, BODY_COLUMNS, BODY_COLUMNS.len()) {
            continue;
        }
        let t = &row.tokens;
        let id = t[0].text.clone();
        let i = out.len();
        let key = |f: &str| format!("bodies[{i}].{f}");
        for (field, col) in [
            ("name", "ID"),
            ("type", "Attachment"),
            ("position", "X0 Y0 Z0"),
            ("orientation", "r0 p0 y0"),
            ("mass", "Mass"),
            ("centre_of_gravity", "CG"),
            ("inertia", "I"),
            ("displacement", "Volume"),
            ("centre_of_buoyancy", "CG"),
            ("added_mass", "Ca"),
            ("quadratic_drag", "CdA"),
            ("motion", "Attachment"),
        ] {
            c.name_key(key(field), format!("{S} › {id} › {col}"));
        }
        if out.iter().any(|b| b.name == body_name(&id)) {
            let d = c
                .diag(
                    Some(t[0].span.clone()),
                    &format!("{S} › {id} › ID"),
                    format!("body {id} is defined twice"),
                )
                .hint("give each body its own ID (MoorDyn numbers them 1, 2, 3, …)");
            c.errors.push(d);
        }
        let word = t[1].text.to_lowercase();
        let base = word.trim_end_matches(|ch: char| ch.is_ascii_digit());
        let kind = match base {
            "free" => Some(DeckBodyKind::Free),
            "fixed" | "fix" | "anchor" => Some(DeckBodyKind::Fixed),
            "coupled" | "vessel" | "ves" | "cpld" => Some(DeckBodyKind::Coupled),
            "coupledpinned" | "vesselpinned" | "vespin" | "cpldpin" => {
                Some(DeckBodyKind::CoupledPinned)
            }
            _ => {
                let d = c
                    .diag(
                        Some(t[1].span.clone()),
                        &format!("{S} › {id} › Attachment"),
                        format!("unknown body type `{}`", t[1].text),
                    )
                    .expected(
                        "Free, Fixed (Fix, Anchor), Coupled (Vessel, Ves, Cpld) or \
                         CoupledPinned (VesselPinned, VesPin, CpldPin)",
                    )
                    .hint(
                        "MoorDyn body types: Free (moves under its loads), Fixed (held), \
                         Coupled (moved by the host program), CoupledPinned (its origin moved \
                         by the host, turning freely)",
                    );
                c.errors.push(d);
                None
            }
        };
        let row_key = format!("{S} › {id}");
        let num = |c: &mut Converter, k: usize, col: &str, unit: &str| {
            c.number(&t[k], &row_key, col, unit).unwrap_or(0.0)
        };
        let position = [
            num(c, 2, "X0", "m"),
            num(c, 3, "Y0", "m"),
            num(c, 4, "Z0", "m"),
        ];
        let angles = [
            num(c, 5, "r0", "deg"),
            num(c, 6, "p0", "deg"),
            num(c, 7, "y0", "deg"),
        ];
        let mass = num(c, 8, "Mass", "kg");
        let volume = num(c, 11, "Volume", "m³");
        let cg = numbers(c, &t[9], &id, "CG", &[1, 3], "m").map(|v| match v.len() {
            1 => Vec3::new(0.0, 0.0, v[0]),
            _ => Vec3::new(v[0], v[1], v[2]),
        });
        let inertia = numbers(c, &t[10], &id, "I", &[1, 3], "kg·m²").map(|v| match v.len() {
            1 => Vec3::repeat(v[0]),
            _ => Vec3::new(v[0], v[1], v[2]),
        });
        let cda = numbers(c, &t[12], &id, "CdA", &[1, 2, 3, 6], "m²").map(|v| match v.len() {
            1 => [v[0]; 6],
            2 => [v[0], v[0], v[0], v[1], v[1], v[1]],
            3 => [v[0], v[1], v[2], v[0], v[1], v[2]],
            _ => [v[0], v[1], v[2], v[3], v[4], v[5]],
        });
        let ca = numbers(c, &t[13], &id, "Ca", &[1, 3], "-").map(|v| match v.len() {
            1 => [v[0]; 3],
            _ => [v[0], v[1], v[2]],
        });
        let Some(kind) = kind else { continue };
        if t[12].text.split('|').count() >= 3 {
            c.note(
                row.line,
                format!(
                    "body {id}: CdA `{}` is read as MoorDyn's documentation gives it (x, y, z \
                     and the rotations about them); MoorDyn 2.7.2's reader drops the first of 3 \
                     or 6 values (its surge and roll drag are zero)",
                    t[12].text
                ),
            );
        }
        let rotated = hawser_angles(angles);
        if angles.iter().filter(|a| **a != 0.0).count() > 1 {
            c.note(
                row.line,
                format!(
                    "body {id}: MoorDyn's orientation r0 p0 y0 = {} {} {} deg (R = R_x R_y R_z) \
                     is hawser's [roll, pitch, yaw] = [{:.6}, {:.6}, {:.6}] deg (R = R_z R_y R_x)",
                    t[5].text, t[6].text, t[7].text, rotated[0], rotated[1], rotated[2]
                ),
            );
        }
        let pose_span = t[2].span.start..t[7].span.end;
        let position = Spanned::new(t[2].span.start..t[4].span.end, position);
        let orientation = Spanned::new(t[5].span.start..t[7].span.end, rotated);
        let (cg, inertia) = (cg.unwrap_or_default(), inertia.unwrap_or_default());
        let (cda, ca) = (cda.unwrap_or_default(), ca.unwrap_or_default());
        let free = kind.moves();
        if !free
            && (mass != 0.0
                || volume != 0.0
                || inertia != Vec3::zeros()
                || cda.iter().chain(&ca).any(|x| *x != 0.0))
        {
            c.note(
                row.line,
                format!(
                    "body {id}: Mass, CG, I, Volume, CdA and Ca have no effect on a `{}` body \
                     (its motion is given; MoorDyn zeroes them too)",
                    t[1].text
                ),
            );
        }
        let kind_word = Token {
            text: String::new(),
            span: t[1].span.clone(),
        };
        let (spec_kind, motion) = match kind {
            DeckBodyKind::Free => (BodyKindSpec::Free, None),
            DeckBodyKind::Fixed => (BodyKindSpec::Fixed, None),
            DeckBodyKind::Pinned | DeckBodyKind::PinnedToBody => (BodyKindSpec::Pinned, None),
            DeckBodyKind::CoupledPinned => match vessel {
                None => (BodyKindSpec::Pinned, None),
                Some(v) => {
                    if position.get_ref().iter().any(|x| *x != 0.0) {
                        let d = c
                            .diag(
                                Some(pose_span.clone()),
                                &format!("{S} › {id} › X0"),
                                format!(
                                    "coupled pinned body {id} is not at the vessel origin, so \
                                     `--vessel-motion` cannot move its pin"
                                ),
                            )
                            .expected("X0 Y0 Z0 = 0 0 0")
                            .hint(
                                "the vessel-motion file gives the track of the pin, the body's \
                                 origin: put the body's origin at the vessel's, or run without \
                                 --vessel-motion to hold the pin at its deck position",
                            );
                        c.errors.push(d);
                    }
                    (
                        BodyKindSpec::Pinned,
                        Some(rigid_motion_spec(&kind_word, Some(v))),
                    )
                }
            },
            DeckBodyKind::Coupled => match vessel {
                None => (BodyKindSpec::Coupled, None),
                Some(v) => {
                    if position.get_ref().iter().chain(&angles).any(|x| *x != 0.0) {
                        let d = c
                            .diag(
                                Some(pose_span.clone()),
                                &format!("{S} › {id} › X0"),
                                format!(
                                    "coupled body {id} is not at the vessel origin, so \
                                     `--vessel-motion` cannot move it"
                                ),
                            )
                            .expected("X0 Y0 Z0 r0 p0 y0 = 0 0 0 0 0 0")
                            .hint(
                                "the vessel-motion file gives the pose of a coupled body's \
                                 origin: put the body's origin at the vessel's (its points \
                                 keep their places on the body), or run without \
                                 --vessel-motion to hold it at its deck pose",
                            );
                        c.errors.push(d);
                    }
                    (
                        BodyKindSpec::Prescribed,
                        Some(rigid_motion_spec(&kind_word, Some(v))),
                    )
                }
            },
        };
        let prescribed = spec_kind == BodyKindSpec::Prescribed;
        // A pin on the vessel's motion takes its position from it; the body keeps its angles.
        let on_motion = motion.is_some();
        let mut spec = bare_body(
            spanned(&t[0], body_name(&id)),
            spanned(&t[1], spec_kind),
            motion,
            (!on_motion).then_some(position),
            (!prescribed && rotated != [0.0; 3]).then_some(orientation),
        );
        spec.pin = kind.pin(on_motion).map(|p| spanned(&t[1], p));
        let mut body = DeckBody {
            name: body_name(&id),
            kind,
            spec,
            type_word: t[1].text.clone(),
            line: row.line,
            spans: [
                t[8].span.clone(),
                t[9].span.clone(),
                t[10].span.clone(),
                t[11].span.clone(),
            ],
            parts: vec![Part {
                centre: cg,
                mass,
                inertia: Mat3::from_diagonal(&inertia),
                volume,
            }],
        };
        if free {
            body.spec.quadratic_drag = Some(spanned(&t[12], cda));
            body.spec.drag_speed = Some(spanned(&t[12], DragSpeedSpec::Magnitude));
            body.spec.added_mass = Some(spanned(
                &t[13],
                [
                    rho * volume * ca[0],
                    rho * volume * ca[1],
                    rho * volume * ca[2],
                    0.0,
                    0.0,
                    0.0,
                ],
            ));
        }
        out.push(body);
    }
    out
}

/// The scenario bodies, with the parts on each free body folded in: total mass, centre of
/// gravity, inertia about it (parallel axes; a full tensor when the parts are off the principal
/// axes), total volume and its centre.
pub(super) fn finish_bodies(c: &mut Converter, bodies: Vec<DeckBody>) -> Vec<BodySpec> {
    let mut out = Vec::new();
    for b in bodies {
        let mut spec = b.spec;
        if !b.kind.moves() {
            out.push(spec);
            continue;
        }
        let parts = &b.parts;
        let mass: f64 = parts.iter().map(|p| p.mass).sum();
        let cg = if mass > 0.0 {
            parts.iter().map(|p| p.centre * p.mass).sum::<Vec3>() / mass
        } else {
            parts[0].centre
        };
        // Each part's inertia about its own centre of gravity plus m (|d|² 1 − d dᵀ).
        let inertia = parts
            .iter()
            .map(|p| {
                let d = p.centre - cg;
                p.inertia + p.mass * (Mat3::identity() * d.norm_squared() - d * d.transpose())
            })
            .sum::<Mat3>();
        let volume: f64 = parts.iter().map(|p| p.volume).sum();
        let centre_of_buoyancy = if volume > 0.0 {
            parts.iter().map(|p| p.centre * p.volume).sum::<Vec3>() / volume
        } else {
            parts[0].centre
        };
        if parts[1..].iter().any(|p| p.mass != 0.0 || p.volume != 0.0) {
            c.note(
                b.line,
                format!(
                    "body {}: the mass and volume of the points and rods on it are part of the \
                     body: {mass} kg with its centre of gravity at [{}, {}, {}] m, {volume} m³ \
                     centred at [{}, {}, {}] m (MoorDyn adds them to the body's loads the same way)",
                    b.name,
                    cg.x,
                    cg.y,
                    cg.z,
                    centre_of_buoyancy.x,
                    centre_of_buoyancy.y,
                    centre_of_buoyancy.z
                ),
            );
        }
        let [mass_span, cg_span, inertia_span, volume_span] = b.spans;
        let off_diagonal = (0..3).any(|i| (0..3).any(|j| i != j && inertia[(i, j)] != 0.0));
        spec.mass = Some(Spanned::new(mass_span, mass));
        spec.centre_of_gravity =
            (cg != Vec3::zeros()).then(|| Spanned::new(cg_span.clone(), cg.into()));
        spec.inertia = Some(Spanned::new(
            inertia_span,
            if off_diagonal {
                InertiaSpec::Matrix(std::array::from_fn(|i| {
                    std::array::from_fn(|j| inertia[(i, j)])
                }))
            } else {
                InertiaSpec::Principal([inertia[(0, 0)], inertia[(1, 1)], inertia[(2, 2)]])
            },
        ));
        if volume > 0.0 {
            spec.displacement = Some(DisplacementSpec {
                kind: Spanned::new(volume_span.clone(), DisplacementKind::Submerged),
                volume: Some(Spanned::new(volume_span.clone(), volume)),
                radius: None,
                height: None,
                length: None,
                breadth: None,
            });
            spec.centre_of_buoyancy = (centre_of_buoyancy != Vec3::zeros())
                .then(|| Spanned::new(cg_span.clone(), centre_of_buoyancy.into()));
            // Added mass and drag at the body origin, buoyancy at its centre.
            spec.hydrodynamic_centre =
                (centre_of_buoyancy != Vec3::zeros()).then(|| Spanned::new(volume_span, [0.0; 3]));
        }
        out.push(spec);
    }
    out
}
