"""hawser: marine cable dynamics from Python.

Statics, natural modes and time-domain simulation of mooring lines, towed cables, tethers and
umbilicals with the bodies and point masses on them, computed by hawser's Rust core.

>>> import hawser
>>> sc = hawser.load("examples/catenary_mooring.toml")      # a TOML scenario or MoorDyn deck
>>> st = sc.statics()                                         # static equilibrium
>>> st.lines["chain"].end_b_tension                           # fairlead tension [N]
>>> res = sc.run(duration=20.0)                               # dynamics
>>> res.timeseries                                            # pandas DataFrame, time index
>>> big = sc.with_overrides({"lines.chain.length": 690.0})    # a variation, validated
>>> many = hawser.run_many([sc, big], workers=2)              # in parallel, bit-identical

docs/python.md walks through it; docs/coupling.md explains the coupling ``Session``.
"""

from ._errors import Diagnostic, ScenarioError, SimulationError
from ._hawser import Scenario, Session, __version__, load, run_many
from ._results import (
    BodyState,
    LineModes,
    LineState,
    Modes,
    PointModes,
    PointState,
    Results,
    Statics,
)

__all__ = [
    "BodyState",
    "Diagnostic",
    "LineModes",
    "LineState",
    "Modes",
    "PointModes",
    "PointState",
    "Results",
    "Scenario",
    "ScenarioError",
    "Session",
    "SimulationError",
    "Statics",
    "__version__",
    "load",
    "run_many",
]
