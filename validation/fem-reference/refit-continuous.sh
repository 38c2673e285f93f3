#!/usr/bin/env bash
# Refit the continuous model's default closure constants to the Kogut-Etsion 2002 and
# Jackson-Green 2005 FEM-based curves, and write them where the code takes them from:
#   src/asperity/continuous_defaults.hpp      (the one source of the defaults; rebuild after)
#   validation/fem-reference/continuous-fit.txt (the full report: constants, standard errors,
#                                               correlations, every residual, Ceres' report)
# Usage (from the repository root): bash validation/fem-reference/refit-continuous.sh build/geartrib
set -euo pipefail
bin="${1:-build/geartrib}"
cd "$(dirname "$0")/../.."
"$bin" fit --model continuous \
  --data validation/fem-reference/kogut-etsion-2002.csv \
  --data validation/fem-reference/jackson-green-2005.csv \
  --free area_scale,area_exponent,plastic_scale,pressure_scale,pressure_exponent \
  --observe load_star,area_star \
  --emit-cpp src/asperity/continuous_defaults.hpp \
  --report validation/fem-reference/continuous-fit.txt \
  -o validation/fem-reference/continuous-fit.toml
