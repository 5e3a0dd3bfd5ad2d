#!/usr/bin/env bash
# Throughput benchmark: MoorDyn (MoorDyn-C Python bindings) vs hawser on the
# OC3-Hywind mooring deck.
#
# Usage: scripts/bench.sh [moordyn_bench.py options...]
#   Defaults: --dt 0.002 --duration 60 --amplitude 2 --period 10
#   Any option given on the command line overrides the default (e.g. --json,
#   --duration 120, --deck PATH, --repeats 5).
#
# Environment:
#   MOORDYN_VERSION  moordyn version to install into the venv (default 2.7.2)
#   BENCH_VENV       virtualenv path (default <repo>/.venv-bench, gitignored)
#   PYTHON           interpreter used to create the venv (default python3)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${BENCH_VENV:-$ROOT/.venv-bench}"
MOORDYN_VERSION="${MOORDYN_VERSION:-2.7.2}"
DECK="${MOORDYN_DECK:-$ROOT/../shared/moordyn-decks/oc3_lines.txt}"

# ---------------------------------------------------------------- MoorDyn side
if [ ! -x "$VENV/bin/python" ]; then
    echo "creating throwaway virtualenv $VENV" >&2
    "${PYTHON:-python3}" -m venv "$VENV"
fi
if ! "$VENV/bin/python" -c "
import sys
from importlib.metadata import version
sys.exit(0 if version('moordyn') == '$MOORDYN_VERSION' else 1)
" 2>/dev/null; then
    echo "installing moordyn==$MOORDYN_VERSION into $VENV" >&2
    "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
        "moordyn==$MOORDYN_VERSION" >&2
fi

"$VENV/bin/python" "$ROOT/scripts/moordyn_bench.py" \
    --deck "$DECK" --dt 0.002 --duration 60 --amplitude 2 --period 10 "$@"

# ------------------------------------------------------------------------------
# hawser side: hawser bench ... (added by the main developer)
# ------------------------------------------------------------------------------
