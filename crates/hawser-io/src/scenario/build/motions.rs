//! Prescribed motions (`[points.motion]`, `[bodies.motion]`, `[obstacles.motion]`): fixed,
//! constant velocity, manoeuvre, vessel-motion file and RAO, checked and converted into
//! [`hawser::model::Motion`] and [`hawser::model::RigidMotion`].

use super::{Builder, Check, NON_NEGATIVE, POSITIVE, span_of};
use crate::scenario::schema::*;
use crate::scenario::tables::{read_rao_table, read_table};
use hawser::math::{Quat, Vec3};
use hawser::model::*;
use hawser::physics::environment::Environment;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

pub(super) fn build_motion(
    b: &mut Builder,
    m: &MotionSpec,
    position: Option<Vec3>,
    key: &str,
    env: &Environment,
) -> Motion {
    let k = |x: &str| format!("{key}.{x}");
    let kind = *m.kind.get_ref();
    let centre = position.unwrap_or_else(Vec3::zeros);
    if matches!(
        kind,
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao
    ) {
        // The point rides on a vessel: `position` is its place on the vessel.
        if position.is_none() {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("type"),
                    "a point on a vessel needs its `position` on the vessel",
                )
                .expected("`position = [x, y, z]` on the point, in m, in vessel axes from the vessel origin")
                .hint("e.g. `position = [-40.0, 0.0, -2.0]` for a tow point 40 m aft of the origin, 2 m below it");
            b.push(d);
        }
        return Motion::Rigid {
            motion: Box::new(build_rigid_motion(b, m, key, env)),
            offset: centre,
        };
    }
    if position.is_none() && !matches!(kind, MotionKind::TimeSeries) {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k("type"),
                "this motion is relative to the point's `position`, which is missing",
            )
            .expected("`position = [x, y, z]` on the point, in m");
        b.push(d);
    }
    let allowed: &[&str] = match kind {
        MotionKind::Fixed => &[],
        MotionKind::ConstantVelocity => &["velocity"],
        MotionKind::Sinusoid => &["amplitude", "period", "frequency", "phase", "ramp_time"],
        MotionKind::CircularOrbit => &[
            "radius",
            "frequency",
            "period",
            "phase",
            "plane",
            "ramp_time",
        ],
        MotionKind::TimeSeries => &["table", "file"],
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao => unreachable!(),
    };
    reject_keys(b, m, key, allowed);
    let required = |b: &mut Builder, name: &str, unit: &str| {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k(name),
                format!("this motion needs `{name}`"),
            )
            .expected(unit.to_string())
            .hint(format!("add `{name} = ...` to the motion table"));
        b.push(d);
    };
    let ramp = b.opt(
        &m.ramp_time,
        &k("ramp_time"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "a few periods lets the system build up without a start-up jerk",
    );
    match kind {
        MotionKind::Fixed => Motion::Fixed { position: centre },
        MotionKind::ConstantVelocity => match &m.velocity {
            Some(v) => Motion::ConstantVelocity {
                start: centre,
                velocity: b.vec3(v, &k("velocity")),
            },
            None => {
                required(b, "velocity", "[vx, vy, vz] in m/s");
                Motion::Fixed { position: centre }
            }
        },
        MotionKind::Sinusoid => {
            let amplitude = match &m.amplitude {
                Some(a) => finite3(b, a, &k("amplitude"), "m"),
                None => {
                    required(b, "amplitude", "m, one value or [ax, ay, az]");
                    [0.0; 3]
                }
            };
            let frequency = frequency_of(b, m, &k("frequency"));
            let phase = m
                .phase
                .as_ref()
                .map(|p| finite3(b, p, &k("phase"), "deg"))
                .unwrap_or([0.0; 3]);
            Motion::Sinusoid {
                centre,
                amplitude: Vec3::from(amplitude),
                frequency: Vec3::from(frequency),
                phase: Vec3::from(phase).map(f64::to_radians),
                ramp,
            }
        }
        MotionKind::CircularOrbit => {
            let radius = match &m.radius {
                Some(r) => b.num(
                    r,
                    &k("radius"),
                    Check {
                        ok: POSITIVE,
                        expected: "m, > 0",
                    },
                    "the orbit radius a",
                ),
                None => {
                    required(b, "radius", "m, > 0");
                    1.0
                }
            };
            for (key, v) in [
                ("frequency", &m.frequency),
                ("period", &m.period),
                ("phase", &m.phase),
            ] {
                if let Some(v) = v
                    && matches!(v.get_ref(), ScalarOrVec3::Vector(_))
                {
                    let d = b
                        .diag(
                            Some(v.span()),
                            &k(key),
                            format!("an orbit takes one `{key}`, not one per axis"),
                        )
                        .expected("a single number")
                        .hint(format!("write e.g. `{key} = 0.2`"));
                    b.push(d);
                }
            }
            let f = frequency_of(b, m, &k("frequency"))[0];
            let (e1, e2) = match m.plane.unwrap_or(PlaneSpec::Xz) {
                PlaneSpec::Xy => (Vec3::x(), Vec3::y()),
                PlaneSpec::Xz => (Vec3::x(), Vec3::z()),
                PlaneSpec::Yz => (Vec3::y(), Vec3::z()),
            };
            let phase = m
                .phase
                .as_ref()
                .map(|p| finite3(b, p, &k("phase"), "deg")[0])
                .unwrap_or(0.0)
                .to_radians();
            Motion::CircularOrbit {
                centre,
                radius,
                frequency: f,
                phase,
                e1,
                e2,
                ramp,
            }
        }
        MotionKind::TimeSeries => {
            let table_key = k(if m.file.is_some() { "file" } else { "table" });
            let rows: Option<(Vec<[f64; 4]>, Option<Range<usize>>)> = match (&m.table, &m.file) {
                (Some(t), None) => Some((t.get_ref().clone(), Some(t.span()))),
                (None, Some(f)) => {
                    let path = b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref());
                    match read_table::<4>(&path, "t, x, y, z") {
                        Ok(rows) => Some((rows, Some(f.span()))),
                        Err(msg) => {
                            let d = b
                                .diag(Some(f.span()), &k("file"), msg)
                                .expected("a CSV file with columns t [s], x, y, z [m]")
                                .hint(path_hint(f.get_ref()));
                            b.push(d);
                            None
                        }
                    }
                }
                (Some(t), Some(_)) => {
                    let d = b.diag(
                        Some(t.span()),
                        &k("table"),
                        "give either `table` or `file`, not both",
                    );
                    b.push(d);
                    None
                }
                (None, None) => {
                    required(b, "table", "rows [t, x, y, z] in s and m, or `file`");
                    None
                }
            };
            match rows {
                Some((rows, span)) => {
                    if rows.is_empty()
                        || !rows.windows(2).all(|w| w[1][0] > w[0][0])
                        || rows.iter().flatten().any(|x| !x.is_finite())
                    {
                        let d = b.diag(span, &k("table"), "the time series needs at least one row and strictly increasing times").expected("rows [t, x, y, z] in s and m").hint("sort the rows by time, e.g. `table = [[0.0, 0.0, 0.0, -10.0], [10.0, 5.0, 0.0, -10.0]]`");
                        b.push(d);
                        Motion::Fixed { position: centre }
                    } else if !rows.iter().all(|r| b.physical(span.clone(), &table_key, r)) {
                        Motion::Fixed { position: centre }
                    } else {
                        Motion::TimeSeries {
                            times: rows.iter().map(|r| r[0]).collect(),
                            positions: rows.iter().map(|r| Vec3::new(r[1], r[2], r[3])).collect(),
                        }
                    }
                }
                None => Motion::Fixed { position: centre },
            }
        }
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao => unreachable!(),
    }
}

/// The trajectory of a point fixed on a vessel at `on_vessel` (vessel axes, from the vessel
/// origin: its position when the vessel is at rest at the global origin) from the vessel's
/// motion rows [t, x, y, z, roll, pitch, yaw] (s, m, deg): r(t) = X(t) + R(t)·r0 with
/// R = R_z(yaw)·R_y(pitch)·R_x(roll), the rows' times shifted by `time_offset`, each channel
/// interpolated by a not-a-knot cubic spline ([`RigidTimeSeries`]: velocities and
/// accelerations of the point are exact for the interpolated motion). The rows must have
/// finite values and strictly increasing times.
pub fn vessel_point_motion(
    rows: &[[f64; 7]],
    on_vessel: Vec3,
    time_offset: f64,
) -> Result<Motion, hawser::ModelError> {
    Ok(Motion::Rigid {
        motion: Box::new(RigidMotion::TimeSeries(vessel_time_series(
            rows,
            time_offset,
        )?)),
        offset: on_vessel,
    })
}

/// The 6-DOF table of a vessel-motion file's rows [t, x, y, z, roll, pitch, yaw] (s, m, deg),
/// times shifted by `time_offset` [s].
fn vessel_time_series(
    rows: &[[f64; 7]],
    time_offset: f64,
) -> Result<RigidTimeSeries, hawser::ModelError> {
    RigidTimeSeries::new(
        rows.iter().map(|r| r[0] + time_offset).collect(),
        &rows
            .iter()
            .map(|r| Vec3::new(r[1], r[2], r[3]))
            .collect::<Vec<_>>(),
        &rows
            .iter()
            .map(|r| [r[4].to_radians(), r[5].to_radians(), r[6].to_radians()])
            .collect::<Vec<_>>(),
    )
}

/// Every key of a motion table: (name, given, span).
fn motion_keys(m: &MotionSpec) -> [(&'static str, bool, Option<Range<usize>>); 23] {
    [
        ("velocity", m.velocity.is_some(), span_of(&m.velocity)),
        ("amplitude", m.amplitude.is_some(), span_of(&m.amplitude)),
        ("period", m.period.is_some(), span_of(&m.period)),
        ("frequency", m.frequency.is_some(), span_of(&m.frequency)),
        ("phase", m.phase.is_some(), span_of(&m.phase)),
        ("radius", m.radius.is_some(), span_of(&m.radius)),
        ("ramp_time", m.ramp_time.is_some(), span_of(&m.ramp_time)),
        ("plane", m.plane.is_some(), Some(m.kind.span())),
        ("table", m.table.is_some(), span_of(&m.table)),
        ("file", m.file.is_some(), span_of(&m.file)),
        (
            "time_offset",
            m.time_offset.is_some(),
            span_of(&m.time_offset),
        ),
        ("start", m.start.is_some(), span_of(&m.start)),
        ("heading", m.heading.is_some(), span_of(&m.heading)),
        ("speed", m.speed.is_some(), span_of(&m.speed)),
        (
            "speed_knots",
            m.speed_knots.is_some(),
            span_of(&m.speed_knots),
        ),
        (
            "straight_before",
            m.straight_before.is_some(),
            span_of(&m.straight_before),
        ),
        (
            "turn_radius",
            m.turn_radius.is_some(),
            span_of(&m.turn_radius),
        ),
        ("turn_angle", m.turn_angle.is_some(), span_of(&m.turn_angle)),
        (
            "straight_after",
            m.straight_after.is_some(),
            span_of(&m.straight_after),
        ),
        (
            "build_up_time",
            m.build_up_time.is_some(),
            span_of(&m.build_up_time),
        ),
        (
            "transition_length",
            m.transition_length.is_some(),
            span_of(&m.transition_length),
        ),
        (
            "mean",
            m.mean.is_some(),
            m.mean.as_ref().map(|x| x.kind.span()),
        ),
        ("type", true, Some(m.kind.span())),
    ]
}

/// Reports every key of motion table `m` (at `key`) that its type does not take.
fn reject_keys(b: &mut Builder, m: &MotionSpec, key: &str, allowed: &[&str]) {
    let kind = *m.kind.get_ref();
    for (name, is, span) in motion_keys(m) {
        if is && name != "type" && !allowed.contains(&name) {
            let d = b
                .diag(
                    span,
                    &format!("{key}.{name}"),
                    format!(
                        "`{name}` does not apply to a `{}` motion",
                        motion_name(kind)
                    ),
                )
                .hint(format!(
                    "this motion takes: {}",
                    if allowed.is_empty() {
                        "no parameters".into()
                    } else {
                        allowed.join(", ")
                    }
                ));
            b.push(d);
        }
    }
}

/// One knot in m/s.
const KNOT: f64 = 1852.0 / 3600.0;

/// The rigid-body motion of a vessel (or a prescribed body) from motion table `m` at `key`:
/// `fixed` and `constant-velocity` (the vessel origin at `start`, default the global origin,
/// with `heading`, default 0), `manoeuvre`, `vessel-motion` (6-DOF file) and `rao` (RAO table
/// file on a `mean` motion, driven by `env`'s waves). Every problem is collected in `b`;
/// after an error the returned motion is a harmless placeholder. Reused by `[bodies.motion]`.
pub(super) fn build_rigid_motion(
    b: &mut Builder,
    m: &MotionSpec,
    key: &str,
    env: &Environment,
) -> RigidMotion {
    let k = |x: &str| format!("{key}.{x}");
    let kind = *m.kind.get_ref();
    let allowed: &[&str] = match kind {
        MotionKind::Fixed => &["start", "heading"],
        MotionKind::ConstantVelocity => &["start", "heading", "velocity"],
        MotionKind::Manoeuvre => &[
            "start",
            "heading",
            "speed",
            "speed_knots",
            "straight_before",
            "turn_radius",
            "turn_angle",
            "straight_after",
            "build_up_time",
            "transition_length",
        ],
        MotionKind::VesselMotion => &["file", "time_offset"],
        MotionKind::Rao => &["file", "mean", "start", "heading"],
        MotionKind::Sinusoid | MotionKind::CircularOrbit | MotionKind::TimeSeries => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("type"),
                    format!(
                        "`{}` is a point motion, not a motion of a vessel or body",
                        motion_name(kind)
                    ),
                )
                .expected(
                    "`fixed`, `constant-velocity`, `manoeuvre`, `vessel-motion` or `rao`",
                )
                .hint("a vessel's 6-DOF history can be given with `vessel-motion` (a file of t, x, y, z, roll, pitch, yaw)");
            b.push(d);
            return RigidMotion::Fixed {
                position: Vec3::zeros(),
                orientation: Quat::identity(),
            };
        }
    };
    reject_keys(b, m, key, allowed);
    let start = m
        .start
        .as_ref()
        .map(|v| b.vec3(v, &k("start")))
        .unwrap_or_else(Vec3::zeros);
    let heading = b
        .opt(
            &m.heading,
            &k("heading"),
            0.0,
            Check {
                ok: |_| true,
                expected: "deg, finite",
            },
            "the vessel's heading from +x toward +y",
        )
        .to_radians();
    let orientation = Quat::from_axis_angle(&Vec3::z_axis(), heading);
    let placeholder = RigidMotion::Fixed {
        position: start,
        orientation,
    };
    let required = |b: &mut Builder, name: &str, unit: &str, hint: &str| {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k(name),
                format!("a `{}` motion needs `{name}`", motion_name(kind)),
            )
            .value("")
            .expected(unit.to_string())
            .hint(hint.to_string());
        b.push(d);
    };
    let file_path = |b: &Builder, f: &Spanned<String>| {
        b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref())
    };
    match kind {
        MotionKind::Fixed => placeholder,
        MotionKind::ConstantVelocity => match &m.velocity {
            Some(v) => RigidMotion::ConstantVelocity {
                start,
                orientation,
                velocity: b.vec3(v, &k("velocity")),
            },
            None => {
                required(
                    b,
                    "velocity",
                    "[vx, vy, vz] in m/s",
                    "add `velocity = [vx, vy, vz]`",
                );
                placeholder
            }
        },
        MotionKind::Manoeuvre => build_manoeuvre(b, m, key, start, heading).unwrap_or(placeholder),
        MotionKind::VesselMotion => {
            let offset = b.opt(
                &m.time_offset,
                &k("time_offset"),
                0.0,
                Check {
                    ok: |_| true,
                    expected: "s, finite",
                },
                "added to the file's times",
            );
            let Some(f) = &m.file else {
                required(
                    b,
                    "file",
                    "a file with columns t, x, y, z, roll, pitch, yaw [s, m, deg]",
                    "add `file = \"vessel_motion.txt\"` (relative to the scenario file)",
                );
                return placeholder;
            };
            let rows = match read_table::<7>(&file_path(b, f), "t, x, y, z, roll, pitch, yaw") {
                Ok(rows) => rows,
                Err(msg) => {
                    let d = b
                        .diag(Some(f.span()), &k("file"), msg)
                        .expected("columns t [s], x, y, z [m], roll, pitch, yaw [deg]")
                        .hint(path_hint(f.get_ref()));
                    b.push(d);
                    return placeholder;
                }
            };
            if !rows
                .iter()
                .all(|r| b.physical(Some(f.span()), &k("file"), r))
            {
                return placeholder;
            }
            match vessel_time_series(&rows, offset) {
                Ok(s) if !rows.is_empty() => RigidMotion::TimeSeries(s),
                _ => {
                    let d = b
                        .diag(
                            Some(f.span()),
                            &k("file"),
                            "the vessel motion needs at least one row and strictly increasing times",
                        )
                        .expected("rows t, x, y, z, roll, pitch, yaw in s, m and deg")
                        .hint("sort the rows by time and remove repeated times");
                    b.push(d);
                    placeholder
                }
            }
        }
        MotionKind::Rao => {
            let mean = match &m.mean {
                Some(mean) => {
                    for (name, v) in [
                        ("start", span_of(&m.start)),
                        ("heading", span_of(&m.heading)),
                    ] {
                        if let Some(span) = v {
                            let d = b
                                .diag(
                                    Some(span),
                                    &k(name),
                                    format!("`{name}` is given both here and by the `mean` motion"),
                                )
                                .hint(format!("give `{name}` in the `mean` table only"));
                            b.push(d);
                        }
                    }
                    if !matches!(
                        mean.kind.get_ref(),
                        MotionKind::Fixed | MotionKind::ConstantVelocity | MotionKind::Manoeuvre
                    ) {
                        let d = b
                            .diag(
                                Some(mean.kind.span()),
                                &k("mean.type"),
                                format!(
                                    "a vessel's mean motion cannot be `{}`",
                                    motion_name(*mean.kind.get_ref())
                                ),
                            )
                            .expected("`fixed`, `constant-velocity` or `manoeuvre`")
                            .hint("the wave-frequency motion comes from the RAOs; the mean motion is the slow one");
                        b.push(d);
                        placeholder.clone()
                    } else {
                        build_rigid_motion(b, mean, &k("mean"), env)
                    }
                }
                None => placeholder.clone(),
            };
            let Some(f) = &m.file else {
                required(
                    b,
                    "file",
                    "an RAO table file (docs/motions.md)",
                    "add `file = \"vessel_raos.csv\"` (relative to the scenario file)",
                );
                return placeholder;
            };
            let table = match read_rao_table(&file_path(b, f)) {
                Ok(t) => t,
                Err(msg) => {
                    let d = b
                        .diag(Some(f.span()), &k("file"), msg)
                        .expected(
                            "a header `period_s` (or `frequency_hz`, `omega_rad_s`), \
                             `heading_deg`, then amplitude and phase of surge, sway, heave \
                             [m/m, deg], roll, pitch, yaw [deg/m, deg]: 14 columns",
                        )
                        .hint(format!(
                            "docs/motions.md describes the RAO file; {}",
                            path_hint(f.get_ref())
                        ));
                    b.push(d);
                    return placeholder;
                }
            };
            match RaoMotion::new(table, &env.waves, mean) {
                Ok(r) => RigidMotion::Rao(Box::new(r)),
                Err(e) => {
                    let d = b.diag(Some(f.span()), &k("file"), e.to_string());
                    b.push(d);
                    placeholder
                }
            }
        }
        MotionKind::Sinusoid | MotionKind::CircularOrbit | MotionKind::TimeSeries => {
            unreachable!()
        }
    }
}

/// The manoeuvre of motion table `m`; `None` after an error.
fn build_manoeuvre(
    b: &mut Builder,
    m: &MotionSpec,
    key: &str,
    start: Vec3,
    heading: f64,
) -> Option<RigidMotion> {
    let k = |x: &str| format!("{key}.{x}");
    let errors = b.errors.len();
    let speed = match (&m.speed, &m.speed_knots) {
        (Some(v), None) => b.num(
            v,
            &k("speed"),
            Check {
                ok: POSITIVE,
                expected: "m/s, > 0",
            },
            "the ship's speed through the water, e.g. 6.17 m/s (12 kn)",
        ),
        (None, Some(v)) => {
            b.num(
                v,
                &k("speed_knots"),
                Check {
                    ok: POSITIVE,
                    expected: "kn, > 0",
                },
                "the ship's speed in knots, e.g. 12",
            ) * KNOT
        }
        (Some(_), Some(v)) => {
            let d = b
                .diag(
                    Some(v.span()),
                    &k("speed_knots"),
                    "give either `speed` [m/s] or `speed_knots` [kn], not both",
                )
                .hint("remove one of them");
            b.push(d);
            1.0
        }
        (None, None) => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("speed"),
                    "a `manoeuvre` motion needs `speed` [m/s] or `speed_knots` [kn]",
                )
                .value("")
                .expected("m/s, > 0 (or `speed_knots` in kn)")
                .hint("add e.g. `speed_knots = 12.0`");
            b.push(d);
            1.0
        }
    };
    let length = |b: &mut Builder, v: &Option<Spanned<f64>>, name: &str, hint: &str| {
        b.opt(
            v,
            &k(name),
            0.0,
            Check {
                ok: NON_NEGATIVE,
                expected: "m, ≥ 0",
            },
            hint,
        )
    };
    let straight_before = length(
        b,
        &m.straight_before,
        "straight_before",
        "the distance run on the initial heading before the turn",
    );
    let transition_length = length(
        b,
        &m.transition_length,
        "transition_length",
        "the distance over which the curvature builds up into the turn, e.g. a ship length",
    );
    let straight_after = m.straight_after.as_ref().map(|v| {
        b.num(
            v,
            &k("straight_after"),
            Check {
                ok: NON_NEGATIVE,
                expected: "m, ≥ 0",
            },
            "the distance run after the turn before the vessel stops; omit it to go on for ever",
        )
    });
    let build_up_time = b.opt(
        &m.build_up_time,
        &k("build_up_time"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "a few minutes lets a towed cable stream out without an impulsive start",
    );
    let turn_radius = match &m.turn_radius {
        Some(v) => b.num(
            v,
            &k("turn_radius"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "a ship's tactical diameter is typically 3–5 ship lengths: the radius is half of it",
        ),
        None => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("turn_radius"),
                    "a `manoeuvre` motion needs `turn_radius`",
                )
                .value("")
                .expected("m, > 0")
                .hint("add e.g. `turn_radius = 250.0`");
            b.push(d);
            1.0
        }
    };
    let turn_angle = match &m.turn_angle {
        Some(v) => b
            .num(
                v,
                &k("turn_angle"),
                Check {
                    ok: |x| x.abs() <= Manoeuvre::MAX_TURN_ANGLE.to_degrees(),
                    expected: "deg, from -36000 to 36000 (100 turns; positive to port, negative to starboard)",
                },
                "e.g. 270 for a turn to port through 270°, -90 for a quarter turn to starboard",
            )
            .to_radians(),
        None => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("turn_angle"),
                    "a `manoeuvre` motion needs `turn_angle`",
                )
                .value("")
                .expected("deg, positive to port, negative to starboard")
                .hint("add e.g. `turn_angle = 270.0`; 0 for a straight run");
            b.push(d);
            0.0
        }
    };
    if b.errors.len() > errors {
        return None;
    }
    let shortest = Manoeuvre::MIN_TRANSITION_RATIO * turn_radius;
    if transition_length > 0.0 && transition_length < shortest && turn_angle != 0.0 {
        let d = b
            .diag(
                span_of(&m.transition_length),
                &k("transition_length"),
                "the curvature transitions are too short to resolve",
            )
            .expected(format!(
                "m, 0 or ≥ 1e-6 × turn_radius = {shortest:.3e} m"
            ))
            .hint("write 0 for a curvature that jumps to 1/turn_radius, or a transition of about a ship length");
        b.push(d);
        return None;
    }
    if transition_length > turn_radius * turn_angle.abs() * (1.0 + 1e-12) && turn_angle != 0.0 {
        let d = b
            .diag(
                span_of(&m.transition_length),
                &k("transition_length"),
                "the curvature transitions are longer than the turn",
            )
            .expected(format!(
                "m, ≤ turn_radius × |turn_angle| = {:.1} m",
                turn_radius * turn_angle.abs()
            ))
            .hint("each transition turns the heading by transition_length / (2 turn_radius); shorten them");
        b.push(d);
        return None;
    }
    let spec = ManoeuvreSpec {
        start,
        heading,
        speed,
        straight_before,
        turn_radius,
        turn_angle,
        straight_after,
        build_up_time,
        transition_length,
    };
    match Manoeuvre::new(spec) {
        Ok(man) => Some(RigidMotion::Manoeuvre(Box::new(man))),
        Err(e) => {
            let span = span_of(&m.straight_after).or(Some(m.kind.span()));
            let d = b
                .diag(span, &k("straight_after"), e.to_string())
                .expected(format!(
                    "m, with the whole track ≥ speed × build_up_time = {:.1} m",
                    speed * build_up_time
                ))
                .hint("lengthen `straight_after` or shorten `build_up_time`");
            b.push(d);
            None
        }
    }
}

/// A motion parameter given as one number or one per axis, checked to be finite.
fn finite3(b: &mut Builder, v: &Spanned<ScalarOrVec3>, key: &str, unit: &str) -> [f64; 3] {
    let a = v.get_ref().as_array();
    if a.iter().any(|x| !x.is_finite()) {
        let d = b
            .diag(Some(v.span()), key, format!("`{key}` is not finite"))
            .expected(format!("{unit}, one finite number or [x, y, z]"))
            .hint("nan and inf are not allowed here");
        b.push(d);
        return [0.0; 3];
    }
    if !b.physical(Some(v.span()), key, &a) {
        return [0.0; 3];
    }
    a
}

/// The name of a motion kind as written in scenario files.
fn motion_name(kind: MotionKind) -> &'static str {
    match kind {
        MotionKind::Fixed => "fixed",
        MotionKind::ConstantVelocity => "constant-velocity",
        MotionKind::Sinusoid => "sinusoid",
        MotionKind::CircularOrbit => "circular-orbit",
        MotionKind::TimeSeries => "time-series",
        MotionKind::VesselMotion => "vessel-motion",
        MotionKind::Manoeuvre => "manoeuvre",
        MotionKind::Rao => "rao",
    }
}

fn frequency_of(b: &mut Builder, m: &MotionSpec, key: &str) -> [f64; 3] {
    match (&m.frequency, &m.period) {
        (Some(f), None) => {
            let f3 = f.get_ref().as_array();
            if f3.iter().any(|x| !(x.is_finite() && *x >= 0.0)) {
                let d = b
                    .diag(Some(f.span()), key, "frequency must be ≥ 0")
                    .expected("Hz, ≥ 0")
                    .hint("the frequency of the motion in Hz, e.g. 0.1 for a 10 s period");
                b.push(d);
            } else if !b.physical(Some(f.span()), key, &f3) {
                return [0.0; 3];
            }
            f3
        }
        (None, Some(p)) => {
            let p3 = p.get_ref().as_array();
            if p3.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
                let d = b
                    .diag(
                        Some(p.span()),
                        &key.replace("frequency", "period"),
                        "period must be > 0",
                    )
                    .expected("s, > 0")
                    .hint("the period of the motion in seconds, e.g. 10.0");
                b.push(d);
                return [0.0; 3];
            }
            if !b.physical(Some(p.span()), &key.replace("frequency", "period"), &p3) {
                return [0.0; 3];
            }
            p3.map(|p| 1.0 / p)
        }
        (Some(f), Some(_)) => {
            let d = b.diag(
                Some(f.span()),
                key,
                "give either `frequency` or `period`, not both",
            );
            b.push(d);
            [0.0; 3]
        }
        (None, None) => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    key,
                    "this motion needs `frequency` [Hz] or `period` [s]",
                )
                .expected("`frequency` in Hz, ≥ 0, or `period` in s, > 0")
                .hint("add e.g. `period = 10.0` to the motion table");
            b.push(d);
            [0.0; 3]
        }
    }
}

/// The hint of a motion file that cannot be read: where a relative path starts from.
fn path_hint(file: &str) -> &'static str {
    if Path::new(file).is_absolute() {
        "check the path"
    } else {
        "the path is relative to the scenario file"
    }
}
