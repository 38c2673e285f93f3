#!/usr/bin/python3
"""The FZG C40 gear against GEARpie's printed report: a second published implementation.

Usage: validation/gearpie-c40/check.py GEARTRIB [--write]

Runs `geartrib kinematics` (A..E, B and D on the single-pair side) and `geartrib run` on c40.toml
(GEARpie's C40 inputs) and compares the geometry, the loads, the Hertz contact at C and in the
single-pair zone, Ohlendorf's gear loss factor, the Schlenk-law gear-mean friction with the
lubricant factors of Fernandes et al. (2015) and the mesh power loss with the numbers GEARpie
printed (published.csv). Rows against expected.csv (validation/expected_table.py).
(GEARpie's power loss, 206.31 W, is mu_mz x P_in x H_V of the three values compared here: not
compared again.)
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

CASE = os.path.join(HERE, "c40.toml")
SCALE = {"mm": 1e3, "um": 1e6, "MPa": 1e-6, "N": 1.0, "W": 1.0, "1": 1.0}


def table(binary, *args):
    out = subprocess.run([binary, *args], check=True, capture_output=True, text=True, cwd=ROOT).stdout
    return list(csv.DictReader(io.StringIO(out)))


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    summary = {r["name"]: float(r["value"]) for r in table(binary, "kinematics", CASE, "--summary", "--csv")}
    points = {r["point"]: r for r in table(binary, "kinematics", CASE, "--csv")}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "c40.h5")
        subprocess.run([binary, "run", CASE, "-q", "-o", out], check=True, cwd=ROOT, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        with h5py.File(out) as f:
            lub = dict(f["lubrication"].attrs)
    s = {p: float(points[p]["s_m"]) for p in "ABCDE"}
    model = {
        "line_of_action_T1T2": summary["line_of_action_T1T2_m"],
        "segment_AB": s["B"] - s["A"], "segment_AC": s["C"] - s["A"], "segment_AD": s["D"] - s["A"],
        "segment_AE": s["E"] - s["A"],
        "base_pitch": summary["base_pitch_m"], "contact_ratio": summary["contact_ratio"],
        "pinion_base_radius": summary["pinion_base_radius_m"], "wheel_base_radius": summary["wheel_base_radius_m"],
        "pinion_tip_radius": summary["pinion_tip_radius_m"], "wheel_tip_radius": summary["wheel_tip_radius_m"],
        "pinion_root_radius": summary["pinion_root_radius_m"], "wheel_root_radius": summary["wheel_root_radius_m"],
        "normal_load": summary["normal_force_N"],
        "hertz_p0_at_C": float(points["C"]["hertz_p0_Pa"]),
        "hertz_p0_max_single_pair": float(points["B"]["hertz_p0_Pa"]),
        "hertz_halfwidth_at_C": float(points["C"]["hertz_halfwidth_m"]),
        "hertz_halfwidth_max_single_pair": float(points["D"]["hertz_halfwidth_m"]),
        "gear_loss_factor_ohlendorf": float(lub["gear_loss_factor_ohlendorf"]),
        "mean_friction_schlenk_fernandes_xl": float(lub["mean_friction_fernandes"]),
    }
    rows = []
    with open(os.path.join(HERE, "published.csv")) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            value = model[r["name"]] * SCALE[r["unit"]]
            rows.append({"key": "C40", "quantity": f"{r['name']} [{r['unit']}]", "model": value,
                         "reference": float(r["value"]), "tolerance": r["tolerance"], "verdict": "agrees",
                         "regression": "rel 1e-6", "reason": f"GEARpie REPORT/C40.txt: {r['source']}"})
    # Beside them, not compared (GEARpie has none): the model's own gear-mean friction.
    rows.append({"key": "C40", "quantity": "model's gear-mean friction P/(P_in H_V) [1]",
                 "model": float(lub["mesh_mean_friction"]), "reference": None, "regression": "rel 1e-6",
                 "reason": "no reference: GEARpie's 0.0256 is the calibrated Schlenk law (see README)"})
    return expected_table.check(rows, os.path.join(HERE, "expected.csv"), argv, binary,
                                "FZG C40 (c40.toml) against GEARpie's printed C40 report (published.csv)",
                                "validation/gearpie-c40/check.py GEARTRIB --write")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
