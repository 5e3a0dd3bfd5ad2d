"""Shared fixtures of the Python package's tests (run by scripts/python_check.sh).

The command-line binary they compare against is ``$HAWSER_BIN``, else
``target/release/hawser`` of the checkout."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"
OC3_DECK = ROOT / "tests" / "data" / "moordyn" / "oc3_lines.txt"


@pytest.fixture(scope="session")
def hawser_bin() -> Path:
    b = Path(os.environ.get("HAWSER_BIN", ROOT / "target" / "release" / "hawser"))
    if not b.exists():
        pytest.fail(f"{b} is missing: build it with `cargo build --release -p hawser-cli`")
    return b


def run_cli(hawser_bin: Path, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    """Runs the command-line tool; returns the completed process (text output)."""
    p = subprocess.run([str(hawser_bin), *args], capture_output=True, text=True, cwd=ROOT)
    if check and p.returncode != 0:
        raise AssertionError(f"hawser {' '.join(args)} exited {p.returncode}:\n{p.stderr}")
    return p
