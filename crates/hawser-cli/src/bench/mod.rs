//! `hawser bench`: time-stepping throughput (node-steps per second per CPU second) of a
//! scenario, and the variants it measures against each other ([`cases`]).

use super::*;

mod cases;
mod coupling;
use cases as bench_cases;

/// Arguments of `hawser bench`.
#[derive(clap::Args, Debug)]
pub struct BenchArgs {
    /// Scenario file (TOML).
    pub file: PathBuf,
    /// Simulated duration [s] (default: the scenario's).
    #[arg(long)]
    pub duration: Option<Real>,
    /// Time step [s] (default: the scenario's rule).
    #[arg(long)]
    pub dt: Option<Real>,
    /// Mass matrix to measure (`fe` lines): lumped, consistent or both.
    #[arg(long, default_value = "both")]
    pub mass: String,
    /// Formulation of every line: as-is (the scenario's), fe, hermite or dg.
    #[arg(long, default_value = "as-is")]
    pub formulation: String,
    /// Polynomial order P of every section with `--formulation dg` (default: the
    /// scenario's, 4 if none); `dg` lines count Σ(P + 1) nodal degrees of freedom per
    /// element as their nodes.
    #[arg(long, value_name = "P")]
    pub order: Option<usize>,
    /// Integration scheme: as-is (the scenario's), rk4, ssp-rk3, three-level,
    /// generalized-alpha, auto or all (the four schemes).
    #[arg(long, default_value = "as-is")]
    pub scheme: String,
    /// `simulation.tolerance` of the cases (the adaptive generalized-α step's local error,
    /// and the accuracy `auto` chooses for) [-].
    #[arg(long)]
    pub tolerance: Option<Real>,
    /// Free rigid bodies: as-is, points (each replaced by point masses at its line ends,
    /// the lines unchanged) or both (each case twice; prints the overhead per body and
    /// step).
    #[arg(long, default_value = "as-is")]
    pub bodies: String,
    /// Sea: as-is, still, regular (H 2 m, T 8 s), jonswap:N (Hs 3 m, Tp 9 s, N
    /// components) or all (still, regular, jonswap:50, jonswap:200; prints the wave
    /// kinematics' cost per node and step over still water, and per evaluation of the
    /// fluid velocity and acceleration alone).
    #[arg(long, default_value = "as-is")]
    pub waves: String,
    /// Wave kinematics of the lines with `--waves`: direct (summed at every point and
    /// evaluation), static-position (sampled at each point's static position and
    /// interpolated in time, default sample interval) or both.
    #[arg(long, default_value = "direct")]
    pub kinematics: String,
    /// Run each case this many times and keep the fastest.
    #[arg(long, default_value_t = 1)]
    pub repeat: usize,
    /// MoorDyn decks: move every Coupled/Vessel point with this vessel motion (columns t,
    /// x, y, z, roll, pitch, yaw in s, m, deg; its first row is t = 0).
    #[arg(long, value_name = "FILE")]
    pub vessel_motion: Option<PathBuf>,
    /// Measure coupling instead: the scenario's prescribed points run as prescribed and as
    /// coupled points a host drives from the same motion every SECONDS (simulated); prints
    /// both throughputs and the CPU-time ratio.
    #[arg(long, value_name = "SECONDS")]
    pub coupling: Option<Real>,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// `hawser bench`.
pub fn run(args: &BenchArgs) -> Result<ExitCode> {
    if let Some(interval) = args.coupling {
        return coupling::run(args, interval);
    }
    bench(
        &args.file,
        args.duration,
        args.dt,
        BenchChoice {
            mass: &args.mass,
            formulation: &args.formulation,
            order: args.order,
            scheme: &args.scheme,
            tolerance: args.tolerance,
            bodies: &args.bodies,
            waves: &args.waves,
            kinematics: &args.kinematics,
            repeat: args.repeat,
        },
        args.vessel_motion.clone(),
        args.json,
    )
}

/// What `hawser bench` varies: mass matrix, formulation, scheme (as given on the command line).
struct BenchChoice<'a> {
    mass: &'a str,
    formulation: &'a str,
    order: Option<usize>,
    scheme: &'a str,
    tolerance: Option<Real>,
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
            err!("error: --mass {other}: expected lumped, consistent or both");
            return Ok(ExitCode::from(2));
        }
    };
    let formulation = match choice.formulation {
        "as-is" => None,
        "fe" => Some(Formulation::Fe),
        "hermite" => Some(Formulation::Hermite),
        "dg" => Some(Formulation::Dg),
        other => {
            err!("error: --formulation {other}: expected as-is, fe, hermite or dg");
            return Ok(ExitCode::from(2));
        }
    };
    if choice.order.is_some() && formulation != Some(Formulation::Dg) {
        err!("error: --order applies to --formulation dg only");
        return Ok(ExitCode::from(2));
    }
    let schemes: Vec<Option<Scheme>> = match choice.scheme {
        "as-is" => vec![None],
        "rk4" => vec![Some(Scheme::Rk4)],
        "ssp-rk3" => vec![Some(Scheme::SspRk3)],
        "three-level" => vec![Some(Scheme::ThreeLevel)],
        "generalized-alpha" => vec![Some(Scheme::GeneralizedAlpha)],
        "auto" => vec![Some(Scheme::Auto)],
        "all" => vec![
            Some(Scheme::Rk4),
            Some(Scheme::SspRk3),
            Some(Scheme::ThreeLevel),
            Some(Scheme::GeneralizedAlpha),
        ],
        other => {
            err!(
                "error: --scheme {other}: expected as-is, rk4, ssp-rk3, three-level, \
                 generalized-alpha, auto or all"
            );
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
            err!("error: --bodies {other}: expected as-is, points or both");
            return Ok(ExitCode::from(2));
        }
    };
    let wave_cases = match bench_cases::parse_waves(choice.waves) {
        Ok(w) => w,
        Err(e) => {
            err!("error: {e}");
            return Ok(ExitCode::from(2));
        }
    };
    use hawser::physics::static_kinematics::WaveKinematicsMethod;
    let static_position: &[bool] = match choice.kinematics {
        "direct" => &[false],
        "static-position" => &[true],
        "both" => &[false, true],
        other => {
            err!("error: --kinematics {other}: expected direct, static-position or both");
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
        if let Some(t) = choice.tolerance {
            model.settings.tolerance = t;
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
                    err!("{}", step_error(file, &loaded, &e));
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
            "formulation": system.lines.first().map_or("fe", |l| l.discretisation.name()),
            "order": model.lines.first().filter(|l| l.formulation == Formulation::Dg).map(|l| l.sections[0].order),
            "scheme": sim.scheme().scheme.name(),
            // `auto` started with generalized-α: its switches to RK4 and back, and the share of
            // the simulated time RK4 stepped.
            "scheme_switches": sim.scheme_switch().map(|w| w.switches),
            "rk4_share": sim.scheme_switch().map(|w| {
                w.explicit_outputs as f64 * model.settings.output_interval / model.settings.duration
            }),
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
            "instruction_set": hawser::math::instruction_set(),
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
            err!(
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
        out!(
            "fe element loop on {} (HAWSER_SIMD=avx2 or baseline to cap it)",
            hawser::math::instruction_set()
        );
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
