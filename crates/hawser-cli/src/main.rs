//! `hawser`: the command-line tool. Parsing, progress display and exit codes only; the work is
//! done by the `hawser` core and `hawser-io`.

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use hawser::SimulationError;
use hawser::math::Real;
use hawser::model::{MassMatrix, Model, Scheme, TimeStep};
use hawser::session::{Session, SessionOptions};
use hawser::statics::StaticOptions;
use hawser::system::{System, Workspace};
use hawser_io::results::{statics_json, warnings_json};
use hawser_io::scenario::tables::read_text_file;
use hawser_io::scenario::{self, InputFormat, LoadedScenario};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// `println!` that ends the program quietly when stdout is a closed pipe (`hawser ... | head`)
/// instead of panicking.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        if let Err(e) = writeln!(std::io::stdout(), $($arg)*) {
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                std::process::exit(0);
            }
        }
    }};
}

/// `eprintln!` that ignores a failed write: a closed or broken standard error (`2>&-`, a
/// pipe whose reader has gone) must not turn an error report into a panic (exit 101).
macro_rules! err {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

mod bench;
mod modes;
mod run;
mod sweep;
mod validate;

#[derive(Parser)]
#[command(
    name = "hawser",
    version,
    about = "Marine cable dynamics: statics and time-domain simulation of cables, moorings and tethers"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Choices a MoorDyn deck leaves to its host program (the duration also for scenarios).
#[derive(clap::Args, Clone, Debug, Default)]
struct DeckArgs {
    /// Simulated duration [s]: replaces a scenario's `simulation.duration`; for a MoorDyn
    /// deck, default the vessel motion's length, else 60 s.
    #[arg(long = "duration", value_name = "SECONDS")]
    deck_duration: Option<Real>,
    /// MoorDyn decks only: move every Coupled/Vessel point with this vessel motion (columns t,
    /// x, y, z, roll, pitch, yaw in s, m, deg; its first row is t = 0; a relative path is
    /// relative to the working directory). A scenario names its motions itself and refuses it.
    #[arg(long, value_name = "FILE")]
    vessel_motion: Option<PathBuf>,
}

impl DeckArgs {
    fn options(&self) -> hawser_io::moordyn::ConvertOptions {
        hawser_io::moordyn::ConvertOptions {
            duration: self.deck_duration,
            vessel_motion: self.vessel_motion.clone(),
        }
    }
}

#[derive(Subcommand)]
enum Command {
    /// Run a dynamic simulation and write results into a directory.
    Run {
        /// Scenario file (TOML) or MoorDyn v2 deck.
        file: PathBuf,
        /// Output directory.
        #[arg(long, short, default_value = "out")]
        out: PathBuf,
        /// Hide the progress bar (on a terminal) or the progress lines (otherwise: every
        /// 10 s and every tenth of the run) and the notes.
        #[arg(long)]
        quiet: bool,
        /// Accept a `time_step` above the stability estimate (expert use; the run stops with
        /// the time, line and node if it diverges).
        #[arg(long)]
        allow_unstable_step: bool,
        /// Replace the results of an earlier run in the output directory (its files are
        /// removed first); without it such a directory is refused.
        #[arg(long)]
        overwrite: bool,
        /// Save a checkpoint (checkpoint.bin) every SECONDS of simulated time, from which
        /// `hawser resume` continues; a run stopped by Ctrl-C or SIGTERM always saves one.
        #[arg(long, value_name = "SECONDS")]
        checkpoint_every: Option<Real>,
        #[command(flatten)]
        deck: DeckArgs,
    },
    /// Run a table of load cases (dotted-key overrides of a scenario) in parallel, each into
    /// OUT/CASE, with a summary table of their extremes (OUT/sweep_summary.csv).
    Sweep(sweep::SweepArgs),
    /// Continue an interrupted run from its checkpoint, appending to its results.
    Resume {
        /// The output directory of the interrupted run.
        dir: PathBuf,
        /// Hide the progress bar or lines.
        #[arg(long)]
        quiet: bool,
    },
    /// Find the static equilibrium and print tensions and positions.
    Statics {
        /// Scenario file (TOML) or MoorDyn v2 deck.
        file: PathBuf,
        /// Print the full solution as JSON.
        #[arg(long)]
        json: bool,
        /// Print the solver's iteration log (residual, shift and step of each Newton
        /// iteration, each change of method) to standard error.
        #[arg(long)]
        trace: bool,
    },
    /// Draw a run's figures (PNG and SVG in DIR/plots) and DIR/report.html, finished or
    /// running.
    Plot {
        /// The output directory of `hawser run`.
        dir: PathBuf,
        /// Also draw the amplitude spectrum of this channel (a column of timeseries.csv,
        /// e.g. `L1.end_b.tension`); repeat for more.
        #[arg(long, value_name = "CHANNEL")]
        spectrum: Vec<String>,
        /// Upper frequency of the spectra [Hz] (default: 1.5 times the frequency below which
        /// 99.5 % of the variance lies).
        #[arg(long, value_name = "HZ")]
        max_frequency: Option<Real>,
    },
    /// Validate a scenario file or MoorDyn deck without running it.
    Check {
        /// Scenario file (TOML) or MoorDyn v2 deck.
        file: PathBuf,
        #[command(flatten)]
        deck: DeckArgs,
    },
    /// Convert a MoorDyn v2 deck into the equivalent hawser scenario (TOML).
    Convert {
        /// MoorDyn v2 input deck.
        file: PathBuf,
        /// Output file (default: standard output).
        #[arg(long, short)]
        out: Option<PathBuf>,
        #[command(flatten)]
        deck: DeckArgs,
    },
    /// Print the JSON Schema of scenario files.
    Schema,
    /// Measure time-stepping throughput (node-steps per second) on a scenario.
    Bench(bench::BenchArgs),
    /// Natural frequencies, mode shapes, connection stiffness and resonance check.
    Modes(modes::ModesArgs),
    /// Run the verification suite: analytic checks for every formulation, a table, and the
    /// report docs/verification/report.md with plots; exits 1 when a check fails.
    Validate(validate::ValidateArgs),
}

/// Exit codes: 0 success, 1 simulation or statics failure, 2 bad input, 130 and 143 a run
/// stopped by SIGINT and SIGTERM (resumable).
fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run {
            file,
            out,
            quiet,
            allow_unstable_step,
            overwrite,
            checkpoint_every,
            deck,
        } => run::run(
            &file,
            &out,
            quiet,
            allow_unstable_step,
            overwrite,
            checkpoint_every,
            &deck,
        ),
        Command::Sweep(args) => sweep::run(&args),
        Command::Resume { dir, quiet } => run::resume(&dir, quiet),
        Command::Statics { file, json, trace } => statics(&file, json, trace),
        Command::Plot {
            dir,
            spectrum,
            max_frequency,
        } => plot(&dir, spectrum, max_frequency),
        Command::Check { file, deck } => check(&file, &deck),
        Command::Convert { file, out, deck } => convert(&file, out.as_deref(), &deck),
        Command::Schema => {
            // Ignore a closed pipe (`hawser schema | head`).
            use std::io::Write;
            let _ = writeln!(std::io::stdout().lock(), "{}", scenario::json_schema());
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench(args) => bench::run(&args),
        Command::Modes(args) => modes::run(&args),
        Command::Validate(args) => validate::run(&args),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            err!("error: {e:#}");
            ExitCode::from(1)
        }
    }
}

/// Loads a scenario or MoorDyn deck, printing diagnostics; `None` means bad input (already
/// reported).
/// The threads of a `--jobs N` option (`hawser validate`, `hawser sweep`): N, or every core
/// when it is not given (clap refuses 0 for the `NonZeroUsize`).
fn jobs_or_cores(jobs: Option<std::num::NonZeroUsize>) -> usize {
    jobs.or_else(|| std::thread::available_parallelism().ok())
        .map_or(1, std::num::NonZeroUsize::get)
}

fn load(file: &Path) -> Option<LoadedScenario> {
    load_with(file, &DeckArgs::default(), false)
}

/// [`load`] with the choices for a MoorDyn deck; prints the deck's conversion notes unless
/// `quiet`.
fn load_with(file: &Path, deck: &DeckArgs, quiet: bool) -> Option<LoadedScenario> {
    match hawser_io::input::load_input(file, &deck.options()) {
        Ok((s, notes)) => {
            if !quiet {
                print_notes(file, &notes);
            }
            Some(s)
        }
        Err(e) => {
            err!("{e}");
            None
        }
    }
}

fn print_notes(file: &Path, notes: &[hawser_io::moordyn::Note]) {
    for n in notes {
        if n.line > 0 {
            err!("note: {}:{}: {}", file.display(), n.line, n.message);
        } else {
            err!("note: {}: {}", file.display(), n.message);
        }
    }
}

fn convert(file: &Path, out: Option<&Path>, deck: &DeckArgs) -> Result<ExitCode> {
    let source = read_text_file(file).with_context(|| format!("cannot read {}", file.display()))?;
    if !hawser_io::moordyn::looks_like_deck(&source) {
        err!(
            "error: {} is not a MoorDyn deck (no `---- LINE TYPES ----`, `---- POINTS ----` or `---- LINES ----` section)\n  = hint: `hawser convert` reads MoorDyn v2 input decks; hawser scenarios need no conversion",
            file.display()
        );
        return Ok(ExitCode::from(2));
    }
    let loaded = match hawser_io::moordyn::parse(file, &source, &deck.options()) {
        Ok(d) => d,
        Err(e) => {
            err!("{e}");
            return Ok(ExitCode::from(2));
        }
    };
    let text = hawser_io::moordyn::to_toml(&loaded, file);
    match out {
        Some(path) => {
            std::fs::write(path, &text)
                .with_context(|| format!("cannot write {}", path.display()))?;
            print_notes(file, &loaded.notes);
            err!("wrote {}", path.display());
        }
        None => out!("{text}"),
    }
    Ok(ExitCode::SUCCESS)
}

/// A MoorDyn deck's `dtM` above hawser's stability limit, as (dtM, limit, its cause) [s]. Its
/// step was chosen for MoorDyn's integrator, so hawser takes its automatic step instead of
/// refusing the deck as it refuses such a step in a hawser scenario.
fn deck_step_above_limit(loaded: &LoadedScenario, system: &System) -> Option<(Real, Real, String)> {
    let TimeStep::Fixed(dt) = loaded.model.settings.time_step else {
        return None;
    };
    let (limit, culprit) = system.stable_step(loaded.model.settings.scheme);
    (loaded.format == InputFormat::MoorDyn && dt > limit).then_some((dt, limit, culprit))
}

/// The assembled intact system of `model` (without its line failures, which are events of a
/// run: statics, modes and checks analyse the intact system).
fn system_of(model: &Model) -> Result<System> {
    System::new(&model.intact()).context("the model is invalid")
}

/// Reports a step rejected by the stability check at the `time_step` key.
fn step_error(file: &Path, loaded: &LoadedScenario, e: &SimulationError) -> String {
    let source = read_text_file(file).unwrap_or_default();
    hawser_io::input::step_diagnostic(file, &source, loaded, e)
        .map_or_else(|| e.to_string(), |d| d.to_string())
}

fn statics(file: &Path, json: bool, trace: bool) -> Result<ExitCode> {
    let Some(loaded) = load(file) else {
        return Ok(ExitCode::from(2));
    };
    let system = system_of(&loaded.model)?;
    let options = StaticOptions {
        trace,
        ..StaticOptions::default()
    };
    let sol = match hawser::statics::solve(&system, None, &options) {
        Ok(s) => s,
        Err(e) => {
            err!("error: {e}");
            return Ok(ExitCode::from(1));
        }
    };
    for line in &sol.log {
        err!("{line}");
    }
    if let Some(f) = &sol.fallback {
        err!("note: {f}; {} converged", sol.method);
    }
    for w in &sol.warnings {
        err!("warning: {w}");
    }
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    if json {
        let mut j = statics_json(&system, &ws);
        j["solver"] = serde_json::json!({
            "method": sol.method,
            "iterations": sol.iterations,
            "residual": sol.residual,
            "tolerance": sol.tolerance,
            "fallback": sol.fallback,
        });
        j["warnings"] = warnings_json(&sol.warnings);
        out!("{}", serde_json::to_string_pretty(&j)?);
        return Ok(ExitCode::SUCCESS);
    }
    out!(
        "static equilibrium: {} ({} iterations, residual {:.2e} N, tolerance {:.2e} N)",
        sol.method,
        sol.iterations,
        sol.residual,
        sol.tolerance
    );
    out!(
        "{:<16} {:>14} {:>14} {:>14}",
        "line",
        "end A T [N]",
        "end B T [N]",
        "max T [N]"
    );
    for (li, l) in system.lines.iter().enumerate() {
        let ta = system.end_force(&ws, li, false).norm();
        let tb = system.end_force(&ws, li, true).norm();
        let tmax = (0..l.nodes())
            .map(|i| system.node_tension(&ws, li, i))
            .fold(0.0, Real::max);
        out!("{:<16} {:>14.2} {:>14.2} {:>14.2}", l.name, ta, tb, tmax);
    }
    strength_table(&system, &ws);
    for w in strength_warnings(&system, &ws, "static") {
        err!("{w}");
    }
    for (i, p) in system.points.iter().enumerate() {
        if p.free_index.is_some() {
            let x = ws.points[i].position;
            out!(
                "point {:<10} at [{:.4}, {:.4}, {:.4}] m",
                p.name,
                x.x,
                x.y,
                x.z
            );
        }
    }
    for &b in &system.free_bodies {
        let k = &ws.bodies[b];
        let (roll, pitch, yaw) = k.orientation.euler_angles();
        out!(
            "body {:<11} at [{:.4}, {:.4}, {:.4}] m, roll {:.3}°, pitch {:.3}°, yaw {:.3}°",
            system.bodies[b].body.name,
            k.position.x,
            k.position.y,
            k.position.z,
            roll.to_degrees(),
            pitch.to_degrees(),
            yaw.to_degrees()
        );
    }
    if system.tow_velocity != hawser::math::Vec3::zeros() {
        steady_tow_report(&system, &ws);
    }
    Ok(ExitCode::SUCCESS)
}

/// The strength check of every section of every line in the state evaluated in `ws`, as a
/// table, when some line type has a minimum breaking load.
fn strength_table(system: &System, ws: &Workspace) {
    use hawser::analysis::strength::line_strength;
    let lines: Vec<_> = (0..system.lines.len())
        .map(|li| line_strength(system, ws, li))
        .collect();
    if !lines
        .iter()
        .flatten()
        .any(|s| s.minimum_breaking_load.is_some())
    {
        return;
    }
    out!(
        "{:<16} {:>3} {:<16} {:>14} {:>10} {:>14} {:>8} {:>11}",
        "strength: line",
        "sec",
        "line type",
        "max T [N]",
        "at s [m]",
        "MBL [N]",
        "T/MBL",
        "T/(MBL/SF)"
    );
    let ratio = |x: Option<Real>| x.map_or("-".to_string(), |x| format!("{x:.4}"));
    for (l, sections) in system.lines.iter().zip(&lines) {
        for s in sections {
            out!(
                "{:<16} {:>3} {:<16} {:>14.2} {:>10.3} {:>14} {:>8} {:>11}",
                l.name,
                s.section,
                s.line_type,
                s.max_tension,
                s.at,
                s.minimum_breaking_load
                    .map_or("-".to_string(), |m| format!("{m:.4e}")),
                ratio(s.utilisation()),
                ratio(s.design_utilisation())
            );
        }
    }
}

/// Warnings for every section whose largest tension in the state evaluated in `ws` (`what`:
/// "static", "initial") exceeds its permissible tension MBL / SF or its MBL.
fn strength_warnings(system: &System, ws: &Workspace, what: &str) -> Vec<String> {
    use hawser::analysis::strength::line_strength;
    let mut out = Vec::new();
    for (li, l) in system.lines.iter().enumerate() {
        for s in line_strength(system, ws, li) {
            let (Some(mbl), Some(permissible)) = (s.minimum_breaking_load, s.permissible_tension())
            else {
                continue;
            };
            let limit = if s.max_tension > mbl {
                format!("its minimum breaking load {mbl:.4e} N")
            } else if s.max_tension > permissible {
                format!(
                    "its permissible tension MBL/SF = {permissible:.4e} N (design utilisation {:.3})",
                    s.max_tension / permissible
                )
            } else {
                continue;
            };
            out.push(format!(
                "warning: line `{}` section {} ({}): the {what} tension {:.4e} N at s = {:.3} m \
                 exceeds {limit}",
                l.name, s.section, s.line_type, s.max_tension, s.at
            ));
        }
    }
    out
}

/// `hawser statics` on a steady tow: the tow velocity, and every free point's and free
/// body's place relative to the towing vessel (the first prescribed point, or the origin of the
/// first prescribed body), along the tow (ahead +, astern −), across it (to port +) and in
/// height, as the elastic-link paper reports the vehicle relative to the vessel (§5).
fn steady_tow_report(system: &System, ws: &Workspace) {
    use hawser::math::Vec3;
    use hawser::model::{BodyKind, PointKind};
    let v = system.tow_velocity;
    out!(
        "steady tow at [{:.4}, {:.4}, {:.4}] m/s ({:.4} m/s): the equilibrium in the frame \
         moving with the vessel; every node, point and body moves at this velocity",
        v.x,
        v.y,
        v.z,
        v.norm()
    );
    let vessel = system
        .points
        .iter()
        .position(|p| matches!(p.kind, PointKind::Prescribed(_)))
        .map(|i| (system.points[i].name.clone(), ws.points[i].position))
        .or_else(|| {
            system
                .bodies
                .iter()
                .enumerate()
                .find(|(_, b)| matches!(b.body.kind, BodyKind::Prescribed(_)))
                .map(|(i, b)| (b.body.name.clone(), ws.bodies[i].position))
        });
    let Some((name, origin)) = vessel else {
        return;
    };
    let ahead = v.normalize();
    let port = Vec3::z().cross(&ahead);
    let rel = |x: Vec3| {
        let d = x - origin;
        (d.dot(&ahead), d.dot(&port), d.z)
    };
    out!(
        "relative to {name}: {:<16} {:>12} {:>12} {:>12}",
        "",
        "along [m]",
        "across [m]",
        "height [m]"
    );
    for (i, p) in system.points.iter().enumerate() {
        if p.free_index.is_some() {
            let (a, c, h) = rel(ws.points[i].position);
            out!("  point {:<26} {:>12.4} {:>12.4} {:>12.4}", p.name, a, c, h);
        }
    }
    for &b in &system.free_bodies {
        let (a, c, h) = rel(ws.bodies[b].position);
        out!(
            "  body {:<27} {:>12.4} {:>12.4} {:>12.4}",
            system.bodies[b].body.name,
            a,
            c,
            h
        );
    }
}

/// `hawser plot DIR`.
fn plot(dir: &Path, spectra: Vec<String>, max_frequency: Option<Real>) -> Result<ExitCode> {
    if let Some(f) = max_frequency
        && !(f > 0.0 && f.is_finite())
    {
        err!("error: --max-frequency {f}: expected a positive frequency in Hz");
        return Ok(ExitCode::from(2));
    }
    let options = hawser_io::plot::PlotOptions {
        spectra,
        max_frequency,
    };
    match hawser_io::plot::plot_run(dir, &options) {
        Ok(w) => {
            for f in &w.figures {
                out!(
                    "{}",
                    dir.join("plots").join(format!("{}.png", f.stem)).display()
                );
            }
            for n in &w.notes {
                err!("note: {n}");
            }
            out!("{}", w.report.display());
            Ok(ExitCode::SUCCESS)
        }
        Err(e) => {
            err!("error: {e}");
            Ok(ExitCode::from(2))
        }
    }
}

fn check(file: &Path, deck: &DeckArgs) -> Result<ExitCode> {
    let Some(loaded) = load_with(file, deck, false) else {
        return Ok(ExitCode::from(2));
    };
    let model = &loaded.model;
    let system = system_of(model)?;
    let (limit, culprit) = system.stable_step(model.settings.scheme);
    if let Some((dt, limit, culprit)) = deck_step_above_limit(&loaded, &system) {
        err!(
            "warning: the deck's dtM = {dt} s is above hawser's stability limit {limit:.4e} s \
             ({culprit}); `hawser run` will use time_step = \"auto\""
        );
    } else if let TimeStep::Fixed(dt) = model.settings.time_step
        && dt > limit
    {
        let e = SimulationError::StepTooLarge {
            step: dt,
            limit,
            culprit,
        };
        err!("{}", step_error(file, &loaded, &e));
        return Ok(ExitCode::from(2));
    }
    let nodes: usize = system.lines.iter().map(|l| l.nodes()).sum();
    let (step, sets) = hawser::session::planned_step(&system, &model.settings);
    let duration = model.settings.duration;
    let run_nodes = hawser::session::stepped_nodes(&system);
    match hawser::session::check_run_length(step, &sets, duration, run_nodes) {
        Err(e) => {
            err!("error: {e}");
            return Ok(ExitCode::from(2));
        }
        Ok(Some(w)) => err!("warning: {w}"),
        Ok(None) => {}
    }
    let choice = hawser::integrate::choose_scheme(&system, &model.settings);
    let adaptive =
        choice.scheme == Scheme::GeneralizedAlpha && model.settings.time_step == TimeStep::Auto;
    let steps = (duration / step).ceil();
    let plan = if adaptive {
        // The accuracy step bounds the adaptive steps from above only: the response (slack,
        // contact, friction) sets how many are taken.
        let switching = if model.settings.scheme == Scheme::Auto {
            "; where generalized-α does more work than RK4 would, RK4 steps that stretch"
        } else {
            ""
        };
        format!(
            "adaptive steps of at most {step:.4e} s, at least {steps:.0} for {duration} s; the \
             response sets how many (RK4's stable time step {limit:.4e} s){switching}"
        )
    } else {
        format!(
            "stable time step {limit:.4e} s ({culprit}); {steps:.0} steps of at most {step:.4e} s \
             for {duration} s"
        )
    };
    out!(
        "{}: ok — {} line(s), {} point(s), {} nodes; scheme {} ({}); {plan}",
        file.display(),
        system.lines.len(),
        system.points.len(),
        nodes,
        choice.scheme.name(),
        choice.reason,
    );
    Ok(ExitCode::SUCCESS)
}
