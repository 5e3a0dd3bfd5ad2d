//! `report.html`: the figures with the summary tables, in plain HTML and CSS (no scripts).

use super::Figure;
use super::data::RunData;
use hawser::analysis::statistics::ChannelStatistics;
use hawser::math::Real;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;

/// `s` with HTML's special characters escaped.
pub(super) fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number with 5 significant digits, in scientific notation when very large or small; a
/// dash for none.
pub(super) fn num(x: Option<Real>) -> String {
    match x {
        Some(x) if x.is_finite() => {
            if x == 0.0 {
                "0".into()
            } else if (1e-3..1e6).contains(&x.abs()) {
                let decimals = (4 - x.abs().log10().floor() as i32).max(0) as usize;
                format!("{x:.decimals$}")
            } else {
                format!("{x:.4e}")
            }
        }
        _ => "–".into(),
    }
}

const STYLE: &str = "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:24px auto;max-width:1150px;color:#222;line-height:1.4}\
h1{font-size:1.6em;margin-bottom:0.2em}h2{font-size:1.25em;margin-top:1.6em;border-bottom:1px solid #ccc}\
table{border-collapse:collapse;font-size:0.85em;margin:0.5em 0}th,td{border:1px solid #ccc;padding:3px 7px}\
th{background:#f0f0f0}td.n{text-align:right;font-variant-numeric:tabular-nums}\
tr.over td{background:#fde2e1}figure{margin:1.2em 0}figure img{max-width:100%;border:1px solid #ddd}\
figcaption{font-size:0.9em;color:#444}.state{display:inline-block;padding:2px 8px;border-radius:4px;background:#e8f4e8}\
.state.bad{background:#fde2e1}.note{color:#555;font-size:0.9em}";

/// The page.
pub(super) fn html(
    dir: &Path,
    run: &RunData,
    stats: &[ChannelStatistics],
    figures: &[Figure],
    notes: &[String],
) -> String {
    let mut h = String::new();
    let name = dir
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .unwrap_or_else(|| dir.display().to_string());
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>hawser run {}</title><style>{STYLE}</style></head><body>\n",
        escape(&name)
    );
    let _ = writeln!(h, "<h1>hawser run <code>{}</code></h1>", escape(&name));
    let state = run.status["state"].as_str().unwrap_or("unknown");
    let ts = &run.timeseries;
    let last = ts.time.last().copied().unwrap_or(0.0);
    let _ = writeln!(
        h,
        "<p><span class=\"state{}\">{}</span> scenario <code>{}</code>; {} samples from t = {} s \
         to {} s.{}</p>",
        if matches!(state, "finished" | "running") {
            ""
        } else {
            " bad"
        },
        escape(state),
        escape(run.status["scenario"].as_str().unwrap_or("?")),
        ts.time.len(),
        num(ts.time.first().copied()),
        num(Some(last)),
        match run.status["error"].as_str() {
            Some(e) => format!(" Stopped: {}", escape(e)),
            None => String::new(),
        }
    );
    if state == "running" {
        let _ = writeln!(
            h,
            "<p class=\"note\">The run is still going: the figures and tables cover the samples \
             written so far. Plot again when it ends for its range graphs and line strength.</p>"
        );
    }
    strength_table(&mut h, &run.summary);
    statistics_table(&mut h, run, stats);
    slack_table(&mut h, &run.summary);
    let _ = writeln!(h, "<h2>Figures</h2>");
    for f in figures {
        let _ = writeln!(
            h,
            "<figure id=\"{stem}\"><img src=\"plots/{stem}.png\" alt=\"{title}\">\
             <figcaption><b>{title}.</b> {caption} <a href=\"plots/{stem}.svg\">SVG</a></figcaption></figure>",
            stem = escape(&f.stem),
            title = escape(&f.title),
            caption = escape(&f.caption)
        );
    }
    if !notes.is_empty() {
        let _ = writeln!(h, "<ul class=\"note\">");
        for n in notes {
            let _ = writeln!(h, "<li>{}</li>", escape(n));
        }
        let _ = writeln!(h, "</ul>");
    }
    let _ = writeln!(
        h,
        "<p class=\"note\">Written by <code>hawser plot</code> {}. Definitions: docs/outputs.md.</p>\n</body></html>",
        env!("CARGO_PKG_VERSION")
    );
    h
}

/// Line strength per line and section from `summary.json`.
fn strength_table(h: &mut String, summary: &Value) {
    let Some(lines) = summary["lines"].as_object() else {
        return;
    };
    let rows: Vec<(&String, &Value)> = lines
        .iter()
        .flat_map(|(l, v)| {
            v["strength"]["sections"]
                .as_array()
                .into_iter()
                .flatten()
                .map(move |s| (l, s))
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(
        h,
        "<h2>Line strength</h2>\n<p class=\"note\">The largest effective tension of each section \
         over the statistics window, where (unstretched arc length from end A) and when, against \
         the minimum breaking load MBL and the permissible tension MBL/SF. Rows above 1 are \
         shaded.</p>\n<table><tr><th>line</th><th>section</th><th>line type</th><th>s [m]</th>\
         <th>max T [N]</th><th>at s [m]</th><th>at t [s]</th><th>MBL [N]</th><th>SF</th>\
         <th>T/MBL</th><th>T/(MBL/SF)</th></tr>"
    );
    for (line, s) in rows {
        let f = |k: &str| s[k].as_f64();
        let over = f("design_utilisation")
            .or(f("utilisation"))
            .is_some_and(|u| u > 1.0);
        let _ = writeln!(
            h,
            "<tr{}><td>{}</td><td class=\"n\">{}</td><td>{}</td><td class=\"n\">{} – {}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            if over { " class=\"over\"" } else { "" },
            escape(line),
            s["section"].as_u64().unwrap_or(0),
            escape(s["line_type"].as_str().unwrap_or("")),
            num(f("start")),
            num(f("end")),
            num(f("max_tension")),
            num(f("at")),
            num(f("time")),
            num(f("minimum_breaking_load")),
            num(f("design_safety_factor")),
            num(f("utilisation")),
            num(f("design_utilisation")),
        );
    }
    let _ = writeln!(h, "</table>");
}

/// Design statistics per channel.
fn statistics_table(h: &mut String, run: &RunData, stats: &[ChannelStatistics]) {
    let o = &run.statistics;
    let _ = writeln!(
        h,
        "<h2>Statistics</h2>\n<p class=\"note\">Over the samples from t = {} s (options from {}). \
         T<sub>z</sub>: mean zero-up-crossing period about the mean. MPM: Rayleigh most-probable \
         maximum x̄ + σ √(2 ln(T<sub>storm</sub>/T<sub>z</sub>)) for a storm of {} s, which \
         assumes a stationary narrow-band Gaussian response.</p>",
        num(Some(o.start)),
        run.statistics_source,
        num(Some(o.storm_duration))
    );
    let ts = &run.timeseries;
    let linked: Vec<&str> = o
        .linked
        .iter()
        .filter_map(|&l| ts.channels.get(l).map(|c| c.name.as_str()))
        .collect();
    let _ = write!(
        h,
        "<table><tr><th>channel</th><th>unit</th><th>min</th><th>at t [s]</th><th>max</th>\
         <th>at t [s]</th><th>mean</th><th>std</th><th>T<sub>z</sub> [s]</th><th>MPM</th>"
    );
    for l in &linked {
        let _ = write!(h, "<th>{} at max</th>", escape(l));
    }
    let _ = writeln!(h, "</tr>");
    for (c, s) in ts.channels.iter().zip(stats) {
        let _ = write!(
            h,
            "<tr><td>{}</td><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{}</td>",
            escape(&c.name),
            escape(&c.unit),
            num(Some(s.min)),
            num(Some(s.time_of_min)),
            num(Some(s.max)),
            num(Some(s.time_of_max)),
            num(Some(s.mean)),
            num(Some(s.std)),
            num(s.zero_up_crossing_period),
            num(s.most_probable_maximum)
        );
        for v in &s.linked_at_max {
            let _ = write!(h, "<td class=\"n\">{}</td>", num(Some(*v)));
        }
        let _ = writeln!(h, "</tr>");
    }
    let _ = writeln!(h, "</table>");
}

/// Slack intervals and snap events per line from `summary.json`.
fn slack_table(h: &mut String, summary: &Value) {
    let Some(lines) = summary["lines"].as_object() else {
        return;
    };
    let _ = writeln!(
        h,
        "<h2>Slack and snap loads</h2>\n<table><tr><th>line</th><th>slack intervals</th>\
         <th>slack time [s]</th><th>snap events</th><th>largest snap peak [N]</th><th>at t [s]</th>\
         <th>at s [m]</th></tr>"
    );
    for (l, v) in lines {
        let slack = v["slack_intervals"].as_array().cloned().unwrap_or_default();
        let snaps = v["snap_events"].as_array().cloned().unwrap_or_default();
        let time: Real = slack
            .iter()
            .map(|s| s["end"].as_f64().unwrap_or(0.0) - s["start"].as_f64().unwrap_or(0.0))
            .sum();
        let peak = snaps.iter().max_by(|a, b| {
            a["peak_tension"]
                .as_f64()
                .partial_cmp(&b["peak_tension"].as_f64())
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let f = |k: &str| peak.and_then(|p| p[k].as_f64());
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            escape(l),
            slack.len(),
            num(Some(time)),
            snaps.len(),
            num(f("peak_tension")),
            num(f("peak_time")),
            num(f("location"))
        );
    }
    let _ = writeln!(h, "</table>");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_escapes() {
        assert_eq!(num(Some(123456.789)), "123457");
        assert_eq!(num(Some(-2.5)), "-2.5000");
        assert_eq!(num(Some(0.0123456)), "0.012346");
        assert_eq!(num(Some(4.88e6)), "4.8800e6");
        assert_eq!(num(None), "–");
        assert_eq!(num(Some(Real::NAN)), "–");
        assert_eq!(escape("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
    }
}
