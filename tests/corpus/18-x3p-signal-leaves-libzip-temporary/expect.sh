# 18: a signal while a surface file is written (issue 30, finding 8). Found: libzip's own temporary
# (NAME.XXXXXX beside geartrib's, 64-200 MB) left behind. Promised: SIGTERM and SIGINT remove every
# temporary; the process dies of the signal (128 + N).
scratch="$tmp/18"; mkdir -p "$scratch"
# signal_while_writing SIGNAL FILE: `surface generate` of 2048 x 2048 points (a 32 MB file) into
# $scratch, the signal sent as soon as a file there holds bytes: the write has begun (the
# reservation creates the temporary empty). Prints the exit status and what the folder holds; an
# attempt whose write ended before the signal arrived prints "missed".
signal_while_writing() {
  local signal=$1 file=$2 pid status n=0
  # (A background job of a script starts with SIGINT ignored: env gives it back its default.)
  env --default-signal="$signal" "$bin" surface generate --nx 2048 --ny 2048 -o "$scratch/$file" >/dev/null 2>&1 &
  pid=$!
  while kill -0 $pid 2>/dev/null && [[ -z "$(find "$scratch" -type f -size +0c 2>/dev/null)" ]] && ((n++ < 20000)); do
    sleep 0.002
  done
  kill -"$signal" $pid 2>/dev/null
  wait $pid
  status=$?
  if [[ $status -eq 0 ]]; then echo missed; rm -f "$scratch/$file"; return; fi
  echo "exit $status: $(ls -A "$scratch" | tr '\n' ' ')"
}
for case in "TERM big.x3p 143" "INT big.x3p 130" "TERM big.h5 143"; do
  set -- $case
  result=missed
  for attempt in 1 2 3 4 5; do  # the write takes ~50 ms; a loaded machine may miss it
    result=$(signal_while_writing "$1" "$2")
    [[ $result != missed ]] && break
  done
  check "sig$1-$2" 0 "^exit $3: $" -- echo "$result"
  rm -rf "$scratch" && mkdir "$scratch"
done
rm -rf "$scratch"
