"""The exceptions of hawser: input diagnostics and simulation failures."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Optional


@dataclass(frozen=True)
class Diagnostic:
    """One problem in an input, as the command line reports it.

    Attributes:
        message: what is wrong.
        file: the file (or the name a scenario given as text or a dict was validated under).
        line: 1-based line of the offending value (0 when the problem has no place in the
            text, such as an override key that names nothing).
        column: 1-based column.
        key: the dotted key, e.g. ``lines[0].length`` or ``lines.chain.length``.
        value: the value as written.
        expected: the unit and range expected, e.g. ``"m, > 0"``.
        hint: how to fix it.
        text: the whole report with the source line, as ``hawser check`` prints it.
    """

    message: str
    file: str
    line: int
    column: int
    key: str
    value: str
    expected: str
    hint: str
    text: str

    @property
    def unit(self) -> str:
        """The unit and range expected (``expected``)."""
        return self.expected

    def __str__(self) -> str:
        return self.text


class ScenarioError(ValueError):
    """An input (scenario file, MoorDyn deck, dict, override) is invalid.

    ``str(e)`` is the command line's report. The first problem's ``file``, ``line``,
    ``column``, ``key``, ``value``, ``expected`` (unit and range) and ``hint`` are attributes;
    ``diagnostics`` lists every problem found.
    """

    diagnostics: List[Diagnostic]

    def __init__(self, text: str, diagnostics: List[Diagnostic]):
        super().__init__(text)
        self.text = text
        self.diagnostics = list(diagnostics)

    def _first(self, name: str) -> Any:
        return getattr(self.diagnostics[0], name) if self.diagnostics else ""

    @property
    def message(self) -> str:
        """What is wrong (the first problem)."""
        return self._first("message")

    @property
    def file(self) -> str:
        """The file of the first problem."""
        return self._first("file")

    @property
    def line(self) -> int:
        """1-based line of the first problem (0: no place in the text)."""
        return self._first("line") or 0

    @property
    def column(self) -> int:
        """1-based column of the first problem."""
        return self._first("column") or 0

    @property
    def key(self) -> str:
        """Dotted key of the first problem."""
        return self._first("key")

    @property
    def value(self) -> str:
        """The value of the first problem as written."""
        return self._first("value")

    @property
    def expected(self) -> str:
        """The unit and range expected at the first problem."""
        return self._first("expected")

    @property
    def unit(self) -> str:
        """The unit and range expected at the first problem (``expected``)."""
        return self.expected

    @property
    def hint(self) -> str:
        """How to fix the first problem."""
        return self._first("hint")

    def __str__(self) -> str:
        return self.text

    def __reduce__(self):
        return (type(self), (self.text, self.diagnostics))


class SimulationError(RuntimeError):
    """The statics, a run or a coupling step failed (no equilibrium found, a divergence with
    the time, line and node, kinematics a session refuses).

    A run that stopped part-way carries its results so far as ``results``
    (a :class:`hawser.Results`, or for ``run_many`` the list of them).
    """

    results: Optional[Any] = None
