#!/usr/bin/env bash
# Cost of free rigid bodies and of wave kinematics per step (issue 6 item 10), recorded in
# BENCHMARKS.md. Scenario: scripts/bench/eight_buoys.toml (8 tethers x 10 fe elements, 88
# nodes, 8 buoys as rigid bodies in 50 m of water), lumped mass, RK4, fixed dt 4 ms; each case
# best of 3 runs (`--repeat 3`; the bodies case 10 s simulated, best of 5).
#
#   1. the same lines with the buoys as free rigid bodies and as point masses (`--bodies both`),
#      in still water: overhead per body per step [us];
#   2. the same lines (buoys as points) in still water, a regular Airy wave (H 2 m, T 8 s) and
#      JONSWAP seas of 50 and 200 components (`--waves all`): wave kinematics per node per
#      step over still water [ns], and the fluid velocity + acceleration alone per evaluation;
#   3. the OC3 mooring (examples/oc3_surge.toml, 320 m deep: most nodes lie far below the
#      waves) under the same seas.
#
# Usage: scripts/bench_bodies_waves.sh [DURATION_S]   (default 2 s simulated)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DURATION="${1:-2}"
cargo build --release -q -p hawser-cli --manifest-path "$ROOT/Cargo.toml"
HAWSER="${CARGO_TARGET_DIR:-$ROOT/target}/release/hawser"
COMMON=(--mass lumped --scheme rk4 --dt 0.004 --repeat 3 --duration "$DURATION")
echo "## bodies against points, still water"
# The still-water runs are cheap: 10 s simulated, best of 5, to see a few us per step.
"$HAWSER" bench "$ROOT/scripts/bench/eight_buoys.toml" --bodies both --mass lumped --scheme rk4 --dt 0.004 --repeat 5 --duration 10
echo
echo "## waves (buoys as points)"
"$HAWSER" bench "$ROOT/scripts/bench/eight_buoys.toml" --bodies points --waves all "${COMMON[@]}"
echo
echo "## waves, OC3 mooring (320 m)"
"$HAWSER" bench "$ROOT/examples/oc3_surge.toml" --waves all --mass lumped --scheme rk4 --dt 0.002 --repeat 3 --duration "$DURATION"
