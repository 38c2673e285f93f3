#!/usr/bin/env bash
# geartrib setup: install missing Debian 12 packages, configure and build (Release), then
#   bash scripts/setup.sh          build only
#   bash scripts/setup.sh run      build, then run the default case (gears/m6z30.toml): the mesh
#                                  along the line of action, then its single-asperity contact
#   bash scripts/setup.sh test     build, then run the default test suite (CTest, label "long" excluded)
# Works as root on a fresh machine (apt-get) and is a no-op for packages already installed.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-build}"
case "$mode" in build|run|test) ;; *) echo "usage: bash scripts/setup.sh [build|run|test]" >&2; exit 2;; esac

packages=(g++ cmake make pkg-config
          libeigen3-dev libsundials-dev libboost-dev libceres-dev libhdf5-dev
          libcli11-dev libtomlplusplus-dev libfmt-dev libgtest-dev libbenchmark-dev)
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
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S . -B build -DCMAKE_BUILD_TYPE="$build_type" >/dev/null
cmake --build build -j "$jobs"

case "$mode" in
  run)
    ./build/geartrib kinematics --summary
    ./build/geartrib kinematics
    ./build/geartrib asperity --summary
    ./build/geartrib asperity --model continuous --delta-star 0.5,1,2,6,10,40,110,1000
    ;;
  test)
    ctest --test-dir build --output-on-failure -j "$jobs" -LE long
    ;;
esac
