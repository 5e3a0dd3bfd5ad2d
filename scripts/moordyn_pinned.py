"""MoorDyn 2.7.2's numbers for hawser's CoupledPinned-body test
(crates/hawser-io/tests/moordyn.rs, coupled_pinned_body_converts_and_runs).

The deck is tests/data/moordyn/buoy_oc3.txt with body 1 made `CoupledPinned`; the host holds
the pin at (0, 0, -60) and the vessel point at (-400, 0, 0) and steps 0.01 s to t = 1 s.
Prints the body's pitch and the force on the pin (the first 3 coupled forces).

    python3 -m venv /tmp/md && /tmp/md/bin/pip install moordyn==2.7.2
    /tmp/md/bin/python scripts/moordyn_pinned.py

MoorDyn 2.7.2's NCoupledDOF counts 6 for a CoupledPinned body but reads and writes 3 entries
for it (MoorDyn2.cpp Init/Step/GetForces): the arrays have 9 entries, the last 3 unused.
"""
import math
import os
import tempfile

import moordyn

here = os.path.dirname(os.path.abspath(__file__))
deck = open(os.path.join(here, "..", "tests", "data", "moordyn", "buoy_oc3.txt")).read()
deck = deck.replace("1    Free         0    0  -60", "1    CoupledPinned 0   0  -60", 1)
with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "pinned_buoy.txt")
    open(path, "w").write(deck)
    s = moordyn.Create(path)
    n = moordyn.NCoupledDOF(s)
    x = [0.0, 0.0, -60.0, -400.0, 0.0, 0.0] + [0.0] * (n - 6)
    xd = [0.0] * n
    moordyn.Init(s, x, xd)
    t, dt, f = 0.0, 0.01, None
    for _ in range(100):
        f = moordyn.Step(s, x, xd, t, dt)
        t += dt
    r, _ = moordyn.GetBodyState(moordyn.GetBody(s, 1))
    print(f"t = {t:.2f} s: pitch {math.degrees(r[4]):.5f} deg, pin force {list(f[:3])} N")
    moordyn.Close(s)
