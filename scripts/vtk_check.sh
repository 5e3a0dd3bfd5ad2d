#!/usr/bin/env bash
# hawser's ParaView, Parquet and CSV files read back by the tools users load them with (CI,
# after scripts/c_check.sh): runs scripts/vtk_check.toml (a line of each formulation, a body of
# each shape, points; about 2 s), then scripts/vtk_check.py reads every .vtp of vtk/run.pvd with
# VTK's XML reader (the PyPI `vtk` package) and checks positions and data against the snapshot
# CSVs bit for bit, body volumes and outward normals; timeseries.parquet with pyarrow and pandas
# (values equal to the CSV's bit for bit, units and model hash in the metadata); timeseries.csv
# with one pd.read_csv call (float columns, exact values, times k × 0.1).
# The packages go into a throwaway virtual environment (installing them takes about a minute
# without a pip cache):
#   VTK_CHECK_VENV  reuse this venv (created if missing) instead of a temporary one
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
VENV="${VTK_CHECK_VENV:-$TMP/venv}"
PACKAGES="vtk==9.7.2 pyarrow==26.0.1 pandas==3.1.1"
if [ ! -x "$VENV/bin/python" ]; then
    "${PYTHON:-python3}" -m venv "$VENV"
fi
start=$(date +%s)
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check $PACKAGES
echo "vtk_check: $PACKAGES ready in $(( $(date +%s) - start )) s" >&2
# The binary as the workspace suite builds it (nothing to do after `cargo test --workspace
# --release`; building hawser-cli alone unifies fewer features and rebuilds the tree).
cargo test --release --workspace --no-run -q
target/release/hawser run scripts/vtk_check.toml --out "$TMP/out" --quiet
"$VENV/bin/python" scripts/vtk_check.py "$TMP/out"
