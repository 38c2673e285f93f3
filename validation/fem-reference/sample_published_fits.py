#!/usr/bin/python3
"""Sample the published finite-element-based fits of Kogut & Etsion (2002) and Jackson & Green
(2005) into reference tables for `geartrib fit` (validation/fem-reference/*.csv).

These are the papers' fitted equations evaluated independently of geartrib's code (plain
Python), for 45 steel (nu = 0.3, S_y = 418 MPa, E = 206 GPa, composite E_t = 113.19 GPa), and
labelled as fits to FEM, not raw FEM. Both are normalised by the CEB critical values
(delta_c = (pi k H/(2 E_t))^2 R, k = 0.454 + 0.41 nu, H = 2.8 S_y), the continuous model's own:
Jackson-Green's own delta_c is 0.08% smaller and is converted. Run from the repository root:
    /usr/bin/python3 validation/fem-reference/sample_published_fits.py
"""
import math
import os

NU, SY, E = 0.3, 418e6, 206e9
ET = E / (2 * (1 - NU * NU))
K = 0.454 + 0.41 * NU
C = 1.295 * math.exp(0.736 * NU)
B = 0.14 * math.exp(23 * SY / E)
DC_RATIO = (C / (K * 2.8)) ** 2  # delta_c(JG) / delta_c(CEB)
HERE = os.path.dirname(os.path.abspath(__file__))


def kogut_etsion(d):
    if d <= 1: return d ** 1.5, d
    if d <= 6: return 1.03 * d ** 1.425, 0.93 * d ** 1.136
    if d <= 110: return 1.40 * d ** 1.263, 0.94 * d ** 1.146
    return 3 * d / K, 2 * d  # fully plastic branch of the model


def jackson_green_own(d):
    if d <= 1.9: return d ** 1.5, d
    a_over_r = math.pi * C * (SY / ET) / 2 * math.sqrt(d) * (d / 1.9) ** (B / 2)
    hg = 2.84 * (1 - math.exp(-0.82 * a_over_r ** -0.7))
    return (math.exp(-0.25 * d ** (5 / 12)) * d ** 1.5 + 4 * hg / C * (1 - math.exp(-d ** (5 / 9) / 25)) * d,
            d * (d / 1.9) ** B)


def jackson_green(d):
    load, area = jackson_green_own(d / DC_RATIO)
    return load * DC_RATIO ** 1.5, area * DC_RATIO


def write(name, header, law, points):
    path = os.path.join(HERE, name)
    with open(path, "w") as f:
        f.write("".join(f"# {line}\n" for line in header))
        f.write("delta_star,load_star,area_star,mean_pressure_over_yield\n")
        for d in points:
            load, area = law(d)
            # F/A over S_y with F_c/A_c = (2/3) k H
            f.write(f"{d:.10g},{load:.12g},{area:.12g},{load / area * 2 / 3 * K * 2.8:.12g}\n")
    print("wrote", path)


def log_space(lo, hi, n):
    return [lo * (hi / lo) ** (i / (n - 1)) for i in range(n)]


common = ["material: 45 steel, nu 0.3, S_y 418 MPa, E 206 GPa, E_t 113.19 GPa, H = 2.8 S_y",
          "units: dimensionless; delta_star, load_star, area_star normalised by the CEB critical values "
          "(k = 0.454 + 0.41 nu); mean_pressure_over_yield = (F/A)/S_y",
          "generator: validation/fem-reference/sample_published_fits.py"]
write("kogut-etsion-2002.csv",
      ["source: Kogut & Etsion, J. Appl. Mech. 69 (2002) 657, eqs. for 1 <= delta* <= 6 and 6 <= delta* <= 110, "
       "and the model's fully plastic branch beyond 110",
       "nature: fits to finite-element results (elastic-perfectly plastic sphere on a rigid flat), not raw FEM; "
       "the fully plastic branch is analytic"] + common,
      kogut_etsion, log_space(1.05, 110, 40) + log_space(150, 1e4, 12))
write("jackson-green-2005.csv",
      ["source: Jackson & Green, J. Tribol. 127 (2005) 343, eqs. for P*, A* (Hertz below delta* = 1.9), "
       "H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)], B = 0.14 exp(23 S_y/E)",
       "nature: fits to finite-element results, not raw FEM; sampled over 1 <= delta* <= 110, the range of "
       "Kogut-Etsion's FEM (Jackson-Green's area keeps growing past 2 pi R delta beyond it)",
       "normalisation: converted from Jackson-Green's own delta_c (C = 1.295 exp(0.736 nu)) to CEB's"] + common,
      jackson_green, log_space(1.05, 110, 40))
