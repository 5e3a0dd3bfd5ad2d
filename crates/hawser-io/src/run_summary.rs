//! The design outputs of a run beside its time series: range graphs of tension along every
//! line (`line_ranges.json`), the strength check of every section against its breaking load,
//! and the design statistics of every channel, for `summary.json`. docs/outputs.md describes
//! each field.

use crate::run_files::{Column, for_each_sample};
use hawser::analysis::range_graph::RangeGraph;
use hawser::analysis::statistics::{ChannelStatistics, StatisticsAccumulator, StatisticsOptions};
use hawser::analysis::strength::{SectionStrength, section_strength, worst_section};
use hawser::math::Real;
use hawser::session::{Decoder, Encoder, View};
use hawser::system::System;
use serde_json::{Value, json};
use std::path::Path;

/// Collects the range graph of every line at each sample in the statistics window.
#[derive(Clone, Debug)]
pub struct DesignRecorder {
    start: Real,
    ranges: Vec<RangeGraph>,
}

impl DesignRecorder {
    /// A recorder for the lines of `system`, from time `options.start`.
    pub fn new(system: &System, options: &StatisticsOptions) -> Self {
        Self {
            start: options.start,
            ranges: system
                .lines
                .iter()
                .map(|l| RangeGraph::new(l.nodes()))
                .collect(),
        }
    }

    /// Adds a sample (allocation-free).
    pub fn sample(&mut self, view: &View<'_>) {
        if view.time >= self.start {
            for (li, r) in self.ranges.iter_mut().enumerate() {
                r.push(view, li);
            }
        }
    }

    /// Saves the range graphs exactly (a checkpoint of a writer).
    pub fn encode(&self, e: &mut Encoder) {
        e.u64(self.ranges.len() as u64);
        self.ranges.iter().for_each(|r| r.encode(e));
    }

    /// A recorder saved by [`DesignRecorder::encode`]; `None` if the bytes do not hold one
    /// for these lines.
    pub fn decode(d: &mut Decoder, system: &System, options: &StatisticsOptions) -> Option<Self> {
        let n = d.u64().ok()? as usize;
        if n != system.lines.len() {
            return None;
        }
        let ranges = (0..n)
            .map(|_| RangeGraph::decode(d).ok())
            .collect::<Option<Vec<_>>>()?;
        let fits = ranges
            .iter()
            .zip(&system.lines)
            .all(|(r, l)| r.max.len() == l.nodes());
        fits.then_some(Self {
            start: options.start,
            ranges,
        })
    }

    /// The range graphs.
    pub fn ranges(&self) -> &[RangeGraph] {
        &self.ranges
    }

    /// The strength check of line `li` on the largest tension of every node over the window.
    pub fn strength(&self, system: &System, li: usize) -> Vec<SectionStrength> {
        let r = &self.ranges[li];
        section_strength(&system.lines[li].mesh, &r.arc_length, &r.max)
    }

    /// `line_ranges.json`: per line the arc length, minimum, mean and maximum tension of each
    /// node, the time of the maximum, and the sections with their permissible tension.
    pub fn line_ranges_json(&self, system: &System) -> Value {
        let lines: serde_json::Map<String, Value> = system
            .lines
            .iter()
            .zip(&self.ranges)
            .map(|(l, r)| {
                let sections: Vec<Value> = section_strength(&l.mesh, &r.arc_length, &r.max)
                    .iter()
                    .map(|s| {
                        json!({
                            "line_type": s.line_type, "start": s.start, "end": s.end,
                            "minimum_breaking_load": s.minimum_breaking_load,
                            "design_safety_factor": s.design_safety_factor,
                            "permissible_tension": s.permissible_tension(),
                        })
                    })
                    .collect();
                let mean: Vec<Real> = (0..r.max.len()).map(|i| r.mean(i)).collect();
                (
                    l.name.clone(),
                    json!({
                        "samples": r.samples,
                        "arc_length": r.arc_length, "min": r.min, "mean": mean, "max": r.max,
                        "time_of_max": r.time_of_max, "sections": sections,
                    }),
                )
            })
            .collect();
        json!({
            "start": self.start,
            "units": {"arc_length": "m", "min": "N", "mean": "N", "max": "N", "time_of_max": "s"},
            "definitions": {
                "arc_length": "unstretched arc length of each node from end A at the last sample [m]",
                "min, mean, max": "effective tension at each node over the samples from `start` [N]",
            },
            "lines": lines,
        })
    }

    /// The strength part of line `li` in `summary.json` ([`strength_json`]).
    pub fn strength_json(&self, system: &System, li: usize) -> Value {
        let r = &self.ranges[li];
        strength_json(&self.strength(system, li), Some(&r.time_of_max))
    }
}

/// One section's strength check as JSON; with `time_of_max` (per node) also the time of the
/// section's largest tension.
pub fn section_json(s: &SectionStrength, time_of_max: Option<&[Real]>) -> Value {
    let mut v = json!({
        "section": s.section, "line_type": s.line_type, "start": s.start, "end": s.end,
        "minimum_breaking_load": s.minimum_breaking_load,
        "design_safety_factor": s.design_safety_factor,
        "permissible_tension": s.permissible_tension(),
        "max_tension": s.max_tension, "at": s.at,
        "utilisation": s.utilisation(), "design_utilisation": s.design_utilisation(),
    });
    if let Some(t) = time_of_max {
        v["time"] = json!(t[s.node]);
    }
    v
}

/// A line's strength check as JSON: every section ([`section_json`]) and the worst one (the
/// largest utilisation against the permissible tension, or against the MBL without a safety
/// factor; `null` when no section has an MBL).
pub fn strength_json(sections: &[SectionStrength], time_of_max: Option<&[Real]>) -> Value {
    json!({
        "sections": sections.iter().map(|s| section_json(s, time_of_max)).collect::<Vec<_>>(),
        "worst": worst_section(sections).map(|s| section_json(s, time_of_max)),
    })
}

/// The design statistics of every channel of the time series in `dir`, read twice (the
/// up-crossings are counted about the mean of the first pass). Returns the channels and
/// their statistics.
pub fn timeseries_statistics(
    dir: &Path,
    options: &StatisticsOptions,
) -> std::io::Result<(Vec<Column>, Vec<ChannelStatistics>)> {
    let mut acc: Option<StatisticsAccumulator> = None;
    let columns = for_each_sample(dir, |t, row| {
        acc.get_or_insert_with(|| StatisticsAccumulator::new(row.len(), options.clone()))
            .push(t, row)
    })?;
    let mut acc = acc.unwrap_or_else(|| StatisticsAccumulator::new(columns.len(), options.clone()));
    for_each_sample(dir, |t, row| acc.push_second(t, row))?;
    Ok((columns, acc.finish()))
}

/// The statistics of each channel as JSON, by name: unit, samples, min and max with their
/// times, mean, std, up-crossings, zero-up-crossing period, most probable extremes, and the
/// linked channels' values at the minimum and maximum.
pub fn statistics_json(columns: &[Column], stats: &[ChannelStatistics], linked: &[usize]) -> Value {
    let linked_names: Vec<&str> = linked
        .iter()
        .filter_map(|&l| columns.get(l).map(|c| c.name.as_str()))
        .collect();
    let map: serde_json::Map<String, Value> = columns
        .iter()
        .zip(stats)
        .map(|(c, s)| {
            let mut v = json!({
                "unit": c.unit, "samples": s.samples,
                "min": s.min, "time_of_min": s.time_of_min,
                "max": s.max, "time_of_max": s.time_of_max,
                "mean": s.mean, "std": s.std,
                "up_crossings": s.up_crossings,
                "zero_up_crossing_period": s.zero_up_crossing_period,
                "most_probable_maximum": s.most_probable_maximum,
                "most_probable_minimum": s.most_probable_minimum,
            });
            if !linked_names.is_empty() {
                let at = |values: &[Real]| -> Value {
                    linked_names
                        .iter()
                        .zip(values)
                        .map(|(n, &x)| (n.to_string(), json!(x)))
                        .collect::<serde_json::Map<_, _>>()
                        .into()
                };
                v["linked"] =
                    json!({"at_min": at(&s.linked_at_min), "at_max": at(&s.linked_at_max)});
            }
            (c.name.clone(), v)
        })
        .collect();
    map.into()
}

/// The `statistics` block of `summary.json`: the window and storm of the statistics, the
/// linked channels by name, and the formulas.
pub fn statistics_options_json(options: &StatisticsOptions, columns: &[Column]) -> Value {
    json!({
        "start": options.start,
        "storm_duration": options.storm_duration,
        "linked_channels": options.linked.iter().filter_map(|&l| columns.get(l).map(|c| c.name.clone())).collect::<Vec<_>>(),
        "definitions": {
            "window": "samples at t ≥ start",
            "std": "population standard deviation σ over the window",
            "zero_up_crossing_period": "T_z: time from the first to the last up-crossing of the mean, over the number of periods between them (crossing times interpolated linearly); null with fewer than two crossings",
            "most_probable_maximum": "x̄ + σ √(2 ln(storm_duration / T_z)): the Rayleigh most-probable maximum of a stationary, narrow-band Gaussian process; null when storm_duration ≤ T_z",
            "most_probable_minimum": "x̄ − σ √(2 ln(storm_duration / T_z))",
            "linked": "the linked channels' values at the sample of the channel's minimum and maximum",
        },
    })
}
