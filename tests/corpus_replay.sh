#!/usr/bin/env bash
# The regression corpus: every input that ever crashed, hung, wrapped, escaped without a location
# or left a half-written output set (tests/corpus/<NN-topic>/, the fuzz findings first), replayed.
# Each folder holds its inputs and expect.sh, sourced in that folder with:
#   $bin  the binary under test;  $tmp  a scratch folder;  check NAME STATUS REGEX -- command...
#   g ARGS...  runs "$bin" ARGS under a 60 s timeout (exit 124: a hang) and, outside sanitizer
#              builds, an 8 GB address-space limit (an unbounded allocation fails instead of
#              swapping the machine);
#   no_nan NAME FILE  fails when FILE has a nan or inf cell.
# Usage: corpus_replay.sh path/to/geartrib [FOLDER...]   (default: every folder)
set -u
bin="$(realpath "$1")"; shift
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/cli_support.sh"
g() {
  if [[ -n "${ASAN_OPTIONS:-}" ]] || ldd "$bin" 2>/dev/null | grep -q libasan; then
    timeout 60 "$bin" "$@"
  else
    (ulimit -v 8000000; timeout 60 "$bin" "$@")
  fi
}
no_nan() {
  if grep -qiE '(^|[^a-z])[-+]?(nan|inf)([^a-z]|$)' "$2"; then echo "FAIL $1: nan or inf in $2"; fail=1; else echo "ok   $1"; fi
}
folders=("$@")
[[ ${#folders[@]} -eq 0 ]] && folders=("$here"/corpus/*/)
for d in "${folders[@]}"; do
  [[ -f "$d/expect.sh" ]] || continue
  echo "# $(basename "$d")"
  (cd "$d" && source ./expect.sh; exit $fail)
  [[ $? -eq 0 ]] || fail=1
done
exit $fail
