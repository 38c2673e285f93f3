# 26 (issue 30, finding 4, the run): a lubricated run that heats its oil beyond the laws wrote NaN
# (-nan in the table and CSV) with exit 0; sweep rows holding it read "ok"; the Python module
# returned it. Found: the stock case at 5e4 N m (ISO/TS 6336-22's h_Y took the oil at contact
# temperatures above 782.8 K, where ISO/TR 15144-1's alpha factor is negative); a sweep to 1e5 N m.
# Now the surfaces' and the ISO contact's oil past the law range (400 degC) is taken at its end and
# flagged (flag_oil_temperature_clamped; beyond the data: flag_oil_extrapolated), a bulk temperature
# past it fails the run (exit 1, nothing written; a sweep point's status "error"), and every output
# is checked finite before it is written or returned (runs::check_finite_outputs).
scratch="$tmp/26"; mkdir -p "$scratch"
cases=../../../gears/m6z30.toml
check stock-5e4Nm-clamped 0 "warning: [0-9]+ of 21 positions \(flag_oil_temperature_clamped\) where .* pass 400.0 degC" -- g run "$cases" --set "torque=5e4 N m" --positions 21 -o "$scratch/hot.h5" --csv "$scratch/hot.csv" -q
no_nan stock-5e4Nm-finite "$scratch/hot.csv"
col=$(head -1 "$scratch/hot.csv" | tr , '\n' | grep -nx flag_oil_temperature_clamped | cut -d: -f1)
if [[ -n "$col" ]] && awk -F, -v c="$col" 'NR>1 && $c==1 {found=1} END {exit !found}' "$scratch/hot.csv"; then echo "ok   stock-5e4Nm-flagged"; else echo "FAIL stock-5e4Nm-flagged: no position with flag_oil_temperature_clamped = 1"; fail=1; fi
check stock-1e5Nm-bulk-beyond-laws 1 "failure: the flanks' bulk temperature \(/lubrication bulk_temperature_K\), estimated by ISO/TS 6336-20 with the iso-flash friction law's flash temperature, is 522.4 degC, beyond 400.0 degC" -- g run "$cases" --set "torque=1e5 N m" --positions 21 -o "$scratch/failed.h5" --csv "$scratch/failed.csv" -q
for f in failed.h5 failed.csv; do [[ -e "$scratch/$f" ]] && { echo "FAIL stock-1e5Nm-nothing-written: $f"; fail=1; }; done
# The sweep: the failing point's status is "error" with the reason; the others' rows finite.
check sweep-to-1e5Nm 0 "" -- g sweep "$cases" --set "torque=1000 N m,5e4 N m,1e5 N m" --set positions=21 -o "$scratch/s.h5" --csv "$scratch/s.csv" -q
status=$(awk -F, 'NR>2 {printf "%s ", $4}' "$scratch/s.csv")
if [[ "$status" == "ok ok error " ]] && grep -q '^2,100000,21,error,"the flanks'"'"' bulk temperature' "$scratch/s.csv"; then echo "ok   sweep-statuses"; else echo "FAIL sweep-statuses: $status"; fail=1; fi
awk -F, 'NR>2 && $4=="ok"' "$scratch/s.csv" > "$scratch/s-ok.csv"
no_nan sweep-ok-rows-finite "$scratch/s-ok.csv"
# An oil with data to 250 degC at the ends of its operating range (oil at 310 and -60 degC): finite.
for t in 583.15K 213.15K; do
  check "hot-pao-oil-$t" 0 "warning: key 'operating.oil_temperature'.* lies outside PAOR" -- g run "$cases" --set "lubricant.file=$PWD/hot-pao.toml" --set "oil_temperature=$t" --positions 21 -o "$scratch/pao.h5" --csv "$scratch/pao-$t.csv" -q
  no_nan "hot-pao-oil-$t-finite" "$scratch/pao-$t.csv"
done
# Python: gt.run returns the clamped run's finite arrays and raises on the failing one; gt.sweep's
# failing point has its status.
python_module="$(dirname "$bin")/python"
if [[ -d "$python_module/geartrib" ]] && /usr/bin/python3 -c "import numpy, xarray, pandas" 2>/dev/null; then
  check python-run-and-sweep 0 "^python ok$" -- env PYTHONPATH="$python_module" timeout 120 /usr/bin/python3 python_runs.py
else
  echo "skip python-run-and-sweep: no Python module beside $bin"
fi
rm -rf "$scratch"
