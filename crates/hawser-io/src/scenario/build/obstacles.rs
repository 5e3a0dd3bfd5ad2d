//! `[[obstacles]]`: fixed or moving spheres and cylinders with their contact parameters,
//! checked and converted into [`hawser::physics::obstacles::Obstacle`].

use super::build_motion;
use super::{Builder, Check, NON_NEGATIVE, POSITIVE, span_of};
use crate::scenario::schema::*;
use hawser::math::Vec3;
use hawser::model::*;
use hawser::physics::environment::Environment;
use hawser::physics::obstacles::{Obstacle, ObstacleDamping, ObstacleShape};

/// `[[obstacles]]`: spheres and cylinders, fixed or moving (`[obstacles.motion]` as a
/// point's), with their contact parameters. Names share the channel namespace with lines,
/// points and bodies.
pub(super) fn build_obstacles(
    b: &mut Builder,
    scenario: &Scenario,
    env: &Environment,
) -> Vec<Obstacle> {
    let mut out: Vec<Obstacle> = Vec::new();
    for (i, o) in scenario.obstacles.iter().enumerate() {
        let k = |key: &str| format!("obstacles[{i}].{key}");
        let name = o.name.get_ref().clone();
        if let Some(first) = scenario.obstacles[..i]
            .iter()
            .position(|x| x.name.get_ref() == &name)
        {
            let line = b.line_of(scenario.obstacles[first].name.span());
            let d = b
                .diag(
                    Some(o.name.span()),
                    &k("name"),
                    format!("obstacle `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each obstacle its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&o.name, &k("name"), "obstacle", "drum.force_x");
        let clash = scenario
            .lines
            .iter()
            .map(|l| ("line", &l.name))
            .chain(scenario.points.iter().map(|p| ("point", &p.name)))
            .chain(scenario.bodies.iter().map(|b| ("body", &b.name)))
            .find(|(_, n)| n.get_ref() == &name);
        if let Some((what, other)) = clash {
            let line = b.line_of(other.span());
            let d = b
                .diag(
                    Some(o.name.span()),
                    &k("name"),
                    format!("obstacle `{name}` has the name of a {what}, defined on line {line}"),
                )
                .hint("obstacles, lines, points and bodies share the channel namespace: give them different names");
            b.push(d);
        }
        let shape = *o.shape.get_ref();
        let radius = b.num(
            &o.radius,
            &k("radius"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "the radius of the sphere or cylinder; the cable's own radius d/2 is added to it",
        );
        let shape = match shape {
            ObstacleShapeSpec::Sphere => {
                for (present, span, key) in [
                    (o.axis.is_some(), span_of(&o.axis), "axis"),
                    (o.length.is_some(), span_of(&o.length), "length"),
                ] {
                    b.not_for(
                        present,
                        span,
                        &k(key),
                        "a sphere",
                        "cylinders (`shape = \"cylinder\"`)",
                    );
                }
                ObstacleShape::Sphere { radius }
            }
            ObstacleShapeSpec::Cylinder => {
                let axis = match &o.axis {
                    Some(a) => {
                        let v = Vec3::from(*a.get_ref());
                        if !(v.iter().all(|x| x.is_finite()) && v.norm() > 0.0) {
                            let d = b
                                .diag(
                                    Some(a.span()),
                                    &k("axis"),
                                    "`axis` must be a non-zero direction",
                                )
                                .expected("[x, y, z], finite and not all zero (normalised)")
                                .hint("e.g. [0, 1, 0] for a horizontal cylinder along y");
                            b.push(d);
                            Vec3::z()
                        } else if !b.physical(Some(a.span()), &k("axis"), a.get_ref()) {
                            Vec3::z()
                        } else {
                            v.normalize()
                        }
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(o.shape.span()),
                                &k("axis"),
                                format!("cylinder `{name}` has no `axis`"),
                            )
                            .expected("[x, y, z], the direction of the cylinder's axis")
                            .hint("add e.g. `axis = [0, 0, 1]` for a vertical cylinder");
                        b.push(d);
                        Vec3::z()
                    }
                };
                let length = o.length.as_ref().map(|l| {
                    b.num(
                        l,
                        &k("length"),
                        Check {
                            ok: POSITIVE,
                            expected: "m, > 0",
                        },
                        "the cylinder's length, centred on `position`; omit it for an infinite cylinder",
                    )
                });
                ObstacleShape::Cylinder {
                    radius,
                    axis,
                    length,
                }
            }
        };
        let position = o.position.as_ref().map(|v| b.vec3(v, &k("position")));
        let motion = match (&o.motion, position) {
            (Some(m), _) => build_motion(b, m, position, &k("motion"), env),
            (None, Some(p)) => Motion::Fixed { position: p },
            (None, None) => {
                let d = b
                    .diag(
                        Some(o.name.span()),
                        &k("position"),
                        format!("obstacle `{name}` has no `position`"),
                    )
                    .expected("[x, y, z] in m, the centre")
                    .hint("add `position = [x, y, z]`: the centre, or where its `motion` starts");
                b.push(d);
                Motion::Fixed {
                    position: Vec3::zeros(),
                }
            }
        };
        let stiffness = b.num(
            &o.stiffness,
            &k("stiffness"),
            Check {
                ok: POSITIVE,
                expected: "N/m², > 0 (per unit length of cable)",
            },
            "a cable pressed with N newtons per metre sinks N/stiffness metres in; round an \
             obstacle of radius R under tension T, N ≈ T/R",
        );
        let damping = match (&o.damping_ratio, &o.damping) {
            (Some(_), Some(c)) => {
                let d = b
                    .diag(
                        Some(c.span()),
                        &k("damping"),
                        "give either `damping_ratio` or `damping`, not both",
                    )
                    .hint("`damping_ratio` scales with each cable's mass; `damping` is per unit length of cable");
                b.push(d);
                ObstacleDamping::Ratio(1.0)
            }
            (_, Some(c)) => ObstacleDamping::PerLength(b.num(
                c,
                &k("damping"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·s/m², ≥ 0 (per unit length of cable)",
                },
                "or give `damping_ratio` (1 = critical)",
            )),
            (ratio, None) => ObstacleDamping::Ratio(b.opt(
                ratio,
                &k("damping_ratio"),
                1.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0 (1 = critical)",
                },
                "use 1 for critical damping",
            )),
        };
        let friction_coefficient = b.opt(
            &o.friction_coefficient,
            &k("friction_coefficient"),
            0.0,
            Check {
                ok: NON_NEGATIVE,
                expected: "-, ≥ 0",
            },
            "steel wire on steel is about 0.1–0.2, fibre rope on steel 0.2–0.3",
        );
        let friction_velocity = b.opt(
            &o.friction_velocity,
            &k("friction_velocity"),
            0.01,
            Check {
                ok: POSITIVE,
                expected: "m/s, > 0",
            },
            "a small speed such as 0.01 m/s",
        );
        out.push(Obstacle {
            name,
            shape,
            motion,
            stiffness,
            damping,
            friction_coefficient,
            friction_velocity,
        });
    }
    out
}
