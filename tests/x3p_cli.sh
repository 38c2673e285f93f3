#!/usr/bin/env bash
# X3P (ISO 25178-72) through the command line: `surface generate` writes one, `surface stats` and
# `surface clean` read it (and clean writes one back), its statistics equal those of the same seed
# written as HDF5, a case's [pinion.flank.topography] table reads it, and a file that is not an
# X3P is refused with exit 2 and nothing written.
# Usage: x3p_cli.sh path/to/geartrib   (run from the source tree; needs python3)
set -u
bin="$1"
source "$(dirname "$0")/cli_support.sh"

gen=(surface generate self-affine --nx 96 --ny 64 --spacing "0.4 um" --seed 5)
check generate 0 "" -- "$bin" "${gen[@]}" -o "$tmp/a.x3p"
"$bin" "${gen[@]}" -o "$tmp/a.h5" >/dev/null 2>&1
check stats 0 "a.x3p: 96 x 64 points at 0.4 x 0.4 um" -- "$bin" surface stats "$tmp/a.x3p"
# Metres by the standard: never a warning about a '# units:' line.
check stats-no-unit-warning 0 "" -- bash -c "! \"$bin\" surface stats \"$tmp/a.x3p\" 2>&1 | grep -q 'units'"

# The same seed through HDF5 and X3P: the same statistics, to the last digit (both hold the heights
# bit for bit).
if diff <("$bin" surface stats "$tmp/a.x3p" --csv 2>/dev/null) <("$bin" surface stats "$tmp/a.h5" --csv 2>/dev/null) >/dev/null; then
  echo "ok   same-statistics-as-hdf5"
else
  echo "FAIL same-statistics-as-hdf5"; diff <("$bin" surface stats "$tmp/a.x3p" --csv) <("$bin" surface stats "$tmp/a.h5" --csv) | head -5; fail=1
fi

check clean 0 "" -- "$bin" surface clean "$tmp/a.x3p" -o "$tmp/b.x3p" --form 1 --outliers 3
check clean-stats 0 "b.x3p: 96 x 64 points at 0.4 x 0.4 um" -- "$bin" surface stats "$tmp/b.x3p" --form 0
# A converter both ways: X3P -> HDF5 -> X3P keeps every height (form 0: nothing removed).
"$bin" surface clean "$tmp/a.x3p" --form 0 -o "$tmp/c.h5" >/dev/null 2>&1
"$bin" surface clean "$tmp/c.h5" --form 0 -o "$tmp/c.x3p" >/dev/null 2>&1
# The container: a zip that Python's zipfile reads, main.xml's MD5 in md5checksum.hex, data.bin's in main.xml.
/usr/bin/python3 - "$tmp/a.x3p" "$tmp/c.x3p" <<'PY' || fail=1
import hashlib, re, sys, zipfile
def parts(path):
    with zipfile.ZipFile(path) as z:
        assert z.testzip() is None, path
        return {n: z.read(n) for n in z.namelist()}
a, c = parts(sys.argv[1]), parts(sys.argv[2])
assert sorted(a) == ["bindata/data.bin", "main.xml", "md5checksum.hex"], sorted(a)
assert a["md5checksum.hex"].decode() == hashlib.md5(a["main.xml"]).hexdigest() + " *main.xml\n"
stated = re.search(rb"<MD5ChecksumPointData>([0-9a-f]{32})<", a["main.xml"]).group(1).decode()
assert stated == hashlib.md5(a["bindata/data.bin"]).hexdigest()
assert a["bindata/data.bin"] == c["bindata/data.bin"], "X3P -> HDF5 -> X3P changed the heights"
print("ok   container-and-checksums")
print("ok   x3p-hdf5-x3p-same-data")
PY

# A case's topography table: the shipped pinion flank's own command (gears/surfaces/README.md)
# written as X3P gives the same measured flank as the shipped HDF5.
"$bin" surface generate self-affine -o "$tmp/pinion.x3p" --nx 384 --ny 384 --spacing "0.25 um" \
  --rq "1 um" --rolloff "10 um" --short-cutoff "2.5 um" --anisotropy 3 --seed 1 >/dev/null 2>&1
check case 0 "pinion flank measured \(.*pinion.x3p\): Ra 0.795 um" -- "$bin" run gears/m6z30-measured.toml -o "$tmp/m.h5" --positions 5 --set "pinion.flank.topography.file=$tmp/pinion.x3p"
x3p_line="$("$bin" run gears/m6z30-measured.toml -o "$tmp/m.h5" --positions 5 --set "pinion.flank.topography.file=$tmp/pinion.x3p" 2>&1 | grep '^pinion flank measured' | sed 's/([^)]*)//')"
h5_line="$("$bin" run gears/m6z30-measured.toml -o "$tmp/m.h5" --positions 5 2>&1 | grep '^pinion flank measured' | sed 's/([^)]*)//')"
[[ -n "$x3p_line" && "$x3p_line" == "$h5_line" ]] && echo "ok   case-same-flank-as-hdf5" || { echo "FAIL case-same-flank-as-hdf5: '$x3p_line' vs '$h5_line'"; fail=1; }

# Not an X3P: exit 2, the file named, nothing written.
echo "not a zip" > "$tmp/bad.x3p"
check not-a-zip 2 "bad.x3p: not an X3P file: not a zip archive" -- "$bin" surface clean "$tmp/bad.x3p" -o "$tmp/out.x3p"
check not-a-zip-case 2 "bad.x3p: not an X3P file" -- "$bin" run gears/m6z30-measured.toml -o "$tmp/bad.h5" --positions 5 --set "pinion.flank.topography.file=$tmp/bad.x3p"
[[ ! -e "$tmp/out.x3p" && ! -e "$tmp/bad.h5" ]] && echo "ok   nothing-written-on-error" || { echo "FAIL written on error"; fail=1; }
[[ -z "$(find "$tmp" -name '.*.tmp.*')" ]] && echo "ok   no-temporaries-left" || { echo "FAIL temporaries left"; fail=1; }
exit $fail
