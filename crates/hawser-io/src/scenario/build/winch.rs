//! `[lines.winch]`: a winch schedule, checked and converted into [`hawser::model::Winch`].

use super::{Builder, Check, NON_NEGATIVE, POSITIVE, span_of};
use crate::scenario::schema::*;
use hawser::model::{Formulation, Line, Winch, WinchEnd, WinchStage};

/// Builds the winch of `line` (already built, with its sections) from `spec`; every problem
/// becomes a diagnostic under `key` (`lines[i].winch`). `None` when the winch is refused.
pub(super) fn build_winch(
    b: &mut Builder,
    spec: &WinchSpec,
    key: &str,
    line: &Line,
) -> Option<Winch> {
    let k = |x: &str| format!("{key}.{x}");
    if line.sections.is_empty() {
        return None; // the line's own diagnostic says why
    }
    let mut ok = true;
    if line.formulation == Formulation::Dg {
        let d = b
            .diag(
                Some(spec.end.span()),
                key,
                format!(
                    "line `{}` is a `dg` line, which cannot have a winch",
                    line.name
                ),
            )
            .expected("a winch on an `fe` or `hermite` line")
            .hint(
                "a dg line's element lengths are built into its modal operators: use \
                 `formulation = \"fe\"` or `\"hermite\"` for the winch line",
            );
        b.push(d);
        ok = false;
    }
    if line.sections.len() > 1 {
        let d = b
            .diag(
                Some(spec.end.span()),
                key,
                format!(
                    "line `{}` has {} sections; a winch rescales its whole line",
                    line.name,
                    line.sections.len()
                ),
            )
            .expected("a winch on a line of one section")
            .hint(
                "put the winch on a single-section line and join it to the rest by a free \
                 point (mass 0)",
            );
        b.push(d);
        ok = false;
    }
    if spec.stages.is_empty() {
        let d = b
            .diag(
                Some(spec.end.span()),
                &k("stages"),
                "the winch has no stages",
            )
            .expected("at least one `{ duration = s, payout_rate = m/s }`")
            .hint("add e.g. `stages = [{ duration = 60.0, payout_rate = 0.5 }]`");
        b.push(d);
        ok = false;
    }
    let mut stages = Vec::new();
    for (j, s) in spec.stages.iter().enumerate() {
        let sk = |x: &str| format!("{key}.stages[{j}].{x}");
        let errors = b.errors.len();
        let duration = b.num(
            &s.duration,
            &sk("duration"),
            Check {
                ok: POSITIVE,
                expected: "s, > 0",
            },
            "the time the winch runs at this stage's payout rate",
        );
        let rate = *s.payout_rate.get_ref();
        if !rate.is_finite() {
            let d = b
                .diag(
                    Some(s.payout_rate.span()),
                    &sk("payout_rate"),
                    "`payout_rate` is not finite",
                )
                .expected("m/s, finite (> 0 pays out, < 0 hauls in, 0 holds)")
                .hint("give the payout rate of unstretched line");
            b.push(d);
        } else {
            b.physical(Some(s.payout_rate.span()), &sk("payout_rate"), &[rate]);
        }
        ok &= b.errors.len() == errors;
        stages.push(WinchStage {
            duration,
            payout_rate: if rate.is_finite() { rate } else { 0.0 },
        });
    }
    let errors = b.errors.len();
    let ramp_time = b.opt(
        &spec.ramp_time,
        &k("ramp_time"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "the time over which the payout rate changes at the start of each stage",
    );
    let minimum_length = b.opt(
        &spec.minimum_length,
        &k("minimum_length"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "m, ≥ 0",
        },
        "the shortest unstretched length the winch may haul the line in to",
    );
    ok &= b.errors.len() == errors;
    let winch = Winch {
        end: match spec.end.get_ref() {
            LineEndSpec::A => WinchEnd::A,
            LineEndSpec::B => WinchEnd::B,
        },
        stages,
        ramp_time,
        minimum_length,
    };
    if ok && let Some((j, s)) = winch.short_ramped_stage() {
        let d = b
            .diag(
                span_of(&spec.ramp_time),
                &k("ramp_time"),
                format!(
                    "`ramp_time` ({ramp_time} s) is longer than stage {j} ({} s), which \
                     changes the payout rate",
                    s.duration
                ),
            )
            .value(ramp_time.to_string())
            .expected(format!(
                "s, ≤ the duration of every stage that changes the rate ({} s here)",
                s.duration
            ))
            .hint("each change of rate must end within its stage: shorten the ramp or lengthen the stage");
        b.push(d);
        ok = false;
    }
    if !ok {
        return None;
    }
    let length = line.length();
    let ((low, at), _) = winch.payout_range();
    let shortest = length + low;
    if !(shortest > minimum_length) || !(shortest > 0.0) {
        // The stage running at that time (the last if after the schedule).
        let mut start = 0.0;
        let mut j = winch.stages.len() - 1;
        for (i, s) in winch.stages.iter().enumerate() {
            if at <= start + s.duration {
                j = i;
                break;
            }
            start += s.duration;
        }
        let d = b
            .diag(
                Some(spec.stages[j].payout_rate.span()),
                &format!("{key}.stages[{j}].payout_rate"),
                format!(
                    "the winch hauls line `{}` in from {length} m to {shortest:.4} m at \
                     t = {at:.3} s, not above its minimum length",
                    line.name
                ),
            )
            .expected(format!(
                "an unstretched length > {minimum_length} m (`minimum_length`) and > 0 at all times"
            ))
            .hint(format!(
                "haul in at most {:.4} m in all: shorten stage {j}, lower its rate, or \
                 lengthen the line",
                length - minimum_length
            ));
        b.push(d);
        return None;
    }
    Some(winch)
}
