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
DECK="${MOORDYN_DECK:-$ROOT/tests/data/moordyn/oc3_lines.txt}"

# ---------------------------------------------------------------- MoorDyn side
. "$ROOT/scripts/moordyn_venv.sh"

OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
"$VENV/bin/python" "$ROOT/scripts/moordyn_bench.py" \
    --deck "$DECK" --dt 0.002 --duration 60 --amplitude 2 --period 10 --repeats 3 "$@" --json \
    > "$OUT/moordyn.json"

# ---------------------------------------------------------------- hawser side
# The same deck read directly by hawser (3 lines x 20 segments, 63 nodes), dt 0.002 s, 60 s,
# every fairlead in the same 2 m / 10 s surge (a vessel-motion file sampled every 0.1 s, the
# MoorDyn side's coupling interval), one core, no file output, best of 3.
cargo build --release -q -p hawser-cli --manifest-path "$ROOT/Cargo.toml"
HAWSER="$ROOT/target/release/hawser"
python3 - "$OUT/surge.txt" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    for i in range(0, 1201):
        t = 0.1 * i
        f.write(f"{t:.1f} {2.0 * math.sin(2 * math.pi * t / 10.0):.12f} 0 0 0 0 0\n")
PY
for i in 1 2 3; do
    "$HAWSER" bench "$DECK" --vessel-motion "$OUT/surge.txt" --duration 60 --dt 0.002 --json > "$OUT/hawser$i.json"
done

python3 - "$OUT" <<'PY'
import json, sys, glob, os
out = sys.argv[1]
md = json.load(open(os.path.join(out, "moordyn.json")))
runs = [json.load(open(f)) for f in sorted(glob.glob(os.path.join(out, "hawser*.json")))]
best = {}
for run in runs:
    for r in run:
        k = r["mass_matrix"]
        if k not in best or r["wall_s"] < best[k]["wall_s"]:
            best[k] = r
# MoorDyn headline: coupling interval 0.1 s, no file output.
m = next(r for r in md["runs"] if r.get("headline"))
m["scheme"] = md["settings"]["time_scheme"]
m_ns = m["node_steps_per_s"]; m_ne = m["node_evaluations_per_s"]
print(f"OC3 deck (oc3_lines.txt, read by both codes), 63 nodes, dt 0.002 s, 60 s, surge 2 m / 10 s; "
      f"MoorDyn {md.get('moordyn_version', '?')} {m.get('scheme', 'RK2')} vs hawser RK4 (best of 3, one core)")
print(f"{'code':<22} {'wall [s]':>9} {'real time x':>12} {'node-steps/s':>14} {'node-evals/s':>14} {'ratio (evals)':>14}")
print(f"{'MoorDyn':<22} {m['wall_s']:>9.3f} {60.0 / m['wall_s']:>12.0f} {m_ns:>14.3e} {m_ne:>14.3e} {1.0:>14.2f}")
for k in ("lumped", "consistent"):
    if k in best:
        r = best[k]
        print(f"{'hawser fe ' + k:<22} {r['wall_s']:>9.3f} {r['real_time_factor']:>12.0f} {r['node_steps_per_s']:>14.3e} "
              f"{r['node_evaluations_per_s']:>14.3e} {r['node_evaluations_per_s'] / m_ne:>14.2f}")
PY
