#!/usr/bin/env bash
# Refit the continuous model's default closure constants and write them where the code takes
# them from, in two steps:
#  1. the plastic core (plastic_scale, plastic_exponent; plastic_onset held at 1, first yield: with
#     it free the onset and the scale correlate at -0.999 and the optimum is the same) to the yielded share of
#     the contact area at the surface in the project's perfectly plastic CalculiX runs
#     (ccx-perfectly-plastic.csv and, at delta* 2.5-5 where it starts, ccx-perfectly-plastic-onset.csv:
#     column plastic_area_fraction with its sd);
#  2. with that core, the contact radius (area_scale, area_exponent) and the mean pressure
#     (pressure_scale, pressure_exponent) to the Kogut-Etsion 2002 and Jackson-Green 2005
#     FEM-based load and area curves.
# Writes:
#   src/asperity/continuous_defaults.hpp        (the one source of the defaults; rebuild after)
#   validation/fem-reference/continuous-fit.txt  (step 2's full report), continuous-fit.toml
#   validation/fem-reference/continuous-core-fit.txt, continuous-core-fit.toml (step 1)
#   validation/fem-reference/continuous-core-fit-hardening.* (step 1 on the hardening runs)
# Usage (from the repository root): bash validation/fem-reference/refit-continuous.sh build/geartrib [OUT]
# With OUT, everything is written into the folder OUT instead (the CTest validation.fem-reference
# does this and compares OUT/continuous_defaults.hpp with the committed header).
set -euo pipefail
bin="$(realpath "${1:-build/geartrib}")"
out="${2:+$(realpath -m "$2")}"
cd "$(dirname "$0")/../.."
here=validation/fem-reference
reports="${out:-$here}"
header="${out:+$out/continuous_defaults.hpp}"
header="${header:-src/asperity/continuous_defaults.hpp}"
[[ -z "$out" ]] || mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
# Step 1 starts from a stated point (a core growing from first yield, scale and exponent 3).
mkdir -p "$tmp/gears" && cp -r materials "$tmp/"
start="[asperity.constants.continuous]
plastic_onset = 1.0
plastic_scale = 3.0
plastic_exponent = 3.0"
printf '%s\n%s\n' "$(cat gears/m6z30-dry.toml)" "$start" > "$tmp/gears/start.toml"
"$bin" fit --model continuous --case "$tmp/gears/start.toml" \
  --data "$here/ccx-perfectly-plastic.csv" --data "$here/ccx-perfectly-plastic-onset.csv" \
  --free plastic_scale,plastic_exponent --observe plastic_area_fraction \
  --report "$reports/continuous-core-fit.txt" -o "$reports/continuous-core-fit.toml" -q
# The same core fitted to the hardening runs (45 steel's flow table), for comparison only.
"$bin" fit --model continuous --case "$tmp/gears/start.toml" --data "$here/ccx-hardening.csv" --data "$here/ccx-hardening-onset.csv" \
  --free plastic_scale,plastic_exponent --observe plastic_area_fraction \
  --report "$reports/continuous-core-fit-hardening.txt" -o "$reports/continuous-core-fit-hardening.toml" -q
# Step 2 starts from a case whose continuous constants carry step 1's core.
cat gears/m6z30-dry.toml "$reports/continuous-core-fit.toml" > "$tmp/gears/case.toml"
"$bin" fit --model continuous --case "$tmp/gears/case.toml" \
  --data "$here/kogut-etsion-2002.csv" --data "$here/jackson-green-2005.csv" \
  --free area_scale,area_exponent,pressure_scale,pressure_exponent --observe load_star,area_star \
  --emit-cpp "$header" --report "$reports/continuous-fit.txt" -o "$reports/continuous-fit.toml" ${out:+-q}
