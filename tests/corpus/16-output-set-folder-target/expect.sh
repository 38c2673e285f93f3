# 16: a target that is a folder (issue 30, finding 5). Found: the run computed, out.h5 committed,
# then "cannot rename ... Is a directory" on the CSV (exit 1, half the outputs written); tradeoff
# found an unwritable target only after computing. Promised: exit 2 naming the target before any
# work, nothing written. The slow cases run under `timeout 20`: computing first would time out (124).
scratch="$tmp/16"; mkdir -p "$scratch/dir" "$scratch/dir.x3p"  # dir.x3p: a folder with a surface's extension
gears="$(cd ../../../gears && pwd)"
in_scratch() { (cd "$scratch" && g "$@"); }
check run-csv-folder 2 "dir: is a folder" -- in_scratch run "$gears/m6z30.toml" -o out.h5 --csv dir --positions 11 -q
check run-h5-folder 2 "dir: is a folder" -- in_scratch run "$gears/m6z30.toml" -o dir --csv out.csv --positions 11 -q
check sweep-csv-folder 2 "dir: is a folder" -- in_scratch sweep "$gears/m6z30.toml" --set positions=5,7 -o sw.h5 --csv dir -q
check sweep-before-points 2 "dir: is a folder" -- timeout 20 "$bin" sweep "$gears/m6z30.toml" --set torque=100Nm:1000Nm:3000 -o "$scratch/sw.h5" --csv "$scratch/dir" -q
check tradeoff-before-runs 2 "dir: is a folder" -- timeout 20 "$bin" tradeoff "$gears/m6z30-deterministic.toml" -q -o "$scratch/dir"
check tradeoff-plot-csv-folder 2 "dir: is a folder" -- timeout 20 "$bin" tradeoff "$gears/m6z30-deterministic.toml" -q -o "$scratch/t.png" --csv "$scratch/dir"
check tradeoff-missing-folder 2 "no-such/t.csv: cannot be written: No such file or directory" -- timeout 20 "$bin" tradeoff "$gears/m6z30-deterministic.toml" -q -o "$scratch/no-such/t.csv"
check case-folder 2 "dir: is a folder" -- in_scratch case "$gears/m6z30.toml" -o dir
check kinematics-folder 2 "dir: is a folder" -- in_scratch kinematics "$gears/m6z30.toml" -o k.txt --csv dir
check dynamics-folder 2 "dir: is a folder" -- in_scratch dynamics "$gears/m6z30.toml" -o dir
check asperity-folder 2 "dir: is a folder" -- in_scratch asperity --case "$gears/m6z30.toml" --csv dir
check multi-asperity-folder 2 "dir: is a folder" -- in_scratch multi-asperity --case "$gears/m6z30.toml" -o m.txt --csv dir
check surface-generate-folder 2 "dir.x3p: is a folder" -- in_scratch surface generate --nx 64 --ny 64 -o dir.x3p
g surface generate --nx 64 --ny 64 -o "$tmp/16-flank.h5" >/dev/null
check surface-equivalent-folder 2 "dir: is a folder" -- in_scratch surface equivalent "$tmp/16-flank.h5" "$tmp/16-flank.h5" -o e.x3p --csv dir
check surface-stats-folder 2 "dir: is a folder" -- in_scratch surface stats "$tmp/16-flank.h5" --csv dir
check fit-folder 2 "dir: is a folder" -- in_scratch fit --model kogut-etsion --data "$gears/../validation/fem-reference/ccx-elastic.csv" -o f.toml --report dir
check fem-folder 2 "dir: is a folder" -- in_scratch fem single-asperity -o f.csv --details dir
check nothing-written 0 "^dir dir.x3p $" -- bash -c 'ls -A "$1" | tr "\n" " "; ls -A "$1/dir"' _ "$scratch"
rm -rf "$scratch" "$tmp/16-flank.h5"
