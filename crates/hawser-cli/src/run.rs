//! `hawser run` and `hawser resume`: a session driven to its end with the result writer and the
//! progress display attached, checkpoints at an interval of simulated time, and a clean stop on
//! SIGINT or SIGTERM (rows flushed, summary over what ran, a checkpoint, exit 130 or 143).

use crate::{DeckArgs, load_with, step_error};
use anyhow::{Context, Result};
use hawser::SimulationError;
use hawser::math::Real;
use hawser::session::{
    Decoder, Encoder, Observer, ObserverError, ObserverId, RunEnd, Session, SessionOptions, View,
};
use hawser_io::results::{RunWriter, prepare_output_dir, remove_run_files, write_atomically};
use hawser_io::scenario::LoadedScenario;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// What `hawser run` was asked: kept in `run.json` beside the results, so that `hawser
/// resume` runs the same scenario with the same choices.
struct Invocation {
    scenario: PathBuf,
    deck: DeckArgs,
    allow_unstable_step: bool,
    checkpoint_every: Option<Real>,
}

impl Invocation {
    fn to_json(&self) -> serde_json::Value {
        json!({
            "scenario": self.scenario.display().to_string(),
            "duration": self.deck.deck_duration,
            "vessel_motion": self.deck.vessel_motion.as_ref().map(|p| p.display().to_string()),
            "allow_unstable_step": self.allow_unstable_step,
            "checkpoint_every": self.checkpoint_every,
            "hawser": env!("CARGO_PKG_VERSION"),
        })
    }

    fn from_json(v: &serde_json::Value) -> Option<Self> {
        Some(Self {
            scenario: PathBuf::from(v["scenario"].as_str()?),
            deck: DeckArgs {
                deck_duration: v["duration"].as_f64(),
                vessel_motion: v["vessel_motion"].as_str().map(PathBuf::from),
            },
            allow_unstable_step: v["allow_unstable_step"].as_bool().unwrap_or(false),
            checkpoint_every: v["checkpoint_every"].as_f64(),
        })
    }
}

/// Shows progress while a run goes: the bar on a terminal, progress lines otherwise (a log
/// file, CI, a batch job), so that a log shows the run is alive.
struct Progress {
    bar: Option<ProgressBar>,
    log: Option<ProgressLog>,
    start: Instant,
}

impl Observer for Progress {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        let time = view.time;
        let wall = self.start.elapsed().as_secs_f64();
        if let Some(bar) = &self.bar {
            bar.set_position((time * 1000.0) as u64);
            if wall > 0.0 {
                bar.set_message(format!("t = {time:.2} s, {:.1}× real time", time / wall));
            }
        }
        if let Some(log) = &mut self.log
            && log.due(time, wall)
        {
            err!("{}", log.line(time, wall));
        }
        Ok(())
    }

    fn finish(&mut self, _: &View<'_>, _: &RunEnd) -> Result<(), ObserverError> {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
        Ok(())
    }
}

impl Progress {
    /// Progress of a run to `duration` [s] that starts at `done` [s]: nothing when `quiet`,
    /// the bar when standard error is a terminal, progress lines otherwise.
    fn new(quiet: bool, duration: Real, done: Real) -> Self {
        use std::io::IsTerminal;
        let terminal = std::io::stderr().is_terminal();
        let bar = (!quiet && terminal).then(|| {
            let bar = ProgressBar::new((duration * 1000.0) as u64);
            bar.set_style(
                ProgressStyle::with_template(
                    "{bar:40} {percent:>3}% {msg} [elapsed {elapsed}, ETA {eta}]",
                )
                .expect("valid template"),
            );
            bar.set_position((done * 1000.0) as u64);
            bar
        });
        Self {
            bar,
            log: (!quiet && !terminal).then(|| ProgressLog::new(duration, done, LOG_INTERVAL)),
            start: Instant::now(),
        }
    }
}

/// Wall time between progress lines off a terminal [s].
const LOG_INTERVAL: f64 = 10.0;

/// When to print a progress line off a terminal: at the first sample after every
/// `interval` seconds of wall time, and after every tenth of the simulated duration.
pub(crate) struct ProgressLog {
    duration: Real,
    /// Simulated time at the start (a resumed run's checkpoint) [s].
    done: Real,
    interval: f64,
    next_wall: f64,
    /// The next tenth of the duration to report (1 … 10).
    next_tenth: u32,
}

impl ProgressLog {
    pub(crate) fn new(duration: Real, done: Real, interval: f64) -> Self {
        let tenths = if duration > 0.0 {
            (10.0 * done / duration).floor() as u32
        } else {
            10
        };
        Self {
            duration,
            done,
            interval,
            next_wall: interval,
            next_tenth: tenths + 1,
        }
    }

    /// Whether a line is due at simulated time `time` [s] after `wall` seconds.
    pub(crate) fn due(&mut self, time: Real, wall: f64) -> bool {
        let mut due = false;
        // A sample within a millionth of the duration of a tenth reaches it (sample times
        // carry round-off).
        while self.next_tenth <= 10
            && time >= (self.next_tenth as Real / 10.0 - 1e-6) * self.duration
        {
            self.next_tenth += 1;
            due = true;
        }
        if wall >= self.next_wall {
            while self.next_wall <= wall {
                self.next_wall += self.interval;
            }
            due = true;
        }
        due
    }

    /// The progress line: simulated time, fraction, real-time factor, elapsed time and ETA.
    fn line(&self, time: Real, wall: f64) -> String {
        let rate = (time - self.done) / wall.max(1e-9);
        let percent = if self.duration > 0.0 {
            100.0 * time / self.duration
        } else {
            100.0
        };
        let eta = if rate > 0.0 {
            clock((self.duration - time).max(0.0) / rate)
        } else {
            "unknown".to_string()
        };
        format!(
            "progress: t = {time:.2} s of {:.2} s ({percent:.0} %), {rate:.2}× real time, \
             elapsed {}, ETA {eta}",
            self.duration,
            clock(wall)
        )
    }
}

/// A duration [s] as `1h02m03s`, `2m03s` or `3s`.
pub(crate) fn clock(seconds: f64) -> String {
    let s = seconds.round() as u64;
    match (s / 3600, s / 60 % 60, s % 60) {
        (0, 0, s) => format!("{s}s"),
        (0, m, s) => format!("{m}m{s:02}s"),
        (h, m, s) => format!("{h}h{m:02}m{s:02}s"),
    }
}

#[cfg(test)]
mod progress_tests {
    use super::*;

    /// Lines at every tenth of the duration and every 10 s of wall time, whichever comes
    /// first; a resumed run starts after the tenths it has done.
    #[test]
    fn progress_lines_at_tenths_and_wall_intervals() {
        let mut log = ProgressLog::new(100.0, 0.0, 10.0);
        // Fast: tenths come before the 10 s.
        assert!(!log.due(0.0, 0.0));
        assert!(!log.due(9.9, 0.5));
        assert!(log.due(10.0 - 1e-9, 0.6));
        assert!(!log.due(15.0, 1.0));
        // Slow: the wall interval comes first.
        assert!(log.due(16.0, 10.2));
        assert!(!log.due(16.5, 15.0));
        assert!(log.due(17.0, 20.0));
        // Several tenths in one sample: one line.
        assert!(log.due(45.0, 21.0));
        assert!(!log.due(49.0, 22.0));
        assert!(log.due(50.0, 23.0));
        let line = log.line(50.0, 25.0);
        assert_eq!(
            line,
            "progress: t = 50.00 s of 100.00 s (50 %), 2.00× real time, elapsed 25s, ETA 25s"
        );
        let resumed = ProgressLog::new(100.0, 35.0, 10.0);
        assert_eq!(resumed.next_tenth, 4);
        assert_eq!(clock(3725.0), "1h02m05s");
        assert_eq!(clock(125.4), "2m05s");
    }
}

/// The stop flags of SIGINT and SIGTERM. A second signal of the same kind ends the process at
/// once (exit 130 or 143), for a run that does not stop quickly enough.
pub(crate) struct Signals {
    pub(crate) any: Arc<AtomicBool>,
    interrupt: Arc<AtomicBool>,
    terminate: Arc<AtomicBool>,
}

impl Signals {
    pub(crate) fn install() -> Self {
        use signal_hook::consts::{SIGINT, SIGTERM};
        let s = Self {
            any: Arc::new(AtomicBool::new(false)),
            interrupt: Arc::new(AtomicBool::new(false)),
            terminate: Arc::new(AtomicBool::new(false)),
        };
        for (signal, flag, code) in [(SIGINT, &s.interrupt, 130), (SIGTERM, &s.terminate, 143)] {
            // A failure to install leaves the default action (the process ends).
            let _ = signal_hook::flag::register_conditional_shutdown(signal, code, flag.clone());
            let _ = signal_hook::flag::register(signal, flag.clone());
            let _ = signal_hook::flag::register(signal, s.any.clone());
        }
        s
    }

    /// The exit code of the signal that stopped the run.
    pub(crate) fn exit_code(&self) -> u8 {
        if self.terminate.load(Ordering::Relaxed) {
            143
        } else {
            130
        }
    }
}

/// Builds the session of a loaded scenario: exit code 2 for a step refused at the
/// `time_step` key, 1 for failed statics (both already reported).
pub(crate) fn session_of(
    file: &Path,
    loaded: &LoadedScenario,
    options: SessionOptions,
) -> Result<std::result::Result<Session, ExitCode>> {
    match Session::with_options(loaded.model.clone(), options) {
        Ok(s) => Ok(Ok(s)),
        Err(SimulationError::Statics(e)) => {
            err!("error: {e}");
            Ok(Err(ExitCode::from(1)))
        }
        Err(e @ SimulationError::StepTooLarge { .. }) => {
            err!("{}", step_error(file, loaded, &e));
            Ok(Err(ExitCode::from(2)))
        }
        Err(e @ SimulationError::StepUnusable { .. }) => {
            err!("error: {e}");
            Ok(Err(ExitCode::from(2)))
        }
        Err(SimulationError::Model(e)) => {
            Err(anyhow::Error::new(e).context("the model is invalid"))
        }
        Err(e) => Err(e.into()),
    }
}

/// `hawser run`.
pub(crate) fn run(
    file: &Path,
    out: &Path,
    quiet: bool,
    allow_unstable_step: bool,
    overwrite: bool,
    checkpoint_every: Option<Real>,
    deck: &DeckArgs,
) -> Result<ExitCode> {
    let signals = Signals::install();
    // --overwrite removes the earlier run's results before anything else: a run refused or
    // failed from here on leaves no earlier summary saying "complete" in its folder.
    if overwrite && let Err(e) = remove_run_files(out) {
        err!("error: {e}");
        return Ok(ExitCode::from(2));
    }
    if let Some(c) = checkpoint_every
        && !(c > 0.0 && c.is_finite())
    {
        err!(
            "error: --checkpoint-every {c}: expected a positive number of seconds of simulated time"
        );
        return Ok(ExitCode::from(2));
    }
    let Some(loaded) = load_with(file, deck, quiet) else {
        return Ok(ExitCode::from(2));
    };
    if !loaded.has_simulation {
        err!(
            "error: {} has no [simulation] table\n  = hint: add `[simulation]` with `duration = ...` (s)",
            file.display()
        );
        return Ok(ExitCode::from(2));
    }
    let t0 = Instant::now();
    let options = SessionOptions {
        allow_unstable_step,
        ..Default::default()
    };
    let mut session = match session_of(file, &loaded, options)? {
        Ok(s) => s,
        Err(code) => return Ok(code),
    };
    // Only once the input is accepted: refused input writes nothing.
    if let Err(e) = prepare_output_dir(out, overwrite) {
        err!("error: {e}");
        return Ok(ExitCode::from(2));
    }
    if let Some(f) = session.step_fallback() {
        err!(
            "warning: the deck's dtM = {} s is above hawser's stability limit {:.4e} s \
             (set by {}); using time_step = \"auto\"",
            f.requested,
            f.limit,
            f.culprit
        );
    }
    let model = &loaded.model;
    if let Some(sol) = session.initial_statics()
        && !quiet
    {
        err!(
            "statics: {} after {} iterations, residual {:.2e} N ({:.2} s)",
            sol.method,
            sol.iterations,
            sol.residual,
            t0.elapsed().as_secs_f64()
        );
        if let Some(f) = &sol.fallback {
            err!("note: {f}; {} converged", sol.method);
        }
    }
    for w in session.warnings() {
        err!("warning: {w}");
    }
    {
        let view = session.view()?;
        for w in crate::strength_warnings(view.system, view.workspace, "initial") {
            err!("{w}");
        }
    }
    let (limit, culprit) = session.stable_step();
    let (limit, culprit) = (limit, culprit.to_string());
    if session.step_size() > limit {
        err!(
            "warning: time step {:.4e} s is above the stability estimate {:.4e} s ({}); --allow-unstable-step is set",
            session.step_size(),
            limit,
            culprit
        );
    }
    if (session.sample_interval() - model.settings.output_interval).abs()
        > 1e-9 * model.settings.output_interval
    {
        err!(
            "note: output_interval {} s is not a whole number of {} s steps; sampling every {} s",
            model.settings.output_interval,
            session.step_size(),
            session.sample_interval()
        );
    }
    if !quiet {
        let choice = session.scheme();
        err!("scheme: {} ({})", choice.scheme.name(), choice.reason);
        if choice.scheme == hawser::model::Scheme::GeneralizedAlpha
            && model.settings.time_step == hawser::model::TimeStep::Auto
        {
            err!(
                "time step: adaptive, tolerance {:.1e}, first step {:.4e} s",
                model.settings.tolerance,
                session.step_size()
            );
        } else {
            // The automatic step divides the output interval: say so when that lowered it.
            let wanted = model.settings.safety_factor * limit;
            let lowered = match (&model.settings.time_step, session.step_fallback()) {
                (hawser::model::TimeStep::Auto, _) | (_, Some(_))
                    if session.step_size() < wanted * (1.0 - 1e-9) =>
                {
                    format!(
                        "; lowered from {} × the limit = {wanted:.4e} s ({:.1} %) so that {} \
                         steps make the output interval of {} s",
                        model.settings.safety_factor,
                        100.0 * (1.0 - session.step_size() / wanted),
                        (session.sample_interval() / session.step_size()).round(),
                        session.sample_interval()
                    )
                }
                _ => String::new(),
            };
            err!(
                "time step {:.4e} s (stability limit {:.4e} s, set by {}{lowered}), {} steps",
                session.step_size(),
                limit,
                culprit,
                (model.settings.duration / session.step_size()).ceil()
            );
        }
    }
    let invocation = Invocation {
        scenario: std::fs::canonicalize(file).unwrap_or_else(|_| file.to_path_buf()),
        deck: deck.clone(),
        allow_unstable_step,
        checkpoint_every,
    };
    let text = serde_json::to_string_pretty(&invocation.to_json())? + "\n";
    write_atomically(&out.join("run.json"), text.as_bytes())?;
    let writer = RunWriter::create(out, &session, file, &loaded.formats, &loaded.statistics)?;
    let writer = session.attach(writer);
    session.attach(Progress::new(quiet, model.settings.duration, 0.0));
    drive(session, writer, out, checkpoint_every, &signals, quiet)
}

/// `hawser resume DIR`: goes on from the checkpoint of an interrupted run, with the scenario
/// and choices of its `run.json`, appending to its files.
pub(crate) fn resume(dir: &Path, quiet: bool) -> Result<ExitCode> {
    let signals = Signals::install();
    let refuse = |why: String| {
        err!("error: cannot resume the run in {}: {why}", dir.display());
        Ok(ExitCode::from(2))
    };
    let invocation = match std::fs::read_to_string(dir.join("run.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .and_then(|v| Invocation::from_json(&v))
    {
        Some(i) => i,
        None => {
            return refuse(
                "it has no readable run.json (it was not written by `hawser run`, or by an \
                 older hawser)"
                    .into(),
            );
        }
    };
    let bytes = match std::fs::read(dir.join("checkpoint.bin")) {
        Ok(b) => b,
        Err(_) => {
            let complete = std::fs::read_to_string(dir.join("status.json"))
                .is_ok_and(|s| s.contains("\"complete\": true"));
            return refuse(if complete {
                "the run is complete".into()
            } else {
                "it has no checkpoint.bin (the run stopped before its first checkpoint, or \
                 diverged); hint: run it again with --overwrite"
                    .into()
            });
        }
    };
    let mut d = Decoder::new(&bytes);
    let (session_bytes, writer_bytes) = match d.u64() {
        Ok(n) if (n as usize) <= d.rest().len() => d.rest().split_at(n as usize),
        _ => return refuse("its checkpoint.bin is truncated or corrupt".into()),
    };
    let file = invocation.scenario.as_path();
    let Some(loaded) = load_with(file, &invocation.deck, quiet) else {
        return Ok(ExitCode::from(2));
    };
    let options = SessionOptions {
        allow_unstable_step: invocation.allow_unstable_step,
        ..Default::default()
    };
    let mut session = match Session::restore(loaded.model.clone(), session_bytes, options) {
        Ok(s) => s,
        Err(e) => return refuse(format!("{e} (scenario {})", file.display())),
    };
    let writer = match RunWriter::resume(
        dir,
        &session,
        file,
        &loaded.formats,
        &loaded.statistics,
        writer_bytes,
    ) {
        Ok(w) => w,
        Err(e) => return refuse(e.to_string()),
    };
    if !quiet {
        err!(
            "resuming {} at t = {:.6} s (step {:.4e} s, {} steps done)",
            file.display(),
            session.time(),
            session.step_size(),
            session.steps_done()
        );
    }
    let writer = session.attach(writer);
    let done = session.time();
    session.attach(Progress::new(quiet, loaded.model.settings.duration, done));
    drive(
        session,
        writer,
        dir,
        invocation.checkpoint_every,
        &signals,
        quiet,
    )
}

/// Writes the session and its writer's progress into `checkpoint.bin` (atomically).
fn write_checkpoint(session: &mut Session, writer: ObserverId, out: &Path) -> Result<()> {
    let core = session.checkpoint();
    let progress = session
        .observer_mut::<RunWriter>(writer)
        .expect("the writer is attached")
        .progress()
        .context("cannot save the writer's progress")?;
    let mut e = Encoder::default();
    e.u64(core.len() as u64);
    e.bytes.extend_from_slice(&core);
    e.bytes.extend_from_slice(&progress);
    write_atomically(&out.join("checkpoint.bin"), &e.bytes)?;
    Ok(())
}

/// A line failure as the run reports it.
fn failure_message(f: &hawser::session::FailureEvent) -> String {
    let why = match f.release.cause {
        hawser::session::ReleaseCause::Time => "its failure time",
        hawser::session::ReleaseCause::Tension => "its failure tension",
        hawser::session::ReleaseCause::Host => "the host's call",
    };
    let joined: String = f
        .joined
        .iter()
        .map(|(line, end)| format!(" and line {line} end {}", end.name()))
        .collect();
    format!(
        "failure: line {} end {}{joined} released from point {} at t = {:.6} s (end tension \
         {:.6e} N; released by {why}); the run went on with the end free",
        f.line,
        f.end.name(),
        f.attachment,
        f.release.time,
        f.release.tension
    )
}

/// Runs the session to its end, checkpointing every `every` seconds of simulated time (at the
/// first sample time at or after each multiple), and stops cleanly on a signal.
fn drive(
    mut session: Session,
    writer: ObserverId,
    out: &Path,
    every: Option<Real>,
    signals: &Signals,
    quiet: bool,
) -> Result<ExitCode> {
    session.set_interrupt(signals.any.clone());
    let end = session.end_time();
    let interval = session.sample_interval();
    let start = Instant::now();
    let simulated_from = session.time();
    let result = loop {
        let target = match every {
            Some(c) => {
                let next = ((session.time() + 0.5 * interval) / c).ceil() * c;
                ((next / interval - 1e-9).ceil() * interval).min(end)
            }
            None => end,
        };
        if let Err(e) = session.advance_to(target) {
            break Err(e);
        }
        if session.time() >= end - 0.5 * session.step_size() {
            break Ok(());
        }
        write_checkpoint(&mut session, writer, out)?;
    };
    let wall = start.elapsed().as_secs_f64();
    let interrupted = matches!(result, Err(SimulationError::Interrupted { .. }));
    if interrupted {
        write_checkpoint(&mut session, writer, out)?;
    }
    let finished = session.finish(result.as_ref().err());
    if !interrupted {
        // A finished or diverged run cannot be resumed.
        let _ = std::fs::remove_file(out.join("checkpoint.bin"));
    }
    // Time of the last row written (a sample whose row could not be written is not counted).
    let written = session
        .observer::<RunWriter>(writer)
        .map_or(session.last_sample_time(), RunWriter::last_time);
    if let Err(failed) = finished {
        // The files could not all be written: say so after what stopped the run, if
        // something did (a write failure stops the run, and the end files then fail too).
        if let Err(e) = &result {
            err!("error: {e}");
        }
        err!(
            "error: {failed}\n  = the results in {} are incomplete (results up to t = {:.6} s; \
             status.json may not say so if it could not be written either)",
            out.display(),
            written,
        );
        return Ok(ExitCode::from(1));
    }
    for f in session.failure_events() {
        err!("{}", failure_message(&f));
    }
    match result {
        Ok(()) => {
            if !quiet {
                let simulated = session.time() - simulated_from;
                err!(
                    "done: {:.2} s simulated in {wall:.2} s ({:.1}× real time); results in {}",
                    session.time(),
                    simulated / wall.max(1e-9),
                    out.display()
                );
                if let Some(s) = session.implicit_statistics() {
                    err!(
                        "generalized-α: {} steps ({} refused), {} Newton iterations, {} \
                         Jacobians",
                        s.steps,
                        s.rejected,
                        s.iterations,
                        s.jacobians
                    );
                }
                if let Some(w) = session.scheme_switch() {
                    err!("{}", switch_summary(&w, session.sample_interval()));
                }
            }
            Ok(ExitCode::SUCCESS)
        }
        Err(e) if interrupted => {
            err!(
                "{e}: results up to t = {:.6} s are in {} (marked interrupted), with a \
                 checkpoint; continue with `hawser resume {}`",
                written,
                out.display(),
                out.display()
            );
            Ok(ExitCode::from(signals.exit_code()))
        }
        Err(e) => {
            err!(
                "error: {e}\n  = results up to t = {:.6} s are in {} (marked incomplete)",
                written,
                out.display()
            );
            Ok(ExitCode::from(1))
        }
    }
}

/// `auto`'s switching in words: the time stepped by each scheme and the switches.
fn switch_summary(w: &hawser::integrate::choice::SchemeSwitch, interval: f64) -> String {
    let explicit = w.explicit_outputs as f64 * interval;
    if w.switches == 0 {
        "auto: generalized-α throughout (it did less work than RK4 would have in every window)"
            .to_string()
    } else {
        format!(
            "auto: RK4 stepped {explicit:.2} s where generalized-α did more work than it would \
             have; {} switches between the two",
            w.switches
        )
    }
}
