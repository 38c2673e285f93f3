#!/usr/bin/python3
"""The mixed-EHL line-contact solver's reference tables: computes them, or checks the stored ones.

Usage: validation/mixed-ehl/reference_tables.py [--write]

Without --write: recomputes every derived number and compares it with the stored CSV files beside
this script (relative 1e-9; exit 1 on any difference, so a stored table cannot drift from its
derivation). With --write: stores them. About 15 s (20-digit quadrature).

Tables (validation/mixed-ehl/README.md says what each row checks and why its tolerance):
  rigid_isoviscous.csv      the rigid-isoviscous line contact with Reynolds' exit, for several inlets,
                            by 20-digit quadrature (mpmath): exit, load and peak coefficients; and the
                            dimensional validation case on the solver's own domain
  smooth_line_reference.csv smooth isothermal operating points (W, U, G; Moes M, L; a dimensional
                            realisation): Hertz half-width and pressure, and the published film fits
                            (Dowson-Higginson 1977, Pan-Hamrock 1989 min and central, Dowson-Toyoda
                            1979), each restated here from its source, not imported from src/
  roughness_attenuation.csv harmonic waviness through a line contact under pure rolling: the cases
                            (M, L, lambda/b, amplitude) and their wavelength parameter
                            nabla = (lambda/b) M^(3/4)/L^(1/2) (Venner, Couhier, Lubrecht & Greenwood
                            1997), grouped so that cases of equal nabla must agree
"""
import csv
import math
import os
import sys

import mpmath as m

HERE = os.path.dirname(os.path.abspath(__file__))
m.mp.dps = 20

# Steel on steel (206 GPa, 0.3): E* = E/(2 (1 - nu^2)); the EHL literature's E' = 2 E*.
E_STAR = 206e9 / (2.0 * (1.0 - 0.3**2))
E_PRIME = 2.0 * E_STAR
RADIUS = 0.01  # R [m], a gear-like reduced radius
ETA0 = 0.05  # eta_0 [Pa s] for the smooth points (speed follows from U)


# --- the rigid-isoviscous contact (a third derivation beside tests/reference/rigid_isoviscous.hpp) ---
def rigid_isoviscous(xi_in):
    """(xi_e, C, c_p): exit, load and peak coefficients for an inlet at xi_in (-inf: flooded)."""
    def integrand(e):
        return lambda t: (t**2 - e**2) / (1 + t**2)**3

    def residual(e):
        points = [xi_in] + ([-e] if -e > xi_in else []) + [0, e]
        return m.quad(integrand(e), points)

    e = m.findroot(residual, 0.4)

    def p(x):
        return m.quad(integrand(e), [xi_in, x])

    load = 24 * m.quad(p, [xi_in, max(xi_in, -e), 0, e])
    return float(e), float(load), float(12 * m.sqrt(2) * p(max(-e, xi_in)))


# The dimensional rigid case the solver runs (README "Rigid-isoviscous"): steel (rigid to 3e-5 of
# the film), R = 10 mm, eta = 0.01 Pa s, u1 = u2 = 1 m/s, the film 10 um at the load below; the
# solver's domain [-960 b, 120 b] (b the Hertz half-width of that load) puts the inlet at
# xi_in = -960 b/sqrt(2 R h0) and leaves the exit (0.475 sqrt(2 R h0) = 91 b) inside.
RIGID = {"radius": 0.01, "viscosity": 0.01, "speed1": 1.0, "speed2": 1.0, "film": 10e-6,
         "inlet_b": 960.0, "outlet_b": 120.0}


def rigid_rows():
    rows = []
    for xi_in in (-m.inf, -10, -5, -3, -1, -0.3):
        e, c, cp = rigid_isoviscous(xi_in)
        rows.append({"inlet_xi": "-inf" if xi_in == -m.inf else f"{float(xi_in):g}", "exit_xi": e, "load_C": c,
                     "peak_c_p": cp, "exit_film_over_h0": 1 + e * e})
    return rows


def rigid_case():
    """The dimensional case at the solver's finite inlet: solve w h0 = C(xi_in(h0)) eta u_m R
    for the load that gives h0 = 10 um with the inlet at -960 b (b depends on the load: a fixed point)."""
    r, eta, um, h0 = RIGID["radius"], RIGID["viscosity"], 0.5 * (RIGID["speed1"] + RIGID["speed2"]), RIGID["film"]
    length = math.sqrt(2 * r * h0)
    w = 4.894968493913369 * eta * um * r / h0  # start from the flooded load
    for _ in range(50):
        b = math.sqrt(4 * w * r / (math.pi * E_STAR))
        xi_in = -RIGID["inlet_b"] * b / length
        e, c, cp = rigid_isoviscous(xi_in)
        w_new = c * eta * um * r / h0
        if abs(w_new / w - 1) < 1e-14:
            break
        w = w_new
    b = math.sqrt(4 * w * r / (math.pi * E_STAR))
    return {"line_load_N_per_m": w, "hertz_halfwidth_m": b, "inlet_xi": -RIGID["inlet_b"] * b / length,
            "outlet_xi": RIGID["outlet_b"] * b / length, "exit_x_m": e * length, "load_C": c,
            "peak_pressure_Pa": cp * eta * um * math.sqrt(r / h0) / h0, "length_m": length,
            "rigidity_2w_over_pi_Estar_h0": 2 * w / (math.pi * E_STAR * h0)}


# --- smooth isothermal operating points ---
# (case, U, G, W): G = 5000 the classical steel/mineral-oil value; U and W spanning gear contacts.
SMOOTH = [("S1", 1e-11, 5000.0, 5e-5), ("S2", 1e-11, 5000.0, 1.3e-4), ("S3", 1e-11, 5000.0, 3e-4),
          ("S4", 1e-10, 5000.0, 1.3e-4), ("S5", 1e-12, 5000.0, 1.3e-4), ("S6", 1e-11, 2500.0, 1.3e-4)]


def film_fits(u, g, w):
    """The published line-contact fits, H = h/R (u the mean speed in U; E' = 2 E*):
    Dowson & Higginson, Elasto-hydrodynamic Lubrication, SI ed., Pergamon 1977: minimum
      H = 2.65 U^0.70 G^0.54 W^-0.13
    Pan & Hamrock, J. Tribol. 111 (1989) 246-251: minimum 1.714 W^-0.128 U^0.694 G^0.568,
      central 2.922 W^-0.166 U^0.692 G^0.470
    Dowson & Toyoda, Proc. 5th Leeds-Lyon Symposium (1978, publ. 1979): central
      H = 3.06 U^0.69 G^0.56 W^-0.10"""
    return {"h_min_dowson_higginson": 2.65 * u**0.70 * g**0.54 * w**-0.13,
            "h_min_pan_hamrock": 1.714 * w**-0.128 * u**0.694 * g**0.568,
            "h_c_pan_hamrock": 2.922 * w**-0.166 * u**0.692 * g**0.470,
            "h_c_dowson_toyoda": 3.06 * u**0.69 * g**0.56 * w**-0.10}


def smooth_rows():
    rows = []
    for case, u, g, w in SMOOTH:
        fits = film_fits(u, g, w)
        row = {"case": case, "W": w, "U": u, "G": g, "M": w * (2 * u)**-0.5, "L": g * (2 * u)**0.25,
               "radius_m": RADIUS, "composite_modulus_Pa": E_STAR, "viscosity_Pa_s": ETA0,
               "pressure_viscosity_per_Pa": g / E_PRIME, "entrainment_m_per_s": u * E_PRIME * RADIUS / ETA0,
               "line_load_N_per_m": w * E_PRIME * RADIUS,
               # Hertz (Johnson 1985 eq. 4.45 with E' = 2 E*): b/R = sqrt(8 W/pi), p_H/E' = sqrt(W/(2 pi)).
               "hertz_halfwidth_over_R": math.sqrt(8 * w / math.pi), "hertz_pressure_over_Eprime": math.sqrt(w / (2 * math.pi))}
        row.update({k + "_over_R": v for k, v in fits.items()})
        rows.append(row)
    return rows


# --- harmonic waviness, pure rolling ---
# Three (M, L) and four nabla: every nabla realised at each (M, L) (the collapse check), and one
# amplitude pair (the linearity check). Amplitudes as a fraction of the smooth central film.
WAVINESS_ML = [(20.0, 10.0), (50.0, 10.0), (20.0, 5.0)]
WAVINESS_NABLA = [1.0, 4.0, 8.0, 16.0]


def waviness_rows():
    rows = []
    for mm, ll in WAVINESS_ML:
        scale = mm**0.75 / ll**0.5
        for nabla in WAVINESS_NABLA:
            for amp in ((0.05, 0.2) if (mm, ll, nabla) == (20.0, 10.0, 4.0) else (0.05,)):
                rows.append({"case": f"M{mm:g}-L{ll:g}-n{nabla:g}-a{amp:g}", "M": mm, "L": ll, "slide_roll": 0.0,
                             "wavelength_over_b": nabla / scale, "amplitude_over_hc": amp, "nabla": nabla,
                             "group": f"nabla {nabla:g}"})
    return rows


TABLES = {
    "rigid_isoviscous.csv": (
        ["# source: derived for issue 32 (no published table): steady Reynolds, rigid cylinder on a plane, constant viscosity,",
         "#   incompressible, h = h0 + x^2/(2R), p = 0 at the inlet xi_in, Reynolds' exit p = dp/dx = 0 at xi_e",
         "# derivation: 20-digit quadrature (mpmath) in this script; tests/reference/rigid_isoviscous.hpp derives the same by",
         "#   closed form and by Odeint shooting (tests/test_rigid_isoviscous.cpp: all three agree to 1e-11)",
         "# units: xi = x/sqrt(2 R h0); w = load_C eta u_m R/h0 (u_m the mean speed); p_max = peak_c_p eta u_m sqrt(R/h0)/h0",
         "# literature: the flooded load is Martin's (1916) with Reynolds' exit; the issue's 4.895 and 0.4751 are these"],
        ["inlet_xi", "exit_xi", "load_C", "peak_c_p", "exit_film_over_h0"], rigid_rows),
    "rigid_isoviscous_case.csv": (
        ["# source: rigid_isoviscous.csv's derivation at the solver's finite inlet (this script, rigid_case())",
         "# case: steel E* = 206 GPa/(2 (1 - 0.3^2)) (rigid: 2 w/(pi E* h0) = 2.5e-5), R = 10 mm, eta = 0.01 Pa s, u1 = u2 = 1 m/s,",
         "#   alpha = 0, incompressible; the solver's domain [-960 b, 120 b] with b the Hertz half-width of the line load;",
         "#   the line load is the one at which the least film is 10 um with p = 0 at that inlet (a fixed point on b)",
         "# units: in the column names; length_m = sqrt(2 R h0)"],
        ["line_load_N_per_m", "hertz_halfwidth_m", "length_m", "inlet_xi", "outlet_xi", "exit_x_m", "load_C",
         "peak_pressure_Pa", "rigidity_2w_over_pi_Estar_h0"], lambda: [rigid_case()]),
    "smooth_line_reference.csv": (
        ["# source: the published film fits restated (see each column), Hertz (Johnson, Contact Mechanics 1985, eq. 4.45)",
         "# groups: W = w/(E' R), U = eta0 u_m/(E' R) (u_m the mean speed), G = alpha E', E' = 2 E*; Moes M = W (2U)^-1/2, L = G (2U)^1/4",
         "# dimensional realisation: steel/steel E* = 206 GPa/(2 (1 - 0.3^2)), R = 10 mm, eta0 = 0.05 Pa s; alpha and u_m follow",
         "# fits: h_min_dowson_higginson (D&H 1977, 2.65 U^0.70 G^0.54 W^-0.13); h_min_pan_hamrock (P&H 1989, 1.714 W^-0.128 U^0.694 G^0.568);",
         "#   h_c_pan_hamrock (P&H 1989, 2.922 W^-0.166 U^0.692 G^0.470); h_c_dowson_toyoda (D&T 1979, 3.06 U^0.69 G^0.56 W^-0.10)",
         "# caveat: the fits' stated (W, U, G) ranges and accuracies were not retrievable in this session (README 'Film formulas')"],
        ["case", "W", "U", "G", "M", "L", "radius_m", "composite_modulus_Pa", "viscosity_Pa_s", "pressure_viscosity_per_Pa",
         "entrainment_m_per_s", "line_load_N_per_m", "hertz_halfwidth_over_R", "hertz_pressure_over_Eprime",
         "h_min_dowson_higginson_over_R", "h_min_pan_hamrock_over_R", "h_c_pan_hamrock_over_R", "h_c_dowson_toyoda_over_R"],
        smooth_rows),
    "roughness_attenuation.csv": (
        ["# source: Venner, Couhier, Lubrecht & Greenwood, Amplitude reduction of waviness in transient EHL line contacts,",
         "#   Tribology Series 32 (1997) 103-112 (Proc. 23rd Leeds-Lyon Symposium), abstract: A_d = the film thickness amplitude",
         "#   at X = 0; A_d/A_i independent of A_i (A_i < H_c and above); A_d/A_i = F(nabla) for all (M, L) with",
         "#   nabla = (lambda/b) M^(3/4)/L^(1/2); lambda/b < 1 hardly deformed, long wavelengths nearly vanish",
         "# conditions: one-sided waviness, pure rolling (slide_roll 0: the waviness moves at the mean speed), smooth film datum H_c",
         "# expected: cases of one group agree (the collapse); A_d/A_i falls with nabla; the amplitude pair agrees (linearity)",
         "# caveat: the curve F itself was not retrievable in this session (README 'Roughness'); no row asserts a value of F"],
        ["case", "M", "L", "slide_roll", "wavelength_over_b", "amplitude_over_hc", "nabla", "group"], waviness_rows),
}


def fmt(v):
    return f"{v:.12g}" if isinstance(v, float) else str(v)


def write_table(name, head, columns, rows):
    with open(os.path.join(HERE, name), "w", newline="") as f:
        for line in head:
            f.write(line + "\n")
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({c: fmt(r[c]) for c in columns})


def check_table(name, columns, rows):
    with open(os.path.join(HERE, name)) as f:
        stored = list(csv.DictReader(line for line in f if not line.startswith("#")))
    bad = 0
    if len(stored) != len(rows):
        print(f"{name}: {len(stored)} rows stored, {len(rows)} computed")
        return 1
    for s, r in zip(stored, rows):
        for c in columns:
            a, b = s[c], fmt(r[c])
            try:
                same = math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=0.0) or a == b
            except ValueError:
                same = a == b
            if not same:
                print(f"{name}: {s.get(columns[0])} {c}: stored {a}, computed {b}")
                bad += 1
    print(f"{name}: {len(rows)} rows, {bad} differ")
    return bad


def main(argv):
    bad = 0
    for name, (head, columns, make) in TABLES.items():
        rows = make()
        if "--write" in argv:
            write_table(name, head, columns, rows)
            print(f"wrote {name} ({len(rows)} rows)")
        else:
            bad += check_table(name, columns, rows)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
