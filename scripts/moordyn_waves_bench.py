#!/usr/bin/env python3
"""MoorDyn 2.7.2 side of the wave-kinematics benchmark (BENCHMARKS.md, "Wave kinematics").

OC3 (the deck tests/data/moordyn/oc3_lines.txt) with its fairleads in a 2 m, 10 s surge,
run twice per repeat, interleaved: in still water and with MoorDyn's grid wave kinematics
(``WaveKin 3``: a wave elevation record ``wave_elevation.txt`` turned into kinematics on the
``water_grid.txt`` grid by FFT). The record is a JONSWAP sea, Hs 6 m, Tp 10 s, gamma 3.3, of
200 components over 0.5-5 x 1/Tp at the origin (random phases, seed 1; the grid cost does not
depend on the components), sampled every dtWave = 0.25 s for the run.

The grid covers the lines: x and y from -900 to 900 m in 37 points (50 m), z from -320 to 0 m
in 17 points (20 m). Reported: the CPU time (time.process_time) of Create + Init (where MoorDyn
fills the grid) + the stepping loop, and of Init and of the loop alone (moordyn_bench.run_once's
timers, switched to CPU time), each as the median over repeats of the paired ratio
waves / still.

Usage: .venv-bench/bin/python scripts/moordyn_waves_bench.py [--duration 20] [--repeats 3]
"""

import argparse
import json
import math
import os
import random
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import moordyn_bench as mb  # noqa: E402
import types  # noqa: E402

# moordyn_bench.run_once times Init and the stepping loop with time.perf_counter: make those
# timers this process's CPU time (the machine is shared; wall time is not a measure).
mb.time = types.SimpleNamespace(perf_counter=time.process_time)


def jonswap_record(duration, dt, hs=6.0, tp=10.0, gamma=3.3, n=200, seed=1):
    wp = 2 * math.pi / tp
    lo, hi = 0.5 * wp, 5.0 * wp
    dw = (hi - lo) / n
    rnd = random.Random(seed)

    def pm(w):
        x = wp / w
        return 5.0 / 16.0 * hs * hs * x ** 4 / w * math.exp(-1.25 * x ** 4)

    def s(w):
        sigma = 0.07 if w <= wp else 0.09
        return pm(w) * gamma ** math.exp(-((w - wp) ** 2) / (2 * sigma ** 2 * wp ** 2))

    comps = []
    for j in range(n):
        w = lo + (j + 0.5) * dw
        comps.append((math.sqrt(2 * s(w) * dw), w, 2 * math.pi * rnd.random()))
    m0 = sum(a * a / 2 for a, _, _ in comps)
    scale = (hs * hs / 16) ** 0.5 / m0 ** 0.5
    rows = []
    for i in range(int(round(duration / dt)) + 1):
        t = i * dt
        rows.append((t, sum(scale * a * math.cos(p - w * t) for a, w, p in comps)))
    return rows


def deck_with_waves(src_lines):
    lines = list(src_lines)
    mb.set_option(lines, "WaveKin", "3")
    mb.set_option(lines, "dtWave", "0.25")
    return lines


GRID = """--------------------- MoorDyn Waves grid File ----------------------------------
List of grid points
--------------------------------------------------------------------------------
2
-900 900 37
2
-900 900 37
2
-320 0 17
"""


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    p.add_argument("--deck", default=os.path.join(here, "..", "tests", "data", "moordyn", "oc3_lines.txt"))
    p.add_argument("--dt", type=float, default=0.002)
    p.add_argument("--duration", type=float, default=20.0)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--json", action="store_true")
    a = p.parse_args()
    import moordyn
    import cmoordyn

    with open(a.deck, encoding="utf-8") as fh:
        src = fh.read().splitlines()
    tmp = tempfile.mkdtemp(prefix="moordyn-waves-")
    still_path, _, _ = mb.prepare_deck(src, os.path.join(tmp, "still"), a.dt, None, False)
    waves_dir = os.path.join(tmp, "waves")
    waves_path, _, _ = mb.prepare_deck(deck_with_waves(src), waves_dir, a.dt, None, False)
    # The record must outlast the run (MoorDyn's grid time axis).
    with open(os.path.join(waves_dir, "wave_elevation.txt"), "w") as fh:
        for t, e in jonswap_record(a.duration + 10.0, 0.25):
            fh.write("%.4f %.6f\n" % (t, e))
    with open(os.path.join(waves_dir, "water_grid.txt"), "w") as fh:
        fh.write(GRID)
    x0 = [c for _, xyz in mb.coupled_points_from_deck(src) for c in xyz]
    console = os.path.join(tmp, "console.txt")
    runs = {"still": [], "waves": []}
    for _ in range(a.repeats):
        for name, path in (("still", still_path), ("waves", waves_path)):
            c0 = time.process_time()
            res = mb.run_once(moordyn, cmoordyn, path, x0, a.dt, 0.1, a.duration, 2.0, 10.0,
                              console, False)
            cpu = time.process_time() - c0
            runs[name].append({"cpu_s": cpu, "loop_cpu_s": res["wall_s"],
                               "init_cpu_s": res["init_wall_s"]})
    ratio_all = statistics.median(w["cpu_s"] / s["cpu_s"] for w, s in zip(runs["waves"], runs["still"]))
    ratio_loop = statistics.median(w["loop_cpu_s"] / s["loop_cpu_s"]
                                   for w, s in zip(runs["waves"], runs["still"]))
    from importlib.metadata import version
    out = {"moordyn": version("moordyn"),
           "duration_s": a.duration, "dtM_s": a.dt, "grid": [37, 37, 17], "dtWave_s": 0.25,
           "runs": runs, "cpu_ratio_waves_to_still_with_init": ratio_all,
           "loop_ratio_waves_to_still": ratio_loop}
    if a.json:
        print(json.dumps(out, indent=2))
    else:
        for k in ("still", "waves"):
            best = min(runs[k], key=lambda r: r["cpu_s"])
            print("%-6s cpu %.3f s (Init %.3f s, stepping loop %.3f s)" % (
                k, best["cpu_s"], best["init_cpu_s"], best["loop_cpu_s"]))
        print("paired ratio waves/still: CPU with init %.3f, stepping loop %.3f" % (ratio_all, ratio_loop))


if __name__ == "__main__":
    main()
