#!/usr/bin/env bash
# The Python package checked from Python: builds the abi3 wheel of crates/hawser-py with
# maturin in a throwaway virtual environment (python3 -m venv; maturin, numpy, pandas and
# pytest from PyPI), installs it, and runs pytest over crates/hawser-py/tests/ against the
# command-line binary (results equal to the CLI's, errors, coupling, checkpoints, run_many).
# The wheel build in release is the main cost (docs/python.md gives the times).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
PYTHON="${PYTHON:-python3}"
VENV="$(mktemp -d)/venv"
trap 'rm -rf "$(dirname "$VENV")"' EXIT
"$PYTHON" -m venv "$VENV"
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
    "maturin>=1.7,<2" numpy pandas pytest
# The binary the tests compare against, as the workspace suite builds it (nothing to do after
# `cargo test --workspace --release`; building hawser-cli alone would rebuild the tree).
cargo test --release --workspace --no-run -q
start=$(date +%s)
"$VENV/bin/maturin" build --release --quiet -m crates/hawser-py/Cargo.toml \
    -i "$VENV/bin/python" -o "$(dirname "$VENV")/wheels"
echo "wheel built in $(( $(date +%s) - start )) s"
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
    "$(dirname "$VENV")"/wheels/hawser_cable-*.whl
# Run from the tests' folder, not the checkout's root, so that `import hawser` is the
# installed wheel.
cd crates/hawser-py/tests
HAWSER_BIN="$ROOT/target/release/hawser" "$VENV/bin/python" -m pytest -q -p no:cacheprovider .
