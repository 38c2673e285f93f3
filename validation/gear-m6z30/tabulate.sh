#!/usr/bin/env bash
# The seed's reference pair (gears/m6z30.toml) at A..E with both load-sharing methods, and the
# two shares along the path; writes the CSVs beside this script's README into $OUT (default: a
# temporary folder) and prints them.
set -euo pipefail
bin="$1"
out="${OUT:-$(mktemp -d)}"
"$bin" kinematics gears/m6z30.toml --summary --csv > "$out/summary.csv"
for m in iso stiffness; do
  "$bin" kinematics gears/m6z30.toml --load-sharing "$m" --csv > "$out/points-$m.csv"
  "$bin" kinematics gears/m6z30.toml --load-sharing "$m" --positions 21 --csv > "$out/path-$m.csv"
done
for f in summary points-iso points-stiffness; do echo "== $f"; cat "$out/$f.csv"; done
echo "== load share along A -> E (position, s_m, iso, stiffness)"
paste -d, <(cut -d, -f1,2,7 "$out/path-iso.csv") <(cut -d, -f7 "$out/path-stiffness.csv")
