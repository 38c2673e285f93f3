#!/usr/bin/python3
"""The areal boundary elements' elastic area-load curve against published GFMD data.

Usage: validation/areal-gfmd/check.py path/to/geartrib [--write] [--points N] [--seeds K]

Generates self-affine surfaces with the reference's spectrum (README.md: H = 0.8, no roll-off,
q_s = 100 q_L; `geartrib surface generate self-affine`), 1024^2 points by default (lambda_s = 10.24
spacings), K = 2 seeds, runs `geartrib contact` elastic at the reference's loads p/(E* g) (g each
surface's own spectral rms gradient) and compares the realisations' mean contact fraction with the
GFMD series Zhou2023 (Xu, Zhu, Xiao & Zhou 2024) where it lies between 1 % and 90 % contact: within
8 % (the issue's bound; the two GFMD series themselves differ by 1-5 %, the realisations by about
1 %). Persson's elastic theory (geartrib's column) is stored beside it: it reads 25-30 % low at
small loads (a documented departure of the theory, not of the solver).

About 3 minutes at 1024^2 (CTest label long). --points 512 is a quicker look (not the stored table).
Exits 1 when any row is not as expected (expected.csv); --write stores the model column.
"""
import csv
import io
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

ESTAR = 1e11  # [Pa]: any (the area depends on p/(E* g) alone)
SERIES = "H0.8_qs100qL_GFMD_Zhou2023"


def reference():
    with open(os.path.join(HERE, "reference.csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [(float(r["pressure_over_Estar_g"]), float(r["area_fraction"])) for r in rows if r["series"] == SERIES]


def option(argv, name, default):
    return int(argv[argv.index(name) + 1]) if name in argv else default


def spectral_gradient(z, dx):
    """sqrt(<|grad z|^2>) of a periodic grid by its Fourier transform (the Nyquist bins left out)."""
    ny, nx = z.shape
    zh = np.fft.fft2(z) / z.size
    qx = 2 * np.pi * np.fft.fftfreq(nx, dx)
    qy = 2 * np.pi * np.fft.fftfreq(ny, dx)
    q2 = qx[None, :] ** 2 + qy[:, None] ** 2
    q2[:, nx // 2] = 0
    q2[ny // 2, :] = 0
    return float(np.sqrt(np.sum(q2 * np.abs(zh) ** 2)))


def main():
    binary = expected_table.binary_argument(sys.argv, __doc__)
    if binary is None:
        return 2
    n = option(sys.argv, "--points", 1024)
    seeds = option(sys.argv, "--seeds", 2)
    ref = reference()
    area = np.zeros(len(ref))
    persson = np.zeros(len(ref))
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, seeds + 1):
            surface = os.path.join(tmp, f"s{seed}.h5")
            length = n * 1e-6
            subprocess.run([binary, "surface", "generate", "self-affine", "-o", surface, "--nx", str(n), "--ny", str(n),
                            "--spacing", "1um", "--rq", "1um", "--hurst", "0.8", "--rolloff", f"{length!r}m",
                            "--short-cutoff", f"{length / 100!r}m", "--seed", str(seed)], check=True)
            with h5py.File(surface, "r") as f:
                g = spectral_gradient(f["z"][:], 1e-6)
            pressures = ",".join(f"{x * ESTAR * g!r}Pa" for x, _ in ref)
            out = subprocess.run([binary, "contact", surface, "--form", "0", "--modulus", f"{ESTAR}Pa", "--hardness",
                                  "none", "--pressure", pressures, "--csv"], check=True, capture_output=True,
                                 text=True).stdout
            rows = list(csv.DictReader(io.StringIO(out)))
            area += np.array([float(r["contact_fraction"]) for r in rows]) / seeds
            persson += np.array([float(r["persson_contact_fraction"]) for r in rows]) / seeds
    if n != 1024 or seeds != 2:
        for (x, a), m, pe in zip(ref, area, persson):
            print(f"p/(E* g) = {x:.4g}: GFMD {a:.4f}, geartrib {m:.4f} ({(m / a - 1) * 100:+.1f} %), Persson {pe:.4f}")
        print("(not the stored table's grid: nothing asserted)")
        return 0
    rows = []
    for (x, a), m, pe in zip(ref, area, persson):
        key = f"p/(E*g)={x:.6g}"
        inside = 0.01 <= a <= 0.90
        rows.append({"key": key, "quantity": "contact_fraction", "model": float(m), "reference": a,
                     "tolerance": "8%" if inside else "", "verdict": "agrees" if inside else "regression",
                     "regression": "rel 1e-3",
                     "reason": "GFMD (Zhou 2023, Xu et al. 2024): the issue's 8 % from 1 to 90 % contact, 1024^2, "
                               "two realisations" if inside else "outside 1-90 % contact: stored, not asserted"})
        rows.append({"key": key, "quantity": "persson_contact_fraction", "model": float(pe), "reference": a,
                     "tolerance": "", "verdict": "regression", "regression": "rel 1e-3",
                     "reason": "Persson's elastic theory on the surfaces' g, beside the data: 25-30 % low at small "
                               "loads (kappa 1.60 against about 2.3), the theory's known departure"})
    return expected_table.check(rows, os.path.join(HERE, "expected.csv"), sys.argv, binary,
                                "areal boundary elements' elastic area-load curve against GFMD (Zhou 2023)",
                                "validation/areal-gfmd/check.py build/geartrib")


if __name__ == "__main__":
    sys.exit(main())
