#!/usr/bin/env bash
# The project's own finite-element reference data with CalculiX (issue 9): the seed's single
# asperity (case gears/m6z30.toml: E_t 113.19 GPa, nu 0.3, S_y 418 MPa) elastic with a mesh
# convergence study, elastic-perfectly-plastic and with the 45-steel flow table to delta* = 100.
# Writes validation/fem-reference/ccx-*.csv (reference tables for `geartrib fit`).
# Usage: bash validation/fem-reference/ccx-study.sh build/geartrib   (about an hour on one core)
set -euo pipefail
bin="$1"
here="$(cd "$(dirname "$0")" && pwd)"
"$bin" fem single-asperity --material elastic --delta-star 1,2,6,10 --refine 20 --convergence -o "$here/ccx-elastic.csv" --details "$here/ccx-elastic-details.csv"
"$bin" fem single-asperity --material perfectly-plastic --delta-star 1,2,6,10,20,50,100 --refine 10 -o "$here/ccx-perfectly-plastic.csv" --details "$here/ccx-perfectly-plastic-details.csv"
"$bin" fem single-asperity --material table --delta-star 1,2,6,10,20,50,100 --refine 10 -o "$here/ccx-hardening.csv" --details "$here/ccx-hardening-details.csv"
