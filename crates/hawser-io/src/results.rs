//! Result writers: `timeseries.csv`, per-line shape snapshots, `summary.json` (design
//! statistics, slack intervals, snap events, line strength), `line_ranges.json` (range graphs
//! of tension along each line), `final_state.json` and `status.json`. Rows are flushed as the
//! run goes, so a run that stops early keeps what it wrote, marked incomplete in
//! `status.json` and `summary.json`.

use crate::run_summary::{
    DesignRecorder, statistics_json, statistics_options_json, strength_json, timeseries_statistics,
};
pub use hawser::analysis::OutputChannel;
use hawser::analysis::statistics::StatisticsOptions;
use hawser::analysis::{Channel, SlackSnapDetector};
use hawser::math::Real;
use hawser::session::{Observer, ObserverError, RunEnd, View};
use hawser::system::{System, Workspace};
use serde_json::{Value, json};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Writes a dynamic run's results into a directory while it runs.
pub struct RunWriter {
    dir: PathBuf,
    channels: Vec<Channel>,
    names: Vec<String>,
    statistics: StatisticsOptions,
    design: DesignRecorder,
    detectors: Vec<SlackSnapDetector>,
    timeseries: BufWriter<File>,
    snapshots: Vec<BufWriter<File>>,
    snapshot_interval: Option<Real>,
    scenario: String,
    next_snapshot: Real,
    last_time: Real,
    samples: u64,
    row: Vec<Real>,
}

fn io_context(path: &Path, e: std::io::Error) -> std::io::Error {
    std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
}

/// Writes `value` to `path` atomically: into a temporary file beside it, then renamed over
/// it, so that a reader (or a kill) never sees half a file.
fn write_json(path: &Path, value: &Value) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(value).expect("JSON serialises");
    write_atomically(path, (text + "\n").as_bytes())
}

/// Writes `bytes` to `path` through a temporary file renamed over it.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, bytes).map_err(|e| io_context(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| io_context(path, e))
}

/// The files and folders a run writes into its output folder: what `--overwrite` removes and
/// what marks a folder as holding a run.
pub const RUN_FILES: [&str; 10] = [
    "status.json",
    "summary.json",
    "timeseries.csv",
    "final_state.json",
    "checkpoint.bin",
    "run.json",
    "snapshots",
    "line_ranges.json",
    "plots",
    "report.html",
];

/// The run files present in `dir` ([`RUN_FILES`]).
pub fn run_files_in(dir: &Path) -> Vec<&'static str> {
    RUN_FILES
        .iter()
        .copied()
        .filter(|f| dir.join(f).symlink_metadata().is_ok())
        .collect()
}

/// Prepares `dir` for a new run: creates it, and refuses it when it holds another run's files
/// unless `overwrite`, which removes them first (the whole `snapshots/` folder included, so
/// nothing stale is left beside the new results; other files are left alone).
pub fn prepare_output_dir(dir: &Path, overwrite: bool) -> std::io::Result<()> {
    let present = run_files_in(dir);
    if !present.is_empty() {
        if !overwrite {
            return Err(std::io::Error::new(
                std::io::ErrorKind::AlreadyExists,
                format!(
                    "{} holds the results of another run ({}); hint: pass --overwrite to \
                     replace them, choose another --out, or continue an interrupted run with \
                     `hawser resume {}`",
                    dir.display(),
                    present.join(", "),
                    dir.display()
                ),
            ));
        }
        for f in present {
            let p = dir.join(f);
            let removed = if p.is_dir() {
                std::fs::remove_dir_all(&p)
            } else {
                std::fs::remove_file(&p)
            };
            removed.map_err(|e| io_context(&p, e))?;
        }
    }
    std::fs::create_dir_all(dir).map_err(|e| io_context(dir, e))
}

impl RunWriter {
    /// Creates the files in `dir` (prepared by [`prepare_output_dir`], or created here when
    /// missing), writes headers and marks the run as running. `statistics` says what the
    /// statistics and range graphs cover (the scenario's `[statistics]`).
    pub fn create(
        dir: &Path,
        system: &System,
        outputs: &[OutputChannel],
        snapshot_interval: Option<Real>,
        scenario: &Path,
        statistics: &StatisticsOptions,
    ) -> std::io::Result<Self> {
        std::fs::create_dir_all(dir).map_err(|e| io_context(dir, e))?;
        write_json(
            &dir.join("status.json"),
            &json!({"complete": false, "state": "running", "scenario": scenario.display().to_string()}),
        )?;
        let path = dir.join("timeseries.csv");
        let mut ts = BufWriter::new(File::create(&path).map_err(|e| io_context(&path, e))?);
        let names: Vec<String> = outputs.iter().map(|c| c.name(system)).collect();
        let channels: Vec<Channel> = outputs.iter().map(|c| c.channel).collect();
        write!(ts, "time [s]")?;
        for (c, n) in channels.iter().zip(&names) {
            write!(ts, ",{n} [{}]", c.unit())?;
        }
        writeln!(ts)?;
        let mut snapshots = Vec::new();
        if snapshot_interval.is_some() {
            let sd = dir.join("snapshots");
            std::fs::create_dir_all(&sd).map_err(|e| io_context(&sd, e))?;
            for l in &system.lines {
                let p = sd.join(format!("{}.csv", safe_file_name(&l.name)));
                let mut w = BufWriter::new(File::create(&p).map_err(|e| io_context(&p, e))?);
                writeln!(
                    w,
                    "time [s],node,arc_length [m],x [m],y [m],z [m],tension [N]"
                )?;
                snapshots.push(w);
            }
        }
        Ok(Self {
            dir: dir.to_path_buf(),
            statistics: statistics.clone(),
            design: DesignRecorder::new(system, statistics),
            row: vec![0.0; channels.len()],
            names,
            channels,
            detectors: vec![SlackSnapDetector::default(); system.lines.len()],
            timeseries: ts,
            snapshots,
            snapshot_interval,
            scenario: scenario.display().to_string(),
            next_snapshot: 0.0,
            last_time: 0.0,
            samples: 0,
        })
    }

    /// Time of the last sample written [s].
    pub fn last_time(&self) -> Real {
        self.last_time
    }

    /// What [`RunWriter::resume`] needs to go on from here: the length of every file written,
    /// the range graphs, the slack and snap detectors and the snapshot schedule. Flushes
    /// first.
    pub fn progress(&mut self) -> std::io::Result<Vec<u8>> {
        let mut e = hawser::session::Encoder::default();
        self.timeseries.flush()?;
        e.u64(self.timeseries.get_ref().metadata()?.len());
        e.u64(self.snapshots.len() as u64);
        for w in &mut self.snapshots {
            w.flush()?;
            e.u64(w.get_ref().metadata()?.len());
        }
        self.design.encode(&mut e);
        e.u64(self.detectors.len() as u64);
        self.detectors.iter().for_each(|d| d.encode(&mut e));
        e.f64(self.next_snapshot);
        e.f64(self.last_time);
        e.u64(self.samples);
        Ok(e.bytes)
    }

    /// Reopens the files of an interrupted run in `dir` to go on from `progress`
    /// ([`RunWriter::progress`]): each file cut back to its length then (rows written after
    /// the checkpoint are written again by the resumed run) and opened for appending.
    pub fn resume(
        dir: &Path,
        system: &System,
        outputs: &[OutputChannel],
        snapshot_interval: Option<Real>,
        scenario: &Path,
        statistics: &StatisticsOptions,
        progress: &[u8],
    ) -> std::io::Result<Self> {
        let bad = |what: &str| {
            std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("{}: the saved writer state {what}", dir.display()),
            )
        };
        let mut d = hawser::session::Decoder::new(progress);
        let get = |d: &mut hawser::session::Decoder| d.u64().map_err(|_| bad("is truncated"));
        let open = |path: PathBuf, len: u64| -> std::io::Result<BufWriter<File>> {
            let f = std::fs::OpenOptions::new()
                .write(true)
                .open(&path)
                .map_err(|e| io_context(&path, e))?;
            if f.metadata()?.len() < len {
                return Err(bad(&format!(
                    "says {} has {len} bytes, but it is shorter: it was changed since",
                    path.display()
                )));
            }
            f.set_len(len).map_err(|e| io_context(&path, e))?;
            let mut f = f;
            std::io::Seek::seek(&mut f, std::io::SeekFrom::End(0))?;
            Ok(BufWriter::new(f))
        };
        let timeseries = open(dir.join("timeseries.csv"), get(&mut d)?)?;
        let count = get(&mut d)? as usize;
        let names: Vec<String> = outputs.iter().map(|c| c.name(system)).collect();
        let channels: Vec<Channel> = outputs.iter().map(|c| c.channel).collect();
        if count
            != if snapshot_interval.is_some() {
                system.lines.len()
            } else {
                0
            }
        {
            return Err(bad("has another number of snapshot files"));
        }
        let mut snapshots = Vec::new();
        for l in &system.lines[..count] {
            let len = get(&mut d)?;
            snapshots.push(open(
                dir.join("snapshots").join(format!("{}.csv", l.name)),
                len,
            )?);
        }
        let design = DesignRecorder::decode(&mut d, system, statistics)
            .ok_or_else(|| bad("has no range graphs of these lines"))?;
        let n = get(&mut d)? as usize;
        if n != system.lines.len() {
            return Err(bad("has another number of lines"));
        }
        let detectors = (0..n)
            .map(|_| SlackSnapDetector::decode(&mut d).map_err(|_| bad("is truncated")))
            .collect::<Result<Vec<_>, _>>()?;
        let next_snapshot = d.f64().map_err(|_| bad("is truncated"))?;
        let last_time = d.f64().map_err(|_| bad("is truncated"))?;
        let samples = get(&mut d)?;
        write_json(
            &dir.join("status.json"),
            &json!({"complete": false, "state": "running", "scenario": scenario.display().to_string(), "resumed_at": last_time}),
        )?;
        Ok(Self {
            dir: dir.to_path_buf(),
            row: vec![0.0; channels.len()],
            statistics: statistics.clone(),
            design,
            names,
            channels,
            detectors,
            timeseries,
            snapshots,
            snapshot_interval,
            scenario: scenario.display().to_string(),
            next_snapshot,
            last_time,
            samples,
        })
    }

    fn write_sample(&mut self, view: &View<'_>) -> std::io::Result<()> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        for (i, c) in self.channels.iter().enumerate() {
            self.row[i] = view.value(c);
        }
        write!(self.timeseries, "{time}")?;
        for v in &self.row {
            write!(self.timeseries, ",{v}")?;
        }
        writeln!(self.timeseries)?;
        self.timeseries.flush()?;
        self.design.sample(view);
        for li in 0..system.lines.len() {
            let lw = &ws.lines[li];
            // The current mesh: a line on a winch changes its unstretched length.
            let mesh = system.line_mesh(ws, li);
            self.detectors[li].push(time, &lw.elements.tension, &lw.elements.strain, |e| {
                0.5 * (mesh.arc_length(e) + mesh.arc_length(e + 1))
            });
        }
        if let Some(interval) = self.snapshot_interval
            && time >= self.next_snapshot - 1e-9 * interval
        {
            for li in 0..system.lines.len() {
                let w = &mut self.snapshots[li];
                for n in view.line_samples(li) {
                    let p = n.position;
                    writeln!(
                        w,
                        "{time},{},{},{},{},{},{}",
                        n.node, n.arc_length, p.x, p.y, p.z, n.tension
                    )?;
                }
                w.flush()?;
            }
            while self.next_snapshot <= time + 1e-9 * interval {
                self.next_snapshot += interval;
            }
        }
        Ok(())
    }

    /// Writes `summary.json`, `final_state.json` and `status.json` from the last state
    /// `view`. `error` marks the run incomplete with its message; `interrupted` says it was
    /// stopped from outside (it can be resumed).
    pub fn write_end(
        &mut self,
        view: &View<'_>,
        error: Option<&str>,
        interrupted: bool,
    ) -> std::io::Result<()> {
        let system = view.system;
        self.timeseries.flush()?;
        for s in &mut self.snapshots {
            s.flush()?;
        }
        for d in &mut self.detectors {
            d.finish(self.last_time);
        }
        let complete = error.is_none();
        // The design statistics of the time series as written (a resumed run's included).
        let (columns, stats) = timeseries_statistics(&self.dir, &self.statistics)?;
        if columns.len() != self.names.len() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "{}: {} channels in the file, {} in the run",
                    self.dir.join("timeseries.csv").display(),
                    columns.len(),
                    self.names.len()
                ),
            ));
        }
        let channels = statistics_json(&columns, &stats, &self.statistics.linked);
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
                        "strength": self.design.strength_json(system, li),
                    }),
                )
            })
            .collect();
        write_json(
            &self.dir.join("line_ranges.json"),
            &self.design.line_ranges_json(system),
        )?;
        write_json(
            &self.dir.join("summary.json"),
            &json!({
                "complete": complete,
                "error": error,
                "end_time": self.last_time,
                "samples": self.samples,
                "statistics": statistics_options_json(&self.statistics, &columns),
                "channels": channels,
                "lines": lines,
                "definitions": {
                    "slack": "some element of the line has strain ≤ 0",
                    "snap": "a slack → taut transition; peak is the largest element tension until the tension falls again",
                    "location": "unstretched arc length from end A [m] of the element carrying the peak",
                    "strength": "per section of each line, the largest node tension over the statistics window (max_tension [N]), where (at: unstretched arc length from end A [m]) and when (time [s]); utilisation = max_tension / minimum_breaking_load, design_utilisation = max_tension / (minimum_breaking_load / design_safety_factor); worst: the section with the largest design utilisation (utilisation without a safety factor)",
                },
            }),
        )?;
        write_json(
            &self.dir.join("final_state.json"),
            &state_json(view, self.last_time),
        )?;
        write_json(
            &self.dir.join("status.json"),
            &json!({
                "complete": complete,
                "state": if complete { "finished" } else if interrupted { "interrupted" } else { "stopped" },
                "error": error,
                "end_time": self.last_time,
                "scenario": self.scenario,
            }),
        )
    }
}

impl Observer for RunWriter {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        self.last_time = view.time;
        self.samples += 1;
        self.write_sample(view).map_err(|e| {
            ObserverError(format!(
                "cannot write the results in {}: {e}",
                self.dir.display()
            ))
        })
    }

    fn finish(&mut self, view: &View<'_>, end: &RunEnd) -> Result<(), ObserverError> {
        Ok(self.write_end(view, end.error.as_deref(), end.interrupted)?)
    }
}

/// One line's node positions, node tensions and end forces as JSON fields; with `velocities`
/// also the node velocities.
fn line_json(view: &View<'_>, li: usize, velocities: bool) -> Value {
    let (system, ws) = (view.system, view.workspace);
    let lw = &ws.lines[li];
    let line = &system.lines[li];
    let end = |b: bool| {
        let f = view.end_force(li, b);
        json!({"tension": f.norm(), "force": [f.x, f.y, f.z]})
    };
    let xyz = |p: hawser::math::Vec3| [p.x, p.y, p.z];
    let mut v = json!({
        "positions": view.line_samples(li).map(|n| xyz(n.position)).collect::<Vec<_>>(),
        "tension": view.line_samples(li).map(|n| n.tension).collect::<Vec<_>>(),
        "end_a": end(false),
        "end_b": end(true),
    });
    if matches!(line.kind, hawser::formulation::LineKind::Hermite(_)) {
        let n = line.mesh.elements();
        v["tangents"] = json!(
            (0..=n)
                .map(|i| xyz(lw.position[hawser::formulation::hermite::vector_index(i, true, n)]))
                .collect::<Vec<_>>()
        );
        v["bending_moment"] = json!(lw.elements.bending_moment);
        v["curvature"] = json!(lw.elements.curvature);
    }
    if velocities {
        v["velocities"] = json!(
            view.line_samples(li)
                .map(|n| xyz(n.velocity))
                .collect::<Vec<_>>()
        );
    }
    v
}

/// Every point's position and, with `velocities`, velocity, as JSON.
fn points_json(system: &System, ws: &Workspace, velocities: bool) -> Value {
    system
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let k = &ws.points[i];
            let mut v = json!({"position": [k.position.x, k.position.y, k.position.z]});
            if velocities {
                v["velocity"] = json!([k.velocity.x, k.velocity.y, k.velocity.z]);
            }
            (p.name.clone(), v)
        })
        .collect::<serde_json::Map<String, Value>>()
        .into()
}

fn lines_json(view: &View<'_>, velocities: bool) -> Value {
    view.system
        .lines
        .iter()
        .enumerate()
        .map(|(li, l)| (l.name.clone(), line_json(view, li, velocities)))
        .collect::<serde_json::Map<String, Value>>()
        .into()
}

/// The positions, velocities, tensions and end forces of every line and point, and the state
/// vector, as JSON (`final_state.json`).
pub fn state_json(view: &View<'_>, time: Real) -> Value {
    json!({
        "time": time,
        "lines": lines_json(view, true),
        "points": points_json(view.system, view.workspace, true),
        "state_vector": view.state,
    })
}

/// The static solution as JSON: per line node positions, node tensions, the force each end
/// exerts on its attachment and the strength check of its sections; per point its position.
/// A steady tow adds `tow_velocity` [m/s], the velocity of the frame it was solved in.
pub fn statics_json(system: &System, ws: &Workspace) -> Value {
    let view = View {
        system,
        workspace: ws,
        time: 0.0,
        state: &[],
        channels: &[],
        sample: 0,
    };
    let mut v =
        json!({"lines": lines_json(&view, false), "points": points_json(system, ws, false)});
    for (li, l) in system.lines.iter().enumerate() {
        let sections = hawser::analysis::strength::line_strength(system, ws, li);
        v["lines"][&l.name]["strength"] = strength_json(&sections, None);
    }
    if system.tow_velocity != hawser::math::Vec3::zeros() {
        let t = system.tow_velocity;
        v["tow_velocity"] = json!([t.x, t.y, t.z]);
    }
    v
}

/// `name` as a file name that stays inside its folder: path separators, `:`, control
/// characters and a leading `.` become `_` (scenario files refuse such names already; a
/// model built in code may still hold them).
pub fn safe_file_name(name: &str) -> String {
    let mut s: String = name
        .chars()
        .map(|c| {
            if matches!(c, '/' | '\\' | ':') || c.is_control() {
                '_'
            } else {
                c
            }
        })
        .collect();
    if s.starts_with('.') || s.is_empty() {
        s.insert(0, '_');
    }
    s
}

#[cfg(test)]
mod safe_name_tests {
    use super::safe_file_name;

    #[test]
    fn names_cannot_leave_the_folder() {
        assert_eq!(safe_file_name("L1"), "L1");
        assert_eq!(safe_file_name("../../etc/passwd"), "_.._.._etc_passwd");
        assert_eq!(safe_file_name("a\\b:c\u{7}"), "a_b_c_");
        assert_eq!(safe_file_name(".hidden"), "_.hidden");
        assert_eq!(safe_file_name(""), "_");
        for n in ["../x", "/abs", "a/../../b", ".."] {
            let p = std::path::Path::new("out").join(safe_file_name(n));
            assert_eq!(p.parent(), Some(std::path::Path::new("out")), "{n}");
        }
    }
}
