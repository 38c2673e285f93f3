# 11 (the case-file lines; the command-line ones are in 11-messages-cli): errors without file or
# key, and a filesystem error as exit 1. Found: --set torque=1e11Nm ended after ~15 s in "nominal
# pressure ... beyond what the rough surface can carry" with no file, line or key; a material name
# of 300 characters escaped as "failure: filesystem error ... File name too long" (exit 1).
scratch="$tmp/11"; mkdir -p "$scratch"  # this folder's scratch, removed at the end (other folders share $tmp)
cases=../../../gears/m6z30.toml
run() { g run "$@" -o "$scratch/out.h5" --positions 11 -q; }
check torque-out-of-range 2 "m6z30.toml \(--set operating.pinion_torque=1e11Nm\): key 'operating.pinion_torque' = \"1e11Nm\": must lie in \[1e-09 N m, 1e\+10 N m\]" -- run "$cases" --set torque=1e11Nm
# A load inside the ranges that the rough surface cannot carry: the torque and the roughness named, with their places
check overload-located 2 "m6z30.toml:[0-9]+: key 'operating.pinion_torque' = 1000 N m: nominal pressure .* beyond what the rough surface can carry.*pinion.flank.ra = 8e-07 m \(.*m6z30.toml:[0-9]+\).*roughness.eta_sigma_beta = 1e-09 \(--set\)" -- run "$cases" --set table_points=4 --set roughness.eta_sigma_beta=1e-9
long=$(printf 'x%.0s' {1..300})
check material-name-too-long 2 "key 'pinion.material' = \"x+\": cannot read .*: File name too long" -- run "$cases" --set "pinion.material=$long"
rm -rf "$scratch"
