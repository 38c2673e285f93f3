# 09: all outputs or none. Found: `run -o out.h5 --csv missing/out.csv` renamed the HDF5 into
# place, then failed on the CSV (exit 1). Now the folders are checked before the run and nothing
# is written unless every output is.
cases=../../../gears/m6z30.toml
echo old > "$tmp/out.h5"
check run-missing-csv-folder 2 "no-such-dir/out.csv: cannot be written" -- g run "$cases" -o "$tmp/out.h5" --csv "$tmp/no-such-dir/out.csv" --positions 11 -q
check run-old-target-kept 0 "^old$" -- cat "$tmp/out.h5"
check sweep-missing-csv-folder 2 "no-such-dir/sw.csv: cannot be written" -- g sweep "$cases" --set positions=5 -o "$tmp/sw.h5" --csv "$tmp/no-such-dir/sw.csv" -q
check sweep-nothing-written 0 "^$" -- ls -A "$tmp" --ignore=out.h5
# A read-only folder (root ignores permissions: only as another user).
if [[ $(id -u) -ne 0 ]]; then
  mkdir "$tmp/ro" && chmod a-w "$tmp/ro"
  check run-read-only-folder 2 "ro/x.h5: cannot be written: Permission denied" -- g run "$cases" -o "$tmp/ro/x.h5" --positions 11 -q
fi
# A killed sweep leaves no target and no temporary, whichever phase the signal meets.
# (The binary itself, not g: the signal must reach it, not a wrapping shell.)
"$bin" sweep "$cases" --set torque=100Nm:1000Nm:3000 -o "$tmp/killed.h5" --csv "$tmp/killed.csv" -q &
sleep 0.5
kill -TERM $!
wait $! 2>/dev/null
check killed-sweep-leaves-nothing 0 "^$" -- ls -A "$tmp" --ignore=out.h5
# A truncated shard is refused by the merge, naming it.
g sweep "$cases" --set positions=5,7 --shard 0/2 -o "$tmp/s0.h5" -q
g sweep "$cases" --set positions=5,7 --shard 1/2 -o "$tmp/s1.h5" -q
head -c 3000 "$tmp/s1.h5" > "$tmp/s1-cut.h5"
check merge-truncated-shard 2 "s1-cut.h5.*not a readable geartrib sweep file" -- g sweep --merge "$tmp/s0.h5" "$tmp/s1-cut.h5" -o "$tmp/m.h5"
check merge-nothing-written 1 "" -- test -e "$tmp/m.h5"
