"""MoorDyn 2.7.2's run of tests/data/moordyn/buoy_pinned_rod.txt: OC3's buoy (free body 1)
with a heavy rod pinned below it (`Body1Pinned`), the vessel point held at (-400, 0, 0).
Prints, every second to t = 20 s, the buoy's surge, heave and pitch and the rod's inclination
from the vertical in the x-z plane (end B relative to end A).

    /tmp/ciclone/.venv-bench/bin/python scripts/moordyn_pinned_rod.py [--no-ic] [--fixed-buoy]

With --no-ic the deck's TmaxIC is set to 0 (start from the deck's geometry, as hawser's
`initial_condition = "as-defined"`). With --fixed-buoy the buoy is made `Fixed` (the pin
still, where MoorDyn's pinned-rod equations are exact).

The rod's inclination at t = 0 is not printed: before the first step MoorDyn reports end B
where `Rod::setup`'s placeholder orientation puts it (along end B's deck coordinates from the
origin, atan(6/13) = 24.78° here); its state starts at the identity quaternion about
q0 = B - A, the deck's 36.87°, which the first step's output shows.
"""
import math
import os
import sys
import tempfile

import moordyn

here = os.path.dirname(os.path.abspath(__file__))
deck = open(os.path.join(here, "..", "tests", "data", "moordyn", "buoy_pinned_rod.txt")).read()
if "--no-ic" in sys.argv:
    deck = deck.replace("2000          TmaxIC", "0             TmaxIC", 1)
if "--fixed-buoy" in sys.argv:
    deck = deck.replace("1    Free         0    0  -60", "1    Fixed        0    0  -60", 1)
with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "pinned_rod.txt")
    open(path, "w").write(deck)
    s = moordyn.Create(path)
    n = moordyn.NCoupledDOF(s)
    x = [-400.0, 0.0, 0.0] + [0.0] * (n - 3)
    xd = [0.0] * n
    moordyn.Init(s, x, xd)
    body = moordyn.GetBody(s, 1)
    rod = moordyn.GetRod(s, 1)
    nseg = moordyn.GetRodN(rod)
    t, dt = 0.0, 0.01
    for k in range(2001):
        if k % 100 == 0:
            r, _ = moordyn.GetBodyState(body)
            a = moordyn.GetRodNodePos(rod, 0)
            b = moordyn.GetRodNodePos(rod, nseg)
            incl = math.degrees(math.atan2(b[0] - a[0], a[2] - b[2]))
            incl = f"{incl:.6f}" if k > 0 else "-"
            print(f"{t:6.2f} surge {r[0]:.6f} heave {r[2]:.6f} pitch {math.degrees(r[4]):.5f} "
                  f"rodA {a[0]:.5f} {a[2]:.5f} incl {incl}")
        if k == 2000:
            break
        moordyn.Step(s, x, xd, t, dt)
        t += dt
    moordyn.Close(s)
