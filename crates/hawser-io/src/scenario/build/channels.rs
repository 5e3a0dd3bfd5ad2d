//! `simulation.outputs`: output channel names checked against the model.

use super::Builder;
use crate::scenario::diagnostics::closest;
use crate::scenario::schema::*;
use hawser::analysis::{Channel, OutputChannel};
use hawser::model::*;
use toml::Spanned;

pub(super) fn build_channels(
    b: &mut Builder,
    spec: Option<&SimulationSpec>,
    model: &Model,
) -> Vec<OutputChannel> {
    let mut out = hawser::analysis::channels::default_channels(model);
    let Some(sim) = spec else { return out };
    for (ci, c) in sim.channels.iter().enumerate() {
        let (label, spec) = match c.get_ref().split_once('=') {
            Some((l, s)) => (Some(l.trim().to_string()), s.trim()),
            None => (None, c.get_ref().trim()),
        };
        if label
            .as_ref()
            .is_some_and(|l| l.is_empty() || l.contains(','))
        {
            let d = b
                .diag(
                    Some(c.span()),
                    &format!("simulation.channels[{ci}]"),
                    "a column name must be non-empty and free of commas",
                )
                .expected("\"NAME = CHANNEL\", e.g. \"FairTen1 = L1.end_b.node_force\"");
            b.push(d);
            continue;
        }
        match Channel::parse(spec, model) {
            Ok(ch) => {
                let o = OutputChannel { channel: ch, label };
                // named channels are always recorded; unnamed repeats are dropped
                if o.label.is_some() || !out.iter().any(|x| x.channel == ch) {
                    out.push(o);
                }
            }
            Err(msg) => unknown_channel(
                b,
                c,
                &format!("simulation.channels[{ci}]"),
                spec,
                msg,
                model,
            ),
        }
    }
    out
}

/// Reports channel `spec` (written at `at`, under `key`) that does not parse against the
/// model (`msg` says why), with a hint listing what its object offers. Nothing is reported
/// when the object is a line that is itself wrong (its error says enough).
pub(super) fn unknown_channel(
    b: &mut Builder,
    at: &Spanned<String>,
    key: &str,
    spec: &str,
    msg: String,
    model: &Model,
) {
    let first = spec.split('.').next().unwrap_or("");
    let hint = if let Some(li) = model.line_index(first) {
        let prefix = format!("lines[{li}].");
        if b.errors.iter().any(|d| d.key.starts_with(&prefix)) {
            return; // the line itself is wrong (e.g. its element count)
        }
        let n = model.lines[li].elements();
        format!(
            "line `{first}` has nodes node0 (end A) … node{n} (end B) and elements \
             element0 … element{}, and the channels {first}.length, \
             {first}.stretched_length, {first}.stretch{}",
            n.saturating_sub(1),
            if model.lines[li].winch.is_some() {
                format!(" and {first}.winch_tension")
            } else {
                String::new()
            }
        )
    } else if model.point_index(first).is_some() {
        format!("point `{first}` has channels {first}.x|y|z|vx|vy|vz|fx|fy|fz")
    } else if model.bodies.iter().any(|b| b.name == first) {
        format!(
            "body `{first}` has channels {first}.{}, .{} and .{}",
            hawser::analysis::BODY_MOTION.join("|"),
            hawser::analysis::BODY_VELOCITY.join("|"),
            hawser::analysis::BODY_LINE_LOAD.join("|")
        )
    } else if model.environment.obstacles.iter().any(|o| o.name == first) {
        format!("obstacle `{first}` has channels {first}.force_x|force_y|force_z|contact_length")
    } else {
        let names = model.lines.iter().map(|l| l.name.as_str());
        let names = names.chain(model.points.iter().map(|p| p.name.as_str()));
        let names = names.chain(model.bodies.iter().map(|b| b.name.as_str()));
        let names = names.chain(model.environment.obstacles.iter().map(|o| o.name.as_str()));
        match closest(first, names) {
            Some(c) => format!("did you mean `{c}`?"),
            None => "a channel starts with the name of a line, a point, a body or an obstacle"
                .to_string(),
        }
    };
    let d = b
        .diag(Some(at.span()), key, msg)
        .expected("LINE.end_a|end_b.tension|node_force|fx|fy|fz, LINE.nodeK.tension|x|y|z|vx|vy|vz, LINE.elementK.strain, LINE.length|stretched_length|stretch|winch_tension, POINT.x|y|z|vx|vy|vz|fx|fy|fz, BODY.x|y|z|roll|pitch|yaw|vx|…|wz|fx|…|mz, POINT|BODY.relative_to.POINT|BODY.x|y|z, OBSTACLE.force_x|force_y|force_z|contact_length")
        .hint(hint);
    b.push(d);
}
