#!/usr/bin/env bash
# The MoorDyn-compatible library checked from C against MoorDyn itself (about a minute once
# built). cargo's own tests of hawser-capi (header up to date, C host on hawser.h equal to the
# Rust session) and hawser-moordyn (MoorDyn-API host through libmoordyn equal to hawser's run)
# run in the workspace suite (README's test command); here:
#  tests/c/moordyn_host.c built once against MoorDyn 2.7.2's own libmoordyn (PyPI wheel, in
#     the throwaway venv of scripts/moordyn_venv.sh) and once against hawser's libmoordyn.so,
#     unchanged: OC3, 2 m 10 s surge, coupling 0.01 s, 60 s; FairTen1-3 extremes and means
#     over 20-60 s must agree within 0.5 % (docs/c-api.md gives the reason for the number).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
# The libraries as the workspace suite builds them (nothing to do after `cargo test
# --workspace --release`; a build of a subset of packages would unify other features and
# rebuild the tree). cargo leaves them in target/release/deps (`cargo build` alone copies
# them up), so the hosts link from there.
cargo test --release --workspace --no-run
LIBDIR="$ROOT/target/release/deps"
test -f "$LIBDIR/libmoordyn.so"
. scripts/moordyn_venv.sh
MD_LIB="$(ls "$VENV"/lib/python3*/site-packages/moordyn.libs/libmoordyn*.so* | head -1)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
[ -n "${KEEP_TMP:-}" ] && trap - EXIT && echo "kept $TMP"
CC="${CC:-cc}"
"$CC" -std=c99 -D_DEFAULT_SOURCE -O1 -o "$TMP/host_moordyn" tests/c/moordyn_host.c \
    -I crates/hawser-moordyn/include "$MD_LIB" -Wl,-rpath,"$(dirname "$MD_LIB")" -lm
"$CC" -std=c99 -D_DEFAULT_SOURCE -O1 -o "$TMP/host_hawser" tests/c/moordyn_host.c \
    -I crates/hawser-moordyn/include -L "$LIBDIR" -lmoordyn \
    -Wl,-rpath,"$LIBDIR" -lm
# MoorDyn writes its log and .out files beside the deck: run it on a copy.
cp tests/data/moordyn/oc3_lines.txt "$TMP/"
for lib in moordyn hawser; do
    /usr/bin/time -f "$lib: %U s user" "$TMP/host_$lib" "$TMP/oc3_lines.txt" 60 0.01 10 \
        > "$TMP/$lib.csv" 2> "$TMP/$lib.err" || { cat "$TMP/$lib.err"; exit 1; }
    grep " s user" "$TMP/$lib.err"
done
python3 - "$TMP/moordyn.csv" "$TMP/hawser.csv" <<'PY'
import csv, sys
def read(p):
    # MoorDyn prints its banner on standard output too: the table starts at its header.
    lines = open(p).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("t,"))
    table = [lines[start]] + [l for l in lines[start + 1:] if l[:1].isdigit() and "," in l]
    rows = list(csv.DictReader(table))
    return [r for r in rows if 20.0 <= float(r["t"]) < 60.0 - 1e-9]
md, hw = read(sys.argv[1]), read(sys.argv[2])
assert len(md) == len(hw) > 0
worst = 0.0
print("| channel | stat | MoorDyn 2.7.2 [kN] | hawser libmoordyn [kN] | diff |")
print("|---|---|---:|---:|---:|")
for c in ["FairTen1", "FairTen2", "FairTen3", "f0", "f2"]:
    a = [float(r[c]) for r in md]
    b = [float(r[c]) for r in hw]
    for name, fn in [("min", min), ("max", max), ("mean", lambda v: sum(v) / len(v))]:
        x, y = fn(a), fn(b)
        d = (y - x) / abs(x)
        if c.startswith("FairTen"):
            worst = max(worst, abs(d))
        print(f"| {c} | {name} | {x/1e3:.1f} | {y/1e3:.1f} | {100*d:+.3f} % |")
print(f"largest FairTen difference {100*worst:.3f} % (tolerance 0.5 %)")
sys.exit(0 if worst <= 5e-3 else 1)
PY
