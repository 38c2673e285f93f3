# Shared by the command-line test scripts (sourced): a scratch folder removed on exit, a failure
# flag, and check NAME EXPECTED_STATUS PATTERN -- command...: runs the command, compares its exit
# status and greps its output (stdout and stderr) for the extended regex PATTERN ("" for none).
fail=0
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
check() {
  local name="$1" want="$2" pattern="$3"; shift 4
  local out status
  out="$("$@" 2>&1)"; status=$?
  if [[ $status -ne $want ]]; then echo "FAIL $name: exit $status, expected $want"; echo "$out" | head -5; fail=1; return; fi
  if [[ -n "$pattern" ]] && ! grep -qE -- "$pattern" <<<"$out"; then echo "FAIL $name: output lacks /$pattern/"; echo "$out" | head -5; fail=1; return; fi
  echo "ok   $name"
}
