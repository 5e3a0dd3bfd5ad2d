//! `hawser`: the command-line tool. Parsing, progress display and exit codes only; the work is
//! done by the `hawser` core and `hawser-io`.

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use hawser::SimulationError;
use hawser::math::Real;
use hawser::model::{MassMatrix, Model, TimeStep};
use hawser::session::{Session, SessionOptions};
use hawser::statics::StaticOptions;
use hawser::system::{System, Workspace};
use hawser_io::results::statics_json;
use hawser_io::scenario::tables::read_text_file;
use hawser_io::scenario::{self, Diagnostic, InputFormat, LoadedScenario};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

mod bench_cases;
mod modes;
mod run;
mod validate;

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

/// Choices a MoorDyn deck leaves to its host program.
#[derive(clap::Args, Clone, Debug, Default)]
struct DeckArgs {
    /// MoorDyn decks: simulated duration [s] (default: the vessel motion's length, else 60 s).
    #[arg(long = "duration", value_name = "SECONDS")]
    deck_duration: Option<Real>,
    /// MoorDyn decks: move every Coupled/Vessel point with this vessel motion (columns t, x,
    /// y, z, roll, pitch, yaw in s, m, deg; its first row is t = 0).
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
        /// Hide the progress bar.
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
    /// Continue an interrupted run from its checkpoint, appending to its results.
    Resume {
        /// The output directory of the interrupted run.
        dir: PathBuf,
        /// Hide the progress bar.
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
    Bench {
        /// Scenario file (TOML).
        file: PathBuf,
        /// Simulated duration [s] (default: the scenario's).
        #[arg(long)]
        duration: Option<Real>,
        /// Time step [s] (default: the scenario's rule).
        #[arg(long)]
        dt: Option<Real>,
        /// Mass matrix to measure (`fe` lines): lumped, consistent or both.
        #[arg(long, default_value = "both")]
        mass: String,
        /// Formulation of every line: as-is (the scenario's), fe, hermite or dg.
        #[arg(long, default_value = "as-is")]
        formulation: String,
        /// Polynomial order P of every section with `--formulation dg` (default: the
        /// scenario's, 4 if none); `dg` lines count Σ(P + 1) nodal degrees of freedom per
        /// element as their nodes.
        #[arg(long, value_name = "P")]
        order: Option<usize>,
        /// Integration scheme: as-is (the scenario's), rk4, ssp-rk3, three-level or all.
        #[arg(long, default_value = "as-is")]
        scheme: String,
        /// Free rigid bodies: as-is, points (each replaced by point masses at its line ends,
        /// the lines unchanged) or both (each case twice; prints the overhead per body and
        /// step).
        #[arg(long, default_value = "as-is")]
        bodies: String,
        /// Sea: as-is, still, regular (H 2 m, T 8 s), jonswap:N (Hs 3 m, Tp 9 s, N
        /// components) or all (still, regular, jonswap:50, jonswap:200; prints the wave
        /// kinematics' cost per node and step over still water, and per evaluation of the
        /// fluid velocity and acceleration alone).
        #[arg(long, default_value = "as-is")]
        waves: String,
        /// Wave kinematics of the lines with `--waves`: direct (summed at every point and
        /// evaluation), static-position (sampled at each point's static position and
        /// interpolated in time, default sample interval) or both.
        #[arg(long, default_value = "direct")]
        kinematics: String,
        /// Run each case this many times and keep the fastest.
        #[arg(long, default_value_t = 1)]
        repeat: usize,
        /// MoorDyn decks: move every Coupled/Vessel point with this vessel motion (columns t,
        /// x, y, z, roll, pitch, yaw in s, m, deg; its first row is t = 0).
        #[arg(long, value_name = "FILE")]
        vessel_motion: Option<PathBuf>,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
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
        Command::Resume { dir, quiet } => run::resume(&dir, quiet),
        Command::Statics { file, json } => statics(&file, json),
        Command::Check { file, deck } => check(&file, &deck),
        Command::Convert { file, out, deck } => convert(&file, out.as_deref(), &deck),
        Command::Schema => {
            // Ignore a closed pipe (`hawser schema | head`).
            use std::io::Write;
            let _ = writeln!(std::io::stdout().lock(), "{}", scenario::json_schema());
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            file,
            duration,
            dt,
            mass,
            formulation,
            order,
            scheme,
            bodies,
            waves,
            kinematics,
            repeat,
            vessel_motion,
            json,
        } => bench(
            &file,
            duration,
            dt,
            BenchChoice {
                mass: &mass,
                formulation: &formulation,
                order,
                scheme: &scheme,
                bodies: &bodies,
                waves: &waves,
                kinematics: &kinematics,
                repeat,
            },
            vessel_motion,
            json,
        ),
        Command::Modes(args) => modes::run(&args),
        Command::Validate(args) => validate::run(&args),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(1)
        }
    }
}

/// Loads a scenario or MoorDyn deck, printing diagnostics; `None` means bad input (already
/// reported).
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
            eprintln!("{e}");
            None
        }
    }
}

fn print_notes(file: &Path, notes: &[hawser_io::moordyn::Note]) {
    for n in notes {
        if n.line > 0 {
            eprintln!("note: {}:{}: {}", file.display(), n.line, n.message);
        } else {
            eprintln!("note: {}: {}", file.display(), n.message);
        }
    }
}

fn convert(file: &Path, out: Option<&Path>, deck: &DeckArgs) -> Result<ExitCode> {
    let source = read_text_file(file).with_context(|| format!("cannot read {}", file.display()))?;
    if !hawser_io::moordyn::looks_like_deck(&source) {
        eprintln!(
            "error: {} is not a MoorDyn deck (no `---- LINE TYPES ----`, `---- POINTS ----` or `---- LINES ----` section)\n  = hint: `hawser convert` reads MoorDyn v2 input decks; hawser scenarios need no conversion",
            file.display()
        );
        return Ok(ExitCode::from(2));
    }
    let loaded = match hawser_io::moordyn::parse(file, &source, &deck.options()) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{e}");
            return Ok(ExitCode::from(2));
        }
    };
    let text = hawser_io::moordyn::to_toml(&loaded, file);
    match out {
        Some(path) => {
            std::fs::write(path, &text)
                .with_context(|| format!("cannot write {}", path.display()))?;
            print_notes(file, &loaded.notes);
            eprintln!("wrote {}", path.display());
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

fn system_of(model: &Model) -> Result<System> {
    System::new(model).context("the model is invalid")
}

/// Reports a step rejected by the stability check at the `time_step` key.
fn step_error(file: &Path, loaded: &LoadedScenario, e: &SimulationError) -> String {
    if let SimulationError::StepTooLarge {
        step,
        limit,
        culprit,
    } = e
    {
        let source = read_text_file(file).unwrap_or_default();
        let d = Diagnostic::new(
            file,
            &source,
            loaded.time_step_span.clone(),
            "simulation.time_step",
            format!("time_step = {step} s is above the stability limit {limit:.4e} s"),
        )
        .expected(format!("s, ≤ {limit:.4e} (set by {culprit})"))
        .hint("use time_step = \"auto\", a smaller step, or fewer elements");
        return d.to_string();
    }
    e.to_string()
}

fn statics(file: &Path, json: bool) -> Result<ExitCode> {
    let Some(loaded) = load(file) else {
        return Ok(ExitCode::from(2));
    };
    let system = system_of(&loaded.model)?;
    let sol = match hawser::statics::solve(&system, None, &StaticOptions::default()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(ExitCode::from(1));
        }
    };
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    if json {
        out!(
            "{}",
            serde_json::to_string_pretty(&statics_json(&system, &ws))?
        );
        return Ok(ExitCode::SUCCESS);
    }
    out!(
        "static equilibrium: {} ({} iterations, residual {:.2e} N)",
        sol.method,
        sol.iterations,
        sol.residual
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

fn check(file: &Path, deck: &DeckArgs) -> Result<ExitCode> {
    let Some(loaded) = load_with(file, deck, false) else {
        return Ok(ExitCode::from(2));
    };
    let model = &loaded.model;
    let system = system_of(model)?;
    let (limit, culprit) = system.stable_step(model.settings.scheme);
    if let Some((dt, limit, culprit)) = deck_step_above_limit(&loaded, &system) {
        eprintln!(
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
        eprintln!("{}", step_error(file, &loaded, &e));
        return Ok(ExitCode::from(2));
    }
    let nodes: usize = system.lines.iter().map(|l| l.nodes()).sum();
    out!(
        "{}: ok — {} line(s), {} point(s), {} nodes; stable time step {:.4e} s ({})",
        file.display(),
        system.lines.len(),
        system.points.len(),
        nodes,
        limit,
        culprit
    );
    Ok(ExitCode::SUCCESS)
}

/// What `hawser bench` varies: mass matrix, formulation, scheme (as given on the command line).
struct BenchChoice<'a> {
    mass: &'a str,
    formulation: &'a str,
    order: Option<usize>,
    scheme: &'a str,
    bodies: &'a str,
    waves: &'a str,
    kinematics: &'a str,
    repeat: usize,
}

fn bench(
    file: &Path,
    duration: Option<Real>,
    dt: Option<Real>,
    choice: BenchChoice,
    vessel_motion: Option<PathBuf>,
    json: bool,
) -> Result<ExitCode> {
    use hawser::model::{Formulation, Scheme};
    let which = choice.mass;
    let deck = DeckArgs {
        deck_duration: duration,
        vessel_motion,
    };
    let Some(loaded) = load_with(file, &deck, true) else {
        return Ok(ExitCode::from(2));
    };
    let masses: &[MassMatrix] = match which {
        "lumped" => &[MassMatrix::Lumped],
        "consistent" => &[MassMatrix::Consistent],
        "both" => &[MassMatrix::Lumped, MassMatrix::Consistent],
        other => {
            eprintln!("error: --mass {other}: expected lumped, consistent or both");
            return Ok(ExitCode::from(2));
        }
    };
    let formulation = match choice.formulation {
        "as-is" => None,
        "fe" => Some(Formulation::Fe),
        "hermite" => Some(Formulation::Hermite),
        "dg" => Some(Formulation::Dg),
        other => {
            eprintln!("error: --formulation {other}: expected as-is, fe, hermite or dg");
            return Ok(ExitCode::from(2));
        }
    };
    if choice.order.is_some() && formulation != Some(Formulation::Dg) {
        eprintln!("error: --order applies to --formulation dg only");
        return Ok(ExitCode::from(2));
    }
    let schemes: Vec<Option<Scheme>> = match choice.scheme {
        "as-is" => vec![None],
        "rk4" => vec![Some(Scheme::Rk4)],
        "ssp-rk3" => vec![Some(Scheme::SspRk3)],
        "three-level" => vec![Some(Scheme::ThreeLevel)],
        "all" => vec![
            Some(Scheme::Rk4),
            Some(Scheme::SspRk3),
            Some(Scheme::ThreeLevel),
        ],
        other => {
            eprintln!("error: --scheme {other}: expected as-is, rk4, ssp-rk3, three-level or all");
            return Ok(ExitCode::from(2));
        }
    };
    // Hermite and dg lines have one mass: measure it once.
    let masses = if matches!(formulation, Some(Formulation::Hermite | Formulation::Dg)) {
        &masses[masses.len() - 1..]
    } else {
        masses
    };
    // false: the scenario's bodies; true: its free bodies replaced by point masses.
    let as_points: &[bool] = match choice.bodies {
        "as-is" => &[false],
        "points" => &[true],
        "both" => &[false, true],
        other => {
            eprintln!("error: --bodies {other}: expected as-is, points or both");
            return Ok(ExitCode::from(2));
        }
    };
    let wave_cases = match bench_cases::parse_waves(choice.waves) {
        Ok(w) => w,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(ExitCode::from(2));
        }
    };
    use hawser::physics::static_kinematics::WaveKinematicsMethod;
    let static_position: &[bool] = match choice.kinematics {
        "direct" => &[false],
        "static-position" => &[true],
        "both" => &[false, true],
        other => {
            eprintln!("error: --kinematics {other}: expected direct, static-position or both");
            return Ok(ExitCode::from(2));
        }
    };
    let mut variants = Vec::new();
    for &mass in masses {
        for &scheme in &schemes {
            for &points in as_points {
                for &w in &wave_cases {
                    for &sp in static_position {
                        // Still water has no wave kinematics to choose.
                        if sp && w == bench_cases::WaveCase::Still && static_position.len() > 1 {
                            continue;
                        }
                        variants.push((mass, scheme, points, w, sp));
                    }
                }
            }
        }
    }
    // Every variant's model, system and initial state first; then the repeats interleaved
    // (variant 1, 2, …, 1, 2, …) so that each repeat pairs the variants under the same load.
    struct Case {
        model: Model,
        system: System,
        y0: Vec<Real>,
        wave_case: bench_cases::WaveCase,
        static_position: bool,
        replaced: usize,
        free_bodies: usize,
        mass: MassMatrix,
    }
    let mut cases = Vec::new();
    for (mass, scheme, points, wave_case, sp) in variants {
        let mut model = loaded.model.clone();
        let replaced = if points {
            bench_cases::bodies_as_points(&mut model)
        } else {
            0
        };
        let free_bodies = model
            .bodies
            .iter()
            .filter(|b| matches!(b.kind, hawser::model::BodyKind::Free))
            .count();
        model.environment.waves = bench_cases::waves_of(wave_case, &model.environment)
            .map_err(|e| anyhow::anyhow!("--waves {}: {e}", wave_case.label()))?;
        model.environment.wave_kinematics = match (sp, model.environment.waves.field()) {
            (true, Some(f)) => WaveKinematicsMethod::StaticPosition {
                sample_interval: WaveKinematicsMethod::default_sample_interval(f),
            },
            (true, None) => model.environment.wave_kinematics,
            (false, _)
                if choice.kinematics == "direct" && wave_case == bench_cases::WaveCase::AsIs =>
            {
                model.environment.wave_kinematics
            }
            (false, _) => WaveKinematicsMethod::Direct,
        };
        for l in &mut model.lines {
            l.mass_matrix = mass;
            if let Some(f) = formulation {
                l.formulation = f;
            }
            if let Some(p) = choice.order {
                for s in &mut l.sections {
                    s.order = p;
                }
            }
        }
        if let Some(s) = scheme {
            model.settings.scheme = s;
        }
        if let Some(d) = duration {
            model.settings.duration = d;
        }
        if let Some(dt) = dt {
            model.settings.time_step = hawser::model::TimeStep::Fixed(dt);
            model.settings.output_interval =
                dt * (model.settings.output_interval / dt).round().max(1.0);
        }
        let system = system_of(&model)?;
        // The start of a `--waves` case is the equilibrium in calm water (its sea has no
        // ramp: the statics of rigid bodies under a full irregular sea at t = 0 do not
        // converge), from which the sea acts at once.
        let statics = StaticOptions::default();
        let y0 = if wave_case == bench_cases::WaveCase::AsIs {
            hawser::session::initial_state(&system, &model, &statics)
        } else {
            let mut calm = model.clone();
            calm.environment.waves = hawser::physics::waves::Waves::None;
            hawser::session::initial_state(&system_of(&calm)?, &calm, &statics)
        }
        .map_err(|e| anyhow::anyhow!("{e}"))?
        .0;
        cases.push(Case {
            model,
            system,
            y0,
            wave_case,
            static_position: sp && wave_case != bench_cases::WaveCase::Still,
            replaced,
            free_bodies,
            mass,
        });
    }
    // Per case: (wall, cpu) of each repeat, and the fastest run's simulation.
    let mut times: Vec<Vec<(f64, f64)>> = vec![Vec::new(); cases.len()];
    let mut best: Vec<Option<(Session, f64)>> = (0..cases.len()).map(|_| None).collect();
    for _ in 0..choice.repeat.max(1) {
        for (k, c) in cases.iter().enumerate() {
            let cpu0 = bench_cases::thread_cpu_seconds();
            let start = Instant::now();
            // Building the session is timed too: it builds the static-position cache.
            let options = SessionOptions::default();
            let mut sim = match Session::from_state(c.model.clone(), c.y0.clone(), options) {
                Ok(s) => s,
                Err(e) => {
                    eprintln!("{}", step_error(file, &loaded, &e));
                    return Ok(ExitCode::from(2));
                }
            };
            sim.run()?;
            let wall = start.elapsed().as_secs_f64();
            let cpu = match (cpu0, bench_cases::thread_cpu_seconds()) {
                (Some(a), Some(b)) => b - a,
                _ => wall,
            };
            times[k].push((wall, cpu));
            if best[k].as_ref().is_none_or(|(_, w)| cpu < *w) {
                best[k] = Some((sim, cpu));
            }
        }
    }
    let mut results = Vec::new();
    for (k, c) in cases.iter().enumerate() {
        let model = &c.model;
        let system = &c.system;
        let Some((sim, cpu)) = best[k].take() else {
            unreachable!("at least one run")
        };
        let wall = times[k].iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
        // Nodal degrees of freedom: N + 1 nodes of fe and hermite lines (their end nodes
        // included), Σ(P + 1) per element of dg lines (modal coefficients of q per element).
        let nodes: usize = model
            .lines
            .iter()
            .map(|l| match l.formulation {
                Formulation::Dg => l.sections.iter().map(|s| s.elements * (s.order + 1)).sum(),
                _ => l.elements() + 1,
            })
            .sum();
        let steps = sim.steps_done();
        let node_steps = nodes as f64 * steps as f64 / cpu;
        let evals = node_steps * sim.evaluations_per_step() as f64;
        let (limit, _) = system.stable_step(model.settings.scheme);
        // Paired CPU-time ratio to the still-water case of the same mass and scheme: the
        // median over repeats of cpu(this) / cpu(still) of the same repeat.
        let still = cases.iter().position(|o| {
            o.wave_case == bench_cases::WaveCase::Still
                && o.mass == c.mass
                && o.model.settings.scheme == model.settings.scheme
                && o.replaced == c.replaced
        });
        let ratio = still.map(|s| {
            let mut r: Vec<f64> = times[k]
                .iter()
                .zip(&times[s])
                .map(|(a, b)| a.1 / b.1)
                .collect();
            bench_cases::median(&mut r)
        });
        let memory = sim
            .workspace()
            .wave_points
            .tables()
            .map(|t| t.memory_bytes());
        results.push(serde_json::json!({
            "formulation": system.lines.first().map_or("fe", |l| l.kind.name()),
            "order": model.lines.first().filter(|l| l.formulation == Formulation::Dg).map(|l| l.sections[0].order),
            "scheme": format!("{:?}", model.settings.scheme).to_lowercase(),
            "stable_step": limit,
            "mass_matrix": format!("{:?}", c.mass).to_lowercase(),
            "nodes": nodes,
            "time_step": sim.step_size(),
            "steps": steps,
            "duration": model.settings.duration,
            "wall_s": wall,
            "cpu_s": cpu,
            "evaluations_per_step": sim.evaluations_per_step(),
            "node_steps_per_s": node_steps,
            "node_evaluations_per_s": evals,
            "real_time_factor": model.settings.duration / cpu,
            "free_bodies": c.free_bodies,
            "bodies_replaced_by_points": c.replaced,
            "waves": c.wave_case.label(),
            "kinematics": if c.static_position { "static-position" } else { "direct" },
            "cpu_ratio_to_still": ratio,
            "wave_table_bytes": memory,
            "wave_table_points": sim.workspace().wave_points.tables().map(|t| t.points()),
            "us_per_step": cpu * 1e6 / steps as f64,
        }));
    }
    add_differences(&mut results);
    // The fluid velocity and acceleration alone, per evaluation, for every sea measured.
    let mut kinematics = Vec::new();
    if choice.waves != "as-is" {
        for &w in &wave_cases {
            let mut environment = loaded.model.environment.clone();
            environment.waves = bench_cases::waves_of(w, &environment)
                .map_err(|e| anyhow::anyhow!("--waves {}: {e}", w.label()))?;
            let (ns, _) = bench_cases::kinematics_ns(&environment, 200, 500, false);
            let (two, _) = bench_cases::kinematics_ns(&environment, 200, 500, true);
            kinematics.push(serde_json::json!({
                "waves": w.label(),
                "ns_per_evaluation": ns,
                "ns_per_evaluation_two_calls": two,
            }));
        }
    }
    let extra = choice.bodies != "as-is" || choice.waves != "as-is";
    for r in &results {
        if let (Some(bytes), Some(points)) = (
            r["wave_table_bytes"].as_u64(),
            r["wave_table_points"].as_u64(),
        ) {
            eprintln!(
                "{} static-position cache: {points} points, {bytes} bytes ({:.0} bytes per point)",
                r["waves"].as_str().unwrap_or(""),
                bytes as f64 / points.max(1) as f64
            );
        }
    }
    if json {
        if extra {
            out!(
                "{}",
                serde_json::to_string_pretty(&serde_json::json!({
                    "runs": results,
                    "kinematics": kinematics,
                }))?
            );
        } else {
            out!("{}", serde_json::to_string_pretty(&results)?);
        }
    } else if extra {
        print_variants(&results, &kinematics);
    } else {
        out!(
            "{:<8} {:<11} {:<12} {:>6} {:>10} {:>10} {:>9} {:>9} {:>16} {:>16}",
            "form.",
            "scheme",
            "mass",
            "nodes",
            "limit [s]",
            "dt [s]",
            "steps",
            "wall [s]",
            "node-steps/s",
            "node-evals/s"
        );
        for r in &results {
            let form = r["formulation"].as_str().unwrap_or("");
            let form = match r["order"].as_u64() {
                Some(p) => format!("{form} P{p}"),
                None => form.to_string(),
            };
            out!(
                "{:<8} {:<11} {:<12} {:>6} {:>10.3e} {:>10.3e} {:>9} {:>9.3} {:>16.3e} {:>16.3e}",
                form,
                r["scheme"].as_str().unwrap_or(""),
                r["mass_matrix"].as_str().unwrap_or(""),
                r["nodes"],
                r["stable_step"].as_f64().unwrap_or(0.0),
                r["time_step"].as_f64().unwrap_or(0.0),
                r["steps"],
                r["wall_s"].as_f64().unwrap_or(0.0),
                r["node_steps_per_s"].as_f64().unwrap_or(0.0),
                r["node_evaluations_per_s"].as_f64().unwrap_or(0.0)
            );
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// Adds to each run of `hawser bench --bodies/--waves` its difference from the matching
/// baseline (same mass matrix and scheme): `body_overhead_us_per_body_step`, the extra wall
/// time per step and free body over the run with its bodies as points [µs], and
/// `kinematics_ns_per_node_step`, the extra wall time per step and nodal degree of freedom
/// over the still-water run [ns].
fn add_differences(results: &mut [serde_json::Value]) {
    let key = |r: &serde_json::Value| {
        (
            r["mass_matrix"].as_str().unwrap_or("").to_string(),
            r["scheme"].as_str().unwrap_or("").to_string(),
        )
    };
    let snapshot = results.to_vec();
    for r in results.iter_mut() {
        let us = r["us_per_step"].as_f64().unwrap_or(0.0);
        let bodies = r["free_bodies"].as_u64().unwrap_or(0);
        let points = r["bodies_replaced_by_points"].as_u64().unwrap_or(0) > 0;
        if bodies > 0 && !points {
            if let Some(base) = snapshot.iter().find(|o| {
                key(o) == key(r)
                    && o["waves"] == r["waves"]
                    && o["bodies_replaced_by_points"].as_u64().unwrap_or(0) == bodies
            }) {
                let d = (us - base["us_per_step"].as_f64().unwrap_or(0.0)) / bodies as f64;
                r["body_overhead_us_per_body_step"] = serde_json::json!(d);
            }
        }
        if r["waves"] != "still" {
            if let Some(base) = snapshot.iter().find(|o| {
                key(o) == key(r)
                    && o["waves"] == "still"
                    && o["bodies_replaced_by_points"] == r["bodies_replaced_by_points"]
            }) {
                let nodes = r["nodes"].as_f64().unwrap_or(1.0);
                let d = (us - base["us_per_step"].as_f64().unwrap_or(0.0)) * 1e3 / nodes;
                r["kinematics_ns_per_node_step"] = serde_json::json!(d);
            }
        }
    }
}

/// The table of `hawser bench --bodies/--waves`.
fn print_variants(results: &[serde_json::Value], kinematics: &[serde_json::Value]) {
    out!(
        "{:<8} {:<11} {:<10} {:<17} {:<7} {:>6} {:>6} {:>10} {:>8} {:>9} {:>10} {:>13} {:>14} {:>15} {:>10}",
        "form.",
        "scheme",
        "mass",
        "waves",
        "kin.",
        "bodies",
        "nodes",
        "dt [s]",
        "steps",
        "wall [s]",
        "us/step",
        "node-steps/s",
        "us/body/step",
        "ns/node/step",
        "cpu/still"
    );
    let opt = |v: &serde_json::Value| v.as_f64().map_or("-".to_string(), |x| format!("{x:.3}"));
    for r in results {
        let bodies = if r["bodies_replaced_by_points"].as_u64().unwrap_or(0) > 0 {
            "points".to_string()
        } else {
            r["free_bodies"].to_string()
        };
        let kin = match r["kinematics"].as_str() {
            Some("static-position") => "static",
            _ => "direct",
        };
        out!(
            "{:<8} {:<11} {:<10} {:<17} {:<7} {:>6} {:>6} {:>10.3e} {:>8} {:>9.3} {:>10.3} {:>13.3e} {:>14} {:>15} {:>10}",
            r["formulation"].as_str().unwrap_or(""),
            r["scheme"].as_str().unwrap_or(""),
            r["mass_matrix"].as_str().unwrap_or(""),
            r["waves"].as_str().unwrap_or(""),
            kin,
            bodies,
            r["nodes"],
            r["time_step"].as_f64().unwrap_or(0.0),
            r["steps"],
            r["wall_s"].as_f64().unwrap_or(0.0),
            r["us_per_step"].as_f64().unwrap_or(0.0),
            r["node_steps_per_s"].as_f64().unwrap_or(0.0),
            opt(&r["body_overhead_us_per_body_step"]),
            opt(&r["kinematics_ns_per_node_step"]),
            opt(&r["cpu_ratio_to_still"])
        );
    }
    if !kinematics.is_empty() {
        out!("");
        out!(
            "{:<13} {:>22} {:>22}",
            "waves",
            "ns per u + a evaluation",
            "as two calls"
        );
        for k in kinematics {
            out!(
                "{:<13} {:>22.1} {:>22.1}",
                k["waves"].as_str().unwrap_or(""),
                k["ns_per_evaluation"].as_f64().unwrap_or(0.0),
                k["ns_per_evaluation_two_calls"].as_f64().unwrap_or(0.0)
            );
        }
    }
}
