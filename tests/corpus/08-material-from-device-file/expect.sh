# 08: a material path naming a device (found: --set pinion.material=/dev/zero read 16 GB).
# Now a data file must be a regular file (a folder, device, pipe or socket is refused) of at most
# 1 MiB for TOML data files (case, material, lubricant), checked before it is read.
scratch="$tmp/08"; mkdir -p "$scratch"  # this folder's scratch, removed at the end (other folders share $tmp)
cases=../../../gears/m6z30.toml
run() { g run "$@" -o "$scratch/out.h5" --positions 11 -q; }
check material-dev-zero 2 "m6z30.toml \(--set pinion.material=/dev/zero\): key 'pinion.material' = \"/dev/zero\": /dev/zero is not a regular file" -- run "$cases" --set pinion.material=/dev/zero
check material-folder 2 "key 'wheel.material' = \"/tmp\": /tmp is a folder" -- run "$cases" --set wheel.material=/tmp
check case-dev-zero 2 "^geartrib: error: /dev/zero: /dev/zero is not a regular file" -- run /dev/zero
check lubricant-dev-zero 2 "key 'lubricant.file' = \"/dev/zero\": /dev/zero is not a regular file" -- run "$cases" --set lubricant.file=/dev/zero
# A material of 1 MiB + 1 byte (a long comment): refused naming the limit; of 1 MiB: read
{ cat ../../../materials/steel-45.toml; printf '#'; head -c $((1048576 - $(wc -c < ../../../materials/steel-45.toml) - 1)) /dev/zero | tr '\0' x; } > "$scratch/at-limit.toml"
{ cat "$scratch/at-limit.toml"; printf x; } > "$scratch/past-limit.toml"
check material-at-limit 0 "" -- run "$cases" --set "pinion.material=$scratch/at-limit.toml"
check material-past-limit 2 "key 'pinion.material' = .*past-limit.toml is 1048577 bytes, beyond the 1 MiB limit" -- run "$cases" --set "pinion.material=$scratch/past-limit.toml"
rm -rf "$scratch"
