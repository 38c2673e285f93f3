# 20: `sweep --merge` trusted the /sweep attributes and /points datasets of its shard files (issue
# 30, finding 3). Found: shard = "4000000000000/3" and shard_count = "0" wrote out of bounds
# (SIGSEGV, temporaries left behind), shard = "100000/3" wrote out of bounds silently,
# points_total = "99999999999" allocated 12.5 GB, "abc" said only "error: stoul". Now every number
# a shard states is checked before it is used (io::merge_sweep_shards), and the shards against
# each other: exit 2 naming the file, the attribute or column, its value and the rule; nothing
# written. s0/s1/s2.h5: a 4-point sweep in 3 shards; each other file one edit of one of them
# (make_inputs.py).
m20="$tmp/20"; mkdir -p "$m20"
merge() { g sweep --merge "$@" -o "$m20/m.h5" --csv "$m20/m.csv" -q; }
check shards-merge 0 "" -- merge s0.h5 s2.h5 s1.h5
check shards-merged-in-order 0 "^0,1,2,3$" -- bash -c "grep -v '^#' '$m20/m.csv' | tail -n +2 | cut -d, -f1 | paste -sd,"
rm -f "$m20/m.h5" "$m20/m.csv"
a="key '/sweep attribute"
check shard-huge 2 "shard-huge.h5: $a shard' = \"4000000000000/3\": must be i/n with 0 <= i < n and n the shard_count \(3\)" -- merge s0.h5 shard-huge.h5 s2.h5
check shard-past-count 2 "shard-past-count.h5: $a shard' = \"100000/3\": must be i/n" -- merge s0.h5 shard-past-count.h5 s2.h5
check shard-not-a-number 2 "shard-not-a-number.h5: $a shard' = \"x/3\": must be i/n" -- merge s0.h5 shard-not-a-number.h5 s2.h5
check shard-other-count 2 "shard-other-count.h5: $a shard' = \"1/4\": must be i/n .* shard_count \(3\)" -- merge s0.h5 shard-other-count.h5 s2.h5
check count-zero 2 "count-zero.h5: $a shard_count' = \"0\": must be a whole number of shards from 1 to 100000" -- merge count-zero.h5
check count-huge 2 "count-huge.h5: $a shard_count' = \"99999999999\": must be a whole number of shards" -- merge count-huge.h5 s1.h5 s2.h5
check total-huge 2 "total-huge.h5: $a points_total' = \"99999999999\": must be a whole number of points from 1 to 100000" -- merge total-huge.h5 s1.h5 s2.h5
check total-abc 2 "total-abc.h5: $a points_total' = \"abc\": must be a whole number of points" -- merge total-abc.h5 s1.h5 s2.h5
check total-signed 2 "total-signed.h5: $a points_total' = \"\+4\": must be a whole number" -- merge total-signed.h5 s1.h5 s2.h5
check total-missing 2 "total-missing.h5: $a points_total': missing: not a geartrib sweep shard" -- merge total-missing.h5 s1.h5 s2.h5
# One sweep: the totals, the axes and the base case agree (the signature alone was compared).
check total-other 2 "total-other.h5: $a points_total' = \"3\": from another sweep .* than s0.h5, whose points_total is \"4\"" -- merge s0.h5 s1.h5 total-other.h5
check sets-other 2 "sets-other.h5: $a sets' = \"torque=1Nm\": from another sweep" -- merge s0.h5 s1.h5 sets-other.h5
check scene-other 2 "scene-other.h5: key '/scene': from another sweep than s0.h5: the base case's text differs" -- merge s0.h5 s1.h5 scene-other.h5
check shard-twice 2 "s1.h5: $a shard' = \"1/3\": shard 1/3 given twice \(also s1.h5\)" -- merge s0.h5 s1.h5 s1.h5 s2.h5
check shard-missing 2 "shard 1/3 is missing" -- merge s0.h5 s2.h5
# The point column: each a whole number below points_total, of its shard, once; the rows those
# the shard owns (a point cast from NaN or 1e300 to an index was undefined behaviour).
for f in point-nan point-negative point-huge point-fraction point-other-shard; do
  check "$f" 2 "$f.h5: key '/points/point' = [^ ]+ \(row 0\): must be a point of shard 1/3: a whole number below points_total \(4\) with index % 3 == 1" -- merge s0.h5 "$f.h5" s2.h5
done
check point-twice 2 "point-twice.h5: key '/points/point' = 0 \(row 1\): a point given twice in the shard" -- merge point-twice.h5 s1.h5 s2.h5
check rows-short 2 "rows-short.h5: key '/points/point' = 1 rows: shard 0/3 of a 4-point sweep owns 2 points" -- merge rows-short.h5 s1.h5 s2.h5
check rows-long 2 "rows-long.h5: key '/points/point' = 3 rows: shard 1/3 of a 4-point sweep owns 1 point" -- merge s0.h5 rows-long.h5 s2.h5
check status-other 2 "status-other.h5: key '/points/status' = \"done\" \(row 0\): must be ok or error" -- merge s0.h5 status-other.h5 s2.h5
check status-missing 2 "status-missing.h5: key '/points/status': missing: not a geartrib sweep shard" -- merge s0.h5 status-missing.h5 s2.h5
# Sizes the file declares, refused before allocating: a column listed 1000 times (each a copy of
# its values), a text column of 10^9 strings (unwritten).
check column-listed-twice 2 "column-listed-twice.h5: not a readable geartrib sweep file \(column point listed twice" -- merge s0.h5 column-listed-twice.h5 s2.h5
check text-column-huge 2 "text-column-huge.h5: not a readable geartrib sweep file \(text column message declares 1000000000 strings, the table has 1 rows\)" -- merge s0.h5 text-column-huge.h5 s2.h5
# A pipe named as a shard: refused, not read without end.
mkfifo "$m20/pipe.h5"
check shard-is-a-pipe 2 "pipe.h5: .*not a regular file" -- merge s0.h5 "$m20/pipe.h5" s2.h5
rm -f "$m20/pipe.h5"
check nothing-written 0 "^$" -- ls -A "$m20"
rm -rf "$m20"
