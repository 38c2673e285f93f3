# 14: a write error while the HDF5 result is written (issue 30, finding 1). Found: exit 139 (SIGSEGV
# in HDF5's exit handler) with a corrupt file under the final name. The file-size limit (ulimit -f,
# SIGXFSZ ignored: EFBIG) stands in for a full disk (ENOSPC takes the same path). Promised: exit 1,
# the target named with the reason, nothing at the target, no temporary.
scratch="$tmp/14"; mkdir -p "$scratch"
cases="$(cd ../../../gears && pwd)"
# limited KIB ARGS...: geartrib in $scratch under a file-size limit of KIB KiB, SIGXFSZ ignored.
limited() {
  local kib=$1; shift
  (trap '' XFSZ; ulimit -f "$kib"; cd "$scratch" && g "$@")
}
check run-efbig 1 "out.h5: not written: cannot write .*File too large" -- limited 20 run "$cases/m6z30-dry.toml" -o out.h5 -q
check run-nothing-left 0 "^$" -- ls -A "$scratch"
check sweep-efbig 1 "sw.h5: not written: .*File too large" -- limited 20 sweep "$cases/m6z30.toml" --set positions=5,7 -o sw.h5 --csv sw.csv -q
check sweep-nothing-left 0 "^$" -- ls -A "$scratch"
check deterministic-efbig 1 "det.h5: not written: .*File too large" -- limited 100 run "$cases/m6z30-deterministic.toml" -o det.h5 --csv det.csv -q --set running_in.meshes=1
check deterministic-nothing-left 0 "^$" -- ls -A "$scratch"
# An old result stays as it was.
echo old > "$scratch/out.h5"
check old-target-efbig 1 "File too large" -- limited 20 run "$cases/m6z30-dry.toml" -o out.h5 -q
check old-target-kept 0 "^old$" -- cat "$scratch/out.h5"
rm -f "$scratch/out.h5"
# The surface writers: HDF5 and X3P (libzip writing through geartrib's own file), and a text table.
check surface-h5-efbig 1 "s.h5: not written: .*File too large" -- limited 64 surface generate --nx 256 --ny 256 -o s.h5
check surface-x3p-efbig 1 "s.x3p: not written: .*File too large" -- limited 64 surface generate --nx 256 --ny 256 -o s.x3p
check kinematics-efbig 1 "k.csv: not written: .*File too large" -- limited 8 kinematics "$cases/m6z30.toml" --positions 2000 -o k.csv
check surfaces-nothing-left 0 "^$" -- ls -A "$scratch"
# Under the limit, the same run writes a readable file (the limit alone made the failure).
check run-within-limit 0 "wrote out.h5" -- limited 1000 run "$cases/m6z30-dry.toml" -o out.h5 -q
check run-within-limit-hdf5 0 "H +D +F" -- od -c -N 4 "$scratch/out.h5"
rm -f "$scratch"/*
# SIGXFSZ not ignored: the limit kills the process (128 + 25), and the handler removes the temporaries first.
check run-sigxfsz 153 "" -- bash -c 'ulimit -f 20; cd "$1" && exec "$2" run "$3" -o out.h5 -q' _ "$scratch" "$bin" "$cases/m6z30-dry.toml"
check sigxfsz-nothing-left 0 "^$" -- ls -A "$scratch"
# A real full disk (ENOSPC): a 1 MiB tmpfs of its own, nearly filled, in a mount namespace of its
# own (root with CAP_SYS_ADMIN; skipped without). Prints the exit status and what is left.
full_disk() {
  unshare -m bash -c 'mkdir -p "$1" && mount -t tmpfs -o size=1m tmpfs "$1" && head -c 1000000 /dev/zero > "$1/filler" 2>/dev/null
    cd "$1" && "${@:2}"; echo "exit=$? left=$(ls -A | tr "\n" " ")"' _ "$scratch/full" "$@"
}
if unshare -m bash -c 'mkdir -p "$1" && mount -t tmpfs -o size=1m tmpfs "$1"' _ "$scratch/full" 2>/dev/null; then
  check enospc-run 0 "^exit=1 left=filler $" -- full_disk "$bin" run "$cases/m6z30.toml" -o out.h5 -q
  check enospc-run-message 0 "out.h5: not written: .*No space left on device" -- full_disk "$bin" run "$cases/m6z30.toml" -o out.h5 -q
  check enospc-sweep 0 "^exit=1 left=filler $" -- full_disk "$bin" sweep "$cases/m6z30.toml" --set positions=5,7 -o sw.h5 --csv sw.csv -q
  # The table on the full disk, the HDF5 file beside it on another: neither is written.
  check enospc-stdout 0 "^exit=1 left=filler table.csv $" -- full_disk bash -c '"$0" run "$1" -o ../ok.h5 --csv -q > table.csv' "$bin" "$cases/m6z30-dry.toml"
  check enospc-stdout-no-h5 1 "" -- test -e "$scratch/ok.h5"
else
  echo "skip a real full disk: no private tmpfs mount here"
fi
rm -rf "$scratch"
