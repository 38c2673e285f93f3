#!/usr/bin/env bash
# The seed's section 6 model by finite elements (CalculiX, plane strain): HLH at h_m = 0 and 2
# delta_pc (spacing 0.5 um), HLH h_m = 0 at spacings 0.25, 1 and 2 um, LHH at h_m = 2 delta_pc;
# approaches 2, 4, 6 delta_pc at delta_pc = 0.5797 nm. Writes validation/seed-section7/ccx-*.csv.
# Usage: bash validation/seed-section7/ccx-runs.sh build/geartrib   (about 35 minutes on one core)
set -euo pipefail
bin="$1"
here="$(cd "$(dirname "$0")" && pwd)"
run() { "$bin" fem three-cylinders --approach 2,4,6 --delta-pc 0.5797nm "$@"; }
run --layout HLH --height-step 0 --spacing 0.5um -o "$here/ccx-HLH-h0.csv"
run --layout HLH --height-step 2 --spacing 0.5um -o "$here/ccx-HLH-h2.csv"
for s in 0.25um 1um 2um; do run --layout HLH --height-step 0 --spacing $s -o "$here/ccx-HLH-h0-s$s.csv"; done
run --layout LHH --height-step 2 --spacing 0.5um -o "$here/ccx-LHH-h2.csv"
