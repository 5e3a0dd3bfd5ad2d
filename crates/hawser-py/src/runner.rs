//! Dynamic runs for Python: a [`Job`] is one run of a loaded scenario, kept in memory by a
//! [`Recorder`] (the time series, hawser-io's [`RunSummary`] and the shape snapshots) and,
//! with an output folder, written by hawser-io's [`RunWriter`] exactly as `hawser run`
//! writes it.
//!
//! [`drive`] runs jobs on worker threads without the GIL while the calling thread keeps it
//! only briefly every [`POLL`]: to draw the progress bar and to check for Ctrl-C
//! (`Python::check_signals`), which sets the sessions' stop flag; each run then stops between
//! two steps with its results so far.

use hawser::Model;
use hawser::analysis::OutputChannel;
use hawser::analysis::statistics::StatisticsOptions;
use hawser::math::Real;
use hawser::session::{Observer, ObserverError, RunEnd, Session, SessionOptions, View};
use hawser::system::System;
use hawser_io::results::{RunSummary, RunWriter, SampleTimes, state_json};
use hawser_io::scenario::{LoadedScenario, ScenarioError};
use pyo3::exceptions::PyKeyboardInterrupt;
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

/// How often the calling thread takes the GIL back while runs go on: to check for Ctrl-C and
/// to draw the progress bar.
pub const POLL: Duration = Duration::from_millis(100);

/// One run to do.
#[derive(Clone)]
pub struct Job {
    /// The scenario as loaded (its duration already overridden if asked).
    pub loaded: LoadedScenario,
    /// The input's text, for a diagnostic of a refused time step.
    pub source: String,
    /// The input's path (or the name it was validated under).
    pub path: PathBuf,
    /// Write `hawser run`'s files here.
    pub out: Option<PathBuf>,
}

impl Job {
    fn model(&self) -> &Model {
        &self.loaded.model
    }

    /// End of the run on the output grid [s] (for the progress bar): the model's duration.
    pub fn duration(&self) -> Real {
        self.model().settings.duration
    }
}

/// Shape snapshots of one line: the columns of `snapshots/LINE.csv`.
#[derive(Clone, Debug, Default)]
pub struct LineSnapshots {
    /// Time [s].
    pub time: Vec<Real>,
    /// Node index.
    pub node: Vec<u64>,
    /// Unstretched arc length [m].
    pub arc_length: Vec<Real>,
    /// Position x, y, z [m].
    pub position: [Vec<Real>; 3],
    /// Effective tension [N].
    pub tension: Vec<Real>,
}

/// An observer keeping a run in memory: every sample's channel values, the summary (design
/// statistics, range graphs, line strength, slack intervals, snap events) and the shape
/// snapshots; the simulated time
/// reached goes to `progress` (the bits of an f64) for the progress bar.
pub struct Recorder {
    /// Range graphs, detectors, snapshot schedule: the same as `summary.json`'s.
    pub summary: RunSummary,
    /// Column names.
    pub names: Vec<String>,
    /// Units of the columns.
    pub units: Vec<&'static str>,
    /// Names of the lines, in model order (of `snapshots`).
    pub lines: Vec<String>,
    /// Sample times [s].
    pub times: Vec<Real>,
    /// Channel values, one row of `names.len()` per sample.
    pub values: Vec<Real>,
    /// Per line.
    pub snapshots: Vec<LineSnapshots>,
    /// The last state as `final_state.json` holds it.
    pub final_state: Option<serde_json::Value>,
    /// The summary as `summary.json` holds it.
    pub summary_json: Option<serde_json::Value>,
    /// The range graphs as `line_ranges.json` holds them.
    pub line_ranges_json: Option<serde_json::Value>,
    /// How the run ended.
    pub end: Option<RunEnd>,
    /// Sample times from the sample counter, as `timeseries.csv` writes them.
    sample_times: SampleTimes,
    progress: Arc<AtomicU64>,
}

impl Recorder {
    fn new(
        system: &System,
        outputs: &[OutputChannel],
        snapshot_interval: Option<Real>,
        statistics: &StatisticsOptions,
        sample_times: SampleTimes,
        samples: usize,
        progress: Arc<AtomicU64>,
    ) -> Self {
        Self {
            sample_times,
            summary: RunSummary::new(system, outputs, snapshot_interval, statistics),
            names: outputs.iter().map(|c| c.name(system)).collect(),
            units: outputs.iter().map(|c| c.channel.unit()).collect(),
            lines: system.lines.iter().map(|l| l.name.clone()).collect(),
            // Sized for the run so that recording does not reallocate as it goes.
            times: Vec::with_capacity(samples),
            values: Vec::with_capacity(samples * outputs.len()),
            snapshots: vec![LineSnapshots::default(); system.lines.len()],
            final_state: None,
            summary_json: None,
            line_ranges_json: None,
            end: None,
            progress,
        }
    }
}

impl Observer for Recorder {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let time = self.sample_times.time(view.sample, view.time);
        let snapshot = self.summary.sample(view, time);
        self.times.push(time);
        self.values.extend_from_slice(self.summary.row());
        if snapshot {
            for (li, s) in self.snapshots.iter_mut().enumerate() {
                for n in view.line_samples(li) {
                    s.time.push(time);
                    s.node.push(n.node as u64);
                    s.arc_length.push(n.arc_length);
                    for k in 0..3 {
                        s.position[k].push(n.position[k]);
                    }
                    s.tension.push(n.tension);
                }
            }
        }
        self.progress
            .store(view.time.to_bits(), std::sync::atomic::Ordering::Relaxed);
        Ok(())
    }

    fn finish(&mut self, view: &View<'_>, end: &RunEnd) -> Result<(), ObserverError> {
        self.summary.finish();
        self.summary.set_end(end);
        self.summary.set_failures(view);
        // The design statistics of the samples kept, as `hawser run` computes them from its
        // time series read back.
        let stats = self.summary.statistics_of_rows(&self.times, &self.values);
        self.summary_json = Some(
            self.summary
                .to_json(view.system, end.error.as_deref(), &stats),
        );
        self.line_ranges_json = Some(self.summary.line_ranges_json(view.system));
        self.final_state = Some(state_json(view, self.summary.last_time()));
        self.end = Some(end.clone());
        Ok(())
    }
}

/// Why a run did not start or could not write.
pub enum Failure {
    /// The input is refused (a time step above the stability limit).
    Input(ScenarioError),
    /// The statics or the model failed before the first step.
    Simulation(String),
    /// The output folder could not be written.
    Io(std::io::Error),
    /// A panic inside hawser, caught.
    Panic(String),
}

/// A run that went: to its end, or stopped (`error`, `interrupted`) with its results so far.
pub struct Outcome {
    /// What it recorded.
    pub recorder: Recorder,
    /// Why it stopped early (a divergence, a failed write), if it did.
    pub error: Option<String>,
    /// Whether it was stopped by Ctrl-C.
    pub interrupted: bool,
    /// Where its files are.
    pub out: Option<PathBuf>,
}

/// What a job comes to.
pub type RunResult = Result<Outcome, Failure>;

/// Runs `job` to its end, or until `stop` is set.
pub fn execute(
    job: &Job,
    stop: &Arc<AtomicBool>,
    progress: &Arc<AtomicU64>,
) -> Result<Outcome, Failure> {
    let model = job.model();
    let mut session =
        Session::with_options(model.clone(), SessionOptions::default()).map_err(|e| {
            match hawser_io::input::step_diagnostic(&job.path, &job.source, &job.loaded, &e) {
                Some(d) => Failure::Input(d.into()),
                None => Failure::Simulation(e.to_string()),
            }
        })?;
    let snapshot_interval = model.settings.snapshot_interval;
    if let Some(out) = &job.out {
        hawser_io::results::prepare_output_dir(out, true).map_err(Failure::Io)?;
        let writer = RunWriter::create(
            out,
            &session,
            &job.path,
            &job.loaded.formats,
            &job.loaded.statistics,
        )
        .map_err(Failure::Io)?;
        session.attach(writer);
    }
    let samples = (session.end_time() / session.sample_interval()).round() as usize + 1;
    let recorder = Recorder::new(
        session.system(),
        session.channels(),
        snapshot_interval,
        &job.loaded.statistics,
        SampleTimes::new(
            &model.settings,
            session.step_size(),
            session.sample_interval(),
        ),
        samples,
        progress.clone(),
    );
    let recorder = session.attach(recorder);
    session.set_interrupt(stop.clone());
    let result = session.run();
    let finished = session.finish(result.as_ref().err());
    let interrupted = matches!(result, Err(hawser::SimulationError::Interrupted { .. }));
    let error = match (result, finished) {
        (Err(e), _) => Some(e.to_string()),
        (Ok(()), Err(e)) => Some(e.to_string()),
        (Ok(()), Ok(())) => None,
    };
    Ok(Outcome {
        recorder: session
            .detach::<Recorder>(recorder)
            .expect("the recorder is attached"),
        error,
        interrupted,
        out: job.out.clone(),
    })
}

/// Runs `jobs` on `workers` threads (each run sequential inside, on one thread) while the
/// calling thread checks for Ctrl-C and updates `bar` (an object with `update_to(seconds)`,
/// or `None`) every [`POLL`]. Returns each job's outcome (`None` for a job not started
/// because of Ctrl-C) and the `KeyboardInterrupt` if there was one.
pub fn drive(
    py: Python<'_>,
    jobs: &[Job],
    workers: usize,
    bar: Option<&Bound<'_, PyAny>>,
) -> PyResult<(Vec<Option<RunResult>>, Option<PyErr>)> {
    let n = jobs.len();
    let next = AtomicUsize::new(0);
    let stop = Arc::new(AtomicBool::new(false));
    let progress: Vec<Arc<AtomicU64>> = (0..n).map(|_| Arc::new(AtomicU64::new(0))).collect();
    let mut results: Vec<Option<RunResult>> = (0..n).map(|_| None).collect();
    let mut signal: Option<PyErr> = None;
    let mut first_error: Option<PyErr> = None;
    std::thread::scope(|scope| {
        let (tx, mut rx) = mpsc::channel::<(usize, RunResult)>();
        for _ in 0..workers.clamp(1, n.max(1)) {
            let (tx, next, stop, progress) = (tx.clone(), &next, &stop, &progress);
            scope.spawn(move || {
                loop {
                    let i = next.fetch_add(1, Ordering::SeqCst);
                    if i >= n || stop.load(Ordering::Relaxed) {
                        break;
                    }
                    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                        execute(&jobs[i], stop, &progress[i])
                    }))
                    .unwrap_or_else(|p| {
                        Err(Failure::Panic(hawser::error::panic_message(p.as_ref())))
                    });
                    if tx.send((i, r)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        loop {
            // Wait without the GIL; the receiver goes into the wait and comes back.
            let (back, got) = py.detach(move || {
                let got = rx.recv_timeout(POLL);
                (rx, got)
            });
            rx = back;
            let finished = match got {
                Ok((i, r)) => {
                    results[i] = Some(r);
                    false
                }
                Err(mpsc::RecvTimeoutError::Timeout) => false,
                Err(mpsc::RecvTimeoutError::Disconnected) => true,
            };
            // Signals first: a Ctrl-C that came during the wait would otherwise be raised
            // inside the progress bar's Python code below.
            if signal.is_none()
                && let Err(e) = py.check_signals()
            {
                stop.store(true, Ordering::Relaxed);
                signal = Some(e);
            }
            if let Some(bar) = bar {
                let done: Real = progress
                    .iter()
                    .map(|p| Real::from_bits(p.load(Ordering::Relaxed)))
                    .sum();
                if let Err(e) = bar.call_method1("update_to", (done,)) {
                    // A Ctrl-C that came while the bar's code ran is raised there: it is the
                    // signal, with the runs' results, not an error of the bar.
                    let slot = if e.is_instance_of::<PyKeyboardInterrupt>(py) {
                        &mut signal
                    } else {
                        &mut first_error
                    };
                    if slot.is_none() {
                        *slot = Some(e);
                        stop.store(true, Ordering::Relaxed);
                    }
                }
            }
            if finished {
                break;
            }
        }
    });
    if let Some(e) = first_error {
        return Err(e);
    }
    Ok((results, signal))
}
