#!/usr/bin/env bash
# The project's own finite-element reference data with CalculiX (issue 9): the seed's single
# asperity (case gears/m6z30.toml: E_t 113.19 GPa, nu 0.3, S_y 418 MPa, H = 2.8 S_y) elastic-
# perfectly-plastic and with the 45-steel flow table to delta* = 100, and elastic with a mesh
# convergence study, and the perfectly plastic runs again at 20 elements across with the
# three-refinement convergence study (10, 14, 20) for delta* = 6-20 and 50-100. Writes
# validation/fem-reference/ccx-*.csv: reference tables for `geartrib fit` and, in *-details.csv,
# contact radius, peak pressure, von Mises and plastic zone.
# Usage: bash validation/fem-reference/ccx-study.sh build/geartrib   (about 3.5 hours on one core)
set -euo pipefail
bin="$1"
here="$(cd "$(dirname "$0")" && pwd)"
levels=1,2,6,7,10,20,50,100
for material in perfectly-plastic table; do
  name=$([[ $material == table ]] && echo hardening || echo "$material")
  "$bin" fem single-asperity --material "$material" --delta-star "$levels" --refine 10 \
    -o "$here/ccx-$name.csv" --details "$here/ccx-$name-details.csv"
  # Where the surface starts to yield (the continuous model's plastic core is fitted to it).
  "$bin" fem single-asperity --material "$material" --delta-star 2.5,3,3.5,4,5 --refine 10 \
    -o "$here/ccx-$name-onset.csv" --details "$here/ccx-$name-onset-details.csv"
done
"$bin" fem single-asperity --material elastic --delta-star 1,2,6,10 --refine 20 --convergence \
  -o "$here/ccx-elastic.csv" --details "$here/ccx-elastic-details.csv"
for levels in 6,10,20 50,100; do
  "$bin" fem single-asperity --material perfectly-plastic --delta-star "$levels" --refine 20 --convergence \
    -o "$here/ccx-perfectly-plastic-fine-${levels//,/-}.csv" --details "$here/ccx-perfectly-plastic-fine-${levels//,/-}-details.csv"
done
