#!/usr/bin/env python3
"""Side-by-side comparison of hawser and MoorDyn (MoorDyn-C v2 Python bindings,
PyPI ``moordyn``) on the public MoorDyn decks in shared/moordyn-decks.

Usage (normally through scripts/moordyn_compare.sh, which prepares the venv
and builds hawser):

    python scripts/moordyn_compare.py --hawser PATH/TO/hawser [--decks DIR]
        [--segments 20,40,80] [--json OUT.json] [--docs DIR] [--keep-tmp]

What is compared
----------------
1. Statics of every deck (oc3_lines, WD0050/0200/0600_Chain): the fairlead
   (end B, node N) and anchor (end A, node 0) tension of every line after
   moordyn.Init, in MoorDyn's FairTen/AnchTen convention: |Fnet| of the end
   node = norm of moordyn.GetLineNodeForce(line, node).  (In MoorDyn 2.7.2
   GetLineNodeTen and GetLineFairTen at an end node return the END SEGMENT
   tension T+Td, which is not FairTen; GetLineNodeForce is Fnet, and its norm
   equals the FairTen channel MoorDyn writes into its .out file, which this
   script checks.)  hawser: `hawser statics DECK --json`,
   lines.L<id>.end_b.tension / end_a.tension (|end-node net force|).
   The chain decks' fileIC line (pointing to a missing .ic file, which makes
   MoorDyn's Init fail) is removed in MoorDyn's temp copy.

2. OC3 surge: every coupled point at x = x0 + A sin(2 pi t / T) (A = 2 m,
   T = 10 s) for 300 s.  MoorDyn: dtM from the deck copy, coupling step
   0.01 s; moordyn.Step(x, xd, t, dt) gets x at the start of each coupling
   interval and xd = forward difference to the next sample, i.e. MoorDyn
   follows the piecewise-linear interpolant of the 0.01 s samples, which is
   exactly what hawser does with the same samples given as --vessel-motion.
   FairTen1..3 are read every 0.1 s (every 10th call; hawser's output
   interval is 0.1 s, the deck has no dtOut).  Repeated with NumSegs = 40 and
   80 in temp copies (dtM set in the copy; hawser uses it unless it exceeds
   its stability limit, and the step it actually used is parsed from its
   stderr).  Statistics are given over the whole record (0-300 s, including
   the start-up transient: the motion starts with full velocity) and over the
   periodic state of the last 50 s.

3. WD0200 chain driven by ZZP1_A1.txt like MoorDyn's own validation test
   (tests/quasi_static_chain.cpp): row i of the motion file is applied at
   t = t_i - t_0 with coupling step 0.1 s, x from the file, xd the forward
   difference.  hawser: --vessel-motion ZZP1_A1.txt --duration 30.  Both, and
   the reference series WD0200_Chain_ZZP1_A1.txt (rows at simulation time
   t_ref + 10 s), are compared for simulation times >= 10 s.

Outputs: a markdown summary (stdout), the MoorDyn numbers as JSON
(tests/data/moordyn_reference.json by default), CSV series and SVG plots in
docs/data and docs/img.
"""

from __future__ import annotations

import argparse
import csv
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, ".."))
sys.path.insert(0, HERE)

import moordyn_bench as mb  # noqa: E402  (deck helpers, fd-1 redirection)

DECKS = ["oc3_lines", "WD0050_Chain", "WD0200_Chain", "WD0600_Chain"]
SURGE_AMPLITUDE = 2.0
SURGE_PERIOD = 10.0
SURGE_DURATION = 300.0
SURGE_COUPLING = 0.01
SAMPLE = 0.1
STEADY_WINDOW = (250.0, 300.0)
CHAIN_COUPLING = 0.1  # DT of MoorDyn's quasi_static_chain test
CHAIN_DURATION = 30.0
CHAIN_FROM = 10.0  # simulation time of the reference's first row


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--hawser", default=os.environ.get(
        "HAWSER", os.path.join(ROOT, "target", "release", "hawser")))
    p.add_argument("--decks", default=os.path.normpath(
        os.path.join(ROOT, "..", "shared", "moordyn-decks")))
    p.add_argument("--segments", default="20,40,80",
                   help="OC3 surge: NumSegs values (comma separated)")
    p.add_argument("--dtm", default="20:0.002,40:0.002,80:0.0005",
                   help="OC3 surge: dtM per NumSegs, SEGS:DT,... (default: the "
                   "deck's 0.002 s for 20 and 40, 0.0005 s for 80)")
    p.add_argument("--json", default=os.path.join(ROOT, "tests", "data", "moordyn_reference.json"))
    p.add_argument("--docs", default=os.path.join(ROOT, "docs"))
    p.add_argument("--keep-tmp", action="store_true")
    return p.parse_args(argv)


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def rel(a, b):
    """Relative difference (a - b) / b."""
    return (a - b) / b if b else float("nan")


def sha256(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


# --------------------------------------------------------------------------
# deck copies


def write_copy(src_lines, path, segments=None, dtm=None, drop_options=(), line_outputs="-"):
    """Temp copy of a deck: NumSegs of every line set to ``segments``, line
    output flags set to ``line_outputs`` (per-node files off), dtM set, the
    options named in ``drop_options`` removed.  Returns what changed."""
    lines = list(src_lines)
    changes = []
    hdr = mb.find_section(lines, ("LINES", "LINE LIST", "LINE PROPERTIES"))
    for i in mb.section_rows(lines, hdr, 2):
        f = lines[i].split()
        if len(f) >= 7:
            if segments is not None and f[5] != str(segments):
                changes.append("line %s NumSegs %s -> %d" % (f[0], f[5], segments))
                f[5] = str(segments)
            if line_outputs is not None and f[6] != line_outputs:
                f[6] = line_outputs
            lines[i] = "  ".join(f)
    if dtm is not None:
        old = mb.set_option(lines, "dtM", repr(dtm))
        changes.append("dtM %s -> %r" % (old, dtm))
    hdr = mb.find_section(lines, ("OPTIONS",))
    i = hdr + 1
    while i < len(lines) and "---" not in lines[i]:
        f = lines[i].split()
        if len(f) >= 2 and f[1] in drop_options:
            changes.append("removed option %s %s" % (f[1], f[0]))
            del lines[i]
            continue
        i += 1
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(lines) + "\n")
    return changes


def log_lines(log_path, starts=("dtM =", "Remaining error", "Best score", "Time integrator",
                                "Finalizing ICs", "Fairlead tensions")):
    out = []
    try:
        with open(log_path, errors="replace") as fh:
            for line in fh:
                s = line.strip()
                if s.startswith(starts):
                    out.append(s)
    except OSError:
        pass
    return out


def moordyn_dtm_from_log(log_path):
    for s in log_lines(log_path, ("dtM =",)):
        m = re.match(r"dtM = ([0-9.eE+-]+) s", s)
        if m:
            return float(m.group(1))
    return None


# --------------------------------------------------------------------------
# MoorDyn


class MD:
    """A MoorDyn system over one deck copy, console output to a file."""

    def __init__(self, moordyn, deck, console):
        self.m = moordyn
        self.deck = deck
        self.console = console
        with mb.redirect_fd1(console):
            self.s = moordyn.Create(deck)
        if not self.s:
            raise SystemExit("moordyn.Create failed on %s (see %s)" % (deck, console))
        self.cpl = [p for _, p in mb.coupled_points_from_deck(mb.read_deck(deck))]
        self.x0 = [c for p in self.cpl for c in p]
        n = moordyn.NCoupledDOF(self.s)
        if n != len(self.x0):
            raise SystemExit("%s: %d coupled DOFs, %d coupled points" % (deck, n, len(self.cpl)))
        self.lines = [moordyn.GetLine(self.s, i)
                      for i in range(1, moordyn.GetNumberLines(self.s) + 1)]
        self.ids = [moordyn.GetLineID(l) for l in self.lines]
        self.nseg = [moordyn.GetLineN(l) for l in self.lines]

    def init(self, x=None):
        with mb.redirect_fd1(self.console):
            err = self.m.Init(self.s, list(x or self.x0), [0.0] * len(self.x0))
        if err:
            raise SystemExit("moordyn.Init failed (%d) on %s, see %s" % (err, self.deck, self.console))

    def fair(self, j):
        """FairTen of line j (0-based): |Fnet| of node N."""
        return norm(self.m.GetLineNodeForce(self.lines[j], self.nseg[j]))

    def anch(self, j):
        """AnchTen of line j: |Fnet| of node 0."""
        return norm(self.m.GetLineNodeForce(self.lines[j], 0))

    def end_segment_tension(self, j, node):
        return norm(self.m.GetLineNodeTen(self.lines[j], node))

    def step(self, x, xd, t, dt):
        with mb.redirect_fd1(self.console):
            f = self.m.Step(self.s, x, xd, t, dt)
        return f

    def close(self):
        with mb.redirect_fd1(self.console):
            self.m.Close(self.s)


def read_md_out(path):
    """MoorDyn main .out file -> (header, rows)."""
    with open(path) as fh:
        rows = [r.split() for r in fh.read().splitlines() if r.strip()]
    return rows[0], [[float(v) for v in r] for r in rows[2:]]


# --------------------------------------------------------------------------
# hawser


def hawser_statics(hawser, deck):
    r = subprocess.run([hawser, "statics", deck, "--json"], capture_output=True, text=True)
    if r.returncode:
        raise SystemExit("hawser statics %s failed:\n%s" % (deck, r.stderr))
    return json.loads(r.stdout)


def hawser_run(hawser, deck, out, duration, motion):
    """Starts `hawser run`; returns the Popen (stderr to out/stderr.txt).
    Not --quiet: the "time step ..." line is only printed without it."""
    os.makedirs(out, exist_ok=True)
    err = open(os.path.join(out, "..", os.path.basename(out) + ".stderr"), "w")
    cmd = [hawser, "run", deck, "--out", out, "--duration", repr(duration),
           "--vessel-motion", motion]
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err), err, cmd


def hawser_finish(proc, errfh, cmd):
    rc = proc.wait()
    errfh.close()
    with open(errfh.name, errors="replace") as fh:
        text = fh.read()
    if rc:
        raise SystemExit("%s failed (%d):\n%s" % (" ".join(cmd), rc, text[-3000:]))
    m = re.search(r"time step ([0-9.eE+-]+) s \(stability limit ([0-9.eE+-]+) s, ([^\n]*)", text)
    info = {"stderr_time_step_line": None, "time_step_s": None, "stability_limit_s": None}
    for line in text.splitlines():
        if line.startswith("time step"):
            info["stderr_time_step_line"] = line.strip()
    if m:
        info["time_step_s"] = float(m.group(1))
        info["stability_limit_s"] = float(m.group(2))
    info["warnings"] = [l.strip() for l in text.splitlines() if l.lower().startswith("warning")]
    return info


def read_timeseries(path):
    with open(path) as fh:
        rows = list(csv.reader(fh))
    head = rows[0]
    cols = {h: [float(r[j]) for r in rows[1:]] for j, h in enumerate(head)}
    return cols


def key(t):
    return int(round(t / SAMPLE))


# --------------------------------------------------------------------------
# statistics


def mmm(values):
    return {"min_N": min(values), "max_N": max(values), "mean_N": sum(values) / len(values)}


def window(times, values, t0, t1):
    """Samples with t0 <= t < t1."""
    return [v for t, v in zip(times, values) if t0 - 1e-9 <= t < t1 - 1e-9]


def diff_stats(a, b, ref_range):
    """a - b over paired samples [N]: rms, max |.|, mean; relative to ref_range."""
    d = [x - y for x, y in zip(a, b)]
    rms = math.sqrt(sum(v * v for v in d) / len(d))
    mx = max(abs(v) for v in d)
    mean = sum(d) / len(d)
    return {"rms_kN": rms / 1e3, "max_abs_kN": mx / 1e3, "mean_kN": mean / 1e3,
            "rms_rel_range": rms / ref_range, "max_rel_range": mx / ref_range,
            "samples": len(d)}


# --------------------------------------------------------------------------
# cases


def case_statics(moordyn, hawser, decks_dir, tmp):
    out = {}
    for name in DECKS:
        deck = os.path.join(decks_dir, name + ".txt")
        if not os.path.exists(deck):
            continue
        copy = os.path.join(tmp, "statics_" + name + ".txt")
        changes = write_copy(mb.read_deck(deck), copy, drop_options=("fileIC",), line_outputs=None)
        md = MD(moordyn, copy, os.path.join(tmp, "console_statics.txt"))
        md.init()
        lines = {}
        for j, lid in enumerate(md.ids):
            lines[str(lid)] = {
                "segments": md.nseg[j],
                "fairlead_tension_N": md.fair(j),
                "anchor_tension_N": md.anch(j),
                "fairlead_end_segment_tension_N": md.end_segment_tension(j, md.nseg[j]),
                "anchor_end_segment_tension_N": md.end_segment_tension(j, 0),
            }
        md.close()
        # MoorDyn's own FairTen channels at t = 0 (decks with OUTPUTS): check the convention.
        check = None
        outf = os.path.splitext(copy)[0] + ".out"
        if os.path.exists(outf):
            head, rows = read_md_out(outf)
            if rows:
                for j, h in enumerate(head):
                    m = re.match(r"FAIRTEN(\d+)$", h.upper())
                    if m and m.group(1) in lines:
                        r_ = rel(lines[m.group(1)]["fairlead_tension_N"], rows[0][j])
                        check = max(check or 0.0, abs(r_))
        hs = hawser_statics(hawser, deck)
        hl = {}
        for lid in lines:
            L = hs["lines"]["L" + lid]
            hl[lid] = {"fairlead_tension_N": L["end_b"]["tension"],
                       "anchor_tension_N": L["end_a"]["tension"]}
        out[name] = {
            "deck": os.path.basename(deck),
            "deck_sha256": sha256(deck),
            "moordyn_copy_changes": changes,
            "moordyn_log": log_lines(os.path.splitext(copy)[0] + ".log"),
            "moordyn_fairten_channel_vs_api_max_rel_diff": check,
            "moordyn": lines,
            "hawser": hl,
        }
    return out


def surge_samples():
    n = int(round(SURGE_DURATION / SURGE_COUPLING))
    w = 2.0 * math.pi / SURGE_PERIOD
    ts = [i * SURGE_COUPLING for i in range(n + 1)]
    # Formatted once, so hawser's file and MoorDyn's inputs are the same numbers.
    xs = [float("%.12g" % (SURGE_AMPLITUDE * math.sin(w * t))) for t in ts]
    return ts, xs


def case_surge(moordyn, hawser, decks_dir, tmp, segments, dtm):
    deck = os.path.join(decks_dir, "oc3_lines.txt")
    src = mb.read_deck(deck)
    ts, xs = surge_samples()
    motion = os.path.join(tmp, "surge_motion.txt")
    with open(motion, "w") as fh:
        for t, x in zip(ts, xs):
            fh.write("%.2f %.12g 0 0 0 0 0\n" % (t, x))
    cases = {}
    series20 = None
    for segs in segments:
        d = os.path.join(tmp, "surge%d" % segs)
        os.makedirs(d, exist_ok=True)
        copy = os.path.join(d, "oc3_lines.txt")
        changes = write_copy(src, copy, segments=segs, dtm=dtm[segs])
        # hawser in the background while MoorDyn runs here (2 cores).
        proc = hawser_run(hawser, copy, os.path.join(d, "hawser"), SURGE_DURATION, motion)

        md = MD(moordyn, copy, os.path.join(d, "console.txt"))
        md.init()
        nl = len(md.lines)
        every = int(round(SAMPLE / SURGE_COUPLING))
        times = [0.0]
        ften = [[md.fair(j)] for j in range(nl)]
        n = len(ts) - 1
        for i in range(n):
            x = list(md.x0)
            xd = [0.0] * len(x)
            v = (xs[i + 1] - xs[i]) / SURGE_COUPLING
            for k in range(len(md.cpl)):
                x[3 * k] += xs[i]
                xd[3 * k] = v
            md.step(x, xd, ts[i], SURGE_COUPLING)
            if (i + 1) % every == 0:
                times.append(round((i + 1) * SURGE_COUPLING, 9))
                for j in range(nl):
                    ften[j].append(md.fair(j))
        md.close()
        # Cross-check against MoorDyn's own FairTen channels in its .out file.
        head, rows = read_md_out(os.path.join(d, "oc3_lines.out"))
        by_t = {key(r[0]): r for r in rows if abs(r[0] / SAMPLE - round(r[0] / SAMPLE)) < 1e-6}
        chk = 0.0
        for j in range(nl):
            col = head.index("FairTen%d" % md.ids[j])
            for t, v in zip(times, ften[j]):
                r = by_t.get(key(t))
                if r is not None:
                    chk = max(chk, abs(rel(v, r[col])))
        hinfo = hawser_finish(*proc)
        hts = read_timeseries(os.path.join(d, "hawser", "timeseries.csv"))
        hmap = {key(t): i for i, t in enumerate(hts["time"])}
        idx = [hmap[key(t)] for t in times]
        res = {"segments": segs, "moordyn_dtM_s": moordyn_dtm_from_log(os.path.join(d, "oc3_lines.log")),
               "deck_copy_changes": changes, "moordyn_log": log_lines(os.path.join(d, "oc3_lines.log")),
               "moordyn_fairten_channel_vs_api_max_rel_diff": chk,
               "hawser": hinfo, "lines": {}}
        for j in range(nl):
            name = "FairTen%d" % md.ids[j]
            hv = [hts[name][i] for i in idx]
            res["lines"][name] = {
                "moordyn": {"all": mmm(window(times, ften[j], 0.0, SURGE_DURATION)),
                            "steady": mmm(window(times, ften[j], *STEADY_WINDOW))},
                "hawser": {"all": mmm(window(times, hv, 0.0, SURGE_DURATION)),
                           "steady": mmm(window(times, hv, *STEADY_WINDOW))},
            }
            if j == 0 and segs == 20:
                n_ = len(window(times, times, 0.0, SURGE_DURATION))
                series20 = (times[:n_], hv[:n_], ften[j][:n_])
        cases[str(segs)] = res
    return cases, series20


def case_chain(moordyn, hawser, decks_dir, tmp):
    deck = os.path.join(decks_dir, "WD0200_Chain.txt")
    motion = os.path.join(decks_dir, "ZZP1_A1.txt")
    reff = os.path.join(decks_dir, "WD0200_Chain_ZZP1_A1.txt")
    d = os.path.join(tmp, "chain")
    os.makedirs(d, exist_ok=True)
    copy = os.path.join(d, "WD0200_Chain.txt")
    changes = write_copy(mb.read_deck(deck), copy, drop_options=("fileIC",))
    with open(motion) as fh:
        mot = [[float(v) for v in r.split()] for r in fh if r.strip()]
    with open(reff) as fh:
        ref = [[float(v) for v in r.split()] for r in fh if r.strip()]
    proc = hawser_run(hawser, copy, os.path.join(d, "hawser"), CHAIN_DURATION, motion)

    md = MD(moordyn, copy, os.path.join(d, "console.txt"))
    md.init([mot[0][1], mot[0][2], mot[0][3]])
    static = {"fairlead_tension_N": md.fair(0), "anchor_tension_N": md.anch(0)}
    t0 = mot[0][0]
    times, fair, anch = [0.0], [md.fair(0)], [md.anch(0)]
    for i in range(len(mot) - 1):
        t = mot[i][0] - t0
        if t >= CHAIN_DURATION - 1e-9:
            break
        x = mot[i][1:4]
        xd = [(mot[i + 1][k + 1] - x[k]) / CHAIN_COUPLING for k in range(3)]
        md.step(x, xd, t, CHAIN_COUPLING)
        times.append(round(t + CHAIN_COUPLING, 9))
        fair.append(md.fair(0))
        anch.append(md.anch(0))
    md.close()
    hinfo = hawser_finish(*proc)
    hts = read_timeseries(os.path.join(d, "hawser", "timeseries.csv"))
    hmap = {key(t): i for i, t in enumerate(hts["time"])}
    mmap = {key(t): i for i, t in enumerate(times)}
    rows = []  # t, hawser fair, md fair, ref fair, hawser anch, md anch, ref anch  [N]
    for r in ref:
        t = r[0] + CHAIN_FROM
        k = key(t)
        if k in hmap and k in mmap:
            rows.append((t, hts["L1.end_b.tension"][hmap[k]], fair[mmap[k]], 1e3 * r[3],
                         hts["L1.end_a.tension"][hmap[k]], anch[mmap[k]], 1e3 * r[4]))
    # The last row (t = 30 s) is the end of the motion table: hawser holds the
    # point there with zero velocity, so its end force at that instant drops
    # the end segment's damping force; it is reported, not compared.
    last = rows[-1] if rows and rows[-1][0] >= CHAIN_DURATION - 1e-9 else None
    stat_rows = rows[:-1] if last else rows
    cmp_ = {}
    for label, (ih, im, ir) in {"fairlead": (1, 2, 3), "anchor": (4, 5, 6)}.items():
        col = lambda c: [row[c] for row in stat_rows]
        rr = col(ir)
        rng = max(rr) - min(rr)
        cmp_[label] = {
            "reference_range_kN": rng / 1e3,
            "reference_min_max_kN": [min(rr) / 1e3, max(rr) / 1e3],
            "moordyn_min_max_kN": [min(col(im)) / 1e3, max(col(im)) / 1e3],
            "hawser_min_max_kN": [min(col(ih)) / 1e3, max(col(ih)) / 1e3],
            "hawser_minus_reference": diff_stats(col(ih), rr, rng),
            "moordyn_minus_reference": diff_stats(col(im), rr, rng),
            "hawser_minus_moordyn": diff_stats(col(ih), col(im), rng),
        }
    mid = chain_mid_interval(moordyn, hawser, d, copy, mot)
    return {
        "deck_copy_changes": changes,
        "compared_times_s": [stat_rows[0][0], stat_rows[-1][0]],
        "excluded_last_row": None if not last else {
            "time_s": last[0], "hawser_fairlead_kN": last[1] / 1e3,
            "moordyn_fairlead_kN": last[2] / 1e3, "reference_fairlead_kN": last[3] / 1e3},
        "mid_interval": mid,
        "moordyn_dtM_s": moordyn_dtm_from_log(os.path.join(d, "WD0200_Chain.log")),
        "moordyn_log": log_lines(os.path.join(d, "WD0200_Chain.log")),
        "hawser": hinfo,
        "moordyn_static": static,
        "moordyn_series": {"time_s": times, "fairlead_tension_N": fair, "anchor_tension_N": anch},
        "rows": rows,
        "comparison": cmp_,
        "files": {"deck": os.path.basename(deck), "deck_sha256": sha256(deck),
                  "motion": os.path.basename(motion), "motion_sha256": sha256(motion),
                  "reference": os.path.basename(reff), "reference_sha256": sha256(reff)},
    }


def chain_mid_interval(moordyn, hawser, d, copy, mot):
    """Diagnostic: hawser vs MoorDyn at the knots of the piecewise-linear
    motion (t = k 0.1 s, where the fairlead velocity jumps and with it the
    end segment's damping force: MoorDyn reports the value at the end of the
    coupling interval, i.e. with the old velocity, hawser the value with the
    new one) and half-way between them (where both are continuous).  MoorDyn
    steps each 0.1 s interval in two halves along the same line x + xd (t -
    t_i); hawser writes every 0.05 s (dtOut in a copy)."""
    dd = os.path.join(d, "mid")
    os.makedirs(dd, exist_ok=True)
    lines = mb.read_deck(copy)
    mb.set_option(lines, "dtOut", "0.05")
    copy2 = os.path.join(dd, "WD0200_Chain.txt")
    with open(copy2, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    motion = os.path.join(os.path.dirname(copy), "motion.txt")
    with open(motion, "w") as fh:
        for r in mot:
            fh.write(" ".join(repr(v) for v in r) + "\n")
    proc = hawser_run(hawser, copy2, os.path.join(dd, "hawser"), CHAIN_DURATION, motion)
    md = MD(moordyn, copy2, os.path.join(dd, "console.txt"))
    md.init([mot[0][1], mot[0][2], mot[0][3]])
    h = 0.5 * CHAIN_COUPLING
    rec = {}
    t0 = mot[0][0]
    for i in range(len(mot) - 1):
        t = mot[i][0] - t0
        if t >= CHAIN_DURATION - 1e-9:
            break
        x = mot[i][1:4]
        xd = [(mot[i + 1][k + 1] - x[k]) / CHAIN_COUPLING for k in range(3)]
        md.step(x, xd, t, h)
        rec[int(round((t + h) / h))] = (md.fair(0), md.anch(0))
        md.step([x[k] + xd[k] * h for k in range(3)], xd, t + h, h)
        rec[int(round((t + 2 * h) / h))] = (md.fair(0), md.anch(0))
    md.close()
    hawser_finish(*proc)
    hts = read_timeseries(os.path.join(dd, "hawser", "timeseries.csv"))
    hv = {int(round(t / h)): (f, a) for t, f, a in
          zip(hts["time"], hts["L1.end_b.tension"], hts["L1.end_a.tension"])}
    out = {}
    for label, odd in (("knots", False), ("mid_interval", True)):
        ks = sorted(k for k in rec if k in hv and (k % 2 == 1) == odd
                    and CHAIN_FROM - 1e-9 <= k * h < CHAIN_DURATION - 1e-9)
        res = {"samples": len(ks)}
        for j, name in ((0, "fairlead"), (1, "anchor")):
            a = [hv[k][j] for k in ks]
            b = [rec[k][j] for k in ks]
            rng = max(b) - min(b)
            s_ = diff_stats(a, b, rng)
            res[name] = {"hawser_minus_moordyn_rms_kN": s_["rms_kN"],
                         "hawser_minus_moordyn_max_abs_kN": s_["max_abs_kN"],
                         "moordyn_range_kN": rng / 1e3}
        out[label] = res
    ks = sorted(k for k in rec if k % 2 == 1 and CHAIN_FROM - 1e-9 <= k * h < CHAIN_DURATION - 1e-9)
    out["moordyn_series"] = {
        "time_s": [round(k * h, 6) for k in ks],
        "fairlead_tension_N": [rec[k][0] for k in ks],
        "anchor_tension_N": [rec[k][1] for k in ks],
    }
    return out


# --------------------------------------------------------------------------
# report


def pct(x):
    return "%+.3f %%" % (100.0 * x)


def markdown(st, surge, chain, md_version):
    o = []
    o.append("## hawser vs MoorDyn %s\n" % md_version)
    o.append("### Statics (|end-node net force|, MoorDyn FairTen/AnchTen convention)\n")
    o.append("| deck | line | fairlead MoorDyn [kN] | fairlead hawser [kN] | diff | "
             "anchor MoorDyn [kN] | anchor hawser [kN] | diff |")
    o.append("|---|---|---:|---:|---:|---:|---:|---:|")
    for name, s in st.items():
        for lid, m in s["moordyn"].items():
            h = s["hawser"][lid]
            o.append("| %s | %s | %.2f | %.2f | %s | %.2f | %.2f | %s |" % (
                name, lid, m["fairlead_tension_N"] / 1e3, h["fairlead_tension_N"] / 1e3,
                pct(rel(h["fairlead_tension_N"], m["fairlead_tension_N"])),
                m["anchor_tension_N"] / 1e3, h["anchor_tension_N"] / 1e3,
                pct(rel(h["anchor_tension_N"], m["anchor_tension_N"]))))
    o.append("")
    o.append("### OC3 surge 2 m / 10 s, 300 s, FairTen every 0.1 s "
             "(all: 0 <= t < 300 s; steady: %g <= t < %g s)\n" % STEADY_WINDOW)
    o.append("| segs | dt MoorDyn / hawser [s] | channel | window | min MD / hawser [kN] | diff | "
             "max MD / hawser [kN] | diff | mean MD / hawser [kN] | diff |")
    o.append("|---|---|---|---|---:|---:|---:|---:|---:|---:|")
    for segs, c in surge.items():
        dts = "%g / %g" % (c["moordyn_dtM_s"] or float("nan"), c["hawser"]["time_step_s"] or float("nan"))
        for name, L in c["lines"].items():
            for w in ("all", "steady"):
                m, h = L["moordyn"][w], L["hawser"][w]
                cells = []
                for q in ("min_N", "max_N", "mean_N"):
                    cells += ["%.1f / %.1f" % (m[q] / 1e3, h[q] / 1e3), pct(rel(h[q], m[q]))]
                o.append("| %s | %s | %s | %s | %s |" % (segs, dts, name, w, " | ".join(cells)))
    o.append("")
    o.append("### WD0200 chain, ZZP1_A1 heave, simulation times 10-30 s "
             "(reference = WD0200_Chain_ZZP1_A1.txt)\n")
    o.append("| tension | pair | RMS [kN] | max abs [kN] | mean [kN] | RMS / ref range | max / ref range |")
    o.append("|---|---|---:|---:|---:|---:|---:|")
    for label, c in chain["comparison"].items():
        for pair in ("hawser_minus_moordyn", "hawser_minus_reference", "moordyn_minus_reference"):
            d = c[pair]
            o.append("| %s | %s | %.1f | %.1f | %+.1f | %.3f | %.3f |" % (
                label, pair.replace("_minus_", " - "), d["rms_kN"], d["max_abs_kN"], d["mean_kN"],
                d["rms_rel_range"], d["max_rel_range"]))
    o.append("")
    for label, c in chain["comparison"].items():
        o.append("- %s range [kN]: reference %.1f-%.1f, MoorDyn %.1f-%.1f, hawser %.1f-%.1f" % (
            label, *c["reference_min_max_kN"], *c["moordyn_min_max_kN"], *c["hawser_min_max_kN"]))
    o.append("- compared: t = %g-%g s every 0.1 s (reference rows 0-%g s)" % (
        chain["compared_times_s"][0], chain["compared_times_s"][1],
        chain["compared_times_s"][1] - CHAIN_FROM))
    e = chain["excluded_last_row"]
    if e:
        o.append("- excluded: t = %g s, the motion table's last row (hawser: velocity 0 from there on): "
                 "fairlead hawser %.1f, MoorDyn %.1f, reference %.1f kN" % (
                     e["time_s"], e["hawser_fairlead_kN"], e["moordyn_fairlead_kN"],
                     e["reference_fairlead_kN"]))
    m = chain["mid_interval"]
    for w in ("knots", "mid_interval"):
        o.append("- hawser - MoorDyn sampled at %s (every 0.1 s, 10-30 s): fairlead RMS %.2f kN "
                 "(max %.2f), anchor RMS %.2f kN (max %.2f)" % (
                     "the motion's knots t = k 0.1 s" if w == "knots" else "mid-interval t = k 0.1 + 0.05 s",
                     m[w]["fairlead"]["hawser_minus_moordyn_rms_kN"],
                     m[w]["fairlead"]["hawser_minus_moordyn_max_abs_kN"],
                     m[w]["anchor"]["hawser_minus_moordyn_rms_kN"],
                     m[w]["anchor"]["hawser_minus_moordyn_max_abs_kN"]))
    o.append("- time steps: MoorDyn dtM %s s (CFL 0.1), hawser %s s" % (
        chain["moordyn_dtM_s"], chain["hawser"]["time_step_s"]))
    return "\n".join(o)


def write_outputs(a, st, surge, series20, chain, md_version):
    os.makedirs(os.path.dirname(a.json), exist_ok=True)
    ref = {
        "generator": "scripts/moordyn_compare.py",
        "generated_utc": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "moordyn_version": md_version,
        "python": platform.python_version(),
        "what": "MoorDyn-C (PyPI moordyn) results on the decks in shared/moordyn-decks, for "
                "regression tests of hawser. Tensions are |net force on the end node| "
                "(MoorDyn's FairTen/AnchTen output channels) = norm of "
                "moordyn.GetLineNodeForce(line, node), node N = fairlead (end B), node 0 = "
                "anchor (end A), in N.",
        "statics": {
            "what": "after moordyn.Init with the coupled points at their deck positions "
                    "(MoorDyn's dynamic-relaxation initial condition); fileIC removed from the "
                    "chain decks (the .ic file is missing). not_fairten_end_segment_tension_N: "
                    "|GetLineNodeTen| at the end nodes (= GetLineFairTen in 2.7.2), the end "
                    "segment's tension, for reference only. fairten_channel_vs_api_max_rel_diff: "
                    "FairTen channels of MoorDyn's .out file at t = 0 vs the numbers here",
            "decks": {n: {"deck": s["deck"], "deck_sha256": s["deck_sha256"],
                          "moordyn_copy_changes": s["moordyn_copy_changes"],
                          "moordyn_log": s["moordyn_log"],
                          "fairten_channel_vs_api_max_rel_diff":
                              s["moordyn_fairten_channel_vs_api_max_rel_diff"],
                          "lines": {lid: {"segments": m["segments"],
                                          "fairlead_tension_N": m["fairlead_tension_N"],
                                          "anchor_tension_N": m["anchor_tension_N"],
                                          "not_fairten_end_segment_tension_N": {
                                              "fairlead": m["fairlead_end_segment_tension_N"],
                                              "anchor": m["anchor_end_segment_tension_N"]}}
                                    for lid, m in s["moordyn"].items()}}
                      for n, s in st.items()},
        },
        "oc3_surge": {
            "deck": "oc3_lines.txt",
            "settings": {
                "motion": "every coupled point x = x0 + A sin(2 pi t / T), y, z fixed",
                "amplitude_m": SURGE_AMPLITUDE, "period_s": SURGE_PERIOD,
                "duration_s": SURGE_DURATION, "coupling_step_s": SURGE_COUPLING,
                "kinematics": "moordyn.Step(x(t_i), (x(t_i+1) - x(t_i)) / dt, t_i, dt): the "
                              "piecewise-linear interpolant of samples every 0.01 s (the "
                              "sample values are rounded to 12 significant digits)",
                "sampled_every_s": SAMPLE,
                "windows": {"all": [0.0, SURGE_DURATION], "steady": list(STEADY_WINDOW),
                            "note": "t0 <= t < t1: the sample at t = 300 s, the end of the "
                                    "motion table, is left out (hawser holds the points there "
                                    "with zero velocity, which changes the end force at that "
                                    "instant)"},
                "time_scheme": "MoorDyn default (RK2)",
            },
            "cases": {segs: {"segments": c["segments"], "dtM_s": c["moordyn_dtM_s"],
                             "deck_copy_changes": c["deck_copy_changes"],
                             "fairten_channel_vs_api_max_rel_diff":
                                 c["moordyn_fairten_channel_vs_api_max_rel_diff"],
                             "fairleads": {n: L["moordyn"] for n, L in c["lines"].items()}}
                      for segs, c in surge.items()},
        },
        "chain_wd0200_zzp1_a1": {
            "files": chain["files"],
            "settings": {
                "driving": "as MoorDyn's tests/quasi_static_chain.cpp: Init at the motion's "
                           "first row; row i applied at t = t_i - t_0 with coupling step 0.1 s, "
                           "x from the file, xd forward difference",
                "dtM_s": chain["moordyn_dtM_s"],
                "deck_copy_changes": chain["deck_copy_changes"],
                "reference_rows_at": "simulation time = reference time + 10 s",
            },
            "static": chain["moordyn_static"],
            "time_s": [t for t in chain["moordyn_series"]["time_s"] if t >= CHAIN_FROM - 1e-9],
            "fairlead_tension_N": [v for t, v in zip(chain["moordyn_series"]["time_s"],
                                                     chain["moordyn_series"]["fairlead_tension_N"])
                                   if t >= CHAIN_FROM - 1e-9],
            "anchor_tension_N": [v for t, v in zip(chain["moordyn_series"]["time_s"],
                                                   chain["moordyn_series"]["anchor_tension_N"])
                                 if t >= CHAIN_FROM - 1e-9],
            "mid_interval": {
                "what": "MoorDyn stepping each 0.1 s coupling interval in two halves along the "
                        "same x + xd (t - t_i); tensions half-way between the motion's knots, "
                        "where the fairlead velocity is continuous (at the knots it jumps, and "
                        "codes that sample on either side of the jump differ by the change of "
                        "the end segment's damping force)",
                **chain["mid_interval"]["moordyn_series"],
            },
        },
    }
    with open(a.json, "w") as fh:
        json.dump(ref, fh, indent=1)
        fh.write("\n")

    data = os.path.join(a.docs, "data")
    img = os.path.join(a.docs, "img")
    os.makedirs(data, exist_ok=True)
    os.makedirs(img, exist_ok=True)
    plot = os.path.join(HERE, "plot_svg.py")
    if series20:
        f1 = os.path.join(data, "moordyn_oc3_surge_fairten1.csv")
        with open(f1, "w") as fh:
            fh.write("time [s],hawser FairTen1 [kN],MoorDyn FairTen1 [kN]\n")
            for t, h, m in zip(*series20):
                fh.write("%.1f,%.4f,%.4f\n" % (t, h / 1e3, m / 1e3))
        subprocess.run([sys.executable, plot, "timeseries", os.path.join(img, "moordyn_oc3_surge.svg"),
                        f1, "hawser FairTen1", "MoorDyn FairTen1", "--ylabel", "fairlead tension [kN]",
                        "--title", "OC3, 20 segments, surge 2 m / 10 s: FairTen1 (last 50 s)",
                        "--from", "%g" % STEADY_WINDOW[0]], check=True)
    f2 = os.path.join(data, "moordyn_chain_zzp1.csv")
    with open(f2, "w") as fh:
        fh.write("time [s],hawser fairlead [kN],MoorDyn fairlead [kN],reference fairlead [kN],"
                 "hawser anchor [kN],MoorDyn anchor [kN],reference anchor [kN]\n")
        for r in chain["rows"][:-1] if chain["excluded_last_row"] else chain["rows"]:
            fh.write("%.1f,%s\n" % (r[0], ",".join("%.3f" % (v / 1e3) for v in r[1:])))
    subprocess.run([sys.executable, plot, "timeseries", os.path.join(img, "moordyn_chain_zzp1.svg"),
                    f2, "hawser fairlead", "MoorDyn fairlead", "reference fairlead",
                    "hawser anchor", "MoorDyn anchor", "reference anchor",
                    "--ylabel", "tension [kN]",
                    "--title", "WD0200 chain, ZZP1_A1 heave: fairlead and anchor tension"], check=True)
    return [a.json, f2] + ([f1] if series20 else [])


def main(argv=None):
    a = parse_args(argv)
    try:
        import moordyn
        from importlib.metadata import version
        md_version = version("moordyn")
    except ImportError as e:
        raise SystemExit("cannot import moordyn: %s" % e)
    if not os.access(a.hawser, os.X_OK):
        raise SystemExit("no hawser binary at %s (give --hawser)" % a.hawser)
    segments = [int(s) for s in a.segments.split(",") if s.strip()]
    dtm = {int(k): float(v) for k, v in (p.split(":") for p in a.dtm.split(","))}
    for s in segments:
        dtm.setdefault(s, 0.002)
    tmp = tempfile.mkdtemp(prefix="moordyn-compare-")
    try:
        print("statics ...", file=sys.stderr)
        st = case_statics(moordyn, a.hawser, a.decks, tmp)
        print("OC3 surge (%s segments) ..." % a.segments, file=sys.stderr)
        surge, series20 = case_surge(moordyn, a.hawser, a.decks, tmp, segments, dtm)
        print("WD0200 chain, ZZP1_A1 ...", file=sys.stderr)
        chain = case_chain(moordyn, a.hawser, a.decks, tmp)
        files = write_outputs(a, st, surge, series20, chain, md_version)
        print(markdown(st, surge, chain, md_version))
        full = os.path.join(tmp, "comparison_full.json")
        with open(full, "w") as fh:
            json.dump({"statics": st, "surge": surge,
                       "chain": {k: v for k, v in chain.items() if k not in ("rows",)}}, fh, indent=1)
        print("\nwrote: %s" % ", ".join(os.path.relpath(f, ROOT) for f in files), file=sys.stderr)
        if a.keep_tmp:
            print("temp dir kept: %s" % tmp, file=sys.stderr)
    finally:
        if not a.keep_tmp:
            shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
