"""The walkthrough of docs/python.md as one script: load a scenario, its statics, a sweep of
the fairlead's surge amplitude run in parallel into a DataFrame, and a plot.

    pip install ./crates/hawser-py pandas matplotlib
    python examples/python/walkthrough.py [PLOT.png]
"""

from __future__ import annotations

import sys
from pathlib import Path

import pandas as pd

import hawser

ROOT = Path(__file__).resolve().parents[2]

# 1. Load a scenario (a TOML scenario or a MoorDyn deck) and find its static equilibrium.
sc = hawser.load(ROOT / "examples" / "catenary_mooring.toml")
print(sc)
st = sc.statics()
print(st)
print(st.table)
chain = st.lines["chain"]
touchdown = chain.arc_length[(chain.position[:, 2] > -150.0 + 0.01).argmax()]
print(f"fairlead tension {chain.end_b_tension / 1e3:.1f} kN, "
      f"touchdown {touchdown:.0f} m from the anchor")

# 2. A sweep of the surge amplitude: one scenario per amplitude, run on two threads.
amplitudes = [1.0, 2.0, 3.0, 4.0]
cases = [sc.with_overrides({"points.fairlead.motion.amplitude": [a, 0.0, 0.0]})
         for a in amplitudes]
results = hawser.run_many(cases, workers=2, progress=False)
table = pd.DataFrame({
    "amplitude [m]": amplitudes,
    "max tension [kN]": [r["chain.end_b.tension"].max() / 1e3 for r in results],
    "min tension [kN]": [r["chain.end_b.tension"].min() / 1e3 for r in results],
    "std [kN]": [r.statistics.loc["chain.end_b.tension", "std"] / 1e3 for r in results],
}).set_index("amplitude [m]")
print(table.round(1))

# 3. Plot the fairlead tension of every case.
if len(sys.argv) > 1:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4))
    for a, r in zip(amplitudes, results):
        ts = r.timeseries
        ax.plot(ts.index, ts["chain.end_b.tension"] / 1e3, label=f"{a:g} m")
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"fairlead tension [k{ts.attrs['units']['chain.end_b.tension']}]")
    ax.set_title("catenary_mooring.toml: fairlead surge 12 s, amplitude swept")
    ax.legend(title="surge amplitude")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=90)
    print(f"wrote {sys.argv[1]}")
