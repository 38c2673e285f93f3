# 04: TOML case and material values (found: an integer beyond 2^53 ended in "bad optional access",
# integers wrapped, "1e308 GPa" became inf after the finiteness check, a tiny bore gave NaN
# stiffness, absurd values ran long and ended without a place). Now every numeric key is checked
# in SI against its declared range (docs/reference/case-file.md) and named with its file and line
# or its --set; a gear value inside the range but outside its plausible band is warned about.
scratch="$tmp/04"; mkdir -p "$scratch"  # this folder's scratch, removed at the end (other folders share $tmp)
cases=../../../gears/m6z30.toml
run() { g run "$@" -o "$scratch/out.h5" --positions 11 -q; }
# (a) integers beyond 2^53 in numeric keys, in a material, a case and a --set
check bigint-material 2 "bigint.toml:7: key 'youngs_modulus' = 9223372036854775807: integer beyond 2\^53" -- run gears/bigint-material.toml
check bigint-face 2 "bigint-face.toml:10: key 'gear_pair.face_width' = 9007199254740993: integer beyond 2\^53" -- run gears/bigint-face.toml
check bigint-set 2 "m6z30.toml \(--set gear_pair.module=9007199254740993\): key 'gear_pair.module'.*integer beyond 2\^53" -- run "$cases" --set gear_pair.module=9007199254740993
# (b) integers range-checked before narrowing (2^32 + 30 teeth, 2^32 + 2 positions: no wrap), even when a later change overrides
check teeth-wrap 2 "--set pinion.teeth=4294967326\): key 'pinion.teeth' = 4294967326: must lie in \[5, 1000\]" -- run "$cases" --set teeth=4294967326
check positions-wrap 2 "--set contact.positions=4294967298\): key 'contact.positions' = 4294967298: must lie in \[2, 100000\]" -- run "$cases" --set contact.positions=4294967298
# (c) finite number x unit = inf: refused after the unit is applied
check inf-modulus-kinematics 2 "inf-modulus.toml:7: key 'youngs_modulus' = \"1e308 GPa\": value must be finite in SI" -- g kinematics gears/inf-modulus.toml --summary
check inf-modulus-run 2 "inf-modulus.toml:7: key 'youngs_modulus' = \"1e308 GPa\": value must be finite in SI" -- run gears/inf-modulus.toml
check huge-speed 2 "--set operating.pinion_speed=1e308rpm\): key 'operating.pinion_speed' = \"1e308rpm\": must lie in" -- run "$cases" --set speed=1e308rpm
# (d) a vanishing bore (NaN fillet-foundation stiffness): refused at the bore
check tiny-bore-kinematics 2 "tiny-bore.toml:21: key 'pinion.bore_diameter' = \"60e-300 mm\": .*below 1/50 of the root diameter" -- g kinematics gears/tiny-bore.toml --summary
check tiny-bore-run 2 "tiny-bore.toml:21: key 'pinion.bore_diameter' = \"60e-300 mm\": .*below 1/50 of the root diameter" -- run gears/tiny-bore.toml
# (e) absurd roughness and torque: refused by the declared range at once (was ~15 s, then no file, line or key)
check huge-ra 2 "huge-ra.toml:27: key 'pinion.flank.ra' = \"0.8e300 um\": must lie in \[1e-10 m, 0.001 m\]" -- run gears/huge-ra.toml
check huge-torque 2 "m6z30.toml \(--set operating.pinion_torque=1e11Nm\): key 'operating.pinion_torque' = \"1e11Nm\": must lie in" -- run "$cases" --set torque=1e11Nm
# (f) a huge module: the module is blamed (was the addendum, with -nan)
check huge-module 2 "--set gear_pair.module=1e300m\): key 'gear_pair.module' = \"1e300m\": must lie in \[1e-06 m, 10 m\]" -- run "$cases" --set module=1e300m
# Inside the range, outside the plausible band of a spur gear: read, and warned about naming the key
solid="--set pinion.bore_diameter=0 --set wheel.bore_diameter=0"
check module-6m-warned 0 "warning: key 'gear_pair.module' = \"6m\": above the plausible band" -- g kinematics "$cases" --summary $solid --set module=6m
check torque-1e8-warned 0 "warning: key 'operating.pinion_torque' = \"1e8Nm\": above the plausible band" -- g kinematics "$cases" --summary --set torque=1e8Nm
check speed-1e6rpm-warned 0 "warning: key 'operating.pinion_speed' = \"1e6rpm\": above the plausible band" -- g kinematics "$cases" --summary --set speed=1e6rpm
# Units: an exponent belongs to the number ("5e-1mm" is 0.5 mm; "2e" is no number with a unit "e")
check exponent-with-unit 0 "gear_pair.face_width +0.0005 m +--set" -- g case "$cases" --set face_width=5e-1mm
check broken-exponent 2 "key 'gear_pair.face_width' = \"2e\": expected '<number> <unit>'" -- g case "$cases" --set face_width=2e
rm -rf "$scratch"
