#!/usr/bin/python3
"""The ladder on the same flanks: GW, Persson, the profile and the areal fidelities against the areal
fidelity at its finest settings, as `geartrib tradeoff --knob ladder` measures it, on the shipped areal
case (gears/m6z30-areal.toml: isotropic ground flanks, Rq 0.3 um, correlation 10 um, A..E) in 45 steel
(98 % of the real area yielded) and in 16MnCr5 (14-39 % yielded).

Usage: validation/areal-ladder/check.py path/to/geartrib [--write]

For each material: the tradeoff's ladder (--min-time 0: one run a rung), and three `geartrib run`s
beside it: the reference (contact.element_size 0.25 um, areal.points 256, areal.tolerance 1e-8: the
finest the case allows, the 0.125 um elements' map being refused), the case as given (the areal
fidelity, GW and Persson beside it) and the profile fidelity (contact.fidelity = deterministic).
Asserted (README.md): the tradeoff names that reference; its errors of GW, Persson, the profile
fidelity and the areal case equal those recomputed here from the runs' HDF5 by the table's metric;
the real area's mean error over the positions against the ladder measured by hand
(docs/guide/contact.md, the previous session); every rung's three errors and its verdict as stored.
The times are reported by the table, not asserted (a benchmark's business: geartrib_bench
cycle_areal). About 3 minutes of CPU (CTest label long).
Exits 1 when any row is not as expected (expected.csv); --write stores the model column.
"""
import csv
import io
import os
import subprocess
import sys
import tempfile

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

CASE = "gears/m6z30-areal.toml"
MATERIALS = ["steel-45", "16MnCr5"]
REFERENCE = ["--set", "contact.element_size=0.25um", "--set", "areal.points=256", "--set", "areal.tolerance=1e-8"]
REFERENCE_NAMED = "element_size 0.25 um, points 256, tolerance 1e-8"
ERRORS = ["error_real_area", "error_plastic_fraction", "error_peak_stress"]
# The rungs recomputed from the runs: (the run, its three series; "" where the model has none).
RECOMPUTED = {
    "GW (statistical)": ("case", ["statistical/statistical_real_area_ratio",
                                  "statistical/statistical_plastic_area_fraction",
                                  "statistical/statistical_max_asperity_von_mises_Pa"]),
    "Persson": ("case", ["statistical/statistical_persson_real_area_ratio",
                         "statistical/statistical_persson_plastic_area_fraction", ""]),
    "profile BEM": ("profile", ["contact/real_area_ratio", "contact/plastic_area_fraction",
                                "contact/max_von_mises_Pa"]),
    "areal (case)": ("case", ["contact/real_area_ratio", "contact/plastic_area_fraction", "contact/max_von_mises_Pa"]),
}
OWN = ["contact/real_area_ratio", "contact/plastic_area_fraction", "contact/max_von_mises_Pa"]
# The ladder measured by hand (docs/guide/contact.md, "The ladder on the same flanks", before this
# case): the real area's mean error over the five positions against the areal fidelity at 0.25 um x
# 256 points (tolerance 1e-6), each position's relative error averaged. GW on 16MnCr5 was quoted as
# "7.0 % (-9 to +8 %)": its range is reproduced, its 7.0 % is not (README.md).
HAND = {
    ("steel-45", "areal (case)"): 0.003, ("steel-45", "GW (statistical)"): 0.017,
    ("steel-45", "Persson"): -0.010, ("steel-45", "profile BEM"): 0.07,
    ("16MnCr5", "areal (case)"): 0.024, ("16MnCr5", "Persson"): -0.29, ("16MnCr5", "profile BEM"): 0.78,
}
HAND_RANGE = {("16MnCr5", "GW (statistical)"): (-0.09, 0.08)}
HAND_DEPARTS = {("16MnCr5", "GW (statistical)"): 0.070}
AGREES = "the ladder measured by hand (docs/guide/contact.md) to its quoted digits: one point (its reference at " \
         "tolerance 1e-6, this one at 1e-8)"


def materials(name):
    return ["--set", f"pinion.material=../materials/{name}.toml", "--set", f"wheel.material=../materials/{name}.toml"]


def path_mean(v):
    """The trapezoid over equal steps (contact::path_mean)."""
    return (0.5 * (v[0] + v[-1]) + sum(v[1:-1])) / (len(v) - 1)


def curve_error(v, ref):
    """The tradeoff's metric on the same positions: the largest difference of the minimum, mean, maximum
    and of any position, over the reference's largest magnitude (src/app/tradeoff_command.cpp)."""
    scale = max(abs(x) for x in ref)
    worst = max(abs(min(v) - min(ref)), abs(max(v) - max(ref)), abs(path_mean(v) - path_mean(ref)),
                max(abs(a - b) for a, b in zip(v, ref)))
    return worst / scale if scale > 0 else worst


def series(path, name):
    with h5py.File(path, "r") as f:
        return [float(x) for x in f[name][()]]


def ladder(binary, material, tmp):
    """The tradeoff's ladder rows (the CSV) and its printed text."""
    table = os.path.join(tmp, f"{material}-ladder.csv")
    text = subprocess.run([binary, "tradeoff", CASE, *materials(material), "--knob", "ladder", "--min-time", "0", "-q",
                           "--csv", table], cwd=ROOT, check=True, capture_output=True, text=True).stdout
    with open(table) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [r for r in rows if r["knob"] == "ladder"], text


def run(binary, material, extra, path):
    subprocess.run([binary, "run", CASE, *materials(material), *extra, "-q", "-o", path], cwd=ROOT, check=True,
                   capture_output=True)


def main():
    binary = expected_table.binary_argument(sys.argv, __doc__)
    if binary is None:
        return 2
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for material in MATERIALS:
            table, text = ladder(binary, material, tmp)
            runs = {name: os.path.join(tmp, f"{material}-{name}.h5") for name in ("reference", "case", "profile")}
            run(binary, material, REFERENCE, runs["reference"])
            run(binary, material, [], runs["case"])
            run(binary, material, ["--set", "contact.fidelity=deterministic", "--set", "contact.threads=1"],
                runs["profile"])
            ref = [series(runs["reference"], q) for q in OWN]
            by_rung = {r["setting"]: r for r in table}
            rows.append({"key": f"{material}/ladder", "quantity": "reference named",
                         "model": f"the areal fidelity at {REFERENCE_NAMED}" in text, "reference": None,
                         "regression": "=", "reason": "the finest settings the case allows: 0.125 um elements' "
                                                      "maps (193598 x 256 points) are refused"})
            for rung, r in by_rung.items():
                key = f"{material}/{rung}"
                for e in ERRORS:
                    value = float(r[e])
                    rows.append({"key": key, "quantity": e, "model": "-" if value != value else value,
                                 "reference": None, "regression": "0.002",
                                 "reason": "the tradeoff's error against the reference (0.2 points of drift allowed)"})
                rows.append({"key": key, "quantity": "verdict", "model": r["note"].split(" (")[0],
                             "reference": None, "regression": "=",
                             "reason": "where the rung holds: within --ladder-tolerance (10 %) on every output it has"})
            for rung, (name, names) in RECOMPUTED.items():
                key = f"{material}/{rung}"
                mine = [series(runs[name], q) if q else None for q in names]
                same = all((m is None and by_rung[rung][e] == "nan") or
                           (m is not None and abs(curve_error(m, w) - float(by_rung[rung][e])) <=
                            1e-6 * max(float(by_rung[rung][e]), 1e-12))
                           for m, w, e in zip(mine, ref, ERRORS))
                rows.append({"key": key, "quantity": "errors recomputed", "model": same, "reference": None,
                             "regression": "=",
                             "reason": "the three errors recomputed from `geartrib run`'s HDF5 of the rung and of the "
                                       "reference by the table's metric, to 1e-6: the same flanks, the same reference"})
                relative = [a / b - 1.0 for a, b in zip(mine[0], ref[0])]
                hand = (material, rung)
                if hand in HAND:
                    rows.append({"key": key, "quantity": "real area mean error", "model": sum(relative) / len(relative),
                                 "reference": HAND[hand], "tolerance": "0.01", "verdict": "agrees",
                                 "regression": "0.002", "reason": AGREES})
                for quantity, value, bound in zip(("real area error min", "real area error max"),
                                                  (min(relative), max(relative)), HAND_RANGE.get(hand, ())):
                    rows.append({"key": key, "quantity": quantity, "model": value, "reference": bound,
                                 "tolerance": "0.01", "verdict": "agrees", "regression": "0.002", "reason": AGREES})
                if hand in HAND_DEPARTS:
                    rows.append({"key": key, "quantity": "real area mean error (magnitude)",
                                 "model": sum(abs(x) for x in relative) / len(relative), "reference": HAND_DEPARTS[hand],
                                 "tolerance": "0.01", "verdict": "departs", "regression": "0.002",
                                 "reason": "the hand's 7.0 % is not reproduced: the errors' mean magnitude is 5.7 %, "
                                           "their mean -2.7 %, their rms 6.6 % (README.md); its range is (the min and max rows)"})
    return expected_table.check(rows, os.path.join(HERE, "expected.csv"), sys.argv, binary,
                                "the ladder on the same flanks (geartrib tradeoff --knob ladder) on gears/m6z30-areal.toml",
                                "validation/areal-ladder/check.py build/geartrib")


if __name__ == "__main__":
    sys.exit(main())
