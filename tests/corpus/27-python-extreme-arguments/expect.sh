# 27 (issue 30, finding 13, the Python module): finite extreme arguments returned NaN or inf with no
# exception, and write_surface wrote files read_surface refuses. Found: boundary_elements with
# line_load=1e300, approach=1e300, modulus=1e-300 or heights near 1e293 m (pressure, displacement
# and gap NaN); surface_statistics of heights times 1e300 (Ra, Rq NaN), beyond the readers' +-1 m;
# asperity with a pair of radius 1e-300 and moduli 1e300 (load, area NaN); write_surface of heights
# 1e300 m or of no valid point. Now every argument is checked against the ranges of the file
# readers and the case schema (ValueError naming the argument, the value and the rule), every
# returned array is checked finite (RuntimeError), and io::write_topography refuses what the
# readers refuse (heights beyond +-1 m, fewer than 9 valid points). extreme_arguments.py holds the
# checks, and the ends of each range returning finite numbers.
python_module="$(dirname "$bin")/python"
if [[ -d "$python_module/geartrib" ]] && /usr/bin/python3 -c "import numpy, xarray" 2>/dev/null; then
  check python-extreme-arguments 0 "^python ok$" -- env PYTHONPATH="$python_module" timeout 120 /usr/bin/python3 extreme_arguments.py
else
  echo "skip python-extreme-arguments: no Python module beside $bin"
fi
# The command's writer refuses the same: a generated surface of Rq 1 m has heights beyond +-1 m.
check surface-generate-heights-beyond 2 "z\[[0-9]+, [0-9]+\] = [-0-9.e+]+ m: heights must lie within \+-1 m .*: no reader would take the file back" -- g surface generate --rq 1m --nx 16 --ny 16 --spacing 1um -o "$tmp/27-huge.x3p"
[[ -e "$tmp/27-huge.x3p" ]] && { echo "FAIL 27: $tmp/27-huge.x3p written"; fail=1; }
