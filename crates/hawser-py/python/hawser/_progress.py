"""Progress bars of long runs: tqdm's when it is installed (a widget in a notebook), else a
one-line bar of hawser's own on standard error."""

from __future__ import annotations

import sys
import time
from typing import Any


class _Bar:
    """A text bar: percentage, simulated time, real-time factor and remaining wall time."""

    def __init__(self, total: float, desc: str):
        self.total = max(float(total), 1e-12)
        self.desc = desc
        self.start = time.monotonic()
        self.last_draw = 0.0
        self.done = 0.0
        self.stream = sys.stderr

    def update_to(self, done: float) -> None:
        self.done = min(float(done), self.total)
        now = time.monotonic()
        if now - self.last_draw >= 0.25:
            self.last_draw = now
            self._draw(now)

    def _draw(self, now: float) -> None:
        wall = now - self.start
        frac = self.done / self.total
        width = 30
        filled = int(round(width * frac))
        speed = self.done / wall if wall > 0 else 0.0
        eta = (self.total - self.done) / speed if speed > 0 else float("nan")
        self.stream.write(
            f"\r{self.desc} |{'#' * filled}{' ' * (width - filled)}| {100 * frac:3.0f}% "
            f"{self.done:.1f}/{self.total:.1f} s simulated, {speed:.1f}x real time, "
            f"ETA {eta:.0f} s "
        )
        self.stream.flush()

    def close(self) -> None:
        self._draw(time.monotonic())
        self.stream.write("\n")
        self.stream.flush()


class _Tqdm:
    def __init__(self, tqdm: Any, total: float, desc: str):
        self.bar = tqdm(total=round(float(total), 3), desc=desc, unit="s", unit_scale=False,
                        bar_format="{l_bar}{bar}| {n:.1f}/{total:.1f} s [{elapsed}<{remaining}]")

    def update_to(self, done: float) -> None:
        self.bar.update(round(min(float(done), self.bar.total), 3) - self.bar.n)

    def close(self) -> None:
        self.bar.close()


def make_bar(total: float, desc: str) -> Any:
    """A bar for ``total`` seconds of simulated time, with ``update_to(seconds)`` and
    ``close()``."""
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return _Bar(total, desc)
    return _Tqdm(tqdm, total, desc)
