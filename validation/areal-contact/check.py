#!/usr/bin/python3
"""Areal FFT boundary elements (`geartrib contact`) against exact solutions and a hand calculation.

Usage: validation/areal-contact/check.py path/to/geartrib [--write]

Writes each surface as an HDF5 height map, runs `geartrib contact` on it and compares with
hand/hand_calc.py: an independent calculation from the published closed forms (each checked there
by a second route: quadrature of the Green's functions, finite differences of Persson's diffusion
equation), written by a helper who did not read geartrib's code (hand/README.md).

  westergaard  z = Delta cos(2 pi x/lambda), periodic, 512 elements a wavelength: the contact
               fraction and the peak pressure at pbar/p* = 0.1, 0.3, 0.6, 0.9 (Westergaard 1939).
  bisinusoid   z = Delta cos cos, periodic, 256^2: complete contact from p* = sqrt 2 pi E* Delta/lambda
               and the exact field above it (Johnson, Greenwood & Higginson 1985); the light-load
               (Hertz per peak) and near-complete asymptotes with their stated accuracy.
  hertz3d      a sphere (R = 10 mm, E* = 115.4 GPa, 10 N) on an open (zero-padded) window: a, p0,
               the approach, and the largest von Mises stress under it and its depth (nu = 0.3).
  plastic      a random surface with H/(E* h'_rms) ~ 1e-5: the contact is the bearing area, A/A0 = pbar/H.
  persson      Persson's areas `geartrib contact` prints beside the solver (the elastic theory's erf, the
               elastic-plastic series) against the hand calculation's finite-difference solution of the
               diffusion equation, on the bisinusoid's exact rms gradient.
Grid convergence: the Westergaard and Hertz rows state their tolerance in elements. Exits 1 when
any row is not as expected (expected.csv); --write stores the model column.
"""
import csv
import io
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

ESTAR = 115.4e9  # [Pa], the hand calculation's Hertz modulus


def hand():
    out = subprocess.run([sys.executable, os.path.join(HERE, "hand", "hand_calc.py")], check=True, cwd=ROOT,
                         capture_output=True, text=True).stdout
    return {(r["case"], r["quantity"], r["x"]): float(r["value"]) for r in csv.DictReader(io.StringIO(out))}


def write_surface(path, z, dx, dy):
    with h5py.File(path, "w") as f:
        d = f.create_dataset("z", data=z)
        d.attrs["dx"] = dx
        d.attrs["dy"] = dy


def contact(binary, surface, *args):
    """The curve's rows (dicts) and the HDF5 result of one `geartrib contact` run."""
    result = surface + ".out.h5"
    cmd = [binary, "contact", surface, "--form", "0", "--modulus", f"{ESTAR} Pa", "--csv", "-o", result, *args]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(io.StringIO(out))]
    return rows, h5py.File(result, "r")


def main():
    binary = expected_table.binary_argument(sys.argv, __doc__)
    if binary is None:
        return 2
    ref = hand()
    rows = []

    def row(key, quantity, model, reference, tolerance, reason, regression="rel 1e-6"):
        """A row; `regression`: how far the model may move from its stored value (a count of elements
        may change by one where another machine's transforms round otherwise)."""
        rows.append({"key": key, "quantity": quantity, "model": model, "reference": reference,
                     "tolerance": tolerance, "verdict": "agrees", "regression": regression, "reason": reason})

    with tempfile.TemporaryDirectory() as tmp:
        # Westergaard: one wavelength of 512 elements, 8 rows across (uniform along y).
        n, lam, delta = 512, 100e-6, 0.5e-6
        s = lam / n
        x = np.arange(n) * s
        path = os.path.join(tmp, "wave.h5")
        write_surface(path, np.tile(delta * np.cos(2 * np.pi * x / lam), (8, 1)), s, s)
        p_star = math.pi * ESTAR * delta / lam
        for r in (0.1, 0.3, 0.6, 0.9):
            curve, f = contact(binary, path, "--pressure", f"{r * p_star!r} Pa", "--hardness", "none")
            row("westergaard", f"contact_fraction@pbar/p*={r}", curve[0]["contact_fraction"],
                ref[("westergaard", "contact_fraction_2a/lambda", f"{r:g}")], f"{2.5 / n:.6g}",
                "Westergaard 1939 (hand_calc.py): +-1 element at each edge of the contact (512 a wavelength)",
                f"{2.0 / n:.6g}")
            if r >= 0.3:
                p0 = f["fields/pressure_Pa"][0, 0] / p_star
                row("westergaard", f"p(0)/p*@pbar/p*={r}", p0, ref[("westergaard", f"p/p*@pbar/p*={r:g}", "0")], "0.5%",
                    "the field's peak; the discrete pressure at the crest, 0.5 % at 512 elements a wavelength")
            f.close()

        # The bisinusoid on 256^2 (one wavelength), complete contact and its asymptotes.
        n, lam, delta = 256, 100e-6, 0.2e-6
        s = lam / n
        c = np.cos(2 * np.pi * np.arange(n) / n)
        z = delta * np.outer(c, c)
        path = os.path.join(tmp, "bisin.h5")
        write_surface(path, z, s, s)
        p_star = math.sqrt(2) * math.pi * ESTAR * delta / lam
        row("bisinusoid", "pstar/(Estar*Delta/lambda)", p_star / (ESTAR * delta / lam),
            ref[("bisinusoid", "pstar/(Estar*Delta/lambda)", "")], "rel 1e-9", "JGH 1985 (the hand's closed form)")
        for r in (1.5, 2.0):
            curve, f = contact(binary, path, "--pressure", f"{r * p_star!r} Pa", "--hardness", "none")
            row("bisinusoid", f"contact_fraction@pbar/p*={r}", curve[0]["contact_fraction"], 1.0, "=",
                "complete contact above p* (JGH 1985)")
            row("bisinusoid", f"peak_pressure/p*@pbar/p*={r}", curve[0]["peak_pressure_Pa"] / p_star,
                ref[("bisinusoid", f"p/p*@pbar/p*={r:g};y/lambda=0", "0")], "rel 1e-6",
                "above p* the field is pbar + p* cos cos exactly; 1e-6 for the iteration's tolerance")
            f.close()
        for r in (0.9, 0.95, 0.98):
            curve, f = contact(binary, path, "--pressure", f"{r * p_star!r} Pa", "--hardness", "none")
            row("bisinusoid", f"noncontact_fraction@pbar/p*={r}", 1.0 - curve[0]["contact_fraction"],
                ref[("bisinusoid", "noncontact_fraction_(1-A/A0)_asymptote", f"{r:g}")], "15%",
                "JGH's near-complete asymptote (the holes penny cracks): +3, +1.5, +0.6 % its own error (hand README), "
                "and the holes 6 to 10 elements across on the grid", f"{8.0 / n ** 2:.6g}")
            f.close()
        for r in (0.003, 0.01):
            curve, f = contact(binary, path, "--pressure", f"{r * p_star!r} Pa", "--hardness", "none")
            row("bisinusoid", f"contact_fraction@pbar/p*={r}", curve[0]["contact_fraction"],
                ref[("bisinusoid", "A/A0_hertz_asymptote", f"{r:g}")], "10%",
                "Hertz per peak (two a cell): +1.3 and +2.8 % its own error (hand README); the spots 5 to 8 elements "
                "in radius", f"{8.0 / n ** 2:.6g}")
            f.close()

        # Persson's columns on the bisinusoid's exact gradient: |grad z|^2 = Delta^2 k^2 (sin^2 cos^2 +
        # cos^2 sin^2), whose mean is Delta^2 k^2/2 (k = 2 pi/lambda).
        g = delta * 2 * math.pi / lam / math.sqrt(2)
        for r in (0.05, 0.2, 0.8):
            curve, f = contact(binary, path, "--pressure", f"{r * ESTAR * g!r} Pa", "--hardness", "none")
            row("persson", f"elastic_area@pbar/(E*g)={r}", curve[0]["persson_contact_fraction"],
                ref[("persson_elastic", "A/A0_finite_difference", f"{r:g}")], "2e-6",
                "the hand's finite differences of the diffusion equation: 2.1e-7 from the erf (hand README), x10")
            f.close()
        for h_ratio, r in ((1.0, 0.1), (1.0, 0.4), (2.0, 0.1), (0.5, 0.04)):
            hardness = h_ratio * ESTAR * g
            curve, f = contact(binary, path, "--pressure", f"{r * ESTAR * g!r} Pa", "--hardness", f"{hardness!r} Pa")
            el = curve[0]["persson_contact_fraction"] - curve[0]["persson_plastic_fraction"]
            key = f"@H/(Estar*hrms')={h_ratio:g}"
            row("persson", f"elastic_area@H/(E*g)={h_ratio},pbar/(E*g)={r}", el,
                ref[("persson_plastic", "A_el/A0_finite_difference" + key, f"{r:g}")], "3e-6",
                "the hand's finite differences with P(H) = 0: 3.2e-7 from the series (hand README), x10")
            row("persson", f"plastic_area@H/(E*g)={h_ratio},pbar/(E*g)={r}", curve[0]["persson_plastic_fraction"],
                ref[("persson_plastic", "A_pl/A0_finite_difference" + key, f"{r:g}")], "3e-6",
                "as the elastic share")
            f.close()

        # Hertz's sphere on an open window: 10 N, 24 elements across the radius, the window 6 radii.
        r_s, load, nu = 10e-3, 10.0, 0.3
        a = ref[("hertz3d", "contact_radius_a[mm]", "10")] * 1e-3
        p0 = ref[("hertz3d", "max_pressure_p0[MPa]", "10")] * 1e6
        n = 144
        s = a / 24
        xs = (np.arange(n) - n // 2) * s
        z = -(xs[None, :] ** 2 + xs[:, None] ** 2) / (2 * r_s)
        path = os.path.join(tmp, "sphere.h5")
        write_surface(path, z, s, s)
        depths = ",".join(f"{d * a!r}m" for d in np.arange(0.40, 0.561, 0.02))
        curve, f = contact(binary, path, "--pressure", f"{load / (n * s) ** 2!r} Pa", "--hardness", "none",
                           "--periodic", "none", "--depths", depths, "--poisson", f"{nu}")
        c0 = curve[0]
        row("hertz3d", "contact_radius/a", math.sqrt(c0["contact_fraction"] * (n * s) ** 2 / math.pi) / (a * 1e0), 1.0,
            "3%", "Hertz (hand); the contact's edge to +-1/2 element of 24 across the radius", "rel 1e-3")
        row("hertz3d", "p0[MPa]", c0["peak_pressure_Pa"] * 1e-6, p0 * 1e-6, "1%",
            "Hertz (hand); the element at the centre, 24 a radius")
        row("hertz3d", "approach[um]", c0["approach_m"] * 1e6, ref[("hertz3d", "approach_delta[um]", "10")], "1%",
            "Hertz (hand); the open window's absolute displacement (Love's elements, DC-FFT)")
        vm = f["stress/max_von_mises_Pa"][:]
        k = int(np.argmax(vm))
        row("hertz3d", "max_von_mises/p0", vm[k] / p0, ref[("hertz3d", "axis_max_von_mises/p0@nu=0.3", "")], "1%",
            "Johnson eqs 3.45-3.46 on the axis (hand; its Boussinesq quadrature agrees): the discrete Hertz pressure, "
            "the padded window's images")
        row("hertz3d", "max_von_mises_depth/a", f["stress/depth_m"][k] / a,
            ref[("hertz3d", "axis_depth_of_max_von_mises/a@nu=0.3", "")], "0.03",
            "as above; the planes lie 0.02 a apart")
        f.close()

        # The plastic limit: white heights, H/(E* h'_rms) ~ 1e-5: A/A0 = pbar/H (the bearing area).
        rng = np.random.default_rng(7)
        n = 64
        path = os.path.join(tmp, "white.h5")
        write_surface(path, rng.normal(0.0, 1e-6, (n, n)), 1e-6, 1e-6)
        hardness = 1e6
        for r in (0.1, 0.5):
            curve, f = contact(binary, path, "--pressure", f"{r * hardness!r} Pa", "--hardness", f"{hardness!r} Pa")
            row("plastic", f"contact_fraction@pbar/H={r}", curve[0]["contact_fraction"], r, f"{1.5 / n ** 2:.6g}",
                "the bearing area pbar/H, to one element of 4096", f"{1.5 / n ** 2:.6g}")
            f.close()

    return expected_table.check(rows, os.path.join(HERE, "expected.csv"), sys.argv, binary,
                                "areal boundary elements against exact solutions and Persson's theory",
                                "validation/areal-contact/check.py build/geartrib")


if __name__ == "__main__":
    sys.exit(main())
