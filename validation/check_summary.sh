#!/usr/bin/env bash
# Compare `geartrib kinematics CASE --summary --csv` with published values.
# Usage: check_summary.sh path/to/geartrib CASE.toml REFERENCE.csv
# REFERENCE.csv: '# ' provenance lines, then rows name,value,tolerance,source (SI, as the summary).
# Prints each quantity beside its reference; exits 1 if any differs by more than its tolerance
# (the published value's last printed digit).
set -euo pipefail
bin="$1"; case_file="$2"; ref="$3"
summary="$("$bin" kinematics "$case_file" --summary --csv)"
grep '^#' "$ref" | sed 's/^# /  /' || true
status=0
printf '%-32s %16s %16s %12s  %s\n' quantity published geartrib tolerance verdict
while IFS=, read -r name value tol source; do
  [[ -z "$name" || "$name" == \#* || "$name" == name ]] && continue
  got="$(awk -F, -v n="$name" '$1 == n {print $2}' <<<"$summary")"
  if [[ -z "$got" ]]; then echo "missing quantity $name"; status=1; continue; fi
  verdict="$(awk -v g="$got" -v v="$value" -v t="$tol" 'BEGIN { d = g - v; if (d < 0) d = -d; print (d <= t ? "ok" : "DIFFERS") }')"
  printf '%-32s %16s %16.8g %12s  %s (%s)\n' "$name" "$value" "$got" "$tol" "$verdict" "$source"
  [[ "$verdict" == ok ]] || status=1
done < "$ref"
exit $status
