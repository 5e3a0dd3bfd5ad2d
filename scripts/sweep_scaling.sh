#!/usr/bin/env bash
# Scaling of `hawser sweep` with --jobs: cases per CPU second and per wall second for
# --jobs 1 and --jobs 2 (or the list in JOBS), on CASES cases of the bundled catenary mooring
# (examples/catenary_mooring.toml, the fairlead surge amplitude varied, DURATION s each,
# statistics from t = 0), each case writing its full run files as `hawser run` does.
#
# Usage: scripts/sweep_scaling.sh            (after `cargo build --release -p hawser-cli`)
# Environment: CASES (default 6), DURATION [s] (default 6), REPEATS (default 3), JOBS
# (default "1 2").
#
# CPU time is user + system time of the whole `hawser sweep` process (all its threads, from
# /usr/bin/time), so it counts the validation of the table and the writing of the files too.
# On a shared machine the wall time depends on what else runs; the CPU time per case does not
# depend on --jobs unless the cores are contended (caches, memory bandwidth), so the ratio of
# CPU times is the measure of the overhead of running cases in parallel. The repeats
# alternate the --jobs values; the medians are printed.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HAWSER="${HAWSER:-$ROOT/target/release/hawser}"
CASES="${CASES:-6}"
DURATION="${DURATION:-6}"
REPEATS="${REPEATS:-3}"
JOBS="${JOBS:-1 2}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

{
    echo "simulation.duration,statistics.start,points.fairlead.motion.amplitude"
    for k in $(seq 1 "$CASES"); do
        echo "$DURATION,0.0,\"[$k.0, 0.0, 0.0]\""
    done
} > "$WORK/cases.csv"

echo "hawser sweep: $CASES cases x $DURATION s of examples/catenary_mooring.toml, $REPEATS repeats"
echo "nproc $(nproc), load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq 1 "$REPEATS"); do
    for j in $JOBS; do
        /usr/bin/time -f "%e %U %S" -o "$WORK/time" \
            "$HAWSER" sweep "$ROOT/examples/catenary_mooring.toml" "$WORK/cases.csv" \
            --out "$WORK/out_$j" --jobs "$j" --quiet --overwrite
        echo "$j $(cat "$WORK/time")" >> "$WORK/times"
    done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$WORK/times" "$CASES" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
cases = int(sys.argv[2])
by = {}
for j, wall, user, sys_ in rows:
    by.setdefault(int(j), []).append((float(wall), float(user) + float(sys_)))
print(f"{'jobs':>4} {'wall [s]':>9} {'CPU [s]':>8} {'cases/CPU-s':>11} {'cases/wall-s':>12} {'CPU/wall':>8}")
base = None
for j in sorted(by):
    wall = statistics.median(w for w, _ in by[j])
    cpu = statistics.median(c for _, c in by[j])
    base = base or cpu
    print(f"{j:>4} {wall:>9.2f} {cpu:>8.2f} {cases / cpu:>11.3f} {cases / wall:>12.3f} {cpu / wall:>8.2f}"
          f"   CPU ratio to the first: {cpu / base:.3f}")
PY
