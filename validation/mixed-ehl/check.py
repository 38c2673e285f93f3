#!/usr/bin/python3
"""The mixed-EHL line-contact solver against its references (validation/mixed-ehl/README.md), each
case run through `geartrib ehl`.

Usage: validation/mixed-ehl/check.py GEARTRIB [--group quick|long|open] [--write]

Every case of the reference tables becomes rows (solver value, reference, tolerance, verdict,
reason), checked against the group's stored table (validation/expected_table.py; --write stores the
solver's values, keeping the references, tolerances and reasons). Exits 1 on any failure.

Groups (README "Running the checks"):
  quick  expected.csv       smooth films against the published fits (S1-S6 and a 16-point grid),
                            the Hertz limit, the spike at S1-S5, load balance, the smooth dry limit
                            against the boundary elements, the thick film, the asperity share against
                            speed. CTest validation.mixed-ehl (label validation), about 30 s.
  long   expected-long.csv  grid convergence of the smooth films (the 2048-4096 change), the thick
                            film through a transient window, the waviness runs: linearity, the
                            collapse at nabla 8 and 16, A_d/A_i as regression. CTest
                            validation.mixed-ehl-long (labels validation and long), about 4 min on one core.
  open   expected-open.csv  the checks the solver fails at present, asserting as the README states
                            them (README "What fails"): not in CTest; exits 1 until the solver meets
                            them.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

GROUPS = {"quick": "expected.csv", "long": "expected-long.csv", "open": "expected-open.csv"}
# The regression margin of a converged solve: the solver stops at a Newton update of 1e-7 p_H; 1e-4
# covers another compiler or libm, while any change of the discretisation moves the films by more
# (the 1024-2048 change is 0.2-2 %).
REGRESSION = "rel 1e-4"


def read_table(name):
    with open(os.path.join(HERE, name)) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {k: [float(r[k]) if k != "state" else r[k] for r in rows] for k in rows[0]}


class Runner:
    """`geartrib ehl` runs, each once per process: the summary (--csv), the profile (-o) and the
    transient's series (--series); a failed run gives {"error": its message}."""

    def __init__(self, binary):
        self.binary = binary
        self.cache = {}

    def __call__(self, args, series=False):
        key = (tuple(args), series)
        if key not in self.cache:
            self.cache[key] = self.run(args, series)
        return self.cache[key]

    def run(self, args, series):
        with tempfile.TemporaryDirectory() as tmp:
            profile, history = os.path.join(tmp, "profile.csv"), os.path.join(tmp, "series.csv")
            command = [self.binary, "ehl", *args, "--csv", "-o", profile] + (["--series", history] if series else [])
            p = subprocess.run(command, capture_output=True, text=True)
            print(f"  ehl {' '.join(args)}: exit {p.returncode}", flush=True)
            if p.returncode:
                lines = p.stderr.strip().splitlines()
                return {"error": f"exit {p.returncode}: {lines[-1] if lines else ''}"}
            out = {}
            for line in p.stdout.splitlines():
                if line.startswith("#") or line.startswith("name,"):
                    continue
                name, value = line.split(",")
                out[name] = float(value)
            out["profile"] = columns(profile)
            if series:
                out["series"] = columns(history)
            return out


def row(key, quantity, model, reference, tolerance, verdict, reason, regression=""):
    return {"key": key, "quantity": quantity, "model": model, "reference": reference, "tolerance": tolerance,
            "verdict": verdict, "regression": regression, "reason": reason}


def value(out, name):
    """A summary value, or the run's error text (which no tolerance accepts)."""
    return out["error"] if "error" in out else out[name]


# --- smooth contacts (smooth_line_reference.csv) ---

SMOOTH_RUNS = {"C": ["--viscosity-law", "roelands"], "I": ["--viscosity-law", "barus", "--incompressible"]}
# The runs that do not converge at present (README 'What fails'): their rows are in the open group.
# (The grid point 5e5 N/m at 10 m/s converges with the second-order transport: quick now. S4 with
# Barus and incompressible oil converges too, but its h_min is 1.18 of Pan-Hamrock's: open.)
OPEN_RUNS = {"S4 I N2048"}
# The grid-convergence rows below 1 % that fail at present (S5's central film was 1.005 %; 0.17 % now).
OPEN_CHANGES = set()


def smooth_args(r, nodes, run):
    # The inlet 4 b, 6 where M < 15 (the inlet meniscus lies farther ahead at low load; README).
    inlet = "6" if float(r["M"]) < 15 else "4"
    return ["--load", r["line_load_N_per_m"], "--radius", r["radius_m"], "--speed", r["entrainment_m_per_s"],
            "--modulus", r["composite_modulus_Pa"], "--viscosity", r["viscosity_Pa_s"], "--alpha",
            r["pressure_viscosity_per_Pa"], "--nodes", str(nodes), "--inlet", inlet, *SMOOTH_RUNS[run]]


def hertz_at(x, b, ph):
    return ph * math.sqrt(1.0 - (x / b) ** 2) if abs(x) < b else 0.0


def spike_present(out):
    """A local pressure maximum downstream of x = 0, within 0.6 b < x < 1.1 b, above Hertz there
    (README), read off the profile."""
    if "error" in out:
        return out["error"]
    x, p = out["profile"]["x_m"], out["profile"]["pressure_Pa"]
    b, ph = out["hertz_half_width_m"], out["hertz_pressure_Pa"]
    return any(p[i] > p[i - 1] and p[i] >= p[i + 1] and 0.6 * b < x[i] < 1.1 * b and p[i] > hertz_at(x[i], b, ph)
               for i in range(1, len(p) - 1))


def load_balance(out, w):
    """|int p dx / w - 1| from the profile (the pressure the file holds: >= 0)."""
    if "error" in out:
        return out["error"]
    return abs(sum(out["profile"]["pressure_Pa"]) * out["node_spacing_m"] / w - 1.0)


def hertz_distance(out, w):
    """int |p - p_Hertz| dx / w."""
    x, p = out["profile"]["x_m"], out["profile"]["pressure_Pa"]
    b, ph = out["hertz_half_width_m"], out["hertz_pressure_Pa"]
    return sum(abs(pi - hertz_at(xi, b, ph)) for xi, pi in zip(x, p)) * out["node_spacing_m"] / w


def smooth_rows(ehl, group):
    rows = []
    points = read_table("smooth_line_reference.csv")
    fit_reason = ("README 'Film formulas': the two minimum-film fits differ by <= 9 % at S1-S6; 15 % adds the "
                  "solver's grid error (~1 % at 2048 nodes) and the Barus/Roelands and density differences")
    for r in points:
        radius, w = float(r["radius_m"]), float(r["line_load_N_per_m"])
        for run in ("C", "I"):
            key = f"{r['case']} {run} N2048"
            spike_group = "open" if r["case"] == "S6" else "quick"
            fits = group == ("open" if key in OPEN_RUNS else "quick")
            if not fits and not (group == spike_group and run == "C"):
                continue
            out = ehl(smooth_args(r, 2048, run))
            if fits:
                hmin, hc = value(out, "min_film_m"), value(out, "central_film_m")
                ok = "error" not in out
                rows.append(row(key, "h_min/h_min(Dowson-Higginson)",
                                hmin / (radius * float(r["h_min_dowson_higginson_over_R"])) if ok else hmin, 1.0,
                                "15%", "agrees", fit_reason, REGRESSION))
                rows.append(row(key, "h_min/h_min(Pan-Hamrock)",
                                hmin / (radius * float(r["h_min_pan_hamrock_over_R"])) if ok else hmin, 1.0, "15%",
                                "agrees", fit_reason, REGRESSION))
                if run == "C":
                    rows.append(row(key, "h_c/h_c(Pan-Hamrock central)",
                                    hc / (radius * float(r["h_c_pan_hamrock_over_R"])) if ok else hc, 1.0, "", "regression",
                                    "README: the two central fits differ by 23-39 % here; which one the solver should "
                                    "meet is decided from the papers' conditions (not retrieved): regression only",
                                    REGRESSION))
                else:
                    rows.append(row(key, "h_c/h_c(Dowson-Toyoda)",
                                    hc / (radius * float(r["h_c_dowson_toyoda_over_R"])) if ok else hc, 1.0, "",
                                    "regression", "README: as the Pan-Hamrock central row", REGRESSION))
                rows.append(row(key, "h_c/h_min > 1 [bool]", (hc / hmin > 1.0) if ok else hc, True, "=", "agrees",
                                "the constriction at the outlet (README)", "="))
                rows.append(row(key, "|int p dx/w - 1|", load_balance(out, w), 0.0, "1e-7", "agrees",
                                "load control: the solver's load tolerance (1e-7), README 'load balance'"))
            if group == spike_group and run == "C":
                rows.append(row(key, "spike: local max in 0.6b<x<1.1b above Hertz [bool]", spike_present(out), True, "=",
                                "agrees",
                                "README 'Petrusevich spike': presence only (its height is grid-dependent)"
                                + ("; S6 (L = 5.3): the pressure falls monotonically past x = 0 (README 'What fails')"
                                   if r["case"] == "S6" else ""), "="))
    if group == "quick":
        # The approach to Hertz with load (S1, S2, S3: M = 11, 29, 67 at L = 10.6).
        outs = [ehl(smooth_args(r, 2048, "C")) for r in points[:3]]
        distances = [hertz_distance(o, float(r["line_load_N_per_m"])) for o, r in zip(outs, points[:3])]
        for r, d in zip(points[:3], distances):
            rows.append(row(f"{r['case']} C N2048", "int |p - p_Hertz| dx/w", d, "", "", "regression",
                            "the distance to Hertz's pressure, recorded", REGRESSION))
        rows.append(row("S1-S3 C N2048", "int |p - p_Hertz| dx/w falls as M grows [bool]",
                        distances[0] > distances[1] > distances[2], True, "=", "agrees",
                        "README 'approach to Hertz': the elastic-piezoviscous asymptote, strict", "="))
    if group in ("long", "open"):
        # Grid convergence: h_c and h_min at 1024, 2048, 4096 nodes (README 'grid convergence').
        for r in points:
            outs = [ehl(smooth_args(r, n, "C")) for n in (1024, 2048, 4096)]
            for name, quantity in (("central_film_m", "h_c"), ("min_film_m", "h_min")):
                key = f"{r['case']} C N1024-4096"
                if any("error" in o for o in outs):
                    change_fine = change_coarse = next(o["error"] for o in outs if "error" in o)
                    below_half = change_fine
                else:
                    h = [o[name] for o in outs]
                    change_coarse, change_fine = abs(h[1] / h[0] - 1.0), abs(h[2] / h[1] - 1.0)
                    below_half = change_fine < 0.5 * change_coarse
                if group == ("open" if (r["case"], quantity) in OPEN_CHANGES else "long"):
                    rows.append(row(key, f"{quantity} change 2048-4096", change_fine, 0.0, "0.01", "agrees",
                                    "README 'grid convergence': below 1 %", REGRESSION))
                if group == "long":
                    rows.append(row(key, f"{quantity} change 2048-4096 < half 1024-2048 [bool]", below_half, True, "=",
                                    "agrees",
                                    "README 'grid convergence': first order at least (second order since the "
                                    "second-order transport)", "="))
    return rows


# --- the 16-point grid against Dowson-Higginson (tests/test_mixed_ehl.cpp's realisation) ---

GRID_RADIUS, GRID_MODULUS, GRID_ETA, GRID_ALPHA = 0.0154, 1.13e11, 0.05, 2e-8  # G = alpha 2 E* = 4520


def dowson_higginson(w, u):
    """Dowson & Higginson (1977), restated here: h_min = 2.65 U^0.70 G^0.54 W^-0.13 R."""
    e_prime = 2.0 * GRID_MODULUS
    U, G, W = GRID_ETA * u / (e_prime * GRID_RADIUS), GRID_ALPHA * e_prime, w / (e_prime * GRID_RADIUS)
    return 2.65 * U**0.70 * G**0.54 * W**-0.13 * GRID_RADIUS


def grid_rows(ehl, group):
    rows = []
    for w in (2e5, 5e5, 1e6, 2e6):  # W 5.75e-5 .. 5.75e-4
        for u in (1.0, 2.0, 5.0, 10.0):  # U 1.44e-11 .. 1.44e-10
            key = f"w {w:g} u {u:g} N2048"
            if group != ("open" if key in OPEN_RUNS else "quick"):
                continue
            out = ehl(["--load", repr(w), "--radius", repr(GRID_RADIUS), "--speed", repr(u), "--modulus",
                       repr(GRID_MODULUS), "--viscosity", repr(GRID_ETA), "--alpha", repr(GRID_ALPHA), "--nodes",
                       "2048"])
            hmin = value(out, "min_film_m")
            rows.append(row(key, "h_min/h_min(Dowson-Higginson)",
                            hmin / dowson_higginson(w, u) if "error" not in out else hmin, 1.0, "10%", "agrees",
                            "Roelands, compressible, G = 4520; 10 %: Pan & Hamrock's minimum-film fit differs from "
                            "Dowson & Higginson's by 6-8 % over this grid (1.714/2.65 U^-0.006 G^0.028 W^0.002 = "
                            "0.92-0.94), plus the solver's grid error (~1 % at 2048 nodes)", REGRESSION))
    return rows


# --- the dry limit against the boundary elements ---

DRY = ["--load", "1e6", "--radius", "15.4mm", "--speed", "0.01m/s", "--modulus", "113GPa", "--viscosity", "1e-12",
       "--alpha", "0", "--viscosity-law", "barus", "--incompressible", "--dry"]


def dry_rows(ehl, group):
    rows = []
    if group == "quick":
        cases = [("smooth N1024", ["--nodes", "1024"])]
    elif group == "open":
        cases = [("smooth N2048", ["--nodes", "2048"]), ("smooth N4096", ["--nodes", "4096"]),
                 ("waviness 0.5um/40um N1024", ["--nodes", "1024", "--waviness", "0.5um,40um", "--steady"])]
    else:
        return rows
    for key, extra in cases:
        out = ehl(DRY + extra)
        key = f"dry {key}"
        if "error" in out:
            interior = edges = share = out["error"]
        else:
            prof = out["profile"]
            x, p, q = prof["x_m"], prof["pressure_Pa"], prof["dry_pressure_Pa"]
            ph = out["hertz_pressure_Pa"]
            touching = [i for i, v in enumerate(q) if v > 0.0]
            in_contact = [i for i, s in enumerate(prof["state"]) if s == "contact"]
            # The boundary elements' contact spans [first, last]; more than two nodes inside it both
            # solve the same elastic equation with the same influence coefficients (the edges may
            # differ by a node, which moves the pressure of the nodes beside it: below).
            inner = [i for i in range(len(x)) if touching and touching[0] + 2 < i < touching[-1] - 2]
            interior = max(abs(p[i] - q[i]) for i in inner) / ph if inner else "no dry contact"
            edges = bool(in_contact) and abs(in_contact[0] - touching[0]) <= 1 and abs(in_contact[-1] - touching[-1]) <= 1
            share = out["asperity_share"]
        rows.append(row(key, "max |p - p_dry|/p_H more than 2 nodes inside", interior, 0.0, "1e-3",
                        "agrees",
                        "the same elastic equation on the same elements where both are in contact: 1e-3 p_H "
                        "(check.py's first statement); the contact criteria differ (film < film floor against gap "
                        "= 0), so the edges may differ by a node (checked below), which moves the pressure at the "
                        "edge node and the next (measured 2.2e-3 and 1.1e-3 p_H at 1024 nodes, README)", REGRESSION if group == "quick" else ""))
        rows.append(row(key, "contact edges within one node of the dry contact's [bool]", edges, True, "=", "agrees",
                        "the solver's contact is film < 2 nm, the dry one gap = 0: the edges may differ by one node",
                        "="))
        rows.append(row(key, "asperity share >= 0.99 [bool]", share >= 0.99 if not isinstance(share, str) else share,
                        True, "=", "agrees", "a vanishing viscosity carries nothing: the contacts carry the load", "="))
    return rows


# --- the thick film and the asperity share against speed ---

THICK = ["--load", "1e6", "--radius", "15.4mm", "--speed1", "5m/s", "--speed2", "4m/s", "--modulus", "113GPa",
         "--viscosity", "0.05", "--alpha", "2e-8", "--waviness", "20nm,40um"]


def film_limit_rows(ehl, group):
    rows = []
    if group == "quick":
        out = ehl(THICK + ["--steady"])
        rows.append(row("thick film steady", "h_min >= 10 x the waviness' amplitude [bool]",
                        value(out, "min_film_m") >= 10 * 20e-9 if "error" not in out else out["error"], True, "=",
                        "agrees", "the premise: the film ten times the roughness or more (README 'thick-film limit')",
                        "="))
        rows.append(row("thick film steady", "asperity share", value(out, "asperity_share"), 0.0, "=", "agrees",
                        "no node's film below the floor: nothing in contact (README 'thick-film limit')", "="))
        # The share against speed (tests/test_mixed_ehl.cpp's case): 1 um waviness of 40 um, steady.
        shares = []
        for u in ("2", "0.5", "0.35"):
            out = ehl(["--load", "1e6", "--radius", "15.4mm", "--speed", u + "m/s", "--modulus", "113GPa",
                       "--viscosity", "0.05", "--alpha", "2e-8", "--waviness", "1um,40um", "--steady"])
            shares.append(value(out, "asperity_share"))
            rows.append(row(f"share u {u} m/s", "asperity share", shares[-1], "", "", "regression", "recorded",
                            "rel 1e-3"))
        rows.append(row("share u 2/0.5/0.35 m/s", "asperity share rises as the speed falls [bool]",
                        all(isinstance(s, float) for s in shares) and shares[0] < shares[1] < shares[2], True, "=",
                        "agrees", "the film thins with speed (README 'the asperity share falling with speed'), strict",
                        "="))
    elif group == "open":
        # The same steady waviness below 0.35 m/s: the share should keep rising; Newton's method
        # reaches the steady contact's other solution instead, the oil locked in the waviness's
        # valleys (share 0 at 0.3-0.02 m/s, the central films 35-10 nm against 16 nm at 0.35 m/s).
        shares = []
        for u in ("0.35", "0.3", "0.2", "0.1", "0.05", "0.02"):
            out = ehl(["--load", "1e6", "--radius", "15.4mm", "--speed", u + "m/s", "--modulus", "113GPa",
                       "--viscosity", "0.05", "--alpha", "2e-8", "--waviness", "1um,40um", "--steady"])
            shares.append(value(out, "asperity_share"))
        rows.append(row("share u 0.35/0.3/0.2/0.1/0.05/0.02 m/s", "asperity share rises as the speed falls [bool]",
                        all(isinstance(s, float) for s in shares) and all(a < b for a, b in zip(shares, shares[1:])),
                        True, "=", "agrees", "README 'What fails': the steady contact's locked oil at low speed", "="))
    elif group == "long":
        out = ehl(THICK, series=True)
        rows.append(row("thick film transient N1024", "largest asperity share over the window",
                        value(out, "asperity_share_max"), 0.0, "=", "agrees",
                        "the waviness moving with surface 1 through the contact over the default window: no contact "
                        "at any instant", "="))
    return rows


# --- waviness through the contact (roughness_attenuation.csv) ---

WAVINESS_W = 1.3e-4  # README 'Roughness': the smooth contact's (M, L) realised at W = 1.3e-4
STEEL_E_STAR = 206e9 / (2.0 * (1.0 - 0.3**2))


def waviness_args(M, L, nodes):
    load = WAVINESS_W * 2.0 * STEEL_E_STAR * 0.01
    return ["--moes", f"{M:g},{L:g}", "--load", repr(load), "--radius", "0.01", "--modulus", repr(STEEL_E_STAR),
            "--viscosity", "0.05", "--viscosity-law", "barus", "--incompressible", "--nodes", str(nodes)]


def attenuation(ehl, c):
    """A_d/A_i of one case: the smooth contact's h_c gives A_i; the waviness on surface 1 enters at the
    inlet, crosses the domain, then travels max(2 contact widths, 2 wavelengths); A_d is half the
    range of the film at x = 0 over the last wavelength's passage."""
    M, L = float(c["M"]), float(c["L"])
    inlet, outlet = 4.0, 1.5
    # At least 40 nodes a wavelength (README: the amplitude's measurement ~1 %).
    nodes = 1024
    while float(c["wavelength_over_b"]) * nodes / (inlet + outlet) < 40:
        nodes *= 2
    base = waviness_args(M, L, nodes)
    smooth = ehl(base)
    if "error" in smooth:
        return smooth["error"]
    b, hc, u = smooth["hertz_half_width_m"], smooth["central_film_m"], smooth["speed1_m_per_s"]
    wavelength, amplitude = float(c["wavelength_over_b"]) * b, float(c["amplitude_over_hc"]) * hc
    window = ((inlet + outlet) * b + max(4.0 * b, 2.0 * wavelength)) / (2.0 * b)
    out = ehl(base + ["--waviness", f"{amplitude!r}m,{wavelength!r}m", "--window", repr(window)], series=True)
    if "error" in out:
        return out["error"]
    t, h = out["series"]["time_s"], out["series"]["central_film_m"]
    last = [hi for ti, hi in zip(t, h) if ti >= t[-1] - wavelength / u * (1.0 + 1e-9)]
    return 0.5 * (max(last) - min(last)) / amplitude


def waviness_rows(ehl, group):
    rows = []
    cases = read_table("roughness_attenuation.csv")
    ratio = {c["case"]: attenuation(ehl, c) for c in cases}
    numeric = lambda v: isinstance(v, float)  # noqa: E731
    if group == "long":
        for c in cases:
            rows.append(row(c["case"], "A_d/A_i", ratio[c["case"]], "", "", "regression",
                            "the film's amplitude at x = 0 over the waviness' (README: the curve F itself not retrieved)",
                            "rel 1e-3"))
    # The collapse: the three (M, L) at one nabla agree within 0.05 (amplitude 0.05 H_c).
    for nabla in ("1", "4", "8", "16"):
        if (group == "long") != (nabla in ("1", "8", "16")):  # nabla 4's spread (0.0515) is open
            continue
        values = [ratio[c["case"]] for c in cases if c["nabla"] == nabla and c["amplitude_over_hc"] == "0.05"]
        spread = max(values) - min(values) if all(numeric(v) for v in values) else next(
            v for v in values if not numeric(v))
        rows.append(row(f"nabla {nabla}", "spread of A_d/A_i over (M, L)", spread, 0.0, "0.05", "agrees",
                        "Venner et al. 1997: A_d/A_i = F(nabla) for all (M, L); 0.05 (README 'Roughness')",
                        "rel 1e-3" if group == "long" else ""))
    if group == "long":
        a, b = ratio["M20-L10-n4-a0.05"], ratio["M20-L10-n4-a0.2"]
        rows.append(row("M20-L10-n4", "A_d/A_i at A_i 0.2 H_c less at 0.05 H_c", b - a if numeric(a) and numeric(b) else
                        (a if not numeric(a) else b), 0.0, "0.03", "agrees",
                        "Venner et al. 1997: A_d/A_i independent of A_i; 0.03 (README)", "rel 1e-2"))
    if group == "long":  # open until the second-order transport
        for M, L in (("20", "10"), ("50", "10"), ("20", "5")):
            values = [ratio[c["case"]] for c in cases if c["M"] == M and c["L"] == L and c["amplitude_over_hc"] == "0.05"]
            falls = all(numeric(v) for v in values) and all(x > y for x, y in zip(values, values[1:]))
            rows.append(row(f"M{M}-L{L}", "A_d/A_i falls from nabla 1 to 16 [bool]", falls, True, "=", "agrees",
                            "Venner et al. 1997: short waves kept, long waves flattened, strict", "="))
        for c in cases:
            if c["nabla"] == "1":
                v = ratio[c["case"]]
                rows.append(row(c["case"], "A_d/A_i >= 0.8 [bool]", v >= 0.8 if numeric(v) else v, True, "=", "agrees",
                                "Venner et al. 1997: lambda/b < 1 hardly deformed, read as within 20 %", "="))
    return rows


# --- the rigid-isoviscous case (rigid_isoviscous_case.csv) ---

def rigid_rows(ehl):
    case = read_table("rigid_isoviscous_case.csv")[0]
    length, b = float(case["length_m"]), float(case["hertz_halfwidth_m"])
    inlet, outlet = -float(case["inlet_xi"]) * length / b, float(case["outlet_xi"]) * length / b
    rows, errors = [], []
    for nodes in (1024, 2048, 4096):
        out = ehl(["--load", case["line_load_N_per_m"], "--radius", "10mm", "--speed", "1m/s", "--modulus",
                   repr(STEEL_E_STAR), "--viscosity", "0.01", "--alpha", "0", "--viscosity-law", "barus",
                   "--incompressible", "--inlet", repr(inlet), "--outlet", repr(outlet), "--nodes", str(nodes)])
        dx = (float(case["outlet_xi"]) - float(case["inlet_xi"])) * length / nodes
        key = f"rigid N{nodes}"
        hmin = value(out, "min_film_m")
        rows.append(row(key, "least film [m]", hmin, 10e-6, f"rel {2 * dx / length:.3g}", "agrees",
                        "twice the first-order upwind error measured by upwind_error_estimate.py (1.02 dx/sqrt(2Rh0))"))
        rows.append(row(key, "rupture x [m]", value(out, "rupture_x_m"), float(case["exit_x_m"]), f"{2 * dx:.3g}",
                        "agrees", "the last wet node within one node of x_e (measured); 2 dx"))
        errors.append(abs(hmin / 10e-6 - 1.0) if "error" not in out else out["error"])
    ratio = errors[2] / errors[1] if all(isinstance(e, float) for e in errors) and errors[1] > 0 else next(
        (e for e in errors if isinstance(e, str)), "no error")
    rows.append(row("rigid N2048-4096", "film error ratio", ratio, 0.5, "0.1", "agrees",
                    "first order: ratio 0.4-0.6 (README)"))
    return rows


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    group = argv[argv.index("--group") + 1] if "--group" in argv else "quick"
    if group not in GROUPS:
        print(f"--group {group}: one of {', '.join(GROUPS)}", file=sys.stderr)
        return 2
    ehl = Runner(binary)
    rows = smooth_rows(ehl, group) + dry_rows(ehl, group) + film_limit_rows(ehl, group)
    rows += grid_rows(ehl, group)
    if group in ("long", "open"):
        rows += waviness_rows(ehl, group)
    if group == "open":
        rows += rigid_rows(ehl)
    return expected_table.check(rows, os.path.join(HERE, GROUPS[group]), argv, binary,
                                f"the mixed-EHL line-contact solver against its references (group {group})",
                                f"validation/mixed-ehl/check.py GEARTRIB --group {group} --write")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
