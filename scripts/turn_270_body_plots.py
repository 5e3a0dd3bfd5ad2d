#!/usr/bin/env python3
"""Plots and numbers of examples/turn_270_body.toml (the towed body as a rigid body) against
examples/turn_270.toml (the body as a free point), docs/motions.md: ship and body tracks,
body depth against time for both, and the rigid body's pitch and roll; prints the steady depth
before the turn, the extreme depths during and after it, the tow-point tensions and the
attitude.

usage: turn_270_body_plots.py POINT.csv BODY.csv [CONTROL.csv]
       (timeseries.csv of the three runs of scripts/turn_270_body.sh; CONTROL is the rigid
       body made to look like the free point; writes docs/img/turn_270_body_*.svg)
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_svg import svg  # noqa: E402


def read(path):
    rows = list(csv.reader(open(path)))
    col = {name: i for i, name in enumerate(rows[0])}
    data = [[float(v) for v in r] for r in rows[1:]]
    return lambda name: [r[col[name]] for r in data]


point, body = read(sys.argv[1]), read(sys.argv[2])
control = read(sys.argv[3]) if len(sys.argv) > 3 else None
t = body("time")
assert t == point("time"), "the runs must have the same samples"
assert control is None or control("time") == t, "the runs must have the same samples"
img = os.path.join(HERE, "..", "docs", "img")

# Tracks from 480 s to 720 s (the straight runs before and after are lines), the free point under the
# rigid body.
late = [i for i, s in enumerate(t) if 480 <= s <= 720]
cut = lambda v: [v[i] for i in late]
svg([("ship tow point", cut(body("tow_point.x")), cut(body("tow_point.y"))),
     ("free point", cut(point("body.x")), cut(point("body.y"))),
     ("rigid body (origin)", cut(body("body.x")), cut(body("body.y")))],
    "x [m]", "y [m]", "270° turn at 12 kn: tracks from t = 480 s to 720 s, rigid body and free point",
    os.path.join(img, "turn_270_body_tracks.svg"), equal=True)
svg([("rigid body: depth of the bale (cable end)", t, [-z for z in body("bale.z")]),
     ("free point", t, [-z for z in point("body.z")])]
    + ([("control: rigid body with the free point's drag and added mass", t,
         [-z for z in control("bale.z")])] if control else []),
    "time [s]", "depth [m]", "270° turn at 12 kn: towed body depth (turn from 529.8 s to 644.3 s)",
    os.path.join(img, "turn_270_body_depth.svg"))
svg([("pitch (positive bow down)", t, body("body.pitch")), ("roll", t, body("body.roll"))],
    "time [s]", "angle [deg]", "270° turn at 12 kn: rigid body attitude",
    os.path.join(img, "turn_270_body_attitude.svg"))

# The turn of the example: straight_before 2900 m at 12 kn with a 120 s build-up (s = U (t − 60)
# after it), radius 150 m through 270°.
u = 12 * 1852 / 3600
t_in = 2900 / u + 60
t_out = t_in + 150 * 1.5 * math.pi / u
print(f"turn from {t_in:.1f} s to {t_out:.1f} s")


def window(values, lo, hi):
    return [(s, v) for s, v in zip(t, values) if lo <= s <= hi]


def report(name, depth, tension):
    steady = [v for _, v in window(depth, 400, t_in)]
    turn = window(depth, t_in, t_out)
    after = window(depth, t_in, t[-1])
    ten = [v for _, v in window(tension, 400, t_in)]
    ten_after = window(tension, t_in, t[-1])
    lo, hi = min(turn, key=lambda p: p[1]), max(turn, key=lambda p: p[1])
    deep = max(after, key=lambda p: p[1])
    tmin, tmax = min(ten_after, key=lambda p: p[1]), max(ten_after, key=lambda p: p[1])
    print(f"{name}:")
    print(f"  steady depth 400–{t_in:.1f} s: {min(steady):.2f} to {max(steady):.2f} m; "
          f"tow-point tension {min(ten) / 1e3:.2f}–{max(ten) / 1e3:.2f} kN")
    print(f"  during the turn: shallowest {lo[1]:.2f} m at {lo[0]:.0f} s, deepest {hi[1]:.2f} m "
          f"at {hi[0]:.0f} s")
    print(f"  from the turn on: deepest {deep[1]:.2f} m at {deep[0]:.0f} s; at the end "
          f"{after[-1][1]:.2f} m; tow-point tension {tmin[1] / 1e3:.1f} kN ({tmin[0]:.0f} s) to "
          f"{tmax[1] / 1e3:.1f} kN ({tmax[0]:.0f} s)")


report("free point", [-z for z in point("body.z")], point("tow.end_a.tension"))
report("rigid body, bale (cable end)", [-z for z in body("bale.z")], body("tow.end_a.tension"))
report("rigid body, origin", [-z for z in body("body.z")], body("tow.end_a.tension"))
if control:
    report("control (rigid body, isotropic drag and added mass, cable at the origin)",
           [-z for z in control("bale.z")], control("tow.end_a.tension"))
    dz = [abs(a - b) for a, b in zip(control("bale.z"), point("body.z"))]
    dh = [math.hypot(a - b, c - e) for a, b, c, e in
          zip(control("body.x"), point("body.x"), control("body.y"), point("body.y"))]
    print(f"  control against the free point: depth within {max(dz[400:530]):.3f} m before the "
          f"turn and {max(dz):.2f} m over the run, horizontal position within {max(dh):.2f} m; "
          f"largest pitch and roll {max(abs(v) for v in control('body.pitch')):.2e}, "
          f"{max(abs(v) for v in control('body.roll')):.2e} deg")
pitch, roll = body("body.pitch"), body("body.roll")
steady_pitch = [v for _, v in window(pitch, 400, t_in)]
print(f"rigid body pitch before the turn: {min(steady_pitch):.2f} to {max(steady_pitch):.2f} deg")
for lo, hi, what in [(t_in, t_out, "during the turn"), (t_in, t[-1], "from the turn on")]:
    p = window(pitch, lo, hi)
    r = window(roll, lo, hi)
    print(f"  {what}: pitch {min(v for _, v in p):.1f} to {max(v for _, v in p):.1f} deg, "
          f"roll {min(v for _, v in r):.2f} to {max(v for _, v in r):.2f} deg")
# Horizontal distance between the rigid body and the free point.
d = [math.hypot(a - b, c - e) for a, b, c, e in
     zip(body("body.x"), point("body.x"), body("body.y"), point("body.y"))]
late = max(window(d, t_in, t[-1]), key=lambda p: p[1])
print(f"largest horizontal distance rigid body – free point after the turn starts: "
      f"{late[1]:.1f} m at {late[0]:.0f} s; before the turn {max(v for _, v in window(d, 400, t_in)):.2f} m")
