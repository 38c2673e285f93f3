#!/usr/bin/python3
"""Where the answer varies along the path: flank finishes x hardness choices on the seed's pair.

Usage: validation/regimes/run.py path/to/geartrib [--write]

For each finish (README.md: sources and assumptions) and both hardness choices of the 45 steel
(hardness = "tabor-yield", 2.8 S_y, and "flow-curve", Tabor's 2.8 x the flow stress at 0.08), runs
`geartrib run` on gears/m6z30-dry.toml (the seed's dry scene) with the finish's roughness and reads, at the points A..E of
the path, the plasticity index, real-area ratio, plastic area fraction, plastic contact fraction,
separation over summit sigma and the validity flags, and the run's regime. Compares them with
expected.csv (relative 1e-6: the runs are deterministic, the margin covers a libm difference) and
exits 1 on any difference; --write stores the table instead.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Per flank, both flanks alike. Spectral moments (m0 um^2, m2, m4 1/m^2) from the sourced Rq with
# an assumed rms slope and bandwidth (README.md); the seed keeps its own Ra and summit radii.
FINISHES = {
    "seed": [],
    "hobbed": ["pinion.flank.m0=2.25 um^2", "pinion.flank.m2=0.010", "pinion.flank.m4=2.22e8 1/m^2"],
    "ground": ["pinion.flank.m0=0.25 um^2", "pinion.flank.m2=0.0025", "pinion.flank.m4=1.25e8 1/m^2"],
    "run-in": ["pinion.flank.m0=0.64 um^2", "pinion.flank.m2=0.0016", "pinion.flank.m4=2.0e7 1/m^2"],
    "superfinished": ["pinion.flank.m0=0.0064 um^2", "pinion.flank.m2=6.4e-5", "pinion.flank.m4=3.2e6 1/m^2"],
}
HARDNESS = ["tabor-yield", "flow-curve"]
NUMBERS = ["plasticity_index", "real_area_ratio", "plastic_area_fraction", "plastic_contact_fraction",
           "separation_over_summit_sigma", "max_delta_star"]
FLAGS = ["beyond_fitted_range", "beyond_paraboloid", "summits_interact", "deep_separation"]


def scene(tmp, hardness):
    """A copy of the default case whose material takes the hardness choice."""
    os.makedirs(os.path.join(tmp, "gears"), exist_ok=True)
    os.makedirs(os.path.join(tmp, "materials"), exist_ok=True)
    shutil.copy(os.path.join(ROOT, "gears/m6z30-dry.toml"), os.path.join(tmp, "gears/m6z30.toml"))
    with open(os.path.join(ROOT, "materials/steel-45.toml")) as f:
        text = f.read()
    marker = '# hardness = "1.17 GPa"'
    assert marker in text, "materials/steel-45.toml changed: update validation/regimes/run.py"
    with open(os.path.join(tmp, "materials/steel-45.toml"), "w") as f:
        f.write(text.replace(marker, f'hardness = "{hardness}"'))
    return os.path.join(tmp, "gears/m6z30.toml")


def changes(finish):
    out = []
    for c in FINISHES[finish]:
        out += ["--set", c, "--set", c.replace("pinion.", "wheel.", 1)]
    return out


def rows(binary):
    table = []
    with tempfile.TemporaryDirectory() as tmp:
        for hardness in HARDNESS:
            case = scene(os.path.join(tmp, hardness), hardness)
            for finish in FINISHES:
                out = os.path.join(tmp, f"{hardness}-{finish}.h5")
                subprocess.run([binary, "run", case, "-q", "-o", out, *changes(finish)], check=True,
                               stdout=subprocess.DEVNULL)
                with h5py.File(out, "r") as f:
                    s = f["mesh/s_m"][()]
                    v = f["contact/validity"]
                    regime = v.attrs["regime"]
                    regime = regime.decode() if isinstance(regime, bytes) else str(regime)
                    for point in "ABCDE":
                        i = int(np.argmin(np.abs(s - f["mesh"].attrs[f"s_{point}_m"])))
                        row = {"finish": finish, "hardness": hardness, "point": point, "regime": regime}
                        for q in NUMBERS:
                            row[q] = float((v[q] if q in v else f["contact"][q])[i])
                        row["flags"] = " ".join(fl for fl in FLAGS if v["flag_" + fl][i] > 0) or "-"
                        table.append(row)
    return table


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    table = rows(argv[1])
    columns = ["finish", "hardness", "point", "regime", *NUMBERS, "flags"]
    expected_path = os.path.join(HERE, "expected.csv")
    if "--write" in argv:
        with open(expected_path, "w", newline="") as f:
            f.write("# validation/regimes/run.py --write: finishes x hardness at A..E (README.md)\n")
            w = csv.DictWriter(f, fieldnames=columns)
            w.writeheader()
            for r in table:
                w.writerow({k: (f"{r[k]:.9g}" if k in NUMBERS else r[k]) for k in columns})
        print(f"wrote {expected_path}")
        return 0
    with open(expected_path) as f:
        expected = list(csv.DictReader(line for line in f if not line.startswith("#")))
    print(f"{'finish':<14} {'hardness':<11} pt {'regime':<15} {'psi':>8} {'A_r/A_n':>8} {'plastic':>9} "
          f"{'d/sigma_s':>9}  flags")
    bad = 0
    if len(expected) != len(table):
        print(f"DIFFERS: {len(table)} rows against {len(expected)} expected")
        return 1
    for r, e in zip(table, expected):
        ok = all(r[k] == e[k] for k in ("finish", "hardness", "point", "regime", "flags"))
        for q in NUMBERS:
            ok = ok and abs(r[q] - float(e[q])) <= 1e-6 * abs(float(e[q])) + 1e-12
        bad += not ok
        print(f"{r['finish']:<14} {r['hardness']:<11} {r['point']:<2} {r['regime']:<15} {r['plasticity_index']:8.3g} "
              f"{r['real_area_ratio']:8.4f} {r['plastic_area_fraction']:9.4g} {r['separation_over_summit_sigma']:9.3f}  "
              f"{r['flags']}{'' if ok else '   DIFFERS from expected.csv'}")
    print(f"{len(table) - bad} passed, {bad} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
