#!/usr/bin/env bash
# Measured-topography tools against references from outside the code: McCool's (1986) summit
# predictions for Gaussian isotropic surfaces, the ISO 16610-61 Gaussian filter's 50% transmission
# at the cut-off, and the generating parameters of synthetic surfaces (the seed's R_m = 6.6 um
# hobbed texture, Rq). Prints each figure beside its reference; exits 1 if one is out of tolerance.
# Usage: compare.sh path/to/geartrib   (about 3 s)
set -euo pipefail
bin="$1"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
status=0
printf '%-44s %12s %12s %9s %9s  %s\n' quantity reference geartrib deviation tolerance verdict
row() {  # row NAME REFERENCE VALUE TOLERANCE(relative)
  local v
  v="$(awk -v r="$2" -v g="$3" -v t="$4" 'BEGIN { d = g / r - 1; a = d < 0 ? -d : d; printf "%+.2f%% %s", 100 * d, (a <= t ? "ok" : "DIFFERS") }')"
  printf '%-44s %12.5g %12.5g %9s %8.0f%%  %s\n' "$1" "$2" "$3" "${v% *}" "$(awk -v t="$4" 'BEGIN{print 100*t}')" "${v#* }"
  [[ "${v#* }" == ok ]] || status=1
}
stat() { awk -F, -v n="$2" '$1 == n {print $2}' <<<"$1"; }

# 1. McCool (1986) from m0, m2, m4 beside the eight-neighbour summits of isotropic Gaussian
#    surfaces (1024 x 1024 at 0.25 um, Rq 1 um, roll-off 20 um), resolved by 16, 8 and 4 spacings
#    per shortest wavelength. Reference: J.I. McCool, Wear 107 (1986) 37-60, eqs. for eta, beta,
#    sigma_s; the discrete summit rule converges to them as the sampling refines (Greenwood 1984).
for n in 16 8 4; do
  "$bin" surface generate self-affine -o "$tmp/iso.h5" --nx 1024 --ny 1024 --spacing "0.25 um" --rq "1 um" \
    --rolloff "20 um" --short-cutoff "$(awk -v n="$n" 'BEGIN{print n * 0.25}') um" --seed 9
  s="$("$bin" surface stats "$tmp/iso.h5" --form 0 --csv 2>/dev/null)"
  tol=$([[ $n -ge 8 ]] && echo 0.05 || echo 0.15)  # 4 spacings: under-resolved, expected to drift
  row "summit density, $n spacings/wavelength" "$(stat "$s" mccool_summit_density_1_per_m2)" "$(stat "$s" summit_density_1_per_m2)" "$tol"
  row "summit radius, $n spacings/wavelength" "$(stat "$s" mccool_summit_radius_m)" "$(stat "$s" summit_radius_m)" "$tol"
  row "summit height sigma, $n spacings/wavelength" "$(stat "$s" mccool_summit_sigma_m)" "$(stat "$s" summit_sigma_m)" "$tol"
  [[ $n -eq 16 ]] && row "Rq (generated 1 um)" 1e-6 "$(stat "$s" Rq_m)" 0.01
done

# 2. The seed's hobbed texture (R_m = 6.6 um, section 5) at a 5 um ridge spacing with 2 nm noise:
#    the cylinder reduction recovers the generating tip radius and spacing.
"$bin" surface generate hobbed -o "$tmp/hob.txt" --noise "2 nm" --seed 11
c="$("$bin" surface asperities "$tmp/hob.txt" --cylinders --form 0 --csv 2>/dev/null)"
mean() { awk -F, -v k="$1" 'NR > 1 && $k > 0 { s += $k; n++ } END { print s / n }' <<<"$c"; }
row "hobbed: mean tip radius R_m [m]" 6.6e-6 "$(mean 3)" 0.10
row "hobbed: mean ridge spacing [m]" 5e-6 "$(mean 4)" 0.05

# 3. ISO 16610-61: a sinusoid at the cut-off wavelength keeps 50% of its amplitude in the
#    roughness (Gaussian weighting, alpha = sqrt(ln 2 / pi)). Profile of 80 um wavelength and
#    1 um amplitude over 800 um, filtered at 80 um: the roughness Rq times sqrt(2) is the kept
#    amplitude (over the whole length, the renormalised edges included: hence 5%).
awk 'BEGIN { print "# units: um"; print "# spacing: 0.5 um"; pi = atan2(0, -1);
  for (j = 0; j < 3; ++j) { line = ""; for (i = 0; i < 1601; ++i) line = line (i ? " " : "") cos(2 * pi * i * 0.5 / 80); print line } }' > "$tmp/wave.txt"
rq="$("$bin" surface stats "$tmp/wave.txt" --form 0 --cutoff "80 um" --csv 2>/dev/null | awk -F, '$1 == "Rq_m" {print $2}')"
row "Gaussian filter: amplitude kept at cut-off" 0.5e-6 "$(awk -v r="$rq" 'BEGIN { print r * sqrt(2) }')" 0.05

exit $status
