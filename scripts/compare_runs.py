#!/usr/bin/env python3
"""Largest difference between two `hawser run` output directories' timeseries.csv.

For each column: max |a - b| over the rows, relative to max |a| of that column (columns that
are zero throughout are compared absolutely). Prints the worst column and exits 1 when it is
at or above --tolerance (default 1e-10): the check that a change which only reorders
arithmetic moves every output by round-off alone.

Usage: compare_runs.py DIR_A DIR_B [--tolerance 1e-10]
"""
import argparse
import csv
import os
import sys


def read(path):
    with open(os.path.join(path, "timeseries.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--tolerance", type=float, default=1e-10)
    a = p.parse_args()
    ha, ra = read(a.a)
    hb, rb = read(a.b)
    if ha != hb or len(ra) != len(rb):
        print(f"different shapes: {len(ha)} x {len(ra)} against {len(hb)} x {len(rb)}")
        return 1
    worst, name = 0.0, ""
    for j, col in enumerate(ha):
        scale = max(abs(r[j]) for r in ra)
        diff = max(abs(x[j] - y[j]) for x, y in zip(ra, rb))
        rel = diff / scale if scale > 0 else diff
        if rel > worst:
            worst, name = rel, col
    print(f"{len(ha)} columns x {len(ra)} rows: largest relative difference {worst:.3e} "
          f"({name or 'none'})")
    return 0 if worst < a.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
