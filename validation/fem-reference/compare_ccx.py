#!/usr/bin/python3
"""The project's CalculiX runs beside the published laws and the continuous model.

Usage: validation/fem-reference/compare_ccx.py path/to/geartrib

Reads ccx-perfectly-plastic.csv and ccx-hardening.csv (with their -details.csv), written by
ccx-study.sh, and prints Markdown tables:
  1. elastic-perfectly-plastic F* and A* beside Kogut-Etsion 2002 and Jackson-Green 2005;
     1b. the same on the finer meshes (ccx-perfectly-plastic-fine-*.csv) with their convergence;
  2. the continuous model refitted (geartrib fit) to the hardening runs: constants and residuals;
  3. the seed's claim (section 3): contact radius and peak contact pressure of the model within 5%
     of the FEM at delta* = 2, 6, 7, 10, with the default and the refitted constants;
  4. the yielded share of the contact area at the surface (the -details.csv columns
     plastic_surface_area_fraction, plastic_surface_inner_radius_over_ac and, for the outer edge,
     plastic_surface_radius_over_ac), perfectly plastic and hardening side by side.
Normalisation: Kogut-Etsion's delta_c, F_c, A_c for the case's pair (Jackson-Green's own delta_c
differs by 0.08% for nu = 0.3). Exit status 0; the tables are the result.
"""
import csv
import io
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def model(bin_, name, levels, case=None):
    cmd = [bin_, "asperity", "--model", name, "--delta-star", ",".join(f"{d:g}" for d in levels), "--csv"]
    if case:
        cmd += ["--case", case]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True, cwd=ROOT).stdout
    return {float(r["delta_star"]): r for r in csv.DictReader(io.StringIO(out))}


def pct(a, b):
    return f"{100 * (a / b - 1):+.1f}%"


def beside_laws(bin_, rows, coarse=None):
    """A Markdown table of F* and A* beside Kogut-Etsion and Jackson-Green (and, when given, the
    coarse mesh's values at the same levels)."""
    levels = [float(r["delta_star"]) for r in rows]
    ke, jg = model(bin_, "kogut-etsion", levels), model(bin_, "jackson-green", levels)
    extra = " (10 across) |" if coarse is not None else ""
    print(f"| delta* | F* ccx |{extra} F* KE 2002 | F* JG 2005 | A* ccx |{extra} A* KE 2002 | A* JG 2005 |")
    print("|---|---|" + ("---|" if coarse is not None else "") + "---|---|---|" + ("---|" if coarse is not None else "") + "---|---|")
    for r in rows:
        d = float(r["delta_star"])
        f, a = float(r["load_star"]), float(r["area_star"])
        fk, fj = float(ke[d]["load_star"]), float(jg[d]["load_star"])
        ak, aj = float(ke[d]["area_star"]), float(jg[d]["area_star"])
        c = coarse.get(d) if coarse is not None else None
        fc = (f" {float(c['load_star']):.4g} |" if c else " |") if coarse is not None else ""
        ac = (f" {float(c['area_star']):.4g} |" if c else " |") if coarse is not None else ""
        print(f"| {d:g} | {f:.4g} |{fc} {fk:.4g} ({pct(fk, f)}) | {fj:.4g} ({pct(fj, f)}) | {a:.4g} |{ac} "
              f"{ak:.4g} ({pct(ak, a)}) | {aj:.4g} ({pct(aj, a)}) |")


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    bin_ = os.path.abspath(argv[1])
    pp = table(os.path.join(HERE, "ccx-perfectly-plastic.csv"))
    print("### 1. Elastic-perfectly-plastic sphere: CalculiX beside the published laws\n")
    beside_laws(bin_, pp)

    # 1b. The same on finer meshes (20 elements across), with their convergence study.
    fine = [os.path.join(HERE, n) for n in ("ccx-perfectly-plastic-fine-6-10-20.csv", "ccx-perfectly-plastic-fine-50-100.csv")]
    fine = [p for p in fine if os.path.exists(p)]
    if fine:
        print("\n### 1b. The same at 20 elements across each run's first contact radius\n")
        beside_laws(bin_, [r for p in fine for r in table(p)], {float(r["delta_star"]): r for r in pp})
        print("\nConvergence (each run's provenance):\n")
        for p in fine:
            with open(p) as f:
                for line in f:
                    if line.startswith("# convergence") or line.startswith("# mesh"):
                        print("    " + line[2:].rstrip())

    # 2. Refit the continuous closure to the hardening runs (load and area).
    hard_csv = os.path.join(HERE, "ccx-hardening.csv")
    with tempfile.TemporaryDirectory() as tmp:
        fragment = os.path.join(tmp, "refit.toml")
        report = os.path.join(tmp, "report.txt")
        subprocess.run([bin_, "fit", "--model", "continuous", "--data", hard_csv,
                        "--free", "area_scale,area_exponent,pressure_scale,pressure_exponent",
                        "--observe", "load_star,area_star", "-q", "-o", fragment, "--report", report],
                       check=True, cwd=ROOT)
        with open(fragment) as f:
            fitted = f.read()
        with open(report) as f:
            lines = f.read().splitlines()
        start = next(i for i, l in enumerate(lines) if l.startswith("Root-mean-square relative error"))
        rms = [l.split() for l in lines[start + 1:start + 3]]
        print("\n### 2. The continuous model refitted to the hardening runs (`geartrib fit`)\n")
        print("```")
        print(fitted.strip())
        print("```")
        print("\nrms relative error: " + ", ".join(f"{n} {100 * float(v):.2f}%" for n, v in rms))
        # A case with the refitted constants, for the model evaluations below.
        case = os.path.join(tmp, "m6z30-refit.toml")
        with open(os.path.join(ROOT, "gears", "m6z30.toml")) as f:
            text = f.read().replace('"../materials/', f'"{ROOT}/materials/')
        with open(case, "w") as f:
            f.write(text + "\n" + "\n".join(l for l in fitted.splitlines() if not l.startswith("#")) + "\n")
        det = {float(r["delta_star"]): r for r in table(os.path.join(HERE, "ccx-hardening-details.csv"))}
        seed_levels = [2.0, 6.0, 7.0, 10.0]
        default, refit = model(bin_, "continuous", seed_levels), model(bin_, "continuous", seed_levels, case)
        hz = model(bin_, "hertz", [1.0])[1.0]
        a_c = float(hz["contact_radius_m"])
        s_y = 418e6
        print("\n### 3. The seed's 5% claim on the hardening runs (contact radius, peak contact pressure)\n")
        print("| delta* | a/a_c ccx | default | refitted | p_max/S_y ccx | default | refitted |")
        print("|---|---|---|---|---|---|---|")
        worst = {"default": 0.0, "refitted": 0.0}
        for d in seed_levels:
            fa, fp = float(det[d]["contact_radius_over_ac"]), float(det[d]["max_pressure_over_yield"])
            cells = []
            for name, m in (("default", default), ("refitted", refit)):
                ma = float(m[d]["contact_radius_m"]) / a_c
                mp = float(m[d]["max_pressure_Pa"]) / s_y
                worst[name] = max(worst[name], abs(ma / fa - 1), abs(mp / fp - 1))
                cells.append((ma, mp))
            print(f"| {d:g} | {fa:.4g} | {cells[0][0]:.4g} ({pct(cells[0][0], fa)}) | {cells[1][0]:.4g} ({pct(cells[1][0], fa)}) "
                  f"| {fp:.4g} | {cells[0][1]:.4g} ({pct(cells[0][1], fp)}) | {cells[1][1]:.4g} ({pct(cells[1][1], fp)}) |")
        for name, w in worst.items():
            print(f"\nLargest difference, {name} constants: {100 * w:.1f}% ({'within' if w <= 0.05 else 'NOT within'} the seed's 5%)")

    # 4. The yielded share of the contact area at the surface (an annulus when inner > 0).
    print("\n### 4. Yielded share of the contact area at the surface\n")
    print("| delta* | a/a_c pp | share pp | yielded r/a_c pp | a/a_c hard | share hard | yielded r/a_c hard |")
    print("|---|---|---|---|---|---|---|")
    mats = [{float(r["delta_star"]): r for r in table(os.path.join(HERE, f"ccx-{m}-details.csv"))}
            for m in ("perfectly-plastic", "hardening")]
    for d in sorted(set(mats[0]) | set(mats[1])):
        cells = []
        for m in mats:
            r = m.get(d)
            if r is None or "plastic_surface_area_fraction" not in r:
                cells.append("| | |")
                continue
            share, inner = float(r["plastic_surface_area_fraction"]), float(r["plastic_surface_inner_radius_over_ac"])
            outer = float(r["plastic_surface_radius_over_ac"])
            ring = f"{inner:.3g}-{outer:.3g}" if share > 0 else "none"
            cells.append(f"{float(r['contact_radius_over_ac']):.4g} | {share:.3f} | {ring} |")
        print(f"| {d:g} | " + " ".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
