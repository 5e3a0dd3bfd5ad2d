//! `[[lines]]`: sections, formulation, ends and winch, checked and converted into
//! [`hawser::model::Line`].

use super::winch;
use super::{Builder, Check, DEFAULT_DG_ORDER, NON_NEGATIVE, POSITIVE};
use crate::scenario::diagnostics::closest;
use crate::scenario::schema::*;
use hawser::model::*;
use std::collections::HashMap;
use toml::Spanned;

pub(super) fn build_lines(
    b: &mut Builder,
    specs: &[LineSpec],
    types: &HashMap<String, usize>,
    points: &HashMap<String, usize>,
    line_types: &[LineType],
) -> (Vec<Line>, Vec<LineFailure>) {
    let mut out = Vec::new();
    let mut failures = Vec::new();
    let mut names = HashMap::new();
    for (i, l) in specs.iter().enumerate() {
        let k = |key: &str| format!("lines[{i}].{key}");
        let name = l.name.get_ref().clone();
        if let Some(first) = names.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(l.name.span()),
                    &k("name"),
                    format!("line `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each line its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&l.name, &k("name"), "line", "L1.end_b.tension");
        let end = |b: &mut Builder, s: &Spanned<String>, key: &str| -> usize {
            match points.get(s.get_ref()) {
                Some(&p) => p,
                None => {
                    let mut defined: Vec<&str> = points.keys().map(String::as_str).collect();
                    defined.sort();
                    let hint = match closest(s.get_ref(), defined.iter().copied()) {
                        Some(c) => format!("did you mean `{c}`?"),
                        None => format!(
                            "define a [[points]] table with `name = \"{}\"`, or correct the name",
                            s.get_ref()
                        ),
                    };
                    let expected = if defined.is_empty() {
                        "the name of a point; no [[points]] are defined".to_string()
                    } else {
                        format!("the name of a point: {}", defined.join(", "))
                    };
                    let d = b
                        .diag(
                            Some(s.span()),
                            &k(key),
                            format!(
                                "line `{}` is attached to point `{}`, which does not exist",
                                l.name.get_ref(),
                                s.get_ref()
                            ),
                        )
                        .expected(expected)
                        .hint(hint);
                    b.push(d);
                    0
                }
            }
        };
        let end_a = end(b, &l.end_a, "end_a");
        let end_b = end(b, &l.end_b, "end_b");
        if l.end_a.get_ref() == l.end_b.get_ref() {
            let d = b
                .diag(
                    Some(l.end_b.span()),
                    &k("end_b"),
                    "both ends of a line are attached to the same point",
                )
                .hint("attach end B to another point");
            b.push(d);
        }
        let formulation = match l.formulation.as_ref().map(|f| *f.get_ref()) {
            None | Some(FormulationSpec::Fe) => Formulation::Fe,
            Some(FormulationSpec::Hermite) => Formulation::Hermite,
            Some(FormulationSpec::Dg) => Formulation::Dg,
        };
        let mut sections = Vec::new();
        let mut section = |b: &mut Builder,
                           t: &Spanned<String>,
                           length: &Spanned<f64>,
                           elements: &Spanned<i64>,
                           order: &Option<Spanned<i64>>,
                           key: &dyn Fn(&str) -> String| {
            let ti = match types.get(t.get_ref()) {
                Some(&ti) => ti,
                None => {
                    let mut defined: Vec<&str> = types.keys().map(String::as_str).collect();
                    defined.sort();
                    let hint = match closest(t.get_ref(), defined.iter().copied()) {
                        Some(c) => format!("did you mean `{c}`?"),
                        None => format!(
                            "define a [[line_types]] table with `name = \"{}\"`, or correct the name",
                            t.get_ref()
                        ),
                    };
                    let expected = if defined.is_empty() {
                        "the name of a line type; no [[line_types]] are defined".to_string()
                    } else {
                        format!("the name of a line type: {}", defined.join(", "))
                    };
                    let d = b
                        .diag(
                            Some(t.span()),
                            &key("type"),
                            format!("line type `{}` does not exist", t.get_ref()),
                        )
                        .expected(expected)
                        .hint(hint);
                    b.push(d);
                    0
                }
            };
            let len = b.num(
                length,
                &key("length"),
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0 (unstretched)",
                },
                "the unstretched length of this section",
            );
            let n = *elements.get_ref();
            if !(1..=1_000_000).contains(&n) {
                let d = b
                    .diag(
                        Some(elements.span()),
                        &key("elements"),
                        "the element count is out of range",
                    )
                    .expected("an integer from 1 to 1000000")
                    .hint("10–100 elements per line is usual");
                b.push(d);
            }
            let max = hawser::formulation::dg::basis::MAX_ORDER as i64;
            let order = match order {
                None => DEFAULT_DG_ORDER,
                Some(o) if formulation != Formulation::Dg => {
                    let d = b
                        .diag(
                            Some(o.span()),
                            &key("order"),
                            "`order` applies to `dg` lines only",
                        )
                        .expected("no `order` on an `fe` or `hermite` line")
                        .hint("set `formulation = \"dg\"` on the line, or remove `order`");
                    b.push(d);
                    DEFAULT_DG_ORDER
                }
                Some(o) => {
                    if !(1..=max).contains(o.get_ref()) {
                        let d = b
                            .diag(
                                Some(o.span()),
                                &key("order"),
                                "the polynomial order is out of range",
                            )
                            .expected(format!("an integer from 1 to {max}"))
                            .hint("the DG paper uses P = 4; P = 2–6 is usual, cost grows like P²");
                        b.push(d);
                    }
                    (*o.get_ref()).clamp(1, max) as usize
                }
            };
            sections.push(Section {
                line_type: ti,
                length: len,
                elements: n.clamp(1, 1_000_000) as usize,
                order,
            });
        };
        match (&l.line_type, &l.length, &l.elements, l.sections.is_empty()) {
            (Some(t), Some(len), Some(n), true) => section(b, t, len, n, &l.order, &k),
            (None, None, None, false) => {
                for (j, s) in l.sections.iter().enumerate() {
                    let key = |x: &str| format!("lines[{i}].sections[{j}].{x}");
                    section(b, &s.line_type, &s.length, &s.elements, &s.order, &key);
                }
            }
            (None, None, None, true) => {
                let d = b
                    .diag(Some(l.name.span()), &k("sections"), format!("line `{name}` has no sections"))
                    .expected("`type`, `length` [m] and `elements` on the line, or [[lines.sections]] tables")
                    .hint("add e.g. `type = \"chain\"`, `length = 900.0`, `elements = 20`");
                b.push(d);
            }
            (_, _, _, false) => {
                let d = b
                    .diag(
                        Some(l.name.span()),
                        &k("sections"),
                        "give either `type`/`length`/`elements` or [[lines.sections]], not both",
                    )
                    .hint("use sections for lines of several types");
                b.push(d);
            }
            (t, len, n, true) => {
                let missing: Vec<&str> = [
                    ("type", t.is_none()),
                    ("length", len.is_none()),
                    ("elements", n.is_none()),
                ]
                .iter()
                .filter(|x| x.1)
                .map(|x| x.0)
                .collect();
                let d = b
                    .diag(
                        Some(l.name.span()),
                        &k(missing[0]),
                        format!(
                            "line `{name}` is missing {}",
                            missing
                                .iter()
                                .map(|m| format!("`{m}`"))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    )
                    .expected("`type` (a line type name), `length` [m] and `elements`");
                b.push(d);
            }
        }
        out.push(Line {
            name,
            sections,
            formulation,
            mass_matrix: match l.mass_matrix {
                Some(MassMatrixSpec::Lumped) => MassMatrix::Lumped,
                _ => MassMatrix::Consistent,
            },
            strain_measure: match l.strain {
                Some(StrainSpec::SmallStrain) => StrainMeasure::SmallStrain,
                _ => StrainMeasure::Exact,
            },
            modal_filter: b.opt(
                &l.modal_filter,
                &k("modal_filter"),
                hawser::formulation::dg::line::DEFAULT_MODAL_FILTER,
                Check {
                    ok: |x| (0.0..=1.0).contains(&x),
                    expected: "-, 0 to 1 (0: no filter)",
                },
                "the default 0.05 keeps slack dg lines from spurious high-mode velocities; \
                 larger values damp more of the motion (docs/dg.md)",
            ),
            shock_filter: b.opt(
                &l.shock_filter,
                &k("shock_filter"),
                0.0,
                Check {
                    ok: |x| (0.0..=1.0).contains(&x),
                    expected: "-, 0 to 1 (0: off)",
                },
                "0.25 settled the peak of an undamped dg snap with the mesh (docs/dg.md)",
            ),
            clamp: [(&l.clamp_a, "clamp_a"), (&l.clamp_b, "clamp_b")].map(|(c, key)| {
                let c = c.as_ref()?;
                let d = b.vec3(c, &k(key));
                let bad = if formulation == Formulation::Fe {
                    Some("a clamped end needs bending: use `formulation = \"hermite\"` or `\"dg\"`")
                } else if !(d.norm() > 0.0) {
                    Some("give the direction of the line's tangent at that end, e.g. [1, 0, 0]")
                } else {
                    None
                };
                if let Some(hint) = bad {
                    let diag = b
                        .diag(
                            Some(c.span()),
                            &k(key),
                            format!("`{key}` cannot be used here"),
                        )
                        .expected("a non-zero direction [-] on a `hermite` or `dg` line")
                        .hint(hint);
                    b.push(diag);
                }
                Some(d)
            }),
            end_a: LineEnd::Point(end_a),
            end_b: LineEnd::Point(end_b),
            winch: None,
        });
        if let Some(w) = &l.winch {
            let line = out.last_mut().expect("just pushed");
            line.winch = winch::build_winch(b, w, &k("winch"), line);
        }
        if let Some(f) = &l.failure {
            let line = out.last().expect("just pushed");
            if let Some(f) = build_failure(b, f, &k("failure"), i, line, line_types) {
                failures.push(f);
            }
        }
    }
    (out, failures)
}

/// Builds the failure of line `index` (`line`, already built) from `spec`; every problem
/// becomes a diagnostic under `key` (`lines[i].failure`). `None` when it is refused.
fn build_failure(
    b: &mut Builder,
    spec: &FailureSpec,
    key: &str,
    index: usize,
    line: &Line,
    line_types: &[LineType],
) -> Option<LineFailure> {
    let k = |x: &str| format!("{key}.{x}");
    let end = match spec.end.get_ref() {
        LineEndSpec::A => End::A,
        LineEndSpec::B => End::B,
    };
    let errors = b.errors.len();
    let refuse = |b: &mut Builder, message: String, expected: &str, hint: &str| {
        let d = b
            .diag(Some(spec.end.span()), key, message)
            .expected(expected.to_string())
            .hint(hint.to_string());
        b.push(d);
    };
    if line.formulation == Formulation::Dg {
        refuse(
            b,
            format!(
                "line `{}` is a `dg` line, whose ends cannot release",
                line.name
            ),
            "a failure on an `fe` or `hermite` line",
            "a dg line's end conditions are built into its numerical flux: use \
             `formulation = \"fe\"` or `\"hermite\"` for a line that fails",
        );
    }
    if line.clamp[end.index()].is_some() {
        refuse(
            b,
            format!(
                "end {} of line `{}` is clamped",
                end.name().to_uppercase(),
                line.name
            ),
            "a failure at a pinned end",
            "remove the end's `clamp_a`/`clamp_b`, or fail the other end",
        );
    }
    let time = spec.time.as_ref().map(|t| {
        b.num(
            t,
            &k("time"),
            Check {
                ok: NON_NEGATIVE,
                expected: "s, ≥ 0",
            },
            "the time at which the end releases",
        )
    });
    let mut tension = spec.tension.as_ref().map(|t| {
        b.num(
            t,
            &k("tension"),
            Check {
                ok: POSITIVE,
                expected: "N, > 0",
            },
            "the end tension at which the end releases (a breaking load)",
        )
    });
    if let Some(mbl) = spec.at_breaking_load.as_ref().filter(|m| *m.get_ref()) {
        // The section at the failing end.
        let section = match end {
            End::A => line.sections.first(),
            End::B => line.sections.last(),
        };
        let lt = section.and_then(|s| line_types.get(s.line_type));
        match (lt.and_then(|t| t.minimum_breaking_load), tension) {
            (_, Some(_)) => {
                let d = b
                    .diag(
                        Some(mbl.span()),
                        &k("at_breaking_load"),
                        "give either `tension` or `at_breaking_load`, not both",
                    )
                    .expected("one release tension")
                    .hint("remove `tension` to release at the line type's breaking load");
                b.push(d);
            }
            (Some(m), None) => tension = Some(m),
            (None, None) => {
                let d = b
                    .diag(
                        Some(mbl.span()),
                        &k("at_breaking_load"),
                        format!(
                            "line type `{}` has no `minimum_breaking_load`",
                            lt.map_or("?", |t| t.name.as_str())
                        ),
                    )
                    .expected("a line type with `minimum_breaking_load` [N]")
                    .hint("give the line type its `minimum_breaking_load`, or give `tension` [N]");
                b.push(d);
            }
        }
    }
    (b.errors.len() == errors).then_some(LineFailure {
        line: index,
        end,
        joined: vec![],
        time,
        tension,
    })
}

/// Builds the `[[failures]]` tables (line ends at one point released together onto one free
/// point) into `failures`, after the lines' own failures; every problem becomes a diagnostic
/// under `failures[i]`.
pub(super) fn build_joined_failures(
    b: &mut Builder,
    specs: &[JoinedFailureSpec],
    lines: &[Line],
    points: &HashMap<String, usize>,
    failures: &mut Vec<LineFailure>,
) {
    for (i, spec) in specs.iter().enumerate() {
        let k = |key: &str| format!("failures[{i}].{key}");
        let errors = b.errors.len();
        let point_name = spec.point.get_ref();
        let Some(&point) = points.get(point_name) else {
            let mut defined: Vec<&str> = points.keys().map(String::as_str).collect();
            defined.sort();
            let hint = match closest(point_name, defined.iter().copied()) {
                Some(c) => format!("did you mean `{c}`?"),
                None => "give the point the lines' ends are attached to".to_string(),
            };
            let d = b
                .diag(
                    Some(spec.point.span()),
                    &k("point"),
                    format!("failure at point `{point_name}`, which does not exist"),
                )
                .expected(format!("the name of a point: {}", defined.join(", ")))
                .hint(hint);
            b.push(d);
            continue;
        };
        if spec.lines.len() < 2 {
            let span = spec.lines.first().map_or(spec.point.span(), |l| l.span());
            let d = b
                .diag(
                    Some(span),
                    &k("lines"),
                    format!(
                        "a [[failures]] table names {} line{}",
                        spec.lines.len(),
                        if spec.lines.len() == 1 { "" } else { "s" }
                    ),
                )
                .expected("two or more lines with an end at the point")
                .hint("one line end's failure is a `[lines.failure]` table of that line");
            b.push(d);
            continue;
        }
        let mut ends: Vec<(usize, End)> = Vec::new();
        for (j, name) in spec.lines.iter().enumerate() {
            let key = format!("failures[{i}].lines[{j}]");
            let Some(li) = lines.iter().position(|l| &l.name == name.get_ref()) else {
                let names: Vec<&str> = lines.iter().map(|l| l.name.as_str()).collect();
                let hint = match closest(name.get_ref(), names.iter().copied()) {
                    Some(c) => format!("did you mean `{c}`?"),
                    None => "name a [[lines]] table".to_string(),
                };
                let d = b
                    .diag(
                        Some(name.span()),
                        &key,
                        format!("line `{}` does not exist", name.get_ref()),
                    )
                    .expected(format!("the name of a line: {}", names.join(", ")))
                    .hint(hint);
                b.push(d);
                continue;
            };
            let l = &lines[li];
            let at = |e: &LineEnd| matches!(e, LineEnd::Point(p) if *p == point);
            let end = match (at(&l.end_a), at(&l.end_b)) {
                (true, false) => End::A,
                (false, true) => End::B,
                (a, _) => {
                    let why = if a {
                        "both its ends are at the point: which one releases is ambiguous"
                            .to_string()
                    } else {
                        "neither of its ends is at the point".to_string()
                    };
                    let d = b
                        .diag(
                            Some(name.span()),
                            &key,
                            format!(
                                "line `{}` cannot release from point `{point_name}`: {why}",
                                l.name
                            ),
                        )
                        .expected(format!("a line with one end at point `{point_name}`"))
                        .hint(
                            "list the lines whose ends meet at the point; a line's own                              `[lines.failure]` names its end",
                        );
                    b.push(d);
                    continue;
                }
            };
            let refuse = |b: &mut Builder, why: String, hint: &str| {
                let d = b
                    .diag(Some(name.span()), &key, why)
                    .expected("an `fe` or `hermite` line with a pinned end at the point")
                    .hint(hint.to_string());
                b.push(d);
            };
            if ends.contains(&(li, end)) {
                refuse(
                    b,
                    format!("line `{}` is listed twice", l.name),
                    "list each line once",
                );
            } else if failures.iter().any(|f| f.ends().any(|e| e == (li, end))) {
                refuse(
                    b,
                    format!(
                        "end {} of line `{}` already has a failure",
                        end.name().to_uppercase(),
                        l.name
                    ),
                    "one failure per line end: remove its `[lines.failure]` or the other \
                     [[failures]] table that names it",
                );
            } else if l.formulation == Formulation::Dg {
                refuse(
                    b,
                    format!(
                        "line `{}` is a `dg` line, whose ends cannot release",
                        l.name
                    ),
                    "a dg line's end conditions are built into its numerical flux: use \
                     `formulation = \"fe\"` or `\"hermite\"` for a line that fails",
                );
            } else if l.clamp[end.index()].is_some() {
                refuse(
                    b,
                    format!(
                        "end {} of line `{}` is clamped",
                        end.name().to_uppercase(),
                        l.name
                    ),
                    "remove the end's `clamp_a`/`clamp_b`: only a pinned end can release",
                );
            } else {
                ends.push((li, end));
            }
        }
        let time = spec.time.as_ref().map(|t| {
            b.num(
                t,
                &k("time"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "s, ≥ 0",
                },
                "the time at which the ends release",
            )
        });
        let tension = spec.tension.as_ref().map(|t| {
            b.num(
                t,
                &k("tension"),
                Check {
                    ok: POSITIVE,
                    expected: "N, > 0",
                },
                "the magnitude of the ends' summed force on the point at which they release",
            )
        });
        if b.errors.len() == errors {
            let (line, end) = ends[0];
            failures.push(LineFailure {
                line,
                end,
                joined: ends[1..].to_vec(),
                time,
                tension,
            });
        }
    }
}

pub(super) fn check_free_points_held(
    b: &mut Builder,
    specs: &[PointSpec],
    lines: &[Line],
    points: &[Point],
) {
    for (i, p) in points.iter().enumerate() {
        if let PointKind::Free { mass, volume, .. } = p.kind {
            let attached = lines
                .iter()
                .any(|l| l.end_a == LineEnd::Point(i) || l.end_b == LineEnd::Point(i));
            if !attached && mass == 0.0 && volume == 0.0 {
                let d = b
                    .diag(
                        Some(specs[i].name.span()),
                        &format!("points[{i}]"),
                        format!("free point `{}` has no mass, no volume and no line", p.name),
                    )
                    .hint("attach a line to it, give it a mass, or remove it");
                b.push(d);
            }
        }
    }
}
