//! `hawser bench --coupling SECONDS`: the cost of coupling. The scenario's prescribed points
//! are run twice over the same duration, with the same step: as prescribed, and as coupled
//! points a host drives at the given coupling interval with the same motion's positions and
//! velocities (what OpenFAST does through MoorDyn's API). Reported as node-steps per CPU
//! second of each and the paired CPU-time ratio (median over `--repeat`).

use super::cases as bench_cases;
use super::*;
use hawser::model::{Motion, couple_prescribed_points};

/// CPU seconds of one run of `session` to `end` [s]; with `motions`, coupled at `interval`.
fn timed(
    mut session: Session,
    end: Real,
    interval: Real,
    motions: &[(usize, Motion)],
) -> Result<(f64, u64)> {
    let cpu0 = bench_cases::thread_cpu_seconds();
    let start = Instant::now();
    if motions.is_empty() {
        session.advance_to(end)?;
    } else {
        let mut forces = vec![0.0; session.coupled_dofs()];
        let mut k = 0u64;
        loop {
            k += 1;
            let t1 = (k as Real * interval).min(end);
            for (p, m) in motions {
                let (x, v, _) = m.kinematics(t1);
                session.set_point_kinematics(*p, t1, x, v, None)?;
            }
            session.advance_to(t1)?;
            session.coupled_forces(&mut forces)?;
            if t1 >= end {
                break;
            }
        }
    }
    let wall = start.elapsed().as_secs_f64();
    let cpu = match (cpu0, bench_cases::thread_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => wall,
    };
    Ok((cpu, session.steps_done()))
}

/// `hawser bench FILE --coupling SECONDS`.
pub fn run(args: &BenchArgs, interval: Real) -> Result<ExitCode> {
    if !(interval.is_finite() && interval > 0.0) {
        err!("error: --coupling {interval}: expected a coupling interval > 0 s");
        return Ok(ExitCode::from(2));
    }
    let deck = DeckArgs {
        deck_duration: args.duration,
        vessel_motion: args.vessel_motion.clone(),
    };
    let Some(loaded) = load_with(&args.file, &deck, true) else {
        return Ok(ExitCode::from(2));
    };
    let mut model = loaded.model.clone();
    if let Some(dt) = args.dt {
        model.settings.time_step = TimeStep::Fixed(dt);
    }
    if let Some(d) = args.duration {
        model.settings.duration = d;
    }
    let (coupled_model, motions) = couple_prescribed_points(&model);
    if motions.is_empty() {
        err!(
            "error: {}: --coupling needs prescribed points to couple; this scenario has none",
            args.file.display()
        );
        return Ok(ExitCode::from(2));
    }
    let end = model.settings.duration;
    // Both runs start from the same state: the prescribed model's initial condition.
    let start = Session::new(model.clone())?;
    let y0 = start.state().to_vec();
    let nodes: usize = model.lines.iter().map(|l| l.elements() + 1).sum();
    let mut ratios = Vec::new();
    let (mut best_p, mut best_c) = (f64::INFINITY, f64::INFINITY);
    let mut steps = (0, 0);
    for _ in 0..args.repeat.max(1) {
        let p = Session::from_state(model.clone(), y0.clone(), SessionOptions::default())?;
        let (cp, sp) = timed(p, end, interval, &[])?;
        let c = Session::from_state(coupled_model.clone(), y0.clone(), SessionOptions::default())?;
        let (cc, sc) = timed(c, end, interval, &motions)?;
        ratios.push(cc / cp);
        best_p = best_p.min(cp);
        best_c = best_c.min(cc);
        steps = (sp, sc);
    }
    let ratio = bench_cases::median(&mut ratios);
    let rate = |cpu: f64, s: u64| nodes as f64 * s as f64 / cpu;
    let result = serde_json::json!({
        "file": args.file.display().to_string(),
        "nodes": nodes,
        "duration": end,
        "coupling_interval": interval,
        "coupled_points": motions.len(),
        "prescribed": {"steps": steps.0, "cpu_seconds": best_p, "node_steps_per_second": rate(best_p, steps.0)},
        "coupled": {"steps": steps.1, "cpu_seconds": best_c, "node_steps_per_second": rate(best_c, steps.1)},
        "cpu_ratio_coupled_over_prescribed": ratio,
        "cost_per_coupling_step_us": (best_c - best_p) / (end / interval) * 1e6,
    });
    if args.json {
        out!("{}", serde_json::to_string_pretty(&result)?);
    } else {
        out!(
            "{}: {} coupled points, {} nodes, {end} s, coupling every {interval} s",
            args.file.display(),
            motions.len(),
            nodes
        );
        out!(
            "  prescribed: {} steps, {:.3} CPU s, {:.3e} node-steps/s",
            steps.0,
            best_p,
            rate(best_p, steps.0)
        );
        out!(
            "  coupled:    {} steps, {:.3} CPU s, {:.3e} node-steps/s",
            steps.1,
            best_c,
            rate(best_c, steps.1)
        );
        out!(
            "  coupled / prescribed CPU time (median of {} pairs): {ratio:.3}",
            ratios.len()
        );
    }
    Ok(ExitCode::SUCCESS)
}
