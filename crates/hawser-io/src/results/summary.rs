//! What a run's results are computed from its samples, whatever keeps them
//! ([`RunSummary`]), and the design fields of `summary.json` and `line_ranges.json`: the
//! design statistics of every channel, the range graphs of tension along every line and the
//! strength check of every section against its breaking load. docs/outputs.md describes
//! each field.

use crate::run_files::for_each_sample;
use hawser::analysis::range_graph::RangeGraph;
use hawser::analysis::statistics::{ChannelStatistics, StatisticsAccumulator, StatisticsOptions};
use hawser::analysis::strength::{SectionStrength, section_strength, worst_section};
use hawser::analysis::{Channel, OutputChannel, SlackSnapDetector};
use hawser::math::Real;
use hawser::session::{Decoder, Encoder, View};
use hawser::system::System;
use serde_json::{Value, json};
use std::path::Path;

use super::FORMAT_VERSION;

/// What a run's results are computed from its samples, whatever keeps them: the row of
/// channel values, the range graph of every line over the statistics window, the slack and
/// snap detectors of every line, and the snapshot schedule. [`super::RunWriter`] writes it
/// into files (`summary.json`, `line_ranges.json`); the Python package keeps it in memory.
/// The design statistics of the channels need every sample twice (the up-crossings are
/// counted about the mean), so they are computed at the end from the samples kept: read back
/// from `timeseries.csv` ([`timeseries_statistics`]) or from memory, with the same
/// [`StatisticsAccumulator`].
#[derive(Clone, Debug)]
pub struct RunSummary {
    pub(super) channels: Vec<Channel>,
    pub(super) names: Vec<String>,
    statistics: StatisticsOptions,
    ranges: Vec<RangeGraph>,
    detectors: Vec<SlackSnapDetector>,
    pub(super) snapshot_interval: Option<Real>,
    next_snapshot: Real,
    last_time: Real,
    samples: u64,
    /// The channel values of the sample being taken.
    row: Vec<Real>,
    /// The run's warnings, written into `summary.json` and `status.json` at its end.
    warnings: Vec<hawser::Warning>,
    /// What the run's time integration did, written into `summary.json` at its end.
    integrator: Option<hawser::integrate::IntegratorReport>,
    /// The run's line failures, `None` when its model has none (no `failures` key then).
    failures: Option<Vec<hawser::session::FailureEvent>>,
}

impl RunSummary {
    /// A summary of the run of `system` with output channels `outputs`, shape snapshots every
    /// `snapshot_interval` [s] (none without it), statistics and range graphs over the
    /// window of `statistics` (the scenario's `[statistics]`).
    pub fn new(
        system: &System,
        outputs: &[OutputChannel],
        snapshot_interval: Option<Real>,
        statistics: &StatisticsOptions,
    ) -> Self {
        Self {
            names: outputs.iter().map(|c| c.name(system)).collect(),
            channels: outputs.iter().map(|c| c.channel).collect(),
            statistics: statistics.clone(),
            ranges: system
                .lines
                .iter()
                .map(|l| RangeGraph::new(l.nodes()))
                .collect(),
            detectors: vec![SlackSnapDetector::default(); system.lines.len()],
            row: vec![0.0; outputs.len()],
            snapshot_interval,
            next_snapshot: 0.0,
            last_time: 0.0,
            samples: 0,
            warnings: Vec::new(),
            integrator: None,
            failures: (!system.failures.is_empty()).then(Vec::new),
        }
    }

    /// How the run ended ([`hawser::session::RunEnd`]): its warnings and what its time
    /// integration did, written into `summary.json` at its end.
    pub fn set_end(&mut self, end: &hawser::session::RunEnd) {
        self.warnings = end.warnings.clone();
        self.integrator = Some(end.integrator.clone());
    }

    /// The line failures that happened by the end of the run (`view.releases`), written into
    /// `summary.json` when the model has failures.
    pub fn set_failures(&mut self, view: &View<'_>) {
        if let Some(f) = &mut self.failures {
            *f = hawser::session::failure_events(view.system, view.releases);
        }
    }

    /// The run's line failures set by [`RunSummary::set_failures`] (`None`: the model has
    /// none).
    pub fn failures(&self) -> Option<&[hawser::session::FailureEvent]> {
        self.failures.as_deref()
    }

    /// The run's warnings set by [`RunSummary::set_end`].
    pub fn warnings(&self) -> &[hawser::Warning] {
        &self.warnings
    }

    /// Reads the channel values of `view` into [`RunSummary::row`] without recording them.
    pub fn read(&mut self, view: &View<'_>) -> &[Real] {
        for (v, c) in self.row.iter_mut().zip(&self.channels) {
            *v = view.value(c);
        }
        &self.row
    }

    /// Records the sample of `view` at `time` [s] (the time written in the time series): the
    /// node tensions into the range graphs (from the statistics window's start on), the
    /// element tensions and strains into the slack and snap detectors. Returns whether a
    /// shape snapshot is due at this sample. Allocates nothing.
    pub fn record(&mut self, view: &View<'_>, time: Real) -> bool {
        let (system, ws) = (view.system, view.workspace);
        self.last_time = time;
        self.samples += 1;
        if time >= self.statistics.start {
            for (li, r) in self.ranges.iter_mut().enumerate() {
                r.push(view, li, time);
            }
        }
        for li in 0..system.lines.len() {
            let lw = &ws.lines[li];
            // The current mesh: a line on a winch changes its unstretched length.
            let mesh = system.line_mesh(ws, li);
            self.detectors[li].push(time, &lw.elements.tension, &lw.elements.strain, |e| {
                0.5 * (mesh.arc_length(e) + mesh.arc_length(e + 1))
            });
        }
        match self.snapshot_interval {
            Some(interval) if time >= self.next_snapshot - 1e-9 * interval => {
                while self.next_snapshot <= time + 1e-9 * interval {
                    self.next_snapshot += interval;
                }
                true
            }
            _ => false,
        }
    }

    /// Takes one sample at `time` [s]: [`RunSummary::read`] then [`RunSummary::record`].
    pub fn sample(&mut self, view: &View<'_>, time: Real) -> bool {
        self.read(view);
        self.record(view, time)
    }

    /// The channel values of the last sample, in column order.
    pub fn row(&self) -> &[Real] {
        &self.row
    }

    /// Column names of the output channels.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The output channels, in column order.
    pub fn channels(&self) -> &[Channel] {
        &self.channels
    }

    /// What the statistics and range graphs cover.
    pub fn statistics(&self) -> &StatisticsOptions {
        &self.statistics
    }

    /// The range graph of every line, in model order.
    pub fn ranges(&self) -> &[RangeGraph] {
        &self.ranges
    }

    /// Time of the last sample [s].
    pub fn last_time(&self) -> Real {
        self.last_time
    }

    /// Samples taken.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// Closes the slack intervals and snap events still open at the last sample.
    pub fn finish(&mut self) {
        for d in &mut self.detectors {
            d.finish(self.last_time);
        }
    }

    /// The design statistics of samples kept in memory: `times[i]` [s] and row i of
    /// `values` (one value per channel, rows one after the other), over this summary's
    /// window.
    pub fn statistics_of_rows(&self, times: &[Real], values: &[Real]) -> Vec<ChannelStatistics> {
        let n = self.names.len();
        let mut acc = StatisticsAccumulator::new(n, self.statistics.clone());
        if n > 0 {
            let rows = || times.iter().copied().zip(values.chunks_exact(n));
            rows().for_each(|(t, row)| acc.push(t, row));
            rows().for_each(|(t, row)| acc.push_second(t, row));
        }
        acc.finish()
    }

    /// The strength check of line `li` on the largest tension of every node over the window.
    pub fn strength(&self, system: &System, li: usize) -> Vec<SectionStrength> {
        let r = &self.ranges[li];
        section_strength(&system.lines[li].mesh, &r.arc_length, &r.max)
    }

    /// The summary as `summary.json` holds it: the result format, the statistics window, per
    /// channel its unit and design statistics (`stats`, in column order:
    /// [`timeseries_statistics`] or [`RunSummary::statistics_of_rows`]); per line its slack
    /// intervals, snap events and strength check; `error` (the reason the run stopped early)
    /// marks it incomplete.
    pub fn to_json(
        &self,
        system: &System,
        error: Option<&str>,
        stats: &[ChannelStatistics],
    ) -> Value {
        let units: Vec<&str> = self.channels.iter().map(|c| c.unit()).collect();
        let lines: serde_json::Map<String, Value> = system
            .lines
            .iter()
            .zip(&self.detectors)
            .enumerate()
            .map(|(li, (l, d))| {
                (
                    l.name.clone(),
                    json!({
                        "slack_intervals": d.intervals.iter().map(|s| json!({"start": s.start, "end": s.end, "min_strain": s.min_strain})).collect::<Vec<_>>(),
                        "snap_events": d.snaps.iter().map(|s| json!({
                            "time": s.time, "peak_time": s.peak_time, "peak_tension": s.peak_tension,
                            "location": s.location, "rise_rate": s.rise_rate})).collect::<Vec<_>>(),
                        "strength": strength_json(&self.strength(system, li), Some(&self.ranges[li].time_of_max)),
                    }),
                )
            })
            .collect();
        let mut v = json!({
            "format_version": FORMAT_VERSION,
            "complete": error.is_none(),
            "error": error,
            "end_time": self.last_time,
            "samples": self.samples,
            "warnings": super::warnings_json(&self.warnings),
            "statistics": statistics_options_json(&self.statistics, &self.names),
            "channels": statistics_json(&self.names, &units, stats, &self.statistics.linked),
            "lines": lines,
            "definitions": {
                "slack": "some element of the line has strain ≤ 0",
                "snap": "a slack → taut transition; peak is the largest element tension until the tension falls again",
                "location": "unstretched arc length from end A [m] of the element carrying the peak",
                "strength": "per section of each line, the largest node tension over the statistics window (max_tension [N]), where (at: unstretched arc length from end A [m]) and when (time [s]); utilisation = max_tension / minimum_breaking_load, design_utilisation = max_tension / (minimum_breaking_load / design_safety_factor); worst: the section with the largest design utilisation (utilisation without a safety factor)",
            },
        });
        if let Some(r) = &self.integrator {
            v["integrator"] = integrator_json(r);
            v["definitions"]["integrator"] = json!(
                "the time integration: the scheme the run started with (scheme = \"auto\" resolved) and why, the steps taken by every scheme, the step at the end [s] (adaptive generalized-α: the nominal step it would take next), generalized-α's steps, refused steps, Newton iterations and Jacobians (null if it never stepped), and auto's switching between generalized-α and RK4 (null unless auto started with adaptive generalized-α): the switches, the simulated time RK4 stepped [s] and whether RK4 stepped at the end"
            );
        }
        if let Some(f) = &self.failures {
            v["failures"] = super::failures_json(f);
            v["definitions"]["failures"] = json!(
                "line ends that released from their attachment during the run: the line, its end (a or b), the point it released from, the time [s] and the end's tension just before [N], and what released it (time, tension or host)"
            );
        }
        v
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
            "start": self.statistics.start,
            "units": {"arc_length": "m", "min": "N", "mean": "N", "max": "N", "time_of_max": "s"},
            "definitions": {
                "arc_length": "unstretched arc length of each node from end A at the last sample [m]",
                "min, mean, max": "effective tension at each node over the samples from `start` [N]",
            },
            "lines": lines,
        })
    }

    /// Saves the summary exactly (range graphs, detectors, snapshot schedule), for a
    /// checkpoint.
    pub fn encode(&self, e: &mut Encoder) {
        e.u64(self.ranges.len() as u64);
        self.ranges.iter().for_each(|r| r.encode(e));
        e.u64(self.detectors.len() as u64);
        self.detectors.iter().for_each(|d| d.encode(e));
        e.f64(self.next_snapshot);
        e.f64(self.last_time);
        e.u64(self.samples);
    }

    /// Restores a summary saved by [`RunSummary::encode`] into this new one (of the same
    /// system and channels); the error says what does not fit.
    pub fn decode(&mut self, d: &mut Decoder) -> Result<(), &'static str> {
        const TRUNCATED: &str = "is truncated";
        let n = d.u64().map_err(|_| TRUNCATED)? as usize;
        if n != self.ranges.len() {
            return Err("has another number of lines");
        }
        let ranges = (0..n)
            .map(|_| RangeGraph::decode(d).map_err(|_| TRUNCATED))
            .collect::<Result<Vec<_>, _>>()?;
        if ranges
            .iter()
            .zip(&self.ranges)
            .any(|(r, s)| r.max.len() != s.max.len())
        {
            return Err("has range graphs of lines with other numbers of nodes");
        }
        self.ranges = ranges;
        let n = d.u64().map_err(|_| TRUNCATED)? as usize;
        if n != self.detectors.len() {
            return Err("has another number of lines");
        }
        self.detectors = (0..n)
            .map(|_| SlackSnapDetector::decode(d).map_err(|_| TRUNCATED))
            .collect::<Result<Vec<_>, _>>()?;
        self.next_snapshot = d.f64().map_err(|_| TRUNCATED)?;
        self.last_time = d.f64().map_err(|_| TRUNCATED)?;
        self.samples = d.u64().map_err(|_| TRUNCATED)?;
        Ok(())
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

/// The design statistics of every channel of the time series in `dir` as written (a resumed
/// run's rows included, so they are exact across a resume), read twice (the up-crossings
/// are counted about the mean of the first pass). Returns the channel names, in file order,
/// and their statistics.
pub fn timeseries_statistics(
    dir: &Path,
    options: &StatisticsOptions,
) -> std::io::Result<(Vec<String>, Vec<ChannelStatistics>)> {
    let mut acc: Option<StatisticsAccumulator> = None;
    let columns = for_each_sample(dir, |t, row| {
        acc.get_or_insert_with(|| StatisticsAccumulator::new(row.len(), options.clone()))
            .push(t, row)
    })?;
    let mut acc = acc.unwrap_or_else(|| StatisticsAccumulator::new(columns.len(), options.clone()));
    for_each_sample(dir, |t, row| acc.push_second(t, row))?;
    Ok((columns.into_iter().map(|c| c.name).collect(), acc.finish()))
}

/// The statistics of each channel as JSON, by name: unit, samples, min and max with their
/// times, mean, std, up-crossings, zero-up-crossing period, most probable extremes, and the
/// linked channels' values at the minimum and maximum.
pub fn statistics_json(
    names: &[String],
    units: &[&str],
    stats: &[ChannelStatistics],
    linked: &[usize],
) -> Value {
    let linked_names: Vec<&str> = linked
        .iter()
        .filter_map(|&l| names.get(l).map(String::as_str))
        .collect();
    let map: serde_json::Map<String, Value> = names
        .iter()
        .zip(units)
        .zip(stats)
        .map(|((name, unit), s)| {
            let mut v = json!({
                "unit": unit, "samples": s.samples,
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
            (name.clone(), v)
        })
        .collect();
    map.into()
}

/// The `statistics` block of `summary.json`: the window and storm of the statistics, the
/// linked channels by name, and the formulas.
pub fn statistics_options_json(options: &StatisticsOptions, names: &[String]) -> Value {
    json!({
        "start": options.start,
        "storm_duration": options.storm_duration,
        "linked_channels": options.linked.iter().filter_map(|&l| names.get(l).cloned()).collect::<Vec<_>>(),
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

/// `summary.json`'s `integrator` ([`hawser::integrate::IntegratorReport`]).
pub fn integrator_json(r: &hawser::integrate::IntegratorReport) -> Value {
    json!({
        "scheme": r.choice.scheme.name(),
        "reason": r.choice.reason,
        "steps": r.steps,
        "time_step": r.time_step,
        "generalized_alpha": r.generalized_alpha.map(|s| json!({
            "steps": s.steps,
            "refused": s.rejected,
            "newton_iterations": s.iterations,
            "jacobians": s.jacobians,
        })),
        "auto_switching": r.switching.map(|w| json!({
            "switches": w.switches,
            "rk4_time": w.rk4_time,
            "rk4_at_end": w.rk4_now,
        })),
    })
}
