//! `hawser modes`: natural frequencies and mode shapes about the static state, the stiffness
//! the lines offer their fixed and prescribed points and every body, and the resonance report.
//!
//! Files written into `--out DIR`: `modes.csv` (mode, frequency, period, label),
//! `shapes_<line>.csv` per line (every mode's nodal displacements, scaled so that the largest
//! displacement of the mode over the whole system is 1), `shapes_points.csv` for free points,
//! `shapes_bodies.csv` for free bodies (origin displacement and rotation), and `modes.json`
//! (what `--json` prints). A model with `dg` lines is analysed through its hermite twin
//! ([`hawser::analysis::modes::modal_twin`]), which the output says.

use anyhow::{Context, Result};
use hawser::analysis::modes::{ModalOptions, ModeOwner, Modes, natural_modes};
use hawser::analysis::resonance::{ResonanceCheck, excitations, resonance_report};
use hawser::linearise::{BodyStiffness, ConnectionStiffness, Linearisation, LinearisationOptions};
use hawser::math::{Real, Vec3};
use hawser::model::PointKind;
use hawser::statics::{StaticOptions, StaticSolution};
use hawser::system::System;
use serde_json::{Value, json};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `hawser modes`.
#[derive(clap::Args)]
pub struct ModesArgs {
    /// Scenario file (TOML).
    file: PathBuf,
    /// Number of modes (the lowest).
    #[arg(long, default_value_t = 10)]
    count: usize,
    /// Directory for mode shapes (CSV per line) and modes.json.
    #[arg(long, short)]
    out: Option<PathBuf>,
    /// Print everything as JSON.
    #[arg(long)]
    json: bool,
    /// Resonance warning margin [%]: warn when an excitation frequency lies within this
    /// fraction of a natural frequency.
    #[arg(long, default_value_t = 10.0)]
    margin: Real,
}

/// Wall times [s] of the stages.
struct Timing {
    statics: f64,
    linearisation: f64,
    modes: f64,
    stiffness: f64,
}

/// Runs `hawser modes`.
pub fn run(args: &ModesArgs) -> Result<ExitCode> {
    if !(args.margin >= 0.0 && args.margin < 100.0) || args.count == 0 {
        eprintln!(
            "error: --margin must be in [0, 100) % and --count at least 1 (got {} %, {})",
            args.margin, args.count
        );
        return Ok(ExitCode::from(2));
    }
    let Some(loaded) = super::load(&args.file) else {
        return Ok(ExitCode::from(2));
    };
    let twin = hawser::analysis::modes::modal_twin(&loaded.model);
    if let Some(t) = &twin {
        for (l, tl) in loaded.model.lines.iter().zip(&t.lines) {
            if l.formulation != tl.formulation {
                eprintln!(
                    "note: line {} (dg, {} elements) is linearised through its hermite twin \
                     ({} cubic elements over the same sections; docs/modes.md)",
                    l.name,
                    l.elements(),
                    tl.elements()
                );
            }
        }
    }
    let system = super::system_of(twin.as_ref().unwrap_or(&loaded.model))?;
    if let Err(e) = hawser::analysis::modes::supported(&system) {
        eprintln!("error: {e}");
        return Ok(ExitCode::from(1));
    }
    let t = Instant::now();
    let sol = match hawser::statics::solve(&system, None, &StaticOptions::default()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(ExitCode::from(1));
        }
    };
    let statics_time = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let lin = hawser::linearise::linearise(&system, &sol.state, LinearisationOptions::default());
    let linearisation_time = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let options = ModalOptions {
        count: args.count,
        ..Default::default()
    };
    let modes = match natural_modes(&system, &lin, &options) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(ExitCode::from(1));
        }
    };
    let modes_time = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let singular = |s| {
        anyhow::anyhow!(
            "the stiffness is singular at {}: a line or joint there has no stiffness (slack, \
             or an unloaded free point); check the static state",
            system.singular_location(s)
        )
    };
    let stiffness = hawser::linearise::connection_stiffness(&system, &lin).map_err(singular)?;
    let body_stiffness = hawser::linearise::body_stiffness(&system, &lin).map_err(singular)?;
    let timing = Timing {
        statics: statics_time,
        linearisation: linearisation_time,
        modes: modes_time,
        stiffness: t.elapsed().as_secs_f64(),
    };
    let margin = args.margin / 100.0;
    let report = resonance_report(&excitations(&system), &modes, margin);
    let document = to_json(
        &system,
        &sol,
        &lin,
        &modes,
        (&stiffness, &body_stiffness),
        &report,
        margin,
        &timing,
    );
    if let Some(dir) = &args.out {
        write_files(dir, &system, &lin, &modes, &document)
            .with_context(|| format!("writing mode shapes into {}", dir.display()))?;
    }
    if args.json {
        print(&serde_json::to_string_pretty(&document)?);
    } else {
        print(&table(
            &system,
            &sol,
            &modes,
            (&stiffness, &body_stiffness),
            &report,
            margin,
        ));
    }
    eprintln!(
        "timing: statics {:.3} s, linearisation {:.3} s, modes {:.3} s ({}), stiffness {:.3} s",
        timing.statics,
        timing.linearisation,
        timing.modes,
        method_name(&modes),
        timing.stiffness
    );
    for r in report.iter().filter(|r| r.warning()) {
        eprintln!(
            "warning: {} at {:.4} Hz is within {} % of mode {} ({:.4} Hz, {})",
            r.excitation.source,
            r.excitation.frequency,
            args.margin,
            r.nearest_mode + 1,
            r.natural_frequency,
            modes.modes[r.nearest_mode].label.text
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes to stdout; a closed pipe ends the program quietly.
fn print(text: &str) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = writeln!(out, "{text}")
        && e.kind() == std::io::ErrorKind::BrokenPipe
    {
        std::process::exit(0);
    }
}

fn method_name(modes: &Modes) -> String {
    match modes.method {
        hawser::analysis::modes::EigenMethod::Dense => match &modes.fallback {
            Some(why) => format!("dense ({why})"),
            None => "dense".to_string(),
        },
        _ => format!(
            "shift-invert subspace iteration, {} iterations, shift {:.3e} rad²/s²",
            modes.iterations, modes.shift
        ),
    }
}

fn body_kind(system: &System, b: usize) -> &'static str {
    match system.bodies[b].body.kind {
        hawser::model::BodyKind::Free => "free",
        hawser::model::BodyKind::Prescribed(_) => "prescribed",
        hawser::model::BodyKind::Coupled => "coupled",
    }
}

fn point_kind(system: &System, p: usize) -> &'static str {
    match system.points[p].kind {
        PointKind::Fixed => "fixed",
        PointKind::Prescribed(_) => "prescribed",
        PointKind::Coupled => "coupled",
        PointKind::Free { .. } => "free",
        PointKind::Body { .. } => "on a body",
    }
}

fn table(
    system: &System,
    sol: &StaticSolution,
    modes: &Modes,
    (stiffness, bodies): (&ConnectionStiffness, &[BodyStiffness]),
    report: &[ResonanceCheck],
    margin: Real,
) -> String {
    let mut s = String::new();
    let mut line = |t: String| {
        s.push_str(&t);
        s.push('\n');
    };
    line(format!(
        "static equilibrium: {} ({} iterations, residual {:.2e} N)",
        sol.method, sol.iterations, sol.residual
    ));
    line(format!(
        "{} degrees of freedom; {}; stiffness asymmetry {:.1e} (symmetric part used)",
        modes.degrees_of_freedom,
        method_name(modes),
        modes.stiffness_asymmetry
    ));
    line(String::new());
    line(format!(
        "{:>4} {:>14} {:>12}  label",
        "mode", "frequency [Hz]", "period [s]"
    ));
    for (i, m) in modes.modes.iter().enumerate() {
        line(format!(
            "{:>4} {:>14.6} {:>12.4}  {}",
            i + 1,
            m.frequency,
            m.period,
            m.label.text
        ));
    }
    line(String::new());
    line(
        "stiffness at connections [N/m] (−∂F/∂x of the lines' force on the point, free points and nodes relaxed):"
            .into(),
    );
    for (i, &p) in stiffness.points.iter().enumerate() {
        let k = stiffness.block(i, i);
        line(format!(
            "  {} ({})",
            system.points[p].name,
            point_kind(system, p)
        ));
        for r in 0..3 {
            line(format!(
                "    [{:>13.5e} {:>13.5e} {:>13.5e} ]",
                k[(r, 0)],
                k[(r, 1)],
                k[(r, 2)]
            ));
        }
    }
    for b in bodies {
        line(format!(
            "  body {} ({}): 6×6 mooring stiffness about its origin [N/m, N/rad; N·m/m, N·m/rad] \
             over x, y, z, rotations about x, y, z (global axes), every body held:",
            system.bodies[b.body].body.name,
            body_kind(system, b.body)
        ));
        for r in 0..6 {
            let row: Vec<String> = (0..6)
                .map(|c| format!("{:>13.5e}", b.matrix[(r, c)]))
                .collect();
            line(format!("    [{} ]", row.join(" ")));
        }
    }
    line(String::new());
    if report.is_empty() {
        line("resonance: no periodic excitation in the scenario (prescribed sinusoids and orbits are checked)".into());
    } else {
        line(format!("resonance (margin {:.3} %):", margin * 100.0));
        for r in report {
            let verdict = if r.warning() {
                "WARNING: within the margin".to_string()
            } else if !r.covered {
                "not covered: above the computed modes, ask for more with --count".to_string()
            } else {
                "clear".to_string()
            };
            line(format!(
                "  {} at {:.4} Hz: nearest mode {} at {:.4} Hz ({:+.1} %, {}) — {}",
                r.excitation.source,
                r.excitation.frequency,
                r.nearest_mode + 1,
                r.natural_frequency,
                100.0 * r.relative_distance,
                modes.modes[r.nearest_mode].label.text,
                verdict
            ));
        }
    }
    s.trim_end().to_string()
}

#[allow(clippy::too_many_arguments)]
fn to_json(
    system: &System,
    sol: &StaticSolution,
    lin: &Linearisation,
    modes: &Modes,
    (stiffness, bodies): (&ConnectionStiffness, &[BodyStiffness]),
    report: &[ResonanceCheck],
    margin: Real,
    timing: &Timing,
) -> Value {
    let owner_name = |o: &ModeOwner| match *o {
        ModeOwner::Line(l) => system.lines[l].name.clone(),
        ModeOwner::Point(p) => system.points[p].name.clone(),
        ModeOwner::Body(b) => system.bodies[b].body.name.clone(),
    };
    let mode_list: Vec<Value> = modes
        .modes
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let lines: serde_json::Map<String, Value> = system
                .lines
                .iter()
                .zip(&m.line_shares)
                .map(|(l, s)| (l.name.clone(), json!(s)))
                .collect();
            let points: serde_json::Map<String, Value> = system
                .free_points
                .iter()
                .map(|&p| (system.points[p].name.clone(), json!(m.point_shares[p])))
                .collect();
            let body_shares: serde_json::Map<String, Value> = system
                .free_bodies
                .iter()
                .map(|&b| (system.bodies[b].body.name.clone(), json!(m.body_shares[b])))
                .collect();
            let directions: serde_json::Map<String, Value> = m
                .direction_shares
                .iter()
                .map(|(d, s)| (d.name().to_string(), json!(s)))
                .collect();
            json!({
                "mode": i + 1,
                "frequency_hz": m.frequency,
                "period_s": m.period,
                "eigenvalue_rad2_per_s2": m.eigenvalue,
                "label": m.label.text,
                "direction": m.label.direction.name(),
                "owners": m.label.owners.iter().map(owner_name).collect::<Vec<_>>(),
                "kinetic_energy_share": {"lines": lines, "points": points, "bodies": body_shares, "directions": directions},
            })
        })
        .collect();
    let stiff: serde_json::Map<String, Value> = stiffness
        .points
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let k = stiffness.block(i, i);
            let rows: Vec<Vec<Real>> = (0..3)
                .map(|r| (0..3).map(|c| k[(r, c)]).collect())
                .collect();
            (
                system.points[p].name.clone(),
                json!({"kind": point_kind(system, p), "matrix_n_per_m": rows}),
            )
        })
        .collect();
    let body_stiff: serde_json::Map<String, Value> = bodies
        .iter()
        .map(|b| {
            let rows: Vec<Vec<Real>> = (0..6)
                .map(|r| (0..6).map(|c| b.matrix[(r, c)]).collect())
                .collect();
            (
                system.bodies[b.body].body.name.clone(),
                json!({"kind": body_kind(system, b.body), "matrix_6x6": rows}),
            )
        })
        .collect();
    let checks: Vec<Value> = report
        .iter()
        .map(|r| {
            json!({
                "source": r.excitation.source,
                "frequency_hz": r.excitation.frequency,
                "nearest_mode": r.nearest_mode + 1,
                "natural_frequency_hz": r.natural_frequency,
                "relative_distance": r.relative_distance,
                "modes_within_margin": r.within_margin.iter().map(|i| i + 1).collect::<Vec<_>>(),
                "warning": r.warning(),
                "covered": r.covered,
            })
        })
        .collect();
    json!({
        "statics": {"method": sol.method, "iterations": sol.iterations, "residual_n": sol.residual},
        "degrees_of_freedom": lin.dofs.len(),
        "method": method_name(modes),
        "stiffness_asymmetry": modes.stiffness_asymmetry,
        "modes": mode_list,
        "stiffness": stiff,
        "body_stiffness": body_stiff,
        "resonance": {"margin": margin, "checks": checks},
        "timing_s": {
            "statics": timing.statics,
            "linearisation": timing.linearisation,
            "modes": timing.modes,
            "stiffness": timing.stiffness,
        },
    })
}

fn write_files(
    dir: &Path,
    system: &System,
    lin: &Linearisation,
    modes: &Modes,
    document: &Value,
) -> Result<()> {
    std::fs::create_dir_all(dir)?;
    let create = |name: &str| -> Result<std::io::BufWriter<std::fs::File>> {
        let path = dir.join(name);
        Ok(std::io::BufWriter::new(
            std::fs::File::create(&path).with_context(|| format!("creating {}", path.display()))?,
        ))
    };
    let mut summary = create("modes.csv")?;
    writeln!(summary, "mode,frequency [Hz],period [s],label")?;
    for (i, m) in modes.modes.iter().enumerate() {
        writeln!(
            summary,
            "{},{},{},\"{}\"",
            i + 1,
            m.frequency,
            m.period,
            m.label.text
        )?;
    }
    summary.flush()?;
    // Static positions of every node.
    let mut ws = system.workspace();
    system.point_kinematics(0.0, &lin.state, &mut ws);
    system.gather_lines(&lin.state, &mut ws);
    let scale: Vec<Real> = modes
        .modes
        .iter()
        .map(|m| 1.0 / m.largest_displacement(&lin.dofs).max(Real::MIN_POSITIVE))
        .collect();
    for (li, l) in system.lines.iter().enumerate() {
        let mut w = create(&format!("shapes_{}.csv", l.name))?;
        writeln!(
            w,
            "mode,node,arc_length [m],x [m],y [m],z [m],ux [-],uy [-],uz [-]"
        )?;
        for (k, m) in modes.modes.iter().enumerate() {
            for node in 0..l.nodes() {
                let r = ws.lines[li].position[l.node_vector(node)];
                let u = m.node_displacement(&lin.dofs, li, node) * scale[k];
                let at = format!("{},{node},{}", k + 1, l.mesh.arc_length(node));
                shape_row(&mut w, &at, &r, &u)?;
            }
        }
        w.flush()?;
    }
    if !system.free_points.is_empty() {
        let mut w = create("shapes_points.csv")?;
        writeln!(w, "mode,point,x [m],y [m],z [m],ux [-],uy [-],uz [-]")?;
        for (k, m) in modes.modes.iter().enumerate() {
            for &p in &system.free_points {
                let r = ws.points[p].position;
                let u = m.point_displacement(&lin.dofs, p) * scale[k];
                let at = format!("{},{}", k + 1, system.points[p].name);
                shape_row(&mut w, &at, &r, &u)?;
            }
        }
        w.flush()?;
    }
    if !system.free_bodies.is_empty() {
        let mut w = create("shapes_bodies.csv")?;
        writeln!(
            w,
            "mode,body,x [m],y [m],z [m],ux [-],uy [-],uz [-],rx [rad/m],ry [rad/m],rz [rad/m]"
        )?;
        for (k, m) in modes.modes.iter().enumerate() {
            for &b in &system.free_bodies {
                let r = ws.bodies[b].position;
                let (u, th) = m.body_motion(&lin.dofs, b).unwrap_or_default();
                let (u, th) = (u * scale[k], th * scale[k]);
                writeln!(
                    w,
                    "{},{},{},{},{},{},{},{},{},{},{}",
                    k + 1,
                    system.bodies[b].body.name,
                    r.x,
                    r.y,
                    r.z,
                    u.x,
                    u.y,
                    u.z,
                    th.x,
                    th.y,
                    th.z
                )?;
            }
        }
        w.flush()?;
    }
    std::fs::write(
        dir.join("modes.json"),
        serde_json::to_string_pretty(document)? + "\n",
    )?;
    Ok(())
}

/// One CSV row of a shape file: the leading columns, the static position and the displacement.
fn shape_row(w: &mut impl Write, at: &str, r: &Vec3, u: &Vec3) -> std::io::Result<()> {
    writeln!(w, "{at},{},{},{},{},{},{}", r.x, r.y, r.z, u.x, u.y, u.z)
}
