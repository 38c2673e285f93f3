#!/usr/bin/python3
"""FZG type C at load stage 10 (the pitting test's 372.6 N m), FVA 3A at 90 degC: geartrib's
lubrication against its re-evaluation and against independent numbers, the published operating
data, the expected trends and the stored expected table.

Usage: validation/fzg-c-lubricated/check.py path/to/geartrib [--write]

1. Runs `geartrib run fzg-c-lubricated.toml` and compares at the named points A..E (where they
   stand: /lubrication/points, B and D with the single pair's load)
   - re-evaluated by independent.py from the same published formulas (relative 1e-6; catches
     units, temperatures, inputs; not a wrong formula): the film, lambda, h_Y, lambda_GF, the
     ISO/TS 6336-20 flash and contact temperatures; along the path the ISO mean coefficients, the
     bulk temperature, the oil's eta and alpha at it;
   - independent (the moving band source integrated numerically): the flash temperature with the
     local friction (0.6 %: Blok's rounded 1.11 and the finite Peclet number).
2. Compares the kinematics with published.csv (pitch radii, pitch-line velocity).
3. Runs three sweeps and asserts the trends (README "Trends").
4. Checks the key numbers against expected.csv (validation/expected_table.py; --write stores them).
Exits 1 on any failure.
"""
import csv
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import expected_table  # noqa: E402
import independent  # noqa: E402

import h5py  # noqa: E402

CASE = os.path.join(HERE, "fzg-c-lubricated.toml")
REL = 1e-6
REL_REASON = ("rel 1e-6: re-evaluated, the same closed forms with the same inputs in double precision (observed 0 "
              "to 1e-15); a 0.1 % change of one input or constant (e.g. beta) moves the film by 1e-5 or more. A "
              "re-evaluation cannot catch a wrong formula")
INDEPENDENT = 0.006
INDEPENDENT_REASON = ("0.6 %: the moving band source integrated numerically (validation/flash-temperature); Blok's "
                      "printed 1.11 is 0.14 % below the integral's 1.1115 and the finite Peclet number moves it by "
                      "up to 0.4 % at Peclet 5")
HY = 1e-3
HY_REASON = ("rel 1e-3: re-evaluated, with its contact temperature theta_M + theta_fl(mu_mC) from the integrated "
             "moving source instead of Blok's closed form (0.1-0.4 % in theta_fl, through S_GF^0.22: up to 4e-4)")
REGRESSION = "rel 1e-6"
REGRESSION_REASON = "Regression rel 1e-6: deterministic; the margin covers libm."
# Per-point quantities: (name in /lubrication/points, label, relative tolerance).
POINT_QUANTITIES = [
    ("film_m", "film after inlet heating (re-evaluated)", REL),
    ("lambda_smooth_film", "film over the composite Rq (re-evaluated)", REL),
    ("iso_flash_temperature_K", "ISO/TS 6336-20 flash temperature, eq. A.5 (re-evaluated)", REL),
    ("iso_contact_temperature_K", "bulk + ISO/TS 6336-20 flash temperature (re-evaluated)", REL),
    ("iso_film_hy_m", "ISO/TS 6336-22 h_Y (re-evaluated; its contact temperature integrated)", HY),
    ("iso_lambda_gf", "ISO/TS 6336-22 lambda_GF (re-evaluated; its contact temperature integrated)", HY),
    ("flash_temperature_K", "flash temperature, local mu (independent: integrated)", INDEPENDENT),
]
SPEEDS = ["500rpm", "1000rpm", "2175rpm", "3000rpm", "4350rpm"]
STAGES = ["5", "7", "9", "10", "12"]   # FZG load stages (the case's PT-C: 0.5 m arm)
RAS = ["0.1um", "0.2um", "0.3um", "0.4um", "0.5um"]


def wait_for(binary):
    """The binary may be momentarily missing while someone rebuilds it: wait up to 90 s."""
    for _ in range(10):
        if os.path.exists(binary):
            return
        time.sleep(10)
    raise SystemExit(f"{binary}: not found")


def geartrib(binary, *args):
    wait_for(binary)
    return subprocess.run([binary, *args], check=True, cwd=ROOT, capture_output=True, text=True).stdout


def rel_diff(a, b):
    return abs(a - b) / abs(b) if b != 0.0 else abs(a - b)


def compare_independent(run_h5):
    """Rows of (what, geartrib, reference, tolerance) and the number of disagreements."""
    pts, summ = independent.compute(run_h5, CASE)
    own, _ = independent.compute(run_h5, CASE, bulk="own")
    with h5py.File(run_h5, "r") as f:
        lub = {k: f["lubrication"][k][()] for k in f["lubrication"] if isinstance(f["lubrication"][k], h5py.Dataset)}
        points = {k: f["lubrication/points"][k][()] for k in f["lubrication/points"]}
        mattrs, lattrs = dict(f["mesh"].attrs), dict(f["lubrication"].attrs)
    rows = []
    for p in independent.POINTS:
        k = pts[p]["index"]
        for q, _label, tol in POINT_QUANTITIES:
            rows.append((f"{p} {q}", float(points[q][k]), pts[p][q], tol))
        rows.append((f"{p} film_m (own bulk estimate)", float(points["film_m"][k]), own[p]["film_m"], REL))
        rows.append((f"{p} s_m", float(points["s_m"][k]), summ["s_named"][p], REL))
        rows.append((f"{p} s_named_m", float(mattrs[f"s_{p}_m"]), summ["s_named"][p], REL))
    rows += [
        ("mean_friction_iso", float(lattrs["mean_friction_iso"]), summ["mu_mc"], REL),
        ("mean_friction_iso_flash", float(lattrs["mean_friction_iso_flash"]), summ["mu_m"], REL),
        ("bulk_temperature_K", float(lattrs["bulk_temperature_K"]), summ["bulk_temperature_K"], REL),
        ("dynamic_viscosity_at_bulk_Pa_s", float(lattrs["dynamic_viscosity_at_bulk_Pa_s"]), summ["eta_bulk_Pa_s"], REL),
        ("pressure_viscosity_at_bulk_per_Pa", float(lattrs["pressure_viscosity_at_bulk_per_Pa"]),
         summ["alpha_bulk_per_Pa"], REL),
        ("composite_rq_m", float(lattrs["composite_rq_m"]), summ["composite_rq_m"], REL),
        ("max iso_flash_temperature_K", float(lub["iso_flash_temperature_K"].max()), summ["max_iso_flash_K"], REL),
    ]
    bad = sum(rel_diff(g, r) > tol for _, g, r, tol in rows)
    return rows, bad, pts, summ, lub, points, lattrs


def published(binary, summ):
    """(name, published, geartrib, tolerance, source) rows of published.csv."""
    summary = {r["name"]: float(r["value"]) for r in csv.DictReader(geartrib(binary, "kinematics", CASE, "--summary",
                                                                               "--csv").splitlines())}
    summary["pitch_line_velocity_m_per_s"] = summary["pinion_speed_rad_per_s"] * summary["pinion_operating_pitch_radius_m"]
    out = []
    with open(os.path.join(HERE, "published.csv")) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            out.append((r["name"], float(r["value"]), summary[r["name"]], float(r["tolerance"]), r["source"]))
    return out


def sweep(binary, tmp, name, *sets):
    out = os.path.join(tmp, f"{name}.csv")
    args = ["sweep", CASE, "-q", "-o", os.path.join(tmp, f"{name}.h5"), "--csv", out]
    for s in sets:
        args += ["--set", s]
    geartrib(binary, *args)
    with open(out) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    for r in rows:
        if r["status"] != "ok":
            raise SystemExit(f"sweep {name}: point {r['point']} {r['status']}: {r['message']}")
    return rows


def increasing(values):
    return all(b > a for a, b in zip(values, values[1:]))


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        run_h5 = os.path.join(tmp, "run.h5")
        geartrib(binary, "run", CASE, "-q", "-o", run_h5)
        rows, bad, pts, summ, lub, points, lattrs = compare_independent(run_h5)
        print("1. geartrib against independent.py at the named points (re-evaluated: rel 1e-6; integrated: 0.6 %)")
        print(f"   {'quantity':<44} {'geartrib':>15} {'reference':>15} {'rel diff':>10}")
        for what, g, r, tol in rows:
            d = rel_diff(g, r)
            print(f"   {what:<44} {g:15.8g} {r:15.8g} {d:10.2e} {'ok' if d <= tol else 'DIFFERS'}")
        print(f"   {len(rows)} compared, {bad} differ")
        failures += bad

        pub = published(binary, summ)
        print("2. published operating data (published.csv)")
        for name, value, got, tol, source in pub:
            ok = abs(got - value) <= tol
            failures += not ok
            print(f"   {name:<34} published {value:<10g} geartrib {got:<12.8g} tolerance {tol:<8g} "
                  f"{'ok' if ok else 'DIFFERS'} ({source})")

        print("3. trends (geartrib sweep)")
        sp = sweep(binary, tmp, "speed", "speed=" + ",".join(SPEEDS))
        tq = sweep(binary, tmp, "torque", "fzg_load_stage=" + ",".join(STAGES))
        tq_fine = sweep(binary, tmp, "torque-ra02", "fzg_load_stage=" + ",".join(STAGES), "ra=0.2um")
        ra = sweep(binary, tmp, "ra", "ra=" + ",".join(RAS))
        series = {
            "speed -> film_m_min": (SPEEDS, [float(r["film_m_min"]) for r in sp]),
            "ra -> asperity_load_share_max": (RAS, [float(r["asperity_load_share_max"]) for r in ra]),
            "torque (Ra 0.2 um) -> asperity_load_share_max": (STAGES, [float(r["asperity_load_share_max"])
                                                                      for r in tq_fine]),
            "torque (case, Ra 0.5 um) -> asperity_load_share_max": (STAGES, [float(r["asperity_load_share_max"])
                                                                            for r in tq]),
        }
        trends = {}
        for what, (axis, values) in series.items():
            trends[what] = increasing(values)
            print(f"   {what:<52} {'increasing' if trends[what] else 'NOT increasing'}: "
                  + ", ".join(f"{a} {v:.5g}" for a, v in zip(axis, values)))
        for what in list(series)[:2]:  # the load trends are documented departures (README Trends)
            failures += not trends[what]
        lam_fine = [float(r["lambda_smooth_film_min"]) for r in tq_fine]
        lam_case = [float(r["lambda_smooth_film_min"]) for r in tq]
        print(f"   lambda_min along the torque sweeps: Ra 0.2 um {lam_fine[0]:.3f} -> {lam_fine[-1]:.3f}; "
              f"Ra 0.5 um {lam_case[0]:.3f} -> {lam_case[-1]:.3f}")

    # 4. The stored expected table.
    erows = []
    refs = {what: (r, tol) for what, _g, r, tol in rows}
    for p in independent.POINTS:
        k = pts[p]["index"]
        where = f"{p} at s = {pts[p]['s_m'] * 1e3:.3f} mm, line load {pts[p]['line_load_N_per_m'] * 1e-3:.2f} N/mm"
        for q in ("film_m", "lambda_smooth_film", "iso_film_hy_m", "iso_lambda_gf", "iso_flash_temperature_K",
                  "flash_temperature_K"):
            ref, tol = refs[f"{p} {q}"]
            erows.append({"key": p, "quantity": q, "model": float(points[q][k]), "reference": ref,
                          "tolerance": f"rel {tol:g}", "verdict": "agrees", "regression": REGRESSION,
                          "reason": f"independent.py, {where}. Tolerance "
                                    f"{ {REL: REL_REASON, HY: HY_REASON}.get(tol, INDEPENDENT_REASON)}. "
                                    f"{REGRESSION_REASON}"})
        erows.append({"key": p, "quantity": "asperity_load_share", "model": float(points["asperity_load_share"][k]),
                      "reference": None, "tolerance": "", "verdict": "regression", "regression": REGRESSION,
                      "reason": f"{where}: Johnson-Greenwood-Poon sharing, the film filling the mean gap; no "
                                f"independent or published value. {REGRESSION_REASON}"})
    path_rows = [
        ("mean_friction_iso", "ISO/TS 6336-21/-22 mu_mC at the pitch point, oil at 90 degC, Ra 0.5 um"),
        ("mean_friction_iso_flash", "ISO/TS 6336-20 mu_m at the pitch point"),
        ("bulk_temperature_K", "ISO/TS 6336-20 estimate 90 degC + 0.47 x the trapezoidal path mean of eq. A.5"),
        ("max iso_flash_temperature_K", "ISO/TS 6336-20 eq. A.5, maximum along A..E"),
    ]
    for q, what in path_rows:
        ref, tol = refs[q]
        model = float(lattrs[q]) if q in lattrs else float(lub["iso_flash_temperature_K"].max())
        erows.append({"key": "path", "quantity": q, "model": model, "reference": ref, "tolerance": f"rel {tol:g}",
                      "verdict": "agrees", "regression": REGRESSION,
                      "reason": f"independent.py: {what}. Tolerance {REL_REASON}. {REGRESSION_REASON}"})
    for q, v in (("min film_m", float(lub["film_m"].min())),
                 ("min lambda_smooth_film", float(lub["lambda_smooth_film"].min())),
                 ("min iso_lambda_gf", float(lub["iso_lambda_gf"].min())),
                 ("max asperity_load_share", float(lub["asperity_load_share"].max())),
                 ("mean asperity_load_share", float(lub["asperity_load_share"].mean())),
                 ("max asperity_share_closure_spread", float(lub["asperity_share_closure_spread"].max())),
                 ("mesh_mean_friction", float(lattrs["mesh_mean_friction"]))):
        erows.append({"key": "path", "quantity": q, "model": v, "reference": None, "tolerance": "",
                      "verdict": "regression", "regression": REGRESSION,
                      "reason": f"Over the 201 positions (film and lambda agree with independent.py at the points "
                                f"above; the asperity share and friction have no independent value). "
                                f"{REGRESSION_REASON}"})
    for name, value, got, tol, source in pub:
        erows.append({"key": "published", "quantity": name, "model": got, "reference": value, "tolerance": f"{tol:g}",
                      "verdict": "agrees", "regression": REGRESSION,
                      "reason": f"{source} (published.csv); tolerance half the last published digit. "
                                f"{REGRESSION_REASON}"})
    trend_reason = {
        "speed -> film_m_min": "Faster: thicker EHL film (U^0.7) despite the hotter bulk; pinion 500-4350 rpm.",
        "ra -> asperity_load_share_max": "Rougher flanks (Ra 0.1-0.5 um on both): lower lambda, larger asperity share.",
        "torque (Ra 0.2 um) -> asperity_load_share_max":
            "Documented departure (README Trends): at lambda_min 0.32 -> 0.14 (Ra 0.2 um, FZG LS 5-12) the "
            "Johnson-Greenwood-Poon sharing's asperity share falls with load (the asperities' pressure at a "
            "separation does not grow with it, the film's does); FZG tests see friction rise with load.",
        "torque (case, Ra 0.5 um) -> asperity_load_share_max":
            "Documented departure (README Trends): at the case's Ra 0.5 um (lambda_min 0.12 -> 0.05) the asperities "
            "carry 0.9999 to 1 of the load at every stage, not rising monotonically.",
    }
    for what, ok in trends.items():
        departs = what.startswith("torque")
        erows.append({"key": "trend", "quantity": what, "model": ok, "reference": True, "tolerance": "=",
                      "verdict": "departs" if departs else "agrees", "regression": "=",
                      "reason": trend_reason[what]})
    status = expected_table.check(
        erows, os.path.join(HERE, "expected.csv"), argv, binary,
        "validation/fzg-c-lubricated: FZG C, pitting-test load stage 10 (372.6 N m), 2175 rpm, FVA 3A at 90 degC; "
        "lubrication at A..E, path extremes, published kinematics, trends",
        "validation/fzg-c-lubricated/check.py GEARTRIB --write (geartrib run fzg-c-lubricated.toml; independent.py; "
        "geartrib kinematics --summary --csv; geartrib sweep over speed, torque, ra)")
    if failures:
        print(f"FAILED: {failures} comparison(s) or trend(s) outside their tolerance (sections 1-3)")
    return 1 if (failures or status) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
