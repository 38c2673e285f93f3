# 05: topography values (found: inf heights in HDF5 gave exit 0 with NaN statistics and `surface
# clean` wrote an all-NaN file; 1e308 um heights gave Rq = inf; '# spacing: 5e-1' was read as metres,
# the exponent's 'e' taken for a unit, where '# spacing: 0.5' is micrometres; a grid in metres read
# as micrometres without a word). Now heights must be finite and within +-1 m (NaN only as the
# documented missing-point marker), a header number is read whole before any unit, and a surface
# whose Rq or spacing is implausible for the unit it was read in draws a warning naming the fix.
# Also 10's `surface generate --spacing 1e-300m` (exit 0 writing NaN) and 11's `--resample 1e-30um`
# (exit 2 naming nothing).
scratch="$tmp/05"; mkdir -p "$scratch"
check inf-height 2 "inf-height.h5: key '/z\[3\]\[4\]' = inf: height inf m beyond \+-1 m" -- g surface stats inf-height.h5 --csv
check inf-height-clean 2 "inf-height.h5: key '/z\[3\]\[4\]' = inf" -- g surface clean inf-height.h5 -o "$scratch/cleaned.h5"
[[ ! -e "$scratch/cleaned.h5" ]] && echo "ok   inf-height-clean-wrote-nothing" || { echo "FAIL inf-height-clean-wrote-nothing"; fail=1; }
check neg-inf-height 2 "neg-inf-height.h5: key '/z\[7\]\[9\]' = -inf" -- g surface stats neg-inf-height.h5
check int-heights 2 "int-heights.h5: key '/z': /z must hold floating-point heights" -- g surface stats int-heights.h5
check huge-heights 2 "huge-heights.txt:6: 1e308: height 1e\+302 m beyond \+-1 m; lengths were read in um" -- g surface stats huge-heights.txt --csv --form 0
# NaN in HDF5 marks a missing point (documented): read, filled, written without NaN.
check nan-height 0 "nan-height.h5: 16 x 16 points at 0.5 x 0.5 um; 2 missing in the file" -- g surface clean nan-height.h5 --fill -o "$scratch/filled.txt"
no_nan nan-height-filled "$scratch/filled.txt"
# '# spacing: 5e-1' is the bare number 0.5 in the file's unit (um), as '# spacing: 0.5' is.
check spacing-plain 0 "spacing-plain.txt: 8 x 8 points at 0.5 x 0.5 um" -- g surface stats spacing-plain.txt --csv --form 0
check spacing-exponent 0 "spacing-exponent.txt: 8 x 8 points at 0.5 x 0.5 um" -- g surface stats spacing-exponent.txt --csv --form 0
# Lengths in metres without a units line, read as um: heights ~1e-7 (Rq 2e-13 m) and a point
# cloud's 1e-5 spacing (1e-11 m) draw warnings naming the fix; a 5e-7 spacing (5e-13 m) is beyond
# the limits: refused, with the same hint. With --unit m all three are read right, without a word.
unit_fix="lengths were read in um \(no '# units:' line\): if the file is in another unit, state it with a '# units: <unit>' line or --unit"
check metres-warning 0 "metres.txt: warning: Rq 2.16e-13 m is implausible for a measured flank \(1 nm to 100 um expected\): $unit_fix" -- g surface stats metres.txt --csv
check metres-coarse-warning 0 "metres-coarse.xyz: warning: spacing 1e-11 m x 1e-11 m is implausible for a measured surface \(1 nm to 1 m expected\): $unit_fix" -- g surface stats metres-coarse.xyz --csv
check metres-spacing 2 "metres-spacing.txt:2: key 'spacing' = 5e-7: spacing 5e-13 m outside 1e-12 m to 1000 m; $unit_fix" -- g surface stats metres-spacing.txt --csv
for f in metres.txt metres-coarse.xyz metres-spacing.txt; do
  out="$(g surface stats "$f" --unit m --csv 2>&1)"
  if [[ $? -eq 0 ]] && ! grep -q warning <<<"$out"; then echo "ok   $f-unit-m"; else echo "FAIL $f-unit-m"; echo "$out" | head -3; fail=1; fi
done
# 10: a generated surface's spacing is range-checked (1e-300 m wrote NaN), and so is its Rq.
check generate-spacing 2 "--spacing '1e-300m': must lie in \[1e-12 m, 1000 m\]" -- g surface generate self-affine -o "$scratch/g.csv" --nx 32 --ny 32 --spacing 1e-300m
[[ ! -e "$scratch/g.csv" ]] && echo "ok   generate-spacing-wrote-nothing" || { echo "FAIL generate-spacing-wrote-nothing"; fail=1; }
check generate-rq 2 "--rq '1e300m': must lie in \(0 m, 1 m\]" -- g surface generate self-affine -o "$scratch/g.csv" --nx 32 --ny 32 --rq 1e300m
check generate-spacing-at-limit 0 "" -- g surface generate self-affine -o "$scratch/g.csv" --nx 32 --ny 32 --spacing 1e-12m --short-cutoff 4e-12m --rolloff 1e-11m
no_nan generate-spacing-at-limit-finite "$scratch/g.csv"
check generate-too-many-points 2 "--nx 16384 --ny 16384: more than the 33554432 points a grid may hold" -- g surface generate self-affine -o "$scratch/g.h5" --nx 16384 --ny 16384
# 11: --resample far below any spacing: the option named (was "resampling spacing too small").
check resample-option 2 "--resample '1e-30um': must lie in \[1e-12 m, 1000 m\]" -- g surface stats spacing-plain.txt --resample 1e-30um
rm -rf "$scratch"
