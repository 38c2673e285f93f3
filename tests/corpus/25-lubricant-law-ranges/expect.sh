# 25 (issue 30, finding 4, lubricant files): a valid-looking lubricant file whose data left one of
# its laws' ranges ran and wrote NaN with exit 0. Found: pressure_viscosity_temperature = "1000 K"
# (allowed 100..1000 K) carried alpha through ISO/TR 15144-1's factor 1 + 516 (1/T - 1/311 K), which
# is negative above 782.8 K: "alpha -116.5 1/GPa", film and lambda NaN; data to 1000 K let a run at
# 800 K take the same negative factor; the linear density went negative when hot; Walther's law
# overflowed to inf for a steep oil when cold. Now each law states its range
# (docs/theory/lubrication.md#where-the-laws-hold) and a file whose data leave one is refused at the
# key, with the law, the value it gives and the limit.
scratch="$tmp/25"; mkdir -p "$scratch"
cases=../../../gears/m6z30.toml
run() { g run "$cases" --set "lubricant.file=$PWD/$1" "${@:2}" -o "$scratch/out.h5" --positions 11 -q; }
check alpha-reference-1000K 2 "alpha-at-1000K.toml:19: key 'pressure_viscosity_temperature' = \"1000 K\": 1000.00 K lies outside \[233.15, 453.15\] K, this oil's data range with at most 40 K below and 60 K above it" -- run alpha-at-1000K.toml
check data-to-1000K 2 "hot-range.toml:15: key 'max_temperature' = \"1000 K\": beyond 673.15 K \(400 degC\).*factor 1 \+ 516 \(1/T - 1/311 K\) falls to 0.107 there and to 0 at 782.8 K" -- run hot-range.toml
check data-to-1000K-oil-800K 2 "hot-range.toml:15: key 'max_temperature' = \"1000 K\": beyond 673.15 K" -- run hot-range.toml --set "oil_temperature=800 K"
check walther-cold-overflow 2 "walther-cold-overflow.toml:14: key 'min_temperature' = \"100 K\": Walther's law .* gives beyond 1e308 m\^2/s at 100.00 K, beyond the 2e7 mm\^2/s top of ASTM D341's range: raise min_temperature to at least 309.08 K" -- run walther-cold-overflow.toml
check walther-below-2cst 2 "walther-below-2cst.toml:15: key 'max_temperature' = \"200 degC\": Walther's law .* gives 1.37 mm\^2/s at 473.15 K, below the 2 mm\^2/s where ASTM D341's nu \+ 0.7 form holds: lower max_temperature to at most 435.64 K" -- run walther-below-2cst.toml
check density-below-half 2 "density-below-half.toml:8: key 'density_temperature_coefficient' = \"1.9e-3 1/K\": the density line falls to 0.407 of its 15 degC value at max_temperature \(600.00 K\)" -- run density-below-half.toml
check correlation-38C-outside 2 "correlation-outside.toml: key 'pressure_viscosity_coefficient': omitted, so ISO/TR 15144-1's correlation takes the viscosity at 38 degC, outside \[313.15, 453.15\] K" -- run correlation-outside.toml
# The case's own temperatures against the shipped oil's operating range (data 0-120 degC, 40 K
# below and 60 K above): the reproducer's 800 K oil, and a given bulk temperature.
check oil-at-800K 2 "m6z30.toml \(--set operating.oil_temperature=800 K\): key 'operating.oil_temperature' = \"800 K\": 526.9 degC is beyond the lubricant's data range \[0.0, 120.0\] degC and the range its laws are taken to for the oil, \[-40.0, 180.0\] degC" -- g run "$cases" --set "oil_temperature=800 K" -o "$scratch/out.h5" --positions 11 -q
check bulk-at-500K 2 "key 'operating.bulk_temperature' = \"500 K\": 226.9 degC is beyond the lubricant's data range" -- g run "$cases" --set "operating.bulk_temperature=500 K" -o "$scratch/out.h5" --positions 11 -q
[[ -e "$scratch/out.h5" ]] && { echo "FAIL 25: a refused run left $scratch/out.h5"; fail=1; }
rm -rf "$scratch"
