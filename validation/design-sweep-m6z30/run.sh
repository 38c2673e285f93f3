#!/usr/bin/env bash
# The what-if sweep of issue 10 on the seed's pair: module x face width x roughness, 27 points,
# one command on all cores, then the plots. Usage (from the source tree):
#   bash validation/design-sweep-m6z30/run.sh build/geartrib
set -euo pipefail
bin="$1"
here="$(cd "$(dirname "$0")" && pwd)"
/usr/bin/time -f "sweep wall time %e s, cpu %U s user" "$bin" sweep gears/m6z30.toml \
  --set module=4mm,6mm,8mm --set face_width=40mm:80mm:3 --set rq=0.005um,0.05um,0.5um \
  -o "$here/sweep.h5" --csv "$here/sweep.csv"
plot=scripts/plot_design_sweep.py
/usr/bin/python3 $plot "$here/sweep.csv" hertz_p0_Pa_max module face_width -o "$here/hertz-pressure.png"
/usr/bin/python3 $plot "$here/sweep.csv" real_area_ratio_min rq module --logx --at face_width=0.08 -o "$here/real-area.png"
/usr/bin/python3 $plot "$here/sweep.csv" plastic_area_fraction_min rq module --logx --at face_width=0.08 -o "$here/plastic-fraction.png"
