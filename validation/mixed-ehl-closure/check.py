#!/usr/bin/python3
"""The statistical closure (film formula, Johnson-Greenwood-Poon load sharing on a Greenwood-Williamson
surface) measured against the mixed-EHL fidelity on the seed's pair (gears/m6z30-mixed-ehl.toml, 11
positions) on six flank sets, and its effective-roughness factor k fitted with Ceres.

Usage: validation/mixed-ehl-closure/check.py GEARTRIB [--group quick|long] [--fit TOOL] [--write]
       validation/mixed-ehl-closure/check.py --table      (the README's tables from the stored CSVs)
       validation/mixed-ehl-closure/check.py GEARTRIB --refit SET RUN.csv   (k of SET against another
         mixed-EHL run of it, e.g. at another mixed_ehl.film_floor; prints the fit tool's rows)
--group long (expected-long.csv, about 8 min on two cores): the mixed-EHL run of each flank set, its
  time means and extremes at A..E and along the path beside the statistical cycle of the same run.
--group quick (expected.csv, the default, about 15 s): the refusals (smooth flanks, traction curves),
  the statistical cycle of every set under every film datum, traction and gear-mean friction law (the
  deterministic fidelity: the same flanks' statistics as the mixed-EHL run's, which it must reproduce),
  the closure's response to k and the Ceres fit (TOOL: geartrib_closure_fit, default beside GEARTRIB in
  validation/) against the mixed-EHL values stored by the long group, and a short mixed-EHL run (A, C
  and E of the near-smooth set) that must reproduce the stored one's.
"""
import concurrent.futures
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import expected_table  # noqa: E402

CASE = "gears/m6z30-mixed-ehl.toml"
# The measured flanks (synthesised from the shipped patches, docs/guide/run.md) lubricated as the
# mixed-EHL case is: its oil, oil temperature, 11 positions and tolerance; the patches resampled to the
# generated flanks' 1 um (at their own 0.25 um the mixed-EHL grid needs ~3500 nodes: README "Run times").
MEASURED = ("gears/m6z30-measured.toml",
            ["lubricant.file=../lubricants/mineral-vg220.toml", "operating.oil_temperature=70degC",
             "contact.positions=11", "mixed_ehl.tolerance=1e-6", "pinion.flank.topography.resample=1um",
             "wheel.flank.topography.resample=1um"])
GEARS = ("pinion", "wheel")
HOBBED_RIDGE_RADIUS = 0.4e-3  # the hobbed profile's default ridge radius [m] (docs/reference/case-file.md)
# Flank sets: (case, --set list, how its heights scale by k: ("rq", Rq) ground, ("hobbed", Rq) ridges and
# random part, ("files", None) the measured patches).
SETS = {
    "near-smooth": (CASE, [f"{g}.flank.profile.rq=10nm" for g in GEARS], ("rq", 10e-9)),
    "superfinished": (CASE, [f"{g}.flank.profile.rq=0.08um" for g in GEARS], ("rq", 0.08e-6)),
    "ground": (CASE, [f"{g}.flank.profile.rq=0.4um" for g in GEARS], ("rq", 0.4e-6)),
    "shipped": (CASE, [], ("rq", 1e-6)),
    "hobbed": (CASE, [s for g in GEARS for s in (f"{g}.flank.profile.kind=hobbed", f"{g}.flank.profile.rq=0.3um")],
               ("hobbed", 0.3e-6)),
    "measured": (MEASURED[0], MEASURED[1] + ["contact.fidelity=mixed_ehl"], ("files", None)),
}
SMOOTH = [f"{g}.flank.profile.kind=smooth" for g in GEARS]
POINTS = {0: "A", 4: "B", 5: "C", 6: "D", 10: "E"}  # of 11 positions (the run's labels: the nearest)
# The statistical cycle alone: the deterministic fidelity computes it from the same flank profiles
# (mesh_deterministic.cpp, profile_statistics), dry contact beside it; elements of the profiles' 1 um.
STATISTICAL = ["contact.fidelity=deterministic", "contact.element_size=1um", "contact.threads=1"]
VARIANTS = {"default": [], "film_gap mean-plane": ["film_gap=mean-plane"],
            "film_gap dry-offset": ["film_gap=dry-offset"],
            "traction isothermal-eyring": ["traction=isothermal-eyring"], "mean_friction iso": ["mean_friction=iso"],
            "mean_friction schlenk": ["mean_friction=schlenk"], "mean_friction fernandes": ["mean_friction=fernandes"]}
K_GRID = [math.exp(math.log(0.02) + j * math.log(100.0) / 33) for j in range(34)]  # 0.02 .. 2, ln-uniform
FIT_OBSERVABLES = {"share": ("ehl_asperity_share_mean", "asperity_load_share"),
                   "friction": ("ehl_friction_coefficient_mean", "friction_coefficient")}

EHL = [("ehl_asperity_share_mean", "EHL asperity share mean [1]"),
       ("ehl_asperity_share_max", "EHL asperity share max [1]"),
       ("ehl_friction_coefficient_mean", "EHL friction mean [1]"),
       ("ehl_central_film_mean_m", "EHL central film mean [m]"), ("ehl_min_film_mean_m", "EHL least film mean [m]"),
       ("ehl_flash_temperature_max_K", "EHL flash temperature max [K]"),
       ("ehl_yield_fraction_max", "EHL yield fraction max [1]")]
CLOSURE = [("asperity_load_share", "closure asperity share [1]"), ("friction_coefficient", "closure friction [1]"),
           ("film_traction_coefficient", "closure film traction [1]"),
           ("film_isothermal_m", "closure film isothermal [m]"), ("film_m", "closure film [m]"),
           ("lambda_smooth_film", "closure lambda [1]"), ("mean_gap_m", "closure mean gap [m]"),
           ("flash_temperature_K", "closure flash temperature [K]")]
# Regression of a stored mixed-EHL value: the windows are deterministic (each position's solve on one
# thread; two runs on this build identical), the tolerance allows another compiler's rounding through
# ~1000 Newton-converged steps (tolerance 1e-6 of p_H and the load).
EHL_REGRESSION = {"ehl_asperity_share_mean": "1e-4", "ehl_asperity_share_max": "1e-3",
                  "ehl_friction_coefficient_mean": "1e-4", "ehl_central_film_mean_m": "1e-9",
                  "ehl_min_film_mean_m": "1e-9", "ehl_flash_temperature_max_K": "0.05",
                  "ehl_yield_fraction_max": "0.01"}
CLOSURE_REGRESSION = "rel 1e-6"  # closed-form laws on the profiles' statistics; the CSV's 10 digits
WHY_EHL = "stored mixed-EHL value (time mean or extreme over the window; tolerance: README 'What is asserted')"
WHY_CLOSURE = "the statistical cycle of the same run (closed-form laws: rel 1e-6)"


def path_mean(v):
    """Trapezoidal mean over equally spaced positions (contact::path_mean, the run's own)."""
    return (0.5 * (v[0] + v[-1]) + sum(v[1:-1])) / (len(v) - 1)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def geartrib(binary, case, sets, out, extra=()):
    """Run `geartrib run`: (exit status, per-position rows or the refusal's message, wall seconds)."""
    cmd = [binary, "run", case, *sum((["--set", s] for s in [*sets, *extra]), []), "-q", "-o", out + ".h5",
           "--csv", out + ".csv"]
    start = time.monotonic()
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    seconds = time.monotonic() - start
    if p.returncode != 0:
        message = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"
        return p.returncode, message, seconds
    return 0, read_rows(out + ".csv"), seconds


def bulk_temperature(row):
    return float(row["contact_temperature_K"]) - float(row["flash_temperature_K"])


def key(name, i):
    return f"{name} {i:02d}" + (f" {POINTS[i]}" if i in POINTS else "")


def row(k, quantity, model, regression="", reason="", reference=None, tolerance="", verdict="regression"):
    return {"key": k, "quantity": quantity, "model": model, "reference": reference, "tolerance": tolerance,
            "verdict": verdict, "regression": regression, "reason": reason}


# ------------------------------------------------------------------------------------------- long
def long_rows(binary, tmp):
    rows, runs = [], {}
    for name, (case, sets, _) in SETS.items():
        rc, got, seconds = geartrib(binary, case, sets, os.path.join(tmp, name))
        print(f"{name}: mixed-EHL run {'ok' if rc == 0 else 'refused'} in {seconds:.1f} s", flush=True)
        if rc != 0:
            rows.append(row(name, "mixed-EHL run [message]", got, "=", "the run's refusal, recorded (README)"))
            continue
        runs[name] = got
        rows.append(row(name, "bulk temperature [K]", bulk_temperature(got[0]), "rel 1e-9",
                        "the oil of both sides: the ISO/TS 6336-20 estimate of the statistical cycle"))
        for i, r in enumerate(got):
            for column, label in EHL + CLOSURE:
                if i in POINTS or column in ("ehl_asperity_share_mean", "ehl_friction_coefficient_mean"):
                    ehl = column.startswith("ehl_")
                    rows.append(row(key(name, i), label, float(r[column]),
                                    EHL_REGRESSION[column] if ehl else CLOSURE_REGRESSION,
                                    WHY_EHL if ehl else WHY_CLOSURE))
        for column, label in EHL + CLOSURE:
            ehl = column.startswith("ehl_")
            rows.append(row(f"{name} path mean", label, path_mean([float(r[column]) for r in got]),
                            EHL_REGRESSION[column] if ehl else CLOSURE_REGRESSION, WHY_EHL if ehl else WHY_CLOSURE))
        for column, label in (("ehl_flash_temperature_max_K", "EHL flash temperature max [K]"),
                              ("flash_temperature_K", "closure flash temperature [K]")):
            ehl = column.startswith("ehl_")
            rows.append(row(f"{name} path max", label, max(float(r[column]) for r in got),
                            EHL_REGRESSION[column] if ehl else CLOSURE_REGRESSION, WHY_EHL if ehl else WHY_CLOSURE))
    rows += trend_rows(runs)
    return rows


def trend_rows(runs):
    rows = []
    col = {n: {c: [float(r[c]) for r in got] for c in got[0]} for n, got in runs.items()}
    family = [n for n in ("near-smooth", "superfinished", "ground", "shipped") if n in col]
    share = [col[n]["asperity_load_share"] for n in family]
    rows.append(row("ground family", "closure share non-decreasing with Rq at every position [bool]",
                    all(a <= b for s, t in zip(share, share[1:]) for a, b in zip(s, t)), reference=True, tolerance="=",
                    verdict="agrees",
                    reason="lambda falls as the flanks roughen (Rq 10 nm, 0.08, 0.4, 1 um; JGP 1972)"))
    least = [path_mean(col[n]["ehl_min_film_mean_m"]) for n in family]
    rows.append(row("ground family", "EHL least film path mean falling with Rq [bool]",
                    all(a > b for a, b in zip(least, least[1:])), reference=True, tolerance="=", verdict="agrees",
                    reason="the rough flanks' heights enter the film (h = h0 + x^2/2R + v - r): its least value falls "
                    "with their amplitude"))
    rows.append(row("all sets", "EHL share mean at most the closure's at every position [bool]",
                    all(e <= s for n in col for e, s in zip(col[n]["ehl_asperity_share_mean"],
                                                            col[n]["asperity_load_share"])),
                    "=", "a finding, stored: the closure puts more load on the asperities than the unified approach's "
                    "film floor counts on every set (README)"))
    if "near-smooth" in col:
        c = col["near-smooth"]
        ratio = [e / d for e, d in zip(c["ehl_min_film_mean_m"], c["film_isothermal_m"])]
        for q, v in (("min", min(ratio)), ("max", max(ratio))):
            rows.append(row("near-smooth", f"EHL least film over Dowson-Higginson's isothermal, path {q} [1]", v,
                            "rel 1e-3", reference=1.0, tolerance="20%", verdict="agrees",
                            reason="a smooth contact: the solver's least film is 0.93-1.04 of Dowson-Higginson's over "
                            "its validated (W, U, G) (docs/theory/mixed-ehl.md); DH's own fit is within ~10% of its "
                            "numerical solutions; here the time mean over a window at 10 nm Rq"))
        rows.append(row("near-smooth", "EHL share max and closure share, path max [1]",
                        max(max(c["ehl_asperity_share_max"]), max(c["asperity_load_share"])), "1e-9",
                        reference=0.0, tolerance="1e-9", verdict="agrees",
                        reason="lambda ~40: no asperity contact in either model"))
        rows.append(row("near-smooth", "EHL friction over the closure's, path means [1]",
                        path_mean(c["ehl_friction_coefficient_mean"]) / path_mean(c["friction_coefficient"]),
                        "rel 1e-3",
                        "a smooth film: the mixed EHL's Newtonian shear capped at the limiting shear against the "
                        "closure's thermal Eyring traction (no asperities in either)"))
    return rows


# ------------------------------------------------------------------------------------------ quick
def scaled_sets(name, k, tmp, patches):
    """--set changes that scale the flanks' heights by k for the statistical side (README 'The fit')."""
    how, rq = SETS[name][2]
    if how == "rq":
        return [f"{g}.flank.profile.rq={k * rq:.12g}" for g in GEARS]
    if how == "hobbed":  # ridges -u^2/(2 R): heights x k <=> R / k; the random part's rq x k
        return [s for g in GEARS for s in (f"{g}.flank.profile.rq={k * rq:.12g}",
                                           f"{g}.flank.profile.ridge_radius={HOBBED_RIDGE_RADIUS / k:.12g}")]
    sets = []
    for g in GEARS:  # the measured patch's heights x k (form removal, outliers, fill and synthesis are linear)
        path = os.path.join(tmp, f"{g}-k{k:.6f}.csv")
        with open(patches[g]) as f, open(path, "w") as out:
            for line in f:
                out.write(line if line.startswith("#") else ",".join(f"{k * float(v):.10g}" for v in line.split(","))
                          + "\n")
        sets.append(f"{g}.flank.topography.file={path}")
    return sets


def submit_scan(binary, pool, bulk, tmp):
    """The statistical cycle of each set in bulk (name -> bulk temperature [K]) with its heights x k,
    at every k of K_GRID: futures keyed (name, j)."""
    patches = {}
    for g in GEARS:
        patches[g] = os.path.join(tmp, f"{g}-patch.csv")
        subprocess.run([binary, "surface", "clean", f"gears/surfaces/{g}-flank.h5", "--form", "0", "-o", patches[g]],
                       cwd=ROOT, check=True, capture_output=True)
    jobs = {}
    for name, t in bulk.items():
        case, sets, _ = SETS[name]
        for j, k in enumerate(K_GRID):
            scaled = [*STATISTICAL, f"bulk_temperature={t}K", *scaled_sets(name, k, tmp, patches)]
            jobs[(name, j)] = pool.submit(geartrib, binary, case, sets, os.path.join(tmp, f"{name}-k{j}"), scaled)
    return jobs


def collect(jobs):
    results = {}
    for job, future in jobs.items():
        rc, got, _ = future.result()
        if rc != 0:
            raise RuntimeError(f"{job}: {got}")
        results[job] = got
    return results


def run_fit(fit_tool, results, targets, tmp):
    """geartrib_closure_fit on the scan's results and targets[(name, observable)] (11 positions' values):
    its result rows."""
    response, target = os.path.join(tmp, "response.csv"), os.path.join(tmp, "target.csv")
    with open(response, "w") as r, open(target, "w") as t:
        r.write("set,observable,position,k,value\n")
        t.write("set,observable,position,value\n")
        for (name, obs), values in targets.items():
            closure = FIT_OBSERVABLES[obs][1]
            for i, value in enumerate(values):
                t.write(f"{name},{obs},{i},{value}\n")
                for j, k in enumerate(K_GRID):
                    r.write(f"{name},{obs},{i},{k:.17g},{results[(name, j)][i][closure]}\n")
    out = subprocess.run([fit_tool, response, target], capture_output=True, text=True, check=True).stdout
    return list(csv.DictReader(out.splitlines()))


def refit(binary, fit_tool, name, run_csv):
    """The fit of k for one set against another mixed-EHL run of it (its CSV), e.g. at another film
    floor: the closure scanned at that run's bulk temperature."""
    got = read_rows(run_csv)
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = collect(submit_scan(binary, pool, {name: f"{bulk_temperature(got[0]):.10g}"}, tmp))
        targets = {(name, obs): [float(r[ehl]) for r in got] for obs, (ehl, _) in FIT_OBSERVABLES.items()}
        for f in run_fit(fit_tool, results, targets, tmp):
            print(",".join(f.values()))
    return 0


def stored_long():
    """The long group's stored table: (key, quantity) -> model value."""
    table = expected_table.read(os.path.join(HERE, "expected-long.csv"))[1]
    return {(r["key"], r["quantity"]): r["model"] for r in table}


def quick_rows(binary, fit_tool, tmp):
    rows, stored = [], stored_long()
    rc, message, _ = geartrib(binary, CASE, SMOOTH, os.path.join(tmp, "smooth"))
    rows.append(row("smooth", "mixed-EHL run [message]", message, "=",
                    "smooth flanks have no statistics for the film's share: refused (exit 2), recorded"))
    rc, message, _ = geartrib(binary, CASE, ["traction=curve", *STATISTICAL], os.path.join(tmp, "curve"))
    rows.append(row("all sets", "traction curve [message]", message, "=",
                    "the lubricant has no measured traction curves: refused (exit 2), recorded"))

    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for name, (case, sets, _) in SETS.items():
            for v, extra in VARIANTS.items():
                out = os.path.join(tmp, f"{name}-{v}".replace(" ", "_"))
                jobs[(name, v)] = pool.submit(geartrib, binary, case, sets, out, [*STATISTICAL, *extra])
        jobs.update(submit_scan(binary, pool, {n: stored[(n, "bulk temperature [K]")] for n in SETS}, tmp))
        results = collect(jobs)

    for name in SETS:
        default = results[(name, "default")]
        same = all(expected_table.within(float(r[c]), float(stored[(key(name, i), label)]), "rel 1e-9")
                   for i, r in enumerate(default) if i in POINTS for c, label in CLOSURE)
        rows.append(row(name, "statistical cycle = the mixed-EHL run's (stored) at A..E [bool]", same,
                        reference=True, tolerance="=", verdict="agrees",
                        reason="the same flank profiles' statistics feed both fidelities' statistical cycle "
                        "(rel 1e-9)"))
        for v in VARIANTS:
            got = results[(name, v)]
            for column, label in (("asperity_load_share", "closure asperity share path mean [1]"),
                                  ("friction_coefficient", "closure friction path mean [1]"),
                                  ("film_m", "closure film path mean [m]"),
                                  ("mean_gap_m", "closure mean gap path mean [m]")):
                rows.append(row(f"{name} {v}", label, path_mean([float(r[column]) for r in got]), CLOSURE_REGRESSION,
                                WHY_CLOSURE))
            rows.append(row(f"{name} {v}", "closure flash temperature path max [K]",
                            max(float(r["flash_temperature_K"]) for r in got), CLOSURE_REGRESSION, WHY_CLOSURE))
            rows.append(row(f"{name} {v}", "bulk temperature [K]", bulk_temperature(got[0]), CLOSURE_REGRESSION,
                            "the ISO/TS 6336-20 estimate with the variant's gear-mean friction law"))
    rows += fit_rows(fit_tool, results, stored, tmp)
    rows += short_run_rows(binary, stored, tmp)
    return rows


def fit_rows(fit_tool, results, stored, tmp):
    targets = {(name, obs): [stored[(key(name, i), dict(EHL)[ehl])] for i in range(11)]
               for name in SETS for obs, (ehl, _) in FIT_OBSERVABLES.items()}
    fits = run_fit(fit_tool, results, targets, tmp)
    rows = []
    why = ("Ceres fit on the stored targets and the closure's tabulated response (deterministic: rel 1e-6)")
    for f in fits:
        k = f"fit {f['set']} {f['observable']}"
        rows.append(row(k, "k [1]", float(f["k"]), "rel 1e-6", why))
        se = float(f["std_error"])
        rows.append(row(k, "k standard error [1]", se if math.isfinite(se) else "undefined",
                        "rel 1e-4" if math.isfinite(se) else "=",
                        "Ceres' covariance x the residual variance (rel 1e-4: the SVD's rounding); undefined where "
                        "the closure is flat in k"))
        rows.append(row(k, "rms residual [1]", float(f["rms_residual"]), "rel 1e-6", why))
        rows.append(row(k, "status", f["status"], "=",
                        "ok, at bound (the grid's end), not identifiable (flat closure) or undetermined"))
    # The largest k at which the closure's share stays below 0.001 at every position: the share's
    # information where the mixed-EHL share is (nearly) zero.
    for name in SETS:
        below = [k for j, k in enumerate(K_GRID)
                 if all(float(r["asperity_load_share"]) < 1e-3 for r in results[(name, j)])]
        rows.append(row(f"fit {name} share", "largest k with closure share < 0.001 everywhere [1]",
                        max(below) if below else 0.0, "rel 1e-9", "a grid node (k 0.02 .. 2, 34 nodes ln-uniform)"))
    return rows


def short_run_rows(binary, stored, tmp):
    """A, C, E of the near-smooth set by themselves (3 positions) at the stored run's bulk temperature:
    each position's window does not depend on the others, so the values are the stored run's."""
    case, sets, _ = SETS["near-smooth"]
    bulk = stored[("near-smooth", "bulk temperature [K]")]
    rc, got, seconds = geartrib(binary, case, sets, os.path.join(tmp, "short"),
                                ["contact.positions=3", f"bulk_temperature={bulk}K"])
    print(f"short mixed-EHL run (near-smooth A, C, E): {seconds:.1f} s", flush=True)
    if rc != 0:
        return [row("near-smooth short", "mixed-EHL run [message]", got, "=", "must run")]
    rows = []
    for r, i in zip(got, (0, 5, 10)):
        for column, label in EHL:
            rows.append(row(f"near-smooth short {POINTS[i]}", label, float(r[column]), EHL_REGRESSION[column], WHY_EHL,
                            reference=float(stored[(key("near-smooth", i), label)]), tolerance=EHL_REGRESSION[column],
                            verdict="agrees"))
    return rows


# ------------------------------------------------------------------------------------------ table
def table():
    """The README's tables, from the stored CSVs."""
    lo = stored_long()
    qu = {(r["key"], r["quantity"]): r["model"] for r in expected_table.read(os.path.join(HERE, "expected.csv"))[1]}

    def v(k, q, scale=1.0, digits=3):
        x = lo.get((k, q))
        if x is None:
            return "-"
        try:
            return f"{float(x) * scale:.{digits}g}"
        except ValueError:
            return x
    print("| set | share EHL (mean / max) | share closure | mu EHL | mu closure | film EHL central / least [um] | "
          "film closure isothermal / inlet-heated [um] | lambda | flash EHL max [K] | flash Blok [K] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name in SETS:
        if (f"{name}", "mixed-EHL run [message]") in lo:
            print(f"| {name} | {lo[(name, 'mixed-EHL run [message]')]} |")
            continue
        for where in ("path mean", *[key(name, i)[len(name) + 1:] for i in POINTS]):
            k = f"{name} {where}"
            flash_e = v(f"{name} path max" if where == "path mean" else k, "EHL flash temperature max [K]")
            flash_s = v(f"{name} path max" if where == "path mean" else k, "closure flash temperature [K]")
            print(f"| {name} {where if where != 'path mean' else '(path mean; flash: path max)'} | "
                  f"{v(k, 'EHL asperity share mean [1]', 1, 2)} / {v(k, 'EHL asperity share max [1]', 1, 2)} | "
                  f"{v(k, 'closure asperity share [1]', 1, 2)} | {v(k, 'EHL friction mean [1]', 1, 3)} | "
                  f"{v(k, 'closure friction [1]', 1, 3)} | {v(k, 'EHL central film mean [m]', 1e6)} / "
                  f"{v(k, 'EHL least film mean [m]', 1e6)} | {v(k, 'closure film isothermal [m]', 1e6)} / "
                  f"{v(k, 'closure film [m]', 1e6)} | {v(k, 'closure lambda [1]')} | {flash_e} | {flash_s} |")
    print()
    print("| set | variant | share | mu | film [um] | mean gap [um] | flash max [K] | bulk [degC] |")
    print("|---|---|---|---|---|---|---|---|")
    for name in SETS:
        for var in VARIANTS:
            k = f"{name} {var}"
            g = lambda q, s=1.0, d=3: f"{float(qu[(k, q)]) * s:.{d}g}" if (k, q) in qu else "-"  # noqa: E731
            print(f"| {name} | {var} | {g('closure asperity share path mean [1]')} | "
                  f"{g('closure friction path mean [1]')} | "
                  f"{g('closure film path mean [m]', 1e6)} | {g('closure mean gap path mean [m]', 1e6)} | "
                  f"{g('closure flash temperature path max [K]')} | "
                  f"{float(qu[(k, 'bulk temperature [K]')]) - 273.15:.1f} |")
    print()
    print("| set | observable | k | standard error | rms residual | status | largest k, closure share < 0.001 |")
    print("|---|---|---|---|---|---|---|")
    def n(x, d):
        try:
            return f"{float(x):.{d}g}"
        except ValueError:
            return x
    for name in [*SETS, "pooled"]:
        for obs in FIT_OBSERVABLES:
            k = f"fit {name} {obs}"
            if (k, "k [1]") not in qu:
                continue
            lim = qu.get((f"fit {name} share", "largest k with closure share < 0.001 everywhere [1]"))
            print(f"| {name} | {obs} | {n(qu[(k, 'k [1]')], 4)} | {n(qu[(k, 'k standard error [1]')], 2)} | "
                  f"{n(qu[(k, 'rms residual [1]')], 3)} | {qu[(k, 'status')]} | "
                  f"{n(lim, 3) if lim is not None and obs == 'share' else ''} |")
    return 0


def main(argv):
    if "--table" in argv:
        return table()
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    group = argv[argv.index("--group") + 1] if "--group" in argv else "quick"
    if group not in ("quick", "long"):
        print(f"--group {group}: quick or long", file=sys.stderr)
        return 2
    fit_tool = (os.path.abspath(argv[argv.index("--fit") + 1]) if "--fit" in argv
                else os.path.join(os.path.dirname(binary), "validation", "geartrib_closure_fit"))
    if "--refit" in argv:
        i = argv.index("--refit")
        return refit(binary, fit_tool, argv[i + 1], os.path.abspath(argv[i + 2]))
    with tempfile.TemporaryDirectory() as tmp:
        rows = long_rows(binary, tmp) if group == "long" else quick_rows(binary, fit_tool, tmp)
    name = "expected-long.csv" if group == "long" else "expected.csv"
    return expected_table.check(
        rows, os.path.join(HERE, name), argv, binary,
        f"the statistical closure against the mixed-EHL fidelity on six flank sets (group {group})",
        f"validation/mixed-ehl-closure/check.py GEARTRIB --group {group} --write")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
