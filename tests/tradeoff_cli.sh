#!/usr/bin/env bash
# `geartrib tradeoff` on the seed's dry scene (gears/m6z30-dry.toml), three knobs (positions, height_points, asperity_model;
# --min-time 0: one run per setting, a few seconds in all): the table's shape, the recommendation
# rule against the printed table, and the error metric against one computed here from the
# per-position results of `geartrib run` at a setting and at the knob's reference
# (src/app/tradeoff_command.cpp, curve_error).
# Usage: tradeoff_cli.sh path/to/geartrib   (run from the source tree; --csv stays last on the line)
set -u
bin="$1"
source "$(dirname "$0")/cli_support.sh"
knobs=(gears/m6z30-dry.toml --knob positions --knob height_points --knob asperity_model)
check table 0 "^knob,setting,time_s,error_real_area,error_plastic_fraction,error_peak_stress,note" -- \
  bash -c '"$0" tradeoff --min-time 0 -q "${@:2}" --csv > "$1" && cat "$1"' "$bin" "$tmp/table.csv" "${knobs[@]}"
check text 0 "^Recommended \(cheapest within 1% of each knob's reference on all three outputs\):" -- \
  bash -c '"$0" tradeoff --min-time 0 -q "${@:2}" > "$1" && cat "$1"' "$bin" "$tmp/table.txt" "${knobs[@]}"
# A tolerance no coarse setting meets: the reference is the only choice, whatever the timings.
check tight-tolerance 0 "" -- \
  bash -c '"$0" tradeoff --min-time 0 -q --tolerance 1e-9 --knob positions --csv > "$1"' "$bin" "$tmp/tight.csv"
check unknown-knob 2 "none of the names is a knob" -- "$bin" tradeoff --min-time 0 --knob no_such_knob
# A setting the case refuses (here the time budget's estimate of the finest elements: 21 positions of
# 55 ms) is left out and said, and the next is the reference; a knob all of whose settings the case
# refuses is the case's refusal (exit 2, its key and rule).
refused=(gears/m6z30-deterministic.toml --knob element_size --min-time 0 -q --set threads=1)
check refused-left-out 0 "^  element_size 0.125 um: .*more than the time budget of 1 s" -- \
  env GEARTRIB_TIME_BUDGET=1s "$bin" tradeoff "${refused[@]}" --set positions=21
check refused-next-is-reference 0 "^element_size,0.25 um,.*,0,0,0,\"reference, recommended\"" -- \
  env GEARTRIB_TIME_BUDGET=1s "$bin" tradeoff "${refused[@]}" --set positions=21 --csv
check refused-all 2 "key 'contact.positions' = 801: the run would take .* more than the time budget of 1 s" -- \
  env GEARTRIB_TIME_BUDGET=1s "$bin" tradeoff "${refused[@]}" --set positions=801
# The ladder's tolerance: a relative error in (0, 1] (the ladder itself: validation/areal-ladder, label long).
check ladder-tolerance 2 "--ladder-tolerance: Value 2 not in range" -- \
  "$bin" tradeoff gears/m6z30-areal.toml --knob ladder --ladder-tolerance 2
# The runs behind five rows, computed independently: positions 11 against 801 (the positions differ:
# path minimum, mean and maximum only), height_points 8 and 16 against 1024 and the ceb and hertz models
# against the case's continuous one (same positions: pointwise too).
for s in contact.positions=11 contact.positions=801 contact.height_points=8 contact.height_points=16 contact.height_points=1024 asperity.model=ceb asperity.model=hertz asperity.model=continuous; do
  "$bin" run gears/m6z30-dry.toml -q --set "$s" -o "$tmp/$s.h5" >/dev/null 2>&1 || { echo "FAIL run --set $s"; fail=1; }
done

/usr/bin/python3 - "$tmp" <<'PY' || fail=1
import csv, math, re, sys
import h5py
tmp = sys.argv[1]
OUTPUTS = ["real_area_ratio", "plastic_area_fraction", "max_asperity_von_mises_Pa"]
ERRORS = ["error_real_area", "error_plastic_fraction", "error_peak_stress"]
LADDERS = {"positions": ["11", "21", "41", "81", "101", "201", "401", "801"],
           "height_points": ["8", "16", "32", "64", "128", "256", "512", "1024"],
           "asperity_model": ["hertz", "ceb", "kogut-etsion", "jackson-green", "zmc", "continuous"],  # the registry's order
           "combined": ["case as given", "recommended", "all highest"]}
PHYSICS = {"asperity_model"}  # reported, never recommended
TOL = 0.01

def table(path):
    lines = open(path).read().splitlines()
    assert lines[0] == "# units: ,,s,1,1,1,", lines[0]
    rows = list(csv.DictReader(lines[1:]))
    for r in rows:
        for k in ["time_s"] + ERRORS:
            r[k] = float(r[k])
    return rows

def by_knob(rows):
    out = {}
    for r in rows:
        out.setdefault(r["knob"], []).append(r)
    return out

# Shape: one row per setting, in ladder order, the reference last with zero error; finite numbers.
rows = table(f"{tmp}/table.csv")
knobs = by_knob(rows)
assert list(knobs) == list(LADDERS), list(knobs)
for k, ladder in LADDERS.items():
    assert [r["setting"] for r in knobs[k]] == ladder, (k, [r["setting"] for r in knobs[k]])
    ref = knobs[k][-1]
    assert ref["note"] in ("reference", "reference, recommended"), ref
    assert all(ref[e] == 0 for e in ERRORS), ref
    for r in knobs[k]:
        assert r["time_s"] > 0 and all(math.isfinite(r[e]) and r[e] >= 0 for e in ERRORS), r
        assert r["note"] in ("", "recommended", "reference", "reference, recommended"), r
        assert ("reference" in r["note"]) == (r is ref), r
print(f"ok   shape: {len(rows)} rows, {', '.join(f'{k} {len(v)}' for k, v in knobs.items())}")

def rule(ladder_rows, tol, slack=0.0):
    """The settings the rule may recommend: within tol on all three outputs and within 5% of the
    fastest such time (the reference is always within); the first of those in ladder order.
    slack widens the 5% both ways for times printed with 4 digits: returns the set of possible picks."""
    worst = [max(r[e] for e in ERRORS) for r in ladder_rows]
    fastest = min([ladder_rows[-1]["time_s"]] + [r["time_s"] for r, w in zip(ladder_rows, worst) if w <= tol])
    picks = set()
    for factor in {1.05 * (1 - slack), 1.05 * (1 + slack)}:
        for r, w in zip(ladder_rows, worst):
            if w <= tol and r["time_s"] <= factor * fastest:
                picks.add(r["setting"])
                break
    return picks

# The recommendation in the CSV: one per tuned knob, the rule's pick; none for physics choices; a
# setting beyond the tolerance is never recommended.
for k in ("positions", "height_points", "asperity_model"):
    rec = [r["setting"] for r in knobs[k] if "recommended" in r["note"]]
    if k in PHYSICS:
        assert rec == [], (k, rec)
        continue
    assert len(rec) == 1 and rec[0] in rule(knobs[k], TOL, 1e-6), (k, rec, rule(knobs[k], TOL, 1e-6))
    r = next(r for r in knobs[k] if r["setting"] == rec[0])
    assert max(r[e] for e in ERRORS) <= TOL, r
print("ok   recommendation-rule (csv): " + ", ".join(f"{k} = {next(r['setting'] for r in knobs[k] if 'recommended' in r['note'])}"
                                              for k in ("positions", "height_points")))
# positions 11 misses 1% on the real area on this case: it can never be the pick.
assert max(knobs["positions"][0][e] for e in ERRORS) > TOL and "recommended" not in knobs["positions"][0]["note"]

# The aligned table and its "Recommended" line (same rule; times printed to 4 digits).
text = open(f"{tmp}/table.txt").read().splitlines()
assert text[0].split() == ["knob", "setting", "time_s"] + ERRORS + ["note"], text[0]
trows = []
for line in text[1:]:
    if not line.strip():
        break
    # Fixed columns: "{:<15} {:<16} {:>10} {:>16} {:>22} {:>17}  {}" (settings may hold spaces)
    knob, setting, t, e1, e2, e3, note = (line[a:b].strip() for a, b in
                                          ((0, 15), (16, 32), (33, 43), (44, 60), (61, 83), (84, 101), (103, None)))
    trows.append({"knob": knob, "setting": setting, "time_s": float(t), "note": note,
                  **{e: float(v) for e, v in zip(ERRORS, (e1, e2, e3))}})
tknobs = by_knob(trows)
assert {k: [r["setting"] for r in v] for k, v in tknobs.items()} == LADDERS
line = next(l for l in text if l.startswith("Recommended"))
printed = dict(re.findall(r" (\w+) = ([^;]+);", line.split(":", 1)[1]))
noted = {k: r["setting"] for k, v in tknobs.items() if k != "combined" for r in v if "recommended" in r["note"]}
assert printed == noted, (printed, noted)
assert set(printed) == {"positions", "height_points"}, printed
for k, s in printed.items():
    assert s in rule(tknobs[k], TOL, 2e-3), (k, s, rule(tknobs[k], TOL, 2e-3))
print(f"ok   recommendation-line: {line.split(':', 1)[1].strip()}")

# --tolerance 1e-9 on positions: only the reference qualifies; the recommended combination is then
# the all-highest one (zero error), and the case as given is the knob's own 201 row.
tight = by_knob(table(f"{tmp}/tight.csv"))
assert [r["note"] for r in tight["positions"]] == [""] * 7 + ["reference, recommended"], tight["positions"]
comb = {r["setting"]: r for r in tight["combined"]}
assert all(comb["recommended"][e] == 0 for e in ERRORS), comb["recommended"]
row201 = next(r for r in tight["positions"] if r["setting"] == "201")
assert all(comb["case as given"][e] == row201[e] for e in ERRORS), (comb["case as given"], row201)
print("ok   tight-tolerance: reference recommended, combined rows consistent")

# The error metric by hand (tradeoff_command.cpp, curve_error): per output, the largest of the
# differences of the path's minimum, mean (trapezoid over equal steps) and maximum and, where the
# positions coincide, of every position; over the reference's largest magnitude.
def run_table(setting):
    # The run's per-position table at full precision (the HDF5 file; its --csv twin has 10 digits).
    with h5py.File(f"{tmp}/{setting}.h5", "r") as f:
        return {"s_m": [float(x) for x in f["mesh/s_m"][()]],
                **{q: [float(x) for x in f["contact"][q][()]] for q in OUTPUTS}}

def mean(v):
    # The path mean: trapezoid over equal steps, summed in the order of contact::path_mean.
    total = 0.5 * (v[0] + v[-1])
    for x in v[1:-1]:
        total += x
    return total / (len(v) - 1)

def error(run, ref, q, pointwise=True):
    v, w = run[q], ref[q]
    scale = max(abs(x) for x in w)
    worst = max(abs(min(v) - min(w)), abs(max(v) - max(w)), abs(mean(v) - mean(w)))
    if pointwise and run["s_m"] == ref["s_m"]:
        worst = max(worst, max(abs(a - b) for a, b in zip(v, w)))
    return worst / scale if scale > 0 else worst

cases = [("positions", "11", "contact.positions=11", "contact.positions=801"),
         ("height_points", "8", "contact.height_points=8", "contact.height_points=1024"),
         ("height_points", "16", "contact.height_points=16", "contact.height_points=1024"),
         ("asperity_model", "ceb", "asperity.model=ceb", "asperity.model=continuous"),
         ("asperity_model", "hertz", "asperity.model=hertz", "asperity.model=continuous")]
for knob, setting, mine, reference in cases:
    run, ref = run_table(mine), run_table(reference)
    row = next(r for r in knobs[knob] if r["setting"] == setting)
    for q, e in zip(OUTPUTS, ERRORS):
        hand = error(run, ref, q)
        # The tradeoff table prints 10 significant digits.
        assert abs(hand - row[e]) <= 1e-9 * row[e] + 1e-15, (knob, setting, e, hand, row[e])
    print(f"ok   error-by-hand {knob} = {setting}: " + ", ".join(f"{e} {row[e]:.6g}" for e in ERRORS))
# The pointwise term must matter somewhere: at least one of these rows has an error set by one
# position rather than by the path's minimum, mean or maximum (the metric without its pointwise
# term more than 10% lower), so the by-hand agreement above tests that term too.
found = []
for knob, setting, mine, reference in cases[1:]:
    run, ref = run_table(mine), run_table(reference)
    row = next(r for r in knobs[knob] if r["setting"] == setting)
    for q, e in zip(OUTPUTS, ERRORS):
        without = error(run, ref, q, pointwise=False)
        if row[e] > 0 and abs(without - row[e]) > 0.1 * row[e]:
            found.append(f"{knob} = {setting} {e} {row[e]:.6g} (path min/mean/max alone {without:.6g})")
assert found, "no row's error is set pointwise"
print("ok   pointwise-term: " + "; ".join(found))
PY
[[ $fail -eq 0 ]] && echo "ok   tradeoff" || echo "FAIL tradeoff"
exit $fail
