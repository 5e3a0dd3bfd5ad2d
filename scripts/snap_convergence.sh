#!/usr/bin/env bash
# Peak snap tension of the position-vector paper's snapping cable (examples/snapping_cable_127.toml)
# as the mesh is refined, with `fe` and `hermite` (issue 4 item 4). Prints one row per run:
# formulation, elements, peak tension at the support and at the sphere [N], wall time.
# Usage: scripts/snap_convergence.sh [hawser binary]   (hermite at 40 elements takes ~4 min)
set -euo pipefail
cd "$(dirname "$0")/.."
H=${1:-target/release/hawser}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in fe hermite; do
  for n in 5 10 20 40; do
    s="$tmp/$f$n.toml"
    sed "s/^elements = 5/elements = $n/; s/^channels = .*/channels = []/" examples/snapping_cable_127.toml > "$s"
    [ "$f" = hermite ] && sed -i "s/^elements = $n/elements = $n\nformulation = \"hermite\"/" "$s"
    start=$(date +%s.%N)
    "$H" run "$s" -o "$tmp/o_$f$n" --quiet
    end=$(date +%s.%N)
    python3 - "$tmp/o_$f$n/summary.json" "$f" "$n" "$start" "$end" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["channels"]
print(f"{sys.argv[2]:8} {sys.argv[3]:>3}  support {c['cable.end_a.tension']['max']:8.1f} N  "
      f"sphere {c['cable.end_b.tension']['max']:8.1f} N  ({float(sys.argv[5]) - float(sys.argv[4]):.1f} s)")
PY
  done
done
