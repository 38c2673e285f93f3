#!/usr/bin/python3
"""The deterministic fidelity on the seed's pair (gears/m6z30-deterministic.toml, dry): smooth flanks
against Hertz at every position, the deterministic answer beside the statistical model on the same
generated ground and hobbed flanks, and running-in on both finishes against the trends the
literature reports (README.md).

Usage: validation/deterministic-m6z30/check.py GEARTRIB [--write]
Runs `geartrib run` five times (about 30 s on two cores) and checks the rows against expected.csv
(validation/expected_table.py).
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import expected_table  # noqa: E402

CASE = "gears/m6z30-deterministic.toml"
SMOOTH = ["pinion.flank.profile.kind=smooth", "wheel.flank.profile.kind=smooth"]
# Hobbed flanks (assumed, README): generating-cut ridges 80 um apart of 250 um tip radius (3.2 um
# deep: Ra ~ 0.8 um, the seed's hobbed finish) with a fine random part of Rq 0.15 um.
HOBBED = [f"{g}.flank.profile.{k}" for g in ("pinion", "wheel") for k in
          ("kind=hobbed", "ridge_spacing=80um", "ridge_radius=250um", "rq=0.15um", "correlation_length=5um")]
# Running-in: 101 positions on 1 um elements (the trends, not the last digit), until shakedown at
# 2 nm or 100 meshes.
RUNNING_IN = ["contact.positions=101", "contact.element_size=1um", "running_in.meshes=100", "running_in.tolerance=2nm"]
# Hertz line contact, plane strain, nu = 0.3 (McEwen 1949; Johnson, Contact Mechanics, eq. 4.49):
# the von Mises maximum below the centre, computed from the closed-form stresses on the axis.
VM_OVER_P0, VM_DEPTH_OVER_B = 0.5575162, 0.7042880


def run(binary, tmp, name, sets):
    out = os.path.join(tmp, name)
    subprocess.run([binary, "run", CASE, *sum((["--set", s] for s in sets), []), "-q", "-o", out + ".h5",
                    "--csv", out + ".csv"], check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    with open(out + ".csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    cols = {k: [float(r[k]) for r in rows] for k in rows[0]}
    history = None
    try:
        import h5py
        with h5py.File(out + ".h5", "r") as h:
            if "running_in" in h:
                g = h["running_in"]
                history = {k: g[k][()] for k in g if g[k].ndim == 1 and len(g[k]) == len(g["mesh"])}
                history["shakedown_mesh"] = int(g.attrs["shakedown_mesh"])
                history["meshes"] = int(g.attrs["meshes"])
    except ImportError:
        sys.exit("needs python3-h5py")
    return cols, history


def mean(v):
    """The path mean (trapezoid over the evenly spaced positions), as geartrib's path_mean."""
    return (0.5 * (v[0] + v[-1]) + sum(v[1:-1])) / (len(v) - 1)


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    rows = []

    def row(key, quantity, model, reference=None, **kw):
        rows.append({"key": key, "quantity": quantity, "model": model, "reference": reference, **kw})

    with tempfile.TemporaryDirectory() as tmp:
        smooth, _ = run(binary, tmp, "smooth", SMOOTH)
        finishes = {"ground": run(binary, tmp, "ground", [])[0], "hobbed": run(binary, tmp, "hobbed", HOBBED)[0]}
        run_in = {"ground": run(binary, tmp, "ground-run-in", RUNNING_IN)[1],
                  "hobbed": run(binary, tmp, "hobbed-run-in", HOBBED + RUNNING_IN)[1]}

    # 1. Smooth flanks: Hertz at every position (element 0.5 um).
    e = 0.5e-6
    p_err = max(abs(p / p0 - 1) for p, p0 in zip(smooth["max_pressure_Pa"], smooth["hertz_p0_Pa"]))
    b_err = max(abs(a - b) / e for a, b in zip(smooth["contact_halfwidth_m"], smooth["hertz_halfwidth_m"]))
    vm = max(v / p0 for v, p0 in zip(smooth["max_von_mises_Pa"], smooth["hertz_p0_Pa"]))
    depth = [z / b for z, b in zip(smooth["max_von_mises_depth_m"], smooth["hertz_halfwidth_m"])]
    row("smooth", "max |p_max/p0 - 1| over 201 positions [1]", p_err, 0.0)
    row("smooth", "max |a - b| over 201 positions [elements]", b_err, 0.0)
    row("smooth", "max von Mises / p0 [1]", vm, VM_OVER_P0)
    row("smooth", "von Mises depth / b, min over the path [1]", min(depth), VM_DEPTH_OVER_B)
    row("smooth", "von Mises depth / b, max over the path [1]", max(depth), VM_DEPTH_OVER_B)
    row("smooth", "plastic area fraction, max [1]", max(smooth["plastic_area_fraction"]), 0.0)

    # 2. Deterministic beside statistical on the same flanks (path means and extremes).
    pairs = [("real_area_ratio", "statistical_real_area_ratio", "real-area ratio"),
             ("plastic_area_fraction", "statistical_plastic_area_fraction", "plastic area fraction"),
             ("mean_real_pressure_Pa", "statistical_mean_real_pressure_Pa", "mean real pressure [Pa]")]
    for name, c in finishes.items():
        for det, stat, label in pairs:
            row(name, f"deterministic {label}, path mean", mean(c[det]))
            row(name, f"statistical {label}, path mean", mean(c[stat]))
        row(name, "deterministic peak pressure / hardness, max [1]", max(c["max_pressure_Pa"]) / 1.1704e9)
        row(name, "statistical highest-asperity pressure / hardness, max [1]",
            max(c["statistical_max_asperity_pressure_Pa"]) / 1.1704e9)
        row(name, "deterministic contact spots, path mean [1]", mean(c["contact_spots"]))
        row(name, "deterministic von Mises max / Hertz p0 at C [1]",
            c["max_von_mises_Pa"][100] / c["hertz_p0_Pa"][100])
        row(name, "positions with the strip's ends loaded [1]", sum(c["flag_strip_edge_loaded"]))

    # 3. Running-in: the literature's trends (README), then the values as a regression.
    for name, h in run_in.items():
        first, last = 0, len(h["mesh"]) - 1
        for g in ("pinion", "wheel"):
            row(f"{name} run-in", f"{g} Rq falls [bool]", bool(h[f"{g}_rq_m"][last] < h[f"{g}_rq_m"][first]), True)
            row(f"{name} run-in", f"{g} peaks flattened: mean peak height falls [bool]",
                bool(h[f"{g}_peak_height_m"][last] < h[f"{g}_peak_height_m"][first]), True)
            if name == "ground":  # a Gaussian flank (Rsk ~ 0) turns negatively skewed
                row(f"{name} run-in", f"{g} skewness falls and ends negative [bool]",
                    bool(h[f"{g}_rsk"][last] < h[f"{g}_rsk"][first] - 0.05 and h[f"{g}_rsk"][last] < 0), True)
            else:  # the ridges' valleys make it negative from the start (-0.64 for pure parabolas): it stays so
                row(f"{name} run-in", f"{g} skewness stays negative [bool]", bool(max(h[f"{g}_rsk"]) < 0), True)
            row(f"{name} run-in", f"{g} Rq final / initial [1]", h[f"{g}_rq_m"][last] / h[f"{g}_rq_m"][first])
            row(f"{name} run-in", f"{g} mean peak height final / initial [1]",
                h[f"{g}_peak_height_m"][last] / h[f"{g}_peak_height_m"][first])
            row(f"{name} run-in", f"{g} Rsk initial [1]", h[f"{g}_rsk"][first])
            row(f"{name} run-in", f"{g} Rsk final [1]", h[f"{g}_rsk"][last])
        plastic = h["plastic_area_fraction_mean"]
        new = h["new_plastic_deformation_m"]
        row(f"{name} run-in", "new plastic deformation, last mesh < first / 100 [bool]",
            bool(new[last] < new[1] / 100), True)
        row(f"{name} run-in", "meshes whose new plastic deformation rose [1]",
            sum(b > a for a, b in zip(new[1:], new[2:])))
        row(f"{name} run-in", "later meshes elastic: plastic fraction last < first / 5 [bool]",
            bool(plastic[last] < plastic[1] / 5), True)
        row(f"{name} run-in", "shakedown reached [bool]", h["shakedown_mesh"] > 0, True)
        row(f"{name} run-in", "meshes to shakedown [1]", h["shakedown_mesh"])
        row(f"{name} run-in", "plastic area fraction, first mesh [1]", plastic[1])
        row(f"{name} run-in", "plastic area fraction, last mesh [1]", plastic[last])
        row(f"{name} run-in", "real-area ratio last / first mesh [1]",
            h["real_area_ratio_mean"][last] / h["real_area_ratio_mean"][1])
    return expected_table.check(
        rows, os.path.join(HERE, "expected.csv"), argv, binary,
        "gears/m6z30-deterministic.toml (dry): smooth vs Hertz; deterministic vs statistical on generated ground "
        "and hobbed flanks; running-in of both",
        "validation/deterministic-m6z30/check.py build/geartrib --write")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
