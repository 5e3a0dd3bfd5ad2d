#!/usr/bin/env python3
"""Largest relative change of any channel between the first and the last sample of a run.

Usage: scripts/towing_drift.py OUT_DIR [OUT_DIR ...]   (directories written by `hawser run`)

For the steady-towing examples (docs/towing.md) it shows that the dynamic run, started from
the statics in the ship's frame, stays at the steady state. Standard library only.
"""
import csv
import sys


def drift(out_dir):
    with open(f"{out_dir}/timeseries.csv", newline="") as f:
        rows = list(csv.reader(f))
    header, first, last = rows[0], rows[1], rows[-1]
    worst, name = 0.0, ""
    for h, a, b in zip(header[1:], first[1:], last[1:]):
        a, b = float(a), float(b)
        change = abs(b - a) / max(abs(a), 1e-9)
        if change > worst:
            worst, name = change, h
    return len(rows) - 1, float(last[0]), worst, name


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for d in sys.argv[1:]:
        samples, end, worst, name = drift(d)
        print(f"{d}: {samples} samples to t = {end:g} s, largest relative change {worst:.1e} ({name})")
