"""run_many: independent runs on threads, identical bit for bit to the same runs done one
after the other; overrides build the load cases."""

from __future__ import annotations

import numpy as np

import hawser
from conftest import EXAMPLES


def cases():
    base = hawser.load(EXAMPLES / "catenary_mooring.toml")
    return [base.with_overrides({"points.fairlead.motion.amplitude": [a, 0.0, 0.0],
                                 "points.fairlead.motion.ramp_time": 0.5})
            for a in (1.0, 2.0, 3.0)]


def test_parallel_runs_equal_serial_runs_bit_for_bit():
    scs = cases()
    serial = [s.run(duration=1.0, progress=False) for s in scs]
    parallel = hawser.run_many(scs, workers=2, duration=1.0, progress=False)
    assert len(parallel) == 3
    for a, b in zip(serial, parallel):
        assert a.names == b.names
        assert np.array_equal(a.time, b.time)
        assert np.array_equal(a._values, b._values)
        assert a.summary == b.summary
        assert a.final_state == b.final_state
    # The amplitudes differ, so do the fairlead tensions.
    peaks = [r["chain.end_b.tension"].max() for r in parallel]
    assert peaks[0] < peaks[1] < peaks[2]


def test_a_failed_case_does_not_lose_the_others():
    scs = cases()
    bad = scs[0].with_overrides({"simulation.time_step": 0.5})
    try:
        hawser.run_many([scs[1], bad], workers=2, duration=0.5, progress=False)
    except hawser.ScenarioError as e:
        assert e.key == "simulation.time_step"
        assert e.results[0] is not None and e.results[0].complete
        assert e.results[1] is None
    else:
        raise AssertionError("the refused time step should raise")
