//! The `dg` verification and validation report, docs/verification/dg.md, with its plots.
//!
//! ```sh
//! cargo run --release -p hawser-io --example dg_report -- koh     # Koh's swinging cable, ~15 min
//! cargo run --release -p hawser-io --example dg_report -- ropos   # the 48 ROPOS cases, ~1.5 h
//! cargo run --release -p hawser-io --example dg_report            # the report, ~1 min
//! ```
//!
//! `koh` and `ropos` run the validation cases from the scenario files under `examples/` and
//! store their results in `docs/verification/data/` (committed); the report runs the
//! verification cases (DG paper §4 ring beam and cantilever from `crates/hawser/tests/dg_common`,
//! the `hawser validate --formulation dg` suite), reads the stored results, checks the paper's
//! claims on them and writes the markdown and SVG plots. `ropos L...` runs only those lengths
//! and merges them into the stored table.

#[path = "../../hawser/tests/dg_common/mod.rs"]
mod dg_common;

use hawser::math::Real;
use hawser::model::{Formulation, Model};
use hawser::validation::signal::{amplitude_spectrum, peak};
use hawser::validation::swinging_cable::{ReleaseRun, run_release, with_discretisation};
use hawser::validation::tether::{
    self, ALPHAS, FREQUENCIES, LENGTHS, RAMP_PERIODS, TetherSummary, run_tether, summarise,
};
use hawser::verification::{Plot, Series};
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn load(example: &str) -> Model {
    let path = root().join("examples").join(example);
    match hawser_io::scenario::load(&path) {
        Ok(s) => s.model,
        Err(e) => panic!("{e}"),
    }
}

fn data_dir() -> PathBuf {
    let d = root().join("docs/verification/data");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("koh") => koh(),
        Some("ropos") => {
            let only: Vec<Real> = args[1..].iter().map(|a| a.parse().unwrap()).collect();
            ropos(&only)
        }
        Some("report") | None => report(),
        Some(other) => {
            eprintln!("unknown mode `{other}`: expected koh, ropos [L...] or report");
            std::process::exit(2);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Koh's swinging cable (DG paper §5)

/// The three variants of the paper's Fig. 3: scenario file and label.
const KOH_VARIANTS: [(&str, &str); 3] = [
    ("koh_swinging_cable_ei0.toml", "EI = 0"),
    ("koh_swinging_cable_undamped.toml", "EI = 0.060, ζb = 0"),
    ("koh_swinging_cable.toml", "EI = 0.060, ζb = 0.020"),
];

/// Decimation of the stored tension series [samples of 1 ms].
const KOH_KEEP: usize = 2;

#[derive(Serialize, Deserialize, Clone)]
struct KohRecord {
    variant: String,
    formulation: String,
    elements: usize,
    order: usize,
    step: Real,
    steps: u64,
    wall_seconds: Real,
    static_tension: Real,
    /// Largest pin tension in the first swing, t ≤ 1.25 s: (time, value).
    peak_first_swing: (Real, Real),
    /// Largest pin tension in 1.6 ≤ t ≤ 2.4 s (the paper's "t = 2 s" event).
    peak_near_2s: (Real, Real),
    /// Largest speed of the free end [m/s].
    tail_speed_max: Real,
    /// Every KOH_KEEP-th sample.
    time: Vec<Real>,
    pin_tension: Vec<Real>,
    /// The free end's path every 10 ms: (x, z).
    tail: Vec<(Real, Real)>,
    /// Amplitude spectrum of the whole record, 0..30 Hz: (f, A).
    spectrum: Vec<(Real, Real)>,
    /// Shapes (x, z of the nodes) every 0.05 s, for the main runs.
    shapes: Vec<(Real, Vec<(Real, Real)>)>,
}

fn koh_record(variant: &str, model: &Model, run: &ReleaseRun, shapes: bool) -> KohRecord {
    let l = &model.lines[0];
    let dt = model.settings.output_interval;
    let spectrum = amplitude_spectrum(&run.pin_tension, dt, 30.0);
    KohRecord {
        variant: variant.into(),
        formulation: format!("{:?}", l.formulation).to_lowercase(),
        elements: l.elements(),
        order: l.sections[0].order,
        step: run.step,
        steps: run.steps,
        wall_seconds: run.wall_seconds,
        static_tension: run.pin_tension[0],
        peak_first_swing: peak(&run.time, &run.pin_tension, 0.0, 1.25).unwrap(),
        peak_near_2s: peak(&run.time, &run.pin_tension, 1.6, 2.4).unwrap(),
        tail_speed_max: run
            .tail_velocity
            .iter()
            .map(|v| v.norm())
            .fold(0.0, Real::max),
        time: run.time.iter().step_by(KOH_KEEP).copied().collect(),
        pin_tension: run.pin_tension.iter().step_by(KOH_KEEP).copied().collect(),
        tail: run.tail.iter().step_by(10).map(|r| (r.x, r.z)).collect(),
        spectrum,
        shapes: if shapes {
            run.shapes
                .iter()
                .map(|(t, s)| (*t, s.iter().map(|r| (r.x, r.z)).collect()))
                .collect()
        } else {
            Vec::new()
        },
    }
}

fn koh() {
    let mut records = Vec::new();
    for (file, label) in KOH_VARIANTS {
        let base = load(file);
        let bending = base.line_types[0].bending_stiffness > 0.0;
        let damped = base.line_types[0].bending_damping > 0.0;
        // (formulation, elements, order, keep shapes): the paper's mesh, the paper's coarser
        // mesh of its convergence check, and the cross-checks.
        let mut runs = vec![
            (Formulation::Dg, 10, 4, true),
            (Formulation::Dg, 7, 4, false),
            (Formulation::Hermite, if damped { 12 } else { 20 }, 4, false),
        ];
        if !bending {
            runs.push((Formulation::Fe, 100, 4, false));
        }
        for (formulation, elements, order, shapes) in runs {
            let model = with_discretisation(&base, formulation, elements, order);
            let run = run_release(&model, shapes.then_some(0.05)).unwrap_or_else(|e| {
                panic!("{file} {formulation:?} N = {elements}: {e}");
            });
            let r = koh_record(label, &model, &run, shapes);
            eprintln!(
                "{label:24} {:8} N {:3} P {}: dt {:.2e} s, {} steps, {:.1} s wall; static {:.3} N, \
                 first swing {:.2} N at {:.3} s, near 2 s {:.2} N at {:.3} s, tail speed {:.2} m/s",
                r.formulation,
                r.elements,
                r.order,
                r.step,
                r.steps,
                r.wall_seconds,
                r.static_tension,
                r.peak_first_swing.1,
                r.peak_first_swing.0,
                r.peak_near_2s.1,
                r.peak_near_2s.0,
                r.tail_speed_max
            );
            records.push(r);
        }
    }
    let path = data_dir().join("koh.json");
    std::fs::write(&path, serde_json::to_string(&records).unwrap()).unwrap();
    eprintln!("wrote {}", path.display());
}

// ---------------------------------------------------------------------------------------------
// The ROPOS tether (DG paper §6)

/// Periods of steady orbit after the build-up.
const ROPOS_PERIODS: Real = 8.0;

#[derive(Serialize, Deserialize, Clone)]
struct RoposRecord {
    length: Real,
    alpha: Real,
    frequency: Real,
    wave_speed: Real,
    step: Real,
    steps: u64,
    wall_seconds: Real,
    output_interval: Real,
    static_ship: Real,
    static_cage: Real,
    ship_min: Real,
    ship_max: Real,
    slack: bool,
    first_slack: Option<Real>,
    /// (time, before, peak, peak time) of the first snap at the cage and at the ship.
    cage_snap: Option<(Real, Real, Real, Real)>,
    ship_snap: Option<(Real, Real, Real, Real)>,
    /// Ship tension over the last two periods, 200 samples per period: (t, T).
    ship_last_periods: Vec<(Real, Real)>,
    /// Cage and ship tension from 0.25 τ before to 2.5 τ after the first cage snap (τ = L/c),
    /// at most 400 samples: (t, T_ship, T_cage).
    first_snap: Vec<(Real, Real, Real)>,
}

fn snap_tuple(s: Option<tether::Snap>) -> Option<(Real, Real, Real, Real)> {
    s.map(|s| (s.time, s.before, s.peak, s.peak_time))
}

fn ropos(only: &[Real]) {
    let base = load("ropos_tether.toml");
    let path = data_dir().join("ropos.json");
    let mut records: Vec<RoposRecord> = std::fs::read_to_string(&path)
        .ok()
        .and_then(|s| serde_json::from_str(&s).ok())
        .unwrap_or_default();
    for &length in &LENGTHS {
        if !only.is_empty() && !only.contains(&length) {
            continue;
        }
        for &alpha in &ALPHAS {
            for &frequency in &FREQUENCIES {
                let model = tether::case(&base, length, alpha, frequency, ROPOS_PERIODS);
                let c = tether::wave_speed(&model);
                let run = run_tether(&model).unwrap_or_else(|e| {
                    panic!("L {length} α {alpha} f {frequency}: {e}");
                });
                let s: TetherSummary = summarise(&run, length, c, RAMP_PERIODS / frequency);
                let t = &run.time;
                let period = 1.0 / frequency;
                let t_end = t[t.len() - 1];
                let every = ((period / 200.0) / model.settings.output_interval).round() as usize;
                let ship_last_periods = (0..t.len())
                    .filter(|&i| t[i] >= t_end - 2.0 * period)
                    .step_by(every.max(1))
                    .map(|i| (t[i], run.ship_tension[i]))
                    .collect();
                let tau = length / c;
                let first_snap = match s.cage_snap {
                    Some(cs) => {
                        let idx: Vec<usize> = (0..t.len())
                            .filter(|&i| {
                                t[i] >= cs.time - 0.25 * tau && t[i] <= cs.time + 2.5 * tau
                            })
                            .collect();
                        let every = idx.len().div_ceil(400).max(1);
                        idx.iter()
                            .step_by(every)
                            .map(|&i| (t[i], run.ship_tension[i], run.cage_tension[i]))
                            .collect()
                    }
                    None => Vec::new(),
                };
                let r = RoposRecord {
                    length,
                    alpha,
                    frequency,
                    wave_speed: c,
                    step: run.step,
                    steps: run.steps,
                    wall_seconds: run.wall_seconds,
                    output_interval: model.settings.output_interval,
                    static_ship: s.static_ship,
                    static_cage: s.static_cage,
                    ship_min: s.ship_min,
                    ship_max: s.ship_max,
                    slack: s.slack,
                    first_slack: s.first_slack,
                    cage_snap: snap_tuple(s.cage_snap),
                    ship_snap: snap_tuple(s.ship_snap),
                    ship_last_periods,
                    first_snap,
                };
                eprintln!(
                    "L {length:6} α {alpha:5} f {frequency:4}: dt {:.2e} s, {:.1} s wall; ship \
                     {:.1}..{:.1} kN, slack {}, cage snap {:?}, travel {:?} (L/c {:.4} s)",
                    r.step,
                    r.wall_seconds,
                    r.ship_min / 1e3,
                    r.ship_max / 1e3,
                    r.slack,
                    r.cage_snap,
                    s.travel_time(),
                    tau
                );
                records.retain(|x| {
                    !(x.length == length && x.alpha == alpha && x.frequency == frequency)
                });
                records.push(r);
                records.sort_by(|a, b| {
                    (a.length, a.alpha, a.frequency)
                        .partial_cmp(&(b.length, b.alpha, b.frequency))
                        .unwrap()
                });
                std::fs::write(&path, serde_json::to_string(&records).unwrap()).unwrap();
            }
        }
    }
    eprintln!("wrote {}", path.display());
}

// ---------------------------------------------------------------------------------------------
// The report

fn report() {
    let _ = (write_plot, md_push, Series::clone);
    eprintln!("report: not yet");
}

#[allow(dead_code)]
fn write_plot(img: &Path, name: &str, plot: &Plot) -> String {
    let svg = hawser_io::verification_report::plot_svg(plot, &plot.title).unwrap();
    std::fs::write(img.join(format!("{name}.svg")), svg).unwrap();
    format!("![{}](img/{name}.svg)\n", plot.title)
}

#[allow(dead_code)]
fn md_push(md: &mut String, s: &str) {
    let _ = writeln!(md, "{s}");
}
