# 28: `asperity --compare` against a reference table holding a 0 (found in review of issue 30: the
# relative difference was inf, written with exit 0). Promised: every number written is finite; where
# the reference is 0, diff_% is the symmetric 200 (model - reference)/(|model| + |reference|).
scratch="$tmp/28"; mkdir -p "$scratch"
printf '%s\n' 'delta_star,contact_radius@zero[um],max_pressure@zero[GPa]' '2,0,0' '6,0.0092,2.42' > "$scratch/zero.csv"
check compare-zero 0 "" -- g asperity --model continuous --compare "$scratch/zero.csv" --csv "$scratch/out.csv"
no_nan compare-zero-finite "$scratch/out.csv"
check compare-zero-200 0 "^2,0,[0-9.e+-]+,200,0,[0-9.e+-]+,200$" -- cat "$scratch/out.csv"
rm -rf "$scratch"
