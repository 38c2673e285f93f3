#!/usr/bin/env bash
# The libFuzzer harnesses of tests/fuzz, built with clang, AddressSanitizer and UBSan in
# build-fuzz/, each seeded with the shipped files and run for a given time:
#   bash scripts/fuzz.sh [SECONDS] [HARNESS...]     default: 1200 s each, all six (case material
#                                                   topography fit_data sweep_merge lubricant), two at a time
# Findings (crash-*, timeout-*, oom-*, leak-*) land in build-fuzz/findings/<harness>/; each one,
# minimised and understood, becomes a folder of tests/corpus/ with its expect.sh. Each run's last
# lines (executions, coverage) are in build-fuzz/findings/<harness>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
seconds="${1:-1200}"; shift || true
harnesses=("$@"); [[ ${#harnesses[@]} -eq 0 ]] && harnesses=(case material topography fit_data sweep_merge lubricant)
command -v clang++ >/dev/null || { echo "fuzz: needs clang (apt-get install clang)" >&2; exit 2; }
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGEARTRIB_FUZZ=ON \
  -DGEARTRIB_BUILD_TESTS=OFF -DGEARTRIB_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${harnesses[@]}")

# Seeds: the shipped files of each kind.
seeds=build-fuzz/seeds
rm -rf "$seeds"; mkdir -p "$seeds"/{case,material,topography,fit_data,sweep_merge,lubricant}
cp gears/*.toml "$seeds/case/"
cp materials/*.toml "$seeds/material/"
cp lubricants/*.toml tests/corpus/2[5-9]-*/*.toml "$seeds/lubricant/"
k=0
for f in gears/surfaces/* validation/*/*.xyz validation/*/*.csv tests/fuzz/*.x3p; do
  [[ -f "$f" ]] || continue
  case "$f" in
    *.xyz) b='\x00' ;; *.asc) b='\x01' ;; *.csv) b='\x02' ;; *.txt) b='\x03' ;; *.grd) b='\x04' ;; *.h5) b='\x05' ;; *.x3p) b='\x06' ;; *) continue ;;
  esac
  [[ $(stat -c %s "$f") -lt 2000000 ]] || continue
  { printf "$b"; cat "$f"; } > "$seeds/topography/seed-$((k++))"
done
cp validation/fem-reference/*.csv "$seeds/fit_data/" 2>/dev/null || true
# sweep_merge builds its shard files from the input's choices: the empty input is one consistent sweep.
: > "$seeds/sweep_merge/consistent-sweep"
for d in tests/corpus/*/; do  # the regression corpus's inputs seed the harness of their kind
  for f in "$d"*; do
    case "$f" in
      *.toml) grep -q '^\[gear_pair\]' "$f" && cp "$f" "$seeds/case/" || cp "$f" "$seeds/material/" ;;
      *.csv|*.txt|*.xyz|*.h5) cp "$f" "$seeds/fit_data/" ;;
    esac
  done
done

mkdir -p build-fuzz/findings
run() {
  local h=$1
  mkdir -p "build-fuzz/findings/$h" "build-fuzz/corpus/$h"
  # As under `setup.sh sanitize`: libhdf5's own leaks suppressed, and its terabyte requests on
  # corrupt files answered with NULL as glibc's malloc would (libhdf5 then refuses the file); a
  # process past 4 GB resident is still a finding.
  (cd "build-fuzz/findings/$h" && \
   ASAN_OPTIONS="allocator_may_return_null=1:detect_leaks=1" \
   LSAN_OPTIONS="suppressions=$root/tests/sanitizer/lsan.supp:print_suppressions=0" \
   ../../tests/fuzz/fuzz_$h -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -max_len=65536 \
     -print_final_stats=1 ../../corpus/$h ../../seeds/$h > ../$h.log 2>&1) || true
  echo "fuzz_$h: $(grep -E '^stat::number_of_executed_units' build-fuzz/findings/$h.log | awk '{print $2}') executions;" \
       "$(ls build-fuzz/findings/$h | grep -cE '^(crash|timeout|oom|leak)-' || true) findings"
}
running=0
for h in "${harnesses[@]}"; do
  run "$h" &
  running=$((running + 1))
  if (( running >= 2 )); then wait -n; running=$((running - 1)); fi
done
wait
