#!/usr/bin/env bash
# geartrib setup: install missing Debian 12 packages, configure and build (Release), then
#   bash scripts/setup.sh          build only
#   bash scripts/setup.sh run      build, then run the main job on the default case (gears/m6z30.toml):
#                                  results/m6z30.h5 (+ .csv) and the plots in results/plots
#   bash scripts/setup.sh test     build, then run the default test suite (CTest, label "long" excluded)
#   bash scripts/setup.sh sanitize build with AddressSanitizer and UBSan in build-sanitize/ (-O1
#                                  -g), then run the default suite under them: any
#                                  report fails its test (tests ~95 s, as the plain suite: CalculiX
#                                  dominates; the build ~15 min on 2 cores)
# Works as root on a fresh machine (apt-get) and is a no-op for packages already installed.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-build}"
case "$mode" in build|run|test|sanitize) ;; *) echo "usage: bash scripts/setup.sh [build|run|test|sanitize]" >&2; exit 2;; esac

packages=(g++ cmake make pkg-config
          libeigen3-dev libsundials-dev libboost-dev libceres-dev libhdf5-dev
          libcli11-dev libtomlplusplus-dev libfmt-dev libgtest-dev libbenchmark-dev libfftw3-dev
          libzip-dev libpugixml-dev
          python3 python3-h5py python3-matplotlib calculix-ccx
          python3-dev python3-numpy pybind11-dev         # the Python module (python/)
          python3-pytest python3-pandas python3-xarray python3-distributed   # its tests, Dask sweeps
          clang-format clang-tidy    # scripts/lint.sh (ctest -R lint.format, ctest -L lint)
          chromium)                  # the HTML report's browser test (ctest -R cli.report)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo="sudo"
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build_type="${GEARTRIB_BUILD_TYPE:-Release}"
werror="${GEARTRIB_WERROR:-OFF}"   # CI (.ci/run) sets ON: a warning fails the build
jobs="$(nproc 2>/dev/null || echo 2)"
if [[ $mode == sanitize ]]; then
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DGEARTRIB_SANITIZE=ON -DGEARTRIB_WERROR="$werror" >/dev/null
  cmake --build build-sanitize -j "$jobs"
  # Leaks are reported too (but libhdf5's own: tests/sanitizer/lsan.supp); an UBSan finding
  # aborts (-fno-sanitize-recover) and fails its test. allocator_may_return_null: a corrupt HDF5
  # file makes libhdf5 ask for terabytes; malloc returns NULL there as glibc's would, and libhdf5
  # refuses the file (without it ASan aborts where the plain build exits 2).
  ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:allocator_may_return_null=1" \
  LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0" \
  UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -LE long
  exit
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" -DGEARTRIB_WERROR="$werror" >/dev/null
cmake --build build -j "$jobs"

case "$mode" in
  run)
    mkdir -p results
    ./build/geartrib kinematics --summary
    ./build/geartrib asperity --summary
    ./build/geartrib run gears/m6z30.toml -o results/m6z30.h5 --csv results/m6z30.csv
    /usr/bin/python3 scripts/plot_mesh.py results/m6z30.h5 results/plots
    ;;
  test)
    ctest --test-dir build --output-on-failure -j "$jobs" -LE long
    ;;
esac
