//! MoorDyn's FAILURE section (v2) as `[lines.failure]` tables (one line) and `[[failures]]`
//! tables (several lines).
//!
//! A row `FailureID  Point  Line(s)  FailTime  FailTen` releases the listed lines' ends at the
//! point (a point ID or a rod end R#A/R#B) at FailTime [s] or when the attachment tension
//! reaches FailTen [N], whichever comes first; 0 switches a trigger off. In MoorDyn the
//! released ends are attached to ONE new free point at the point's place and velocity
//! (MoorDyn2.cpp `detachLines`), so several lines of one row stay joined: one line is
//! hawser's release of one line end, several are a `[[failures]]` table whose ends share one
//! free point (docs/failure.md). docs/moordyn.md has the map, and what MoorDyn-C 2.7 itself
//! does with the row.

use super::{Converter, line_name, point_name, spanned};
use crate::moordyn::deck::{Section, Token};
use crate::scenario::schema::*;

const S: &str = "FAILURE";

/// The scenario name of the FAILURE row's Point column: `P#` for a point ID (3, P3, Point3,
/// C3, Con3), `R#A`/`R#B` for a rod end; `None` for neither.
fn attachment_name(tok: &Token) -> Option<String> {
    let w = tok.text.to_lowercase();
    if let Some(n) = ["point", "con", "p", "c"]
        .iter()
        .find_map(|p| w.strip_prefix(p).filter(|r| r.parse::<u64>().is_ok()))
        .or_else(|| w.parse::<u64>().is_ok().then_some(w.as_str()))
    {
        return Some(point_name(n));
    }
    ["rod", "r"].iter().find_map(|p| {
        let rest = w.strip_prefix(p)?;
        let digits = rest.trim_end_matches(['a', 'b']);
        let end = &rest[digits.len()..];
        (digits.parse::<u64>().is_ok() && (end == "a" || end == "b"))
            .then(|| format!("R{digits}{}", end.to_uppercase()))
    })
}

/// Sets the `failure` of the lines a one-line FAILURE row names, and adds a `[[failures]]`
/// table to `joined` for each row of several lines.
pub(super) fn convert_failures(
    c: &mut Converter,
    s: &Section,
    lines: &mut [LineSpec],
    joined: &mut Vec<JoinedFailureSpec>,
) {
    for row in &s.rows {
        let t = &row.tokens;
        // FailureID Point Line[,Line...] FailTime FailTen: the lexer splits the line list at
        // its commas.
        if t.len() < 5 {
            let end = row.span.end;
            let d = c
                .diag(
                    Some(end..end),
                    S,
                    format!("this {S} row has {} columns", t.len()),
                )
                .value(c.source[row.span.clone()].trim().to_string())
                .expected("FailureID Point Line(s) FailTime FailTen, e.g. `1 5 2 0 1.2e6`")
                .hint("give every column; FailTime and FailTen take 0 for no trigger");
            c.errors.push(d);
            continue;
        }
        let id = &t[0].text;
        let at = |col: &str| format!("{S} › {id} › {col}");
        let (time_tok, tension_tok) = (&t[t.len() - 2], &t[t.len() - 1]);
        let line_toks = &t[2..t.len() - 2];
        let Some(point) = attachment_name(&t[1]) else {
            let d = c
                .diag(
                    Some(t[1].span.clone()),
                    &at("Point"),
                    format!("`{}` is not a point or a rod end", t[1].text),
                )
                .expected("a point ID (5, P5, Point5) or a rod end (R1A, R1B)")
                .hint("a failure releases the lines attached at a point or rod end");
            c.errors.push(d);
            continue;
        };
        let trigger = |c: &mut Converter, tok: &Token, col: &str, unit: &str| {
            let x = c.number(tok, &format!("{S} › {id}"), col, unit)?;
            if !(x >= 0.0) {
                let d = c
                    .diag(
                        Some(tok.span.clone()),
                        &at(col),
                        format!("{col} {} is negative", tok.text),
                    )
                    .expected(format!("{unit}, ≥ 0 (0: no {col} trigger)"))
                    .hint("give the release time or tension, or 0 to switch it off");
                c.errors.push(d);
                return None;
            }
            (x > 0.0).then(|| spanned(tok, x))
        };
        let time = trigger(c, time_tok, "FailTime", "s");
        let tension = trigger(c, tension_tok, "FailTen", "N");
        if line_toks.len() > 1 {
            if let Some(f) = joined_row(
                c,
                row.line,
                id,
                &t[1],
                &point,
                line_toks,
                lines,
                (time, tension),
            ) {
                c.name_key(format!("failures[{}]", joined.len()), format!("{S} › {id}"));
                joined.push(f);
            }
            continue;
        }
        let line_tok = &line_toks[0];
        let Some(k) = find_line(c, id, line_tok, lines) else {
            continue;
        };
        let line = &mut lines[k];
        let end = if line.end_a.get_ref() == &point {
            LineEndSpec::A
        } else if line.end_b.get_ref() == &point {
            LineEndSpec::B
        } else {
            let d = c
                .diag(
                    Some(t[1].span.clone()),
                    &at("Point"),
                    format!(
                        "failure {id}: line {} is not attached to {} (its ends are at {} and {})",
                        line_tok.text,
                        t[1].text,
                        line.end_a.get_ref(),
                        line.end_b.get_ref()
                    ),
                )
                .expected("the point or rod end one of the line's ends is attached to")
                .hint("a failure releases a line at a point it is attached to");
            c.errors.push(d);
            continue;
        };
        let in_joined = joined
            .iter()
            .any(|f| f.lines.iter().any(|n| n.get_ref() == line.name.get_ref()));
        if line.failure.is_some() || in_joined {
            let d = c
                .diag(
                    Some(line_tok.span.clone()),
                    &at("Lines"),
                    format!("line {} fails in two rows", line_tok.text),
                )
                .expected("one failure per line")
                .hint("hawser releases one end of a line: keep one of the rows");
            c.errors.push(d);
            continue;
        }
        if time.is_none() && tension.is_none() {
            c.note(
                row.line,
                format!(
                    "failure {id}: FailTime and FailTen are 0, so line {} releases only on a \
                     host's call",
                    line_tok.text
                ),
            );
        }
        c.name_key(format!("lines[{k}].failure"), format!("{S} › {id}"));
        line.failure = Some(FailureSpec {
            end: spanned(&t[1], end),
            time,
            tension,
            at_breaking_load: None,
        });
    }
}

/// The index of the line a FAILURE row's line token names; a diagnostic when there is none.
fn find_line(c: &mut Converter, id: &str, tok: &Token, lines: &[LineSpec]) -> Option<usize> {
    let name = match tok.text.parse::<u64>() {
        Ok(n) => line_name(&n.to_string()),
        Err(_) => line_name(&tok.text),
    };
    let k = lines.iter().position(|l| l.name.get_ref() == &name);
    if k.is_none() {
        let ids: Vec<&str> = lines.iter().map(|l| &l.name.get_ref()[1..]).collect();
        let d = c
            .diag(
                Some(tok.span.clone()),
                &format!("{S} › {id} › Lines"),
                format!(
                    "failure {id} names line {}, which is not in the LINES table",
                    tok.text
                ),
            )
            .expected(format!("a line ID: {}", ids.join(", ")))
            .hint("correct the line ID");
        c.errors.push(d);
    }
    k
}

/// A FAILURE row of several lines as a `[[failures]]` table: the lines' ends at `point` (the
/// scenario name of the row's Point column `point_tok`) release together onto one free point
/// and stay joined, as in MoorDyn. `None` (with diagnostics) when a line is unknown, not at the
/// point, listed twice or already failing in another row.
#[allow(clippy::too_many_arguments)]
fn joined_row(
    c: &mut Converter,
    row_line: usize,
    id: &str,
    point_tok: &Token,
    point: &str,
    line_toks: &[Token],
    lines: &[LineSpec],
    (time, tension): (Option<toml::Spanned<f64>>, Option<toml::Spanned<f64>>),
) -> Option<JoinedFailureSpec> {
    let errors = c.errors.len();
    let mut names = Vec::new();
    for tok in line_toks {
        let Some(k) = find_line(c, id, tok, lines) else {
            continue;
        };
        let line = &lines[k];
        let at = format!("{S} › {id} › Lines");
        if line.end_a.get_ref() != point && line.end_b.get_ref() != point {
            let d = c
                .diag(
                    Some(tok.span.clone()),
                    &at,
                    format!(
                        "failure {id}: line {} is not attached to {} (its ends are at {} and {})",
                        tok.text,
                        point_tok.text,
                        line.end_a.get_ref(),
                        line.end_b.get_ref()
                    ),
                )
                .expected("lines with an end at the row's point or rod end")
                .hint("a failure releases the lines attached at its point");
            c.errors.push(d);
        } else if line.failure.is_some()
            || names
                .iter()
                .any(|n: &toml::Spanned<String>| n.get_ref() == line.name.get_ref())
        {
            let d = c
                .diag(
                    Some(tok.span.clone()),
                    &at,
                    format!("line {} fails twice", tok.text),
                )
                .expected("one failure per line end")
                .hint("keep one of the rows, or list the line once");
            c.errors.push(d);
        } else {
            names.push(spanned(tok, line.name.get_ref().clone()));
        }
    }
    if time.is_none() && tension.is_none() {
        c.note(
            row_line,
            format!(
                "failure {id}: FailTime and FailTen are 0, so its lines release only on a \
                 host's call"
            ),
        );
    }
    (c.errors.len() == errors).then(|| JoinedFailureSpec {
        point: spanned(point_tok, point.to_string()),
        lines: names,
        time,
        tension,
    })
}
