# 15: output targets that are not regular files (issue 30, finding 2). Found: a device node, a FIFO
# or a symbolic link replaced by a regular file (as root, `-o /dev/null` replaced /dev/null).
# Promised: a character device or FIFO written as a stream and kept; a link followed (its file
# replaced, the link kept); a link to nothing, a folder refused (exit 2). Private nodes only: mknod
# needs root (CAP_MKNOD) and a mount that allows devices, skipped without them.
scratch="$tmp/15"; mkdir -p "$scratch"
dry="$(cd ../../../gears && pwd)/m6z30-dry.toml"
run() { g run "$dry" --positions 5 -q "$@"; }
if mknod -m 666 "$scratch/null" c 1 3 2>/dev/null && mknod -m 666 "$scratch/full" c 1 7 && : > "$scratch/null" 2>/dev/null; then
  check device-null 0 "wrote .*null" -- run -o "$scratch/null"
  check device-null-kept 0 "" -- test -c "$scratch/null"
  check device-full 1 "full: No space left on device" -- run -o "$scratch/full" --csv "$scratch/beside.csv"
  check device-full-kept 0 "" -- test -c "$scratch/full"
  check device-full-nothing-beside 1 "" -- test -e "$scratch/beside.csv"
  rm -f "$scratch/null" "$scratch/full"
else
  echo "skip device targets: mknod not permitted here"
  rm -f "$scratch/null" "$scratch/full"
fi
# A FIFO with its reader: the reader gets the whole HDF5 file, the FIFO stays.
mkfifo "$scratch/pipe.h5"
timeout 30 cat "$scratch/pipe.h5" > "$scratch/got.h5" &  # bounded: a writer that never opens it must not hang the suite
reader=$!
check fifo 0 "wrote .*pipe.h5" -- run -o "$scratch/pipe.h5"
[[ -p "$scratch/pipe.h5" ]] || kill $reader 2>/dev/null  # replaced: its reader would wait for nothing
wait $reader
check fifo-kept 0 "" -- test -p "$scratch/pipe.h5"
check fifo-got-hdf5 0 "H +D +F" -- od -c -N 4 "$scratch/got.h5"
check fifo-got-readable 0 "^5$" -- /usr/bin/python3 -c 'import h5py, sys; print(len(h5py.File(sys.argv[1])["mesh/s_m"]))' "$scratch/got.h5"
rm -f "$scratch/pipe.h5" "$scratch/got.h5"
# Standard output on a pipe through a link (what /dev/stdout is; a private link here: a binary that
# replaces links must not replace the system's): a stream too, the link kept.
ln -s /proc/self/fd/1 "$scratch/stdout"
check stdout-link-pipe 0 "H +D +F" -- bash -c '"$0" run "$1" --positions 5 -q -o "$2" | od -c -N 4' "$bin" "$dry" "$scratch/stdout"
check stdout-link-kept 0 "" -- test -L "$scratch/stdout"
rm -f "$scratch/stdout"
# Standard output redirected to a file (a job's log, appended to) and named as the target: the
# output appended through the descriptor after what the log held, never a new file renamed over it.
echo "before" > "$scratch/job.log"
ln -s /proc/self/fd/1 "$scratch/stdout"
check stdout-link-file 0 "" -- bash -c '"$0" kinematics --positions 3 --csv -o "$1" >> "$2"' "$bin" "$scratch/stdout" "$scratch/job.log"
check stdout-link-file-appended 0 "^before,point,s_m," -- bash -c 'head -2 "$0" | tr "\n" ","' "$scratch/job.log"
rm -f "$scratch/stdout" "$scratch/job.log"
# One file under two names: refused before the run (one output would replace the other).
check two-names 2 "out.csv: is the same file as the output .*out.csv" -- bash -c 'cd "$0" && "$1" run "$2" --positions 5 -q -o out.csv --csv ./out.csv' "$scratch" "$bin" "$dry"
check two-names-nothing 1 "" -- test -e "$scratch/out.csv"
# A character device is a stream two outputs may share, standard output on it too (a cron job's
# `-o /dev/null --csv /dev/stdout > /dev/null`); a file standard output is redirected to is not.
check devnull-and-stdout-on-it 0 "" -- bash -c '"$0" run "$1" --positions 5 -q -o /dev/null --csv /dev/stdout > /dev/null' "$bin" "$dry"
check stdout-file-named-again 2 "is the same file as the output /dev/stdout" -- bash -c 'cd "$0" && "$1" run "$2" --positions 5 -q -o /dev/stdout --csv log.csv > log.csv' "$scratch" "$bin" "$dry"
rm -f "$scratch/log.csv"  # the shell's redirection made it
# A symbolic link: the file it names gets the result, the link stays.
mkdir "$scratch/real"; echo original > "$scratch/real/out.h5"; ln -s real/out.h5 "$scratch/link.h5"
check symlink 0 "wrote .*link.h5" -- run -o "$scratch/link.h5"
check symlink-kept 0 "" -- test -L "$scratch/link.h5"
check symlink-target-written 0 "H +D +F" -- od -c -N 4 "$scratch/real/out.h5"
check symlink-nothing-beside 0 "^link.h5 real out.h5 $" -- bash -c 'ls -A "$1" | tr "\n" " "; ls -A "$1/real" | tr "\n" " "' _ "$scratch"
# A link to nothing, a folder: refused before the run.
ln -s real/missing.h5 "$scratch/dangling.h5"
check symlink-dangling 2 "dangling.h5: a symbolic link to real/missing.h5, which does not exist" -- run -o "$scratch/dangling.h5"
check symlink-dangling-nothing 1 "" -- test -e "$scratch/real/missing.h5"
check folder 2 "real: is a folder" -- run -o "$scratch/real"
rm -rf "$scratch"
