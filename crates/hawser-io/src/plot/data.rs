//! What `hawser plot` reads from a run folder: status, time series, snapshots, range graphs,
//! the summary, and the statistics options.

use crate::results::safe_file_name;
use crate::run_files::{Snapshot, Timeseries, read_snapshots, read_timeseries};
use hawser::analysis::statistics::StatisticsOptions;
use hawser::math::Real;
use serde_json::Value;
use std::path::Path;

/// One section on a range graph.
#[derive(Clone, Debug, PartialEq)]
pub struct RangeSection {
    /// Line type name.
    pub line_type: String,
    /// Arc lengths of its first and last node [m].
    pub start: Real,
    /// See `start`.
    pub end: Real,
    /// MBL [N].
    pub minimum_breaking_load: Option<Real>,
    /// SF [-].
    pub design_safety_factor: Option<Real>,
    /// MBL / SF [N].
    pub permissible_tension: Option<Real>,
}

/// The range graph of one line.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LineRange {
    /// Node arc lengths [m].
    pub arc_length: Vec<Real>,
    /// Minimum tension per node [N].
    pub min: Vec<Real>,
    /// Mean tension per node [N].
    pub mean: Vec<Real>,
    /// Maximum tension per node [N].
    pub max: Vec<Real>,
    /// Its sections (none when derived from snapshots).
    pub sections: Vec<RangeSection>,
    /// Samples it covers.
    pub samples: u64,
    /// Derived from the snapshots of a run that has not finished.
    pub from_snapshots: bool,
}

/// A run folder as read by `hawser plot`.
pub struct RunData {
    /// `status.json` (null if absent).
    pub status: Value,
    /// `summary.json` (null if absent: the run is still going).
    pub summary: Value,
    /// The time series.
    pub timeseries: Timeseries,
    /// Line names, in the order of their end-tension channels.
    pub lines: Vec<String>,
    /// Snapshots per line (empty without `snapshot_interval`).
    pub snapshots: Vec<Vec<Snapshot>>,
    /// Range graph per line, if any.
    pub ranges: Vec<Option<LineRange>>,
    /// What the statistics cover.
    pub statistics: StatisticsOptions,
    /// Where the statistics options came from.
    pub statistics_source: &'static str,
}

fn read_json(path: &Path) -> Value {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or(Value::Null)
}

fn numbers(v: &Value) -> Vec<Real> {
    v.as_array()
        .map(|a| a.iter().map(|x| x.as_f64().unwrap_or(Real::NAN)).collect())
        .unwrap_or_default()
}

/// The range graph of a line from `line_ranges.json`'s entry.
fn range_of_json(v: &Value) -> Option<LineRange> {
    let r = LineRange {
        arc_length: numbers(&v["arc_length"]),
        min: numbers(&v["min"]),
        mean: numbers(&v["mean"]),
        max: numbers(&v["max"]),
        sections: v["sections"]
            .as_array()
            .map(|a| {
                a.iter()
                    .map(|s| RangeSection {
                        line_type: s["line_type"].as_str().unwrap_or("").to_string(),
                        start: s["start"].as_f64().unwrap_or(Real::NAN),
                        end: s["end"].as_f64().unwrap_or(Real::NAN),
                        minimum_breaking_load: s["minimum_breaking_load"].as_f64(),
                        design_safety_factor: s["design_safety_factor"].as_f64(),
                        permissible_tension: s["permissible_tension"].as_f64(),
                    })
                    .collect()
            })
            .unwrap_or_default(),
        samples: v["samples"].as_u64().unwrap_or(0),
        from_snapshots: false,
    };
    let n = r.arc_length.len();
    (n > 0 && [r.min.len(), r.mean.len(), r.max.len()] == [n, n, n] && r.samples > 0).then_some(r)
}

/// A range graph from the snapshots at or after `start` [s] (a run still going has no
/// `line_ranges.json` yet).
fn range_of_snapshots(snapshots: &[Snapshot], start: Real) -> Option<LineRange> {
    let used: Vec<&Snapshot> = snapshots
        .iter()
        .filter(|s| s.time >= start && !s.tension.is_empty())
        .collect();
    let last = used.last()?;
    let n = last.tension.len();
    let mut r = LineRange {
        arc_length: last.arc_length.clone(),
        min: vec![Real::INFINITY; n],
        mean: vec![0.0; n],
        max: vec![Real::NEG_INFINITY; n],
        sections: Vec::new(),
        samples: 0,
        from_snapshots: true,
    };
    for s in used.iter().filter(|s| s.tension.len() == n) {
        r.samples += 1;
        for (i, &t) in s.tension.iter().enumerate() {
            r.min[i] = r.min[i].min(t);
            r.max[i] = r.max[i].max(t);
            r.mean[i] += t;
        }
    }
    r.mean.iter_mut().for_each(|m| *m /= r.samples as Real);
    Some(r)
}

/// The statistics options of a run: those its `summary.json` records; for a run still going,
/// those of its scenario (through `run.json`); else the defaults. Linked channels are found
/// by name among the time series' channels.
fn statistics_options(
    dir: &Path,
    summary: &Value,
    ts: &Timeseries,
) -> (StatisticsOptions, &'static str) {
    let s = &summary["statistics"];
    if s.is_object() {
        let linked = s["linked_channels"]
            .as_array()
            .map(|a| {
                a.iter()
                    .filter_map(|n| n.as_str().and_then(|n| ts.index(n)))
                    .collect()
            })
            .unwrap_or_default();
        return (
            StatisticsOptions {
                start: s["start"].as_f64().unwrap_or(0.0),
                storm_duration: s["storm_duration"]
                    .as_f64()
                    .unwrap_or(hawser::analysis::statistics::DEFAULT_STORM_DURATION),
                linked,
            },
            "summary.json",
        );
    }
    let run = read_json(&dir.join("run.json"));
    if let Some(scenario) = run["scenario"].as_str() {
        let deck = crate::moordyn::ConvertOptions {
            duration: run["duration"].as_f64(),
            vessel_motion: run["vessel_motion"].as_str().map(Into::into),
        };
        if let Ok((loaded, _)) = crate::input::load_input(Path::new(scenario), &deck)
            && loaded.model.outputs.len() == ts.channels.len()
        {
            return (loaded.statistics, "the scenario");
        }
    }
    (StatisticsOptions::default(), "the defaults")
}

/// Reads the run in `dir`.
pub fn read_run(dir: &Path) -> Result<RunData, String> {
    if !dir.join("timeseries.csv").is_file() {
        return Err(format!(
            "{} has no timeseries.csv: it is not the output folder of `hawser run` (or the run \
             has not started writing)",
            dir.display()
        ));
    }
    let timeseries = read_timeseries(dir).map_err(|e| e.to_string())?;
    let status = read_json(&dir.join("status.json"));
    let summary = read_json(&dir.join("summary.json"));
    let mut lines: Vec<String> = Vec::new();
    for c in &timeseries.channels {
        for end in [".end_a.tension", ".end_b.tension"] {
            if let Some(l) = c.name.strip_suffix(end)
                && !lines.iter().any(|x| x == l)
            {
                lines.push(l.to_string());
            }
        }
    }
    let (statistics, statistics_source) = statistics_options(dir, &summary, &timeseries);
    let snapshots: Vec<Vec<Snapshot>> = lines
        .iter()
        .map(|l| {
            let p = dir
                .join("snapshots")
                .join(format!("{}.csv", safe_file_name(l)));
            if p.is_file() {
                read_snapshots(&p).map_err(|e| e.to_string())
            } else {
                Ok(Vec::new())
            }
        })
        .collect::<Result<_, _>>()?;
    let ranges_json = read_json(&dir.join("line_ranges.json"));
    let ranges = lines
        .iter()
        .zip(&snapshots)
        .map(|(l, s)| {
            range_of_json(&ranges_json["lines"][l])
                .or_else(|| range_of_snapshots(s, statistics.start))
        })
        .collect();
    Ok(RunData {
        status,
        summary,
        timeseries,
        lines,
        snapshots,
        ranges,
        statistics,
        statistics_source,
    })
}

/// The bodies of a run: names with all six motion channels, and their columns.
pub fn bodies(ts: &Timeseries) -> Vec<(String, [usize; 6])> {
    let mut out = Vec::new();
    for c in &ts.channels {
        let Some(body) = c.name.strip_suffix(".roll") else {
            continue;
        };
        let cols: Option<Vec<usize>> = hawser::analysis::BODY_MOTION
            .iter()
            .map(|d| ts.index(&format!("{body}.{d}")))
            .collect();
        if let Some(cols) = cols {
            out.push((
                body.to_string(),
                [cols[0], cols[1], cols[2], cols[3], cols[4], cols[5]],
            ));
        }
    }
    out
}
