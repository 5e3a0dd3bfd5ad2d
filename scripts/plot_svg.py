#!/usr/bin/env python3
"""Plots columns of hawser's timeseries.csv (or x–z shapes from a snapshot file) as an SVG,
with no dependencies beyond the standard library.

usage:
  plot_svg.py timeseries OUT.svg CSV COLUMN [COLUMN ...] [--scale S] [--ylabel L] [--title T] [--from T0]
  plot_svg.py shapes OUT.svg SNAPSHOT.csv [--every K] [--title T]
Columns are matched by their name without a unit in brackets (hawser's files have none;
the comparison tables in docs/data have them), e.g. `cable.end_a.tension`.
"""
import csv, sys

W, H, ML, MR, MT, MB = 760, 380, 70, 20, 34, 46
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]

def nice_ticks(lo, hi, n=6):
    import math
    span = hi - lo or 1.0
    step = 10 ** math.floor(math.log10(span / n))
    for m in (1, 2, 5, 10):
        if span / (step * m) <= n:
            step *= m
            break
    t = math.ceil(lo / step) * step
    out = []
    while t <= hi + 1e-12 * span:
        out.append(round(t, 12))
        t += step
    return out

def svg(series, xlabel, ylabel, title, out, equal=False):
    xs = [x for s in series for x in s[1]]
    ys = [y for s in series for y in s[2]]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if y1 == y0:
        y1 = y0 + 1
    pad = 0.05 * (y1 - y0)
    y0, y1 = y0 - pad, y1 + pad
    if equal:
        # Same metres per pixel on both axes.
        sx = (x1 - x0) / (W - ML - MR); sy = (y1 - y0) / (H - MT - MB)
        s = max(sx, sy)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        x0, x1 = cx - s * (W - ML - MR) / 2, cx + s * (W - ML - MR) / 2
        y0, y1 = cy - s * (H - MT - MB) / 2, cy + s * (H - MT - MB) / 2
    px = lambda x: ML + (x - x0) / (x1 - x0) * (W - ML - MR)
    py = lambda y: H - MB - (y - y0) / (y1 - y0) * (H - MT - MB)
    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{W/2}" y="20" text-anchor="middle" font-size="14">{title}</text>']
    for t in nice_ticks(x0, x1):
        o.append(f'<line x1="{px(t):.1f}" y1="{MT}" x2="{px(t):.1f}" y2="{H-MB}" stroke="#eee"/>')
        o.append(f'<text x="{px(t):.1f}" y="{H-MB+16}" text-anchor="middle">{t:g}</text>')
    for t in nice_ticks(y0, y1):
        o.append(f'<line x1="{ML}" y1="{py(t):.1f}" x2="{W-MR}" y2="{py(t):.1f}" stroke="#eee"/>')
        o.append(f'<text x="{ML-6}" y="{py(t)+4:.1f}" text-anchor="end">{t:g}</text>')
    o.append(f'<rect x="{ML}" y="{MT}" width="{W-ML-MR}" height="{H-MT-MB}" fill="none" stroke="black"/>')
    o.append(f'<text x="{W/2}" y="{H-8}" text-anchor="middle">{xlabel}</text>')
    o.append(f'<text transform="translate(16,{H/2}) rotate(-90)" text-anchor="middle">{ylabel}</text>')
    for i, (name, x, y) in enumerate(series):
        c = COLOURS[i % len(COLOURS)]
        pts = " ".join(f"{px(a):.1f},{py(b):.1f}" for a, b in zip(x, y))
        o.append(f'<polyline fill="none" stroke="{c}" stroke-width="1.2" points="{pts}"/>')
        if name:
            o.append(f'<text x="{ML+10}" y="{MT+16+14*i}" fill="{c}">{name}</text>')
    o.append("</svg>")
    open(out, "w").write("\n".join(o) + "\n")

def opt(args, flag, default=None, conv=str):
    if flag in args:
        i = args.index(flag); v = args[i + 1]; del args[i:i + 2]; return conv(v)
    return default

def main():
    args = sys.argv[1:]
    kind, out = args[0], args[1]
    title = opt(args, "--title", "")
    if kind == "timeseries":
        scale = opt(args, "--scale", 1.0, float); ylabel = opt(args, "--ylabel", "")
        start = opt(args, "--from", float("-inf"), float)
        rows = list(csv.reader(open(args[2])))
        head = [h.split(" [")[0] for h in rows[0]]
        t = [float(r[0]) for r in rows[1:]]
        series = []
        for col in args[3:]:
            j = head.index(col)
            pairs = [(a, float(r[j]) * scale) for a, r in zip(t, rows[1:]) if a >= start]
            series.append((col, [p[0] for p in pairs], [p[1] for p in pairs]))
        svg(series, "time [s]", ylabel, title, out)
    elif kind == "shapes":
        every = opt(args, "--every", 1, int)
        rows = list(csv.reader(open(args[2])))[1:]
        times = sorted({float(r[0]) for r in rows})[::every]
        series = []
        for tt in times:
            pts = [(float(r[3]), float(r[5])) for r in rows if float(r[0]) == tt]
            series.append(("", [p[0] for p in pts], [p[1] for p in pts]))
        svg(series, "x [m]", "z [m]", title, out, equal=False)

if __name__ == "__main__":
    main()
