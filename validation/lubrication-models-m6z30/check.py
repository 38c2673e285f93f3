#!/usr/bin/python3
"""The lubricated default case under every film formula and inlet-heating correction, and its
Stribeck curve: how far apart the literature's formulas put the film, lambda, the asperities' share
and the friction on the seed's pair, and the trends physics requires along a speed sweep.

Usage: validation/lubrication-models-m6z30/check.py GEARTRIB [--write]
Runs `geartrib sweep gears/m6z30.toml` (4 formulas x 3 corrections; 9 speeds on Ra 0.2 um flanks
at a fixed bulk temperature) and checks the rows against expected.csv (validation/expected_table.py).
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

QUANTITIES = [("film_m_min", "film min [m]"), ("film_m_mean", "film mean [m]"),
              ("lambda_smooth_film_min", "lambda min [1]"),
              ("asperity_load_share_mean", "asperity share mean [1]"),
              ("friction_coefficient_mean", "friction mean [1]")]
# The closures of the load sharing: what the film's thickness equals x how the asperities press.
CLOSURE_QUANTITIES = [("asperity_load_share_min", "asperity share min [1]"),
                      ("asperity_load_share_mean", "asperity share mean [1]"),
                      ("asperity_load_share_max", "asperity share max [1]"),
                      ("friction_coefficient_mean", "friction mean [1]"), ("mesh_mean_friction", "gear-mean friction [1]")]
SPEEDS = ["1rpm", "3rpm", "10rpm", "30rpm", "100rpm", "300rpm", "1000rpm", "3000rpm", "10000rpm"]


def sweep(binary, tmp, name, sets):
    out = os.path.join(tmp, name)
    subprocess.run([binary, "sweep", "gears/m6z30.toml", *sum((["--set", s] for s in sets), []), "-q",
                    "-o", out + ".h5", "--csv", out + ".csv"], check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    with open(out + ".csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert all(r["status"] == "ok" for r in rows), [r["message"] for r in rows if r["status"] != "ok"]
    return rows


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        models = sweep(binary, tmp, "models", ["film_formula=dowson-higginson,pan-hamrock-min,pan-hamrock-central,"
                                               "dowson-toyoda", "inlet_heating=gupta,murch-wilson,none"])
        stribeck = sweep(binary, tmp, "stribeck", ["speed=" + ",".join(SPEEDS), "positions=41",
                                                   "bulk_temperature=80degC", "ra=0.2um"])
        closures = sweep(binary, tmp, "closures", ["film_gap=mean-gap,mean-plane,dry-offset",
                                                   "asperity_pressure=auto,asperity-model"])
        traction = sweep(binary, tmp, "traction", ["traction=thermal-eyring,isothermal-eyring",
                                                   "speed=100rpm,1000rpm,3000rpm", "ra=0.2um"])
    for r in models:
        key = f"{r['film_formula']} {r['inlet_heating']}"
        rows += [{"key": key, "quantity": label, "model": float(r[q]), "reference": None} for q, label in QUANTITIES]
    for r in closures:
        key = f"{r['film_gap']} {r['asperity_pressure']}"
        rows += [{"key": key, "quantity": label, "model": float(r[q]), "reference": None}
                 for q, label in CLOSURE_QUANTITIES]
    shares = [float(r["asperity_load_share_mean"]) for r in closures]
    rows.append({"key": "closures", "quantity": "asperity share mean spread max - min [1]",
                 "model": max(shares) - min(shares), "reference": None})
    for r in traction:
        key = f"{r['traction']} {r['speed']} Ra 0.2um"
        rows += [{"key": key, "quantity": "film traction coefficient max [1]",
                  "model": float(r["film_traction_coefficient_max"]), "reference": None},
                 {"key": key, "quantity": "gear-mean friction [1]", "model": float(r["mesh_mean_friction"]),
                  "reference": None}]
    by = {(r["traction"], r["speed"]): float(r["film_traction_coefficient_max"]) for r in traction}
    rows.append({"key": "traction", "quantity": "thermal below isothermal at every speed [bool]",
                 "model": all(by[("thermal-eyring", v)] <= by[("isothermal-eyring", v)] for _, v in by),
                 "reference": True, "tolerance": "=", "verdict": "agrees",
                 "reason": "the film's shear heating lowers its viscosity (Johnson & Greenwood 1980)"})
    films = [float(r["film_m_min"]) for r in models if r["inlet_heating"] == "gupta"]
    rows.append({"key": "formulas (gupta)", "quantity": "film min spread max/min [1]",
                 "model": max(films) / min(films), "reference": None})
    u = [float(r["entrainment_m_per_s_mean"]) for r in stribeck]
    share = [float(r["asperity_load_share_mean"]) for r in stribeck]
    film = [float(r["film_m_min"]) for r in stribeck]
    isothermal = [float(r["film_isothermal_m_min"]) for r in stribeck]
    practical = SPEEDS.index("3000rpm") + 1  # up to a 28 m/s pitch-line speed
    mu = [float(r["friction_coefficient_mean"]) for r in stribeck]
    rows += [{"key": "stribeck", "quantity": "entrainment speed increasing [bool]",
              "model": all(a < b for a, b in zip(u, u[1:])), "reference": True},
             {"key": "stribeck", "quantity": "isothermal film min increasing with speed [bool]",
              "model": all(a < b for a, b in zip(isothermal, isothermal[1:])), "reference": True},
             {"key": "stribeck", "quantity": "film min increasing with speed to 3000 rpm [bool]",
              "model": all(a < b for a, b in zip(film[:practical], film[1:practical])), "reference": True},
             {"key": "stribeck", "quantity": "film min 10000 rpm over 3000 rpm [1]",
              "model": film[-1] / film[practical - 1], "reference": None},
             {"key": "stribeck", "quantity": "asperity share decreasing with speed [bool]",
              "model": all(a > b for a, b in zip(share, share[1:])), "reference": True},
             {"key": "stribeck", "quantity": "asperity share at the slowest point [1]", "model": share[0],
              "reference": None},
             {"key": "stribeck", "quantity": "asperity share at the fastest point [1]", "model": share[-1],
              "reference": None},
             {"key": "stribeck", "quantity": "friction minimum [1]", "model": min(mu), "reference": None},
             {"key": "stribeck", "quantity": "speed of the friction minimum [m/s]", "model": u[mu.index(min(mu))],
              "reference": None}]
    return expected_table.check(
        rows, os.path.join(HERE, "expected.csv"), argv, binary,
        "gears/m6z30.toml lubricated: film formulas x inlet-heating corrections; Stribeck sweep (Ra 0.2 um, bulk "
        "80 degC); film gap x asperity pressure closures; thermal and isothermal traction",
        "validation/lubrication-models-m6z30/check.py GEARTRIB --write (geartrib sweep gears/m6z30.toml "
        "--set film_formula=... --set inlet_heating=...; --set speed=1rpm..10000rpm positions=41 "
        "bulk_temperature=80degC ra=0.2um)")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
