"""The Python cost of a coupling step: OC3's three fairleads (tests/data/moordyn/oc3_lines.txt)
stepped at a 0.1 s coupling interval from Python, against the same stepping from Rust
(`hawser bench tests/data/moordyn/oc3_lines.txt --coupling 0.1`). CPU time of the calling
thread per `Session.step` call; docs/python.md records the numbers.

    python examples/python/step_overhead.py [DURATION_S] [REPEATS]
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import hawser

ROOT = Path(__file__).resolve().parents[2]
DECK = ROOT / "tests" / "data" / "moordyn" / "oc3_lines.txt"
INTERVAL = 0.1


def python_per_step(duration: float) -> float:
    s = hawser.load(DECK).session()
    s.init()
    x = np.array([5.2, 0.0, -70.0, -2.6, 4.5, -70.0, -2.6, -4.5, -70.0])
    xd = np.zeros(9)
    steps = round(duration / INTERVAL)
    c0 = time.thread_time()
    for _ in range(steps):
        s.step(s.time, INTERVAL, x, xd)
    return (time.thread_time() - c0) / steps


def rust_per_step(duration: float, repeats: int) -> float:
    exe = ROOT / "target" / "release" / "hawser"
    out = subprocess.run(
        [str(exe), "bench", str(DECK), "--coupling", str(INTERVAL), "--duration", str(duration),
         "--repeat", str(repeats), "--json"],
        capture_output=True, text=True, check=True).stdout
    r = json.loads(out)
    return r["coupled"]["cpu_seconds"] / (duration / INTERVAL)


if __name__ == "__main__":
    duration = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    py = min(python_per_step(duration) for _ in range(repeats))
    rs = rust_per_step(duration, repeats)
    print(f"OC3, 3 coupled fairleads, coupling every {INTERVAL} s, {duration} s, best of {repeats}:")
    print(f"  Rust   (hawser bench --coupling): {rs * 1e6:9.1f} us CPU per coupling step")
    print(f"  Python (Session.step):            {py * 1e6:9.1f} us CPU per coupling step")
    print(f"  Python overhead: {(py - rs) * 1e6:.1f} us per step ({100 * (py - rs) / rs:+.2f} %)")
