//! Result writers: `timeseries.csv` (and from it `timeseries.parquet`), per-line shape
//! snapshots as CSV and as ParaView files, `channels.json` (units), `summary.json` (design
//! statistics, slack intervals, snap events, line strength), `line_ranges.json` (range graphs
//! of tension along each line), `final_state.json` and `status.json`. Rows are written whole
//! as the run goes, so a run that stops early keeps what it wrote, marked incomplete in
//! `status.json` and `summary.json`; the JSON files are replaced atomically. docs/outputs.md
//! describes every file; [`FORMAT_VERSION`] names their layout.
//!
//! Readers: [`read_table`] (a CSV file of a finished or running run, a torn last line
//! dropped), [`read_units`] (`channels.json`).

mod csv;
#[cfg(feature = "parquet")]
mod parquet;
mod summary;
mod vtk;

pub use csv::{RowSink, RowWriter, SampleTimes, Table, TableReader, push_number, read_table};
#[cfg(feature = "parquet")]
pub use parquet::{write_columns_parquet, write_parquet};
pub use summary::{
    RunSummary, integrator_json, section_json, statistics_json, statistics_options_json,
    strength_json, timeseries_statistics,
};
pub use vtk::{PVD_FILE, VTK_DIR, VtkWriter};

use crate::scenario::OutputFormats;
use csv::cannot;
pub use hawser::analysis::OutputChannel;
use hawser::analysis::statistics::StatisticsOptions;
use hawser::math::Real;
use hawser::session::{Observer, ObserverError, RunEnd, Session, View};
use hawser::system::{System, Workspace};
use serde_json::{Value, json};
use std::path::{Path, PathBuf};

/// The version of the layout of a run's files (column names, units, keys). It changes when a
/// reader written for the old layout would read the new one wrongly (a column renamed, a unit
/// or a meaning changed); new keys in the JSON files and new files leave it. `status.json`,
/// `summary.json`, `channels.json` and the Parquet metadata carry it; `hawser resume` refuses
/// a run written in another. Version 1 (unnumbered): units in the CSV headers
/// (`time [s],L1.end_a.tension [N]`). Version 2: plain column names, units in
/// `channels.json`, times from the sample counter, exponents for tiny and huge numbers.
pub const FORMAT_VERSION: u64 = 2;

/// The header of every line's snapshot file (`snapshots/LINE.csv`) and the units of its
/// columns.
pub const SNAPSHOT_COLUMNS: [(&str, &str); 7] = [
    ("time", "s"),
    ("node", "-"),
    ("arc_length", "m"),
    ("x", "m"),
    ("y", "m"),
    ("z", "m"),
    ("tension", "N"),
];

/// A column of a table of mixed types (the summary table of a sweep), one value per row.
#[derive(Clone, Debug, PartialEq)]
pub enum Column {
    /// Text per row (`None`: empty).
    Text(Vec<Option<String>>),
    /// A number per row (`None`: empty).
    Number(Vec<Option<Real>>),
}

/// Writes a dynamic run's results into a directory while it runs.
pub struct RunWriter {
    dir: PathBuf,
    summary: RunSummary,
    timeseries: RowWriter,
    snapshots: Vec<RowWriter>,
    vtk: Option<VtkWriter>,
    parquet: bool,
    scenario: String,
    model_hash: u64,
    times: SampleTimes,
}

/// Writes `value` to `path` atomically: into a temporary file beside it, then renamed over
/// it, so that a reader (or a kill) never sees half a file.
fn write_json(path: &Path, value: &Value) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(value).expect("JSON serialises");
    write_atomically(path, (text + "\n").as_bytes())
}

/// Writes `bytes` to `path` through a temporary file renamed over it: `path` holds either its
/// old or its new content, whenever the process stops. Errors name the file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, bytes).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        cannot("write", &tmp, e)
    })?;
    std::fs::rename(&tmp, path).map_err(|e| cannot("write", path, e))
}

/// The files and folders a run writes into its output folder: what `--overwrite` removes and
/// what marks a folder as holding a run.
pub const RUN_FILES: [&str; 13] = [
    "status.json",
    "summary.json",
    "line_ranges.json",
    "timeseries.csv",
    "timeseries.parquet",
    "channels.json",
    "final_state.json",
    "checkpoint.bin",
    "run.json",
    "snapshots",
    VTK_DIR,
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

/// Removes the run files ([`RUN_FILES`]) from `dir` (the whole `snapshots/`, `vtk/` and
/// `plots/` folders included, so that nothing stale is left beside new results; other files are left
/// alone). Nothing to do for a folder that does not exist.
pub fn remove_run_files(dir: &Path) -> std::io::Result<()> {
    for f in run_files_in(dir) {
        let p = dir.join(f);
        let removed = if p.is_dir() && !p.is_symlink() {
            std::fs::remove_dir_all(&p)
        } else {
            std::fs::remove_file(&p)
        };
        removed.map_err(|e| cannot("remove", &p, e))?;
    }
    Ok(())
}

/// Prepares `dir` for a new run: creates it, and refuses it when it holds another run's files
/// unless `overwrite`, which removes them first ([`remove_run_files`]).
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
        remove_run_files(dir)?;
    }
    std::fs::create_dir_all(dir).map_err(|e| cannot("create", dir, e))
}

/// The units of a run's columns from its `channels.json`: `timeseries` (column name → unit,
/// `time` included) and `snapshots` (snapshot column → unit).
pub fn read_units(dir: &Path) -> std::io::Result<Value> {
    let path = dir.join("channels.json");
    let text = std::fs::read_to_string(&path).map_err(|e| cannot("read", &path, e))?;
    serde_json::from_str(&text).map_err(|e| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("{}: {e}", path.display()),
        )
    })
}

/// Writes `dir/status.json`: `fields` with the format version, the scenario file, the hash of
/// its model ([`hawser::session::model_hash`], as in checkpoints) and the hawser version.
fn write_status(
    dir: &Path,
    scenario: &Path,
    model_hash: u64,
    fields: Value,
) -> std::io::Result<()> {
    let mut v = json!({
        "format_version": FORMAT_VERSION,
        "scenario": scenario.display().to_string(),
        "model_hash": format!("{model_hash:016x}"),
        "hawser": env!("CARGO_PKG_VERSION"),
    });
    if let (Some(v), Value::Object(f)) = (v.as_object_mut(), fields) {
        v.extend(f);
    }
    write_json(&dir.join("status.json"), &v)
}

/// Refuses formats this build cannot write (Parquet without the `parquet` feature).
fn check_formats(formats: &OutputFormats) -> std::io::Result<()> {
    if formats.parquet && !cfg!(feature = "parquet") {
        return Err(std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "this hawser was built without Parquet (cargo feature `parquet`)",
        ));
    }
    Ok(())
}

/// The path of line `line`'s snapshot file in `dir`.
fn snapshot_path(dir: &Path, system: &System, line: usize) -> PathBuf {
    dir.join("snapshots")
        .join(format!("{}.csv", safe_file_name(&system.lines[line].name)))
}

impl RunWriter {
    /// Creates the files of `session`'s run in `dir` (prepared by [`prepare_output_dir`], or
    /// created here when missing): marks the run as running in `status.json`, writes
    /// `channels.json` and the headers of the CSV files at once (so that a folder that cannot
    /// take them is found before the run starts, with the file's name) and the empty ParaView
    /// collection. `scenario` is the file the run came from; `formats` the formats written
    /// besides CSV and JSON; `statistics` what the design statistics and range graphs cover
    /// (the scenario's `[statistics]`, [`crate::scenario::LoadedScenario::statistics`]).
    pub fn create(
        dir: &Path,
        session: &Session,
        scenario: &Path,
        formats: &OutputFormats,
        statistics: &StatisticsOptions,
    ) -> std::io::Result<Self> {
        check_formats(formats)?;
        std::fs::create_dir_all(dir).map_err(|e| cannot("create", dir, e))?;
        let system = session.system();
        let hash = hawser::session::model_hash(session.model());
        write_status(
            dir,
            scenario,
            hash,
            json!({"complete": false, "state": "running"}),
        )?;
        let outputs = session.channels();
        let names: Vec<String> = outputs.iter().map(|c| c.name(system)).collect();
        let units = json!({
            "format_version": FORMAT_VERSION,
            "timeseries": std::iter::once(("time".to_string(), json!("s")))
                .chain(names.iter().zip(outputs).map(|(n, c)| (n.clone(), json!(c.channel.unit()))))
                .collect::<serde_json::Map<_, _>>(),
            "snapshots": SNAPSHOT_COLUMNS
                .iter()
                .map(|(n, u)| (n.to_string(), json!(u)))
                .collect::<serde_json::Map<_, _>>(),
        });
        write_json(&dir.join("channels.json"), &units)?;
        let header = std::iter::once("time").chain(names.iter().map(String::as_str));
        let timeseries = RowWriter::create(&dir.join("timeseries.csv"), header)?;
        let mut w = Self::new(dir, session, scenario, formats, statistics, timeseries)?;
        if w.summary.snapshot_interval.is_some() {
            let sd = dir.join("snapshots");
            std::fs::create_dir_all(&sd).map_err(|e| cannot("create", &sd, e))?;
            for li in 0..system.lines.len() {
                w.snapshots.push(RowWriter::create(
                    &snapshot_path(dir, system, li),
                    SNAPSHOT_COLUMNS.iter().map(|(n, _)| *n),
                )?);
            }
            if formats.vtk {
                w.vtk = Some(VtkWriter::create(dir, system)?);
            }
        }
        Ok(w)
    }

    /// The writer's fixed parts, with its files not yet opened.
    fn new(
        dir: &Path,
        session: &Session,
        scenario: &Path,
        formats: &OutputFormats,
        statistics: &StatisticsOptions,
        timeseries: RowWriter,
    ) -> std::io::Result<Self> {
        let system = session.system();
        let outputs = session.channels();
        let settings = &session.model().settings;
        Ok(Self {
            dir: dir.to_path_buf(),
            summary: RunSummary::new(system, outputs, settings.snapshot_interval, statistics),
            timeseries,
            snapshots: Vec::new(),
            vtk: None,
            parquet: formats.parquet,
            scenario: scenario.display().to_string(),
            model_hash: hawser::session::model_hash(session.model()),
            times: SampleTimes::new(settings, session.step_size(), session.sample_interval()),
        })
    }

    /// Time of the last sample written [s].
    pub fn last_time(&self) -> Real {
        self.summary.last_time()
    }

    /// The range graphs, slack intervals and snap events so far.
    pub fn summary(&self) -> &RunSummary {
        &self.summary
    }

    /// What [`RunWriter::resume`] needs to go on from here: the result format, the length of
    /// every file written, the range graphs, the slack and snap detectors and the snapshot
    /// schedule.
    pub fn progress(&mut self) -> std::io::Result<Vec<u8>> {
        let mut e = hawser::session::Encoder::default();
        e.u64(FORMAT_VERSION);
        e.u64(self.timeseries.len());
        e.u64(self.snapshots.len() as u64);
        for w in &self.snapshots {
            e.u64(w.len());
        }
        let (pvd, count) = self.vtk.as_ref().map_or((0, 0), VtkWriter::progress);
        e.bool(self.vtk.is_some());
        e.u64(pvd);
        e.u64(count);
        self.summary.encode(&mut e);
        Ok(e.bytes)
    }

    /// Reopens the files of an interrupted run in `dir` to go on from `progress`
    /// ([`RunWriter::progress`]): each file cut back to its length then (rows written after
    /// the checkpoint are written again by the resumed run) and opened for appending.
    pub fn resume(
        dir: &Path,
        session: &Session,
        scenario: &Path,
        formats: &OutputFormats,
        statistics: &StatisticsOptions,
        progress: &[u8],
    ) -> std::io::Result<Self> {
        let bad = |what: &str| {
            std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("{}: the saved writer state {what}", dir.display()),
            )
        };
        check_formats(formats)?;
        let truncated = |_| bad("is truncated");
        let mut d = hawser::session::Decoder::new(progress);
        let version = d.u64().map_err(truncated)?;
        if version != FORMAT_VERSION {
            return Err(bad(&format!(
                "is of another result format (this hawser writes format {FORMAT_VERSION}); \
                 hint: finish the run with the hawser that started it, or run it again with \
                 --overwrite"
            )));
        }
        let timeseries =
            RowWriter::reopen(&dir.join("timeseries.csv"), d.u64().map_err(truncated)?)?;
        let mut w = Self::new(dir, session, scenario, formats, statistics, timeseries)?;
        let system = session.system();
        let count = d.u64().map_err(truncated)? as usize;
        let expected = if w.summary.snapshot_interval.is_some() {
            system.lines.len()
        } else {
            0
        };
        if count != expected {
            return Err(bad("has another number of snapshot files"));
        }
        for li in 0..count {
            let len = d.u64().map_err(truncated)?;
            w.snapshots
                .push(RowWriter::reopen(&snapshot_path(dir, system, li), len)?);
        }
        let has_vtk = d.bool().map_err(truncated)?;
        let vtk_progress = (d.u64().map_err(truncated)?, d.u64().map_err(truncated)?);
        if has_vtk != (formats.vtk && w.summary.snapshot_interval.is_some()) {
            return Err(bad("has another choice of ParaView files"));
        }
        if has_vtk {
            w.vtk = Some(VtkWriter::resume(dir, system, vtk_progress)?);
        }
        w.summary.decode(&mut d).map_err(bad)?;
        w.write_status(
            json!({"complete": false, "state": "running", "resumed_at": w.summary.last_time()}),
        )?;
        Ok(w)
    }

    /// Writes `status.json` ([`write_status`]).
    fn write_status(&self, fields: Value) -> std::io::Result<()> {
        write_status(
            &self.dir,
            Path::new(&self.scenario),
            self.model_hash,
            fields,
        )
    }

    fn write_sample(&mut self, view: &View<'_>, time: Real) -> std::io::Result<()> {
        let ts = &mut self.timeseries;
        ts.number(time);
        for v in self.summary.read(view) {
            ts.number(*v);
        }
        ts.end_row();
        ts.commit()?;
        // The summary covers the rows written.
        if self.summary.record(view, time) {
            for li in 0..view.system.lines.len() {
                let w = &mut self.snapshots[li];
                for n in view.line_samples(li) {
                    let p = n.position;
                    w.number(time);
                    w.integer(n.node as u64);
                    for x in [n.arc_length, p.x, p.y, p.z, n.tension] {
                        w.number(x);
                    }
                    w.end_row();
                }
                w.commit()?;
            }
            if let Some(vtk) = &mut self.vtk {
                vtk.snapshot(view, time)?;
            }
        }
        Ok(())
    }

    /// The design statistics of the channels of `timeseries.csv` as written.
    fn channel_statistics(
        &self,
    ) -> std::io::Result<Vec<hawser::analysis::statistics::ChannelStatistics>> {
        let (names, stats) = timeseries_statistics(&self.dir, self.summary.statistics())?;
        if names != self.summary.names {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "{}: its columns are not the run's channels ({} columns, {} channels)",
                    self.dir.join("timeseries.csv").display(),
                    names.len(),
                    self.summary.names.len()
                ),
            ));
        }
        Ok(stats)
    }

    /// Writes `timeseries.parquet` (when chosen) from the CSV.
    #[cfg(feature = "parquet")]
    fn write_parquet(&self, complete: bool) -> std::io::Result<()> {
        if !self.parquet {
            return Ok(());
        }
        let unit_map: serde_json::Map<String, Value> = std::iter::once(("time", "s"))
            .chain(
                self.summary
                    .names
                    .iter()
                    .map(String::as_str)
                    .zip(self.summary.channels.iter().map(|c| c.unit())),
            )
            .map(|(n, u)| (n.to_string(), json!(u)))
            .collect();
        let metadata = [
            ("hawser.format_version", FORMAT_VERSION.to_string()),
            ("hawser.model_hash", format!("{:016x}", self.model_hash)),
            ("hawser.units", Value::Object(unit_map).to_string()),
            ("hawser.complete", complete.to_string()),
        ]
        .map(|(k, v)| (k.to_string(), v));
        write_parquet(
            &self.dir.join("timeseries.csv"),
            &self.dir.join("timeseries.parquet"),
            &metadata,
        )
    }

    /// Without the `parquet` feature a writer that chose Parquet is refused at creation.
    #[cfg(not(feature = "parquet"))]
    fn write_parquet(&self, _: bool) -> std::io::Result<()> {
        debug_assert!(!self.parquet);
        Ok(())
    }

    /// Writes `timeseries.parquet` (when chosen), `summary.json` (its design statistics from
    /// `timeseries.csv` read back: exact across a resume), `line_ranges.json`,
    /// `final_state.json` and `status.json` from the last state `view`. `error` marks the run incomplete with its
    /// message; `interrupted` says it was stopped from outside (it can be resumed). A file
    /// that cannot be written marks the run incomplete with its error in the files after it,
    /// and is the error returned.
    pub fn write_end(
        &mut self,
        view: &View<'_>,
        error: Option<&str>,
        interrupted: bool,
    ) -> std::io::Result<()> {
        self.summary.finish();
        let mut failure = None;
        let mut error = error.map(str::to_string);
        if let Err(e) = self.write_parquet(error.is_none()) {
            error.get_or_insert_with(|| e.to_string());
            failure = Some(e);
        }
        let written = self
            .channel_statistics()
            .and_then(|stats| {
                write_json(
                    &self.dir.join("summary.json"),
                    &self.summary.to_json(view.system, error.as_deref(), &stats),
                )
            })
            .and_then(|()| {
                write_json(
                    &self.dir.join("line_ranges.json"),
                    &self.summary.line_ranges_json(view.system),
                )
            })
            .and_then(|()| {
                write_json(
                    &self.dir.join("final_state.json"),
                    &state_json(view, self.summary.last_time()),
                )
            });
        if let Err(e) = written {
            error.get_or_insert_with(|| e.to_string());
            failure.get_or_insert(e);
        }
        let complete = error.is_none();
        let mut fields = json!({
            "complete": complete,
            "state": if complete { "finished" } else if interrupted { "interrupted" } else { "stopped" },
            "error": error,
            "end_time": self.summary.last_time(),
            "warnings": warnings_json(self.summary.warnings()),
        });
        if let Some(f) = self.summary.failures() {
            fields["failures"] = failures_json(f);
        }
        let status = self.write_status(fields);
        match failure {
            Some(e) => Err(e),
            None => status,
        }
    }
}

impl Observer for RunWriter {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let time = self.times.time(view.sample, view.time);
        // A line failed since the last sample: `status.json` says so while the run goes on.
        let released = view.releases.iter().flatten().count();
        if released > self.summary.failures().map_or(0, <[_]>::len) {
            self.summary.set_failures(view);
            self.write_status(json!({
                "complete": false,
                "state": "running",
                "failures": self.summary.failures().map(failures_json),
            }))?;
        }
        // The error names the file.
        Ok(self.write_sample(view, time)?)
    }

    fn finish(&mut self, view: &View<'_>, end: &RunEnd) -> Result<(), ObserverError> {
        self.summary.set_end(end);
        self.summary.set_failures(view);
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
    if matches!(
        line.discretisation,
        hawser::formulation::Discretisation::Hermite(_)
    ) {
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
        // A failure's free end not released yet is no point of the run.
        .filter(|(_, p)| !p.dormant)
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
/// exerts on its attachment and the strength check of its sections; per point its position;
/// per body (when there are any) the position of its origin, its roll, pitch and yaw [deg]
/// (R = R_z R_y R_x) and the lines' load on it [N, N·m about its origin].
/// A steady tow adds `tow_velocity` [m/s], the velocity of the frame it was solved in.
pub fn statics_json(system: &System, ws: &Workspace) -> Value {
    let view = View {
        system,
        workspace: ws,
        time: 0.0,
        state: &[],
        channels: &[],
        sample: 0,
        releases: &[],
    };
    let mut v =
        json!({"lines": lines_json(&view, false), "points": points_json(system, ws, false)});
    for (li, l) in system.lines.iter().enumerate() {
        let sections = hawser::analysis::strength::line_strength(system, ws, li);
        v["lines"][&l.name]["strength"] = strength_json(&sections, None);
    }
    if !system.bodies.is_empty() {
        let bodies: serde_json::Map<String, Value> = system
            .bodies
            .iter()
            .enumerate()
            .map(|(b, body)| {
                let k = &ws.bodies[b];
                let (roll, pitch, yaw) = k.orientation.euler_angles();
                let x = k.position;
                (
                    body.body.name.clone(),
                    json!({
                        "position": [x.x, x.y, x.z],
                        "roll_pitch_yaw_deg": [roll.to_degrees(), pitch.to_degrees(), yaw.to_degrees()],
                        "line_load": view.body_line_load(b),
                    }),
                )
            })
            .collect();
        v["bodies"] = Value::Object(bodies);
    }
    if system.tow_velocity != hawser::math::Vec3::zeros() {
        let t = system.tow_velocity;
        v["tow_velocity"] = json!([t.x, t.y, t.z]);
    }
    v
}

/// Warnings as JSON: an array of `{"kind": …, "message": …}` (`summary.json`, `status.json`,
/// `hawser statics --json`).
/// Line failures as JSON: per release, the line, end, attachment, time [s], tension [N] and
/// cause, in the model's order of failures; with `joined` (`[{line, end}]`) the further line
/// ends released with it onto the same free point, when there are any.
pub fn failures_json(events: &[hawser::session::FailureEvent]) -> Value {
    events
        .iter()
        .map(|e| {
            let mut v = json!({
                "line": e.line,
                "end": e.end.name(),
                "attachment": e.attachment,
                "time": e.release.time,
                "tension": e.release.tension,
                "cause": e.release.cause.name(),
            });
            if !e.joined.is_empty() {
                v["joined"] = e
                    .joined
                    .iter()
                    .map(|(line, end)| json!({"line": line, "end": end.name()}))
                    .collect::<Vec<_>>()
                    .into();
            }
            v
        })
        .collect::<Vec<_>>()
        .into()
}

/// The run's warnings as JSON.
pub fn warnings_json(warnings: &[hawser::Warning]) -> Value {
    warnings
        .iter()
        .map(|w| json!({"kind": w.kind(), "message": w.to_string()}))
        .collect::<Vec<_>>()
        .into()
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
