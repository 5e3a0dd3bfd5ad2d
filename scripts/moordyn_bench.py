#!/usr/bin/env python3
"""MoorDyn side of the hawser-vs-MoorDyn throughput benchmark.

Drives every coupled point ("fairlead") of a MoorDyn deck in surge,

    x(t) = x0 + A sin(2 pi t / T),   xdot(t) = A (2 pi / T) cos(2 pi t / T),

through the MoorDyn-C Python bindings (PyPI package ``moordyn``) and measures
the wall time of the stepping loop only (time.perf_counter around the loop of
moordyn.Step calls; creation, initial-condition solve and kinematics
precomputation are outside the timed region).

Usage:
    python scripts/moordyn_bench.py --deck PATH --dt 0.002 --duration 60 \
        --amplitude 2 --period 10 [--json]

What is run (each configuration ``--repeats`` times on a fresh instance; the
best wall time is reported, all times are kept in the JSON):

  * coupling step = --coupling-dt (default 0.1 s, MoorDyn's typical coupling
    interval; MoorDyn sub-steps it internally with dtM = --dt, i.e. 50 internal
    steps per moordyn.Step call at dt = 0.002).  This minimises Python-call
    overhead and is the HEADLINE number.
  * coupling step = --dt (one internal step per moordyn.Step call): shows the
    Python-call overhead; its tension record is the finest for accuracy work.

  Both with the deck's file outputs stripped (per-line node outputs and output
  channels removed in the temp copy, so the timing is the solver, not disk
  I/O).  With --outputs both (default) the two configurations are repeated
  with the deck's outputs kept, as extra rows.

Semantics of moordyn.Step(system, x, xd, t, dt) in MoorDyn-C v2: x and xd are
the coupled-point positions/velocities at the START of the coupling interval
[t, t+dt]; MoorDyn moves the points as x + xd (tau - t) inside it.  So the
kinematics passed for call i are x(t_i), xdot(t_i) with t_i = i * coupling.

Node counts: nodes = sum over lines of (segments + 1) (63 for the OC3 deck),
internal nodes = sum of (segments - 1) (57).  node-steps/s = nodes * internal
time steps / wall; node-evaluations/s = node-steps/s * right-hand-side
evaluations per time step (2 for MoorDyn's default RK2, the midpoint rule).
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import math
import os
import platform
import re
import shutil
import statistics
import sys
import tempfile
import time

# Right-hand-side (CalcStateDeriv) evaluations per internal time step of the
# explicit MoorDyn-C v2 time schemes, keyed by the name MoorDyn reports.
RHS_EVALS = {
    "1st order Euler": 1,
    "1st order Local-Timestep Euler": 1,
    "2nd order Heun": 1,  # predictor uses the previous derivative
    "2nd order Runge-Kutta": 2,  # midpoint rule
    "4th order Runge-Kutta": 4,
    "2nd order Adams-Bashforth": 1,
    "3rd order Adams-Bashforth": 1,
    "4th order Adams-Bashforth": 1,
}

COUPLED_TYPES = ("COUPLED", "CPLD", "VESSEL", "VES", "FAIRLEAD")


def default_deck() -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(
        os.path.join(here, "..", "..", "shared", "moordyn-decks", "oc3_lines.txt")
    )


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--deck", default=default_deck(), help="MoorDyn input file")
    p.add_argument("--dt", type=float, default=0.002, help="MoorDyn dtM (s)")
    p.add_argument("--duration", type=float, default=60.0, help="simulated time (s)")
    p.add_argument("--amplitude", type=float, default=2.0, help="surge amplitude A (m)")
    p.add_argument("--period", type=float, default=10.0, help="surge period T (s)")
    p.add_argument(
        "--coupling-dt",
        type=float,
        default=0.1,
        help="coupling interval of the headline run (s); default 0.1",
    )
    p.add_argument(
        "--scheme",
        default=None,
        help="set the deck's tScheme option in the copy (e.g. RK2, RK4, Euler, "
        "Heun); default: leave the deck alone (MoorDyn's default is RK2)",
    )
    p.add_argument(
        "--outputs",
        choices=("none", "deck", "both"),
        default="both",
        help="none: strip the deck's file outputs (timed headline); deck: keep "
        "them; both (default): headline without, extra rows with",
    )
    p.add_argument("--repeats", type=int, default=3, help="runs per configuration")
    p.add_argument("--keep-tmp", action="store_true", help="keep the temp dir")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    return p.parse_args(argv)


# --------------------------------------------------------------------------
# deck handling


def read_deck(path):
    with open(path, "r", encoding="utf-8", errors="replace") as fh:
        return fh.read().splitlines()


def find_section(lines, names):
    """Index of the header line of the first section whose title contains one
    of ``names`` (MoorDyn section headers are '---- TITLE ----' lines)."""
    for i, line in enumerate(lines):
        if "---" in line and any(n in line.upper() for n in names):
            return i
    return -1


def section_rows(lines, start, skip):
    """Indices of the rows of the section starting at header ``start``,
    after ``skip`` column-name/unit lines, until the next '---' line."""
    out = []
    i = start + 1 + skip
    while i < len(lines) and "---" not in lines[i]:
        if lines[i].strip():
            out.append(i)
        i += 1
    return out


def coupled_points_from_deck(lines):
    """[(id, (x, y, z))] of the coupled points, in deck order (MoorDyn orders
    the coupled DOFs of points in the order they appear)."""
    hdr = find_section(
        lines, ("POINT", "CONNECTION PROPERTIES", "NODE PROPERTIES")
    )
    if hdr < 0:
        raise SystemExit("no POINTS section in the deck")
    pts = []
    for i in section_rows(lines, hdr, 2):
        f = lines[i].split()
        if len(f) < 5:
            continue
        kind = re.match(r"[A-Za-z]*", f[1]).group(0).upper()
        if kind in COUPLED_TYPES:
            pts.append((int(f[0]), (float(f[2]), float(f[3]), float(f[4]))))
    return pts


def set_option(lines, name, value):
    """Set option ``name`` (case-insensitive) in the OPTIONS section, adding it
    if absent.  Returns the old value or None."""
    hdr = find_section(lines, ("OPTIONS",))
    if hdr < 0:
        raise SystemExit("no OPTIONS section in the deck")
    i = hdr + 1
    while i < len(lines) and "---" not in lines[i]:
        f = lines[i].split()
        if len(f) >= 2 and f[1].lower() == name.lower():
            old = f[0]
            lines[i] = "%-13s %s" % (value, " ".join(f[1:]))
            return old
        i += 1
    lines.insert(i, "%-13s %s" % (value, name))
    return None


def strip_outputs(lines):
    """Disable file outputs: line output flags -> '-', output channel list
    emptied (MoorDyn then writes only the Time column of the main .out)."""
    hdr = find_section(lines, ("LINES", "LINE LIST", "LINE PROPERTIES"))
    if hdr >= 0:
        for i in section_rows(lines, hdr, 2):
            f = lines[i].split()
            if len(f) >= 7:
                f[6] = "-"
                lines[i] = "  ".join(f)
    hdr = find_section(lines, ("OUTPUT",))
    if hdr >= 0:
        i = hdr + 1
        while i < len(lines) and "---" not in lines[i]:
            if lines[i].strip() and lines[i].strip().upper() != "END":
                del lines[i]
                continue
            i += 1


def prepare_deck(src_lines, dst_dir, dt, scheme, keep_outputs):
    lines = list(src_lines)
    old_dt = set_option(lines, "dtM", repr(dt))
    old_scheme = None
    if scheme:
        old_scheme = set_option(lines, "tScheme", scheme)
    if not keep_outputs:
        strip_outputs(lines)
    os.makedirs(dst_dir, exist_ok=True)
    path = os.path.join(dst_dir, "lines.txt")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(lines) + "\n")
    return path, old_dt, old_scheme


# --------------------------------------------------------------------------
# MoorDyn console output goes to the process's fd 1: send it to a file so
# --json output stays clean and the table is readable.


@contextlib.contextmanager
def redirect_fd1(path):
    sys.stdout.flush()
    saved = os.dup(1)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    try:
        os.dup2(fd, 1)
        yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(fd)
        os.close(saved)


def internal_steps(coupling, dtm):
    """Replicates MoorDyn-C v2's sub-stepping loop in MoorDyn::Step
    (t_target = dt; while t_target > 0: h = min(dtM, t_target); ...) in
    doubles: returns (number of internal steps, shortest step)."""
    t_target = coupling
    n = 0
    hmin = dtm
    while t_target > 0.0:
        h = dtm if dtm < t_target else t_target
        t_target -= h
        hmin = min(hmin, h)
        n += 1
    return n, hmin


def last_time_in_out(path):
    """Last Time value of MoorDyn's main .out file (None if unreadable)."""
    try:
        with open(path, "r") as fh:
            rows = [r for r in fh.read().splitlines() if r.strip()]
        return float(rows[-1].split()[0])
    except (OSError, ValueError, IndexError):
        return None


def log_ic_summary(log_path):
    """IC-generation lines of MoorDyn's log (method and residual)."""
    out = []
    try:
        with open(log_path, "r", errors="replace") as fh:
            for line in fh:
                s = line.strip()
                if s.startswith(("Finalizing ICs", "Remaining error", "Best score",
                                 "Fairlead tensions", "dtM =", "Time integrator")):
                    out.append(s)
    except OSError:
        pass
    return out


def norm(v):
    return math.sqrt(sum(c * c for c in v))


# --------------------------------------------------------------------------


def run_once(moordyn, cmoordyn, deck_path, x0, dt, coupling, duration, amp, period,
             console, want_statics):
    """One Create/Init/step-loop/Close cycle.  Returns a dict."""
    n_cpl = len(x0) // 3
    n_calls = int(round(duration / coupling))
    if abs(n_calls * coupling - duration) > 1e-9 * max(1.0, duration):
        raise SystemExit(
            "duration %g is not a multiple of the coupling step %g" % (duration, coupling)
        )
    omega = 2.0 * math.pi / period
    # Precompute the kinematics (outside the timed loop): start-of-interval
    # positions and velocities for every call.
    xs, vs, ts = [], [], []
    for i in range(n_calls):
        t = i * coupling
        s, c = math.sin(omega * t), math.cos(omega * t)
        x = list(x0)
        v = [0.0] * len(x0)
        for k in range(n_cpl):
            x[3 * k] = x0[3 * k] + amp * s
            v[3 * k] = amp * omega * c
        xs.append(x)
        vs.append(v)
        ts.append(t)

    res = {}
    with redirect_fd1(console):
        system = moordyn.Create(deck_path)
        ndof = moordyn.NCoupledDOF(system)
        if ndof != len(x0):
            raise SystemExit(
                "deck has %d coupled DOFs but %d coupled points were found; only "
                "decks whose coupled objects are points are supported" % (ndof, n_cpl)
            )
        res["time_scheme"] = cmoordyn.get_tscheme(system)
        res["dtM"] = cmoordyn.get_dt(system)
        t0 = time.perf_counter()
        err = moordyn.Init(system, x0, [0.0] * len(x0))
        res["init_wall_s"] = time.perf_counter() - t0
        if err:
            raise SystemExit("moordyn.Init failed with code %d (see %s)" % (err, console))
        n_lines = moordyn.GetNumberLines(system)
        lines = [moordyn.GetLine(system, i) for i in range(1, n_lines + 1)]
        segs = [moordyn.GetLineN(l) for l in lines]
        res["segments"] = segs

        if want_statics:
            # Step with dt = 0 only returns the coupled-point forces.
            f0 = moordyn.Step(system, x0, [0.0] * len(x0), 0.0, 0.0)
            st = []
            for j, l in enumerate(lines):
                top = moordyn.GetLineNodeTen(l, segs[j])
                bot = moordyn.GetLineNodeTen(l, 0)
                st.append({
                    "line": moordyn.GetLineID(l),
                    "fairlead_tension_N": moordyn.GetLineFairTen(l),
                    "fairlead_tension_vec_N": list(top),
                    "fairlead_H_N": math.hypot(top[0], top[1]),
                    "fairlead_V_N": abs(top[2]),
                    "anchor_tension_N": norm(bot),
                    "fairlead_node_pos_m": list(moordyn.GetLineNodePos(l, segs[j])),
                })
            pf = []
            for k in range(n_cpl):
                fv = f0[3 * k:3 * k + 3]
                pf.append({"force_vec_N": list(fv), "magnitude_N": norm(fv)})
            fh, fv_, ah, av = moordyn.GetFASTtens(system, n_lines)
            res["statics"] = {
                "lines": st,
                "coupled_point_forces": pf,
                "GetFASTtens": {
                    "fairlead_H_N": list(fh), "fairlead_V_N": list(fv_),
                    "anchor_H_N": list(ah), "anchor_V_N": list(av),
                },
            }

        step = moordyn.Step
        fair_ten = moordyn.GetLineFairTen
        line1 = lines[0]
        ten1 = [0.0] * n_calls
        forces = [None] * n_calls
        t0 = time.perf_counter()
        for i in range(n_calls):
            forces[i] = step(system, xs[i], vs[i], ts[i], coupling)
            ten1[i] = fair_ten(line1)
        wall = time.perf_counter() - t0

        res["wall_s"] = wall
        res["final_fairlead_tension_N"] = [fair_ten(l) for l in lines]
        res["final_coupled_point_force_N"] = [
            norm(forces[-1][3 * k:3 * k + 3]) for k in range(n_cpl)
        ]
        res["n_calls"] = n_calls
        res["ten1"] = ten1
        res["pf1"] = [norm(f[0:3]) for f in forces]
        moordyn.Close(system)
    return res


def stats(values, coupling):
    i_min = min(range(len(values)), key=values.__getitem__)
    i_max = max(range(len(values)), key=values.__getitem__)
    return {
        "min_N": values[i_min],
        "t_min_s": round((i_min + 1) * coupling, 9),
        "max_N": values[i_max],
        "t_max_s": round((i_max + 1) * coupling, 9),
        "mean_N": sum(values) / len(values),
        "samples": len(values),
        "sampled_every_s": coupling,
    }


def main(argv=None):
    a = parse_args(argv)
    try:
        import moordyn
        import cmoordyn
    except ImportError as e:
        raise SystemExit("cannot import moordyn (pip install moordyn): %s" % e)
    try:
        from importlib.metadata import version

        md_version = version("moordyn")
    except Exception:
        md_version = "unknown"

    if a.dt <= 0 or a.duration <= 0 or a.period <= 0 or a.coupling_dt <= 0:
        raise SystemExit("dt, duration, period and coupling-dt must be positive")
    deck = os.path.abspath(a.deck)
    src = read_deck(deck)
    with open(deck, "rb") as fh:
        deck_sha = hashlib.sha256(fh.read()).hexdigest()
    cpl = coupled_points_from_deck(src)
    if not cpl:
        raise SystemExit("the deck has no coupled points")
    x0 = [c for _, p in cpl for c in p]

    tmp = tempfile.mkdtemp(prefix="moordyn-bench-")
    console = os.path.join(tmp, "moordyn_console.txt")

    configs = []  # (label, coupling, keep_outputs)
    variants = {"none": [False], "deck": [True], "both": [False, True]}[a.outputs]
    for keep in variants:
        suffix = ", deck outputs" if keep else ""
        configs.append(("coupling %gs%s" % (a.coupling_dt, suffix), a.coupling_dt, keep))
        if abs(a.coupling_dt - a.dt) > 1e-15:
            configs.append(("coupling = dt%s" % suffix, a.dt, keep))
    headline = configs[0][0]

    runs = []
    statics = None
    meta = None
    try:
        for ci, (label, coupling, keep) in enumerate(configs):
            d = os.path.join(tmp, "run%d" % ci)
            deck_copy, old_dt, old_scheme = prepare_deck(src, d, a.dt, a.scheme, keep)
            walls = []
            first = None
            for r in range(max(1, a.repeats)):
                res = run_once(moordyn, cmoordyn, deck_copy, x0, a.dt, coupling,
                               a.duration, a.amplitude, a.period, console,
                               want_statics=(statics is None))
                if statics is None:
                    statics = res.pop("statics")
                    meta = {
                        "time_scheme": res["time_scheme"],
                        "dtM": res["dtM"],
                        "segments": res["segments"],
                        "deck_dtM_before_override": old_dt,
                        "deck_tScheme_before_override": old_scheme,
                        "ic_log": log_ic_summary(os.path.join(d, "lines.log")),
                        "init_wall_s": res["init_wall_s"],
                    }
                walls.append(res["wall_s"])
                if first is None:
                    first = res
            segs = first["segments"]
            nodes = sum(n + 1 for n in segs)
            inodes = sum(n - 1 for n in segs)
            n_int, hmin = internal_steps(coupling, a.dt)
            steps = n_int * first["n_calls"]
            evals = RHS_EVALS.get(first["time_scheme"])
            wall = min(walls)
            nsps = nodes * steps / wall
            runs.append({
                "label": label,
                "headline": label == headline,
                "coupling_dt_s": coupling,
                "internal_steps_per_call": n_int,
                "shortest_internal_step_s": hmin,
                "calls": first["n_calls"],
                "internal_steps": steps,
                "deck_outputs": keep,
                "repeats": len(walls),
                "wall_s": wall,
                "wall_s_all": walls,
                "wall_s_median": statistics.median(walls),
                "us_per_internal_step": 1e6 * wall / steps,
                "us_per_call": 1e6 * wall / first["n_calls"],
                "node_steps_per_s": nsps,
                "internal_node_steps_per_s": inodes * steps / wall,
                "node_evaluations_per_s": nsps * evals if evals else None,
                "sim_end_time_from_out_s": last_time_in_out(os.path.join(d, "lines.out")),
                "final_fairlead_tension_N": first["final_fairlead_tension_N"],
                "final_coupled_point_force_N": first["final_coupled_point_force_N"],
                "line1_fairlead_tension": stats(first["ten1"], coupling),
                "line1_coupled_point_force": stats(first["pf1"], coupling),
            })
    except SystemExit:
        try:
            with open(console) as fh:
                tail = fh.read()[-3000:]
            sys.stderr.write("--- MoorDyn console (tail) ---\n%s\n" % tail)
        except OSError:
            pass
        raise
    finally:
        if not a.keep_tmp:
            shutil.rmtree(tmp, ignore_errors=True)

    segs = meta["segments"]
    evals = RHS_EVALS.get(meta["time_scheme"])
    out = {
        "tool": "moordyn",
        "moordyn_version": md_version,
        "python": platform.python_version(),
        "platform": platform.platform(),
        "deck": deck,
        "deck_sha256": deck_sha,
        "tmp_dir": tmp if a.keep_tmp else None,
        "settings": {
            "dt_s": a.dt,
            "duration_s": a.duration,
            "amplitude_m": a.amplitude,
            "period_s": a.period,
            "motion": "surge of every coupled point: x0 + A sin(2 pi t / T)",
            "scheme_requested": a.scheme,
            "time_scheme": meta["time_scheme"],
            "rhs_evaluations_per_step": evals,
            "dtM_reported_by_moordyn": meta["dtM"],
            "deck_dtM_before_override": meta["deck_dtM_before_override"],
            "repeats": a.repeats,
            "timing": "time.perf_counter around the moordyn.Step loop only "
            "(kinematics precomputed; loop also reads line 1 fairlead tension "
            "each call); best of repeats",
        },
        "model": {
            "lines": len(segs),
            "segments_per_line": segs,
            "nodes": sum(n + 1 for n in segs),
            "internal_nodes": sum(n - 1 for n in segs),
            "coupled_points": [{"id": i, "pos_m": list(p)} for i, p in cpl],
        },
        "initial_conditions": {
            "moordyn_log": meta["ic_log"],
            "init_wall_s": meta["init_wall_s"],
        },
        "statics": statics,
        "headline": headline,
        "runs": runs,
    }
    if a.json:
        print(json.dumps(out, indent=2))
    else:
        print_table(out)
    return 0


def print_table(o):
    s, m = o["settings"], o["model"]
    print("MoorDyn %s (Python %s) on %s" % (o["moordyn_version"], o["python"], o["deck"]))
    print("  scheme: %s (%s RHS evaluations/step), dtM = %g s, duration %g s, "
          "surge A = %g m, T = %g s"
          % (s["time_scheme"], s["rhs_evaluations_per_step"], s["dt_s"],
             s["duration_s"], s["amplitude_m"], s["period_s"]))
    print("  model: %d lines x %s segments; nodes = %d, internal nodes = %d; "
          "%d coupled points"
          % (m["lines"], "/".join(str(n) for n in m["segments_per_line"]), m["nodes"],
             m["internal_nodes"], len(m["coupled_points"])))
    for line in o["initial_conditions"]["moordyn_log"]:
        print("  MoorDyn log: %s" % line)
    print()
    print("Statics after moordyn.Init (fairleads at deck positions):")
    print("  %-5s %14s %12s %12s %14s %16s" % (
        "line", "T_fair [N]", "H [N]", "V [N]", "T_anchor [N]", "|F_point| [N]"))
    for j, l in enumerate(o["statics"]["lines"]):
        pf = o["statics"]["coupled_point_forces"][j]["magnitude_N"] \
            if j < len(o["statics"]["coupled_point_forces"]) else float("nan")
        print("  %-5d %14.1f %12.1f %12.1f %14.1f %16.1f" % (
            l["line"], l["fairlead_tension_N"], l["fairlead_H_N"], l["fairlead_V_N"],
            l["anchor_tension_N"], pf))
    print("  (T_fair = GetLineFairTen = top-segment tension; |F_point| = force on the")
    print("   coupled point, = MoorDyn's FairTen channel, includes the end node's weight)")
    print()
    hdr = ("run", "coupling", "steps/call", "wall [s]", "us/step", "node-steps/s",
           "node-evals/s")
    print("  %-32s %9s %10s %9s %8s %13s %13s" % hdr)
    for r in o["runs"]:
        print("  %-32s %9g %10d %9.4f %8.2f %13.4g %13s" % (
            ("* " if r["headline"] else "  ") + r["label"], r["coupling_dt_s"],
            r["internal_steps_per_call"], r["wall_s"], r["us_per_internal_step"],
            r["node_steps_per_s"],
            "%.4g" % r["node_evaluations_per_s"] if r["node_evaluations_per_s"] else "n/a"))
    print("  * headline: largest coupling interval (least Python-call overhead), "
          "deck file outputs stripped; best of %d" % s["repeats"])
    print()
    print("Fairlead tension (line 1, GetLineFairTen) over the run, and final tensions:")
    for r in o["runs"]:
        st = r["line1_fairlead_tension"]
        print("  %-32s min %11.1f  max %11.1f  mean %11.1f  final %s" % (
            r["label"], st["min_N"], st["max_N"], st["mean_N"],
            " ".join("%.1f" % t for t in r["final_fairlead_tension_N"])))


if __name__ == "__main__":
    sys.exit(main())
