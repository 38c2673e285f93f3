# 01: an HDF5 topography whose dx or dy attribute is an array (found: read into one double, a
# stack buffer overflow; an array dy was silently replaced by dx). Now an attribute is read only
# when it holds exactly one floating-point number (a scalar or a 1-element array); anything else
# is refused naming the file and the attribute, as is a spacing outside 1e-12 m to 1000 m.
check dx-array 2 "dx-array.h5: key '/z dx': attribute dx holds 2 values, not one number" -- g surface stats dx-array.h5
check dy-array 2 "dy-array.h5: key '/z dy': attribute dy holds 64 values, not one number" -- g surface stats dy-array.h5
check dx-string 2 "dx-string.h5: key '/z dx': attribute dx is not a floating-point number" -- g surface stats dx-string.h5
check dx-integer 2 "dx-integer.h5: key '/z dx': attribute dx is not a floating-point number" -- g surface stats dx-integer.h5
check dx-tiny 2 "dx-tiny.h5: key '/z dx' = 1e-300: spacing 1e-300 m outside 1e-12 m to 1000 m" -- g surface stats dx-tiny.h5
# A one-element array is one number: read (what h5py writes for attrs['dx'] = [5e-7]).
check dx-one-element 0 "dx-one-element.h5: 16 x 16 points at 0.5 x 0.5 um" -- g surface stats dx-one-element.h5
# The same reader behind multi-asperity --topography.
check dx-array-multi-asperity 2 "dx-array.h5: key '/z dx': attribute dx holds 2 values" -- g multi-asperity --topography dx-array.h5 --delta-pc 0.5797nm --elements 2048
# ... and behind a case's [pinion.flank.topography] table (nothing written).
check dx-array-case 2 "dx-array.h5: key '/z dx': attribute dx holds 2 values" -- g run ../../../gears/m6z30-measured.toml -o "$tmp/01-case.h5" --positions 5 -q --set "pinion.flank.topography.file=$PWD/dx-array.h5"
[[ ! -e "$tmp/01-case.h5" ]] && echo "ok   dx-array-case-wrote-nothing" || { echo "FAIL dx-array-case-wrote-nothing"; fail=1; }
