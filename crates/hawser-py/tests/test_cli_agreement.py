"""The package's statics and runs equal the command line's on the bundled examples.

Both compute with the same core and hawser-io code, so the numbers must agree to round-off:
the CSV and JSON files print every float in its shortest round-trip form, so a parsed value
is the computed one exactly. The tolerance 1e-12 (relative to each channel's largest
magnitude) leaves room only for printing, not for a different computation."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

import hawser
from conftest import EXAMPLES, OC3_DECK, ROOT, run_cli

TOL = 1e-12
# Short runs keep the suite to seconds: (example, duration [s]).
CASES = [
    ("catenary_mooring.toml", 1.0),
    ("snapping_cable_0807.toml", 2.0),
    ("taut_tether_payload.toml", 2.0),
    ("wave_buoy.toml", 2.0),
    ("towing_system1_body.toml", 2.0),
]


def close(a, b, tol=TOL):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape
    scale = max(np.max(np.abs(a), initial=0.0), 1e-300)
    return np.max(np.abs(a - b), initial=0.0) <= tol * scale


def read_csv(path: Path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header = rows[0]
    data = np.array([[float(x) for x in r] for r in rows[1:]])
    return header, data


@pytest.mark.parametrize("name", [c[0] for c in CASES] + ["oc3_lines.txt"])
def test_statics_equal_the_cli(hawser_bin, name):
    path = OC3_DECK if name == "oc3_lines.txt" else EXAMPLES / name
    cli = json.loads(run_cli(hawser_bin, "statics", str(path), "--json").stdout)
    st = hawser.load(path).statics()
    assert st.method == cli["solver"]["method"]
    assert st.iterations == cli["solver"]["iterations"]
    for line, c in cli["lines"].items():
        ours = st.lines[line]
        assert close(ours.position, c["positions"]), line
        assert close(ours.tension, c["tension"]), line
        assert close(ours.end_a_force, c["end_a"]["force"]), line
        assert close(ours.end_b_force, c["end_b"]["force"]), line
        assert abs(ours.end_b_tension - c["end_b"]["tension"]) <= TOL * c["end_b"]["tension"]
    for point, c in cli["points"].items():
        assert close(st.points[point].position, c["position"]), point


def short_copy(tmp_path: Path, name: str, duration: float) -> tuple[hawser.Scenario, Path]:
    """The example with `simulation.duration` overridden, and the same scenario written to a
    file for the command line."""
    overrides = {"simulation.duration": duration}
    if name == "catenary_mooring.toml":
        # Its statistics window starts after its 24 s ramp: within the shortened run.
        overrides["statistics.start"] = 0.0
    sc = hawser.load(EXAMPLES / name).with_overrides(overrides)
    f = tmp_path / name
    f.write_text(sc.to_toml())
    return hawser.load(f), f


@pytest.mark.parametrize("name,duration", CASES)
def test_runs_equal_the_cli(hawser_bin, tmp_path, name, duration):
    sc, f = short_copy(tmp_path, name, duration)
    cli_out = tmp_path / "cli"
    run_cli(hawser_bin, "run", str(f), "--out", str(cli_out), "--quiet")
    res = sc.run(progress=False, out=tmp_path / "py")
    header, data = read_csv(cli_out / "timeseries.csv")
    assert header == ["time", *res.names]
    assert close(res.time, data[:, 0])
    for i, n in enumerate(res.names):
        assert close(res[n], data[:, i + 1]), n
    # Units: channels.json's, and the DataFrame's attrs.
    units = json.loads((cli_out / "channels.json").read_text())["timeseries"]
    assert units["time"] == "s"
    assert [units[n] for n in res.names] == [res.units[n] for n in res.names]
    # Summary (statistics, slack, snaps) and final state: the same documents.
    summary = json.loads((cli_out / "summary.json").read_text())
    assert_json_close(res.summary, summary)
    assert_json_close(res.line_ranges, json.loads((cli_out / "line_ranges.json").read_text()))
    assert_json_close(res.final_state, json.loads((cli_out / "final_state.json").read_text()))
    # Snapshots: the same shapes at the same times.
    for line, cols in res._snapshots.items():
        h, d = read_csv(cli_out / "snapshots" / f"{line}.csv")
        assert h == ["time", "node", "arc_length", "x", "y", "z", "tension"]
        for k, c in enumerate(h):
            assert close(cols[c], d[:, k]), (line, c)
    # The files written from Python are the command line's, byte for byte.
    for file in ["timeseries.csv", "summary.json", "line_ranges.json", "final_state.json"]:
        assert (tmp_path / "py" / file).read_bytes() == (cli_out / file).read_bytes(), file
    status = json.loads((tmp_path / "py" / "status.json").read_text())
    assert status["complete"] and status["state"] == "finished"


def assert_json_close(a, b, path="$"):
    if isinstance(b, dict):
        assert isinstance(a, dict) and set(a) == set(b), path
        for k in b:
            assert_json_close(a[k], b[k], f"{path}.{k}")
    elif isinstance(b, list):
        assert isinstance(a, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            assert_json_close(x, y, f"{path}[{i}]")
    elif isinstance(b, float):
        assert abs(a - b) <= TOL * max(abs(b), 1e-300), (path, a, b)
    else:
        assert a == b, (path, a, b)


def test_a_moordyn_deck_runs_as_on_the_command_line(hawser_bin, tmp_path):
    cli_out = tmp_path / "cli"
    run_cli(hawser_bin, "run", str(OC3_DECK), "--duration", "2", "--out", str(cli_out), "--quiet")
    sc = hawser.load(OC3_DECK, duration=2.0)
    assert sc.format == "moordyn" and sc.duration == 2.0
    res = sc.run(progress=False)
    header, data = read_csv(cli_out / "timeseries.csv")
    assert header == ["time", *res.names]
    for i, n in enumerate(res.names):
        assert close(res[n], data[:, i + 1]), n


def test_results_as_dataframe_and_as_arrays():
    pd = pytest.importorskip("pandas")
    # The example's statistics window starts at 24 s, after its ramp: from 0 in this short run.
    res = hawser.load(EXAMPLES / "catenary_mooring.toml").with_overrides(
        {"statistics.start": 0.0}).run(duration=0.5, progress=False)
    df = res.timeseries
    assert isinstance(df, pd.DataFrame)
    assert df.index.name == "time" and list(df.columns) == res.names
    assert df.attrs["units"]["chain.end_b.tension"] == "N"
    assert df.attrs["units"]["time"] == "s"
    assert np.array_equal(df["chain.node68.z"].to_numpy(), res["chain.node68.z"])
    d = res.to_dict()
    assert np.array_equal(d["time"], res.time) and set(d) == {"time", *res.names}
    stats = res.statistics
    assert stats.loc["chain.end_b.tension", "unit"] == "N"
    assert stats.loc["chain.end_b.tension", "max"] == pytest.approx(res["chain.end_b.tension"].max(), rel=0)
    shape = res.snapshot("chain", 0.0)
    assert shape["position"].shape == (137, 3) and shape["time"] == 0.0


def test_modes_equal_the_cli(hawser_bin):
    path = EXAMPLES / "oc3_modes.toml"
    cli = json.loads(run_cli(hawser_bin, "modes", str(path), "--json", "--count", "6").stdout)
    m = hawser.load(path).modes(count=6)
    assert len(m) == 6
    assert close(m.frequencies, [x["frequency_hz"] for x in cli["modes"]])
    assert m.labels == [x["label"] for x in cli["modes"]]
    for name, c in cli["stiffness"].items():
        assert close(m.stiffness[name], c["matrix_n_per_m"]), name
    assert [r["source"] for r in m.resonance] == [r["source"] for r in cli["resonance"]["checks"]]
    for line, lm in m.lines.items():
        assert lm.shapes.shape == (6, len(lm.arc_length), 3)
    # Each mode is scaled to a largest nodal displacement of 1 over the system (an fe model:
    # every displacement group is a node or a free point).
    per_object = [np.max(np.linalg.norm(lm.shapes, axis=2), axis=1) for lm in m.lines.values()]
    per_object += [np.linalg.norm(pm.shapes, axis=1) for pm in m.points.values()]
    largest = np.max(per_object, axis=0)
    assert np.allclose(largest, 1.0, rtol=0, atol=1e-12)
