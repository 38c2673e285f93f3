# 19: stale and concurrent temporaries (issue 30, finding 9). Found: a temporary named by PID, left
# by a SIGKILLed run, failed every later run with the same PID ("File exists", exit 2; a container's
# PID 1 every time); writers of one path in one process collided. Promised: temporaries unique per
# attempt; a stale one never blocks.
scratch="$tmp/19"; mkdir -p "$scratch"
gears="$(cd ../../../gears && pwd)"
# The same PID as a stale temporary's: exec keeps the shell's.
check exec-same-pid 0 "wrote out.h5" -- bash -c 'cd "$1" && touch .out.h5.tmp.$$ && exec "$2" run "$3" -o out.h5 --positions 5 -q' _ "$scratch" "$bin" "$gears/m6z30-dry.toml"
check exec-stale-kept 0 "^1 $" -- bash -c 'ls -A "$1" | grep -c "^\.out\.h5\.tmp\." | tr "\n" " "' _ "$scratch"
rm -f "$scratch"/.out.h5.tmp.* "$scratch/out.h5"
# As in a container: PID 1 killed mid-run, then the next job as PID 1 (needs unshare and root).
if unshare --pid --fork true 2>/dev/null; then
  (timeout -s KILL 0.5 unshare --pid --fork "$bin" run "$gears/m6z30-deterministic.toml" -o "$scratch/out.h5" -q --set running_in.meshes=50; true) >/dev/null 2>&1  # (true: no "Killed" notice)
  check pid1-killed-nothing-at-target 1 "" -- test -e "$scratch/out.h5"
  check pid1-next-job 0 "wrote .*out.h5" -- unshare --pid --fork "$bin" run "$gears/m6z30-dry.toml" -o "$scratch/out.h5" --positions 5 -q
  rm -f "$scratch"/.out.h5.tmp.* "$scratch/out.h5"
else
  echo "skip pid-1 jobs: unshare --pid not permitted here"
fi
# Eight processes writing one path at once: all succeed, one whole file, no temporary left.
for k in 1 2 3 4 5 6 7 8; do
  "$bin" surface generate --nx 128 --ny 128 --seed $k -o "$scratch/same.x3p" >"$scratch/log.$k" 2>&1 &
done
wait
check concurrent-all-succeed 0 "^$" -- bash -c 'cat "$1"/log.* | grep -v "^wrote\|points at"; true' _ "$scratch"
rm -f "$scratch"/log.*
check concurrent-one-file 0 "^same.x3p $" -- bash -c 'ls -A "$1" | tr "\n" " "' _ "$scratch"
check concurrent-file-whole 0 "128 x 128 points" -- g surface stats "$scratch/same.x3p"
rm -rf "$scratch"
