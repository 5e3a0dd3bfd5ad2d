"""Results of hawser's computations as Python objects: numpy arrays always, pandas
DataFrames when pandas is installed."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Optional

import numpy as np

try:  # pandas is optional
    import pandas as _pd
except ImportError:  # pragma: no cover - depends on the environment
    _pd = None


def _has_pandas() -> bool:
    return _pd is not None


def _frame(columns: Dict[str, Any], index: Optional[str] = None) -> Any:
    """A DataFrame of ``columns`` (index: the column ``index``), or the dict itself without
    pandas."""
    if _pd is None:
        return columns
    df = _pd.DataFrame(columns)
    if index is not None:
        df = df.set_index(index)
    return df


class Results:
    """The results of one dynamic run (``Scenario.run``), what ``hawser run`` writes.

    Attributes:
        time: sample times [s].
        names: output channel names (plain, as in ``summary.json``; units in ``units``).
        units: unit of each channel, ``{name: unit}``.
        summary: ``summary.json`` as a dict: per channel unit and design statistics (min, max
            and their times, mean, std, zero-up-crossing period, most probable extremes,
            linked values); per line its slack intervals, snap events and strength check;
            whether the run is complete.
        line_ranges: ``line_ranges.json`` as a dict: per line the minimum, mean and maximum
            tension at every node over the statistics window, and its sections.
        final_state: ``final_state.json`` as a dict (positions, velocities, tensions and end
            forces of every line, every point, the state vector).
        complete: whether the run reached its end time.
        error: why it stopped early (divergence, interruption), else None.
        interrupted: whether Ctrl-C stopped it.
        out: the folder its files were written into, if any.
    """

    def __init__(self, raw: Dict[str, Any]):
        self.time: np.ndarray = raw["time"]
        self._values: np.ndarray = raw["values"]
        self.names: List[str] = list(raw["names"])
        self.units: Dict[str, str] = dict(zip(self.names, raw["units"]))
        self.summary: Dict[str, Any] = raw.get("summary", {})
        self.line_ranges: Dict[str, Any] = raw.get("line_ranges", {})
        self.final_state: Dict[str, Any] = raw.get("final_state", {})
        self._snapshots: Dict[str, Dict[str, np.ndarray]] = raw.get("snapshots", {})
        self.complete: bool = raw["complete"]
        self.error: Optional[str] = raw["error"]
        self.interrupted: bool = raw["interrupted"]
        self.out: Optional[str] = raw["out"]

    @property
    def end_time(self) -> float:
        """Time of the last sample [s]."""
        return float(self.time[-1]) if len(self.time) else 0.0

    def __getitem__(self, name: str) -> np.ndarray:
        """The samples of channel ``name``."""
        try:
            return self._values[:, self.names.index(name)]
        except ValueError:
            raise KeyError(f"no channel named {name!r} (channels: {', '.join(self.names)})") from None

    def __contains__(self, name: object) -> bool:
        return name in self.names

    def to_dict(self) -> Dict[str, np.ndarray]:
        """The time series as a dict of arrays: ``"time"`` [s], then every channel."""
        d = {"time": self.time}
        d.update({n: self._values[:, i] for i, n in enumerate(self.names)})
        return d

    @property
    def timeseries(self) -> Any:
        """The time series: a pandas DataFrame indexed by time [s] with a column per channel
        (units in ``df.attrs["units"]``), or without pandas the dict of ``to_dict()``."""
        if _pd is None:
            return self.to_dict()
        df = _pd.DataFrame(self._values, columns=self.names,
                           index=_pd.Index(self.time, name="time"))
        df.attrs["units"] = {"time": "s", **self.units}
        return df

    @property
    def statistics(self) -> Any:
        """Per channel its unit and design statistics over the statistics window (min and
        max with their times, mean, standard deviation, zero-up-crossing period, most
        probable extremes, linked values; a DataFrame indexed by channel, or a dict of
        dicts)."""
        ch = self.summary.get("channels", {})
        rows = {n: ch[n] for n in self.names if n in ch}
        if _pd is None:
            return rows
        df = _pd.DataFrame.from_dict(rows, orient="index")
        df.index.name = "channel"
        return df

    def _events(self, kind: str, fields: List[str]) -> Any:
        rows = [
            {"line": line, **{f: e[f] for f in fields}}
            for line, events in self.summary.get("lines", {}).items()
            for e in events[kind]
        ]
        if _pd is None:
            return rows
        return _pd.DataFrame(rows, columns=["line", *fields])

    @property
    def slack_intervals(self) -> Any:
        """Intervals during which some element of a line was slack: line, start [s], end [s],
        smallest strain [-] (a DataFrame, or a list of dicts)."""
        return self._events("slack_intervals", ["start", "end", "min_strain"])

    @property
    def snap_events(self) -> Any:
        """Snap loads (a slack line going taut): line, time [s] of the transition, peak time
        [s], peak tension [N], location (arc length from end A [m]) and mean rise rate [N/s]
        (a DataFrame, or a list of dicts)."""
        return self._events(
            "snap_events", ["time", "peak_time", "peak_tension", "location", "rise_rate"]
        )

    @property
    def snapshots(self) -> Dict[str, Any]:
        """Line shapes every ``snapshot_interval``: per line the columns of
        ``snapshots/LINE.csv`` (time [s], node, arc_length [m], x, y, z [m], tension [N]), as a
        DataFrame or a dict of arrays."""
        return {line: _frame(dict(cols)) for line, cols in self._snapshots.items()}

    def snapshot(self, line: str, time: float) -> Dict[str, np.ndarray]:
        """The shape of ``line`` at the snapshot time nearest ``time`` [s]: ``time``,
        ``arc_length`` [m], ``position`` (n × 3) [m] and ``tension`` [N]."""
        s = self._snapshots[line]
        times = np.unique(s["time"])
        if len(times) == 0:
            raise KeyError(f"line {line!r} has no snapshots")
        t = times[np.argmin(np.abs(times - time))]
        m = s["time"] == t
        return {
            "time": float(t),
            "arc_length": s["arc_length"][m],
            "position": np.column_stack([s["x"][m], s["y"][m], s["z"][m]]),
            "tension": s["tension"][m],
        }

    def __repr__(self) -> str:
        state = "complete" if self.complete else ("interrupted" if self.interrupted else "stopped")
        return (f"<hawser.Results {len(self.time)} samples to t = {self.end_time:g} s, "
                f"{len(self.names)} channels, {state}>")


@dataclass(frozen=True)
class LineState:
    """One line at rest: its nodes from end A to end B.

    Attributes:
        arc_length: unstretched arc length of each node from end A [m].
        position: node positions, n × 3 [m].
        tension: effective tension at each node [N].
        end_a_force: force the line exerts on its end A attachment [N].
        end_b_force: force the line exerts on its end B attachment [N].
    """

    arc_length: np.ndarray
    position: np.ndarray
    tension: np.ndarray
    end_a_force: np.ndarray
    end_b_force: np.ndarray

    @property
    def end_a_tension(self) -> float:
        """Tension at end A (the norm of its end force) [N]."""
        return float(np.linalg.norm(self.end_a_force))

    @property
    def end_b_tension(self) -> float:
        """Tension at end B (the norm of its end force) [N]."""
        return float(np.linalg.norm(self.end_b_force))


@dataclass(frozen=True)
class PointState:
    """A point at rest: position [m], the force of its lines on it [N], and its kind
    (fixed, prescribed, coupled, free, on a body)."""

    position: np.ndarray
    force: np.ndarray
    kind: str


@dataclass(frozen=True)
class BodyState:
    """A rigid body at rest: origin position [m], orientation roll, pitch, yaw [deg]
    (R = Rz(yaw) Ry(pitch) Rx(roll)) and the load of its lines, force [N] and moment about
    its origin [N·m]."""

    position: np.ndarray
    orientation: np.ndarray
    line_load: np.ndarray


class Statics:
    """The static equilibrium (``Scenario.statics``), as ``hawser statics`` reports it.

    Attributes:
        lines: per line name a :class:`LineState`.
        points: per point name a :class:`PointState`.
        bodies: per body name a :class:`BodyState`.
        method: the solver that converged; ``iterations`` and ``residual`` [N] its figures.
        tow_velocity: the velocity [m/s] of a steady tow's frame, else None.
    """

    def __init__(self, raw: Dict[str, Any]):
        self.method: str = raw["method"]
        self.iterations: int = raw["iterations"]
        self.residual: float = raw["residual"]
        self.lines: Dict[str, LineState] = {n: LineState(**d) for n, d in raw["lines"].items()}
        self.points: Dict[str, PointState] = {n: PointState(**d) for n, d in raw["points"].items()}
        self.bodies: Dict[str, BodyState] = {n: BodyState(**d) for n, d in raw["bodies"].items()}
        self.tow_velocity: Optional[np.ndarray] = raw["tow_velocity"]

    @property
    def table(self) -> Any:
        """Per line the tension at end A, at end B and the largest node tension [N], as
        ``hawser statics`` prints them (a DataFrame indexed by line, or a dict)."""
        rows = {
            name: {
                "end_a_tension": l.end_a_tension,
                "end_b_tension": l.end_b_tension,
                "max_tension": float(np.max(l.tension, initial=0.0)),
            }
            for name, l in self.lines.items()
        }
        if _pd is None:
            return rows
        df = _pd.DataFrame.from_dict(rows, orient="index")
        df.index.name = "line"
        return df

    def __repr__(self) -> str:
        return (f"<hawser.Statics {self.method}, {self.iterations} iterations, residual "
                f"{self.residual:.2e} N, {len(self.lines)} lines>")


@dataclass(frozen=True)
class LineModes:
    """The mode shapes of one line: ``arc_length`` [m] and static ``position`` (n × 3) [m]
    of its nodes, and ``shapes`` (modes × n × 3) [-], each mode scaled so that its largest
    nodal displacement over the whole system is 1."""

    arc_length: np.ndarray
    position: np.ndarray
    shapes: np.ndarray


@dataclass(frozen=True)
class PointModes:
    """The mode shapes at a free point: static ``position`` [m] and ``shapes`` (modes × 3)."""

    position: np.ndarray
    shapes: np.ndarray


class Modes:
    """Natural modes about the static state (``Scenario.modes``), as ``hawser modes``
    computes them.

    Attributes:
        frequencies: natural frequencies [Hz], lowest first.
        periods: natural periods [s].
        labels: each mode in words ("first in-plane mode of line L1").
        lines: per line its :class:`LineModes`; ``points``: per free point its
            :class:`PointModes`.
        stiffness: per fixed or prescribed point the 3 × 3 stiffness the lines offer it
            [N/m], free points and nodes relaxed.
        resonance: the scenario's periodic excitations against the natural frequencies.
        document: ``modes.json`` as a dict.
    """

    def __init__(self, raw: Dict[str, Any]):
        self.document: Dict[str, Any] = raw["document"]
        modes = self.document["modes"]
        self.frequencies = np.array([m["frequency_hz"] for m in modes])
        self.periods = np.array([m["period_s"] for m in modes])
        self.labels: List[str] = [m["label"] for m in modes]
        self.lines: Dict[str, LineModes] = {n: LineModes(**d) for n, d in raw["lines"].items()}
        self.points: Dict[str, PointModes] = {n: PointModes(**d) for n, d in raw["points"].items()}
        self.stiffness: Dict[str, np.ndarray] = dict(raw["stiffness"])
        self.resonance: List[Dict[str, Any]] = self.document["resonance"]["checks"]

    @property
    def table(self) -> Any:
        """Mode number, frequency [Hz], period [s] and label (a DataFrame, or a dict)."""
        cols = {
            "mode": np.arange(1, len(self.frequencies) + 1),
            "frequency": self.frequencies,
            "period": self.periods,
            "label": self.labels,
        }
        return _frame(cols, index="mode")

    def __len__(self) -> int:
        return len(self.frequencies)

    def __repr__(self) -> str:
        f = ", ".join(f"{x:.4g}" for x in self.frequencies[:4])
        return f"<hawser.Modes {len(self)} modes: {f}{', ...' if len(self) > 4 else ''} Hz>"


