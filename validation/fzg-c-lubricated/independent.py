#!/usr/bin/python3
"""Re-evaluation and independent computation of the lubrication numbers of fzg-c-lubricated.toml at A..E.

Usage: validation/fzg-c-lubricated/independent.py RUN.h5 [CASE.toml]

Two kinds of check, kept apart because they can catch different errors:
- RE-EVALUATED (the same published formulas, written again here from their sources, with this
  script's own unit parser, TOML reading, gear geometry, kinematics and oil properties): catches
  wrong units, temperatures, inputs and plumbing; it cannot catch a wrong formula or constant,
  since it types the same one. The film (Dowson-Higginson), Gupta's inlet heating, lambda, the ISO
  mean coefficients, the ISO/TS 6336-20 flash temperature (eq. A.5) and bulk temperature, h_Y and
  lambda_GF.
- INDEPENDENT (another derivation): the flash temperatures by numerical integration of the moving
  band source (validation/flash-temperature/moving_source.py), with the run's local friction and
  with ISO/TS 6336-22's mu_mC, at the named points.
From the run's HDF5 it takes only what belongs to other parts of geartrib: the load sharing (line
load per position and at the named points, which stand where they are: B and D with the single
pair's load), the ISO effective tip relief C_eff (ISO 6336-1 stiffness), the local friction (for the
local flash temperature), and for the strict comparison the bulk temperature.

Formulas (SI unless stated):
  E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2); u = (v1 + v2)/2; R = rho1 rho2/(rho1 + rho2)
  Dowson & Higginson (1977) minimum film: h = R 2.65 U^0.70 G^0.54 W^-0.13,
      U = eta u/(E' R), G = alpha E', W = w/(E' R), eta and alpha at the bulk temperature
  Gupta, Cheng, Zhu & Wedeven (1992) inlet heating: phi = (1 - 13.2 (p_h/E') L^0.42) /
      (1 + 0.213 (1 + 2.23 SRR^0.83) L^0.64), L = beta eta u^2/k_f, beta = -d ln(eta)/dT, SRR = |v1 - v2|/u
  film = phi h; lambda_smooth_film = film / sqrt(Rq1^2 + Rq2^2), Rq = sqrt(pi/2) Ra (Gaussian profile)
  Walther / ASTM D341: log10 log10(nu + 0.7) = A - B log10(T/K), nu in mm^2/s through the 40/100 degC points;
      rho(T) = rho15 (1 - c (T - 15 degC)); eta = nu rho
  alpha(T) = alpha_ref (1 + 516 (1/T - 1/311))/(1 + 516 (1/T_ref - 1/311)) (ISO/TR 15144-1 temperature law,
      anchored at the lubricant file's measured alpha)
  ISO/TS 6336-21/-22 mean friction: mu_mC = 0.045 (w_Bt/(v_SigmaC rho_redC))^0.2 eta_oil^-0.05 X_R X_L,
      X_R = 2.2 (Ra/rho_redC)^0.25; N/mm (at least 150), m/s, mm, mPa s (oil temperature), um; w_Bt = T1/(r1 b)
  ISO/TS 6336-20 mean friction: mu_m = 0.060 (w_Bt/(v_SigmaC rho_redC))^0.2 X_L eta_oil^-0.05 Ra^0.25
  ISO/TS 6336-20 flash temperature (ISO/TR 13989-1 A.5): theta = mu_m X_M X_J X_G (X_Gamma w_Bt)^0.75 v_t^0.5/a^0.25,
      X_M = E_r^0.25/B_M (x 1000, ISO units), X_G = 0.51 X_ab sqrt(u+1) |sqrt(1+G) - sqrt(1-G/u)|/((1+G)^0.25 (u-G)^0.25),
      X_ab = 1.22 sin^0.25 a_wt cos^0.25 a_n/(cos^0.5 a_wt cos^0.5 a_t), X_J = 1 + C_eff/50 (-G/(G_E - G_A))^3 (G < 0),
      X_Gamma = the run's load share (ISO load sharing), v_t = omega1 r1
  Bulk temperature (ISO/TS 6336-20): theta_M = theta_oil + 0.47 mean(theta_fl) along A..E (trapezoidal)
  ISO/TS 6336-22 (ISO/TR 15144-1): h_Y = 1.6 R G^0.6 U^0.7 W^-0.13 S_GF^0.22, U = eta_M (v1 + v2)/(2 E' R),
      W = 2 pi p_H^2/E'^2, S_GF = alpha(theta_B) eta(theta_B)/(alpha_M eta_M), theta_B = theta_M + Blok(mu_mC);
      lambda_GF = h_Y / ((Ra1 + Ra2)/2)
"""
import math
import os
import re
import sys
import tomllib

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "flash-temperature"))
import moving_source  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "fzg-c-lubricated.toml")
POINTS = ("A", "B", "C", "D", "E")
ZERO_C = 273.15

# Unit factors to SI (this script's own table; only the units these files use).
UNITS = {
    "": 1.0, "m": 1.0, "mm": 1e-3, "um": 1e-6,
    "deg": math.pi / 180.0, "rad": 1.0,
    "N m": 1.0, "rpm": 2.0 * math.pi / 60.0,
    "Pa": 1.0, "MPa": 1e6, "GPa": 1e9,
    "1/Pa": 1.0, "1/K": 1.0, "m^2/N": 1.0,
    "mm^2/s": 1e-6, "kg/m^3": 1.0,
    "W/(m K)": 1.0, "J/(kg K)": 1.0,
    "K": 1.0,
}


def si(value):
    """A case-file value in SI: a bare number, or '<number> <unit>' (degC converted to K)."""
    if isinstance(value, (int, float)):
        return float(value)
    m = re.fullmatch(r"\s*([-+0-9.eE]+)\s*(.*?)\s*", value)
    if not m:
        raise ValueError(f"not a quantity: {value!r}")
    number, unit = float(m.group(1)), m.group(2)
    if unit == "degC":
        return number + ZERO_C
    if unit not in UNITS:
        raise ValueError(f"unit {unit!r} not in independent.py's table ({value!r})")
    return number * UNITS[unit]


def load_toml(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


# --- the FZG load stage ---------------------------------------------------------------------------
FZG_TABLE = os.path.join(os.path.dirname(os.path.dirname(HERE)), "gears", "fzg", "load-stages.csv")
FZG_ARM = {"A/8.3/90": "0.5m", "PT-C": "0.5m", "GF-C/8.3/90": "0.35m"}  # the tests' lever arms (gears/fzg/README.md)


def fzg_torque(stage, test):
    """The pinion torque [N m] of an FZG load stage, read from the shipped table (gears/fzg)."""
    import csv
    with open(FZG_TABLE) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if int(row["load_stage"]) == int(stage):
                return float(row[f"pinion_torque_arm_{FZG_ARM[test]}[N m]"])
    raise ValueError(f"no FZG load stage {stage} in {FZG_TABLE}")


# --- the oil ------------------------------------------------------------------------------------
class Oil:
    def __init__(self, path):
        d = load_toml(path)
        self.name = d["name"]
        self.nu40 = si(d["kinematic_viscosity_40C"]) * 1e6   # mm^2/s
        self.nu100 = si(d["kinematic_viscosity_100C"]) * 1e6
        self.rho15 = si(d["density_15C"])
        self.c = si(d["density_temperature_coefficient"])
        self.alpha_ref = si(d["pressure_viscosity_coefficient"]) if "pressure_viscosity_coefficient" in d else None
        self.t_alpha = si(d.get("pressure_viscosity_temperature", "40 degC"))
        self.k = si(d["thermal_conductivity"])
        self.base = d["base_oil"]
        self.x_l_given = float(d.get("iso_lubricant_factor", 0.0))
        self.t_max = si(d["max_temperature"])
        # Walther constants: W(T) = A - B log10 T through the 40 and 100 degC points.
        w40 = math.log10(math.log10(self.nu40 + 0.7))
        w100 = math.log10(math.log10(self.nu100 + 0.7))
        l40, l100 = math.log10(313.15), math.log10(373.15)
        self.B = (w40 - w100) / (l100 - l40)
        self.A = w40 + self.B * l40

    def nu(self, t):
        """Kinematic viscosity [mm^2/s] at t [K]."""
        return 10.0 ** (10.0 ** (self.A - self.B * math.log10(t))) - 0.7

    def density(self, t):
        return self.rho15 * (1.0 - self.c * (t - (15.0 + ZERO_C)))

    def eta(self, t):
        """Dynamic viscosity [Pa s]."""
        return self.nu(t) * 1e-6 * self.density(t)

    def beta(self, t):
        """-d ln(eta)/dT [1/K], analytically from Walther's law and the linear density."""
        y = 10.0 ** (self.A - self.B * math.log10(t))      # log10(nu + 0.7)
        nu = 10.0 ** y - 0.7
        dnu_dt = -(nu + 0.7) * math.log(10.0) * self.B * y / t
        drho_dt = -self.rho15 * self.c
        return -(dnu_dt / nu + drho_dt / self.density(t))

    def alpha(self, t):
        """Pressure-viscosity coefficient [1/Pa]: ISO/TR 15144-1 temperature law."""
        law = lambda temp: 1.0 + 516.0 * (1.0 / temp - 1.0 / 311.0)  # noqa: E731
        if self.alpha_ref is not None:
            return self.alpha_ref * law(t) / law(self.t_alpha)
        eta38 = self.eta(311.15) * 1e3  # mPa s
        return 2.657e-8 * eta38 ** 0.1348 * law(t)

    def x_l(self):
        """ISO/TS 6336-20's table (ISO/TR 13989-1); an ester's file gives its own."""
        return self.x_l_given or {"mineral": 1.0, "pao": 0.8, "polyglycol-insoluble": 0.7,
                                  "polyglycol-water-soluble": 0.6, "phosphate-ester": 1.3,
                                  "traction-fluid": 1.5}[self.base]


# --- the gears ----------------------------------------------------------------------------------
class Gears:
    """Spur-gear geometry and kinematics from the case (independent of geartrib's kinematics)."""

    def __init__(self, case_path):
        self.case_path = case_path
        c = load_toml(case_path)
        self.case = c
        here = os.path.dirname(os.path.abspath(case_path))
        g = c["gear_pair"]
        self.m = si(g["module"])
        self.b = si(g["face_width"])
        self.alpha = si(g["pressure_angle"])
        self.z1, self.z2 = c["pinion"]["teeth"], c["wheel"]["teeth"]
        self.a_w = si(g["center_distance"])
        a0 = self.m * (self.z1 + self.z2) / 2.0
        self.alpha_w = math.acos(a0 * math.cos(self.alpha) / self.a_w)
        self.rb1 = self.m * self.z1 / 2.0 * math.cos(self.alpha)
        self.rb2 = self.m * self.z2 / 2.0 * math.cos(self.alpha)
        self.r1 = self.m * self.z1 / 2.0                      # reference pitch radius
        self.rw1 = self.a_w * self.z1 / (self.z1 + self.z2)   # operating pitch radii
        self.rw2 = self.a_w * self.z2 / (self.z1 + self.z2)
        self.ra1 = si(c["pinion"]["tip_diameter"]) / 2.0
        self.ra2 = si(c["wheel"]["tip_diameter"]) / 2.0
        self.t1t2 = self.a_w * math.sin(self.alpha_w)
        self.pb = math.pi * self.m * math.cos(self.alpha)
        s_e = math.sqrt(self.ra1 ** 2 - self.rb1 ** 2)
        s_a = self.t1t2 - math.sqrt(self.ra2 ** 2 - self.rb2 ** 2)
        self.s = {"A": s_a, "B": s_e - self.pb, "C": self.rb1 * math.tan(self.alpha_w), "D": s_a + self.pb, "E": s_e}
        op = c["operating"]
        self.torque = si(op["pinion_torque"]) if "pinion_torque" in op else fzg_torque(op["fzg_load_stage"],
                                                                                      op["fzg_test"])
        self.w1 = si(op["pinion_speed"])
        self.w2 = self.w1 * self.z1 / self.z2
        self.t_oil = si(op["oil_temperature"])
        self.t_bulk_given = si(op["bulk_temperature"]) if "bulk_temperature" in op else None
        self.ra = (si(c["pinion"]["flank"]["ra"]), si(c["wheel"]["flank"]["ra"]))
        self.oil = Oil(os.path.join(here, c["lubricant"]["file"]))
        mats = [load_toml(os.path.join(here, c[g_]["material"])) for g_ in ("pinion", "wheel")]
        e = [si(mm["youngs_modulus"]) for mm in mats]
        nu = [float(mm["poisson_ratio"]) for mm in mats]
        self.e_red = 2.0 / ((1 - nu[0] ** 2) / e[0] + (1 - nu[1] ** 2) / e[1])
        self.thermal = [(si(mm["thermal_conductivity"]), si(mm["density"]), si(mm["specific_heat"])) for mm in mats]
        self.b_m = [math.sqrt(k * rho * c) for k, rho, c in self.thermal]

    # kinematics at a position s along the line of action, measured from T1 (pinion side)
    def rho(self, s):
        return s, self.t1t2 - s

    def radius(self, s):
        r1, r2 = self.rho(s)
        return r1 * r2 / (r1 + r2)

    def speeds(self, s):
        r1, r2 = self.rho(s)
        return self.w1 * r1, self.w2 * r2

    def pitch_line_velocity(self):
        return self.w1 * self.rw1

    def pitch_point(self):
        """(w_Bt N/mm, v_SigmaC m/s, rho_redC mm, eta_oil mPa s, Ra um) as the ISO formulas take them."""
        w_bt = self.torque / (self.r1 * self.b) * 1e-3
        v1c, v2c = self.speeds(self.s["C"])
        return (w_bt, v1c + v2c, self.radius(self.s["C"]) * 1e3, self.oil.eta(self.t_oil) * 1e3,
                0.5 * (self.ra[0] + self.ra[1]) * 1e6)

    def mean_friction_iso(self):
        """ISO/TS 6336-21/-22 mu_mC at the pitch point, in the standard's units (w_Bt at least 150 N/mm)."""
        w_bt, v_sum, rho, eta, ra = self.pitch_point()
        x_r = 2.2 * (ra / rho) ** 0.25
        return 0.045 * (max(w_bt, 150.0) / (v_sum * rho)) ** 0.2 * eta ** -0.05 * x_r * self.oil.x_l()

    def mean_friction_iso_flash(self):
        """ISO/TS 6336-20 mu_m (ISO/TR 13989-1 eqs. 25-28 as transcribed) at the pitch point."""
        w_bt, v_sum, rho, eta, ra = self.pitch_point()
        return 0.060 * (w_bt / (v_sum * rho)) ** 0.2 * self.oil.x_l() * eta ** -0.05 * ra ** 0.25

    def gamma(self, s):
        return s / self.s["C"] - 1.0

    def iso_flash(self, s, share, c_eff):
        """ISO/TS 6336-20 eq. A.5 at s with X_Gamma = share and the effective tip relief c_eff [m]."""
        u = self.z2 / self.z1
        g = self.gamma(s)
        x_ab = (1.22 * math.sin(self.alpha_w) ** 0.25 * math.cos(self.alpha) ** 0.25 /
                (math.cos(self.alpha_w) ** 0.5 * math.cos(self.alpha) ** 0.5))
        x_g = (0.51 * x_ab * math.sqrt(u + 1.0) * abs(math.sqrt(1.0 + g) - math.sqrt(1.0 - g / u)) /
               ((1.0 + g) ** 0.25 * (u - g) ** 0.25))
        e_r_nmm2 = self.e_red * 1e-6
        b_iso = 0.5 * (self.b_m[0] + self.b_m[1]) / math.sqrt(1000.0)
        x_m = e_r_nmm2 ** 0.25 / b_iso * 1000.0
        g_a, g_e = self.gamma(self.s["A"]), self.gamma(self.s["E"])
        x_j = 1.0 if g >= 0.0 else max(1.0, 1.0 + c_eff * 1e6 / 50.0 * (-g / (g_e - g_a)) ** 3)
        w_bt = self.torque / (self.r1 * self.b) * 1e-3
        v_t = self.w1 * self.r1
        return self.mean_friction_iso_flash() * x_m * x_j * x_g * (share * w_bt) ** 0.75 * v_t ** 0.5 / \
            (self.a_w * 1e3) ** 0.25

    def materials(self):
        """(k, rho, c) of pinion and wheel, for the moving-source integration."""
        return self.thermal


def flash_temperature(mu, w, b_h, v1, v2, g):
    """The flash temperature [K] by integrating the moving band source (not Blok's closed form)."""
    return moving_source.flash_temperature(mu, w, b_h, v1, v2, *g.materials())[0]


def read_run(h5):
    with h5py.File(h5, "r") as f:
        mesh = {k: f["mesh"][k][()] for k in f["mesh"]}
        lub = {k: f["lubrication"][k][()] for k in f["lubrication"] if isinstance(f["lubrication"][k], h5py.Dataset)}
        points = {k: f["lubrication/points"][k][()] for k in f["lubrication/points"]}
        mesh_attrs = dict(f["mesh"].attrs)
        lub_attrs = dict(f["lubrication"].attrs)
    points["point"] = [x.decode() if isinstance(x, bytes) else x for x in points["point"]]
    return mesh, lub, points, mesh_attrs, lub_attrs


def compute(h5, case_path=CASE, bulk=None):
    """Per named point (at its own place, from /lubrication/points): the re-evaluated and independent
    values; and along the path the ISO quantities.

    bulk: the bulk temperature [K] the film uses; None takes the run's (so that only the formulas are
    compared), 'own' this script's estimate."""
    g = Gears(case_path)
    mesh, lub, points, mesh_attrs, lub_attrs = read_run(h5)
    s = mesh["s_m"]
    c_eff = float(lub_attrs["iso_effective_tip_relief_m"])
    mu_mc = g.mean_friction_iso()
    mu_m = g.mean_friction_iso_flash()
    iso_all = np.array([g.iso_flash(x, share, c_eff) for x, share in zip(s, mesh["load_share"])])
    mean_trapz = float(np.sum(0.5 * (iso_all[1:] + iso_all[:-1]) * np.diff(s)) / (s[-1] - s[0]))
    own_bulk = g.t_oil + 0.47 * mean_trapz
    if g.t_bulk_given:
        own_bulk = g.t_bulk_given
    t_m = {None: float(lub_attrs["bulk_temperature_K"]), "own": own_bulk}[bulk]
    oil = g.oil
    eta_m, alpha_m, beta_m = oil.eta(t_m), oil.alpha(t_m), oil.beta(t_m)
    rq = math.sqrt(math.pi / 2.0) * math.hypot(*g.ra)
    ra_mean = 0.5 * (g.ra[0] + g.ra[1])
    out = {}
    for k, p in enumerate(points["point"]):
        if p not in POINTS:
            continue
        si_ = float(points["s_m"][k])
        w = float(points["line_load_N_per_m"][k])
        r = g.radius(si_)
        v1, v2 = g.speeds(si_)
        u = 0.5 * (v1 + v2)
        b_h = math.sqrt(8.0 * w * r / (math.pi * g.e_red))   # Hertz from the point's line load
        p_h = 2.0 * w / (math.pi * b_h)
        U = eta_m * u / (g.e_red * r)
        G = alpha_m * g.e_red
        W = w / (g.e_red * r)
        h_iso = r * 2.65 * U ** 0.70 * G ** 0.54 * W ** -0.13
        L = beta_m * eta_m * u ** 2 / oil.k
        srr = abs(v1 - v2) / u
        phi = (1.0 - 13.2 * (p_h / g.e_red) * L ** 0.42) / (1.0 + 0.213 * (1.0 + 2.23 * srr ** 0.83) * L ** 0.64)
        film = phi * h_iso
        th_blok_iso = flash_temperature(mu_mc, w, b_h, v1, v2, g)
        t_b = t_m + th_blok_iso
        s_gf = oil.alpha(t_b) * oil.eta(t_b) / (alpha_m * eta_m)
        U_y = eta_m * (v1 + v2) / (2.0 * g.e_red * r)
        W_y = 2.0 * math.pi * p_h ** 2 / g.e_red ** 2
        h_y = 1.6 * r * G ** 0.6 * U_y ** 0.7 * W_y ** -0.13 * s_gf ** 0.22
        share = w / (g.torque / g.rb1 / g.b)   # X_Gamma: the point's share of the normal load
        iso_fl = g.iso_flash(si_, share, c_eff)
        out[p] = {
            "index": k, "s_m": si_, "s_named_m": g.s[p], "line_load_N_per_m": w,
            "film_m": film, "lambda_smooth_film": film / rq, "iso_film_hy_m": h_y, "iso_lambda_gf": h_y / ra_mean,
            "iso_flash_temperature_K": iso_fl, "iso_contact_temperature_K": t_m + iso_fl,
            # Independent: the moving band source integrated, with the point's local friction.
            "flash_temperature_K": flash_temperature(float(points["friction_coefficient"][k]), w, b_h, v1, v2, g),
            "blok_flash_temperature_iso_mu_K": th_blok_iso,
        }
    summary = {
        "mu_mc": mu_mc, "mu_m": mu_m, "bulk_temperature_K": own_bulk, "bulk_used_K": t_m,
        "mean_iso_flash_K": mean_trapz, "max_iso_flash_K": float(iso_all.max()),
        "eta_bulk_Pa_s": eta_m, "alpha_bulk_per_Pa": alpha_m, "beta_bulk_per_K": beta_m,
        "eta_oil_Pa_s": oil.eta(g.t_oil), "composite_rq_m": rq, "mean_ra_m": ra_mean,
        "pitch_line_velocity_m_per_s": g.pitch_line_velocity(), "operating_pressure_angle_deg": math.degrees(g.alpha_w),
        "d_w1_m": 2 * g.rw1, "d_w2_m": 2 * g.rw2, "oil_max_temperature_K": oil.t_max,
        "s_named": dict(g.s),
    }
    return out, summary


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    case = argv[2] if len(argv) > 2 else CASE
    pts, summ = compute(argv[1], case)
    own, _ = compute(argv[1], case, bulk="own")
    print(f"mu_mC {summ['mu_mc']:.6g} (ISO/TS 6336-21/-22), mu_m {summ['mu_m']:.6g} (ISO/TS 6336-20); bulk (own "
          f"estimate) {summ['bulk_temperature_K'] - ZERO_C:.3f} degC, (run's) {summ['bulk_used_K'] - ZERO_C:.3f} degC; "
          f"eta {summ['eta_bulk_Pa_s'] * 1e3:.5g} mPa s, alpha {summ['alpha_bulk_per_Pa'] * 1e9:.5g} 1/GPa, beta "
          f"{summ['beta_bulk_per_K']:.5g} 1/K at the run's bulk")
    print(f"{'pt':<3} {'s mm':>8} {'w N/mm':>8} {'film um':>9} {'lambda':>7} {'ISO fl K':>9} {'flash K':>8} "
          f"{'h_Y um':>8} {'lam_GF':>7} {'film(own bulk)':>14}")
    for p in POINTS:
        r = pts[p]
        print(f"{p:<3} {r['s_m'] * 1e3:8.3f} {r['line_load_N_per_m'] * 1e-3:8.2f} {r['film_m'] * 1e6:9.5f} "
              f"{r['lambda_smooth_film']:7.4f} {r['iso_flash_temperature_K']:9.3f} {r['flash_temperature_K']:8.3f} "
              f"{r['iso_film_hy_m'] * 1e6:8.5f} {r['iso_lambda_gf']:7.4f} {own[p]['film_m'] * 1e6:14.5f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
