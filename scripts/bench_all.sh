#!/usr/bin/env bash
# Every speed target of hawser against MoorDyn 2.7.2, in one run: OC3 at the same step and at
# each code's best step, OC3 in a 200-component JONSWAP sea, a 1000 m chain at 20 to 1280
# segments, the stiff-seabed chain, `scheme = "auto"` on the README example and OC3, the
# parameter sweep. Paired CPU-time ratios (the machine may be shared). What it prints and
# how: scripts/bench_all.py. Results are recorded in BENCHMARKS.md.
#
# Usage: scripts/bench_all.sh [bench_all.py options: --repeats N, --duration S, --segments
#        20,40,..., --chain-duration S, --only PARTS, --record]
# Environment: as scripts/moordyn_venv.sh (BENCH_VENV, MOORDYN_VERSION, PYTHON).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/moordyn_venv.sh"
cargo build --release -q -p hawser-cli --manifest-path "$ROOT/Cargo.toml"
exec "$VENV/bin/python" "$ROOT/scripts/bench_all.py" --hawser "$ROOT/target/release/hawser" "$@"
