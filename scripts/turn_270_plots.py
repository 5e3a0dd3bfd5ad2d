#!/usr/bin/env python3
"""Plots of examples/turn_270.toml (docs/motions.md): ship and body tracks in the horizontal
plane and the body depth against time, from a run's timeseries.csv; prints the steady depth
before the turn and the extreme depths during and after it.

usage: turn_270_plots.py OUT_DIR/timeseries.csv   (writes docs/img/turn_270_*.svg)
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_svg import svg  # noqa: E402

rows = list(csv.reader(open(sys.argv[1])))
col = {name: i for i, name in enumerate(rows[0])}
data = [[float(v) for v in r] for r in rows[1:]]
get = lambda name: [r[col[name]] for r in data]
t = get("time")
img = os.path.join(HERE, "..", "docs", "img")
svg([("ship tow point", get("ship.x"), get("ship.y")), ("body", get("body.x"), get("body.y"))],
    "x [m]", "y [m]", "270° turn at 12 kn: horizontal tracks", os.path.join(img, "turn_270_tracks.svg"),
    equal=True)
svg([("body depth", t, [-z for z in get("body.z")])], "time [s]", "depth [m]",
    "270° turn at 12 kn: towed body depth (turn from 529.8 s to 644.3 s)",
    os.path.join(img, "turn_270_depth.svg"))

# The turn of the example: straight_before 2900 m at 12 kn with a 120 s build-up (s = U (t − 60)
# after it), radius 150 m through 270°.
u = 12 * 1852 / 3600
t_in = 2900 / u + 60
t_out = t_in + 150 * 1.5 * math.pi / u
z = list(zip(t, get("body.z")))
steady = [-v for s, v in z if 400 <= s <= t_in]
turn = [(s, -v) for s, v in z if t_in <= s <= t_out]
after = [(s, -v) for s, v in z if s >= t_in]
print(f"turn from {t_in:.1f} s to {t_out:.1f} s")
print(f"steady depth before the turn (400 s to {t_in:.1f} s): {min(steady):.2f} to {max(steady):.2f} m")
print("during the turn: shallowest %.2f m at %.0f s, deepest %.2f m at %.0f s"
      % (min(turn, key=lambda p: p[1])[1], min(turn, key=lambda p: p[1])[0],
         max(turn, key=lambda p: p[1])[1], max(turn, key=lambda p: p[1])[0]))
print("from the turn to the end: deepest %.2f m at %.0f s; at the end %.2f m"
      % (max(after, key=lambda p: p[1])[1], max(after, key=lambda p: p[1])[0], after[-1][1]))
