# 21: sweep axes reaching the same key under two names (issue 30, finding 15). Found:
# `--set teeth=30,31 --set pinion.teeth=25` ran every point with a 25-tooth pinion while the
# table's teeth column said 30 and 31 (exit 0): only identical names were caught as "given twice".
# Now an alias and the dotted keys it stands for are one key, and an axis that replaces another's
# key (a torque and an FZG load stage, a flank's rq and its ra) is refused too: exit 2 naming both
# axes and the key, before any point runs.
cases=../../../gears/m6z30.toml
m21="$tmp/21"; mkdir -p "$m21"
sw() { g sweep "$cases" "$@" --set positions=5 -o "$m21/s.h5" --csv "$m21/s.csv" -q; }
check alias-and-dotted-key 2 "^geartrib: error: --set teeth \(pinion.teeth, wheel.teeth\) and --set pinion.teeth set the same key pinion.teeth: a key given twice" -- sw --set teeth=30,31 --set pinion.teeth=25
check dotted-key-and-alias 2 "--set wheel.teeth and --set teeth \(pinion.teeth, wheel.teeth\) set the same key wheel.teeth" -- sw --set wheel.teeth=25 --set teeth=30,31
check gear-alias-and-dotted-key 2 "--set z1 \(pinion.teeth\) and --set pinion.teeth set the same key pinion.teeth" -- sw --set z1=20,25 --set pinion.teeth=30
check two-aliases 2 "--set rq \(pinion.flank.rq, wheel.flank.rq\) and --set wheel.flank.rq set the same key wheel.flank.rq" -- sw --set rq=0.2um,0.4um --set wheel.flank.rq=0.3um
check torque-and-load-stage 2 "--set torque \(operating.pinion_torque\) and --set fzg_load_stage \(operating.fzg_load_stage\) change the same key: --set fzg_load_stage \(operating.fzg_load_stage\) replaces operating.pinion_torque" -- sw --set torque=500Nm,1000Nm --set fzg_load_stage=5 --set fzg_test=PT-C
check rq-and-ra 2 "--set rq .* and --set pinion.flank.ra change the same key: --set pinion.flank.ra replaces pinion.flank.rq" -- sw --set rq=0.2um,0.4um --set pinion.flank.ra=0.1um
check identical-names 2 "--set torque given twice" -- sw --set torque=500Nm --set torque=1000Nm
check nothing-written 0 "^$" -- ls -A "$m21"
# Keys that do not overlap still sweep together: the two flanks' rq, the load stage with its test,
# a roughness form with the summit radius.
check flanks-apart 0 "" -- sw --set pinion.flank.rq=0.2um,0.4um --set wheel.flank.rq=0.3um --set summit_radius=20um
check stage-and-test 0 "" -- g sweep ../../../gears/fzg-c.toml --set fzg_load_stage=4,5 --set fzg_test=PT-C --set positions=5 -o "$m21/s.h5" -q
rm -rf "$m21"
