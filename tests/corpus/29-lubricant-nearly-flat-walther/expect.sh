# 29: fuzz_lubricant's finding (issue 30): a lubricant whose viscosity is nearly flat in temperature
# (311.6 mm^2/s at 40 degC, 311.15 at 100 degC). Walther's law alone reaches 2e7 mm^2/s only near
# 0 K, so the law range began at 0 K, where ISO/TR 15144-1's alpha factor 1 + 516 (1/T - 1/311) is
# infinite (the harness evaluates every law over the whole law range). Promised: the law range stops
# at -100 degC (kMinOilTemperature; tested in LubricantRanges.DataLeavingALawsRangeIsRefusedAtItsKey
# and seeded into fuzz_lubricant by scripts/fuzz.sh); here, the run-level promise on the same oil: at
# the coldest oil the file allows (its data's -20 degC less 40 K) a run is finite, and colder is
# refused at the key.
scratch="$tmp/29"; mkdir -p "$scratch"
case_file="$(cd ../../../gears && pwd)/m6z30.toml"
lub="$PWD/nearly-flat.toml"
check cold-edge 0 "" -- g run "$case_file" -q --positions 11 --set "lubricant.file=$lub" --set "oil_temperature=-60 degC" --csv "$scratch/cold.csv" -o "$scratch/cold.h5"
no_nan cold-edge-finite "$scratch/cold.csv"
check colder 2 "oil_temperature" -- g run "$case_file" -q --positions 11 --set "lubricant.file=$lub" --set "oil_temperature=-61 degC" -o "$scratch/colder.h5"
# Data colder than the floor (the third finding: a file with data from 100 K was taken, its data
# range outside its law range): refused at the key and line.
sed "s/^min_temperature = .*/min_temperature = '-150 degC'/" "$lub" > "$scratch/too-cold.toml"
check data-below-floor 2 "too-cold.toml:[0-9]+: key 'min_temperature' = .*-150 degC.*: below 173.15 K \(-100 degC\)" -- g run "$case_file" -q --positions 11 --set "lubricant.file=$scratch/too-cold.toml" -o "$scratch/x.h5"
rm -rf "$scratch"
