#!/usr/bin/env bash
# Throughput of the dg formulation for P = 1..6 against fe and hermite on the OC3 mooring
# (examples/oc3_surge.toml: 3 lines x 20 elements, switched to the automatic step), SSP-RK3
# (the DG paper's scheme), best of 3 runs each. Prints a markdown table for BENCHMARKS.md.
#
# Usage: scripts/bench_dg.sh [DURATION_S]   (default 1 s simulated)
#
# Nodal degrees of freedom ("nodes"): N + 1 per fe/hermite line, sum of (P + 1) per element
# for dg lines (the modal coefficients of q per element; v and the evolved r add the same
# count again twice, so a dg element of order P holds 9 (P + 1) numbers).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DURATION="${1:-1}"
cargo build --release -q -p hawser-cli --manifest-path "$ROOT/Cargo.toml"
HAWSER="${CARGO_TARGET_DIR:-$ROOT/target}/release/hawser"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
sed 's/^time_step = .*/time_step = "auto"/' "$ROOT/examples/oc3_surge.toml" > "$TMP/oc3.toml"
cp "$ROOT"/examples/*.txt "$TMP/" 2>/dev/null || true

run() { # formulation [order]
    local best=""
    for i in 1 2 3; do
        if [ -n "${2:-}" ]; then
            "$HAWSER" bench "$TMP/oc3.toml" --formulation "$1" --order "$2" --scheme ssp-rk3 --mass consistent --duration "$DURATION" --json > "$TMP/r$i.json"
        else
            "$HAWSER" bench "$TMP/oc3.toml" --formulation "$1" --scheme ssp-rk3 --mass consistent --duration "$DURATION" --json > "$TMP/r$i.json"
        fi
    done
    python3 - "$TMP" "$1" "${2:-}" <<'PY'
import json, sys, glob, os
runs = [json.load(open(f))[0] for f in sorted(glob.glob(os.path.join(sys.argv[1], "r*.json")))]
r = min(runs, key=lambda r: r["wall_s"])
form = sys.argv[2] + (f" P = {sys.argv[3]}" if sys.argv[3] else "")
print(f"| {form} | {r['nodes']} | {r['stable_step']:.3e} | {r['time_step']:.3e} | {r['steps']} | "
      f"{r['wall_s']:.3f} | {r['node_steps_per_s']:.3e} | {r['real_time_factor']:.3g} |")
PY
}

echo "OC3 mooring (examples/oc3_surge.toml, auto step), SSP-RK3, ${DURATION} s simulated, best of 3"
echo
echo "| formulation | nodal DOFs | stable limit [s] | step [s] | steps | wall [s] | node-steps/s | real time × |"
echo "|---|---|---|---|---|---|---|---|"
run fe
run hermite
for p in 1 2 3 4 5 6; do run dg "$p"; done
