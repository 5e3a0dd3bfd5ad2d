//! `hawser sweep SCENARIO CASES --out DIR`: the load cases of a table of dotted-key overrides
//! (hawser-io's [`hawser_io::sweep`]) run on a pool of `--jobs` threads (rayon), one case per
//! task and each case sequential on its thread, so that a case writes into `DIR/CASE/` the
//! files `hawser run` writes for the base scenario with the case's overrides, bit for bit; then
//! one summary table of the cases (`DIR/sweep_summary.csv`, and `.parquet` when the base
//! scenario writes Parquet). Every case is validated before any runs; a case that fails (its
//! statics, a divergence) is a row with its error; Ctrl-C stops the cases going (their files
//! marked interrupted) and writes the summary of what ran. docs/sweep.md describes it.

use crate::DeckArgs;
use crate::run::{ProgressLog, Signals, clock};
use anyhow::{Context, Result};
use hawser::math::Real;
use hawser::session::{Observer, ObserverError, Session, SessionOptions, View};
use hawser_io::results::{RunWriter, prepare_output_dir, run_files_in};
use hawser_io::scenario::ScenarioError;
use hawser_io::scenario::tables::read_text_file;
use hawser_io::sweep::{
    Case, CaseOutcome, CaseScenario, CaseStatus, read_case_table, summary_columns, validate_case,
    write_summary,
};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// `hawser sweep`'s command line.
#[derive(clap::Args)]
pub(crate) struct SweepArgs {
    /// Base scenario file (TOML) or MoorDyn v2 deck.
    scenario: PathBuf,
    /// Table of load cases: CSV (a header of dotted keys such as `lines.chain.length`, an
    /// optional `name` column, one row per case) or TOML (`[[cases]]` tables).
    cases: PathBuf,
    /// Output directory: one folder per case (the files of `hawser run`) and the summary
    /// table.
    #[arg(long, short)]
    out: PathBuf,
    /// Cases run at once, each on one thread (default: every core).
    #[arg(long, value_name = "N")]
    jobs: Option<std::num::NonZeroUsize>,
    /// Run only shard I of N (1 ≤ I ≤ N): the cases k (0-based table row) with k mod N = I − 1;
    /// its summary is `sweep_summary.shard-I-of-N.csv`.
    #[arg(long, value_name = "I/N", value_parser = parse_shard)]
    shard: Option<Shard>,
    /// Hide the progress bar (on a terminal) or the progress lines (otherwise).
    #[arg(long)]
    quiet: bool,
    /// Replace the results of earlier runs in the case folders and an earlier summary.
    #[arg(long)]
    overwrite: bool,
    /// Accept a `time_step` above the stability estimate in every case (as `hawser run`).
    #[arg(long)]
    allow_unstable_step: bool,
    #[command(flatten)]
    deck: DeckArgs,
}

/// Shard `index` (1-based) of `count`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shard {
    index: usize,
    count: usize,
}

impl Shard {
    /// Whether case `k` (0-based table row) belongs to this shard: k mod N = I − 1.
    fn holds(&self, k: usize) -> bool {
        k % self.count == self.index - 1
    }
}

fn parse_shard(s: &str) -> Result<Shard, String> {
    let bad = || format!("`{s}`: expected I/N with whole numbers 1 ≤ I ≤ N, e.g. 1/4");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let (index, count) = (
        i.trim().parse::<usize>().map_err(|_| bad())?,
        n.trim().parse::<usize>().map_err(|_| bad())?,
    );
    if index == 0 || index > count {
        return Err(bad());
    }
    Ok(Shard { index, count })
}

/// The simulated time a case has reached [s], as the bits of an f64, for the progress bar.
struct CaseProgress(Arc<AtomicU64>);

impl Observer for CaseProgress {
    fn sample(&mut self, view: &View<'_>) -> Result<(), ObserverError> {
        self.0.store(view.time.to_bits(), Ordering::Relaxed);
        Ok(())
    }
}

/// What every case shares.
struct Setup<'a> {
    out: &'a Path,
    overwrite: bool,
    allow_unstable_step: bool,
    stop: Arc<AtomicBool>,
}

/// Runs one case into `dir` as `hawser run` runs a scenario: the same session, the same
/// writer, driven to its end (or stopped by `setup.stop`).
fn run_case(
    setup: &Setup,
    case: &Case,
    scenario: &CaseScenario,
    progress: &Arc<AtomicU64>,
) -> CaseOutcome {
    let failed = |error: String| CaseOutcome {
        status: CaseStatus::Failed,
        error: Some(error),
        summary: None,
    };
    if setup.stop.load(Ordering::Relaxed) {
        return CaseOutcome {
            status: CaseStatus::NotRun,
            error: None,
            summary: None,
        };
    }
    let options = SessionOptions {
        allow_unstable_step: setup.allow_unstable_step,
        ..Default::default()
    };
    let loaded = &scenario.loaded;
    let mut session = match Session::with_options(loaded.model.clone(), options) {
        Ok(s) => s,
        Err(e) => return failed(e.to_string()),
    };
    let dir = setup.out.join(&case.name);
    if let Err(e) = prepare_output_dir(&dir, setup.overwrite) {
        return failed(e.to_string());
    }
    match RunWriter::create(
        &dir,
        &session,
        &scenario.path,
        &loaded.formats,
        &loaded.statistics,
    ) {
        Ok(w) => session.attach(w),
        Err(e) => return failed(e.to_string()),
    };
    session.attach(CaseProgress(progress.clone()));
    session.set_interrupt(setup.stop.clone());
    let result = session.advance_to(session.end_time());
    let finished = session.finish(result.as_ref().err());
    let summary = std::fs::read_to_string(dir.join("summary.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok());
    let interrupted = matches!(result, Err(hawser::SimulationError::Interrupted { .. }));
    let error = match (result, finished) {
        (Err(e), _) => Some(e.to_string()),
        (Ok(()), Err(e)) => Some(e.to_string()),
        (Ok(()), Ok(())) => None,
    };
    CaseOutcome {
        status: match (&error, interrupted) {
            (None, _) => CaseStatus::Complete,
            (Some(_), true) => CaseStatus::Interrupted,
            (Some(_), false) => CaseStatus::Failed,
        },
        error,
        summary,
    }
}

/// [`run_case`] with a panic inside hawser caught as the case's error.
fn run_case_caught(
    setup: &Setup,
    case: &Case,
    scenario: &CaseScenario,
    progress: &Arc<AtomicU64>,
) -> CaseOutcome {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        run_case(setup, case, scenario, progress)
    }))
    .unwrap_or_else(|p| {
        let what = hawser::error::panic_message(p.as_ref());
        CaseOutcome {
            status: CaseStatus::Failed,
            error: Some(format!("internal error (a panic in hawser): {what}")),
            summary: None,
        }
    })
}

/// The progress display of a sweep: one bar over the simulated time of all its cases (a
/// finished or failed case counts whole), or progress lines off a terminal.
struct SweepProgress {
    bar: Option<ProgressBar>,
    log: Option<ProgressLog>,
    start: Instant,
    total: Real,
}

impl SweepProgress {
    fn new(quiet: bool, total: Real) -> Self {
        use std::io::IsTerminal;
        let terminal = std::io::stderr().is_terminal();
        let bar = (!quiet && terminal).then(|| {
            let bar = ProgressBar::new((total * 1000.0) as u64);
            bar.set_style(
                ProgressStyle::with_template(
                    "{bar:40} {percent:>3}% {msg} [elapsed {elapsed}, ETA {eta}]",
                )
                .expect("valid template"),
            );
            bar
        });
        Self {
            bar,
            log: (!quiet && !terminal).then(|| ProgressLog::new(total, 0.0, 10.0)),
            start: Instant::now(),
            total,
        }
    }

    /// Shows `simulated` [s] of the total, `done` of `cases` cases ended, `failed` of them
    /// failed.
    fn show(&mut self, simulated: Real, done: usize, cases: usize, failed: usize) {
        let wall = self.start.elapsed().as_secs_f64();
        let failed = match failed {
            0 => String::new(),
            f => format!(", {f} failed"),
        };
        if let Some(bar) = &self.bar {
            bar.set_position((simulated * 1000.0) as u64);
            bar.set_message(format!("{done}/{cases} cases{failed}"));
        }
        if let Some(log) = &mut self.log
            && log.due(simulated, wall)
        {
            let rate = simulated / wall.max(1e-9);
            let eta = match rate > 0.0 {
                true => clock((self.total - simulated).max(0.0) / rate),
                false => "unknown".to_string(),
            };
            err!(
                "progress: {done} of {cases} cases done{failed}; {simulated:.1} s of {:.1} s \
                 simulated ({:.0} %), elapsed {}, ETA {eta}",
                self.total,
                100.0 * simulated / self.total.max(1e-300),
                clock(wall)
            );
        }
    }

    fn finish(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

/// Prints `e` (the table's or the cases' diagnostics) and returns the exit code of bad input.
fn refuse(e: &ScenarioError) -> ExitCode {
    err!("{e}");
    ExitCode::from(2)
}

/// `hawser sweep`.
pub(crate) fn run(args: &SweepArgs) -> Result<ExitCode> {
    let signals = Signals::install();
    let jobs = crate::jobs_or_cores(args.jobs);
    let base = args.scenario.as_path();
    let Some(loaded) = crate::load_with(base, &args.deck, args.quiet) else {
        return Ok(ExitCode::from(2));
    };
    if !loaded.has_simulation {
        err!(
            "error: {} has no [simulation] table\n  = hint: add `[simulation]` with `duration = ...` (s)",
            base.display()
        );
        return Ok(ExitCode::from(2));
    }
    let source = read_text_file(base).with_context(|| format!("cannot read {}", base.display()))?;
    let table = match read_case_table(&args.cases) {
        Ok(t) => t,
        Err(e) => return Ok(refuse(&e)),
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .context("cannot start the threads of the sweep")?;
    // Every case of the table is validated (every shard refuses a bad table alike) before any
    // runs.
    let deck = args.deck.options();
    let validated: Vec<_> = pool.install(|| {
        table
            .cases
            .par_iter()
            .map(|c| validate_case(base, &source, &deck, &table, c))
            .collect()
    });
    let mut diagnostics = Vec::new();
    let mut scenarios = Vec::new();
    for (case, v) in table.cases.iter().zip(validated) {
        match v {
            Ok(s) => {
                if args.shard.is_none_or(|s| s.holds(case.index)) {
                    scenarios.push((case, s));
                }
            }
            Err(d) => diagnostics.extend(d),
        }
    }
    if !diagnostics.is_empty() {
        return Ok(refuse(&ScenarioError { diagnostics }));
    }
    let stem = match args.shard {
        Some(s) => format!("sweep_summary.shard-{}-of-{}", s.index, s.count),
        None => "sweep_summary".to_string(),
    };
    if let Some(code) = check_outputs(args, &stem, &scenarios) {
        return Ok(code);
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let total: Real = scenarios
        .iter()
        .map(|(_, s)| s.loaded.model.settings.duration)
        .sum();
    if !args.quiet {
        err!(
            "sweep: {} case(s){} of {}, {} at a time",
            scenarios.len(),
            args.shard.map_or(String::new(), |s| format!(
                " (shard {} of {})",
                s.index, s.count
            )),
            table.file.display(),
            jobs.min(scenarios.len().max(1))
        );
    }
    let outcomes = run_cases(args, &pool, &scenarios, total, &signals);
    let cases: Vec<&Case> = scenarios.iter().map(|(c, _)| *c).collect();
    let columns = summary_columns(&table, &cases, &outcomes);
    let written = write_summary(&args.out, &stem, &columns, loaded.formats.parquet)?;
    let count = |s: CaseStatus| outcomes.iter().filter(|o| o.status == s).count();
    let (complete, failed, interrupted, not_run) = (
        count(CaseStatus::Complete),
        count(CaseStatus::Failed),
        count(CaseStatus::Interrupted),
        count(CaseStatus::NotRun),
    );
    for ((case, _), o) in scenarios.iter().zip(&outcomes) {
        if o.status == CaseStatus::Failed {
            err!(
                "error: case `{}` failed: {}",
                case.name,
                o.error.as_deref().unwrap_or("")
            );
        }
    }
    let mut tally = format!("{complete} complete");
    for (n, what) in [
        (failed, "failed"),
        (interrupted, "interrupted"),
        (not_run, "not run"),
    ] {
        if n > 0 {
            tally += &format!(", {n} {what}");
        }
    }
    if !args.quiet || failed + interrupted + not_run > 0 {
        err!(
            "sweep: {} case(s): {tally}; summary in {}",
            outcomes.len(),
            written
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(" and ")
        );
    }
    Ok(
        if signals.any.load(Ordering::Relaxed) && interrupted + not_run > 0 {
            ExitCode::from(signals.exit_code())
        } else if failed + interrupted + not_run > 0 {
            ExitCode::from(1)
        } else {
            ExitCode::SUCCESS
        },
    )
}

/// Refuses (exit 2) output folders that hold an earlier run, and an earlier summary of this
/// sweep, unless `--overwrite`.
fn check_outputs(
    args: &SweepArgs,
    stem: &str,
    scenarios: &[(&Case, CaseScenario)],
) -> Option<ExitCode> {
    if args.overwrite {
        return None;
    }
    let mut held: Vec<String> = scenarios
        .iter()
        .filter(|(c, _)| !run_files_in(&args.out.join(&c.name)).is_empty())
        .map(|(c, _)| c.name.clone())
        .collect();
    for ext in ["csv", "parquet"] {
        let f = format!("{stem}.{ext}");
        if args.out.join(&f).exists() {
            held.push(f);
        }
    }
    if held.is_empty() {
        return None;
    }
    let shown = match held.len() {
        n if n > 5 => format!("{}, … ({n} in all)", held[..5].join(", ")),
        _ => held.join(", "),
    };
    err!(
        "error: {} holds the results of an earlier sweep ({shown})\n  = hint: pass --overwrite \
         to replace them, or choose another --out",
        args.out.display()
    );
    Some(ExitCode::from(2))
}

/// Runs the cases on `pool` while this thread shows the progress every 100 ms; returns their
/// outcomes in table order.
fn run_cases(
    args: &SweepArgs,
    pool: &rayon::ThreadPool,
    scenarios: &[(&Case, CaseScenario)],
    total: Real,
    signals: &Signals,
) -> Vec<CaseOutcome> {
    let setup = Setup {
        out: &args.out,
        overwrite: args.overwrite,
        allow_unstable_step: args.allow_unstable_step,
        stop: signals.any.clone(),
    };
    let n = scenarios.len();
    let progress: Vec<Arc<AtomicU64>> = (0..n).map(|_| Arc::new(AtomicU64::new(0))).collect();
    let ended: Vec<AtomicBool> = (0..n).map(|_| AtomicBool::new(false)).collect();
    let failed = AtomicUsize::new(0);
    let mut display = SweepProgress::new(args.quiet, total);
    let show = |display: &mut SweepProgress| {
        let simulated: Real = (0..n)
            .map(|i| match ended[i].load(Ordering::Relaxed) {
                true => scenarios[i].1.loaded.model.settings.duration,
                false => Real::from_bits(progress[i].load(Ordering::Relaxed)),
            })
            .sum();
        let done = ended.iter().filter(|e| e.load(Ordering::Relaxed)).count();
        display.show(simulated, done, n, failed.load(Ordering::Relaxed));
    };
    let outcomes = std::thread::scope(|scope| {
        let work = scope.spawn(|| {
            pool.install(|| {
                (0..n)
                    .into_par_iter()
                    .with_max_len(1)
                    .map(|i| {
                        let (case, scenario) = &scenarios[i];
                        let o = run_case_caught(&setup, case, scenario, &progress[i]);
                        if o.status == CaseStatus::Failed {
                            failed.fetch_add(1, Ordering::Relaxed);
                        }
                        ended[i].store(true, Ordering::Relaxed);
                        o
                    })
                    .collect::<Vec<_>>()
            })
        });
        while !work.is_finished() {
            show(&mut display);
            std::thread::sleep(Duration::from_millis(100));
        }
        work.join()
    });
    show(&mut display);
    display.finish();
    match outcomes {
        Ok(o) => o,
        // run_case_caught catches every panic of a case; this is one of rayon itself.
        Err(_) => (0..n)
            .map(|_| CaseOutcome {
                status: CaseStatus::Failed,
                error: Some("internal error: the thread pool of the sweep panicked".into()),
                summary: None,
            })
            .collect(),
    }
}
