# 06: fit data and options (found: extreme observations made Ceres fail with exit 1 and no row
# named; free constants no observed column depends on gave exit 0 with NaN standard errors written
# to -o; --weight nan and --weight -1 were accepted). Now the data's values have stated ranges
# (docs/guide/fit.md) checked at file:line and column, a free constant the data cannot move is
# refused before Ceres runs (nothing written), and weights must be finite and positive.
scratch="$tmp/06"; mkdir -p "$scratch"  # this folder's scratch, removed at the end (other folders share $tmp)
F="--model kogut-etsion --case ../../../gears/m6z30.toml --free load_coefficient_1,load_exponent_1"
check denormal-observation 2 "denormal.csv:3: key 'load_star' = 1e-320: must be 0 or lie in \[1e-12, 1e\+12\].*\(column 2\)" -- g fit $F --data denormal.csv -o "$scratch/a.toml"
check overflowing-observation 2 "overflow.csv:3: key 'load_star' = 1e308: must be 0 or lie in" -- g fit $F --data overflow.csv -o "$scratch/a.toml"
check no-dependence 2 "free constant 'load_coefficient_1' of model 'kogut-etsion' changes none of the observed values \(area_star" -- g fit $F --data area-only.csv -o "$scratch/b.toml"
check nothing-written 0 "^$" -- ls -A "$scratch"
check weight-nan 2 "--weight nan \(for load_star\): a weight must be finite, positive" -- g fit $F --data ke.csv --observe load_star --weight nan
check weight-negative 2 "--weight -1 \(for load_star\): a weight must be finite, positive" -- g fit $F --data ke.csv --observe load_star --weight -1 -q
check weight-zero 2 "--weight 0 \(for load_star\)" -- g fit $F --data ke.csv --observe load_star --weight 0 -q
# The same data with a good weight fits, and writes no nan
check weight-good 0 "" -- g fit $F --data ke.csv --observe load_star --weight 2 -q -o "$scratch/c.toml"
no_nan fitted-toml-finite "$scratch/c.toml"
rm -rf "$scratch"
