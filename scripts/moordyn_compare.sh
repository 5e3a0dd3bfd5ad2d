#!/usr/bin/env bash
# hawser vs MoorDyn (MoorDyn-C Python bindings) on the public MoorDyn decks:
# statics of every deck, OC3 surge at 20/40/80 segments, WD0200 chain under
# the ZZP1_A1 heave against MoorDyn and the reference series, a free body
# (buoy_oc3.txt) in statics and in a surge of its vessel point.
#
# Usage: scripts/moordyn_compare.sh [moordyn_compare.py options...]
#   e.g. --segments 20 (skip the refined OC3 runs), --keep-tmp
#
# Writes tests/data/moordyn_reference.json, docs/data/moordyn_*.csv and
# docs/img/moordyn_*.svg; prints a markdown summary on stdout.
#
# Environment:
#   MOORDYN_VERSION   moordyn version to install into the venv (default 2.7.2)
#   BENCH_VENV        virtualenv path (default <repo>/.venv-bench, gitignored;
#                     shared with scripts/bench.sh)
#   PYTHON            interpreter used to create the venv (default python3)
#   CARGO_TARGET_DIR  cargo target directory (default <repo>/target)
#   MOORDYN_DECKS     deck directory (default <repo>/tests/data/moordyn)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DECKS="${MOORDYN_DECKS:-$ROOT/tests/data/moordyn}"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"

# ---------------------------------------------------------------- MoorDyn side
. "$ROOT/scripts/moordyn_venv.sh"

# ---------------------------------------------------------------- hawser side
CARGO_TARGET_DIR="$TARGET" cargo build --release -q -p hawser-cli \
    --manifest-path "$ROOT/Cargo.toml"

exec "$VENV/bin/python" "$ROOT/scripts/moordyn_compare.py" \
    --hawser "$TARGET/release/hawser" --decks "$DECKS" "$@"
