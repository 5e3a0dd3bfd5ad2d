#!/usr/bin/env python3
"""Natural frequency of the submerged snapping cable (position-vector paper §3.1) as the model
finds it: a small-amplitude (1 mm) frequency sweep of the top support, the steady tension
amplitude at the top against frequency, and the analytic estimate of the first axial mode.

usage: python3 scripts/snapping_sweep.py [path/to/hawser]   (run from the repository root)
"""
import csv, math, os, re, subprocess, sys, tempfile

hawser = sys.argv[1] if len(sys.argv) > 1 else "target/release/hawser"
base = open("examples/snapping_cable_127.toml").read()

def amplitude(freq, amp=0.0001):
    text = re.sub(r"amplitude = \[0.0, 0.0, 0.10\], frequency = [0-9.]+, ramp_time = 4.0",
                  f"amplitude = [0.0, 0.0, {amp}], frequency = {freq}, ramp_time = 3.0", base)
    text = text.replace("duration = 20.0", "duration = 12.0")
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "s.toml")
        open(path, "w").write(text)
        subprocess.run([hawser, "run", path, "--out", os.path.join(d, "o"), "--quiet"], check=True)
        rows = list(csv.reader(open(os.path.join(d, "o", "timeseries.csv"))))
    t = [float(r[0]) for r in rows[1:]]
    T = [float(r[1]) for r in rows[1:]]
    late = [x for tt, x in zip(t, T) if tt > 7.0]
    return 0.5 * (max(late) - min(late)) / (amp * 1000.0)

# Analytic first axial mode: payload (mass + added mass) on the elastic cable, with a third
# of the cable's mass (Rayleigh); buoyancy does not change the stiffness.
EA, L, gamma = 134.2e3, 18.9, 0.0112
m = 12.2 + 0.18 * 1000.0 * 0.0043930
f_axial = math.sqrt(EA / L / (m + gamma * L / 3)) / (2 * math.pi)
freqs = [0.5, 0.807, 1.0, 1.27, 1.5, 2.0, 2.5, 3.0, 3.3, 3.4, 3.5, 3.55, 3.6, 3.65, 3.7, 3.75, 3.8, 3.9, 4.0, 4.5, 5.0]
print(f"analytic first axial mode: {f_axial:.3f} Hz (k = EA/L = {EA/L:.0f} N/m, m = {m + gamma*L/3:.3f} kg)")
print("frequency [Hz]  tension amplitude per mm of support motion [N/mm]")
best = (0, 0)
for f in freqs:
    a = amplitude(f)
    best = max(best, (a, f))
    print(f"{f:14.3f}  {a / 1.0:10.3f}")
print(f"peak of the sweep: {best[1]:.2f} Hz")
