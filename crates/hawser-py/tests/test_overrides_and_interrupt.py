"""Scenarios as dicts and overrides; Ctrl-C during a run keeps the results so far."""

from __future__ import annotations

import json
import os
import signal
import threading

import numpy as np
import pytest

import hawser
from conftest import EXAMPLES


def test_dict_round_trip_and_overrides():
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml")
    d = sc.to_dict()
    same = hawser.Scenario.from_dict(d, base_dir=EXAMPLES)
    a, b = sc.statics(), same.statics()
    assert np.array_equal(a.lines["chain"].tension, b.lines["chain"].tension)
    longer = sc.with_overrides({"lines.chain.length": 700.0, "environment.current": None})
    ld = longer.to_dict()
    assert ld["lines"][0]["length"] == 700.0 and "current" not in ld["environment"]
    assert longer.statics().lines["chain"].end_b_tension < a.lines["chain"].end_b_tension
    # Arrays of numbers by index, and the source is unchanged.
    moved = sc.with_overrides({"points.fairlead.position.2": -20.0})
    assert moved.to_dict()["points"][1]["position"] == [0.0, 0.0, -20.0]
    assert sc.to_dict() == d
    # numpy values are scenario values.
    np_amp = sc.with_overrides({"points.fairlead.motion.amplitude": np.array([1.0, 0.0, 0.0])})
    assert np_amp.to_dict()["points"][1]["motion"]["amplitude"] == [1.0, 0.0, 0.0]


@pytest.fixture
def ctrl_c():
    """Python's own Ctrl-C handler for the test (a process started in the background by a
    non-interactive shell inherits SIGINT ignored, and Python then installs no handler)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


class _Bar:
    """A progress bar that notes when the run has stepped, and can send Ctrl-C itself."""

    def __init__(self, send_inside):
        self.stepping = threading.Event()
        self.send_inside = send_inside

    def update_to(self, done):
        if done > 0.0 and not self.stepping.is_set():
            self.stepping.set()
            if self.send_inside:
                os.kill(os.getpid(), signal.SIGINT)

    def close(self):
        pass


@pytest.mark.parametrize("inside_the_bar", [False, True])
def test_ctrl_c_stops_a_run_and_keeps_its_results(tmp_path, monkeypatch, ctrl_c,
                                                   inside_the_bar):
    # Ctrl-C once the run is stepping: from another thread (as from the terminal), or while
    # the progress bar's Python code runs, where Python raises it inside the bar.
    import hawser._progress as progress

    bar = _Bar(inside_the_bar)
    monkeypatch.setattr(progress, "make_bar", lambda total, desc: bar)
    cancelled = threading.Event()

    def send():
        if bar.stepping.wait(60) and not cancelled.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=send)
    if not inside_the_bar:
        sender.start()
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml")
    try:
        with pytest.raises(KeyboardInterrupt) as info:
            sc.run(duration=6000.0, out=tmp_path / "run", progress=True)
    finally:
        cancelled.set()
        bar.stepping.set()
        if sender.is_alive():
            sender.join()
    res = info.value.results
    assert res.interrupted and not res.complete
    assert 0 < res.end_time < 6000.0
    status = json.loads((tmp_path / "run" / "status.json").read_text())
    assert status["state"] == "interrupted"
    rows = (tmp_path / "run" / "timeseries.csv").read_text().splitlines()
    assert len(rows) - 1 == len(res.time)
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["complete"] is False and summary["end_time"] == res.end_time


def test_runs_release_the_gil():
    """Another Python thread keeps running while a run computes (it would not get a single
    bytecode in if the run held the GIL)."""
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml")
    ticks, done = [0], threading.Event()

    def count():
        while not done.is_set():
            ticks[0] += 1

    t = threading.Thread(target=count)
    t.start()
    try:
        before = ticks[0]
        sc.run(duration=0.5, progress=False)
        during = ticks[0] - before
    finally:
        done.set()
        t.join()
    assert during > 1000, during
