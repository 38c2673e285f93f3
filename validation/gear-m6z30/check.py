#!/usr/bin/python3
"""The seed's reference pair at A..E and along the path, checked against expected.csv.

Usage: validation/gear-m6z30/check.py path/to/geartrib [--write]

Runs tabulate.sh (the kinematics summary, A..E with ISO and stiffness load sharing, the load share
at 21 positions with both) and checks each value against expected.csv (README.md, "What is
asserted"): the geometry, Hertz and speed values against the hand computation to a relative 1e-6,
the mesh stiffness within 30% of ISO 6336-1's c_gamma_alpha, every value against its stored model
value to a relative 1e-6 (load sharing by tooth stiffness has no published value: regression).
Exits 1 when any row is not as expected; --write stores the model column instead.
"""
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import expected_table  # noqa: E402

# Columns of `kinematics --csv` that depend on the load-sharing method; the others are the same
# geometry and speeds under both methods (checked under iso, asserted equal under stiffness).
SHARED = ("load_share", "line_load_N_per_m", "hertz_p0_Pa", "hertz_halfwidth_m")


def read(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def rows_of(folder):
    rows = [{"key": "summary", "quantity": r["name"], "model": float(r["value"]), "reference": None}
            for r in read(os.path.join(folder, "summary.csv"))]
    points = {m: read(os.path.join(folder, f"points-{m}.csv")) for m in ("iso", "stiffness")}
    for r in points["iso"]:
        rows += [{"key": f"iso {r['point']}", "quantity": q, "model": float(v), "reference": None}
                 for q, v in r.items() if q != "point"]
    for r, iso in zip(points["stiffness"], points["iso"]):
        rows += [{"key": f"stiffness {r['point']}", "quantity": q, "model": float(r[q]), "reference": None} for q in SHARED]
        same = all(r[q] == iso[q] for q in r if q not in SHARED)
        rows.append({"key": f"stiffness {r['point']}", "quantity": "other columns as under iso", "model": same,
                     "reference": None})
    for m in ("iso", "stiffness"):
        for r in read(os.path.join(folder, f"path-{m}.csv")):
            rows.append({"key": f"{m} path {int(r['point']):02d}", "quantity": "load_share",
                         "model": float(r["load_share"]), "reference": None})
    return rows


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(["bash", os.path.join(HERE, "tabulate.sh"), binary], check=True, cwd=ROOT,
                       env={**os.environ, "OUT": tmp}, stdout=subprocess.DEVNULL)
        rows = rows_of(tmp)
    return expected_table.check(
        rows, os.path.join(HERE, "expected.csv"), argv, binary,
        "gears/m6z30.toml along the line of action: summary, A..E (iso, stiffness), load share at 21 positions",
        "validation/gear-m6z30/check.py GEARTRIB --write (runs tabulate.sh: geartrib kinematics gears/m6z30.toml "
        "--summary --csv; --load-sharing iso|stiffness --csv; the same with --positions 21)")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
