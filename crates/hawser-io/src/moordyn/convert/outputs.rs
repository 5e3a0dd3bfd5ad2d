//! OUTPUTS: MoorDyn channel names into labelled hawser channels.

use super::{Converter, spanned};
use super::{line_name, point_name};
use crate::moordyn::deck::Section;
use crate::scenario::schema::*;
use toml::Spanned;

/// OUTPUTS: MoorDyn channel names become labelled hawser channels.
pub(super) fn convert_outputs(
    c: &mut Converter,
    s: &Section,
    lines: &[LineSpec],
    bodies: &[(String, bool)],
) -> Vec<Spanned<String>> {
    let segments = |line: &str| {
        lines
            .iter()
            .find(|l| l.name.get_ref() == line)
            .and_then(|l| l.elements.as_ref().map(|n| *n.get_ref() as usize))
    };
    let mut out = Vec::new();
    for row in &s.rows {
        for t in &row.tokens {
            let body = |name: &str| bodies.iter().find(|b| b.0 == name).map(|b| b.1);
            match output_channel(&t.text, segments, body) {
                Ok(spec) => {
                    if spec.ends_with(".wx") || spec.ends_with(".wy") || spec.ends_with(".wz") {
                        let line = c.line_of(&t.span);
                        c.note(
                            line,
                            format!(
                                "output `{}`: hawser's angular velocity is in rad/s, MoorDyn's in deg/s",
                                t.text
                            ),
                        );
                    }
                    if spec.ends_with(".roll") || spec.ends_with(".pitch") || spec.ends_with(".yaw")
                    {
                        let line = c.line_of(&t.span);
                        c.note(
                            line,
                            format!(
                                "output `{}`: hawser's roll, pitch, yaw are the angles of \
                                 R = R_z R_y R_x, MoorDyn's of R = R_x R_y R_z; they differ at \
                                 second order when the body turns about two axes",
                                t.text
                            ),
                        );
                    }
                    out.push(spanned(t, format!("{} = {spec}", t.text)))
                }
                Err(msg) => {
                    let d = c
                        .diag(Some(t.span.clone()), "OUTPUTS", msg)
                        .expected(
                            "FairTen#, AnchTen#, L#N#PX|PY|PZ|VX|VY|VZ|T, P#PX|PY|PZ|VX|VY|VZ, \
                             B#PX|PY|PZ|RX|RY|RZ|VX|VY|VZ|RVX|RVY|RVZ",
                        )
                        .hint("# is the line, node or point number, e.g. FairTen1, L1N20T, P4PZ");
                    c.errors.push(d);
                }
            }
        }
    }
    out
}

/// The hawser channel of a MoorDyn output name (case-insensitive, as in MoorDyn-C 2.7's
/// `decomposeString`); `segments` gives a line's segment count by its scenario name, `body`
/// whether a body (by its scenario name) is free (`None`: no such body).
/// The tension `T` of an end node is MoorDyn's |Fnet| of that node (`node_force`).
pub fn output_channel(
    name: &str,
    segments: impl Fn(&str) -> Option<usize>,
    body: impl Fn(&str) -> Option<bool>,
) -> Result<String, String> {
    let u = name.to_uppercase();
    let split_num = |s: &str| -> Option<(String, String)> {
        let digits: String = s.chars().take_while(|ch| ch.is_ascii_digit()).collect();
        (!digits.is_empty()).then(|| (digits.clone(), s[digits.len()..].to_string()))
    };
    for (prefix, end) in [("FAIRTEN", "end_b"), ("ANCHTEN", "end_a")] {
        if let Some(rest) = u.strip_prefix(prefix) {
            return match split_num(rest) {
                Some((n, tail)) if tail.is_empty() => {
                    let line = line_name(&n);
                    if segments(&line).is_none() {
                        return Err(format!("`{name}`: there is no line {n}"));
                    }
                    Ok(format!("{line}.{end}.node_force"))
                }
                _ => Err(format!("`{name}` is not {prefix}<line number>")),
            };
        }
    }
    let quantity = |q: &str| -> Option<&'static str> {
        Some(match q {
            "PX" => "x",
            "PY" => "y",
            "PZ" => "z",
            "VX" => "vx",
            "VY" => "vy",
            "VZ" => "vz",
            "T" | "TEN" => "tension",
            "FX" => "fx",
            "FY" => "fy",
            "FZ" => "fz",
            _ => return None,
        })
    };
    let line_rest = u
        .strip_prefix("LINE")
        .or_else(|| u.strip_prefix('L'))
        .and_then(split_num);
    if let Some((l, tail)) = line_rest {
        let line = line_name(&l);
        let Some(n) = segments(&line) else {
            return Err(format!("`{name}`: there is no line {l}"));
        };
        let form =
            || format!("`{name}`: a line channel is L<line>N<node><quantity>, e.g. L{l}N{n}T");
        let tail = tail
            .strip_prefix("NODE")
            .or_else(|| tail.strip_prefix('N'))
            .ok_or_else(form)?;
        let (node, q) = if let Some(q) = tail.strip_prefix('A') {
            (0, q.to_string())
        } else if let Some(q) = tail.strip_prefix('B') {
            (n, q.to_string())
        } else {
            let (k, q) = split_num(tail).ok_or_else(form)?;
            (k.parse::<usize>().map_err(|_| form())?, q)
        };
        if node > n {
            return Err(format!("`{name}`: line {l} has nodes 0 … {n}"));
        }
        let end = if node == 0 {
            Some("end_a")
        } else if node == n {
            Some("end_b")
        } else {
            None
        };
        return match (quantity(&q), end) {
            (Some("tension"), Some(e)) => Ok(format!("{line}.{e}.node_force")),
            (Some(f @ ("fx" | "fy" | "fz")), Some(e)) => Ok(format!("{line}.{e}.{f}")),
            (Some("fx" | "fy" | "fz"), None) => Err(format!(
                "`{name}`: node forces are available at the line ends (N0 and N{n}) only"
            )),
            (Some(q), _) => Ok(format!("{line}.node{node}.{q}")),
            (None, _) => Err(format!(
                "`{name}`: line node quantity `{q}` is not available (PX, PY, PZ, VX, VY, VZ, T)"
            )),
        };
    }
    let point_rest = u
        .strip_prefix("POINT")
        .or_else(|| u.strip_prefix('P'))
        .and_then(split_num);
    if let Some((p, q)) = point_rest {
        return match quantity(&q).filter(|q| *q != "tension") {
            Some(q) => Ok(format!("{}.{q}", point_name(&p))),
            None => Err(format!(
                "`{name}`: point quantity `{q}` is not available (PX, PY, PZ, VX, VY, VZ, FX, FY, FZ)"
            )),
        };
    }
    if u.starts_with("CON") || u.starts_with('C') {
        return Err(format!(
            "`{name}`: MoorDyn v2 names point channels P<point><quantity> (Con/C are v1 names)"
        ));
    }
    let body_rest = u
        .strip_prefix("BODY")
        .or_else(|| u.strip_prefix('B'))
        .and_then(split_num);
    if let Some((b, q)) = body_rest {
        let scenario_name = super::body_name(&b);
        let Some(free) = body(&scenario_name) else {
            return Err(format!("`{name}`: there is no body {b}"));
        };
        let channel = match q.as_str() {
            "PX" => "x",
            "PY" => "y",
            "PZ" => "z",
            "RX" => "roll",
            "RY" => "pitch",
            "RZ" => "yaw",
            "VX" => "vx",
            "VY" => "vy",
            "VZ" => "vz",
            "RVX" => "wx",
            "RVY" => "wy",
            "RVZ" => "wz",
            "FX" | "FY" | "FZ" | "MX" | "MY" | "MZ" if !free => {
                return Ok(format!("{scenario_name}.{}", q.to_lowercase()));
            }
            "FX" | "FY" | "FZ" | "MX" | "MY" | "MZ" => {
                return Err(format!(
                    "`{name}`: MoorDyn's force on a free body is the net of its weight, \
                     buoyancy, drag and lines; hawser records the lines' load on it \
                     (`{scenario_name}.fx` … `.mz` in a scenario), a different quantity"
                ));
            }
            _ => {
                return Err(format!(
                    "`{name}`: body quantity `{q}` is not available (PX, PY, PZ, RX, RY, RZ, VX, \
                     VY, VZ, RVX, RVY, RVZ; FX … MZ of fixed and coupled bodies)"
                ));
            }
        };
        return Ok(format!("{scenario_name}.{channel}"));
    }
    if u.starts_with('R') {
        return Err(format!("`{name}`: rod channels are not available"));
    }
    Err(format!("unknown MoorDyn output channel `{name}`"))
}
