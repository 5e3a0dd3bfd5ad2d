"""A load-case table spread over a Dask cluster: every row of the table is one hawser run
(a scenario with its keys overridden), computed on a worker; the summary rows come back into
one pandas DataFrame.

    pip install ./crates/hawser-py "dask[distributed]" pandas
    python examples/python/dask_load_cases.py                 # a LocalCluster on this machine
    python examples/python/dask_load_cases.py tcp://HOST:8786 # the same code on a real cluster

On a cluster every worker needs the package installed and the scenario file readable at the
same path (or send the scenario itself: a hawser.Scenario pickles with its text).
"""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

import pandas as pd

import hawser

SCENARIO = Path(__file__).resolve().parents[1] / "catenary_mooring.toml"


def load_case(scenario: hawser.Scenario, case: dict, duration: float) -> dict:
    """One row of the table: the run of `scenario` with the case's keys set, summarised."""
    res = scenario.with_overrides(case).run(duration=duration, progress=False)
    fairlead = res["chain.end_b.tension"]
    return {
        **case,
        "max_tension_kN": fairlead.max() / 1e3,
        "min_tension_kN": fairlead.min() / 1e3,
        "slack_intervals": len(res.slack_intervals),
        "complete": res.complete,
    }


def main(address: str | None = None, duration: float = 30.0) -> pd.DataFrame:
    from dask.distributed import Client, LocalCluster

    scenario = hawser.load(SCENARIO)
    # The load-case table: surge amplitude × current at the surface.
    amplitudes = [1.0, 2.0, 3.0, 4.0]
    surface_currents = [0.3, 0.6]
    cases = [
        {
            "points.fairlead.motion.amplitude": [a, 0.0, 0.0],
            "environment.current.profile": [[-150.0, 0.1, 0.0, 0.0], [-50.0, 0.35 * u / 0.6, 0.0, 0.0], [0.0, u, 0.0, 0.0]],
        }
        for a, u in itertools.product(amplitudes, surface_currents)
    ]
    # One thread per worker process: each run is sequential, the workers are the parallelism.
    cluster = None if address else LocalCluster(n_workers=2, threads_per_worker=1)
    with Client(address or cluster) as client:
        print(f"dask: {client}", file=sys.stderr)
        futures = [client.submit(load_case, scenario, c, duration, pure=False) for c in cases]
        rows = client.gather(futures)
    if cluster is not None:
        cluster.close()
    table = pd.DataFrame(rows)
    table.insert(0, "amplitude_m", [c["points.fairlead.motion.amplitude"][0] for c in cases])
    table.insert(1, "surface_current_m_s", [c["environment.current.profile"][2][1] for c in cases])
    return table.drop(columns=["points.fairlead.motion.amplitude", "environment.current.profile"])


if __name__ == "__main__":
    print(main(sys.argv[1] if len(sys.argv) > 1 else None).to_string(index=False))
