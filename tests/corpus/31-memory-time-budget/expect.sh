# 31 (issue 30, finding 11): valid keys made one run take tens of GB or a day, found only by running
# out of memory (std::bad_alloc, exit 1) or time: the hunting order of 1000 teeth kept 2000 flanks of
# 1.6e6 points (26 GB); pressure_profiles = "all" grows with elements x positions; running_in.meshes =
# 100000 ran ~24 h; 7 nm elements over 20 half-widths ran 100 min. Now each run's memory and time are
# estimated from its sizes and measured per-unit costs before anything is made (runs::run_mesh_cycle,
# contact::deterministic_cost) and refused past the budget (GEARTRIB_MEMORY_BUDGET, default 4 GiB;
# GEARTRIB_TIME_BUDGET, default 1 h) with exit 2, the estimate and the key to change; nothing written.
d=../../../gears/m6z30-deterministic.toml
check hunting-1000-teeth 2 "key 'running_in.teeth' = hunting: the run would hold about 24.5 GiB \(flanks 24.5 GiB: 1000 profiles.*more than the memory budget of 4 GiB \(GEARTRIB_MEMORY_BUDGET\): the hunting order holds every tooth's flank" -- g run $d -o "$tmp/h.h5" -q --set teeth=1000 --set "pinion.bore_diameter=0 m" --set "wheel.bore_diameter=0 m" --set running_in.meshes=1 --set running_in.teeth=hunting --set contact.positions=45
check hunting-nothing-written 1 "" -- test -e "$tmp/h.h5"
check profiles-all-100000 2 "key 'contact.pressure_profiles' = all: the run would hold about 11.. GiB .*pressure profiles 11.4 GiB: 100000 of 5120 elements.*keep the profiles at the named points" -- g run $d -o "$tmp/p.h5" -q --set contact.pressure_profiles=all --set contact.positions=100000 --set contact.strip_halfwidths=8
check meshes-100000 2 "key 'running_in.meshes' = 100000: the run would take about .* h on [0-9]+ cores \(2.01e\+07 strip solves: 201 positions x 100000 meshes at most, each about 5.9 ms on one core for 1280 elements.*more than the time budget of 1 h \(GEARTRIB_TIME_BUDGET\): at most [0-9]+ meshes fit it" -- g run $d -o "$tmp/r.h5" -q --set running_in.meshes=100000 --set "running_in.tolerance=2e-15 m"
check elements-7nm 2 "key 'contact.element_size' = 7e-09 m: the run would take about .* h on [0-9]+ cores \(201 strip solves: 201 positions, each about .* min on one core for 914098 elements.*coarser elements, or a shorter strip \(contact.strip_halfwidths\)" -- g run $d -o "$tmp/e.h5" -q --set contact.element_size=7nm --set pinion.flank.profile.spacing=7nm --set wheel.flank.profile.spacing=7nm --set contact.strip_halfwidths=20
# The budget is the user's: raised, the same keys run (shakedown at the first mesh here); lowered, a
# small run is refused; a malformed budget names its variable.
GEARTRIB_TIME_BUDGET="30 d" check meshes-100000-budget-raised 0 "wrote" -- g run $d -o "$tmp/r.h5" -q --set running_in.meshes=100000 --set "running_in.tolerance=1 mm" --set contact.positions=61
GEARTRIB_TIME_BUDGET="1 s" check meshes-budget-lowered 2 "key 'running_in.meshes' = 100: .*more than the time budget of 1 s" -- g run $d -o "$tmp/r.h5" -q --set running_in.meshes=100
GEARTRIB_MEMORY_BUDGET="4 XB" check memory-budget-malformed 2 "environment: key 'GEARTRIB_MEMORY_BUDGET' = 4 XB: unknown unit 'XB'" -- g run $d -o "$tmp/r.h5" -q --set contact.positions=11
GEARTRIB_TIME_BUDGET="0 s" check time-budget-outside 2 "environment: key 'GEARTRIB_TIME_BUDGET' = 0 s: must lie in \[1 s, 365 d\]" -- g run $d -o "$tmp/r.h5" -q --set contact.positions=11
check budget-refusals-nothing-written 1 "" -- test -e "$tmp/p.h5" -o -e "$tmp/e.h5"
# geartrib fit: each --data file is capped at 64 MiB but their number was not (6 x 63 MB: std::bad_alloc
# under 8 GB). The data's memory is counted file by file and refused at the file that passes the budget.
/usr/bin/python3 - "$tmp/big.csv" <<'PY'
import sys
rows = [l for l in open('../06-fit/ke.csv') if not l.startswith('#')]
out, size, i = [rows[0]], 0, 0
while size < 63 * 2**20: l = rows[1 + i % (len(rows) - 1)]; out.append(l); size += len(l); i += 1
open(sys.argv[1], 'w').write(''.join(out))
PY
fit=(fit --model kogut-etsion --case ../../../gears/m6z30.toml --free load_coefficient_1,load_exponent_1 -q)
check fit-six-63MB-files 2 "big.csv: key '--data': with this file the fit would hold about 5.8. GiB \(3 data files so far.*more than the memory budget of 4 GiB \(GEARTRIB_MEMORY_BUDGET\)" -- g "${fit[@]}" $(for k in 1 2 3 4 5 6; do echo --data "$tmp/big.csv"; done)
GEARTRIB_MEMORY_BUDGET="1 MiB" check fit-budget-lowered 2 "ke.csv: key '--data': with this file the fit would hold about .* more than the memory budget of 1 MiB" -- g "${fit[@]}" $(for k in $(seq 1 30); do echo --data ../06-fit/ke.csv; done)
