"""Invalid input raises hawser.ScenarioError carrying what the command line reports: file,
line, column, key, value, expected unit and range, hint; its text is the command line's."""

from __future__ import annotations

import pickle

import pytest

import hawser
from conftest import EXAMPLES, run_cli

def bad_copy(tmp_path):
    """The catenary example with a negative line diameter; the file and the line number."""
    lines = (EXAMPLES / "catenary_mooring.toml").read_text().splitlines()
    i = next(k for k, l in enumerate(lines) if l.startswith("diameter = "))
    lines[i] = "diameter = -0.1"
    f = tmp_path / "bad.toml"
    f.write_text("\n".join(lines) + "\n")
    return f, i + 1


def test_a_bad_file_gives_the_cli_diagnostic(hawser_bin, tmp_path):
    f, line = bad_copy(tmp_path)
    with pytest.raises(hawser.ScenarioError) as info:
        hawser.load(f)
    e = info.value
    assert isinstance(e, ValueError)
    assert (e.file, e.line, e.column) == (str(f), line, 12)
    assert e.key == "line_types[0].diameter"
    assert e.value == "-0.1"
    assert e.expected.startswith("m")
    assert e.unit == e.expected
    assert e.hint
    cli = run_cli(hawser_bin, "check", str(f), check=False)
    assert cli.returncode == 2
    assert str(e) == cli.stderr.strip()
    assert str(e.diagnostics[0]) == str(e)
    # It pickles (to cross process boundaries, e.g. Dask workers) with its attributes.
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.key, e2.line, str(e2)) == (e.key, e.line, str(e))


def test_a_bad_dict_names_the_key_and_the_line_of_its_toml():
    d = hawser.load(EXAMPLES / "catenary_mooring.toml").to_dict()
    d["line_types"][0]["axial_stiffness"] = -5.0
    with pytest.raises(hawser.ScenarioError) as info:
        hawser.Scenario.from_dict(d)
    e = info.value
    assert e.key == "line_types[0].axial_stiffness"
    assert e.value == "-5.0"
    assert e.file == "<dict>"
    text = hawser.Scenario.from_dict(hawser.load(EXAMPLES / "catenary_mooring.toml").to_dict()).to_toml()
    # The line and column point into the dict's TOML text.
    assert text.splitlines()[e.line - 1].strip().startswith("axial_stiffness")


def test_overrides_that_name_nothing_name_the_key():
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml")
    with pytest.raises(hawser.ScenarioError) as info:
        sc.with_overrides({"lines.chian.length": 900.0, "points.fairlead.position.x": 1.0})
    e = info.value
    assert [d.key for d in e.diagnostics] == ["lines.chian.length", "points.fairlead.position.x"]
    assert e.message == "`lines` has no element named `chian`"
    assert "did you mean `chain`?" in e.hint
    assert e.value == "900.0" and e.line == 0
    # A valid key with an invalid value: the validation's diagnostic, in the overridden text.
    with pytest.raises(hawser.ScenarioError) as info:
        sc.with_overrides({"lines.chain.length": -1.0})
    e = info.value
    assert e.key == "lines[0].length" and e.value == "-1.0"
    assert e.file.endswith("catenary_mooring.toml (with overrides)")


def test_a_time_step_above_the_limit_is_refused_at_its_key(hawser_bin, tmp_path):
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml").with_overrides(
        {"simulation.time_step": 0.5, "simulation.duration": 1.0, "statistics.start": 0.0})
    f = tmp_path / "big_step.toml"
    f.write_text(sc.to_toml())
    cli = run_cli(hawser_bin, "run", str(f), "--out", str(tmp_path / "o"), check=False)
    assert cli.returncode == 2
    with pytest.raises(hawser.ScenarioError) as info:
        hawser.load(f).run(progress=False)
    e = info.value
    assert e.key == "simulation.time_step" and e.value == "0.5"
    assert "stability limit" in e.message and e.hint
    assert str(e) in cli.stderr


def test_a_deck_error_names_the_deck_line(tmp_path):
    from conftest import OC3_DECK

    lines = OC3_DECK.read_text().splitlines()
    i = next(k for k, l in enumerate(lines) if l.split()[:1] == ["1"] and "Fixed" in l)
    lines[i] = lines[i].replace("Fixed", "Fixd")
    f = tmp_path / "deck.txt"
    f.write_text("\n".join(lines) + "\n")
    with pytest.raises(hawser.ScenarioError) as info:
        hawser.load(f)
    assert info.value.line == i + 1 and info.value.file == str(f)


def test_input_that_is_not_there_and_values_that_are_not_scenario_values(tmp_path):
    with pytest.raises(OSError):
        hawser.load(tmp_path / "missing.toml")
    with pytest.raises(TypeError, match="environment.depth"):
        hawser.Scenario.from_dict({"environment": {"depth": object()}})
    sc = hawser.load(EXAMPLES / "catenary_mooring.toml")
    with pytest.raises(ValueError, match="duration"):
        sc.run(duration=-1.0, progress=False)
