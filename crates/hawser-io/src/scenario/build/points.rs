//! `[[points]]`: fixed, prescribed and free points, checked and converted into
//! [`hawser::model::Point`].

use super::build_motion;
use super::{Builder, Check, NON_NEGATIVE, span_of};
use crate::scenario::diagnostics::closest;
use crate::scenario::schema::*;
use hawser::math::Vec3;
use hawser::model::*;
use hawser::physics::environment::Environment;
use hawser::physics::seabed::Bathymetry;
use std::collections::HashMap;

pub(super) fn build_points(
    b: &mut Builder,
    specs: &[PointSpec],
    env: &Environment,
    body_names: &[String],
) -> (Vec<Point>, HashMap<String, usize>) {
    let mut out = Vec::new();
    let mut index = HashMap::new();
    for (i, p) in specs.iter().enumerate() {
        let k = |key: &str| format!("points[{i}].{key}");
        let name = p.name.get_ref().clone();
        if let Some(first) = index.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(p.name.span()),
                    &k("name"),
                    format!("point `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each point its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&p.name, &k("name"), "point", "buoy.z");
        let kind = *p.kind.get_ref();
        let kind_name = match kind {
            PointKindSpec::Fixed => "a fixed point",
            PointKindSpec::Free => "a free point",
            PointKindSpec::Prescribed => "a prescribed point",
            PointKindSpec::Body => "a point on a body",
            PointKindSpec::Coupled => "a coupled point",
        };
        if kind != PointKindSpec::Body
            && let Some(body) = &p.body
        {
            b.not_for(
                true,
                Some(body.span()),
                &k("body"),
                kind_name,
                "points on bodies (`type = \"body\"`)",
            );
        }
        let position = p.position.as_ref().map(|v| b.vec3(v, &k("position")));
        if kind != PointKindSpec::Free {
            for (present, span, key) in [
                (p.mass.is_some(), span_of(&p.mass), "mass"),
                (p.volume.is_some(), span_of(&p.volume), "volume"),
                (p.drag_area.is_some(), span_of(&p.drag_area), "drag_area"),
                (
                    p.added_mass_coefficient.is_some(),
                    span_of(&p.added_mass_coefficient),
                    "added_mass_coefficient",
                ),
                (p.force.is_some(), span_of(&p.force), "force"),
            ] {
                b.not_for(
                    present,
                    span,
                    &k(key),
                    kind_name,
                    "free points (`type = \"free\"`)",
                );
            }
        }
        if kind != PointKindSpec::Prescribed && p.motion.is_some() {
            let span = p.motion.as_ref().map(|m| m.kind.span());
            b.not_for(
                true,
                span,
                &k("motion"),
                kind_name,
                "prescribed points (`type = \"prescribed\"`)",
            );
        }
        let point_kind = match kind {
            PointKindSpec::Fixed => PointKind::Fixed,
            PointKindSpec::Coupled => PointKind::Coupled,
            PointKindSpec::Free => PointKind::Free {
                mass: b.opt(
                    &p.mass,
                    &k("mass"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "kg, ≥ 0",
                    },
                    "the point's mass in air",
                ),
                volume: b.opt(
                    &p.volume,
                    &k("volume"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "m³, ≥ 0",
                    },
                    "displaced volume; buoyancy is ρ g V",
                ),
                drag_area: b.opt(
                    &p.drag_area,
                    &k("drag_area"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "m², ≥ 0 (C_d × area)",
                    },
                    "e.g. 0.5 × π r² for a sphere",
                ),
                added_mass_coefficient: b.opt(
                    &p.added_mass_coefficient,
                    &k("added_mass_coefficient"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0",
                    },
                    "0.5 for a sphere",
                ),
                force: p
                    .force
                    .as_ref()
                    .map(|f| b.vec3(f, &k("force")))
                    .unwrap_or_else(Vec3::zeros),
            },
            PointKindSpec::Body => {
                let body = match &p.body {
                    Some(name) => match body_names.iter().position(|n| n == name.get_ref()) {
                        Some(i) => i,
                        None => {
                            let hint = match closest(
                                name.get_ref(),
                                body_names.iter().map(String::as_str),
                            ) {
                                Some(c) => format!("did you mean `{c}`?"),
                                None => "define a [[bodies]] table with that name".to_string(),
                            };
                            let d = b
                                .diag(
                                    Some(name.span()),
                                    &k("body"),
                                    format!("body `{}` does not exist", name.get_ref()),
                                )
                                .expected("the name of a [[bodies]] table")
                                .hint(hint);
                            b.push(d);
                            0
                        }
                    },
                    None => {
                        let d = b
                            .diag(
                                Some(p.kind.span()),
                                &k("body"),
                                format!("point `{name}` is on a body but names none"),
                            )
                            .expected("`body = \"NAME\"`, a [[bodies]] name")
                            .hint("and `position` = the offset from the body origin in body axes");
                        b.push(d);
                        0
                    }
                };
                PointKind::Body {
                    body,
                    offset: position.unwrap_or_else(Vec3::zeros),
                }
            }
            PointKindSpec::Prescribed => match &p.motion {
                Some(m) => PointKind::Prescribed(build_motion(b, m, position, &k("motion"), env)),
                None => {
                    let d = b
                        .diag(
                            Some(p.kind.span()),
                            &k("motion"),
                            format!("prescribed point `{name}` has no `motion`"),
                        )
                        .expected(
                            "a `motion` table of type fixed, constant-velocity, sinusoid, \
                             circular-orbit or time-series",
                        )
                        .hint(
                            "add e.g. `motion = { type = \"sinusoid\", amplitude = [2.0, 0.0, \
                             0.0], period = 10.0 }`, or make the point `fixed`",
                        );
                    b.push(d);
                    PointKind::Fixed
                }
            },
        };
        let pos = match (position, &point_kind) {
            // A point on a vessel: `position` is its place on the vessel; it starts where the
            // vessel's motion puts it at t = 0.
            (Some(_), PointKind::Prescribed(m @ Motion::Rigid { .. })) => m.initial_position(),
            (Some(p), _) => p,
            (None, PointKind::Prescribed(m)) => m.initial_position(),
            (None, _) => {
                let d = b
                    .diag(
                        Some(p.name.span()),
                        &k("position"),
                        format!("point `{name}` has no `position`"),
                    )
                    .expected("[x, y, z] in m");
                b.push(d);
                Vec3::zeros()
            }
        };
        let bed = env.seabed_at(pos.x, pos.y).z;
        if env.has_seabed()
            && kind != PointKindSpec::Body
            && pos.z < bed - 1e-9 * (1.0 + bed.abs())
            && let Some(ps) = &p.position
        {
            let flat = matches!(env.bathymetry, Bathymetry::Flat);
            let d = b
                .diag(
                    Some(ps.span()),
                    &k("position"),
                    format!("point `{name}` is below the seabed"),
                )
                .expected(if flat {
                    format!("z ≥ −depth = {bed}")
                } else {
                    format!(
                        "z ≥ {bed}, the seabed's height at x = {}, y = {}",
                        pos.x, pos.y
                    )
                })
                .hint(if flat {
                    "raise the point, or increase `environment.depth`; anchors sit on the \
                     seabed at z = −depth"
                } else {
                    "raise the point onto the seabed; anchors sit on it"
                });
            b.push(d);
        }
        out.push(Point {
            name,
            position: pos,
            kind: point_kind,
        });
    }
    (out, index)
}
