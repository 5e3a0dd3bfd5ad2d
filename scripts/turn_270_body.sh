#!/bin/sh
# Runs the 270° turn with the towed body as a free point (examples/turn_270.toml), as a rigid
# body (examples/turn_270_body.toml) and, as a control, as a rigid body made to look like the
# free point (isotropic C·A = 1.5 m² and added mass 0.5 ρV on every axis, the cable at the
# body origin, so no line moment), then prints the numbers and writes the plots of
# docs/motions.md ("The 270° turn with a rigid body").
# usage: scripts/turn_270_body.sh [OUT_DIR]   (default out/turn_270_body_study; about 10 s)
set -e
out=${1:-out/turn_270_body_study}
root=$(dirname "$0")/..
hawser=${HAWSER:-"cargo run -q --release -p hawser-cli --"}
mkdir -p "$out"
sed -e 's/^quadratic_drag = .*/quadratic_drag = [1.5, 1.5, 1.5, 1.0, 9.5, 9.5]/' \
    -e 's/^added_mass = .*/added_mass = [3203.0, 3203.0, 3203.0, 0.0, 7750.0, 7750.0]/' \
    -e 's/^position = \[0.4, 0.0, 0.4\]/position = [0.0, 0.0, 0.0]/' \
    -e 's/^position = \[-30.4, 0.0, -481.4\]/position = [-30.0, 0.0, -481.0]/' \
    "$root/examples/turn_270_body.toml" > "$out/turn_270_body_isotropic.toml"
grep -q '^quadratic_drag = \[1.5, 1.5, 1.5' "$out/turn_270_body_isotropic.toml"
grep -q '^position = \[0.0, 0.0, 0.0\]' "$out/turn_270_body_isotropic.toml"
$hawser run "$root/examples/turn_270.toml" --out "$out/point" --quiet
$hawser run "$root/examples/turn_270_body.toml" --out "$out/body" --quiet
$hawser run "$out/turn_270_body_isotropic.toml" --out "$out/isotropic" --quiet
python3 "$root/scripts/turn_270_body_plots.py" "$out/point/timeseries.csv" \
    "$out/body/timeseries.csv" "$out/isotropic/timeseries.csv"
