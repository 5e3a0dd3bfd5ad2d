"""Type stubs of the extension module ``hawser._hawser`` (the Rust half of the package)."""

from os import PathLike
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from ._results import Modes, Results, Statics

__version__: str

_Path = Union[str, PathLike]
_Array = npt.ArrayLike

def load(
    path: _Path, *, vessel_motion: Optional[_Path] = None, duration: Optional[float] = None
) -> Scenario:
    """Reads and validates a hawser scenario (TOML) or a MoorDyn v2 deck (recognised by its
    content). For a deck, ``vessel_motion`` (t, x, y, z, roll, pitch, yaw in s, m, deg) moves
    its coupled points and ``duration`` [s] sets its simulated time. Raises
    :class:`hawser.ScenarioError` for invalid input, ``OSError`` for a file it cannot read."""

def run_many(
    scenarios: Sequence[Scenario],
    workers: Optional[int] = None,
    *,
    duration: Optional[float] = None,
    out: Optional[Sequence[_Path]] = None,
    overwrite: bool = False,
    progress: bool = True,
) -> List[Results]:
    """Runs independent scenarios on ``workers`` threads of this process (default: one per
    core), the GIL released; results in order, each identical bit for bit to the same run
    done alone. A failed run raises once all have ended, with the list of results (None for
    the failed) as the exception's ``results``; Ctrl-C raises ``KeyboardInterrupt`` likewise."""

class Scenario:
    """A hawser TOML scenario or MoorDyn v2 deck, read and validated; immutable."""

    def __init__(
        self,
        source: str,
        path: Optional[_Path] = None,
        *,
        vessel_motion: Optional[_Path] = None,
        duration: Optional[float] = None,
        overrides: Optional[Mapping[str, Any]] = None,
    ) -> None:
        """The scenario of the text ``source`` (TOML or a deck), validated as if read from
        ``path`` (files it names are found beside it), with ``overrides`` set as by
        ``with_overrides``."""
    @staticmethod
    def from_toml(text: str, base_dir: Optional[_Path] = None) -> Scenario:
        """The scenario of TOML ``text``; files it names are looked for in ``base_dir``."""
    @staticmethod
    def from_dict(d: Mapping[str, Any], base_dir: Optional[_Path] = None) -> Scenario:
        """The scenario of a dict holding the TOML structure (``to_dict()``'s form)."""
    def with_overrides(self, overrides: Mapping[str, Any]) -> Scenario:
        """A new scenario with dotted keys set, e.g. ``{"lines.chain.length": 900.0,
        "points.fairlead.motion.amplitude": [2.0, 0.0, 0.0], "environment.waves.seed": 7}``:
        arrays of tables by element ``name`` (or index), arrays of numbers by index, ``None``
        removes a key. Raises :class:`hawser.ScenarioError` naming the key."""
    @property
    def overrides(self) -> Dict[str, Any]:
        """The dotted keys set on the input, in order, with their values (None: removed)."""
    def to_dict(self) -> Dict[str, Any]:
        """The TOML structure as a dict (a deck's hawser conversion)."""
    def to_toml(self) -> str:
        """The scenario as TOML (a deck's conversion, as ``hawser convert`` writes it)."""
    @property
    def path(self) -> str:
        """The file read, or the name the scenario was validated under."""
    @property
    def source(self) -> str:
        """The input's text, before overrides (``to_toml()`` gives the scenario with them)."""
    @property
    def format(self) -> str:
        """``"toml"`` or ``"moordyn"``."""
    @property
    def notes(self) -> List[str]:
        """What reading a MoorDyn deck converted or ignored."""
    @property
    def lines(self) -> List[str]:
        """Line names, in model order."""
    @property
    def points(self) -> List[str]:
        """Point names, in model order."""
    @property
    def bodies(self) -> List[str]:
        """Body names, in model order."""
    @property
    def duration(self) -> float:
        """Simulated duration of a run [s]."""
    def statics(self) -> Statics:
        """The static equilibrium, as ``hawser statics`` finds it."""
    def modes(self, count: int = 10, margin: float = 0.1) -> Modes:
        """The lowest ``count`` natural modes, connection stiffness and resonance report
        (``margin``: a fraction), as ``hawser modes`` computes them."""
    def run(
        self,
        duration: Optional[float] = None,
        out: Optional[_Path] = None,
        *,
        overwrite: bool = False,
        progress: bool = True,
    ) -> Results:
        """Runs the dynamics to ``duration`` [s] (default: the scenario's); with ``out``
        also writes the files of ``hawser run``. The GIL is released; Ctrl-C raises
        ``KeyboardInterrupt`` with the results so far as ``results`` (files flushed, marked
        interrupted); a divergence raises :class:`hawser.SimulationError` likewise."""
    def session(self) -> Session:
        """A coupling session of this scenario."""

class Session:
    """A run stepped by a coupling host (docs/coupling.md): kinematics of the coupled bodies
    (x, y, z [m], roll, pitch, yaw [rad]) then points (x, y, z [m]) at the end of each
    coupling interval in, forces and moments of the lines out (MoorDyn's layout)."""

    def __init__(self, scenario: Scenario) -> None: ...
    @property
    def scenario(self) -> Scenario: ...
    @property
    def coupled_dofs(self) -> int:
        """6 per coupled body, then 3 per coupled point."""
    @property
    def dof_names(self) -> List[str]:
        """Names of the coupled degrees of freedom (``"P4.x"``, ``"platform.yaw"``)."""
    @property
    def time(self) -> float:
        """Simulated time [s]."""
    @property
    def time_step(self) -> float:
        """The integrator's time step [s]."""
    @property
    def integrator(self) -> Dict[str, Any]:
        """What the time integration did so far (``summary.json``'s ``integrator``): scheme,
        reason, steps, time_step [s], generalized_alpha (steps, refused, newton_iterations,
        jacobians) and auto_switching (switches, rk4_time [s], rk4_at_end)."""
    @property
    def initialised(self) -> bool: ...
    @property
    def channels(self) -> List[str]:
        """Output channel names (the order of ``values()``)."""
    @property
    def units(self) -> List[str]:
        """Output channel units."""
    def init(
        self, x: Optional[_Array] = None, xd: Optional[_Array] = None, xdd: Optional[_Array] = None
    ) -> None:
        """Places the coupled objects at ``x`` (default: input positions), solves the statics
        there, sets the velocities ``xd`` (default: rest) and the accelerations ``xdd`` (for
        hosts that give them at every step)."""
    def step(
        self, t: float, dt: float, x: _Array, xd: _Array, xdd: Optional[_Array] = None
    ) -> np.ndarray:
        """Computes [t, t + dt] with the kinematics at its END, t + dt; returns the forces
        and moments of the lines on the coupled objects at t + dt. ``t`` is the session's
        time, or the start of the interval just computed (a corrector step)."""
    def set_coupled(self, t1: float, x: _Array, xd: _Array, xdd: Optional[_Array] = None) -> None:
        """Sets the coupled kinematics at ``t1``, the end of the next interval."""
    def advance_to(self, t: float) -> None:
        """Steps to ``t`` [s]; Ctrl-C stops it between two steps (KeyboardInterrupt)."""
    def forces(self) -> np.ndarray:
        """Forces [N] and moments [N·m] of the lines on the coupled objects now."""
    def point_force(self, name: str) -> np.ndarray:
        """Force [N] of the lines on a point now."""
    def release(self, line: Union[str, int], end: str) -> None:
        """Releases end "A" or "B" of a line from its attachment now (docs/failure.md); the
        end needs a `[lines.failure]` in the scenario."""
    @property
    def failures(self) -> List[Dict[str, Any]]:
        """The line failures so far: line, end, attachment, time [s], tension [N], cause."""
    def body_force(self, name: str) -> np.ndarray:
        """Force [N] and moment about the origin [N·m] of the lines on a body now."""
    def line_tension(self, line: Union[str, int]) -> np.ndarray:
        """Effective tension [N] at the nodes of a line, end A to end B."""
    def line_positions(self, line: Union[str, int]) -> np.ndarray:
        """Node positions [m] of a line, n × 3."""
    def values(self) -> np.ndarray:
        """The output channels' values now."""
    def checkpoint(self) -> bytes:
        """The session saved to bytes."""
    def restore(self, data: bytes) -> None:
        """Continues from ``checkpoint()`` bytes of a session of the same scenario."""
    def __getstate__(self) -> Tuple[Optional[List[float]], Optional[bytes]]: ...
    def __setstate__(self, state: Tuple[Optional[List[float]], Optional[bytes]]) -> None: ...
