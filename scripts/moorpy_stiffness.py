#!/usr/bin/env python3
"""MoorPy's 6x6 mooring stiffness of OC3-Hywind's mooring, the reference of hawser's
`body_stiffness` (crates/hawser-io/tests/body_modes.rs).

Usage (normally through scripts/moorpy_stiffness.sh, which prepares a throwaway venv):

    python scripts/moorpy_stiffness.py [--deck tests/data/moordyn/oc3_body.txt]
        [--json tests/data/moorpy_oc3_stiffness.json]

MoorPy (PyPI `moorpy`) reads the MoorDyn deck (a coupled body at the origin carrying the three
fairleads), solves its quasi-static equilibrium (elastic catenaries with seabed contact) and
gives the stiffness of the coupled body's six degrees of freedom (x, y, z, rotations about x,
y, z) with the lines relaxed: `System.getCoupledStiffnessA(lines_only=True)`, analytic from the
catenaries' own stiffness matrices, and the finite-difference `getCoupledStiffness` with small
steps (dx = 0.01 m, dth = 1e-4 rad) as a check of it.  Both are written to the JSON, with the
fairlead and anchor tensions.
"""

import argparse
import datetime
import json
import os
import platform
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, ".."))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--deck", default=os.path.join(ROOT, "tests", "data", "moordyn", "oc3_body.txt"))
    p.add_argument("--json", default=os.path.join(ROOT, "tests", "data", "moorpy_oc3_stiffness.json"))
    a = p.parse_args(argv)
    import moorpy as mp
    from importlib.metadata import version
    ms = mp.System(file=a.deck)
    ms.initialize()
    ms.solveEquilibrium()
    analytic = ms.getCoupledStiffnessA(lines_only=True)
    fd = ms.getCoupledStiffness(dx=0.01, dth=1e-4, lines_only=True)
    out = {
        "generator": "scripts/moorpy_stiffness.py",
        "generated_utc": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "moorpy_version": version("moorpy"),
        "python": platform.python_version(),
        "deck": os.path.relpath(a.deck, ROOT),
        "what": "6x6 stiffness [N/m, N/rad; N m/m, N m/rad] of the coupled body at the origin "
                "over x, y, z and rotations about x, y, z, lines relaxed (MoorPy's quasi-static "
                "catenaries), rows the force and moment components",
        "analytic": analytic.tolist(),
        "finite_difference_dx_0.01_dth_1e-4": fd.tolist(),
        "lines": {str(l.number): {"fairlead_tension_N": float(l.TB), "anchor_tension_N": float(l.TA)}
                  for l in ms.lineList},
    }
    with open(a.json, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    print("wrote %s" % os.path.relpath(a.json, ROOT), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
