"""The coupling session: a host stepping OC3's three fairleads (made `coupled`) with the
2 m, 10 s surge of examples/oc3_surge.toml reproduces the prescribed run; checkpoints and
pickles continue it bit for bit. docs/coupling.md states the semantics; the Rust test
crates/hawser-io/tests/coupling.rs makes the same comparison over 60 s."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import hawser
from conftest import EXAMPLES, OC3_DECK

FAIRLEADS = ["fairlead1", "fairlead2", "fairlead3"]
DT_C = 0.1  # coupling interval [s]
END = 10.0  # s
AMPLITUDE, PERIOD = 2.0, 10.0  # the surge of oc3_surge.toml: x = x0 + A sin(2π t / T)
# The fairleads' input positions [m].
X0 = np.array([5.2, 0.0, -70.0, -2.6, 4.5, -70.0, -2.6, -4.5, -70.0])


def surge(x0: np.ndarray, t: float):
    """Positions, velocities and accelerations of the three fairleads at t (flat, 9)."""
    w = math.tau * (1.0 / PERIOD)
    x, v, a = x0.copy(), np.zeros(9), np.zeros(9)
    s, c = math.sin(w * t), math.cos(w * t)
    for k in range(3):
        x[3 * k] += AMPLITUDE * s
        v[3 * k] = AMPLITUDE * w * c
        a[3 * k] = -AMPLITUDE * w * w * s
    return x, v, a


@pytest.fixture(scope="module")
def scenarios():
    prescribed = hawser.load(EXAMPLES / "oc3_surge.toml").with_overrides(
        {"simulation.output_interval": DT_C})
    coupled = prescribed.with_overrides(
        {**{f"points.{p}.type": "coupled" for p in FAIRLEADS},
         **{f"points.{p}.motion": None for p in FAIRLEADS}})
    return prescribed, coupled


def fairlead_tensions(forces: np.ndarray) -> np.ndarray:
    return np.linalg.norm(forces.reshape(3, 3), axis=1)


@pytest.mark.parametrize("accelerations", [True, False])
def test_coupled_stepping_equals_the_prescribed_run(scenarios, accelerations):
    prescribed, coupled = scenarios
    ref = prescribed.run(duration=END, progress=False)
    s = hawser.Session(coupled)
    assert s.coupled_dofs == 9
    assert s.dof_names[:3] == ["fairlead1.x", "fairlead1.y", "fairlead1.z"]
    # The surge starts at full velocity (no ramp): so do the coupled points.
    _, v0, a0 = surge(X0, 0.0)
    s.init(X0, v0, a0 if accelerations else None)
    x0 = X0
    got = []
    for k in range(1, round(END / DT_C) + 1):
        x, v, a = surge(x0, k * DT_C)
        f = s.step(s.time, DT_C, x, v, a if accelerations else None)
        got.append(fairlead_tensions(f))
    assert s.time == pytest.approx(END, abs=1e-12)
    got = np.array(got)
    want = np.column_stack([ref[f"L{k}.end_b.tension"][1:] for k in (1, 2, 3)])
    # With the accelerations the interpolant is quintic, exact for this motion but for
    # round-off: the Rust test's tolerance, 1e-9 of the tension (measured 1.2e-12). Without
    # them it is cubic, off by O(dt³) in velocity: the Rust test's 0.1 % (measured 2.3e-7).
    rel = np.max(np.abs(got - want)) / np.max(np.abs(want))
    assert rel < (1e-9 if accelerations else 1e-3), rel
    # The forces are the lines' reactions at the fairleads, as read point by point.
    assert np.allclose(s.point_force("fairlead1"), s.forces()[:3], rtol=0, atol=0)
    assert s.line_positions("L1").shape == (21, 3)
    assert s.line_tension(0).shape == (21,)


def test_the_session_reports_its_integrator(scenarios):
    """`Session.integrator` is `summary.json`'s `integrator` of the steps taken so far."""
    _, coupled = scenarios
    s = hawser.Session(coupled)
    s.init(X0)
    assert s.integrator["steps"] == 0
    run_on(s, X0, 1, 11)
    r = s.integrator
    assert r["steps"] > 0 and r["time_step"] == s.time_step
    assert r["reason"]
    if r["scheme"] == "rk4":
        # A fixed step: one step per time step of the second.
        assert r["steps"] == round(s.time / s.time_step)
        assert r["generalized_alpha"] is None and r["auto_switching"] is None
    else:
        assert r["scheme"] == "generalized-alpha", r
        g = r["generalized_alpha"]
        assert 0 < g["steps"] <= r["steps"] and g["newton_iterations"] >= g["steps"], r


def test_a_repeated_interval_replaces_the_first(scenarios):
    _, coupled = scenarios
    x0 = X0
    once, twice = hawser.Session(coupled), hawser.Session(coupled)
    once.init(x0)
    twice.init(x0)
    x, v, a = surge(x0, DT_C)
    twice.step(0.0, DT_C, x + 0.1, v, a)  # a first guess, then corrected
    f2 = twice.step(0.0, DT_C, x, v, a)
    f1 = once.step(0.0, DT_C, x, v, a)
    assert np.array_equal(f1, f2)


def run_on(s: hawser.Session, x0, start: int, stop: int):
    out = []
    for k in range(start, stop):
        x, v, a = surge(x0, k * DT_C)
        out.append(s.step(s.time, DT_C, x, v, a))
    return np.array(out)


def test_checkpoint_and_pickle_continue_bit_for_bit(scenarios):
    _, coupled = scenarios
    x0 = X0
    a = hawser.Session(coupled)
    a.init()
    run_on(a, x0, 1, 21)
    saved = a.checkpoint()
    assert isinstance(saved, bytes)
    pickled = pickle.dumps(a)
    rest = run_on(a, x0, 21, 41)
    b = hawser.Session(coupled)
    b.restore(saved)
    assert b.time == pytest.approx(2.0, abs=1e-12)
    assert np.array_equal(run_on(b, x0, 21, 41), rest)
    c = pickle.loads(pickled)
    assert c.time == pytest.approx(2.0, abs=1e-12)
    assert np.array_equal(run_on(c, x0, 21, 41), rest)
    # A session not yet initialised pickles too.
    d = pickle.loads(pickle.dumps(hawser.Session(coupled)))
    assert not d.initialised


def test_a_moordyn_deck_couples_its_coupled_points():
    s = hawser.load(OC3_DECK).session()
    assert s.dof_names == [f"P{p}.{c}" for p in (4, 5, 6) for c in "xyz"]
    s.init()
    f = s.step(0.0, DT_C, X0, np.zeros(9))
    assert f.shape == (9,) and np.all(np.isfinite(f))
    with pytest.raises(ValueError, match="9 coupled degrees of freedom"):
        s.step(s.time, DT_C, np.zeros(3), np.zeros(3))
    with pytest.raises(hawser.SimulationError, match="session is at"):
        s.step(5.0, DT_C, np.zeros(9), np.zeros(9))
    with pytest.raises(RuntimeError, match="not initialised"):
        hawser.load(OC3_DECK).session().forces()
    # A deck with overrides (set in its hawser conversion) is still a deck to a host.
    varied = hawser.load(OC3_DECK).with_overrides({"environment.water_density": 1030.0})
    assert varied.format == "moordyn" and varied.session().coupled_dofs == 9


def test_scenarios_pickle():
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml").with_overrides({"lines.chain.length": 690.0})
    back = pickle.loads(pickle.dumps(sc))
    assert back.path == sc.path and back.source == sc.source
    assert back.overrides == sc.overrides == {"lines.chain.length": 690.0}
    assert back.to_dict() == sc.to_dict()
    deck = pickle.loads(pickle.dumps(hawser.load(OC3_DECK, duration=3.0)))
    assert deck.format == "moordyn" and deck.duration == 3.0


def test_a_host_releases_a_line_and_a_failure_row_fires(tmp_path):
    """OC3 with a FAILURE row: line 1 lets go of fairlead P4 at 0.5 s (the row's time), the
    host releases line 2 at P5 itself (a row with both triggers 0), and an end without a
    failure is refused. Each fairlead then carries no line: its force is zero."""
    deck = OC3_DECK.read_text().replace(
        "---------------------- OPTIONS",
        "---------------------- FAILURE ----\n"
        "FailureID Point Line(s) FailTime FailTen\n"
        "() () (,) (s or 0) (N or 0)\n"
        "1 4 1 0.5 0\n"
        "2 5 2 0 0\n"
        "---------------------- OPTIONS",
        1,
    )
    path = tmp_path / "oc3_failure.txt"
    path.write_text(deck)
    s = hawser.load(path).session()
    s.init()
    for k in range(1, 11):
        s.step(s.time, DT_C, X0, np.zeros(9))
    (f,) = s.failures
    assert (f["line"], f["end"], f["attachment"], f["cause"]) == ("L1", "b", "P4", "time")
    assert 0.5 <= f["time"] < 0.5 + DT_C and f["tension"] > 1e5
    assert np.all(s.point_force("P4") == 0.0)
    assert np.linalg.norm(s.point_force("P5")) > 1e5
    with pytest.raises(hawser.SimulationError, match="no failure in the model"):
        s.release("L3", "B")
    s.release("L2", "B")
    assert [e["cause"] for e in s.failures] == ["time", "host"]
    assert np.all(s.point_force("P5") == 0.0)
    s.step(s.time, DT_C, X0, np.zeros(9))
