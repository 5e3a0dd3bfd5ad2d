//! Drawing the figures of `hawser plot` with plotters, on any backend (PNG and SVG).

use super::data::{LineRange, RunData};
use crate::run_files::Snapshot;
use crate::verification_report::tick_format;
use hawser::math::Real;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Figure size [px].
pub(super) const SIZE: (u32, u32) = (1100, 650);
const CAPTION: u32 = 24;
const LABEL: u32 = 17;

/// The tab10 palette.
pub(super) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// One curve of a chart.
pub(super) struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub color: RGBColor,
    pub width: u32,
    /// A dot at the last point (end B of a line in plan view, where a vertical line is a
    /// point).
    pub end_marker: bool,
}

/// A band filled between two curves: points (x, lower, upper) and its colour.
pub(super) type Band = (Vec<(f64, f64, f64)>, RGBColor);

/// What a chart shows.
pub(super) struct Chart<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub series: Vec<Series>,
    /// Axis ranges; `None`: the data's, padded.
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    pub band: Option<Band>,
    /// Horizontal segments (x0, x1, y, label, colour) drawn over the curves.
    pub segments: Vec<(f64, f64, f64, String, RGBColor)>,
    pub legend: bool,
}

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// The range of `values` padded by 4 % (a span of 2 about a constant, of ±5 % about a
/// constant away from zero).
pub(super) fn padded(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !(lo.is_finite() && hi.is_finite()) {
        return (0.0, 1.0);
    }
    if hi - lo <= 1e-12 * lo.abs().max(hi.abs()) {
        let d = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
        return (lo - d, hi + d);
    }
    let pad = 0.04 * (hi - lo);
    (lo - pad, hi + pad)
}

/// At most about `2 · buckets` points of `points` (sorted by x): per bucket of x its first,
/// smallest, largest and last point, in order, so that every peak stays visible.
pub(super) fn decimate(points: &[(f64, f64)], buckets: usize) -> Vec<(f64, f64)> {
    if points.len() <= 4 * buckets {
        return points.to_vec();
    }
    let per = points.len().div_ceil(buckets);
    let mut out = Vec::with_capacity(4 * buckets);
    for chunk in points.chunks(per) {
        let (mut lo, mut hi) = (0, 0);
        for (i, p) in chunk.iter().enumerate() {
            if p.1 < chunk[lo].1 {
                lo = i;
            }
            if p.1 > chunk[hi].1 {
                hi = i;
            }
        }
        let mut keep = [0, lo.min(hi), lo.max(hi), chunk.len() - 1];
        keep.sort_unstable();
        let mut last = usize::MAX;
        for k in keep {
            if k != last {
                out.push(chunk[k]);
                last = k;
            }
        }
    }
    out
}

/// Draws `chart` on `area`.
pub(super) fn draw_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &Chart<'_>,
) -> Result<(), String> {
    let (x0, x1) = chart.x_range.unwrap_or_else(|| {
        padded(
            chart
                .series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.0)),
        )
    });
    let (y0, y1) = chart.y_range.unwrap_or_else(|| {
        padded(
            chart
                .series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1))
                .chain(chart.segments.iter().map(|s| s.2)),
        )
    });
    let mut c = ChartBuilder::on(area)
        .caption(chart.title, ("sans-serif", CAPTION))
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(88)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    let (fx, fy) = (tick_format(x0, x1), tick_format(y0, y1));
    c.configure_mesh()
        .x_desc(chart.x_label)
        .y_desc(chart.y_label)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style(("sans-serif", LABEL - 2))
        .axis_desc_style(("sans-serif", LABEL))
        .max_light_lines(1)
        .light_line_style(RGBColor(242, 242, 242))
        .bold_line_style(RGBColor(215, 215, 215))
        .draw()
        .map_err(err)?;
    if let Some((band, color)) = &chart.band {
        let mut outline: Vec<(f64, f64)> = band.iter().map(|&(x, lo, _)| (x, lo)).collect();
        outline.extend(band.iter().rev().map(|&(x, _, hi)| (x, hi)));
        c.draw_series(std::iter::once(Polygon::new(
            outline,
            color.mix(0.18).filled(),
        )))
        .map_err(err)?;
    }
    for s in &chart.series {
        let color = s.color;
        let width = s.width;
        if s.end_marker
            && let Some(&p) = s.points.last()
        {
            c.draw_series(std::iter::once(Circle::new(p, 4, color.filled())))
                .map_err(err)?;
        }
        let drawn = c
            .draw_series(LineSeries::new(
                s.points.iter().copied(),
                color.stroke_width(width),
            ))
            .map_err(err)?;
        if chart.legend && !s.label.is_empty() {
            drawn.label(s.label.clone()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], color.stroke_width(width.max(2)))
            });
        }
    }
    let mut labelled: Vec<String> = Vec::new();
    for (a, b, y, label, color) in &chart.segments {
        let color = *color;
        let drawn = c
            .draw_series(std::iter::once(PathElement::new(
                vec![(*a, *y), (*b, *y)],
                color.stroke_width(3),
            )))
            .map_err(err)?;
        if chart.legend && !labelled.contains(label) {
            labelled.push(label.clone());
            drawn.label(label.clone()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], color.stroke_width(3))
            });
        }
    }
    if chart.legend {
        c.configure_series_labels()
            .position(legend_corner(chart, (x0, x1), (y0, y1)))
            .label_font(("sans-serif", LABEL - 2))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(160, 160, 160))
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// The corner of the plot with the fewest points of the curves and segments (the upper right
/// on a tie), for the legend.
fn legend_corner(chart: &Chart<'_>, x: (f64, f64), y: (f64, f64)) -> SeriesLabelPosition {
    let corners = [
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    let fraction = |v: f64, (lo, hi): (f64, f64)| (v - lo) / (hi - lo);
    let inside = |p: (f64, f64), right: bool, upper: bool| {
        let (fx, fy) = (fraction(p.0, x), fraction(p.1, y));
        (if right { fx > 0.6 } else { fx < 0.4 }) && (if upper { fy > 0.6 } else { fy < 0.4 })
    };
    // Every piece of every curve and segment as 8 points along it.
    let along = |a: (f64, f64), b: (f64, f64)| {
        (0..8).map(move |k| {
            let f = k as f64 / 8.0;
            (a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1))
        })
    };
    let points = chart
        .series
        .iter()
        .flat_map(|s| s.points.windows(2).flat_map(|w| along(w[0], w[1])))
        .chain(
            chart
                .segments
                .iter()
                .flat_map(|s| along((s.0, s.2), (s.1, s.2))),
        );
    let mut count = [0usize; 4];
    for p in points {
        for (k, &(_, right, upper)) in corners.iter().enumerate() {
            count[k] += usize::from(inside(p, right, upper));
        }
    }
    let best = (0..4).min_by_key(|&k| count[k]).unwrap_or(0);
    corners[best].0.clone()
}

/// A colour for the k-th of n snapshots, from early (blue) to late (red) through the
/// palette's purple.
fn time_colour(k: usize, n: usize) -> RGBColor {
    let f = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        1.0
    };
    let (a, b) = ((31.0, 119.0, 180.0), (214.0, 39.0, 40.0));
    let mix = |x: f64, y: f64| (x + f * (y - x)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The end tensions of every line against time: one chart.
pub(super) fn end_tensions<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    run: &RunData,
) -> Result<(), String> {
    area.fill(&WHITE).map_err(err)?;
    let ts = &run.timeseries;
    let mut series = Vec::new();
    for (k, line) in run.lines.iter().enumerate() {
        for (j, (end, width)) in [("end_a", 1), ("end_b", 2)].into_iter().enumerate() {
            let Some(c) = ts.index(&format!("{line}.{end}.tension")) else {
                continue;
            };
            let points = ts.points(c);
            series.push(Series {
                label: format!("{line} {}", if end == "end_a" { "end A" } else { "end B" }),
                points: decimate(&points, 1500),
                color: PALETTE[(2 * k + j) % PALETTE.len()],
                width,
                end_marker: false,
            });
        }
    }
    draw_chart(
        area,
        &Chart {
            title: "End tensions",
            x_label: "time [s]",
            y_label: "tension [N]",
            series,
            x_range: None,
            y_range: None,
            band: None,
            segments: Vec::new(),
            legend: true,
        },
    )
}

/// The range graph of a line: minimum, mean and maximum tension along the arc length, the
/// band between them, and the permissible tension (and MBL) of each section when they are on
/// the scale. Returns a note when a limit is off the scale.
pub(super) fn range_graph<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    line: &str,
    range: &LineRange,
) -> Result<Option<String>, String> {
    area.fill(&WHITE).map_err(err)?;
    let pts = |v: &[Real]| -> Vec<(f64, f64)> {
        range
            .arc_length
            .iter()
            .copied()
            .zip(v.iter().copied())
            .collect()
    };
    let top = range.max.iter().copied().fold(0.0, f64::max);
    let mut segments = Vec::new();
    let mut off_scale = Vec::new();
    for s in &range.sections {
        // A limit more than 3 times above the largest tension would flatten the curves.
        for (value, label, color) in [
            (
                s.permissible_tension,
                "permissible tension MBL/SF",
                RGBColor(255, 127, 14),
            ),
            (s.minimum_breaking_load, "MBL", RGBColor(120, 0, 0)),
        ] {
            let Some(v) = value else { continue };
            if label == "MBL" && s.design_safety_factor.is_none() && s.permissible_tension.is_some()
            {
                // Without a safety factor the permissible tension is the MBL: draw it once.
                continue;
            }
            if v <= 3.0 * top {
                segments.push((s.start, s.end, v, label.to_string(), color));
            } else {
                off_scale.push(format!("{label} of {} ({v:.4e} N)", s.line_type));
            }
        }
    }
    let series = vec![
        Series {
            label: "maximum".into(),
            points: pts(&range.max),
            color: RGBColor(214, 39, 40),
            width: 2,
            end_marker: false,
        },
        Series {
            label: "mean".into(),
            points: pts(&range.mean),
            color: RGBColor(40, 40, 40),
            width: 2,
            end_marker: false,
        },
        Series {
            label: "minimum".into(),
            points: pts(&range.min),
            color: RGBColor(31, 119, 180),
            width: 2,
            end_marker: false,
        },
    ];
    let band = range
        .arc_length
        .iter()
        .zip(range.min.iter().zip(&range.max))
        .map(|(&s, (&lo, &hi))| (s, lo, hi))
        .collect();
    let (lo, _) = padded(range.min.iter().copied());
    let hi = segments.iter().map(|s| s.2).fold(top, f64::max);
    let title = format!("Range graph of {line}: effective tension along the line");
    draw_chart(
        area,
        &Chart {
            title: &title,
            x_label: "unstretched arc length from end A [m]",
            y_label: "effective tension [N]",
            series,
            x_range: None,
            // Room above the curves for the legend.
            y_range: Some((lo.min(0.0), 1.2 * hi)),
            band: Some((band, RGBColor(214, 39, 40))),
            segments,
            legend: true,
        },
    )?;
    Ok((!off_scale.is_empty()).then(|| off_scale.join("; ")))
}

/// The snapshots to draw: at most `count`, evenly spread over those given.
pub(super) fn pick(snapshots: &[Snapshot], count: usize) -> Vec<&Snapshot> {
    let n = snapshots.len();
    if n <= count {
        return snapshots.iter().collect();
    }
    let mut out: Vec<&Snapshot> = (0..count)
        .map(|k| &snapshots[(k * (n - 1) + (count - 1) / 2) / (count - 1)])
        .collect();
    out.dedup_by(|a, b| a.time == b.time);
    out
}

/// Ranges (x, y) of the data made to the same metres per pixel on a plot of `pixels`, unless
/// one extent is below 1/20 of the other (then each axis its own, and `false`).
fn equal_aspect(
    x: (f64, f64),
    y: (f64, f64),
    pixels: (f64, f64),
) -> ((f64, f64), (f64, f64), bool) {
    let (w, h) = (x.1 - x.0, y.1 - y.0);
    if w < h / 20.0 || h < w / 20.0 {
        return (
            padded([x.0, x.1].into_iter()),
            padded([y.0, y.1].into_iter()),
            false,
        );
    }
    let scale = (w / pixels.0).max(h / pixels.1) * 1.08;
    let (cx, cy) = (0.5 * (x.0 + x.1), 0.5 * (y.0 + y.1));
    let (hw, hh) = (0.5 * scale * pixels.0, 0.5 * scale * pixels.1);
    ((cx - hw, cx + hw), (cy - hh, cy + hh), true)
}

/// Line shapes at snapshot times: side view (in the vertical plane through the line's ends
/// at the first snapshot) above, plan view below. Returns the times drawn.
pub(super) fn shapes<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    line: &str,
    snapshots: &[Snapshot],
) -> Result<Vec<f64>, String> {
    area.fill(&WHITE).map_err(err)?;
    let picked = pick(snapshots, 8);
    let first = picked.first().ok_or("no snapshots")?;
    // The side view's horizontal axis: the plan direction from end A to end B.
    let (a, b) = (first.position[0], first.position[first.position.len() - 1]);
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let span = dx.hypot(dy);
    let (ex, ey, along) = if span > 1e-6 * first.arc_length.last().copied().unwrap_or(1.0).max(1.0)
    {
        (
            dx / span,
            dy / span,
            "horizontal distance from end A towards end B [m]",
        )
    } else {
        (1.0, 0.0, "x − x(end A) [m]")
    };
    let u = |p: &[f64; 3]| (p[0] - a[0]) * ex + (p[1] - a[1]) * ey;
    let (top, bottom) = area.split_vertically(area.dim_in_pixel().1 / 2);
    let n = picked.len();
    let legend_of = |k: usize| format!("t = {} s", trim_number(picked[k].time));
    // Side view.
    let series: Vec<Series> = picked
        .iter()
        .enumerate()
        .map(|(k, s)| Series {
            label: legend_of(k),
            points: s.position.iter().map(|p| (u(p), p[2])).collect(),
            color: time_colour(k, n),
            width: 2,
            end_marker: false,
        })
        .collect();
    let plot_px = |d: &DrawingArea<DB, Shift>| {
        let (w, h) = d.dim_in_pixel();
        (
            (w as f64 - 88.0 - 24.0).max(10.0),
            (h as f64 - 48.0 - 24.0 - 34.0).max(10.0),
        )
    };
    let xs = padded(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let zs = padded(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let (xr, zr, to_scale) = equal_aspect(xs, zs, plot_px(&top));
    let title = format!(
        "{line}: side view{}",
        if to_scale { "" } else { " (axes not to scale)" }
    );
    let mut segments = Vec::new();
    if zr.0 < 0.0 && zr.1 > 0.0 {
        segments.push((
            xr.0,
            xr.1,
            0.0,
            "water surface".to_string(),
            RGBColor(120, 180, 230),
        ));
    }
    draw_chart(
        &top,
        &Chart {
            title: &title,
            x_label: along,
            y_label: "z [m]",
            series,
            x_range: Some(xr),
            y_range: Some(zr),
            band: None,
            segments,
            legend: true,
        },
    )?;
    // Plan view, with a dot at end B.
    let series: Vec<Series> = picked
        .iter()
        .enumerate()
        .map(|(k, s)| Series {
            label: legend_of(k),
            points: s.position.iter().map(|p| (p[0], p[1])).collect(),
            color: time_colour(k, n),
            width: 2,
            end_marker: true,
        })
        .collect();
    let xs = padded(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let ys = padded(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let (xr, yr, to_scale) = equal_aspect(xs, ys, plot_px(&bottom));
    let title = format!(
        "{line}: plan view{}",
        if to_scale { "" } else { " (axes not to scale)" }
    );
    draw_chart(
        &bottom,
        &Chart {
            title: &title,
            x_label: "x [m]",
            y_label: "y [m]",
            series,
            x_range: Some(xr),
            y_range: Some(yr),
            band: None,
            segments: Vec::new(),
            legend: false,
        },
    )?;
    Ok(picked.iter().map(|s| s.time).collect())
}

/// A number without trailing zeros (times in legends).
pub(super) fn trim_number(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A body's motions in six degrees of freedom: x, y, z [m] on the left, roll, pitch, yaw
/// [deg] on the right.
pub(super) fn body_motions<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    run: &RunData,
    body: &str,
    columns: [usize; 6],
) -> Result<(), String> {
    area.fill(&WHITE).map_err(err)?;
    let ts = &run.timeseries;
    let panels = area.split_evenly((3, 2));
    let names = ["x", "roll", "y", "pitch", "z", "yaw"];
    let dof = [0, 3, 1, 4, 2, 5];
    for (k, panel) in panels.iter().enumerate() {
        let c = columns[dof[k]];
        let unit = if dof[k] < 3 { "m" } else { "deg" };
        let points = ts.points(c);
        let title = format!("{body}.{}", names[k]);
        let y_label = format!("{} [{unit}]", names[k]);
        draw_chart(
            panel,
            &Chart {
                title: &title,
                x_label: "time [s]",
                y_label: &y_label,
                series: vec![Series {
                    label: String::new(),
                    points: decimate(&points, 800),
                    color: PALETTE[dof[k] % 3],
                    width: 2,
                    end_marker: false,
                }],
                x_range: None,
                y_range: None,
                band: None,
                segments: Vec::new(),
                legend: false,
            },
        )?;
    }
    Ok(())
}

/// The amplitude spectrum of a channel.
pub(super) fn spectrum<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    unit: &str,
    spectrum: &[(f64, f64)],
) -> Result<(), String> {
    area.fill(&WHITE).map_err(err)?;
    let top = spectrum.iter().map(|p| p.1).fold(0.0, f64::max);
    let y_label = format!("amplitude [{unit}]");
    draw_chart(
        area,
        &Chart {
            title,
            x_label: "frequency [Hz]",
            y_label: &y_label,
            series: vec![Series {
                label: String::new(),
                points: spectrum.to_vec(),
                color: PALETTE[0],
                width: 2,
                end_marker: false,
            }],
            x_range: Some((0.0, spectrum.last().map_or(1.0, |p| p.0))),
            y_range: Some((0.0, if top > 0.0 { 1.06 * top } else { 1.0 })),
            band: None,
            segments: Vec::new(),
            legend: false,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_the_extremes() {
        let points: Vec<(f64, f64)> = (0..100_000)
            .map(|i| {
                (
                    i as f64,
                    if i == 54_321 {
                        9.0
                    } else {
                        (i as f64 * 0.01).sin()
                    },
                )
            })
            .collect();
        let d = decimate(&points, 500);
        assert!(d.len() <= 2000 && d.len() >= 500, "{}", d.len());
        assert!(d.contains(&(54_321.0, 9.0)));
        assert_eq!(d[0], points[0]);
        assert_eq!(d[d.len() - 1], points[points.len() - 1]);
        assert!(d.windows(2).all(|w| w[0].0 < w[1].0));
    }

    #[test]
    fn padding_and_picking() {
        assert_eq!(padded([2.0, 2.0].into_iter()), (1.9, 2.1));
        assert_eq!(padded([0.0, 0.0].into_iter()), (-1.0, 1.0));
        let (lo, hi) = padded([0.0, 100.0].into_iter());
        assert!((lo + 4.0).abs() < 1e-12 && (hi - 104.0).abs() < 1e-12);
        let snaps: Vec<Snapshot> = (0..31)
            .map(|k| Snapshot {
                time: k as f64,
                ..Default::default()
            })
            .collect();
        let times: Vec<f64> = pick(&snaps, 8).iter().map(|s| s.time).collect();
        assert_eq!(times.len(), 8);
        assert_eq!((times[0], times[7]), (0.0, 30.0));
    }
}
