#!/usr/bin/env bash
# `geartrib sweep`: a small factorial in parallel, the same sweep in two shards merged back to the
# identical table, a point with impossible geometry reported while the sweep goes on, the trends
# physics requires, and clear errors for bad sweep input.
# Usage: sweep_cli.sh path/to/geartrib   (run from the source tree; needs python3-h5py)
set -u
bin="$1"
source "$(dirname "$0")/cli_support.sh"
# 2 x 2 x 2 points, 21 positions each (fast); the same plan below in shards.
plan=(gears/m6z30-dry.toml --set module=4mm,8mm --set face_width=40mm:80mm:2 --set rq=0.01um,0.8um --set positions=21)
# The summary line: the points, their wall time and threads, and the process's peak memory.
check full 0 "8 points, 0 failed; [0-9.e+-]+ s on 2 threads, peak memory [0-9]+ MB" -- "$bin" sweep "${plan[@]}" --threads 2 -o "$tmp/full.h5" --csv "$tmp/full.csv"
check shard0 0 "4 points" -- "$bin" sweep "${plan[@]}" --shard 0/2 -o "$tmp/s0.h5"
check shard1 0 "4 points" -- "$bin" sweep "${plan[@]}" --shard 1/2 -o "$tmp/s1.h5"
check merge 0 "8 points, 0 failed; peak memory [0-9]+ MB" -- "$bin" sweep --merge "$tmp/s1.h5" "$tmp/s0.h5" -o "$tmp/merged.h5" --csv "$tmp/merged.csv"
check merge-missing-shard 2 "shard 1/2 is missing" -- "$bin" sweep --merge "$tmp/s0.h5" -o "$tmp/bad.h5"
"$bin" run -q --set positions=5 -o "$tmp/run.h5" >/dev/null
check merge-not-a-sweep 2 "not a readable geartrib sweep file" -- "$bin" sweep --merge "$tmp/run.h5" -o "$tmp/bad.h5"
check merge-twice 2 "given twice" -- "$bin" sweep --merge "$tmp/s0.h5" "$tmp/s0.h5" -o "$tmp/bad.h5"
"$bin" sweep -q --set module=4mm,5mm --set positions=21 --shard 1/2 -o "$tmp/other.h5" >/dev/null 2>&1
check merge-other-sweep 2 "from another sweep" -- "$bin" sweep --merge "$tmp/s0.h5" "$tmp/other.h5" -o "$tmp/bad.h5"
# A shard whose column has another unit (edited here) is refused, not merged under the first unit.
cp "$tmp/s1.h5" "$tmp/s1-unit.h5"
/usr/bin/python3 -c 'import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    v = f["points/values"]
    units = v.attrs["units"].decode().replace("1,m,", "1,mm,", 1).encode()
    v.attrs.create("units", units, dtype=h5py.string_dtype("utf-8", len(units)))' "$tmp/s1-unit.h5"
check merge-unit-differs 2 "column module is numeric \[mm\] here and numeric \[m\] in another shard" -- "$bin" sweep --merge "$tmp/s0.h5" "$tmp/s1-unit.h5" -o "$tmp/bad.h5"
[[ ! -e "$tmp/bad.h5" ]] && echo "ok   nothing-written-on-error" || { echo "FAIL bad.h5 written"; fail=1; }

# Merged equals unsharded (all columns but the timing), and the trends physics requires.
/usr/bin/python3 - "$tmp/full.csv" "$tmp/merged.csv" "$tmp/full.h5" <<'PY' || fail=1
import csv, sys
import h5py
def read(p):
    rows = list(csv.DictReader(l for l in open(p) if not l.startswith("#")))
    return [{k: v for k, v in r.items() if k != "seconds"} for r in rows]
full, merged = read(sys.argv[1]), read(sys.argv[2])
assert full == merged, "merged shards differ from the unsharded sweep"
print("ok   merged-equals-unsharded")
def text(x):
    return x.decode() if isinstance(x, bytes) else x
def points(f):
    """The sweep table: the numeric block /points/values by its column names, the text columns."""
    g, v = f["points"], f["points/values"]
    names, units = text(v.attrs["columns"]).split(","), text(v.attrs["units"]).split(",")
    assert v.shape == (len(g["status"]), len(names)), v.shape
    cols = {n: v[:, k] for k, n in enumerate(names)}
    for n in text(g.attrs["columns"]).split(","):
        if n not in cols: cols[n] = [text(x) for x in g[n][()]]
    return cols, dict(zip(names, units))
with h5py.File(sys.argv[3]) as f:
    p, units = points(f)
    assert units["module"] == "m", units["module"]
    assert units["hertz_p0_Pa_max"] == "Pa"
    assert "version" in f["sweep"].attrs and "sets" in f["sweep"].attrs
    assert b"[gear_pair]" in f["scene"][()] if isinstance(f["scene"][()], bytes) else "[gear_pair]" in f["scene"][()]
    m, b, rq = p["module"], p["face_width"], p["rq"]
    p0, area, plastic = p["hertz_p0_Pa_max"], p["real_area_ratio_min"], p["plastic_area_fraction_min"]
    idx = {(m[i], b[i], rq[i]): i for i in range(len(m))}
    for (mi, bi, ri), i in idx.items():
        if mi == 0.004: assert p0[idx[(0.008, bi, ri)]] < p0[i], "larger module must lower the Hertz pressure"
        if bi == 0.04: assert p0[idx[(mi, 0.08, ri)]] < p0[i], "wider face must lower the Hertz pressure"
        if ri == 1e-8:
            assert area[idx[(mi, bi, 8e-7)]] < area[i], "rougher must lower the real-area ratio"
            assert plastic[idx[(mi, bi, 8e-7)]] > plastic[i], "rougher must raise the plastic fraction"
print("ok   trends-and-units")
with h5py.File(sys.argv[3]) as f:
    p, _ = points(f)
    # The validity verdict per point: regime and the flags' position counts (21 positions each).
    regime = p["regime"]
    assert set(regime) <= {"elastic", "elastic-plastic", "fully plastic"}, regime
    beyond = p["positions_beyond_fitted_range"]
    assert all(0 <= n <= 21 for n in beyond), beyond
    for (mi, bi, ri), i in idx.items():
        if ri == 8e-7: assert regime[i] == "fully plastic" and beyond[i] == 21, (regime[i], beyond[i])
    assert all(len(v) > 0 for v in p["validity"])
print("ok   validity-per-point")
PY

# The lubricated runs' mesh-level values, one column each: those of `geartrib run` at the same point
# (its /lubrication attributes, bit for bit: one computation), with units; the per-pair loss is
# pair_power_loss_W_*, and the mesh's mean loss is its path mean times the contact ratio.
lub=(--set torque=500Nm,2000Nm --set ra=0.4um,0.8um --set lubrication.scuffing_temperature=300degC --set positions=21)
check lubricated 0 "4 points, 0 failed" -- "$bin" sweep "${lub[@]}" -o "$tmp/lub.h5"
"$bin" run -q --set torque=2000Nm --set ra=0.4um --set lubrication.scuffing_temperature=300degC --set positions=21 -o "$tmp/lub-run.h5" >/dev/null
# A mixed sweep (lubricant=none runs the case dry): dry points have NaN there. Its shards are one
# dry and one lubricated (point % 2), merged dry shard first: the columns in the unsharded order.
mixed=(--set torque=500Nm,1000Nm --set lubricant=none,../lubricants/mineral-vg220.toml --set positions=21)
"$bin" sweep -q "${mixed[@]}" -o "$tmp/mixed.h5" --csv "$tmp/mixed.csv" >/dev/null
"$bin" sweep -q "${mixed[@]}" --shard 0/2 -o "$tmp/mixed0.h5" >/dev/null
"$bin" sweep -q "${mixed[@]}" --shard 1/2 -o "$tmp/mixed1.h5" >/dev/null
check merge-mixed 0 "4 points, 0 failed" -- "$bin" sweep --merge "$tmp/mixed0.h5" "$tmp/mixed1.h5" -o "$tmp/mixed-merged.h5" --csv "$tmp/mixed-merged.csv"
/usr/bin/python3 - "$tmp" <<'PY' || fail=1
import csv, math, sys
import h5py
tmp = sys.argv[1]
def text(x):
    return x.decode() if isinstance(x, bytes) else x
def table(path):
    with h5py.File(path) as f:
        v = f["points/values"]
        names, units = text(v.attrs["columns"]).split(","), text(v.attrs["units"]).split(",")
        return {n: v[:, k] for k, n in enumerate(names)}, dict(zip(names, units)), text(f["sweep"].attrs["axes"])
p, units, axes = table(f"{tmp}/lub.h5")
assert axes == "torque,ra,lubrication.scuffing_temperature,positions", axes
with h5py.File(f"{tmp}/lub-run.h5") as f:
    run = {k: float(v) for k, v in f["lubrication"].attrs.items() if not isinstance(v, (bytes, str))}
for name in ("mesh_power_loss_W", "tooth_friction_efficiency", "gear_loss_factor_path", "bulk_temperature_K",
             "iso_scuffing_safety", "scuffing_safety", "min_iso_lambda_gf"):
    assert name in run, name
i = [k for k in range(4) if p["torque"][k] == 2000 and p["ra"][k] == 4e-7][0]
for name, value in run.items():  # every value of the run's summary, as one column, the run's number
    assert name in p and not any(name + s in p for s in ("_min", "_mean", "_max")), name
    assert p[name][i] == value or (math.isnan(value) and math.isnan(p[name][i])), (name, p[name][i], value)
assert (units["mesh_power_loss_W"], units["bulk_temperature_K"], units["tooth_friction_efficiency"]) == ("W", "K", "1")
assert all(f"pair_power_loss_W_{s}" in p for s in ("min", "mean", "max"))
assert not any(n.startswith("power_loss_W") for n in p)
for k in range(4):
    # Both trapezoidal over the same positions: equal to rounding (1e-12 relative).
    mesh = p["pair_power_loss_W_mean"][k] * p["contact_ratio"][k]
    assert math.isclose(p["mesh_power_loss_W"][k], mesh, rel_tol=1e-12), (p["mesh_power_loss_W"][k], mesh)
    assert p["tooth_friction_efficiency"][k] < 1.0 and p["scuffing_safety"][k] > 0.0
print("ok   lubricated-mesh-level-columns")
m, _, _ = table(f"{tmp}/mixed.h5")
lubed = [not math.isnan(x) for x in m["mesh_power_loss_W"]]
assert lubed == [False, True, False, True], lubed  # points (500, none), (500, oil), (1000, none), (1000, oil)
def rows(path):
    lines = [l for l in open(path) if not l.startswith("#")]
    r = list(csv.reader(lines))
    s = r[0].index("seconds")
    return [x[:s] + x[s + 1:] for x in r]
full, merged = rows(f"{tmp}/mixed.csv"), rows(f"{tmp}/mixed-merged.csv")
assert full[0] == merged[0], "merged columns not in the unsharded order"
assert full == merged, "merged mixed shards differ from the unsharded sweep"
print("ok   mixed-sweep-merged-equals-unsharded")
PY

# A point whose geometry is impossible is reported in its row; the others run.
check bad-point-reported 0 "1 failed" -- "$bin" sweep --set x1=0,1.5 --set positions=21 -o "$tmp/x.h5" --csv "$tmp/x.csv"
grep -q "tip interference" "$tmp/x.csv" && echo "ok   bad-point-message" || { echo "FAIL bad-point-message"; fail=1; }
check zip 0 "2 points" -- "$bin" sweep --zip --set z1=29,31 --set z2=31,29 --set positions=21 -o "$tmp/z.h5"

# A sweep over FZG load stages (issue 29): each point runs its stage's torque from
# gears/fzg/load-stages.csv (the micropitting test's 0.35 m arm). The largest line load along the
# path is the single-pair zone's full load T1/(r_b1 b), r_b1 = m z1 cos(alpha)/2: it must equal the
# table's torque over r_b1 b to the CSV's 10 significant digits (relative 1e-9; a torque from the
# neighbouring stage is off by 15 % or more).
check fzg-stages 0 "4 points, 0 failed" -- "$bin" sweep gears/fzg-c.toml --set fzg_load_stage=5,7,9,10 --set positions=21 \
  -o "$tmp/fzg.h5" --csv "$tmp/fzg.csv"
/usr/bin/python3 - "$tmp/fzg.csv" <<'PY' || fail=1
import csv, math, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
table = {5: 69.98, 7: 132.455, 9: 215.513, 10: 265.0}  # gears/fzg/load-stages.csv, 0.35 m arm [N m]
r_b1, b = 4.5e-3 * 16 / 2 * math.cos(math.radians(20)), 14e-3
assert [int(r["fzg_load_stage"]) for r in rows] == list(table), [r["fzg_load_stage"] for r in rows]
for r in rows:
    want = table[int(r["fzg_load_stage"])] / (r_b1 * b)
    got = float(r["line_load_N_per_m_max"])
    assert r["status"] == "ok" and abs(got / want - 1) < 1e-9, (r["fzg_load_stage"], got, want)
print("ok   fzg-stages-torques")
PY

# Bad sweep input: exit 2, nothing written.
check no-set 2 "at least one --set" -- "$bin" sweep -o "$tmp/bad.h5"
check no-equals 2 "expected key=value" -- "$bin" sweep --set module -o "$tmp/bad.h5"
check bad-range 2 "same unit" -- "$bin" sweep --set face_width=40mm:0.08m:3 -o "$tmp/bad.h5"
check bad-count 2 "integer count" -- "$bin" sweep --set face_width=40mm:80mm:x -o "$tmp/bad.h5"
check zip-lengths 2 "equal lengths" -- "$bin" sweep --zip --set z1=20,30 --set z2=30,31,32 -o "$tmp/bad.h5"
check bad-shard 2 "0 <= i < n" -- "$bin" sweep --set z1=20,30 --shard 2/2 -o "$tmp/bad.h5"
check same-key-twice 2 "given twice" -- "$bin" sweep --set z1=20 --set z1=30 -o "$tmp/bad.h5"
# Axis values are checked against the parameter table before any point runs.
check axis-unit 2 "value '4GPa' for gear_pair.module: unit 'GPa' is a pressure" -- "$bin" sweep --set module=4GPa,5mm -o "$tmp/bad.h5"
check axis-choice 2 "unknown value 'fine'" -- "$bin" sweep --set fidelity=fine -o "$tmp/bad.h5"
check axis-range 2 "must lie in \[5, 1000\]" -- "$bin" sweep --set teeth=4,30 -o "$tmp/bad.h5"
check unknown-key 0 "unknown key" -- "$bin" sweep --set gear_pair.modul=5mm -o "$tmp/u.h5" --csv "$tmp/u.csv"
check run-set 2 "--set gear_pair.module=-5mm" -- "$bin" run -q --set module=-5mm -o "$tmp/bad.h5"
check run-set-integer 2 "expected an integer" -- "$bin" run -q --set pinion.teeth=30.5 -o "$tmp/bad.h5"
[[ ! -e "$tmp/bad.h5" ]] && echo "ok   nothing-written-on-bad-input" || { echo "FAIL bad.h5 written"; fail=1; }
exit $fail
