# 32 (issue 30, finding 12): `geartrib tradeoff` on a deterministic case whose flanks are a measured
# trace sampled coarser than 0.125 um (optical profilers: 0.3-1 um) was refused with exit 2, blaming
# a --set contact.element_size the user never gave: the knob's ladder always went down to 0.125 um,
# which the case's own rule (elements not finer than the profile spacing) refuses. And tradeoff checked
# its output folder only after computing (48 s). Now the ladder keeps the settings not finer than the
# flanks' spacing, with the spacing itself as the reference when it falls between them
# (runs::finest_element_size), and the outputs are reserved before the first run.
/usr/bin/python3 make_inputs.py "$tmp" 1 1 && mkdir "$tmp/03" && /usr/bin/python3 make_inputs.py "$tmp/03" 0.3 0.5
t=(tradeoff --knob element_size --min-time 0 --set contact.positions=11 -q)
g "${t[@]}" "$tmp/trace.toml" --csv > "$tmp/1um.csv" 2>&1
check trace-1um-ladder 0 "^element_size,1 um,.*reference" -- cat "$tmp/1um.csv"
check trace-1um-coarser-settings 0 "element_size,4 um,.*element_size,2 um,.*element_size,1 um," -- tr '\n' ' ' < "$tmp/1um.csv"
check trace-1um-nothing-finer 1 "" -- grep -E "^element_size,0\.(5|25|125) um" "$tmp/1um.csv"
g "${t[@]}" "$tmp/03/trace.toml" --csv > "$tmp/03um.csv" 2>&1
check trace-0.3um-reference 0 "^element_size,0.3 um,.*reference" -- cat "$tmp/03um.csv"
check trace-0.3um-ladder-above 0 "^element_size,0.5 um," -- cat "$tmp/03um.csv"
check trace-0.3um-nothing-finer 1 "" -- grep -E "^element_size,0\.(25|125) um" "$tmp/03um.csv"
# The outputs before the computation: a missing folder is named at once (the whole deterministic
# tradeoff takes minutes: a 5 s limit fails it if the check comes after).
check missing-folder-first 2 "missing/t.csv: cannot be written: No such file or directory" -- timeout 5 "$bin" tradeoff ../../../gears/m6z30-deterministic.toml -q -o "$tmp/missing/t.csv"
check missing-csv-folder-first 2 "missing/t.csv: cannot be written" -- timeout 5 "$bin" tradeoff ../../../gears/m6z30-deterministic.toml -q --csv "$tmp/missing/t.csv"
check missing-png-folder-first 2 "missing/t.png: cannot be written" -- timeout 5 "$bin" tradeoff ../../../gears/m6z30-deterministic.toml -q -o "$tmp/missing/t.png"
check nothing-written 1 "" -- test -e "$tmp/missing"
