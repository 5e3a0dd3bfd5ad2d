"""MoorDyn 2.7.2's numbers for hawser's joined-failure test
(crates/hawser-io/tests/joined_failure.rs, tests/data/moordyn/joined_failure.txt).

MoorDyn-C 2.7.2 cannot run the deck's FAILURE row as written: its time check is inverted
(MoorDyn2.cpp Step: `if (failure->status || (failure->time < t)) continue;`, so a row with
FailTime > 0 fires at the first Step and one with FailTime 0 never does), FailTen is not read
by any check ("step 2: check for tension-triggered failures" is a comment), and the new free
point of `detachLines` is never added to the time integrator, so it stays where it was made
and holds the released ends fixed. Run with the row as written, this script shows that (the
joined point still at P3 after 4 s). The comparison therefore runs the deck's post-release
twin: P3 a free massless point (what `detachLines` makes), no initial-condition solve
(`TmaxIC 0`: the chains start from MoorDyn's catenaries, the static shapes they had until the
release), and reports the joined point's depth and line 1's tension at it at 1, 2, 3, 5 and
10 s after the release.

    python3 -m venv /tmp/md && /tmp/md/bin/pip install moordyn==2.7.2
    /tmp/md/bin/python scripts/moordyn_joined.py
"""
import math
import os
import tempfile

import moordyn

here = os.path.dirname(os.path.abspath(__file__))
deck = open(os.path.join(here, "..", "tests", "data", "moordyn", "joined_failure.txt")).read()


def run(text, steps, report):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "deck.txt")
        open(path, "w").write(text)
        s = moordyn.Create(path)
        moordyn.Init(s, [], [])
        t, dt = 0.0, 0.05
        for k in range(1, steps + 1):
            moordyn.Step(s, [], [], t, dt)
            t = k * dt
            report(s, t)
        moordyn.Close(s)


# 1. The row as written: the new point (the 4th) never moves.
def as_written(s, t):
    if abs(t - 4.0) < 1e-9:
        p = moordyn.GetPoint(s, moordyn.GetNumberPoints(s))
        print(f"as written, t = 4 s: {moordyn.GetNumberPoints(s)} points, the new one at "
              f"{moordyn.GetPointPos(p)}")


run(deck, 80, as_written)

# 2. The post-release twin.
twin = deck.replace("3     Fixed     0.0     0       -20.0", "3     Free      0.0     0       -20.0", 1)
a, b = twin.index("---------------------- FAILURE"), twin.index("---------------------- OPTIONS")
twin = twin[:a] + twin[b:]
twin = twin.replace("100           WtrDpth       water depth (m)\n",
                    "100           WtrDpth       water depth (m)\n0             TmaxIC        -\n", 1)


def after(s, t):
    for want in (1.0, 2.0, 3.0, 5.0, 10.0):
        if abs(t - want) < 1e-9:
            z = moordyn.GetPointPos(moordyn.GetPoint(s, 3))[2]
            l1 = moordyn.GetLine(s, 1)
            ten = math.sqrt(sum(x * x for x in moordyn.GetLineNodeTen(l1, moordyn.GetLineN(l1))))
            print(f"({want}, {z:.4f}, {ten:.2f}),")


run(twin, 200, after)
