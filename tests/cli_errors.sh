#!/usr/bin/env bash
# The command line: exit status, messages and outputs for good and bad input.
# Usage: cli_errors.sh path/to/geartrib   (run from the source tree)
set -u
bin="$1"
source "$(dirname "$0")/cli_support.sh"

# The required CSV columns, in order.
header="delta_star,delta_m,load_N,load_star,area_m2,area_star,contact_radius_m,plastic_radius_m,mean_pressure_Pa,max_pressure_Pa,plastic_fraction,max_von_mises_Pa,von_mises_depth_m"
check csv-header 0 "^$header\$" -- "$bin" asperity --model jackson-green --delta-star 1,2,6 --csv
check range-rows 0 "" -- "$bin" asperity --range 1e-3:1e4:200 --csv
rows=$("$bin" asperity --range 1e-3:1e4:200 --csv | wc -l)
[[ $rows -eq 201 ]] && echo "ok   range-count" || { echo "FAIL range-count: $rows lines"; fail=1; }
check side 0 "theta_deg" -- "$bin" asperity --contact side --mu 0.1 --delta-star 2 --csv
check summary 0 "113.19 GPa" -- "$bin" asperity --summary
# Each model states its range and what answers past it.
check law-range 0 "range: delta\* <= 110, contact radius <= 0.5 x the summit radius; past it: continuous switch" -- "$bin" asperity --model jackson-green --constants
# Issue 14: the continuous model has no yielded surface at delta* = 2 (the CalculiX runs show none).
check no-surface-yield-at-2 0 "^2,.*,0.00201" -- "$bin" asperity --model continuous --delta-star 2 --csv
check help 0 "delta\*" -- "$bin" asperity --help
check version 0 "SUNDIALS" -- "$bin" version

# Kinematics: required columns, summary keys, bad input.
kin_cols="point,s_m,gamma,rho1_m,rho2_m,r_eq_m,load_share,line_load_N_per_m,hertz_p0_Pa,hertz_halfwidth_m"
check kinematics-header 0 "^$kin_cols," -- "$bin" kinematics --csv
for col in v1_m_per_s v2_m_per_s entrainment_m_per_s sliding_m_per_s srr mesh_stiffness_N_per_m; do
  check "kinematics-column-$col" 0 "$col" -- "$bin" kinematics --csv --points C
done
for key in center_distance_m operating_pressure_angle_rad base_pitch_m length_of_contact_m contact_ratio \
           mean_mesh_stiffness_N_per_m iso_c_prime_N_per_m_um iso_c_gamma_alpha_N_per_m_um; do
  check "summary-$key" 0 "^$key," -- "$bin" kinematics --summary --csv
done
check kinematics-positions 0 "^10," -- "$bin" kinematics --positions 11 --load-sharing stiffness --csv
# The mesh stiffness beyond a factor 1.5 of ISO's c_gamma_alpha is warned, naming the bores: bores at
# the fillet-foundation fit's end (r_f/r_bore = 7) give 0.469 of ISO; solid bodies (a shaft seat
# at r_f/3) lie within the band.
check stiffness-band-warned 0 "warning: the mean mesh stiffness .* is 0.469 x ISO 6336-1's c_gamma_alpha.*r_f/r_bore = 7 for pinion.bore_diameter" -- \
  "$bin" kinematics --summary --set pinion.bore_diameter=23.5714mm --set wheel.bore_diameter=23.5714mm
solid_out="$("$bin" kinematics --summary --csv --set pinion.bore_diameter=0 --set wheel.bore_diameter=0 2>&1)"
grep -q "warning" <<<"$solid_out" && { echo "FAIL stiffness-solid-not-warned"; fail=1; } || echo "ok   stiffness-solid-not-warned"
check stiffness-band-run 0 "warning: the mean mesh stiffness .* x ISO 6336-1's c_gamma_alpha" -- \
  "$bin" run gears/m6z30-dry.toml --set load_sharing=stiffness --set pinion.bore_diameter=10mm --positions 5 -o "$tmp/k.h5" -q
check kinematics-bad-point 2 "unknown point 'F'" -- "$bin" kinematics --points A,F
check kinematics-bad-sharing 2 "" -- "$bin" kinematics --load-sharing equal

# Multi-asperity: per-asperity columns, totals, layouts, sweep, bad input.
check multi-columns 0 "^asperity,load_N_per_m,contact_width_m,max_pressure_Pa,max_surface_von_mises_Pa,max_deformation_m" -- \
  "$bin" multi-asperity --layout LHL --height-step 1 --spacing 0.5um --delta-pc 0.5797nm --elements 2048 --csv
check multi-totals 0 "^inflection_depth_m," -- "$bin" multi-asperity --layout HLH --delta-pc 0.5797nm --elements 2048 --csv
# The solve's cost beside its time: FFT count, one transform's time, their product.
check multi-cost 0 "^fft_time_s," -- "$bin" multi-asperity --layout HLH --delta-pc 0.5797nm --elements 2048 --csv
check multi-single 0 "^1H," -- "$bin" multi-asperity --layout H --delta-pc 0.5797nm --elements 2048 --csv
# The boundary elements' modulus is named: composite E_t = 113.19 GPa by default, E/(1 - nu^2) = 226.37 GPa on request.
check multi-composite 0 "^modulus_composite_Pa,1.1318" -- "$bin" multi-asperity --layout H --delta-pc 0.5797nm --elements 2048 --csv
check multi-single-body 0 "^modulus_single_body_Pa,2.2637" -- "$bin" multi-asperity --layout H --modulus single-body --delta-pc 0.5797nm --elements 2048 --csv
check multi-bad-modulus 2 "modulus" -- "$bin" multi-asperity --modulus rigid
check multi-load 0 "line_load_N_per_m +150" -- "$bin" multi-asperity --layout HHH --load 150 --delta-pc 0.5797nm --elements 2048
check multi-sweep 0 "^2e-06," -- "$bin" multi-asperity --layout HHH --sweep-spacing 0.5um:2um:4 --delta-pc 0.5797nm --elements 2048 --csv
check multi-bad-layout 2 "layout must be letters H and L" -- "$bin" multi-asperity --layout LXL
check multi-bad-spacing 2 "unknown unit 'parsec'" -- "$bin" multi-asperity --spacing 1parsec

# Fitting: the constants list, a fit, and each kind of unusable input.
check fit-list 0 "plastic_scale" -- "$bin" fit --list continuous
check fit-run 0 "Root-mean-square" -- "$bin" fit --model kogut-etsion --data validation/fem-reference/kogut-etsion-2002.csv \
  --free load_coefficient_1,load_exponent_1 --observe load_star
check fit-unknown-constant 2 "has no constant 'nope'" -- "$bin" fit --model continuous \
  --data validation/fem-reference/kogut-etsion-2002.csv --free nope
printf '# source: test\ndelta_star,load_star\n1.5,2.0\n2.0,nan\n' > "$tmp/nan.csv"
check fit-nan 2 "nan.csv:4: key 'load_star' = nan: not a finite number" -- "$bin" fit --model continuous --data "$tmp/nan.csv"
printf 'delta_star,load_star\n1.5,2.0\n' > "$tmp/one.csv"
check fit-too-few 2 "1 observations cannot determine 5 free constants" -- "$bin" fit --model continuous --data "$tmp/one.csv" \
  --free area_scale,area_exponent,plastic_scale,pressure_scale,pressure_exponent

# Dynamics: a steady cycle, a short sweep, bad input.
check dynamics-cycle 0 "^time_s,s_m,mesh_stiffness_N_per_m,deflection_m" -- "$bin" dynamics --speed 1000rpm --integrator odeint --csv
check dynamics-sweep 0 "^speed_rpm,mesh_frequency_Hz,dynamic_factor" -- "$bin" dynamics --speed-sweep 500rpm:1500rpm:3 --csv
check dynamics-bad-speed 2 "expected a angular speed|angular speed" -- "$bin" dynamics --speed 1000mm

# Measured topography: generate -> stats / asperities / equivalent, the measured case, bad files.
check surface-generate 0 "" -- "$bin" surface generate hobbed -o "$tmp/hob.xyz" --nx 256 --ny 16 --noise "2 nm" --seed 3
check surface-cylinders 0 "tip radius R_m 6\.[0-9]+ \+- " -- "$bin" surface asperities "$tmp/hob.xyz" --cylinders --form 0
check surface-cylinder-columns 0 "^centre_m,height_m,tip_radius_m,spacing_m" -- "$bin" surface asperities "$tmp/hob.xyz" --cylinders --csv
check surface-generate-sa 0 "" -- "$bin" surface generate self-affine -o "$tmp/a.h5" --nx 64 --ny 64 --seed 1
check surface-generate-sb 0 "" -- "$bin" surface generate self-affine -o "$tmp/b.csv" --nx 64 --ny 64 --seed 2
check surface-stats 0 "^Rq_m,.*" -- "$bin" surface stats "$tmp/a.h5" --csv
check surface-mccool 0 "^mccool_summit_radius_m," -- "$bin" surface stats "$tmp/b.csv" --csv --cutoff "10 um" --outliers 5 --fill
check surface-summits 0 "^x_m,y_m,height_m,radius_m" -- "$bin" surface asperities "$tmp/a.h5" --csv
check surface-equivalent 0 "^summit_density_1_per_m2," -- "$bin" surface equivalent "$tmp/a.h5" "$tmp/b.csv" -o "$tmp/e.txt" --csv
[[ -s "$tmp/e.txt" ]] && echo "ok   surface-equivalent-file" || { echo "FAIL surface-equivalent-file"; fail=1; }
check surface-multi 0 "^1[HL]," -- "$bin" multi-asperity --topography "$tmp/hob.xyz" --form 0 --delta-pc 0.5797nm --elements 2048 --csv
check measured-case 0 "pinion flank measured \(surfaces/pinion-flank.h5\)" -- "$bin" run gears/m6z30-measured.toml -o "$tmp/m.h5" --positions 5
printf '# spacing: 1 um\n1 2 3\n4 five 6\n' > "$tmp/bad-number.txt"
check surface-bad-number 2 "bad-number.txt:3: .*not a number" -- "$bin" surface stats "$tmp/bad-number.txt"
printf '# spacing: 1 um\n1,2,3\n4,5\n' > "$tmp/ragged.csv"
check surface-ragged 2 "ragged.csv:3: .*ragged row" -- "$bin" surface stats "$tmp/ragged.csv"
printf '' > "$tmp/empty.txt"
check surface-empty 2 "empty.txt:.*no height rows" -- "$bin" surface stats "$tmp/empty.txt"
printf '# spacing: 1 um\nNaN NaN NaN\nBad Bad Bad\nNaN NaN NaN\n' > "$tmp/missing.txt"
check surface-all-missing 2 "missing.txt:4: .*too few valid points" -- "$bin" surface stats "$tmp/missing.txt"
printf '# spacing: -1 um\n1 2 3\n' > "$tmp/spacing.txt"
check surface-bad-spacing 2 "spacing.txt:1: .*spacing must be positive" -- "$bin" surface stats "$tmp/spacing.txt"
printf '1 2 3\n4 5 6\n7 8 9\n' > "$tmp/nospacing.txt"
check surface-no-spacing 2 "spacing missing" -- "$bin" surface stats "$tmp/nospacing.txt"
check surface-given-spacing 0 "^points,9" -- "$bin" surface stats "$tmp/nospacing.txt" --grid-spacing "1 um" --form 0 --csv
printf "1 2 3\n" > "$tmp/a.dat"
check surface-unknown-format 2 "unknown topography format" -- "$bin" surface stats "$tmp/a.dat"
check surface-misaligned 2 "same size and spacing" -- "$bin" surface equivalent "$tmp/a.h5" "$tmp/hob.xyz" -o "$tmp/x.h5"
[[ ! -e "$tmp/x.h5" ]] && echo "ok   surface-nothing-written-on-error" || { echo "FAIL x.h5 written"; fail=1; }
printf 'not hdf5\n' > "$tmp/text.h5"
check surface-not-hdf5 2 "text.h5: .*not a readable HDF5 topography file" -- "$bin" surface stats "$tmp/text.h5"
/usr/bin/python3 - "$tmp/nodx.h5" <<'PY' 2>/dev/null && check surface-hdf5-no-dx 2 "nodx.h5: .*attribute dx" -- "$bin" surface stats "$tmp/nodx.h5"
import sys, h5py, numpy
with h5py.File(sys.argv[1], "w") as f: f["z"] = numpy.zeros((4, 4))
PY
check surface-bad-outliers 2 "outlier limit" -- "$bin" surface stats "$tmp/a.h5" --outliers 1

# What users read names no section of the thesis or internal errata ("seed section 5"): the help of
# every command, the schema (the missing-key errors quote its meanings), the summaries, the citations.
seed_refs=""
for args in "--help" "run --help" "sweep --help" "tradeoff --help" "kinematics --help" "dynamics --help" \
            "asperity --help" "asperity --summary" "asperity --constants --model continuous" "multi-asperity --help" \
            "surface --help" "surface asperities --help" "surface generate --help" "fem --help" \
            "fem single-asperity --help" "fem three-cylinders --help" "fit --help" "case --help" "case --schema"; do
  # shellcheck disable=SC2086
  if "$bin" $args 2>&1 | grep -qiE "seed section|seed sections|seed's|\\(seed\\b|errata"; then seed_refs+=" [$args]"; fi
done
[[ -z "$seed_refs" ]] && echo "ok   no-seed-references" || { echo "FAIL seed references in:$seed_refs"; fail=1; }

# Bad input: exit 2 with a message naming what is wrong.
# The case as it would run, and the parameter table.
check case-listing 0 "^gear_pair.module +0.005 m +--set" -- "$bin" case --set module=5mm
check case-schema 0 "^key,kind,SI unit,default,range,required by,aliases,meaning" -- "$bin" case --schema
check case-bad-set 2 "key 'contact.positions'" -- "$bin" case --set positions=1
# A --set list may be typed with bare words; a string where the list belongs says how to write it.
check set-bare-list 0 "^contact.outputs +\\[real_area, plastic_fraction\\] +--set" -- "$bin" case --set 'contact.outputs=[real_area, plastic_fraction]'
check set-list-as-string 2 "\\(--set contact.outputs=real_area\\): key 'contact.outputs' = \"real_area\": expected an array of strings, written \\[\"a\", \"b\"\\] in a case file; --set takes the same or bare words: KEY=\\[a, b\\]" -- \
  "$bin" run --set contact.outputs=real_area -o "$tmp/list.h5" -q
check unknown-model 2 "unknown asperity model 'nope'" -- "$bin" asperity --model nope
check bad-range 2 "MIN:MAX:COUNT" -- "$bin" asperity --range 1:0:5
check bad-contact 2 "" -- "$bin" asperity --contact sideways
check missing-case 2 "file not found" -- "$bin" asperity --case "$tmp/none.toml"
mkdir -p "$tmp/gears" "$tmp/materials"
cp gears/m6z30.toml "$tmp/gears/" && cp -r lubricants "$tmp/"
sed 's/youngs_modulus = "206 GPa"/youngs_modulus = "-206 GPa"/' materials/steel-45.toml > "$tmp/materials/steel-45.toml"
check negative-modulus 2 "steel-45.toml:[0-9]+: key 'youngs_modulus' = \"-206 GPa\": must be positive" -- \
  "$bin" asperity --case "$tmp/gears/m6z30.toml"

# Each kind of bad field in a data file: exit 2, message with file:line, key, value, rule.
bad_case() {  # bad_case NAME FILE SED_EXPR PATTERN
  local name="$1" file="$2" expr="$3" pattern="$4"
  rm -rf "$tmp/b" && mkdir -p "$tmp/b/gears" "$tmp/b/materials"
  cp gears/m6z30.toml "$tmp/b/gears/" && cp materials/steel-45.toml "$tmp/b/materials/" && cp -r lubricants "$tmp/b/"
  sed -i "$expr" "$tmp/b/$file"
  check "$name" 2 "$pattern" -- "$bin" asperity --case "$tmp/b/gears/m6z30.toml"
}
bad_case poisson-range materials/steel-45.toml 's/^poisson_ratio = 0.3/poisson_ratio = 0.7/' \
  "steel-45.toml:[0-9]+: key 'poisson_ratio' = 0.7: Poisson's ratio must lie in \\(0, 0.5\\)"
bad_case unknown-unit gears/m6z30.toml 's/module = "6 mm"/module = "6 furlong"/' \
  "m6z30.toml:[0-9]+: key 'gear_pair.module' = \"6 furlong\": unknown unit 'furlong'"
bad_case wrong-type gears/m6z30.toml '0,/teeth = 30/s//teeth = "thirty"/' \
  "m6z30.toml:[0-9]+: key 'pinion.teeth' = \"thirty\": expected an integer"
bad_case missing-key gears/m6z30.toml '/^face_width/d' \
  "m6z30.toml:[0-9]+: key 'gear_pair.face_width': missing required key"
# A flank's summit radius has no default: the error gives the rule for choosing it.
bad_case missing-summit-radius gears/m6z30.toml '0,/^summit_radius = /{/^summit_radius = /d}' \
  "m6z30.toml:[0-9]+: key 'pinion.flank.summit_radius': missing required key \\(Mean summit radius .*required with ra, rq or summit_density.*geartrib surface stats FILE.*McCool's beta = 0.375 sqrt\\(pi/m4\\)"
# A bare number is SI: module = 4.5 is 4.5 m. Implausible as SI but plausible in another unit, it is
# refused at its own key, saying how it was read and what was meant (before any geometry error).
bad_case bare-module gears/m6z30.toml 's/module = "6 mm"/module = 4.5/' \
  "m6z30.toml:[0-9]+: key 'gear_pair.module' = 4.5: read as 4.5 m \\(a bare number is SI\\), above the plausible band \\[5e-05 m, 0.1 m\\] of a spur gear: did you mean \"4.5 mm\"\\?"
check bare-pressure-angle 2 "m6z30.toml \\(--set gear_pair.pressure_angle=20\\): key 'gear_pair.pressure_angle' = 20: read as 20 rad .*did you mean \"20 deg\"" -- \
  "$bin" run --set pressure_angle=20 -o "$tmp/bare.h5" -q
check bare-module-fzg 2 "fzg-c.toml \\(--set gear_pair.module=4.5\\): key 'gear_pair.module' = 4.5: read as 4.5 m" -- \
  "$bin" run validation/fzg-type-c/fzg-c.toml --set module=4.5 -o "$tmp/bare.h5" -q
[[ ! -e "$tmp/bare.h5" ]] && echo "ok   bare-nothing-written" || { echo "FAIL bare.h5 written"; fail=1; }
# With its unit the value is read; an impossible pair from it is blamed on it first.
check implausible-module-geometry 2 "key 'gear_pair.module' = \"4.5 m\": above the plausible band .* the pair it gives cannot exist: centre distance too small.*\\(key 'gear_pair.center_distance'\\)" -- \
  "$bin" kinematics validation/fzg-type-c/fzg-c.toml --set "module=4.5 m"
bad_case contact-ratio gears/m6z30.toml 's/^tip_shortening = 0.0/tip_shortening = 0.6/' \
  "m6z30.toml:[0-9]+: key 'gear_pair.addendum_coefficient'.*contact ratio 0.[0-9]+ is below 1"
bad_case tip-interference gears/m6z30.toml '0,/teeth = 30/s//teeth = 8/; 0,/bore_diameter = "60 mm"/s//bore_diameter = "10 mm"/' \
  "key 'wheel.teeth'.*no involute exists"
bad_case jammed gears/m6z30.toml 's/^# center_distance = "180 mm"/center_distance = "179 mm"/' \
  "m6z30.toml:[0-9]+: key 'gear_pair.center_distance' = \"179 mm\": centre distance 179 mm is below the zero-backlash"

# The lubricated run's input (issue 16): exit 2 naming the key, nothing written.
bad_case lub-viscosity gears/m6z30.toml 's#^file = "../lubricants/mineral-vg220.toml"#dynamic_viscosity = "-0.04 Pa s"\npressure_viscosity_coefficient = "2e-8 1/Pa"#' \
  "m6z30.toml:[0-9]+: key 'lubricant.dynamic_viscosity' = \"-0.04 Pa s\": must be positive"
bad_case lub-alpha gears/m6z30.toml 's#^file = "../lubricants/mineral-vg220.toml"#dynamic_viscosity = "0.04 Pa s"\npressure_viscosity_coefficient = 0#' \
  "key 'lubricant.pressure_viscosity_coefficient' = 0: must be positive"
bad_case lub-both-forms gears/m6z30.toml 's#^\[lubricant\]#[lubricant]\ndynamic_viscosity = "0.04 Pa s"#' \
  "key 'lubricant.dynamic_viscosity' = \"0.04 Pa s\": the lubricant file gives the oil's data"
bad_case lub-hot-oil gears/m6z30.toml 's#^oil_temperature = "70 degC"#oil_temperature = "300 degC"#' \
  "key 'operating.oil_temperature' = \"300 degC\": 300.0 degC is beyond the lubricant's data range"
bad_case lub-no-oil-temperature gears/m6z30.toml '/^oil_temperature/d' \
  "key 'operating.oil_temperature'.*missing required key"
bad_case lub-boundary-mu gears/m6z30.toml 's/^mu = 0.1 /mu = 1.5 /' \
  "key 'friction.mu' = 1.5: must lie in \\[0, 1\\]"
bad_case lub-file-viscosity lubricants/mineral-vg220.toml 's#^kinematic_viscosity_40C = "220 mm^2/s"#kinematic_viscosity_40C = "-220 mm^2/s"#' \
  "mineral-vg220.toml:[0-9]+: key 'kinematic_viscosity_40C' = \"-220 mm\\^2/s\": must be positive"
bad_case lub-no-thermal-data materials/steel-45.toml '/^thermal_conductivity/d' \
  "key 'pinion.material'.*thermal_conductivity and specific_heat"
# Issue 29: measured traction curves out of order or outside [0, 1], an ester without its ISO
# lubricant factor, a traction model without curves: exit 2 naming file, line, key, value, rule.
curve='$a [traction_curves.a]\nsource = "test"\nhertz_pressure = "1 GPa"\ntemperature = "80 degC"\nentrainment_speed = "5 m/s"'
bad_case lub-curve-order lubricants/mineral-vg220.toml "$curve\nslide_to_roll = [0.0, 0.2, 0.1]\ncoefficient = [0.0, 0.04, 0.05]" \
  "mineral-vg220.toml:[0-9]+: key 'traction_curves.a.slide_to_roll' = \\[0, 0.2, 0.1\\]: must increase strictly \\(entry 2 after 0.2\\)"
bad_case lub-curve-range lubricants/mineral-vg220.toml "$curve\nslide_to_roll = [0.0, 0.1]\ncoefficient = [0.0, 1.2]" \
  "mineral-vg220.toml:[0-9]+: key 'traction_curves.a.coefficient' = \\[0, 1.2\\]: must lie in \\[0, 1\\] \\(entry 1: 1.2\\)"
rm -rf "$tmp/b" && mkdir -p "$tmp/b/gears" "$tmp/b/materials" && cp gears/m6z30.toml "$tmp/b/gears/" \
  && cp materials/steel-45.toml "$tmp/b/materials/" && cp -r lubricants "$tmp/b/"
sed -i '/^iso_lubricant_factor/d' "$tmp/b/lubricants/ester-vg320-estr.toml"
sed -i 's#mineral-vg220.toml#ester-vg320-estr.toml#' "$tmp/b/gears/m6z30.toml"
check lub-ester-no-factor 2 "ester-vg320-estr.toml.*key 'iso_lubricant_factor'.*tabulates no lubricant factor X_L for base oil 'ester'" -- "$bin" run "$tmp/b/gears/m6z30.toml" -o "$tmp/b/out.h5" -q
[[ ! -e "$tmp/b/out.h5" ]] && echo "ok   lub-ester-nothing-written" || { echo "FAIL lub-ester-nothing-written"; fail=1; }
check lub-traction-no-curves 2 "m6z30.toml .--set lubrication.traction=curve.: key 'lubrication.traction' = \"?curve\"?: \"curve\" needs measured traction curves, and ../lubricants/mineral-vg220.toml has no \\[traction_curves.NAME\\] table" -- \
  "$bin" run gears/m6z30.toml --set lubrication.traction=curve -o "$tmp/nocurve.h5" -q
[[ ! -e "$tmp/nocurve.h5" ]] && echo "ok   lub-traction-nothing-written" || { echo "FAIL lub-traction-nothing-written"; fail=1; }
# A lubricated case runs dry from the command line.
check lub-none 0 "wrote" -- "$bin" run gears/m6z30.toml --set lubricant=none -o "$tmp/none.h5" -q
/usr/bin/python3 -c "import h5py, sys; sys.exit('lubrication' in h5py.File(sys.argv[1]))" "$tmp/none.h5" \
  && echo "ok   lub-none-dry" || { echo "FAIL lub-none-dry: /lubrication written"; fail=1; }
# Warned, not refused: 130 degC lies 10 K beyond the oil's data (Walther extrapolated).
rm -rf "$tmp/w" && mkdir -p "$tmp/w/gears" && cp -r materials lubricants "$tmp/w/"
sed 's#^oil_temperature = "70 degC"#oil_temperature = "130 degC"#' gears/m6z30.toml > "$tmp/w/gears/m6z30.toml"
check lub-warm-oil-warned 0 "warning: key 'operating.oil_temperature': 130.0 degC lies outside" -- \
  "$bin" run "$tmp/w/gears/m6z30.toml" -o "$tmp/w/out.h5" -q
# A run requires only what it uses: no cylinder asperity (asperity.cylinder.tip_radius); the
# multi-asperity study, which uses it, still requires it at its key.
rm -rf "$tmp/nocyl" && mkdir -p "$tmp/nocyl/gears" && cp -r materials lubricants "$tmp/nocyl/"
sed '/^tip_radius = /d' gears/m6z30-dry.toml > "$tmp/nocyl/gears/dry.toml"
check run-without-cylinder 0 "wrote" -- "$bin" run "$tmp/nocyl/gears/dry.toml" --positions 5 -o "$tmp/nocyl/o.h5" -q
check multi-needs-cylinder 2 "dry.toml:[0-9]+: key 'asperity.cylinder.tip_radius': missing required key" -- \
  "$bin" multi-asperity --case "$tmp/nocyl/gears/dry.toml" --layout H --elements 2048
# A dry run needs no lubricant: the seed's dry scene has no [lubricant] and writes no /lubrication.
check dry-no-lubricant 0 "wrote" -- "$bin" run gears/m6z30-dry.toml -o "$tmp/dry.h5" -q

# Deterministic fidelity (issue 20): no profile, a profile shorter than the flank it must cover,
# elements finer than a profile's sampling: exit 2 naming the key and file; nothing written.
check det-no-profile 2 "m6z30-dry.toml \(--set contact.fidelity=deterministic\): key 'pinion.flank': the deterministic fidelity rolls each flank's profile" -- \
  "$bin" run gears/m6z30-dry.toml --set contact.fidelity=deterministic -o "$tmp/det-bad.h5" -q
check det-short-profile 2 "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.file' = surfaces/pinion-flank.h5: its profile along x is 0.09575 mm long; the deterministic contact reads 11.46 mm.*synthesise one from its spectrum \(synthesis = \"psd\" or \"iaaft\" in \[pinion.flank.topography\]\)" -- \
  "$bin" run gears/m6z30-measured.toml --fidelity deterministic --set pinion.flank.topography.synthesis=none -o "$tmp/det-bad.h5" -q
check det-sampling 2 "key 'contact.element_size' = 0.1 um: finer than the 0.125 um spacing of pinion.flank.profile.spacing" -- \
  "$bin" run gears/m6z30-deterministic.toml --set contact.element_size=0.1um -o "$tmp/det-bad.h5" -q
check det-smooth-statistical 2 "key 'pinion.flank.profile.kind'.*only contact.fidelity = \"deterministic\" takes it" -- \
  "$bin" run gears/m6z30-deterministic.toml --fidelity uncoupled --set pinion.flank.profile.kind=smooth -o "$tmp/det-bad.h5" -q
check det-strip 2 "key 'contact.strip_halfwidths' = 1: must lie in \[1.05, 20\]" -- \
  "$bin" run gears/m6z30-deterministic.toml --set contact.strip_halfwidths=1 -o "$tmp/det-bad.h5" -q
check det-teeth 2 "unknown tooth order 'all'" -- \
  "$bin" run gears/m6z30-deterministic.toml --set running_in.teeth=all -o "$tmp/det-bad.h5" -q
check det-running-in-positions 2 "key 'contact.positions' = 21: running-in needs every flank point in the strip at two positions or more.*use [0-9]+ positions \(checked at the Hertz half-widths they sample" -- \
  "$bin" run gears/m6z30-deterministic.toml --positions 21 --set running_in.meshes=3 -o "$tmp/det-bad.h5" -q
check det-overload 2 "m6z30-deterministic.toml:[0-9]+: key 'contact.strip_halfwidths' = 2: the line load 1.478e\+07 N/m would yield the whole strip.*a strip of 5 half-widths, which would carry it, reaches .*: lower the torque" -- \
  "$bin" run gears/m6z30-deterministic.toml --set torque=1e5Nm --positions 11 -o "$tmp/det-bad.h5" -q
[[ ! -e "$tmp/det-bad.h5" ]] && echo "ok   det-nothing-written"
# Mixed-EHL fidelity (issue 32): a dry case, a window shorter than the contact, a grid coarser than
# the flanks' profiles, a position that does not converge (a tolerance below rounding): exit 2
# naming the key (and the position); nothing written.
check ehl-dry 2 "m6z30-mixed-ehl.toml:[0-9]+: key 'contact.fidelity' = \"mixed_ehl\": \"mixed_ehl\" solves the lubricant's film between the flanks, and the case is dry" -- \
  "$bin" run gears/m6z30-mixed-ehl.toml --set lubricant.file=none -o "$tmp/ehl-bad.h5" -q
check ehl-window 2 "key 'mixed_ehl.window' = 0.5: must lie in \[1, 1000\]" -- \
  "$bin" run gears/m6z30-mixed-ehl.toml --set mixed_ehl.window=0.5 -o "$tmp/ehl-bad.h5" -q
check ehl-grid 2 "key 'mixed_ehl.grid_spacing' = 2 um: coarser than the 1 um spacing of pinion.flank.profile.spacing" -- \
  "$bin" run gears/m6z30-mixed-ehl.toml --set mixed_ehl.grid_spacing=2um -o "$tmp/ehl-bad.h5" -q
check ehl-not-converged 2 "key 'mixed_ehl.tolerance' = 1e-17: at position 1 of 3 \(s = 16.1376 mm, point A, .*the start of its window \(the steady contact and the lead-in\): mixed EHL: not converged.*a looser tolerance \(mixed_ehl.tolerance\)" -- \
  "$bin" run gears/m6z30-mixed-ehl.toml --positions 3 --set threads=1 --set mixed_ehl.tolerance=1e-17 \
  --set pinion.flank.profile.spacing=2um --set wheel.flank.profile.spacing=2um --set mixed_ehl.grid_spacing=2um \
  -o "$tmp/ehl-bad.h5" -q
[[ ! -e "$tmp/ehl-bad.h5" ]] && echo "ok   ehl-nothing-written" || { echo "FAIL ehl-bad.h5 written"; fail=1; }
# A measured profile trace (a stylus's line along the involute, one grid row): its spectral
# moments give the statistical roughness and the deterministic run rolls it; 14 mm covers the
# seed's pinion (10.7 mm active plus the strip), 5 mm does not.
rm -rf "$tmp/trace" && mkdir -p "$tmp/trace"
for mm_long in 14 5; do
  awk -v n=$((mm_long * 2000)) 'BEGIN { printf "# units: um\n# spacing: 0.5 um\n";
    for (i = 0; i < n; i++) printf "%s%.5f", (i ? "," : ""), 0.2 * sin(i * 0.37) + 0.1 * sin(i * 0.091 + 1) + 0.05 * sin(i * 1.3);
    printf "\n" }' > "$tmp/trace/trace-$mm_long.csv"
  /usr/bin/python3 - "$tmp/trace/case-$mm_long.toml" "trace-$mm_long.csv" <<'PY'
import re, sys
s = open("gears/m6z30-deterministic.toml").read()
for gear in ("pinion", "wheel"):
    s = re.sub(r"\[%s\.flank\.profile\][^\[]*" % gear, '[%s.flank.topography]\nfile = "%s"\nform = 1\n\n' % (gear, sys.argv[2]), s)
s = s.replace('"../materials/', '"' + __import__("os").path.abspath("materials") + "/")
open(sys.argv[1], "w").write(s)
PY
done
check det-measured-trace 0 "wrote" -- "$bin" run "$tmp/trace/case-14.toml" --positions 21 -o "$tmp/trace/o.h5" -q
check det-measured-trace-short 2 "case-5.toml:[0-9]+: key 'pinion.flank.topography.file' = trace-5.csv: its profile along x is 4.999 mm long; the deterministic contact reads 11.3 mm" -- \
  "$bin" run "$tmp/trace/case-5.toml" --positions 21 -o "$tmp/trace/bad.h5" -q
# A measured patch with a missing point on the line the deterministic fidelity would roll: a
# statistical run reads its summits and never that line (runs); the deterministic run names the
# line and the keys that mend it.
rm -rf "$tmp/holes" && mkdir -p "$tmp/holes"
awk 'BEGIN { printf "# units: um\n# spacing: 0.5 um\n"; for (j = 0; j < 256; j++) { for (i = 0; i < 256; i++)
  printf "%s%s", (i ? "," : ""), (j == 128 && i == 100) ? "NaN" : sprintf("%.4f", 0.5 * sin(i * 0.31 + j * 0.07) + 0.4 * sin(i * 0.13 - j * 0.29 + 1) + 0.2 * sin(i * 1.7 + j * 2.3));
  printf "\n" } }' > "$tmp/holes/patch.csv"
sed -e 's#"surfaces/[a-z]*-flank.h5"#"patch.csv"#' -e 's#^fill = true#fill = false#' -e "s#\"\.\./materials/#\"$PWD/materials/#" \
  gears/m6z30-measured.toml > "$tmp/holes/case.toml"
check holes-statistical 0 "wrote" -- "$bin" run "$tmp/holes/case.toml" --positions 5 -o "$tmp/holes/o.h5" -q
check holes-deterministic 2 "case.toml:[0-9]+: key 'pinion.flank.topography.file' = \"patch.csv\": .*patch.csv: the line the deterministic fidelity rolls along x: row 128 \\(y = 6.4e-05 m\\) has 1 missing point\\(s\\).*pinion.flank.topography.fill = true fills missing points" -- \
  "$bin" run "$tmp/holes/case.toml" --fidelity deterministic --positions 5 -o "$tmp/holes/d.h5" -q
[[ ! -e "$tmp/holes/d.h5" ]] && echo "ok   holes-nothing-written" || { echo "FAIL holes d.h5 written"; fail=1; }
# A patch shorter than the flank (issue 29): the shipped measured case synthesises flank-long profiles
# from its 96 um patches and runs deterministically, recording what each flank came from; the synthesis
# keys out of range or too short a length: exit 2 naming file, line, key, value and rule, nothing written.
check det-synthesised 0 "pinion flank synthesised \(psd, seed 1\) from surfaces/pinion-flank.h5: 384 lines of 96 um" -- \
  "$bin" run gears/m6z30-measured.toml --fidelity deterministic --positions 21 -o "$tmp/synth.h5"
# IAAFT on this patch (its spectrum bare below 7.5 um wavelengths) stalls with m4 raised: warned.
check det-synthesised-iaaft 0 "warning: the pinion flank's IAAFT synthesis stopped after 200 iterations.*curvature moment m4 \+[0-9.]+%" -- "$bin" run gears/m6z30-measured.toml \
  --fidelity deterministic --positions 21 --set pinion.flank.topography.synthesis=iaaft \
  --set pinion.flank.topography.synthesis_length=12mm -o "$tmp/synth-iaaft.h5"
/usr/bin/python3 - "$tmp/synth.h5" "$tmp/synth-iaaft.h5" <<'PY' && echo "ok   det-synthesised-recorded" || { echo "FAIL det-synthesised-recorded"; fail=1; }
import sys, h5py
g = h5py.File(sys.argv[1], "r")["synthesis"]
p, w = g["pinion"].attrs, g["wheel"].attrs
assert p["patch"] == b"surfaces/pinion-flank.h5" and w["patch"] == b"surfaces/wheel-flank.h5", dict(p)
assert p["method"] == b"psd" and p["seed"] == 1 and w["seed"] == 1001 and p["teeth"] == 1, dict(p)
assert p["patch_lines"] == 384 and 0 < p["profile_rq_m"] < p["patch_rq_m"] and "iaaft_converged" not in p, dict(p)
p = h5py.File(sys.argv[2], "r")["synthesis/pinion"].attrs
assert p["method"] == b"iaaft" and p["iaaft_converged"] == 0 and p["iaaft_iterations"] == 200, dict(p)
assert p["iaaft_curvature_ratio"] > 1.05 and 12e-3 <= p["profile_length_m"] < 12.1e-3, dict(p)
PY
# The hunting order: a profile per tooth (seed + tooth), 30 a flank; no shared seeds (1 and 1001), no warning.
check det-synthesised-hunting 0 "pinion flank synthesised \(psd, seed 1 \+ tooth\)" -- "$bin" run gears/m6z30-measured.toml \
  --fidelity deterministic --set running_in.teeth=hunting --set running_in.meshes=1 --positions 60 \
  --set contact.element_size=2um -o "$tmp/synth-hunting.h5"
"$bin" case gears/m6z30-measured.toml --set contact.fidelity=deterministic --set running_in.teeth=hunting \
  --set running_in.meshes=1 2>&1 | grep -q "share values with" && { echo "FAIL det-synthesised-hunting: seeds warned"; fail=1; }
/usr/bin/python3 - "$tmp/synth-hunting.h5" <<'PY' && echo "ok   det-synthesised-hunting-recorded" || { echo "FAIL det-synthesised-hunting-recorded"; fail=1; }
import sys, h5py
g = h5py.File(sys.argv[1], "r")["synthesis"]
assert g["pinion"].attrs["teeth"] == 30 and g["wheel"].attrs["teeth"] == 30 and g["wheel"].attrs["seed"] == 1001
PY
bad_measured() {  # bad_measured NAME SED_EXPR PATTERN: the measured case changed, run deterministically
  rm -rf "$tmp/s" && mkdir -p "$tmp/s/gears" && cp -r gears/surfaces "$tmp/s/gears/" && cp -r materials "$tmp/s/"
  sed "$2" gears/m6z30-measured.toml > "$tmp/s/gears/m6z30-measured.toml"
  check "$1" 2 "$3" -- "$bin" run "$tmp/s/gears/m6z30-measured.toml" --fidelity deterministic --positions 21 -o "$tmp/s/out.h5" -q
  [[ ! -e "$tmp/s/out.h5" ]] && echo "ok   $1-nothing-written" || { echo "FAIL $1: out.h5 written"; fail=1; }
}
bad_measured synth-seed-negative 's/^synthesis_seed = 1 .*/synthesis_seed = -1/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis_seed' = -1: must not be negative \(range \[0, 4294967295\]\)"
bad_measured synth-seed-large 's/^synthesis_seed = 1001 .*/synthesis_seed = 4294967296/' \
  "m6z30-measured.toml:[0-9]+: key 'wheel.flank.topography.synthesis_seed' = 4294967296: must lie in \[0, 4294967295\]"
bad_measured synth-seed-fraction 's/^synthesis_seed = 1 .*/synthesis_seed = 1.5/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis_seed' = 1.5: expected an integer"
bad_measured synth-length-range 's/^# synthesis_length = "12 mm" .*/synthesis_length = "2 m"/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis_length' = \"2 m\": must lie in \[0 m, 1 m\]"
bad_measured synth-length-negative 's/^# synthesis_length = "12 mm" .*/synthesis_length = "-5 mm"/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis_length' = \"-5 mm\": must not be negative"
bad_measured synth-length-short 's/^# synthesis_length = "12 mm" .*/synthesis_length = "5 mm"/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis_length' = 5 mm: the synthesised profile, centred on the pinion's active flank, must cover the 11.46 mm the deterministic contact reads"
bad_measured synth-method 's/^synthesis = "psd" .*/synthesis = "fft"/' \
  "m6z30-measured.toml:[0-9]+: key 'pinion.flank.topography.synthesis' = \"fft\": unknown value 'fft' \(known: none, psd, iaaft\)"
# The same seed on both flanks: warned (the same phases), not refused.
check synth-same-seed 0 "warning: key 'wheel.flank.topography.synthesis_seed' = 1: the wheel's synthesis seeds \(1\) share values with the pinion's \(1\)" -- \
  "$bin" case gears/m6z30-measured.toml --set contact.fidelity=deterministic --set wheel.flank.topography.synthesis_seed=1
# The lightest load: elastic, a finite answer (the capped bracket cannot resolve it; the elastic solve can).
check det-light-load 0 "wrote" -- "$bin" run gears/m6z30-deterministic.toml --set torque=1e-6Nm --positions 11 -o "$tmp/det-light.h5" -q || { echo "FAIL det-bad.h5 written"; fail=1; }

# FZG load stages (issue 29): a case names the load stage and the test instead of a torque; the
# torque comes from gears/fzg/load-stages.csv and `geartrib case` says so. Bad input: exit 2 naming
# file, line, key, value and rule; nothing written.
check fzg-stage-torque 0 "^operating.pinion_torque +265 N m +FZG load stage 10 of GF-C/8.3/90, 0.35 m arm \(gears/fzg/load-stages.csv\)" -- \
  "$bin" case gears/fzg-c.toml
check fzg-stage-origin 0 "^operating.fzg_load_stage +10 +gears/fzg-c.toml:52" -- "$bin" case gears/fzg-c.toml
check fzg-set-stage 0 "^operating.pinion_torque +215.513 N m +FZG load stage 9 of GF-C/8.3/90" -- \
  "$bin" case gears/fzg-c.toml --set fzg_load_stage=9
check fzg-set-test 0 "^operating.pinion_torque +372.6 N m +FZG load stage 10 of PT-C, 0.5 m arm" -- \
  "$bin" case gears/fzg-c.toml --set fzg_test=PT-C
check fzg-set-torque 0 "^operating.pinion_torque +300 N m +--set" -- "$bin" case gears/fzg-c.toml --set torque=300Nm
check fzg-a-stage 0 "^operating.pinion_torque +534.5 N m +FZG load stage 12 of A/8.3/90, 0.5 m arm" -- "$bin" case gears/fzg-a.toml
check fzg-validation-stage 0 "^operating.pinion_torque +372.6 N m +FZG load stage 10 of PT-C" -- \
  "$bin" case validation/fzg-c-lubricated/fzg-c-lubricated.toml
bad_fzg() {  # bad_fzg NAME SED_EXPR PATTERN: gears/fzg-c.toml edited in a scratch copy and run
  rm -rf "$tmp/f" && mkdir -p "$tmp/f/gears" && cp -r materials lubricants "$tmp/f/" && cp gears/fzg-c.toml "$tmp/f/gears/"
  sed -i "$2" "$tmp/f/gears/fzg-c.toml"
  check "$1" 2 "$3" -- "$bin" run "$tmp/f/gears/fzg-c.toml" -o "$tmp/f/out.h5" -q
  [[ ! -e "$tmp/f/out.h5" ]] && echo "ok   $1-nothing-written" || { echo "FAIL $1: out.h5 written"; fail=1; }
}
bad_fzg fzg-stage-15 's/^fzg_load_stage = 10 /fzg_load_stage = 15 /' \
  "fzg-c.toml:52: key 'operating.fzg_load_stage' = 15: must lie in \\[1, 14\\]"
bad_fzg fzg-stage-0 's/^fzg_load_stage = 10 /fzg_load_stage = 0 /' \
  "fzg-c.toml:52: key 'operating.fzg_load_stage' = 0: must be positive \\(range \\[1, 14\\]\\)"
bad_fzg fzg-stage-fraction 's/^fzg_load_stage = 10 /fzg_load_stage = 9.5 /' \
  "fzg-c.toml:52: key 'operating.fzg_load_stage' = 9.5: expected an integer"
bad_fzg fzg-torque-and-stage 's/^fzg_load_stage = 10 /pinion_torque = "265 N m"\nfzg_load_stage = 10 /' \
  "fzg-c.toml:52: key 'operating.pinion_torque' = \"265 N m\": give the torque or the FZG load stage, not both \\(operating.fzg_load_stage = 10 at .*fzg-c.toml:53\\)"
bad_fzg fzg-stage-without-test '/^fzg_test/d' \
  "fzg-c.toml:52: key 'operating.fzg_load_stage' = 10: needs operating.fzg_test, the test whose lever arm sets the stage's torque"
bad_fzg fzg-test-without-stage 's/^fzg_load_stage = 10 /pinion_torque = "265 N m"/' \
  "fzg-c.toml:53: key 'operating.fzg_test' = \"GF-C/8.3/90\": names the test of operating.fzg_load_stage, which is not given"
bad_fzg fzg-unknown-test 's#^fzg_test = "GF-C/8.3/90"#fzg_test = "GT-C/8.3/90"#' \
  "fzg-c.toml:53: key 'operating.fzg_test' = \"GT-C/8.3/90\": unknown FZG test 'GT-C/8.3/90' \\(known: A/8.3/90, PT-C, GF-C/8.3/90\\)"
bad_fzg fzg-unconfirmed-stage 's/^fzg_load_stage = 10 /fzg_load_stage = 13 /' \
  "fzg-c.toml:52: key 'operating.fzg_load_stage' = 13: the 0.35 m arm's torque at load stage 13 \\(438.8533 N m\\) is unconfirmed in gears/fzg/load-stages.csv"
check fzg-set-stage-15 2 "fzg-c.toml \(--set operating.fzg_load_stage=15\): key 'operating.fzg_load_stage' = 15: must lie in \[1, 14\]" -- \
  "$bin" run gears/fzg-c.toml --set fzg_load_stage=15 -o "$tmp/fzg-bad.h5" -q
check fzg-sweep-stage-15 2 "'fzg_load_stage=9,15': value '15' for operating.fzg_load_stage: must lie in \[1, 14\]" -- \
  "$bin" sweep gears/fzg-c.toml --set fzg_load_stage=9,15 -o "$tmp/fzg-bad.h5" -q
[[ ! -e "$tmp/fzg-bad.h5" ]] && echo "ok   fzg-nothing-written" || { echo "FAIL fzg-bad.h5 written"; fail=1; }

# The line contact (geartrib ehl): the summary's rows, the profile's columns, the transient's series,
# refusals at the option that gave the value, nothing written on error.
ehl=("$bin" ehl --load 1e6 --radius 15.4mm --speed 5m/s --modulus 113GPa --viscosity 0.05 --alpha 2e-8 --nodes 256)
check ehl-summary 0 "^min_film_over_dowson_higginson,(0\.9|1\.0)" -- "${ehl[@]}" --csv  # within 10 % of Dowson-Higginson
check ehl-profile 0 "" -- "${ehl[@]}" -q -o "$tmp/ehl.csv"
grep -q "^x_m,pressure_Pa,film_m,shear_Pa,heights_m,state\$" "$tmp/ehl.csv" && echo "ok   ehl-profile-columns" || { echo "FAIL ehl-profile-columns"; fail=1; }
check ehl-series 0 "^time_per_step_s," -- "${ehl[@]}" --waviness 20nm,100um --window 0.5 --time-step 4 --series "$tmp/ehl-series.csv" --csv
grep -q "^time_s,central_film_m,min_film_m,peak_pressure_Pa" "$tmp/ehl-series.csv" && echo "ok   ehl-series-columns" || { echo "FAIL ehl-series-columns"; fail=1; }
check ehl-groups 0 "^moes_M,29\.06888" -- "$bin" ehl --groups 1.3e-4,1e-11,5000 --radius 10mm --modulus 113.1868GPa --viscosity 0.05 --nodes 256 --csv
check ehl-lubricant 0 "^viscosity_Pa_s,0\.0164" -- "$bin" ehl --materials materials/steel-45.toml --lubricant lubricants/mineral-vg100.toml --oil-temperature 80degC --load 3e5 --radius 10mm --speed 5m/s --nodes 256 --csv
check ehl-no-load 2 "--load W" -- "$bin" ehl --radius 10mm --speed 1m/s --modulus 113GPa --viscosity 0.05 --alpha 0
check ehl-bad-unit 2 "--radius '10parsec': unknown unit 'parsec'" -- "${ehl[@]/15.4mm/10parsec}"
check ehl-few-nodes 2 "--nodes: nodes must lie in" -- "${ehl[@]/256/8}"
check ehl-still-roughness 2 "--window: the rough surface does not move" -- "$bin" ehl --load 1e6 --radius 15.4mm --speed1 1m/s --speed2 0m/s --modulus 113GPa --viscosity 0.05 --alpha 2e-8 --waviness 0.1um,50um --rough-surface 2
check ehl-steady-smooth 2 "--steady needs a roughness" -- "${ehl[@]}" --steady
check ehl-cold-oil 2 "--oil-temperature '-90degC'" -- "$bin" ehl --modulus 113GPa --lubricant lubricants/mineral-vg100.toml --oil-temperature -90degC --load 3e5 --radius 10mm --speed 5m/s
check ehl-not-converged 1 "not converged in 1 iterations" -- "${ehl[@]}" --max-iterations 1 -o "$tmp/ehl-bad.csv"
check ehl-missing-folder 2 "" -- "${ehl[@]}" -o "$tmp/no/such/folder/ehl.csv"
[[ ! -e "$tmp/ehl-bad.csv" ]] && echo "ok   ehl-nothing-written" || { echo "FAIL ehl-bad.csv written"; fail=1; }

# Output files: written whole, atomically; nothing written on error.
check output-file 0 "" -- "$bin" asperity --csv -o "$tmp/out.csv" --delta-star 1,2
grep -q "^$header\$" "$tmp/out.csv" && echo "ok   output-content" || { echo "FAIL output-content"; fail=1; }
ls -a "$tmp" | grep -q '\.tmp\.' && { echo "FAIL temporary file left behind"; fail=1; }
check output-on-error 2 "" -- "$bin" asperity --case "$tmp/gears/m6z30.toml" -o "$tmp/bad.csv"
[[ ! -e "$tmp/bad.csv" ]] && echo "ok   nothing-written-on-error" || { echo "FAIL bad.csv written"; fail=1; }

# The ratings: a K factor below 1 refused at its key (exit 2) and nothing written; the table's
# safety factors and a dry case's finding.
check rate-k-below-one 2 "key 'rating.application_factor' = 0.9: must lie in \[1, 10\]" -- \
  "$bin" rate gears/m6z30.toml --set rating.application_factor=0.9 -o "$tmp/rate.txt" --csv "$tmp/rate.csv"
[[ ! -e "$tmp/rate.txt" && ! -e "$tmp/rate.csv" ]] && echo "ok   rate-nothing-written" || { echo "FAIL rate wrote"; fail=1; }
sed 's/^quality = "MQ"/quality = "MX"/' materials/steel-45.toml > "$tmp/steel-45-mx.toml"
check rate-quality-unknown 2 "steel-45-mx.toml:[0-9]*: key 'rating.quality'.*unknown ISO 6336-5 quality 'MX'" -- \
  "$bin" rate gears/m6z30.toml --set "pinion.material=$tmp/steel-45-mx.toml"
check rate-safeties 0 "S_F_pinion +5\.9" -- "$bin" rate gears/m6z30.toml
check rate-dry 0 "a dry case: pitting" -- "$bin" rate gears/m6z30-dry.toml

# Areal contact (`geartrib contact`, contact.fidelity = "areal"): a surface, its area-load curve, and
# refusals at the option or key (exit 2), nothing written.
"$bin" surface generate self-affine -o "$tmp/areal.h5" --nx 256 --ny 256 --spacing 1um --rq 0.3um --rolloff 128um \
  --short-cutoff 4um --seed 2 > /dev/null
check contact-curve 0 "^mean_pressure_Pa,approach_m,contact_fraction" -- \
  "$bin" contact "$tmp/areal.h5" --form 0 --material materials/16MnCr5.toml --pressure 10MPa:1GPa:3 --csv
check contact-at-hardness 2 "--pressure '2GPa': a mean pressure \(2e\+09 Pa\) at or above the hardness" -- \
  "$bin" contact "$tmp/areal.h5" --form 0 --modulus 100GPa --hardness 1GPa --pressure 2GPa -o "$tmp/contact-bad.h5"
check contact-no-modulus 2 "--modulus '': give the composite modulus" -- "$bin" contact "$tmp/areal.h5" --pressure 1MPa
check contact-memory 2 "needs .* to solve, beyond the memory budget 1 MiB \(GEARTRIB_MEMORY_BUDGET\)" -- \
  env GEARTRIB_MEMORY_BUDGET=1MiB "$bin" contact "$tmp/areal.h5" --modulus 100GPa --pressure 1MPa -o "$tmp/contact-bad.h5"
check contact-approach-half-periodic 2 "--approach '1um': the approach of a window periodic in one direction alone" -- \
  "$bin" contact "$tmp/areal.h5" --form 0 --modulus 100GPa --periodic x --approach 1um
[[ ! -e "$tmp/contact-bad.h5" ]] && echo "ok   contact-nothing-written" || { echo "FAIL contact-bad.h5 written"; fail=1; }
check areal-narrow-window 2 "key 'areal.window' = 8e-06 m: the window across the face \(8 um\) is narrower than the pinion's correlation length" -- \
  "$bin" run gears/m6z30-areal.toml --set areal.window=8um -o "$tmp/areal-bad.h5" -q
check areal-hobbed-isotropic 2 "key 'areal.lay'.*an isotropic map is made from a generated ground profile" -- \
  "$bin" run gears/m6z30-areal.toml --set pinion.flank.profile.kind=hobbed -o "$tmp/areal-bad.h5" -q
# The patch lay: a measured patch synthesised into the flanks' maps; refused without a topography, or
# with a lay ratio out of its range.
check areal-patch-no-topography 2 "key 'areal.lay' = patch: the patch lay makes each flank's map from its measured topography" -- \
  "$bin" run gears/m6z30-areal.toml --set areal.lay=patch -o "$tmp/areal-bad.h5" -q
check areal-lay-ratio-range 2 "key 'areal.lay_ratio' = 0.5" -- \
  "$bin" run gears/m6z30-areal.toml --set areal.lay=directional --set areal.lay_ratio=0.5 -o "$tmp/areal-bad.h5" -q
check areal-patch-finer-elements 2 "key 'contact.element_size' = 0.2 um: finer than the spacing along x of surfaces/pinion-flank.h5" -- \
  "$bin" run gears/m6z30-measured.toml --set contact.fidelity=areal --set areal.lay=patch --set element_size=0.2um --positions 2 -o "$tmp/areal-bad.h5" -q
[[ ! -e "$tmp/areal-bad.h5" ]] && echo "ok   areal-nothing-written" || { echo "FAIL areal-bad.h5 written"; fail=1; }
# Persson's closure takes Gaussian heights: exponential ones refused at the key.
check persson-exponential 2 "key 'lubrication.asperity_pressure' = persson: Persson's theory takes Gaussian heights" -- \
  "$bin" run gears/m6z30.toml --set lubrication.asperity_pressure=persson --set roughness.distribution=exponential -o "$tmp/persson-bad.h5" -q
# The flanks' own spectra asked for where a flank has none (given by Ra): refused at the key; the
# moments' fit asked for where these measured summits' band admits none: refused, naming the other.
check persson-spectrum-flanks 2 "key 'lubrication.persson_spectrum' = \"flanks\": the pinion flank has no spectrum of its own" -- \
  "$bin" run gears/m6z30.toml --set lubrication.asperity_pressure=persson --set lubrication.persson_spectrum=flanks -o "$tmp/persson-bad.h5" -q
check persson-spectrum-moments 2 "with lubrication.persson_spectrum = \"moments\" it is fitted to the statistical model's moments, and none fits them" -- \
  "$bin" run gears/m6z30-measured.toml --set lubricant.file=../lubricants/mineral-vg220.toml --set operating.oil_temperature=70degC \
  --set lubrication.asperity_pressure=persson --set lubrication.persson_spectrum=moments -o "$tmp/persson-bad.h5" -q
# Generated ground and superfinished surfaces: written; a plateau outside (0, 1) refused, naming it.
check surface-generate-ground 0 "" -- "$bin" surface generate ground -o "$tmp/ground.h5" --nx 64 --ny 64 --correlation 4um
check surface-generate-superfinished 0 "" -- "$bin" surface generate superfinished -o "$tmp/sf.h5" --nx 64 --ny 64 --correlation 4um
check surface-generate-plateau 2 "--plateau 1.5: the area cut flat must lie in \(0, 1\)" -- \
  "$bin" surface generate superfinished -o "$tmp/sf-bad.h5" --nx 64 --ny 64 --plateau 1.5
[[ ! -e "$tmp/sf-bad.h5" ]] && echo "ok   superfinished-nothing-written" || { echo "FAIL sf-bad.h5 written"; fail=1; }

exit $fail
