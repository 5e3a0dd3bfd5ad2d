#!/usr/bin/env python3
"""Statistics and plots of examples/rov_irregular_waves.toml (docs/examples.md §8): tether top
and bottom tensions (mean, std, min, max, time with the bottom tension below 5 % of its
static value, and the slack intervals hawser reports), the vessel's and the ROV's motions, all
after the build-up (t ≥ T0, default 30 s). Writes docs/img/rov_irregular_waves_*.svg.

usage: rov_waves_stats.py OUT_DIR [T0]     (OUT_DIR of `hawser run`, with timeseries.csv and
                                            summary.json)
"""
import csv, json, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_svg import svg  # noqa: E402

out = sys.argv[1]
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else 30.0
rows = list(csv.reader(open(os.path.join(out, "timeseries.csv"))))
col = {name: i for i, name in enumerate(rows[0])}
data = [[float(v) for v in r] for r in rows[1:]]
static = {name: data[0][i] for name, i in col.items()}
data = [r for r in data if r[0] >= t0]
get = lambda name: [r[col[name]] for r in data]
t = get("time")
dt = t[1] - t[0]


def stats(name, scale=1.0):
    v = [x * scale for x in get(name)]
    m = sum(v) / len(v)
    s = math.sqrt(sum((x - m) ** 2 for x in v) / len(v))
    return m, s, min(v), max(v)


print(f"{len(t)} samples from {t[0]:.1f} s to {t[-1]:.1f} s (every {dt:.3g} s)")
print(f"{'channel':28s} {'static':>10s} {'mean':>10s} {'std':>9s} {'min':>10s} {'max':>10s}")
for name, unit in [("tether.end_a.tension", "N"), ("tether.end_b.tension", "N"),
                   ("aframe.z", "m"), ("vessel.z", "m"), ("vessel.roll", "deg"),
                   ("vessel.pitch", "deg"), ("rov.x", "m"), ("rov.y", "m"), ("rov.z", "m"),
                   ("rov.vz", "m/s"), ("rov.roll", "deg"), ("rov.pitch", "deg"),
                   ("rov.yaw", "deg")]:
    m, s, lo, hi = stats(name)
    print(f"{name + ' [' + unit + ']':28s} {static[name]:10.4g} {m:10.4g} {s:9.3g} {lo:10.4g} {hi:10.4g}")

bottom = get("tether.end_b.tension")
low = 0.05 * static["tether.end_b.tension"]
below = sum(1 for x in bottom if x < low)
print(f"bottom tension below 5 % of its static value ({low:.1f} N): {below} samples, "
      f"{below * dt:.2f} s of {t[-1] - t[0]:.0f} s")
summary = json.load(open(os.path.join(out, "summary.json")))
slack = [s for s in summary["lines"]["tether"]["slack_intervals"] if s["start"] >= t0]
total = sum(s["end"] - s["start"] for s in slack)
print(f"slack intervals (some element with strain ≤ 0) from {t0:.0f} s: {len(slack)}, "
      f"{total:.2f} s in all, longest {max((s['end'] - s['start'] for s in slack), default=0):.2f} s, "
      f"smallest strain {min((s['min_strain'] for s in slack), default=0):.2e}")
# Heave transfer: the ROV's and the A-frame's heave standard deviations.
print(f"ROV heave std / A-frame heave std: {stats('rov.z')[1] / stats('aframe.z')[1]:.3f}")

img = os.path.join(HERE, "..", "docs", "img")
window = [i for i, s in enumerate(t) if s <= t0 + 120]
cut = lambda v: [v[i] for i in window]
svg([("top (A-frame)", cut(t), cut([x / 1e3 for x in get("tether.end_a.tension")])),
     ("bottom (ROV)", cut(t), cut([x / 1e3 for x in bottom]))],
    "time [s]", "tension [kN]", "ROV tether in a JONSWAP sea (Hs 2.5 m, Tp 8 s): end tensions",
    os.path.join(img, "rov_irregular_waves_tension.svg"))
svg([("A-frame heave", cut(t), cut([z - static["aframe.z"] for z in get("aframe.z")])),
     ("ROV heave", cut(t), cut([z - static["rov.z"] for z in get("rov.z")]))],
    "time [s]", "z − z(0) [m]", "ROV tether in a JONSWAP sea: A-frame and ROV heave",
    os.path.join(img, "rov_irregular_waves_heave.svg"))

# Where the bottom tension's swing comes from: the ROV's heave inertia and drag. With a_z the
# heave acceleration (central differences of rov.vz), m + A33 = 3000 + 3500 kg and the heave
# drag ½ ρ (C A)_z |v_z| v_z, (C A)_z = 5.1 m², the vertical balance of the ROV is
# T_b,z − wet weight ≈ (m + A33) a_z + ½ ρ (C A)_z |v_z| v_z (the tether is nearly vertical).
vz = get("rov.vz")
az = [(vz[i + 1] - vz[i - 1]) / (2 * dt) for i in range(1, len(vz) - 1)]
est = [(3000 + 3500) * a + 0.5 * 1025 * 5.1 * abs(v) * v for a, v in zip(az, vz[1:-1])]
swing = [b - static["tether.end_b.tension"] for b in bottom[1:-1]]
rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v))
taut = [i for i, b in enumerate(bottom[1:-1]) if b > low]
print(f"bottom tension swing: RMS {rms(swing):.0f} N; (m + A33) a_z + heave drag: RMS "
      f"{rms(est):.0f} N (inertia alone {rms([(3000 + 3500) * a for a in az]):.0f} N); "
      f"difference RMS {rms([swing[i] - est[i] for i in taut]):.0f} N while taut")
