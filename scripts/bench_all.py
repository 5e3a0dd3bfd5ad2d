#!/usr/bin/env python3
"""hawser against MoorDyn 2.7.2 in one run: paired CPU-time ratios and the speed targets.

Run by scripts/bench_all.sh (which builds hawser and makes the MoorDyn venv); run this file
with the venv's Python. Every hawser number is `hawser bench --json` (the CPU time of the
running thread); every MoorDyn number is the CPU time (time.process_time) of the stepping loop
of scripts/moordyn_bench.py's run_once (MoorDyn-C through its Python bindings, a 0.1 s
coupling interval, no file output). Each case runs REPEATS times alternating the two codes;
a ratio is the median over the pairs of the same repeat, so that the machine's load, shared
with other work, affects both sides of each ratio alike.

Targets printed (each with its measured value):
  1. OC3 at the same step (dt 2 ms): hawser fe, RK4, lumped mass >= 10 M node-steps per CPU
     second; CPU per step of hawser RK4 <= 1/2 of MoorDyn RK2's.
  2. OC3 with hawser at 5 ms (--hawser-dt) against MoorDyn at the deck's dtM 2 ms, per
     simulated second (the accuracy of each at its step is not checked here: BENCHMARKS.md).
  3. Waves: OC3 in JONSWAP Hs 6 m, Tp 10 s, 200 components, static-position kinematics: CPU
     per step <= 3x still water (and direct summation for comparison).
  4. A 1000 m chain at 20 to 1280 segments (hawser only): CPU per node-step and per
     simulated second at the automatic step.
  5. The stiff-seabed chain (tests/data/stiff_seabed_chain.toml, scripts/stiff_chain.py): hawser
     `scheme = "auto"` against MoorDyn RK2 at its largest stable dtM, CPU per run (target
     >= 20x) and the top tension's cycle maxima against the converged RK4 reference (target
     within 0.5 %).
  6. OC3 at each code's best step: the largest step at which each code's line-1 fairlead
     tension maximum and minimum (sampled every 0.1 s over the run) stay within 0.5 % of its
     own run at a step 8x shorter (MoorDyn RK2 on its deck; hawser RK4, lumped, on the same
     deck), and the paired CPU per simulated second at those steps.
  7. The fast defaults: `scheme = "auto"` on the README example (examples/catenary_mooring.toml,
     60 s; target >= 100x real time per CPU second) and on OC3 (examples/oc3_surge.toml, 300 s,
     automatic step, tolerance 1e-3; target >= 4000x), every fairlead tension's maximum and
     minimum within 0.5 % of RK4 at a quarter of its default step (safety factor 0.2).
  8. The parameter sweep: `hawser sweep` of 6 cases of the README example with --jobs 1 and 2,
     cases per CPU second (per core) and per wall second (as scripts/sweep_scaling.sh).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import types

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import moordyn_bench as mb  # noqa: E402
import stiff_chain as sc  # noqa: E402

# run_once times its stepping loop with time.perf_counter: make that this process's CPU time.
mb.time = types.SimpleNamespace(perf_counter=time.process_time)

DECK = os.path.join(ROOT, "tests", "data", "moordyn", "oc3_lines.txt")
OC3 = os.path.join(ROOT, "examples", "oc3_surge.toml")


def hawser_bench(hawser, args):
    """`hawser bench ARGS --json`, parsed: the list of runs."""
    out = subprocess.run([hawser, "bench", *args, "--json"], check=True,
                         capture_output=True, text=True).stdout
    data = json.loads(out)
    return data["runs"] if isinstance(data, dict) else data


def moordyn_loop_cpu(path, x0, dt, duration):
    """CPU seconds of MoorDyn's stepping loop over `duration` at dtM `dt` (surge 2 m, 10 s)."""
    import moordyn
    import cmoordyn

    console = os.path.join(os.path.dirname(path), "console.txt")
    res = mb.run_once(moordyn, cmoordyn, path, x0, dt, 0.1, duration, 2.0, 10.0, console, False)
    return res["wall_s"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--hawser", default=os.path.join(ROOT, "target", "release", "hawser"))
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--duration", type=float, default=20.0, help="OC3 simulated time [s]")
    p.add_argument("--hawser-dt", type=float, default=0.005,
                   help="hawser's step for the second OC3 comparison [s] (5 ms: its FairTen1 "
                   "minimum, maximum and mean within 0.02 %% of its 2 ms run, BENCHMARKS.md)")
    p.add_argument("--segments", default="20,40,80,160,320,640,1280")
    p.add_argument("--chain-duration", type=float, default=1.0,
                   help="1000 m chain simulated time [s]")
    p.add_argument("--stiff-dtm", type=float, default=sc.MOORDYN_LARGEST_STABLE_DTM,
                   help="MoorDyn's dtM for the stiff-seabed chain [s] (default: its largest "
                   "stable step, `scripts/stiff_chain.py bisect`)")
    parts = ["oc3", "waves", "chain", "stiff", "best", "defaults", "sweep"]
    p.add_argument("--only", default=",".join(parts),
                   help="comma-separated parts to run (default: all): oc3 (1-2), waves (3), "
                   "chain (4), stiff (5), best (6), defaults (7), sweep (8)")
    p.add_argument("--record", action="store_true",
                   help="also write what this run prints into BENCHMARKS.md, as its section "
                   "\"Last recorded run\" (replacing the one before), with the command, the "
                   "date, the commit and the load")
    a = p.parse_args()
    only = set(a.only.split(","))
    if not only <= set(parts):
        p.error(f"--only: unknown part(s) {sorted(only - set(parts))}; expected {parts}")
    from importlib.metadata import version

    tee = Tee(sys.stdout)
    sys.stdout = tee
    tmp = tempfile.mkdtemp(prefix="bench-all-")
    surge = os.path.join(tmp, "surge.txt")
    with open(surge, "w") as f:
        for i in range(int(round((a.duration + 10.0) / 0.1)) + 1):
            t = 0.1 * i
            f.write(f"{t:.1f} {2.0 * math.sin(2 * math.pi * t / 10.0):.12f} 0 0 0 0 0\n")
    with open(DECK, encoding="utf-8") as fh:
        src = fh.read().splitlines()
    md_deck, _, _ = mb.prepare_deck(src, os.path.join(tmp, "moordyn"), 0.002, None, False)
    x0 = [c for _, xyz in mb.coupled_points_from_deck(src) for c in xyz]
    md_steps = int(round(a.duration / 0.002))
    nodes = 63

    load = os.getloadavg()[0]
    print(f"hawser bench vs MoorDyn {version('moordyn')} (RK2), paired CPU time, median of "
          f"{a.repeats} pairs; load average at start {load:.1f} on {os.cpu_count()} cores")

    if "oc3" in only:
        oc3_same_step(a, md_deck, x0, surge, md_steps, nodes)
    if "waves" in only:
        waves(a)
    if "chain" in only:
        chain(a, tmp)
    if "stiff" in only:
        stiff(a, tmp)
    if "best" in only:
        best_steps(a, tmp, surge, src, x0)
    if "defaults" in only:
        fast_defaults(a, tmp)
    if "sweep" in only:
        sweep(a, tmp)
    sys.stdout = tee.out
    if a.record:
        record(sys.argv[1:], "".join(tee.text), load)


def oc3_same_step(a, md_deck, x0, surge, md_steps, nodes):
    """1-2. OC3 at the same step, and hawser at --hawser-dt against MoorDyn at 2 ms."""
    # 1-2. OC3 at the same step and at hawser's automatic step.
    same, auto, md = [], [], []
    for _ in range(a.repeats):
        md.append(moordyn_loop_cpu(md_deck, x0, 0.002, a.duration))
        base = [DECK, "--vessel-motion", surge, "--duration", str(a.duration), "--mass", "lumped"]
        same.append(hawser_bench(a.hawser, base + ["--dt", "0.002"])[0])
        auto.append(hawser_bench(a.hawser, base + ["--dt", str(a.hawser_dt)])[0])
    md_step = [c / md_steps for c in md]
    h_step = [r["cpu_s"] / r["steps"] for r in same]
    ratio_same = statistics.median(m / h for m, h in zip(md_step, h_step))
    ns = statistics.median(nodes * r["steps"] / r["cpu_s"] for r in same)
    print("\nOC3 deck (3 x 20 segments, 63 nodes, surge 2 m / 10 s), "
          f"{a.duration:g} s simulated")
    print(f"  MoorDyn RK2 dt 2 ms: {statistics.median(md_step) * 1e6:.1f} us CPU per step, "
          f"{nodes / statistics.median(md_step):.3e} node-steps per CPU s")
    print(f"  hawser RK4 lumped dt 2 ms: {statistics.median(h_step) * 1e6:.1f} us CPU per step, "
          f"{ns:.3e} node-steps per CPU s (element loop on "
          f"{same[0].get('instruction_set', 'an unreported instruction set')})")
    print(f"  target: hawser >= 1.0e7 node-steps per CPU s (RK4, lumped): {ns:.3e} "
          f"[{'met' if ns >= 1e7 else 'NOT met'}]")
    print(f"  target: MoorDyn CPU per step / hawser's >= 2 at the same step: {ratio_same:.2f} "
          f"[{'met' if ratio_same >= 2 else 'NOT met'}]")
    ratio_auto = statistics.median(m / r["cpu_s"] for m, r in zip(md, auto))
    print(f"  hawser RK4 at {auto[0]['time_step']:.3e} s (its stable limit "
          f"{auto[0]['stable_step']:.3e} s) against MoorDyn RK2 at dtM 2 ms, CPU per simulated "
          f"second MoorDyn / hawser: {ratio_auto:.2f} (each code's step for 0.5 % accuracy is "
          "not searched here)")



def waves(a):
    """3. OC3 in a 200-component JONSWAP sea against still water."""
    runs = [hawser_bench(a.hawser, [OC3, "--waves", "still,jonswap:200:6:10", "--kinematics",
                                    "both", "--mass", "lumped", "--scheme", "rk4", "--dt",
                                    "0.002", "--duration", "4", "--repeat", str(a.repeats)])]
    print("\nOC3 in JONSWAP Hs 6 m, Tp 10 s, 200 components (hawser bench --waves, 4 s, "
          "paired CPU ratio to still water, median over repeats)")
    for r in runs[0]:
        if r["waves"] == "still":
            continue
        extra = ""
        if r.get("wave_table_bytes"):
            extra = f", cache {r['wave_table_bytes'] / 1e3:.0f} kB"
        line = f"  {r['kinematics']}: {r['cpu_ratio_to_still']:.2f}x still water{extra}"
        if r["kinematics"] == "static-position":
            ok = r["cpu_ratio_to_still"] <= 3.0
            line += f"  target <= 3x: [{'met' if ok else 'NOT met'}]"
        print(line)



def chain(a, tmp):
    """4. The 1000 m chain at 20 to 1280 segments."""
    print("\n1000 m chain (the OC3 chain, one line, anchor to a fairlead in the 2 m / 10 s "
          f"surge), automatic step, {a.chain_duration:g} s simulated, best of {a.repeats}")
    print(f"  {'segments':>8} {'dt [s]':>10} {'ns/node-step':>13} {'CPU s per simulated s':>22}")
    with open(OC3, encoding="utf-8") as fh:
        oc3 = fh.read()
    head = oc3.split("[[points]]")[0]
    for n in [int(s) for s in a.segments.split(",")]:
        path = os.path.join(tmp, f"chain_{n}.toml")
        with open(path, "w") as f:
            f.write(head.replace("time_step = 0.002", 'time_step = "auto"'))
            f.write('[[points]]\nname = "anchor"\ntype = "fixed"\n'
                    "position = [853.87, 0.0, -320.0]\n\n")
            f.write('[[points]]\nname = "fairlead"\ntype = "prescribed"\n'
                    "position = [5.2, 0.0, -70.0]\n"
                    'motion = { type = "sinusoid", amplitude = [2.0, 0.0, 0.0], period = 10.0 }\n\n')
            f.write(f'[[lines]]\nname = "L1"\nend_a = "anchor"\nend_b = "fairlead"\n'
                    f'type = "chain"\nlength = 1000.0\nelements = {n}\n')
        r = hawser_bench(a.hawser, [path, "--duration", str(a.chain_duration), "--mass",
                                    "lumped", "--repeat", str(a.repeats)])[0]
        per_node_step = r["cpu_s"] / (r["nodes"] * r["steps"])
        print(f"  {n:>8} {r['time_step']:>10.3e} {per_node_step * 1e9:>13.0f} "
              f"{r['cpu_s'] / r['duration']:>22.3e}")



def stiff(a, tmp):
    """The stiff-seabed chain: paired CPU ratio MoorDyn RK2 / hawser auto, and the maxima."""
    path = sc.write(tmp, "stiff_auto.toml", sc.scenario_text())
    t, v, stats = sc.hawser_series(a.hawser, path, tmp)
    err = sc.worst_error(sc.cycle_maxima(t, v), sc.REFERENCE_MAXIMA)
    md_t, md_v, _ = sc.moordyn_run(tmp, a.stiff_dtm)
    md_err = sc.worst_error(sc.cycle_maxima(md_t, md_v), sc.REFERENCE_MAXIMA)
    pairs = []
    for _ in range(a.repeats):
        _, _, md = sc.moordyn_run(tmp, a.stiff_dtm)
        h = sc.hawser_bench(a.hawser, path)
        pairs.append((md, h))
    ratio = statistics.median(m / h["cpu_s"] for m, h in pairs)
    print("\nStiff-seabed chain (33 m, 165 segments, seabed 1.8e9 Pa/m critically damped, top "
          f"on a 0.2 m / 1.25 s vertical circle, {sc.DURATION:g} s simulated)")
    print(f"  MoorDyn RK2 dtM {a.stiff_dtm:.3e} s: CPU {statistics.median(m for m, _ in pairs):.3f}"
          f" s, cycle maxima within {md_err * 100:.3f} % of the RK4 reference")
    print(f"  hawser auto ({sc.scheme_label(pairs[0][1])}): CPU "
          f"{statistics.median(h['cpu_s'] for _, h in pairs):.3f} s, {stats or 'explicit'}")
    print(f"  target: MoorDyn CPU / hawser auto's >= 20: {ratio:.2f} "
          f"[{'met' if ratio >= 20 else 'NOT met'}]")
    print(f"  target: hawser auto's cycle maxima within 0.5 % of the RK4 reference: "
          f"{err * 100:.3f} % [{'met' if err <= 5e-3 else 'NOT met'}]")


def extremes_error(value, reference):
    """Worst relative difference of the (max, min) pairs in `value` from `reference`."""
    return max(abs(v - r) / abs(r) for v, r in zip(value, reference))


def best_steps(a, tmp, surge, src, x0):
    """6. The largest step of each code within 0.5 % of its own run at a step 8x shorter
    (line 1's fairlead tension maximum and minimum), and the paired CPU at those steps."""
    print(f"\nOC3 deck at each code's best step: the largest step with line 1's fairlead tension "
          f"maximum and minimum within 0.5 % of the code's own run at a step 8x shorter, "
          f"{a.duration:g} s")

    def moordyn_extremes(dt):
        deck, _, _ = mb.prepare_deck(src, os.path.join(tmp, f"md_{dt:.6f}"), dt, None, False)
        console = os.path.join(tmp, f"md_{dt:.6f}", "console.txt")
        import moordyn
        import cmoordyn
        try:
            r = mb.run_once(moordyn, cmoordyn, deck, x0, dt, 0.1, a.duration, 2.0, 10.0,
                            console, False)
        except (SystemExit, RuntimeError, ValueError):
            return None, deck
        v = r["ten1"]
        if not all(math.isfinite(x) for x in v):
            return None, deck
        return (max(v), min(v)), deck

    def hawser_extremes(dt):
        deck, _, _ = mb.prepare_deck(src, os.path.join(tmp, f"hw_{dt:.6f}"), dt, None, True)
        out = os.path.join(tmp, f"hw_{dt:.6f}", "out")
        run = subprocess.run([a.hawser, "run", deck, "--vessel-motion", surge, "--duration",
                              str(a.duration), "--out", out, "--quiet", "--overwrite"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            return None, deck
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as fh:
            ch = json.load(fh)["channels"]["FairTen1"]
        return (ch["max"], ch["min"]), deck

    # Steps that divide the 0.1 s output and coupling interval, so that every code samples
    # its tension at the same instants at every step (steps that do not divide it sample
    # between steps, which moved hawser's minimum by 0.3 % at 3 ms).
    ladder = [0.1 / n for n in (100, 50, 40, 25, 20, 16, 14, 12, 10)]
    limit = hawser_bench(a.hawser, [DECK, "--vessel-motion", surge, "--duration", "0.1",
                                    "--mass", "lumped"])[0]["stable_step"]
    best = {}
    for code, extremes, steps in [
        ("MoorDyn RK2", moordyn_extremes, ladder),
        ("hawser RK4 lumped", hawser_extremes, [s for s in ladder if s <= limit]),
    ]:
        ref, _ = extremes(steps[0] / 8)
        print(f"  {code} dt {steps[0] / 8 * 1e3:.3f} ms (the reference): max {ref[0]:.1f} N, "
              f"min {ref[1]:.1f} N")
        found = None
        for dt in steps:
            e, deck = extremes(dt)
            err = extremes_error(e, ref) if e else float("inf")
            print(f"  {code} dt {dt * 1e3:.3f} ms: "
                  + (f"max {e[0]:.1f} N, min {e[1]:.1f} N, {err * 100:.3f} % from dt/8"
                     if e else "diverged"))
            if err > 5e-3:
                break
            found = (dt, deck)
        best[code] = found
    md_dt, md_deck = best["MoorDyn RK2"]
    h_dt, _ = best["hawser RK4 lumped"]
    pairs = []
    for _ in range(a.repeats):
        m = moordyn_loop_cpu(md_deck, x0, md_dt, a.duration)
        h = hawser_bench(a.hawser, [DECK, "--vessel-motion", surge, "--duration", str(a.duration),
                                    "--mass", "lumped", "--dt", str(h_dt)])[0]["cpu_s"]
        pairs.append((m, h))
    ratio = statistics.median(m / h for m, h in pairs)
    print(f"  best steps: MoorDyn {md_dt * 1e3:.3f} ms, hawser {h_dt * 1e3:.3f} ms (its stable "
          f"limit {limit * 1e3:.3f} ms); CPU per simulated second MoorDyn / hawser: {ratio:.2f} "
          f"(MoorDyn {statistics.median(m for m, _ in pairs):.3f} s, hawser "
          f"{statistics.median(h for _, h in pairs):.3f} s)")


def simulation_variant(text, **keys):
    """`text` with the `[simulation]` keys given replaced or added (TOML values as Python
    values: str quoted, numbers as they print)."""
    lines = text.splitlines()
    start = lines.index("[simulation]")
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("[")), len(lines))
    kept = [ln for ln in lines[start + 1:end]
            if ln.split("=")[0].strip() not in keys]
    new = [f"{k} = {json.dumps(v) if isinstance(v, str) else repr(v)}" for k, v in keys.items()]
    return "\n".join(lines[:start + 1] + new + kept + lines[end:]) + "\n"


def fairlead_extremes(hawser, path, out):
    """`hawser run`: (channel, max, min) of every line's end-B tension (the fairleads)."""
    subprocess.run([hawser, "run", path, "--out", out, "--quiet", "--overwrite"], check=True,
                   capture_output=True, text=True)
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as fh:
        ch = json.load(fh)["channels"]
    return {k: (v["max"], v["min"]) for k, v in ch.items() if k.endswith(".end_b.tension")}


def fast_defaults(a, tmp):
    """7. `scheme = "auto"` on the README example and OC3: real time per CPU second and the
    fairlead tension extremes against RK4 at safety factor 0.2."""
    cases = [
        ("README example", os.path.join(ROOT, "examples", "catenary_mooring.toml"), {}, 100.0),
        ("OC3, 300 s", OC3, {"duration": 300.0, "time_step": "auto", "tolerance": 1e-3},
         4000.0),
    ]
    print("\nThe fast defaults: scheme = \"auto\" against RK4 at safety factor 0.2 (extremes of "
          "every fairlead tension), real time per CPU second (hawser bench, consistent mass, "
          f"best of {a.repeats})")
    for name, path, keys, target in cases:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        auto = os.path.join(tmp, f"auto_{os.path.basename(path)}")
        ref = os.path.join(tmp, f"ref_{os.path.basename(path)}")
        with open(auto, "w", encoding="utf-8") as fh:
            fh.write(simulation_variant(text, scheme="auto", **keys))
        ref_keys = {**keys, "scheme": "rk4", "time_step": "auto", "safety_factor": 0.2}
        ref_keys.pop("tolerance", None)
        with open(ref, "w", encoding="utf-8") as fh:
            fh.write(simulation_variant(text, **ref_keys))
        e_auto = fairlead_extremes(a.hawser, auto, auto + ".out")
        e_ref = fairlead_extremes(a.hawser, ref, ref + ".out")
        worst = max(((extremes_error(e_auto[k], e_ref[k]), k) for k in e_ref))
        r = hawser_bench(a.hawser, [auto, "--mass", "consistent", "--repeat", str(a.repeats)])[0]
        rtf = r["duration"] / r["cpu_s"]
        print(f"  {name}: auto chose {r['scheme']}, {r['steps']} steps, CPU {r['cpu_s']:.3f} s, "
              f"{rtf:.0f}x real time; worst fairlead extreme {worst[0] * 100:.3f} % ({worst[1]})")
        print(f"  target: >= {target:.0f}x real time per CPU second: {rtf:.0f}x "
              f"[{'met' if rtf >= target else 'NOT met'}]; extremes within 0.5 %: "
              f"{worst[0] * 100:.3f} % [{'met' if worst[0] <= 5e-3 else 'NOT met'}]")


def sweep(a, tmp):
    """8. `hawser sweep` of 6 cases with --jobs 1 and 2: CPU (all threads, from the children's
    rusage) and wall time, medians over the repeats, alternating."""
    cases = os.path.join(tmp, "cases.csv")
    with open(cases, "w", encoding="utf-8") as fh:
        fh.write("simulation.duration,statistics.start,points.fairlead.motion.amplitude\n")
        for k in range(1, 7):
            fh.write(f'6.0,0.0,"[{k}.0, 0.0, 0.0]"\n')
    base = os.path.join(ROOT, "examples", "catenary_mooring.toml")
    runs = {1: [], 2: []}
    for _ in range(a.repeats):
        for jobs in (1, 2):
            out = os.path.join(tmp, f"sweep_{jobs}")
            shutil.rmtree(out, ignore_errors=True)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            subprocess.run([a.hawser, "sweep", base, cases, "--out", out, "--jobs", str(jobs),
                            "--quiet", "--overwrite"], check=True, capture_output=True)
            wall = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            runs[jobs].append((cpu, wall))
    print(f"\nhawser sweep: 6 cases x 6 s of the README example, median of {a.repeats}; load "
          f"average now {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    cpu1 = statistics.median(c for c, _ in runs[1])
    for jobs in (1, 2):
        cpu = statistics.median(c for c, _ in runs[jobs])
        wall = statistics.median(w for _, w in runs[jobs])
        print(f"  --jobs {jobs}: CPU {cpu:.2f} s ({6 / cpu:.3f} cases per CPU second, per core), "
              f"wall {wall:.2f} s ({6 / wall:.3f} cases per wall second), CPU ratio to --jobs 1 "
              f"{cpu / cpu1:.3f}")


class Tee:
    """Standard output that also keeps what was written (for `--record`)."""

    def __init__(self, out):
        self.out, self.text = out, []

    def write(self, text):
        self.text.append(text)
        return self.out.write(text)

    def flush(self):
        self.out.flush()


BEGIN = "<!-- bench_all.py --record: begin (written by the script; edit the script, not this) -->"
END = "<!-- bench_all.py --record: end -->"


def record(argv, text, load, path=os.path.join(ROOT, "BENCHMARKS.md")):
    """Writes `text`, a run's printed targets, into BENCHMARKS.md between BEGIN and END (the
    section before the first `## ` heading after the targets table when there is none yet)."""
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    block = "\n".join([
        BEGIN,
        "### Last recorded run",
        "",
        f"`python3 scripts/bench_all.py {' '.join(argv)}` on {when}, commit {commit}"
        f"{' with uncommitted changes' if dirty else ''}, load average {load:.1f} at the start "
        f"on {os.cpu_count()} cores: what it printed.",
        "",
        "```text",
        text.strip("\n"),
        "```",
        END,
    ])
    with open(path, encoding="utf-8") as fh:
        doc = fh.read()
    if BEGIN in doc and END in doc:
        doc = doc[:doc.index(BEGIN)] + block + doc[doc.index(END) + len(END):]
    else:
        at = doc.index("\n## ", doc.index("## All targets in one run"))
        doc = doc[:at] + "\n\n" + block + "\n" + doc[at:]
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(doc)
    print(f"recorded in {path}")


if __name__ == "__main__":
    main()
