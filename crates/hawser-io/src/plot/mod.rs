//! `hawser plot DIR`: PNG and SVG figures of a finished or running run, drawn with plotters
//! (text in the bundled DejaVu Sans through ab_glyph, so no system font library is needed),
//! and `report.html`, a page without scripts that shows them with the summary tables.
//! docs/outputs.md says what each figure shows.
//!
//! Figures, in `DIR/plots/`: `end_tensions`, `range_LINE` and `shapes_LINE` per line,
//! `motions_BODY` per body, `spectrum_CHANNEL` per channel asked for.

pub mod data;
mod figures;
mod report;

use crate::results::safe_file_name;
use data::{RunData, bodies, read_run};
use hawser::analysis::statistics::ChannelStatistics;
use hawser::math::Real;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// The bundled font: DejaVu Sans 2.37 (licence in `crates/hawser-io/fonts/LICENSE`).
static DEJAVU_SANS: &[u8] = include_bytes!("../../fonts/DejaVuSans.ttf");

/// Registers the bundled font as plotters' `sans-serif` (once; every style falls back to it).
/// Every drawing with text calls it first: with ab_glyph, plotters draws only registered
/// fonts.
pub fn register_fonts() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        if plotters::style::register_font("sans-serif", FontStyle::Normal, DEJAVU_SANS).is_err() {
            unreachable!("the bundled font parses");
        }
    });
}

/// What to draw besides the standard figures.
#[derive(Clone, Debug, Default)]
pub struct PlotOptions {
    /// Channels whose amplitude spectrum to draw (names as in `timeseries.csv`).
    pub spectra: Vec<String>,
    /// Upper frequency of the spectra [Hz]; `None`: 1.5 times the frequency below which
    /// 99.5 % of the variance lies, at most the Nyquist frequency.
    pub max_frequency: Option<Real>,
}

/// A figure written: file stem (in `plots/`), title and what it shows.
#[derive(Clone, Debug)]
pub struct Figure {
    /// File name without extension, in `plots/` (`.png` and `.svg`).
    pub stem: String,
    /// Title.
    pub title: String,
    /// Caption.
    pub caption: String,
}

/// What `hawser plot` wrote.
#[derive(Clone, Debug)]
pub struct Written {
    /// The figures.
    pub figures: Vec<Figure>,
    /// `report.html`.
    pub report: PathBuf,
    /// Figures left out and why.
    pub notes: Vec<String>,
}

/// Draws into `DIR/STEM.png` and `DIR/STEM.svg`: evaluates `$body` (generic over the
/// backend, which a closure cannot be) with `$area` the root of each, and gives the SVG
/// pass's result.
macro_rules! both {
    ($dir:expr, $stem:expr, $size:expr, |$area:ident| $body:expr) => {{
        let png = $dir.join(format!("{}.png", $stem));
        {
            let $area = BitMapBackend::new(&png, $size).into_drawing_area();
            $body?;
            $area
                .present()
                .map_err(|e| format!("{}: {e}", png.display()))?;
        }
        let svg = $dir.join(format!("{}.svg", $stem));
        let $area = SVGBackend::new(&svg, $size).into_drawing_area();
        let out = $body?;
        $area
            .present()
            .map_err(|e| format!("{}: {e}", svg.display()))?;
        out
    }};
}

/// The upper frequency of a spectrum [Hz]: 1.5 times the lowest frequency below which
/// 99.5 % of Σ A² lies, at most the last frequency.
fn spectrum_limit(spectrum: &[(Real, Real)]) -> Real {
    let total: Real = spectrum.iter().map(|p| p.1 * p.1).sum();
    let mut sum = 0.0;
    for &(f, a) in spectrum {
        sum += a * a;
        if sum >= 0.995 * total {
            return (1.5 * f).min(spectrum.last().map_or(f, |p| p.0));
        }
    }
    spectrum.last().map_or(1.0, |p| p.0)
}

/// The samples of channel `c` in the statistics window and their interval [s]; an error when
/// they are not equally spaced.
fn window_samples(run: &RunData, c: usize) -> Result<(Vec<Real>, Real), String> {
    let ts = &run.timeseries;
    let first = ts.time.partition_point(|&t| t < run.statistics.start);
    let time = &ts.time[first..];
    if time.len() < 4 {
        return Err("fewer than 4 samples in the statistics window".into());
    }
    let dt = (time[time.len() - 1] - time[0]) / (time.len() - 1) as Real;
    if let Some(w) = time
        .windows(2)
        .find(|w| ((w[1] - w[0]) - dt).abs() > 1e-6 * dt)
    {
        return Err(format!(
            "the samples are not equally spaced (t = {} s follows t = {} s; the mean interval is {dt} s)",
            w[1], w[0]
        ));
    }
    Ok((ts.values[c][first..].to_vec(), dt))
}

/// Writes the figures of the run in `dir` into `dir/plots/` and `dir/report.html`.
pub fn plot_run(dir: &Path, options: &PlotOptions) -> Result<Written, String> {
    register_fonts();
    let run = read_run(dir)?;
    let out = dir.join("plots");
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let mut figures = Vec::new();
    let mut notes = Vec::new();
    let ts = &run.timeseries;
    if ts.time.is_empty() {
        return Err(format!("{}: timeseries.csv has no rows yet", dir.display()));
    }
    let size = figures::SIZE;

    if !run.lines.is_empty() {
        both!(out, "end_tensions", size, |area| figures::end_tensions(
            &area, &run
        ));
        figures.push(Figure {
            stem: "end_tensions".into(),
            title: "End tensions".into(),
            caption: "The tension at end A (thin) and end B (thick) of every line against time: \
                      the magnitude of the force each end exerts on its attachment."
                .into(),
        });
    }
    for (k, line) in run.lines.iter().enumerate() {
        let stem = format!("range_{}", safe_file_name(line));
        match &run.ranges[k] {
            Some(range) => {
                let note = both!(out, stem, size, |area| figures::range_graph(
                    &area, line, range
                ));
                let mut caption = format!(
                    "Minimum, mean and maximum effective tension at every node of {line} over {} \
                     {} from t = {} s, with the band between minimum and maximum",
                    range.samples,
                    if range.from_snapshots {
                        "snapshots (the run has not finished; line_ranges.json is written at its end)"
                    } else {
                        "samples"
                    },
                    figures::trim_number(run.statistics.start),
                );
                if range
                    .sections
                    .iter()
                    .any(|s| s.minimum_breaking_load.is_some())
                {
                    caption += ", and the permissible tension MBL/SF (orange) and MBL (dark red) of each section";
                }
                caption += ".";
                if let Some(n) = note {
                    caption += &format!(" Off the scale: {n}.");
                }
                figures.push(Figure {
                    stem,
                    title: format!("Range graph of {line}"),
                    caption,
                });
            }
            None => notes.push(format!(
                "no range graph of {line}: the run has no line_ranges.json yet and no snapshots"
            )),
        }
    }
    for (k, line) in run.lines.iter().enumerate() {
        let snaps = &run.snapshots[k];
        if snaps.is_empty() {
            notes.push(format!(
                "no shapes of {line}: the run has no snapshots (set simulation.snapshot_interval)"
            ));
            continue;
        }
        let stem = format!("shapes_{}", safe_file_name(line));
        let tall = (size.0, size.1 * 3 / 2);
        let times = both!(out, stem, tall, |area| figures::shapes(&area, line, snaps));
        figures.push(Figure {
            stem,
            title: format!("Shapes of {line}"),
            caption: format!(
                "{line} at {} of its {} snapshots (t = {} s), blue to red in time: side view in \
                 the vertical plane through its ends at the first time drawn, and plan view \
                 with a dot at end B.",
                times.len(),
                snaps.len(),
                times
                    .iter()
                    .map(|t| figures::trim_number(*t))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        });
    }
    for (body, columns) in bodies(ts) {
        let stem = format!("motions_{}", safe_file_name(&body));
        let tall = (size.0, size.1 * 3 / 2);
        both!(out, stem, tall, |area| figures::body_motions(
            &area, &run, &body, columns
        ));
        figures.push(Figure {
            stem,
            title: format!("Motions of {body}"),
            caption: format!(
                "{body}: position of its origin (x, y, z) and its roll, pitch and yaw \
                 (R = R_z(yaw) R_y(pitch) R_x(roll)) against time."
            ),
        });
    }
    for name in &options.spectra {
        let Some(c) = ts.index(name) else {
            let mut known: Vec<&str> = ts.channels.iter().map(|c| c.name.as_str()).collect();
            known.truncate(12);
            return Err(format!(
                "--spectrum {name}: no such channel in timeseries.csv (channels: {}{})",
                known.join(", "),
                if ts.channels.len() > 12 { ", …" } else { "" }
            ));
        };
        let (x, dt) = window_samples(&run, c).map_err(|e| format!("--spectrum {name}: {e}"))?;
        let nyquist = 0.5 / dt;
        let full = hawser::validation::signal::amplitude_spectrum(&x, dt, nyquist);
        let f_max = options
            .max_frequency
            .unwrap_or_else(|| spectrum_limit(&full))
            .min(nyquist);
        let spectrum: Vec<(Real, Real)> = full.into_iter().filter(|p| p.0 <= f_max).collect();
        let peak = spectrum
            .iter()
            .copied()
            .fold((0.0, 0.0), |a, p| if p.1 > a.1 { p } else { a });
        let unit = ts.channels[c].unit.clone();
        let title = format!("Amplitude spectrum of {name}");
        let stem = format!("spectrum_{}", safe_file_name(name));
        both!(out, stem, size, |area| figures::spectrum(
            &area, &title, &unit, &spectrum
        ));
        figures.push(Figure {
            stem,
            title,
            caption: format!(
                "Single-sided amplitude spectrum of {name} from t = {} s ({} samples every {} s, \
                 mean removed, no window; resolution {:.4} Hz), up to {:.4} Hz. Largest \
                 component: {:.4e} {unit} at {:.4} Hz (period {:.3} s).",
                figures::trim_number(run.statistics.start),
                x.len(),
                figures::trim_number(dt),
                1.0 / (x.len() as Real * dt),
                f_max,
                peak.1,
                peak.0,
                if peak.0 > 0.0 {
                    1.0 / peak.0
                } else {
                    Real::INFINITY
                }
            ),
        });
    }
    let stats: Vec<ChannelStatistics> = {
        let columns: Vec<&[Real]> = ts.values.iter().map(|v| v.as_slice()).collect();
        hawser::analysis::statistics::statistics_of(&ts.time, &columns, run.statistics.clone())
    };
    let html = report::html(dir, &run, &stats, &figures, &notes);
    let report = dir.join("report.html");
    crate::results::write_atomically(&report, html.as_bytes())
        .map_err(|e| format!("{}: {e}", report.display()))?;
    Ok(Written {
        figures,
        report,
        notes,
    })
}
