//! The verification report: the suite's rows ([`hawser::verification::Check`]) as a plain text
//! table for the terminal and a markdown table, and its plots as SVG files (plotters, SVG
//! backend; text is left to the viewer's fonts).
//!
//! Layout on disk: `report.md` and, beside it, `img/<case>_<formulation>_<plot>.svg`, linked
//! from the report by relative paths.

use hawser::math::Real;
use hawser::verification::{CASES, CaseResult, Check, Outcome, Plot, Tolerance, run_label};
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// Column titles of the table, in order.
pub const COLUMNS: [&str; 8] = [
    "case",
    "formulation",
    "quantity",
    "expected",
    "computed",
    "error",
    "tolerance",
    "result",
];

/// A number with 6 significant digits, in scientific notation when very large or small.
fn number(x: Real) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-3..1e6).contains(&a) {
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.5e}")
    }
}

/// A small number (errors, tolerances) with 3 significant digits.
fn small(x: Real) -> String {
    if !x.is_finite() {
        "—".into()
    } else if x == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&x.abs()) {
        format!("{}", (x * 1e3).round() / 1e3)
    } else {
        format!("{x:.2e}")
    }
}

fn with_unit(s: String, unit: &str) -> String {
    if unit == "-" || s == "—" {
        s
    } else {
        format!("{s} {unit}")
    }
}

/// The eight cells of a row: case, formulation, quantity, expected, computed, error,
/// tolerance, result.
pub fn cells(c: &Check) -> [String; 8] {
    let (error, tolerance) = match c.tolerance {
        Tolerance::Relative(t) => (
            format!("{} (rel)", small(c.error)),
            format!("≤ {} (rel)", small(t)),
        ),
        Tolerance::Absolute(t) => (
            with_unit(small(c.error), c.unit),
            with_unit(format!("≤ {}", small(t)), c.unit),
        ),
        Tolerance::AtMost(t) => (
            with_unit(small(c.error), c.unit),
            with_unit(format!("≤ {}", small(t)), c.unit),
        ),
        Tolerance::AtLeast(t) => (
            with_unit(small(c.error), c.unit),
            with_unit(format!("≥ {}", small(t)), c.unit),
        ),
    };
    let (error, tolerance) = if c.computed.is_finite() {
        (error, tolerance)
    } else {
        ("—".into(), "—".into())
    };
    let result = match &c.outcome {
        Outcome::Pass => "pass".to_string(),
        Outcome::Fail(None) => "FAIL".to_string(),
        Outcome::Fail(Some(why)) => format!("FAIL: {why}"),
        Outcome::NotAvailable(why) => format!("n/a: {why}"),
    };
    [
        c.case.to_string(),
        run_label(c.formulation, c.scheme),
        c.quantity.clone(),
        with_unit(number(c.expected), c.unit),
        with_unit(number(c.computed), c.unit),
        error,
        tolerance,
        result,
    ]
}

/// Counts of passed, failed and not available rows.
pub fn tally(results: &[CaseResult]) -> (usize, usize, usize) {
    let mut t = (0, 0, 0);
    for c in results.iter().flat_map(|r| &r.checks) {
        match c.outcome {
            Outcome::Pass => t.0 += 1,
            Outcome::Fail(_) => t.1 += 1,
            Outcome::NotAvailable(_) => t.2 += 1,
        }
    }
    t
}

/// The rows as an aligned plain text table (header and a rule first).
pub fn text_table(checks: &[&Check]) -> String {
    let rows: Vec<[String; 8]> = checks.iter().map(|c| cells(c)).collect();
    let mut width = COLUMNS.map(|c| c.chars().count());
    for r in &rows {
        for (w, cell) in width.iter_mut().zip(r.iter()).take(7) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: &[String]| {
        let mut s = String::new();
        for (k, cell) in cells.iter().enumerate() {
            if k < 7 {
                let pad = width[k] - cell.chars().count();
                // Numbers right-aligned, words left-aligned.
                if (3..7).contains(&k) {
                    let _ = write!(s, "{}{cell}  ", " ".repeat(pad));
                } else {
                    let _ = write!(s, "{cell}{}  ", " ".repeat(pad));
                }
            } else {
                s.push_str(cell);
            }
        }
        s.trim_end().to_string()
    };
    let header: Vec<String> = COLUMNS.iter().map(|s| s.to_string()).collect();
    let mut out = line(&header) + "\n";
    out += &"-".repeat(width.iter().sum::<usize>() + 2 * 7 + 6);
    out.push('\n');
    for r in &rows {
        out += &line(r);
        out.push('\n');
    }
    out
}

fn markdown_escape(s: &str) -> String {
    s.replace('|', "\\|")
}

/// File name of a plot's SVG.
pub fn plot_file(result: &CaseResult, plot: &Plot) -> String {
    format!(
        "{}_{}_{}.svg",
        result.case,
        run_label(result.formulation, result.scheme)
            .replace(" (", "-")
            .replace(')', ""),
        plot.name
    )
}

/// The markdown report: `preamble` (how it was produced), the tally, the table, then per case
/// its description and plots (linked as `img/<file>`).
pub fn markdown(results: &[CaseResult], preamble: &str) -> String {
    let mut md = String::from("# Verification report\n\n");
    md += preamble.trim_end();
    md += "\n\n";
    let (pass, fail, na) = tally(results);
    let _ = writeln!(
        md,
        "**{pass} passed, {fail} failed, {na} not available.** Errors are relative (rel) or in \
         the quantity's unit; bounds (≤, ≥) judge the computed value itself. Each tolerance is \
         stated and justified in the case's documentation (`crates/hawser/src/verification/`).\n"
    );
    let _ = writeln!(md, "| {} |", COLUMNS.join(" | "));
    let _ = writeln!(md, "|{}", "---|".repeat(COLUMNS.len()));
    for c in results.iter().flat_map(|r| &r.checks) {
        let row: Vec<String> = cells(c).iter().map(|s| markdown_escape(s)).collect();
        let _ = writeln!(md, "| {} |", row.join(" | "));
    }
    md += "\n## Cases\n";
    for case in CASES {
        let ran: Vec<&CaseResult> = results.iter().filter(|r| r.case == case.name).collect();
        if ran.is_empty() {
            continue;
        }
        let _ = writeln!(md, "\n### {}\n\n{}.\n", case.name, case.description);
        for r in ran {
            for p in &r.plots {
                let _ = writeln!(
                    md,
                    "![{} ({})](img/{})\n",
                    p.title,
                    run_label(r.formulation, r.scheme),
                    plot_file(r, p)
                );
            }
        }
    }
    md
}

/// Writes `report` (markdown) and its plots under `img/` beside it, creating directories.
pub fn write_report(results: &[CaseResult], report: &Path, preamble: &str) -> std::io::Result<()> {
    let dir = report.parent().unwrap_or(Path::new("."));
    let img = dir.join("img");
    std::fs::create_dir_all(&img)?;
    for r in results {
        for p in &r.plots {
            let svg = plot_svg(
                p,
                &format!("{} ({})", p.title, run_label(r.formulation, r.scheme)),
            )
            .map_err(std::io::Error::other)?;
            std::fs::write(img.join(plot_file(r, p)), svg)?;
        }
    }
    std::fs::write(report, markdown(results, preamble))
}

/// Tick labels for an axis spanning lo..hi: scientific notation for very small or large
/// values, otherwise as many decimals as the span needs.
pub(crate) fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let big = lo.abs().max(hi.abs());
    let sci = !(1e-2..1e5).contains(&big);
    let decimals = (2.0 - (hi - lo).log10().floor()).clamp(0.0, 6.0) as usize;
    let zero = 1e-6 * (hi - lo);
    move |v: &f64| {
        if v.abs() < zero {
            "0".into()
        } else if sci {
            format!("{v:.2e}")
        } else {
            format!("{v:.decimals$}")
        }
    }
}

/// A plot as an SVG document; logarithmic plots are drawn as log10 of both axes.
pub fn plot_svg(plot: &Plot, title: &str) -> Result<String, String> {
    // With the `plot` feature plotters measures text with ab_glyph, which knows only the
    // fonts registered with it.
    #[cfg(feature = "plot")]
    crate::plot::register_fonts();
    let tr = |v: Real| if plot.log { v.log10() } else { v };
    // (label, points, markers)
    type Curve = (String, Vec<(f64, f64)>, bool);
    let series: Vec<Curve> = plot
        .series
        .iter()
        .map(|s| {
            let pts =
                s.x.iter()
                    .zip(&s.y)
                    .map(|(&x, &y)| (tr(x), tr(y)))
                    .filter(|(x, y)| x.is_finite() && y.is_finite())
                    .collect();
            (s.label.clone(), pts, s.markers)
        })
        .collect();
    let bounds = |f: fn(&(f64, f64)) -> f64| {
        let (lo, hi) = series
            .iter()
            .flat_map(|s| s.1.iter().map(f))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        if !(hi > lo) {
            let c = if lo.is_finite() { lo } else { 0.0 };
            (c - 1.0, c + 1.0)
        } else {
            let pad = 0.05 * (hi - lo);
            (lo - pad, hi + pad)
        }
    };
    let (x0, x1) = bounds(|p| p.0);
    let (y0, y1) = bounds(|p| p.1);
    let label = |l: &str| {
        if plot.log {
            format!("log10 {l}")
        } else {
            l.to_string()
        }
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 500)).into_drawing_area();
        let e = |e: DrawingAreaErrorKind<_>| e.to_string();
        root.fill(&WHITE).map_err(e)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(e)?;
        let (fx, fy) = (tick_format(x0, x1), tick_format(y0, y1));
        chart
            .configure_mesh()
            .x_desc(label(&plot.x_label))
            .y_desc(label(&plot.y_label))
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .draw()
            .map_err(e)?;
        for (k, (name, pts, markers)) in series.into_iter().enumerate() {
            let colour = Palette99::pick(k).to_rgba();
            if markers {
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 3, colour.filled())))
                    .map_err(e)?
                    .label(name)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 3, colour.filled()));
            } else {
                chart
                    .draw_series(LineSeries::new(pts, colour.stroke_width(2)))
                    .map_err(e)?
                    .label(name)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                    });
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(e)?;
        root.present().map_err(e)?;
    }
    Ok(svg)
}
