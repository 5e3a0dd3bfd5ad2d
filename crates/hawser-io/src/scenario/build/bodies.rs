//! `[[bodies]]`: rigid bodies, checked and converted into [`hawser::model::Body`].

use super::{Builder, Check, NON_NEGATIVE, POSITIVE, build_rigid_motion, span_of};
use crate::scenario::schema::*;
use hawser::math::{Mat3, Quat, Vec3, Vec6};
use hawser::model::{
    Body, BodyKind, Displacement, DragSpeed, Member, Pin, RigidMotion, Thrust, Wind,
};
use hawser::physics::environment::Environment;
use std::collections::HashMap;
use toml::Spanned;

/// The rotation from body to global axes of `[roll, pitch, yaw]` in degrees:
/// R = Rz(yaw)·Ry(pitch)·Rx(roll), as for vessel motions.
pub fn orientation_from_degrees(roll_pitch_yaw: [f64; 3]) -> Quat {
    let [roll, pitch, yaw] = roll_pitch_yaw.map(f64::to_radians);
    Quat::from_euler_angles(roll, pitch, yaw)
}

/// Builds the bodies; every problem becomes a diagnostic. `taken` maps the names of points
/// and lines (the channel namespace bodies share) to what they are. `env` drives the RAO
/// motions of prescribed bodies (the same waves as the lines).
pub(super) fn build_bodies(
    b: &mut Builder,
    specs: &[BodySpec],
    taken: &HashMap<String, &str>,
    env: &Environment,
) -> Vec<Body> {
    let mut out = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::new();
    // Bodies pinned to bodies: (index, parent's name, point in the parent's axes [m]).
    let mut on_bodies = Vec::new();
    for (i, s) in specs.iter().enumerate() {
        let k = |key: &str| format!("bodies[{i}].{key}");
        let name = s.name.get_ref().clone();
        if let Some(first) = index.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(s.name.span()),
                    &k("name"),
                    format!("body `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each body its own name"
                ));
            b.push(d);
        }
        if name.contains(['.', ',', '"']) || name.is_empty() {
            let d = b
                .diag(
                    Some(s.name.span()),
                    &k("name"),
                    "body names must be non-empty without `.`, `,` or quotes",
                )
                .hint("they become channel names such as `barge.heave`");
            b.push(d);
        }
        if let Some(what) = taken.get(&name) {
            let d = b
                .diag(
                    Some(s.name.span()),
                    &k("name"),
                    format!("body `{name}` has the name of a {what}"),
                )
                .hint("bodies, points and lines share the channel namespace: give them different names");
            b.push(d);
        }

        let pinned = *s.kind.get_ref() == BodyKindSpec::Pinned;
        let pin = s.pin.as_ref().map(|p| *p.get_ref()).unwrap_or_default();
        if let Some(p) = &s.pin
            && !pinned
        {
            let d = b
                .diag(Some(p.span()), &k("pin"), "only a pinned body has a `pin`")
                .hint(
                    "give the body `type = \"pinned\"` to pin its origin and let it turn, or \
                     remove `pin`",
                );
            b.push(d);
        }
        let pinned_on_motion = pinned && pin == PinSpec::Prescribed;
        let pinned_on_body = pinned && pin == PinSpec::Body;
        for (key, span) in [
            ("pin_body", span_of(&s.pin_body)),
            ("pin_point", span_of(&s.pin_point)),
        ] {
            if let Some(span) = span.filter(|_| !pinned_on_body) {
                let d = b
                    .diag(
                        Some(span),
                        &k(key),
                        format!("only a body with `pin = \"body\"` has a `{key}`"),
                    )
                    .hint(
                        "give the body `type = \"pinned\"` and `pin = \"body\"` to pin it to a \
                         point of another body, or remove the key",
                    );
                b.push(d);
            }
        }
        if pinned_on_body && s.pin_body.is_none() {
            let d = b
                .diag(
                    s.pin.as_ref().map(|p| p.span()),
                    &k("pin_body"),
                    format!("body `{name}` is pinned to a body but has no `pin_body`"),
                )
                .expected("the name of another body")
                .hint(
                    "add e.g. `pin_body = \"buoy\"` and `pin_point = [0.0, 0.0, -2.0]` (the \
                     point in that body's axes)",
                );
            b.push(d);
        }
        if let (true, Some(parent)) = (pinned_on_body, &s.pin_body) {
            let point = s
                .pin_point
                .as_ref()
                .map_or(Vec3::zeros(), |p| b.vec3(p, &k("pin_point")));
            on_bodies.push((i, parent, point));
        }
        let prescribed = *s.kind.get_ref() == BodyKindSpec::Prescribed;
        // A prescribed body is placed by its motion (`start`, `heading` or the file); a pose
        // given beside it would be a second, conflicting, answer. The motion of a pin places
        // the origin only: the body's orientation is its own.
        if prescribed || pinned_on_motion || pinned_on_body {
            for (key, span) in [
                ("position", span_of(&s.position)),
                (
                    "orientation",
                    span_of(&s.orientation).filter(|_| prescribed),
                ),
            ] {
                if let Some(span) = span {
                    let d = if pinned_on_body {
                        b.diag(
                            Some(span),
                            &k(key),
                            "a body pinned to a body takes its `position` from the pin",
                        )
                        .hint(
                            "remove it: the body's origin starts on `pin_point` of `pin_body` \
                             (the body's `orientation` stays its own)",
                        )
                    } else if pinned_on_motion {
                        b.diag(
                            Some(span),
                            &k(key),
                            "a body on a prescribed pin takes its `position` from the pin's motion",
                        )
                        .hint(
                            "remove it; give the pin's place at t = 0 as `start` in \
                             `[bodies.motion]` (the body's `orientation` stays its own)",
                        )
                    } else {
                        b.diag(
                            Some(span),
                            &k(key),
                            format!("a prescribed body takes its `{key}` from its motion"),
                        )
                        .hint(
                            "remove it; give the body origin's place at t = 0 as `start` and \
                             `heading` in `[bodies.motion]` (a `vessel-motion` file gives the \
                             whole pose)",
                        )
                    };
                    b.push(d);
                }
            }
        }
        let position = match &s.position {
            Some(p) => b.vec3(p, &k("position")),
            None if prescribed || pinned_on_motion || pinned_on_body => Vec3::zeros(),
            None => {
                let d = b
                    .diag(
                        Some(s.name.span()),
                        &k("position"),
                        format!("body `{name}` has no `position`"),
                    )
                    .expected("[x, y, z] of the body origin in m")
                    .hint("add e.g. `position = [0.0, 0.0, -10.0]`");
                b.push(d);
                Vec3::zeros()
            }
        };
        let orientation = match &s.orientation {
            Some(o) => {
                let a = *o.get_ref();
                if a.iter().any(|x| !x.is_finite()) {
                    let d = b
                        .diag(
                            Some(o.span()),
                            &k("orientation"),
                            "`orientation` has a non-finite angle",
                        )
                        .expected("[roll, pitch, yaw] in degrees");
                    b.push(d);
                    Quat::identity()
                } else if !b.physical(Some(o.span()), &k("orientation"), &a) {
                    Quat::identity()
                } else {
                    orientation_from_degrees(a)
                }
            }
            None => Quat::identity(),
        };
        let free = matches!(s.kind.get_ref(), BodyKindSpec::Free | BodyKindSpec::Pinned);
        // A free or pinned body needs its mass and inertia; the others' own loads are not
        // computed.
        for (key, given) in [("mass", s.mass.is_some()), ("inertia", s.inertia.is_some())] {
            if free && !given {
                let d = b
                    .diag(
                        Some(s.kind.span()),
                        &k(key),
                        format!(
                            "{} body `{name}` has no `{key}`",
                            if pinned { "pinned" } else { "free" }
                        ),
                    )
                    .expected(match key {
                        "mass" => "the mass in air in kg, > 0",
                        _ => "[Ixx, Iyy, Izz] about the centre of gravity in kg·m²",
                    })
                    .hint("a free or pinned body moves under its mass and inertia: give both");
                b.push(d);
            }
        }
        let mass = match &s.mass {
            Some(m) => b.num(
                m,
                &k("mass"),
                Check {
                    ok: if free { POSITIVE } else { NON_NEGATIVE },
                    expected: if free { "kg, > 0" } else { "kg, ≥ 0" },
                },
                "the body's mass in air, without added mass",
            ),
            None if free => 1.0,
            None => 0.0,
        };
        let centre = |b: &mut Builder, v: &Option<Spanned<[f64; 3]>>, key: &str| {
            v.as_ref()
                .map(|v| b.vec3(v, &k(key)))
                .unwrap_or_else(Vec3::zeros)
        };
        let centre_of_gravity = centre(b, &s.centre_of_gravity, "centre_of_gravity");
        let centre_of_buoyancy = centre(b, &s.centre_of_buoyancy, "centre_of_buoyancy");
        let inertia = match &s.inertia {
            Some(i) => build_inertia(b, i, &k("inertia"), free),
            None if free => Mat3::identity(),
            None => Mat3::zeros(),
        };
        if let Some(p) = &s.hydrodynamic_centre
            && matches!(
                s.displacement.as_ref().map(|d| *d.kind.get_ref()),
                Some(DisplacementKind::Cylinder | DisplacementKind::Box)
            )
        {
            let d = b
                .diag(
                    Some(p.span()),
                    &k("hydrodynamic_centre"),
                    "`hydrodynamic_centre` is for a `submerged` displacement or none",
                )
                .hint(
                    "a cylinder or box takes its added mass, fluid inertia and drag at the \
                     centroid of its wet volume: remove the key",
                );
            b.push(d);
        }
        let hydrodynamic_centre = s
            .hydrodynamic_centre
            .as_ref()
            .map(|p| b.vec3(p, &k("hydrodynamic_centre")));
        let members = s
            .members
            .iter()
            .enumerate()
            .map(|(j, m)| build_member(b, m, &k(&format!("members[{j}]"))))
            .collect();
        let drag_speed = match s.drag_speed.as_ref().map(|d| *d.get_ref()) {
            Some(DragSpeedSpec::Magnitude) => DragSpeed::Magnitude,
            _ => DragSpeed::Component,
        };
        let displacement = match &s.displacement {
            Some(d) => build_displacement(b, d, &k("displacement")),
            None => Displacement::None,
        };
        let six = |b: &mut Builder, v: &Option<Spanned<[f64; 6]>>, key: &str, unit: &str| {
            v.as_ref()
                .map(|v| non_negative6(b, v, &k(key), unit))
                .unwrap_or_else(Vec6::zeros)
        };
        let added_mass = six(
            b,
            &s.added_mass,
            "added_mass",
            "kg for surge, sway, heave and kg·m² for roll, pitch, yaw, each ≥ 0",
        );
        let linear_drag = six(
            b,
            &s.linear_drag,
            "linear_drag",
            "N·s/m for surge, sway, heave and N·m·s/rad for roll, pitch, yaw, each ≥ 0",
        );
        let mut quadratic_drag = six(
            b,
            &s.quadratic_drag,
            "quadratic_drag",
            "C·A in m² for surge, sway, heave and C·A·L³ in m⁵ for roll, pitch, yaw, each ≥ 0",
        );
        match (&s.drag_coefficients, &s.drag_areas) {
            (Some(c), Some(a)) => {
                let c3 = non_negative3(b, c, &k("drag_coefficients"), "-, each ≥ 0");
                let a3 = non_negative3(b, a, &k("drag_areas"), "m², each ≥ 0");
                if let Some(q) = &s.quadratic_drag {
                    let d = b
                        .diag(
                            Some(q.span()),
                            &k("quadratic_drag"),
                            "`quadratic_drag` and `drag_coefficients`/`drag_areas` both give the \
                             quadratic drag",
                        )
                        .hint(
                            "give one: `quadratic_drag` (six C·A products, with the rotations) \
                             or `drag_coefficients` with `drag_areas` (the translations)",
                        );
                    b.push(d);
                }
                for j in 0..3 {
                    quadratic_drag[j] = c3[j] * a3[j];
                }
            }
            (Some(one), None) | (None, Some(one)) => {
                let (given, missing) = match s.drag_areas {
                    None => ("drag_coefficients", "drag_areas"),
                    Some(_) => ("drag_areas", "drag_coefficients"),
                };
                let d = b
                    .diag(
                        Some(one.span()),
                        &k(missing),
                        format!("`{given}` needs `{missing}`"),
                    )
                    .expected(match missing {
                        "drag_areas" => "[Ax, Ay, Az] in m²",
                        _ => "[Cx, Cy, Cz], dimensionless",
                    })
                    .hint(format!(
                        "add `{missing} = [..., ..., ...]`: the quadratic drag along body axis \
                         i is ½ ρ C_i A_i |u_i| u_i"
                    ));
                b.push(d);
            }
            (None, None) => {}
        }
        let thrust = match &s.thrust {
            Some(t) => build_thrust(b, t, &k("thrust")),
            None => Thrust::None,
        };
        let wind = s.wind.as_ref().map(|w| Wind {
            velocity: b.vec3(&w.velocity, &k("wind.velocity")),
            drag_area: b.num(
                &w.drag_area,
                &k("wind.drag_area"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "m², ≥ 0 (C_d × area)",
                },
                "the superstructure's drag coefficient times its area facing the wind",
            ),
            centre: centre(b, &w.centre, "wind.centre"),
        });
        let kind = match (s.kind.get_ref(), &s.motion) {
            (BodyKindSpec::Pinned, Some(m)) if pin == PinSpec::Prescribed => {
                BodyKind::Pinned(Pin::Prescribed(build_rigid_motion(b, m, &k("motion"), env)))
            }
            (BodyKindSpec::Pinned, None) if pin == PinSpec::Prescribed => {
                let d = b
                    .diag(
                        s.pin.as_ref().map(|p| p.span()),
                        &k("motion"),
                        format!(
                            "body `{name}` is pinned on a prescribed motion but has no `motion`"
                        ),
                    )
                    .expected(
                        "a `[bodies.motion]` table of type `fixed`, `constant-velocity`, \
                         `manoeuvre`, `vessel-motion` or `rao` for the pin",
                    )
                    .hint(
                        "add e.g. `motion = { type = \"constant-velocity\", velocity = [2.0, \
                         0.0, 0.0] }`, or pin it in place with `pin = \"fixed\"`",
                    );
                b.push(d);
                BodyKind::Pinned(Pin::Fixed)
            }
            (BodyKindSpec::Prescribed, Some(m)) => {
                BodyKind::Prescribed(build_rigid_motion(b, m, &k("motion"), env))
            }
            (BodyKindSpec::Prescribed, None) => {
                let d = b
                    .diag(
                        Some(s.kind.span()),
                        &k("motion"),
                        format!("prescribed body `{name}` has no `motion`"),
                    )
                    .expected(
                        "a `[bodies.motion]` table of type `fixed`, `constant-velocity`, \
                         `manoeuvre`, `vessel-motion` or `rao`",
                    )
                    .hint(
                        "add e.g. `motion = { type = \"constant-velocity\", velocity = [2.0, \
                         0.0, 0.0] }`, or make it `type = \"fixed\"`",
                    );
                b.push(d);
                BodyKind::Free
            }
            (kind, motion) => {
                if let Some(m) = motion {
                    let d = b
                        .diag(
                            Some(m.kind.span()),
                            &k("motion"),
                            format!(
                                "a `{}` body has no `motion`",
                                match kind {
                                    BodyKindSpec::Free => "free",
                                    BodyKindSpec::Coupled => "coupled",
                                    BodyKindSpec::Pinned => "pinned",
                                    _ => "fixed",
                                }
                            ),
                        )
                        .hint(if pinned {
                            "give the body `pin = \"prescribed\"` to move its pin as the \
                             motion says, or remove the `motion` table"
                        } else {
                            "give the body `type = \"prescribed\"` to move it as the motion \
                             says, or remove the `motion` table"
                        });
                    b.push(d);
                }
                match kind {
                    BodyKindSpec::Fixed => BodyKind::Prescribed(RigidMotion::Fixed {
                        position,
                        orientation,
                    }),
                    BodyKindSpec::Coupled => BodyKind::Coupled,
                    BodyKindSpec::Pinned if pin == PinSpec::Coupled => {
                        BodyKind::Pinned(Pin::Coupled)
                    }
                    // Its parent is set once every body is built.
                    BodyKindSpec::Pinned if pin == PinSpec::Body => BodyKind::Pinned(Pin::Body {
                        body: i,
                        point: Vec3::zeros(),
                    }),
                    BodyKindSpec::Pinned => BodyKind::Pinned(Pin::Fixed),
                    _ => BodyKind::Free,
                }
            }
        };
        // A prescribed body starts where its motion is at t = 0.
        let (position, orientation) = match &kind {
            BodyKind::Prescribed(m) if prescribed => {
                let k0 = m.kinematics(0.0);
                (k0.position, k0.orientation)
            }
            // A body on a prescribed pin starts with its origin where the pin is at t = 0.
            BodyKind::Pinned(Pin::Prescribed(m)) => (m.kinematics(0.0).position, orientation),
            _ => (position, orientation),
        };
        out.push(Body {
            name,
            position,
            orientation,
            kind,
            mass,
            centre_of_gravity,
            inertia,
            displacement,
            centre_of_buoyancy,
            added_mass,
            linear_drag,
            quadratic_drag,
            drag_speed,
            hydrodynamic_centre,
            members,
            thrust,
            wind,
        });
    }
    // Bodies pinned to bodies: the parent by name, the origin on its point at t = 0.
    for (i, parent, point) in on_bodies {
        let k = format!("bodies[{i}].pin_body");
        let child = specs[i].name.get_ref();
        let name = parent.get_ref();
        let problem = match index.get(name) {
            None => Some((
                format!("body `{child}` is pinned to body `{name}`, which does not exist"),
                format!(
                    "the bodies are {}",
                    specs
                        .iter()
                        .map(|s| format!("`{}`", s.name.get_ref()))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            )),
            Some(&p) if p == i => Some((
                format!("body `{child}` is pinned to itself"),
                "name another body: the pin joins two bodies".to_string(),
            )),
            Some(&p) if out[p].kind.pin().and_then(Pin::parent).is_some() => Some((
                format!(
                    "body `{child}` is pinned to body `{name}`, which is itself pinned to a body"
                ),
                "a pin on a body takes a free, fixed, prescribed, coupled or pinned parent \
                 (one level): pin both bodies to the same parent, or make `{name}` free"
                    .replace("{name}", name),
            )),
            Some(_) => None,
        };
        if let Some((why, hint)) = problem {
            let d = b.diag(Some(parent.span()), &k, why).hint(hint);
            b.push(d);
            continue;
        }
        let p = index[name];
        out[i].kind = BodyKind::Pinned(Pin::Body { body: p, point });
        out[i].position = out[p].initial_kinematics().point(&point).0;
    }
    out
}

/// A member: ends apart, a diameter > 0, at least one segment, coefficients ≥ 0.
fn build_member(b: &mut Builder, m: &MemberSpec, key: &str) -> Member {
    let k = |f: &str| format!("{key}.{f}");
    let end_a = b.vec3(&m.end_a, &k("end_a"));
    let end_b = b.vec3(&m.end_b, &k("end_b"));
    if end_a == end_b {
        let d = b
            .diag(
                Some(m.end_b.span()),
                &k("end_b"),
                "a member's ends are at the same place",
            )
            .expected("end_b ≠ end_a, in body axes [m]")
            .hint("a member is a cylinder from end_a to end_b");
        b.push(d);
    }
    let diameter = b.num(
        &m.diameter,
        &k("diameter"),
        Check {
            ok: POSITIVE,
            expected: "m, > 0",
        },
        "the member's diameter",
    );
    let segments = match &m.segments {
        Some(n) if *n.get_ref() >= 1 => *n.get_ref() as usize,
        Some(n) => {
            let d = b
                .diag(
                    Some(n.span()),
                    &k("segments"),
                    "a member needs at least one segment",
                )
                .expected("a whole number ≥ 1")
                .hint("the member's loads are lumped at its segments' ends");
            b.push(d);
            1
        }
        None => 1,
    };
    let mut coefficient = |v: &Option<Spanned<f64>>, f: &str, what: &str| {
        v.as_ref()
            .map(|v| {
                b.num(
                    v,
                    &k(f),
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "≥ 0, dimensionless",
                    },
                    what,
                )
            })
            .unwrap_or(0.0)
    };
    Member {
        end_a,
        end_b,
        diameter,
        segments,
        normal_drag: coefficient(
            &m.normal_drag,
            "normal_drag",
            "drag coefficient across the member",
        ),
        normal_added_mass: coefficient(
            &m.normal_added_mass,
            "normal_added_mass",
            "added-mass coefficient across the member",
        ),
        end_drag: coefficient(&m.end_drag, "end_drag", "drag coefficient of each wet end"),
        end_added_mass: coefficient(
            &m.end_added_mass,
            "end_added_mass",
            "axial added-mass coefficient of each wet end",
        ),
    }
}

/// [Ixx, Iyy, Izz] or a full tensor, symmetric; positive definite for a free body (`free`),
/// positive semi-definite (zero allowed) for the others.
fn build_inertia(b: &mut Builder, v: &Spanned<InertiaSpec>, key: &str, free: bool) -> Mat3 {
    let (m, principal) = match v.get_ref() {
        InertiaSpec::Principal(d) => (Mat3::from_diagonal(&Vec3::from(*d)), true),
        InertiaSpec::Matrix(rows) => (Mat3::from_fn(|i, j| rows[i][j]), false),
    };
    let expected = "kg·m² about the centre of gravity in body axes: [Ixx, Iyy, Izz] each > 0, \
                    or a symmetric positive definite 3×3 tensor";
    let problem = if m.iter().any(|x| !x.is_finite()) {
        Some("`inertia` has a non-finite entry")
    } else if !b.physical(Some(v.span()), key, m.as_slice()) {
        return Mat3::identity();
    } else if (m - m.transpose()).abs().max() > 1e-9 * m.abs().max() {
        Some("`inertia` is not symmetric")
    } else if !free && (m.abs().max() == 0.0 || m.symmetric_eigenvalues().min() >= 0.0) {
        None
    } else if !(m.abs().max() > 0.0) || m.cholesky().is_none() {
        Some(match principal {
            true => "`inertia` has a principal moment ≤ 0",
            false => "`inertia` is not positive definite",
        })
    } else {
        None
    };
    if let Some(message) = problem {
        let d = b
            .diag(Some(v.span()), key, message)
            .expected(expected)
            .hint(match principal {
                true => "a solid box l × b × h of mass m has Ixx = m(b² + h²)/12, …",
                false => {
                    "the tensor has I_xy = I_yx = −∫ x y dm off the diagonal, and every \
                     principal moment > 0"
                }
            });
        b.push(d);
        return Mat3::identity();
    }
    m
}

/// The displaced volume of one kind, with the keys that kind takes.
fn build_displacement(b: &mut Builder, d: &DisplacementSpec, key: &str) -> Displacement {
    let k = |x: &str| format!("{key}.{x}");
    let kind = *d.kind.get_ref();
    let (name, needs): (&str, &[&str]) = match kind {
        DisplacementKind::Submerged => ("submerged", &["volume"]),
        DisplacementKind::Cylinder => ("cylinder", &["radius", "height"]),
        DisplacementKind::Box => ("box", &["length", "breadth", "height"]),
    };
    let given = [
        ("volume", &d.volume),
        ("radius", &d.radius),
        ("height", &d.height),
        ("length", &d.length),
        ("breadth", &d.breadth),
    ];
    for (field, value) in given {
        if value.is_some() && !needs.contains(&field) {
            let diag = b
                .diag(
                    span_of(value),
                    &k(field),
                    format!("`{field}` does not apply to a `{name}` displacement"),
                )
                .hint(format!(
                    "remove it; a `{name}` displacement takes {}",
                    needs
                        .iter()
                        .map(|n| format!("`{n}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
            b.push(diag);
        }
    }
    let mut get = |field: &str, check: Check, hint: &str| -> f64 {
        let value = given
            .iter()
            .find(|(f, _)| *f == field)
            .and_then(|(_, v)| v.as_ref());
        match value {
            Some(v) => b.num(v, &k(field), check, hint),
            None => {
                let diag = b
                    .diag(
                        Some(d.kind.span()),
                        &k(field),
                        format!("a `{name}` displacement needs `{field}`"),
                    )
                    .expected(check.expected)
                    .hint(format!("add `{field} = ...` to the displacement"));
                b.push(diag);
                1.0
            }
        }
    };
    let length = || Check {
        ok: POSITIVE,
        expected: "m, > 0",
    };
    match kind {
        DisplacementKind::Submerged => Displacement::Submerged {
            volume: get(
                "volume",
                Check {
                    ok: NON_NEGATIVE,
                    expected: "m³, ≥ 0",
                },
                "the volume of water the body displaces; buoyancy is ρ g V",
            ),
        },
        DisplacementKind::Cylinder => Displacement::Cylinder {
            radius: get("radius", length(), "the cylinder's radius"),
            height: get("height", length(), "the cylinder's height along body z"),
        },
        DisplacementKind::Box => Displacement::Box {
            length: get("length", length(), "the box's length along body x"),
            breadth: get("breadth", length(), "the box's breadth along body y"),
            height: get("height", length(), "the box's height along body z"),
        },
    }
}

/// A constant thrust or a schedule.
fn build_thrust(b: &mut Builder, t: &ThrustSpec, key: &str) -> Thrust {
    let k = |x: &str| format!("{key}.{x}");
    match &t.table {
        Some(table) => {
            for (field, v) in [("force", &t.force), ("moment", &t.moment)] {
                if let Some(v) = v {
                    let d = b
                        .diag(
                            Some(v.span()),
                            &k(field),
                            format!("`{field}` and `table` both give the thrust"),
                        )
                        .hint(
                            "give a constant `force`/`moment`, or a `table` of rows [t, Fx, Fy, \
                             Fz, Mx, My, Mz]",
                        );
                    b.push(d);
                }
            }
            let rows = table.get_ref();
            let finite = rows.iter().flatten().all(|x| x.is_finite());
            let increasing = rows.windows(2).all(|w| w[1][0] > w[0][0]);
            if rows.is_empty() || !finite || !increasing {
                let d = b
                    .diag(
                        Some(table.span()),
                        &k("table"),
                        match (rows.is_empty(), finite) {
                            (true, _) => "the thrust schedule has no rows",
                            (false, false) => "the thrust schedule has a non-finite entry",
                            _ => "the thrust schedule's times are not strictly increasing",
                        },
                    )
                    .expected("rows [t, Fx, Fy, Fz, Mx, My, Mz] in s, N and N·m, t increasing")
                    .hint("e.g. `table = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [10.0, 5e4, 0.0, 0.0, 0.0, 0.0, 0.0]]`");
                b.push(d);
                return Thrust::None;
            }
            if !rows
                .iter()
                .all(|r| b.physical(Some(table.span()), &k("table"), r))
            {
                return Thrust::None;
            }
            Thrust::Schedule {
                times: rows.iter().map(|r| r[0]).collect(),
                forces: rows.iter().map(|r| Vec3::new(r[1], r[2], r[3])).collect(),
                moments: rows.iter().map(|r| Vec3::new(r[4], r[5], r[6])).collect(),
            }
        }
        None => {
            if t.force.is_none() && t.moment.is_none() {
                let d = b
                    .diag(
                        None,
                        key,
                        "`thrust` gives neither a force, a moment nor a table",
                    )
                    .expected("`force` [N] and/or `moment` [N·m] in body axes, or a `table`")
                    .hint("e.g. `thrust = { force = [1.0e4, 0.0, 0.0] }`, or remove `thrust`");
                b.push(d);
            }
            let force = t.force.as_ref().map(|f| b.vec3(f, &k("force")));
            let moment = t.moment.as_ref().map(|m| b.vec3(m, &k("moment")));
            Thrust::Constant {
                force: force.unwrap_or_else(Vec3::zeros),
                moment: moment.unwrap_or_else(Vec3::zeros),
            }
        }
    }
}

/// Six finite numbers ≥ 0.
fn non_negative6(b: &mut Builder, v: &Spanned<[f64; 6]>, key: &str, expected: &str) -> Vec6 {
    let a = *v.get_ref();
    if let Some(j) = a.iter().position(|x| !(*x >= 0.0) || !x.is_finite()) {
        let axis = ["surge", "sway", "heave", "roll", "pitch", "yaw"][j];
        let d = b
            .diag(
                Some(v.span()),
                key,
                format!("`{key}` has a negative or non-finite value for {axis} (entry {j})"),
            )
            .expected(expected.to_string())
            .hint("write 0 for an axis without it");
        b.push(d);
        return Vec6::zeros();
    }
    if !b.physical(Some(v.span()), key, &a) {
        return Vec6::zeros();
    }
    Vec6::from(a)
}

/// Three finite numbers ≥ 0.
fn non_negative3(b: &mut Builder, v: &Spanned<[f64; 3]>, key: &str, expected: &str) -> Vec3 {
    let a = *v.get_ref();
    if let Some(j) = a.iter().position(|x| !(*x >= 0.0) || !x.is_finite()) {
        let d = b
            .diag(
                Some(v.span()),
                key,
                format!(
                    "`{key}` has a negative or non-finite value along body {}",
                    ["x", "y", "z"][j]
                ),
            )
            .expected(expected.to_string())
            .hint("write 0 for an axis without drag");
        b.push(d);
        return Vec3::zeros();
    }
    if !b.physical(Some(v.span()), key, &a) {
        return Vec3::zeros();
    }
    Vec3::from(a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn build(source: &str) -> (Vec<Body>, Vec<String>) {
        let specs: Scenario = toml::from_str(source).expect("valid TOML");
        let mut b = Builder::new(Path::new("bodies.toml"), source);
        let taken = HashMap::from([("anchor".to_string(), "point")]);
        let bodies = build_bodies(&mut b, &specs.bodies, &taken, &Environment::default());
        (bodies, b.errors.iter().map(|d| d.to_string()).collect())
    }

    /// `drag_speed` and `hydrodynamic_centre` reach the model; a coupled or fixed body may
    /// leave out its mass and inertia (zero), a free one may not, and a cylinder refuses a
    /// hydrodynamic centre (its wet centroid is the centre).
    #[test]
    fn drag_speed_centre_and_optional_mass() {
        let (bodies, errors) = build(
            r#"
[[bodies]]
name = "buoy"
type = "free"
position = [0.0, 0.0, -30.0]
mass = 100.0
inertia = [10.0, 10.0, 10.0]
displacement = { type = "submerged", volume = 0.5 }
centre_of_buoyancy = [0.0, 0.0, -1.0]
hydrodynamic_centre = [0.0, 0.0, 0.0]
drag_speed = "magnitude"

[[bodies]]
name = "platform"
type = "coupled"
position = [0.0, 0.0, 0.0]
"#,
        );
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(bodies[0].drag_speed, DragSpeed::Magnitude);
        assert_eq!(bodies[0].hydrodynamic_centre, Some(Vec3::zeros()));
        assert_eq!((bodies[1].mass, bodies[1].inertia), (0.0, Mat3::zeros()));
        assert_eq!(bodies[1].drag_speed, DragSpeed::Component);
        let (_, errors) = build(
            r#"
[[bodies]]
name = "can"
type = "free"
position = [0.0, 0.0, -30.0]
displacement = { type = "cylinder", radius = 1.0, height = 2.0 }
hydrodynamic_centre = [0.0, 0.0, 1.0]
"#,
        );
        let all = errors.join("\n");
        assert!(all.contains("free body `can` has no `mass`"), "{all}");
        assert!(all.contains("free body `can` has no `inertia`"), "{all}");
        assert!(
            all.contains("`hydrodynamic_centre` is for a `submerged`"),
            "{all}"
        );
    }

    /// Every key lands in the model's field, in its units: degrees to a quaternion
    /// (R = Rz(yaw) Ry(pitch) Rx(roll)), drag coefficients times areas.
    #[test]
    fn every_key_reaches_the_model() {
        let (bodies, errors) = build(
            r#"
[[bodies]]
name = "towfish"
type = "free"
position = [1.0, 2.0, -30.0]
orientation = [10.0, -5.0, 90.0]
mass = 9500.0
centre_of_gravity = [0.0, 0.0, -0.2]
inertia = [[4000.0, 0.0, -10.0], [0.0, 9000.0, 0.0], [-10.0, 0.0, 9500.0]]
displacement = { type = "box", length = 4.0, breadth = 1.5, height = 1.0 }
centre_of_buoyancy = [0.1, 0.0, 0.1]
added_mass = [600.0, 2000.0, 2500.0, 300.0, 3000.0, 2800.0]
linear_drag = [0.0, 0.0, 100.0, 0.0, 0.0, 0.0]
drag_coefficients = [0.8, 1.2, 1.2]
drag_areas = [1.5, 4.0, 6.0]
thrust = { table = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [10.0, 1e4, 0.0, 0.0, 0.0, 0.0, 500.0]] }
wind = { velocity = [15.0, 0.0, 0.0], drag_area = 20.0, centre = [0.0, 0.0, 2.0] }

[[bodies]]
name = "frame"
type = "fixed"
position = [0.0, 0.0, -50.0]
mass = 100.0
inertia = [10.0, 10.0, 10.0]
displacement = { type = "cylinder", radius = 0.5, height = 2.0 }
thrust = { force = [1.0, 2.0, 3.0] }
"#,
        );
        assert!(errors.is_empty(), "{errors:?}");
        let t = &bodies[0];
        assert_eq!(t.position, Vec3::new(1.0, 2.0, -30.0));
        let (r, p, y) = (10f64.to_radians(), -5f64.to_radians(), 90f64.to_radians());
        let rot = |axis: Vec3, a: f64| {
            *Quat::from_scaled_axis(axis * a)
                .to_rotation_matrix()
                .matrix()
        };
        let expected = rot(Vec3::z(), y) * rot(Vec3::y(), p) * rot(Vec3::x(), r);
        let got = *t.orientation.to_rotation_matrix().matrix();
        assert!((got - expected).abs().max() < 1e-15);
        assert_eq!(t.kind, BodyKind::Free);
        assert_eq!(t.inertia[(0, 2)], -10.0);
        assert_eq!(
            t.displacement,
            Displacement::Box {
                length: 4.0,
                breadth: 1.5,
                height: 1.0
            }
        );
        assert_eq!(t.added_mass[4], 3000.0);
        assert_eq!(t.linear_drag[2], 100.0);
        assert!((t.quadratic_drag[1] - 4.8).abs() < 1e-12 && t.quadratic_drag[3] == 0.0);
        assert_eq!(
            t.thrust.at(5.0),
            (Vec3::new(5e3, 0.0, 0.0), Vec3::new(0.0, 0.0, 250.0))
        );
        assert_eq!(t.wind.as_ref().unwrap().drag_area, 20.0);
        let f = &bodies[1];
        assert_eq!(
            f.kind,
            BodyKind::Prescribed(RigidMotion::Fixed {
                position: Vec3::new(0.0, 0.0, -50.0),
                orientation: Quat::identity()
            })
        );
        assert_eq!(f.inertia, Mat3::identity() * 10.0);
        assert_eq!(f.thrust.at(0.0), (Vec3::new(1.0, 2.0, 3.0), Vec3::zeros()));
        assert_eq!(f.wind, None);
        // Every built body passes the core's own range checks.
        for body in &bodies {
            body.check().unwrap();
        }
    }

    #[test]
    fn name_shared_with_a_point_is_refused() {
        let (_, errors) = build(
            "[[bodies]]\nname = \"anchor\"\ntype = \"free\"\nposition = [0.0, 0.0, 0.0]\nmass = 1.0\ninertia = [1.0, 1.0, 1.0]\n",
        );
        assert_eq!(errors.len(), 1);
        assert!(
            errors[0].contains("has the name of a point"),
            "{}",
            errors[0]
        );
    }
}
