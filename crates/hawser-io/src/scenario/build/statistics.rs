//! `[statistics]`: the window, storm duration and linked channels of the design statistics,
//! checked into [`hawser::analysis::statistics::StatisticsOptions`].

use super::channels::unknown_channel;
use super::{Builder, Check, NON_NEGATIVE, POSITIVE};
use crate::scenario::schema::*;
use hawser::analysis::statistics::{DEFAULT_STORM_DURATION, StatisticsOptions};
use hawser::analysis::{Channel, OutputChannel};
use hawser::model::*;

/// The statistics options; linked channels not among `model.outputs` are appended to them
/// (recorded), and `linked` holds their column indices among the outputs.
pub(super) fn build_statistics(
    b: &mut Builder,
    spec: Option<&StatisticsSpec>,
    has_simulation: bool,
    model: &mut Model,
) -> StatisticsOptions {
    let mut options = StatisticsOptions::default();
    let Some(spec) = spec else { return options };
    options.start = b.opt(
        &spec.start,
        "statistics.start",
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "the end of the build-up, e.g. 100 s",
    );
    if let Some(start) = &spec.start
        && has_simulation
        && options.start > 0.0
        && options.start >= model.settings.duration
    {
        let d = b
            .diag(
                Some(start.span()),
                "statistics.start",
                format!(
                    "`statistics.start` = {} s leaves at most the last sample of the {} s run",
                    options.start, model.settings.duration
                ),
            )
            .expected(format!(
                "s, ≥ 0 and < simulation.duration = {} s",
                model.settings.duration
            ))
            .hint("start the statistics after the build-up but well before the end");
        b.push(d);
    }
    options.storm_duration = b.opt(
        &spec.storm_duration,
        "statistics.storm_duration",
        DEFAULT_STORM_DURATION,
        Check {
            ok: POSITIVE,
            expected: "s, > 0",
        },
        "the duration of the sea state, 10800 s (3 h) by design codes",
    );
    for (k, c) in spec.linked_channels.iter().enumerate() {
        let key = format!("statistics.linked_channels[{k}]");
        let name = c.get_ref().trim();
        let column = match model
            .outputs
            .iter()
            .position(|o| o.label.as_deref() == Some(name))
        {
            Some(i) => i,
            None => match Channel::parse(name, model) {
                Ok(ch) => match model.outputs.iter().position(|o| o.channel == ch) {
                    Some(i) => i,
                    None => {
                        model.outputs.push(OutputChannel::new(ch));
                        model.outputs.len() - 1
                    }
                },
                Err(msg) => {
                    unknown_channel(b, c, &key, name, msg, model);
                    continue;
                }
            },
        };
        if options.linked.contains(&column) {
            let d = b
                .diag(
                    Some(c.span()),
                    &key,
                    format!("channel `{name}` is linked twice"),
                )
                .expected("each channel once")
                .hint("remove the repeated name");
            b.push(d);
            continue;
        }
        options.linked.push(column);
    }
    options
}
