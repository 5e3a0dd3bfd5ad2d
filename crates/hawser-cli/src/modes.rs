//! `hawser modes`: natural frequencies and mode shapes about the static state, the stiffness
//! the lines offer their fixed and prescribed points and every body, and the resonance report.
//!
//! Files written into `--out DIR`: `modes.csv` (mode, frequency, period, label),
//! `shapes_<line>.csv` per line (every mode's nodal displacements, scaled so that the largest
//! displacement of the mode over the whole system is 1), `shapes_points.csv` for free points,
//! `shapes_bodies.csv` for free bodies (origin displacement and rotation), and `modes.json`
//! (what `--json` prints). A model with `dg` lines is analysed through its hermite twin
//! ([`hawser_io::modes::modal_model`]), which the command says.

use anyhow::{Context, Result};
use hawser::analysis::resonance::ResonanceCheck;
use hawser::math::{Real, Vec3};
use hawser::system::System;
use hawser_io::modes::{ModalAnalysis, body_kind, point_kind};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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

/// Runs `hawser modes`.
pub fn run(args: &ModesArgs) -> Result<ExitCode> {
    if !(args.margin >= 0.0 && args.margin < 100.0) || args.count == 0 {
        err!(
            "error: --margin must be in [0, 100) % and --count at least 1 (got {} %, {})",
            args.margin,
            args.count
        );
        return Ok(ExitCode::from(2));
    }
    let Some(loaded) = super::load(&args.file) else {
        return Ok(ExitCode::from(2));
    };
    let (model, notes) = hawser_io::modes::modal_model(&loaded.model);
    for n in &notes {
        err!("note: {n}");
    }
    let system = super::system_of(&model)?;
    let analysis = match ModalAnalysis::compute(&system, args.count, args.margin / 100.0) {
        Ok(a) => a,
        Err(e) => {
            err!("error: {e}");
            return Ok(ExitCode::from(1));
        }
    };
    let document = analysis.to_json(&system);
    if let Some(dir) = &args.out {
        write_files(dir, &system, &analysis, &document)
            .with_context(|| format!("writing mode shapes into {}", dir.display()))?;
    }
    if args.json {
        print(&serde_json::to_string_pretty(&document)?);
    } else {
        print(&table(&system, &analysis));
    }
    let timing = &analysis.timing;
    err!(
        "timing: statics {:.3} s, linearisation {:.3} s, modes {:.3} s ({}), stiffness {:.3} s",
        timing.statics,
        timing.linearisation,
        timing.modes,
        analysis.method_name(),
        timing.stiffness
    );
    let modes = &analysis.modes;
    for r in analysis.resonance.iter().filter(|r| r.warning()) {
        err!(
            "warning: {} at {:.4} Hz is within {} % of mode {} ({:.4} Hz, {})",
            r.excitation.source,
            r.excitation.frequency,
            args.margin,
            r.nearest_mode + 1,
            r.natural_frequency,
            modes.modes[r.nearest_mode].label.text
        );
    }
    if let Some(c) = analysis.spectrum.as_ref().filter(|c| c.warning()) {
        err!(
            "warning: {} mode(s) inside the band holding {} % of the wave energy ({:.4}–{:.4} Hz): {}",
            c.inside.len(),
            100.0 * c.band.fraction,
            c.band.low,
            c.band.high,
            c.inside
                .iter()
                .map(|&i| format!("{} ({})", i + 1, modes.modes[i].label.text))
                .collect::<Vec<_>>()
                .join(", ")
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

fn table(system: &System, analysis: &ModalAnalysis) -> String {
    let (sol, modes, stiffness) = (&analysis.statics, &analysis.modes, &analysis.stiffness);
    let (report, margin): (&[ResonanceCheck], Real) = (&analysis.resonance, analysis.margin);
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
        analysis.method_name(),
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
    for b in &analysis.body_stiffness {
        line(format!(
            "  body {} ({}): 6×6 mooring stiffness about its origin [N/m, N/rad; N·m/m, N·m/rad] \
             over x, y, z, rotations about x, y, z (global axes), lines relaxed:",
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
        line("resonance: no periodic excitation in the scenario (prescribed sinusoids, orbits and waves are checked)".into());
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
    if let Some(c) = &analysis.spectrum {
        let verdict = if c.warning() {
            let list: Vec<String> = c.inside.iter().map(|i| (i + 1).to_string()).collect();
            format!("WARNING: modes {} inside", list.join(", "))
        } else if !c.covered {
            "not covered: the band reaches above the computed modes, ask for more with --count"
                .to_string()
        } else {
            "clear: no computed mode inside".to_string()
        };
        line(format!(
            "  sea band holding {} % of the wave energy: {:.4}–{:.4} Hz — {}",
            100.0 * c.band.fraction,
            c.band.low,
            c.band.high,
            verdict
        ));
    }
    s.trim_end().to_string()
}

fn write_files(
    dir: &Path,
    system: &System,
    analysis: &ModalAnalysis,
    document: &serde_json::Value,
) -> Result<()> {
    std::fs::create_dir_all(dir)?;
    let create = |name: &str| -> Result<std::io::BufWriter<std::fs::File>> {
        let path = dir.join(name);
        Ok(std::io::BufWriter::new(
            std::fs::File::create(&path).with_context(|| format!("creating {}", path.display()))?,
        ))
    };
    let modes = &analysis.modes.modes;
    let mut summary = create("modes.csv")?;
    writeln!(summary, "mode,frequency [Hz],period [s],label")?;
    for (i, m) in modes.iter().enumerate() {
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
    let shapes = analysis.shapes(system);
    for (li, l) in system.lines.iter().enumerate() {
        let mut w = create(&format!("shapes_{}.csv", l.name))?;
        writeln!(
            w,
            "mode,node,arc_length [m],x [m],y [m],z [m],ux [-],uy [-],uz [-]"
        )?;
        for (k, u) in shapes.line_displacements.iter().enumerate() {
            let nodes = shapes.line_positions[li].iter().zip(&u[li]);
            for (node, (r, d)) in nodes.enumerate() {
                let at = format!("{},{node},{}", k + 1, l.mesh.arc_length(node));
                shape_row(&mut w, &at, r, d)?;
            }
        }
        w.flush()?;
    }
    if !shapes.points.is_empty() {
        let mut w = create("shapes_points.csv")?;
        writeln!(w, "mode,point,x [m],y [m],z [m],ux [-],uy [-],uz [-]")?;
        for (k, u) in shapes.point_displacements.iter().enumerate() {
            for (i, &p) in shapes.points.iter().enumerate() {
                let at = format!("{},{}", k + 1, system.points[p].name);
                shape_row(&mut w, &at, &shapes.point_positions[i], &u[i])?;
            }
        }
        w.flush()?;
    }
    if !shapes.bodies.is_empty() {
        let mut w = create("shapes_bodies.csv")?;
        writeln!(
            w,
            "mode,body,x [m],y [m],z [m],ux [-],uy [-],uz [-],rx [rad/m],ry [rad/m],rz [rad/m]"
        )?;
        for (k, u) in shapes.body_motions.iter().enumerate() {
            for (i, &b) in shapes.bodies.iter().enumerate() {
                let at = format!("{},{}", k + 1, system.bodies[b].body.name);
                let (d, th) = u[i];
                let r = shapes.body_positions[i];
                writeln!(
                    w,
                    "{at},{},{},{},{},{},{},{},{},{}",
                    r.x, r.y, r.z, d.x, d.y, d.z, th.x, th.y, th.z
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
