//! ROD TYPES and RODS: MoorDyn's rigid rods as members of hawser bodies
//! (`[[bodies.members]]`, [`hawser::model::Member`]).
//!
//! A rod is a rigid cylinder with MoorDyn's lumped hydrodynamics (side drag and added mass,
//! drag and added mass of its wet ends, buoyancy, seabed contact), which a member reproduces.
//! Its type decides the body it is a member of:
//!
//! - `Free` (`Point`, `Con`): a free body `R#` of its own, its origin at end A, its axes the
//!   global axes at t = 0, with the rod's mass w·L at mid-length and the inertia of a solid
//!   cylinder (MoorDyn's lumped nodes with its inertia correction give exactly that);
//! - `Fixed` (`Fix`, `Anchor`): a fixed body `R#`; `Coupled` (`Vessel`, `Ves`, `Cpld`): a
//!   coupled body `R#` (or a prescribed one on `--vessel-motion`);
//! - `Body#`: a member of body `B#` (coordinates in its axes), its mass and inertia folded in;
//! - `Pinned` (`Pin`): a pinned body `R#` (origin and pin at end A, held where it is, turning
//!   freely), mass and inertia as for `Free`; `CoupledPinned` (`VesselPinned`, `VesPin`,
//!   `CpldPin`): the same on a coupled pin (three translations set by the host), or on
//!   `--vessel-motion`;
//! - `Body#Pinned`: a body `R#` pinned to body `B#` (`pin = "body"`): its origin and pin at
//!   end A, the point (Xa, Ya, Za) of `B#` in `B#`'s axes, its axes `B#`'s at t = 0, turning
//!   freely about the pin while `B#` carries the pin's force; mass and inertia as for `Free`;
//! - `NumSegs` 0 (MoorDyn's zero-length rod, a joint that passes bending between lines):
//!   refused.
//!
//! Lines attach to `R#A` and `R#B`: points of those names on the rod's body at its ends.

use super::bodies::{DeckBody, DeckBodyKind, Part, bare_body, body_name};
use super::{Converter, VesselFile, rigid_motion_spec, spanned};
use crate::moordyn::deck::{Section, Token};
use crate::scenario::schema::*;
use hawser::math::{Mat3, Vec3};
use std::collections::HashMap;
use toml::Spanned;

/// The columns of MoorDyn-C 2.7's ROD TYPES table.
pub(super) const ROD_TYPE_COLUMNS: &[&str] =
    &["TypeName", "Diam", "Mass/m", "Cd", "Ca", "CdEnd", "CaEnd"];

/// The columns of MoorDyn-C 2.7's RODS table.
pub(super) const ROD_COLUMNS: &[&str] = &[
    "ID",
    "RodType",
    "Attachment",
    "Xa",
    "Ya",
    "Za",
    "Xb",
    "Yb",
    "Zb",
    "NumSegs",
    "RodOutputs",
];

/// A rod type: diameter [m], mass per length [kg/m], Cd, Ca, CdEnd, CaEnd, and the row's
/// tokens (for spans).
pub(super) struct RodType {
    values: [f64; 6],
    tokens: Vec<Token>,
}

/// ROD TYPES rows by name.
pub(super) fn convert_rod_types(c: &mut Converter, s: &Section) -> HashMap<String, RodType> {
    const S: &str = "ROD TYPES";
    let mut out = HashMap::new();
    for row in &s.rows {
        if !c.check_columns(S, row, ROD_TYPE_COLUMNS, ROD_TYPE_COLUMNS.len()) {
            continue;
        }
        let t = &row.tokens;
        let key = format!("{S} › {}", t[0].text);
        let units = ["m", "kg/m", "-", "-", "-", "-"];
        let mut values = [0.0; 6];
        for (j, v) in values.iter_mut().enumerate() {
            *v = c
                .number(&t[j + 1], &key, ROD_TYPE_COLUMNS[j + 1], units[j])
                .unwrap_or(0.0);
        }
        out.insert(
            t[0].text.clone(),
            RodType {
                values,
                tokens: t.clone(),
            },
        );
    }
    out
}

/// A rod's name as a body of its own: `R` and its MoorDyn ID.
pub(super) fn rod_name(id: &str) -> String {
    format!("R{id}")
}

/// The rods of a deck: the points at their ends (`R#A`, `R#B`), and the names of the ends of
/// rods refused with an error (so that the lines on them add no second error).
#[derive(Default)]
pub(super) struct RodEnds {
    /// Points at the ends of the rods converted.
    pub points: Vec<PointSpec>,
    /// `R#A`, `R#B` of the rods refused.
    pub refused: Vec<String>,
}

/// RODS rows: new bodies for free, fixed and coupled rods, members (and folded mass) of the
/// bodies others are on.
pub(super) fn convert_rods(
    c: &mut Converter,
    s: &Section,
    types: &HashMap<String, RodType>,
    bodies: &mut Vec<DeckBody>,
    vessel: Option<&VesselFile>,
) -> RodEnds {
    const S: &str = "RODS";
    let mut out = RodEnds::default();
    for row in &s.rows {
        if !c.check_columns(S, row, ROD_COLUMNS, ROD_COLUMNS.len() - 1) {
            continue;
        }
        let t = &row.tokens;
        let id = t[0].text.clone();
        let errors = c.errors.len();
        let done = convert_rod(c, t, row.line, types, bodies, vessel, &mut out.points);
        if !done || c.errors.len() > errors {
            out.refused
                .extend(["A", "B"].map(|e| format!("{}{e}", rod_name(&id))));
        }
    }
    out
}

/// One RODS row; false when it is refused.
#[allow(clippy::too_many_arguments)]
fn convert_rod(
    c: &mut Converter,
    t: &[Token],
    line: usize,
    types: &HashMap<String, RodType>,
    bodies: &mut Vec<DeckBody>,
    vessel: Option<&VesselFile>,
    points: &mut Vec<PointSpec>,
) -> bool {
    const S: &str = "RODS";
    {
        let id = t[0].text.clone();
        let key = format!("{S} › {id}");
        let Some(rod_type) = types.get(&t[1].text) else {
            let known: Vec<&str> = types.keys().map(String::as_str).collect();
            let d = c
                .diag(
                    Some(t[1].span.clone()),
                    &format!("{key} › RodType"),
                    format!("rod {id} has the unknown rod type `{}`", t[1].text),
                )
                .expected(if known.is_empty() {
                    "a ROD TYPES section naming it".to_string()
                } else {
                    format!("one of: {}", known.join(", "))
                })
                .hint("rod types are the TypeName column of ROD TYPES");
            c.errors.push(d);
            return false;
        };
        let coordinate =
            |c: &mut Converter, k: usize| c.number(&t[k], &key, ROD_COLUMNS[k], "m").unwrap_or(0.0);
        let a = Vec3::new(coordinate(c, 3), coordinate(c, 4), coordinate(c, 5));
        let b = Vec3::new(coordinate(c, 6), coordinate(c, 7), coordinate(c, 8));
        let segments = c.count(&t[9], &key, "NumSegs").unwrap_or(1);
        if segments == 0 {
            let d = c
                .diag(
                    Some(t[9].span.clone()),
                    &format!("{key} › NumSegs"),
                    format!(
                        "rod {id} has no length (NumSegs 0): MoorDyn's zero-length rod is a \
                         joint that passes bending between the lines on it, which hawser does \
                         not model"
                    ),
                )
                .expected("NumSegs ≥ 1")
                .hint("join the lines at a free point (POINTS, `Free`) instead");
            c.errors.push(d);
            return false;
        }
        let length = (b - a).norm();
        if !(length > 0.0) {
            let d = c
                .diag(
                    Some(t[3].span.start..t[8].span.end),
                    &format!("{key} › Xa"),
                    format!("rod {id} has both ends at the same place"),
                )
                .expected("end B apart from end A, in m")
                .hint("Xa Ya Za and Xb Yb Zb give the rod's two ends");
            c.errors.push(d);
            return false;
        }
        if segments < 0 {
            let d = c
                .diag(
                    Some(t[9].span.clone()),
                    &format!("{key} › NumSegs"),
                    format!("rod {id} has a negative number of segments"),
                )
                .expected("NumSegs ≥ 1");
            c.errors.push(d);
            return false;
        }
        if let Some(flags) = t.get(10)
            && flags.text != "-"
            && !flags.text.is_empty()
        {
            c.note(
                line,
                format!(
                    "rod {id}: output flags `{}` are not written (no per-rod files)",
                    flags.text
                ),
            );
        }
        let [diameter, mass_per_length, cd, ca, cd_end, ca_end] = rod_type.values;
        let tt = &rod_type.tokens;
        let word = t[2].text.to_lowercase();
        // MoorDyn's decomposition: letters, a number, letters.
        let letters: String = word
            .chars()
            .take_while(|ch| ch.is_ascii_alphabetic())
            .collect();
        let rest = &word[letters.len()..];
        let number: String = rest.chars().take_while(|ch| ch.is_ascii_digit()).collect();
        let tail = &rest[number.len()..];
        // The member in the axes of the body it is on, and that body.
        let axis = (b - a) / length;
        let radius = 0.5 * diameter;
        let mass = mass_per_length * length;
        // A solid cylinder about its centre: m (L²/12 + r²/4) across the axis, m r²/2 along.
        let inertia = mass
            * (length * length / 12.0 + radius * radius / 4.0)
            * (Mat3::identity() - axis * axis.transpose())
            + 0.5 * mass * radius * radius * axis * axis.transpose();
        let member = |end_a: Vec3, end_b: Vec3| MemberSpec {
            end_a: Spanned::new(t[3].span.start..t[5].span.end, end_a.into()),
            end_b: Spanned::new(t[6].span.start..t[8].span.end, end_b.into()),
            diameter: spanned(&tt[1], diameter),
            segments: Some(spanned(&t[9], segments)),
            normal_drag: Some(spanned(&tt[3], cd)),
            normal_added_mass: Some(spanned(&tt[4], ca)),
            end_drag: Some(spanned(&tt[5], cd_end)),
            end_added_mass: Some(spanned(&tt[6], ca_end)),
        };
        let (body, offset_a) = match letters.as_str() {
            "body" => {
                let Some(i) = bodies.iter().position(|x| x.name == body_name(&number)) else {
                    let d = c
                        .diag(
                            Some(t[2].span.clone()),
                            &format!("{key} › Attachment"),
                            format!(
                                "rod {id} is on body `{}`, which is not in the BODIES table",
                                t[2].text
                            ),
                        )
                        .expected("Body# with a body ID of the BODIES table")
                        .hint("a rod on a body is `Body#`, # the body's ID in BODIES");
                    c.errors.push(d);
                    return false;
                };
                if tail.contains("pin") {
                    // A body `R#` of its own, its origin at end A on the body's point `a`, its
                    // axes the body's at t = 0, turning freely about the pin.
                    let name = rod_name(&id);
                    let parent = &bodies[i];
                    let mut spec = bare_body(
                        spanned(&t[0], name.clone()),
                        spanned(&t[2], BodyKindSpec::Pinned),
                        None,
                        None,
                        parent.spec.orientation.clone(),
                    );
                    spec.members.push(member(Vec3::zeros(), b - a));
                    spec.pin = Some(spanned(&t[2], PinSpec::Body));
                    spec.pin_body = Some(spanned(&t[2], parent.name.clone()));
                    spec.pin_point = Some(Spanned::new(t[3].span.start..t[5].span.end, a.into()));
                    let span = |k: usize| t[k].span.clone();
                    bodies.push(DeckBody {
                        name,
                        kind: DeckBodyKind::PinnedToBody,
                        spec,
                        type_word: t[2].text.clone(),
                        line,
                        spans: [tt[2].span.clone(), span(3), tt[1].span.clone(), span(3)],
                        parts: vec![Part {
                            centre: 0.5 * (b - a),
                            mass,
                            inertia,
                            volume: 0.0,
                        }],
                    });
                    (bodies.len() - 1, Vec3::zeros())
                } else {
                    let on = &mut bodies[i];
                    on.spec.members.push(member(a, b));
                    if on.kind.moves() {
                        on.fold(Part {
                            centre: 0.5 * (a + b),
                            mass,
                            inertia,
                            volume: 0.0,
                        });
                    }
                    (i, a)
                }
            }
            "free" | "point" | "con" | "fixed" | "fix" | "anchor" | "coupled" | "vessel"
            | "ves" | "cpld" | "pinned" | "pin" | "coupledpinned" | "vesselpinned" | "vespin"
            | "cpldpin" => {
                let kind = match letters.as_str() {
                    "free" | "point" | "con" => DeckBodyKind::Free,
                    "fixed" | "fix" | "anchor" => DeckBodyKind::Fixed,
                    "pinned" | "pin" => DeckBodyKind::Pinned,
                    "coupled" | "vessel" | "ves" | "cpld" => DeckBodyKind::Coupled,
                    _ => DeckBodyKind::CoupledPinned,
                };
                let (spec_kind, motion) = match (kind, vessel) {
                    (DeckBodyKind::Free, _) => (BodyKindSpec::Free, None),
                    (DeckBodyKind::Fixed, _) => (BodyKindSpec::Fixed, None),
                    (DeckBodyKind::Pinned | DeckBodyKind::PinnedToBody, _)
                    | (DeckBodyKind::CoupledPinned, None) => (BodyKindSpec::Pinned, None),
                    (DeckBodyKind::Coupled, None) => (BodyKindSpec::Coupled, None),
                    (DeckBodyKind::Coupled | DeckBodyKind::CoupledPinned, Some(v)) => {
                        if a != Vec3::zeros() {
                            let d = c
                                .diag(
                                    Some(t[3].span.start..t[5].span.end),
                                    &format!("{key} › Xa"),
                                    format!(
                                        "coupled rod {id} does not start at the vessel origin, \
                                         so `--vessel-motion` cannot move it"
                                    ),
                                )
                                .expected("Xa Ya Za = 0 0 0")
                                .hint(
                                    "the vessel-motion file gives the pose of the rod's end A; \
                                     run without --vessel-motion to hold it in place",
                                );
                            c.errors.push(d);
                        }
                        let word = Token {
                            text: String::new(),
                            span: t[2].span.clone(),
                        };
                        let kind = if kind == DeckBodyKind::Coupled {
                            BodyKindSpec::Prescribed
                        } else {
                            BodyKindSpec::Pinned
                        };
                        (kind, Some(rigid_motion_spec(&word, Some(v))))
                    }
                };
                // A prescribed rod, or a pin on the vessel, takes its end A from the motion.
                let prescribed = motion.is_some();
                let name = rod_name(&id);
                let pose = Spanned::new(t[3].span.start..t[5].span.end, a.into());
                let mut spec = bare_body(
                    spanned(&t[0], name.clone()),
                    spanned(&t[2], spec_kind),
                    motion,
                    (!prescribed).then_some(pose),
                    None,
                );
                spec.members.push(member(Vec3::zeros(), b - a));
                spec.pin = kind.pin(prescribed).map(|p| spanned(&t[2], p));
                let span = |k: usize| t[k].span.clone();
                bodies.push(DeckBody {
                    name,
                    kind,
                    spec,
                    type_word: t[2].text.clone(),
                    line,
                    spans: [tt[2].span.clone(), span(3), tt[1].span.clone(), span(3)],
                    parts: vec![Part {
                        centre: 0.5 * (b - a),
                        mass: if kind.moves() { mass } else { 0.0 },
                        inertia: if kind.moves() { inertia } else { Mat3::zeros() },
                        volume: 0.0,
                    }],
                });
                (bodies.len() - 1, Vec3::zeros())
            }
            _ => {
                let d = c
                    .diag(
                        Some(t[2].span.clone()),
                        &format!("{key} › Attachment"),
                        format!("unknown rod attachment `{}`", t[2].text),
                    )
                    .expected(
                        "Free (Point, Con), Fixed (Fix, Anchor), Coupled (Vessel), Pinned \
                         (Pin), CoupledPinned (VesselPinned), Body#",
                    )
                    .hint(
                        "MoorDyn rod types: Free, Fixed, Coupled, Pinned, CoupledPinned (pinned \
                         at end A), Body# (fixed on a body)",
                    );
                c.errors.push(d);
                return false;
            }
        };
        let on = bodies[body].name.clone();
        for (end, offset) in [("A", offset_a), ("B", offset_a + (b - a))] {
            points.push(PointSpec {
                name: spanned(&t[0], format!("{}{end}", rod_name(&id))),
                kind: spanned(&t[2], PointKindSpec::Body),
                position: Some(Spanned::new(t[3].span.start..t[8].span.end, offset.into())),
                mass: None,
                volume: None,
                drag_area: None,
                added_mass_coefficient: None,
                force: None,
                motion: None,
                body: Some(spanned(&t[2], on.clone())),
            });
        }
    }
    true
}
