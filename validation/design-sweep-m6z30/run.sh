#!/usr/bin/env bash
# The what-if sweep of issue 10 on the seed's dry pair: module x face width x roughness, 27 points,
# one command on all cores, then the plots. Usage (from the source tree):
#   bash validation/design-sweep-m6z30/run.sh build/geartrib
set -euo pipefail
bin="$1"
here="$(cd "$(dirname "$0")" && pwd)"
/usr/bin/time -f "sweep wall time %e s, cpu %U s user" "$bin" sweep gears/m6z30-dry.toml \
  --set module=4mm,6mm,8mm --set face_width=40mm:80mm:3 --set rq=0.005um,0.05um,0.5um \
  -o "$here/sweep.h5" --csv "$here/sweep.csv"
plot=scripts/plot_design_sweep.py
/usr/bin/python3 $plot "$here/sweep.h5" --quantity hertz_p0_Pa_max --at rq=5e-9 -o "$here/hertz-pressure.png"
/usr/bin/python3 $plot "$here/sweep.h5" --quantity real_area_ratio_min --x rq --lines module --at face_width=0.08 --logx -o "$here/real-area.png"
/usr/bin/python3 $plot "$here/sweep.h5" --quantity plastic_area_fraction_min --x rq --lines module --at face_width=0.08 --logx -o "$here/plastic-fraction.png"
