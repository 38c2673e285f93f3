#!/usr/bin/env python3
"""Sanity check of the lubricant data files lubricants/*.toml.

For every file: parses the values with their units, fits Walther's law (ASTM D341)
    log10(log10(nu_cSt + 0.7)) = A - B log10(T/K)
through the 40 and 100 degC viscosities, prints nu at 40/70/80/90/100 degC and the
ASTM D2270 viscosity index, and checks plausible ranges. Exit 0 if every file passes,
1 otherwise (each failure is printed). Standalone: Python >= 3.11 (tomllib), no other
dependencies.  Usage: python3 lubricants/check_walther.py [FILE.toml ...]
"""
import bisect
import math
import pathlib
import sys
import tomllib

# Unit table of the data files (value in SI = number * factor); temperatures handled apart.
UNITS = {
    "kinematic_viscosity": {"m^2/s": 1.0, "mm^2/s": 1e-6, "cSt": 1e-6},
    "density": {"kg/m^3": 1.0},
    "pv_coefficient": {"1/Pa": 1.0, "1/GPa": 1e-9, "m^2/N": 1.0},
    "conductivity": {"W/(m K)": 1.0},
    "specific_heat": {"J/(kg K)": 1.0},
    "per_temperature": {"1/K": 1.0},
    "pressure": {"Pa": 1.0, "MPa": 1e6, "GPa": 1e9},
}
KEYS = {  # key: (kind, required)
    "kinematic_viscosity_40C": ("kinematic_viscosity", True),
    "kinematic_viscosity_100C": ("kinematic_viscosity", True),
    "density_15C": ("density", True),
    "density_temperature_coefficient": ("per_temperature", True),
    "pressure_viscosity_coefficient": ("pv_coefficient", False),
    "pressure_viscosity_temperature": ("temperature", False),
    "thermal_conductivity": ("conductivity", True),
    "specific_heat": ("specific_heat", True),
    "eyring_stress": ("pressure", True),
    "limiting_shear_coefficient": ("dimensionless", True),
    "min_temperature": ("temperature", True),
    "max_temperature": ("temperature", True),
}
BASE_OILS = ("mineral", "pao", "ester", "polyglycol-insoluble", "polyglycol-water-soluble", "phosphate-ester",
             "traction-fluid")
# Plausible viscosity index by base oil (ASTM D2270); outside -> failure.
VI_RANGE = {"mineral": (70, 120), "pao": (120, 200), "ester": (110, 220), "polyglycol-insoluble": (150, 300),
            "polyglycol-water-soluble": (150, 300)}
# Plausible ranges in SI (key: (lo, hi)); the first four are the required ones of the brief.
RANGES = {
    "kinematic_viscosity_40C": (5e-6, 2000e-6),
    "density_15C": (750.0, 1100.0),
    "thermal_conductivity": (0.08, 0.25),
    "specific_heat": (1500.0, 2800.0),
    "kinematic_viscosity_100C": (2e-6, 200e-6),          # D2270 needs >= 2 mm^2/s
    "density_temperature_coefficient": (3e-4, 1.2e-3),
    "pressure_viscosity_coefficient": (0.5e-8, 4e-8),
    "eyring_stress": (0.5e6, 50e6),
    "limiting_shear_coefficient": (0.01, 0.2),
}

# ASTM D2270 Table 1: kinematic viscosity at 100 degC Y, and L, H (40 degC viscosities of the
# VI 0 and VI 100 oils with that Y), all in mm^2/s; rows "Y L H" separated by "|".
D2270_TABLE = """
2 7.994 6.394 | 2.1 8.64 6.894 | 2.2 9.309 7.41 | 2.3 10 7.944 | 2.4 10.71 8.496
2.5 11.45 9.063 | 2.6 12.21 9.647 | 2.7 13 10.25 | 2.8 13.8 10.87 | 2.9 14.63 11.5
3 15.49 12.15 | 3.1 16.36 12.82 | 3.2 17.26 13.51 | 3.3 18.18 14.21 | 3.4 19.12 14.93
3.5 20.09 15.66 | 3.6 21.08 16.42 | 3.7 22.09 17.19 | 3.8 23.13 17.97 | 3.9 24.19 18.77
4 25.32 19.56 | 4.1 26.5 20.37 | 4.2 27.75 21.21 | 4.3 29.07 22.05 | 4.4 30.48 22.92
4.5 31.96 23.81 | 4.6 33.52 24.71 | 4.7 35.13 25.63 | 4.8 36.79 26.57 | 4.9 38.5 27.53
5 40.23 28.49 | 5.1 41.99 29.46 | 5.2 43.76 30.43 | 5.3 45.53 31.4 | 5.4 47.31 32.37
5.5 49.09 33.34 | 5.6 50.87 34.32 | 5.7 52.64 35.29 | 5.8 54.42 36.26 | 5.9 56.2 37.23
6 57.97 38.19 | 6.1 59.74 39.17 | 6.2 61.52 40.15 | 6.3 63.32 41.13 | 6.4 65.18 42.14
6.5 67.12 43.18 | 6.6 69.16 44.24 | 6.7 71.29 45.33 | 6.8 73.48 46.44 | 6.9 75.72 47.51
7 78 48.57 | 7.1 80.25 49.61 | 7.2 82.39 50.69 | 7.3 84.53 51.78 | 7.4 86.66 52.88
7.5 88.85 53.98 | 7.6 91.04 55.09 | 7.7 93.2 56.2 | 7.8 95.43 57.31 | 7.9 97.72 58.45
8 100 59.6 | 8.1 102.3 60.74 | 8.2 104.6 61.89 | 8.3 106.9 63.05 | 8.4 109.2 64.18
8.5 111.5 65.32 | 8.6 113.9 66.48 | 8.7 116.2 67.64 | 8.8 118.5 68.79 | 8.9 120.9 69.94
9 123.3 71.1 | 9.1 125.7 72.27 | 9.2 128 73.42 | 9.3 130.4 74.57 | 9.4 132.8 75.73
9.5 135.3 76.91 | 9.6 137.7 78.08 | 9.7 140.1 79.27 | 9.8 142.7 80.46 | 9.9 145.2 81.67
10 147.7 82.87 | 10.1 150.3 84.08 | 10.2 152.9 85.3 | 10.3 155.4 86.51 | 10.4 158 87.72
10.5 160.6 88.95 | 10.6 163.2 90.19 | 10.7 165.8 91.4 | 10.8 168.5 92.65 | 10.9 171.2 93.92
11 173.9 95.19 | 11.1 176.6 96.45 | 11.2 179.4 97.71 | 11.3 182.1 98.97 | 11.4 184.9 100.2
11.5 187.6 101.5 | 11.6 190.4 102.8 | 11.7 193.3 104.1 | 11.8 196.2 105.4 | 11.9 199 106.7
12 201.9 108 | 12.1 204.8 109.4 | 12.2 207.8 110.7 | 12.3 210.7 112 | 12.4 213.6 113.3
12.5 216.6 114.7 | 12.6 219.6 116 | 12.7 222.6 117.4 | 12.8 225.7 118.7 | 12.9 228.8 120.1
13 231.9 121.5 | 13.1 235 122.9 | 13.2 238.1 124.2 | 13.3 241.2 125.6 | 13.4 244.3 127
13.5 247.4 128.4 | 13.6 250.6 129.8 | 13.7 253.8 131.2 | 13.8 257 132.6 | 13.9 260.1 134
14 263.3 135.4 | 14.1 266.6 136.8 | 14.2 269.8 138.2 | 14.3 273 139.6 | 14.4 276.3 141
14.5 279.6 142.4 | 14.6 283 143.9 | 14.7 286.4 145.3 | 14.8 289.7 146.8 | 14.9 293 148.2
15 296.5 149.7 | 15.1 300 151.2 | 15.2 303.4 152.6 | 15.3 306.9 154.1 | 15.4 310.3 155.6
15.5 313.9 157 | 15.6 317.5 158.6 | 15.7 321.1 160.1 | 15.8 324.6 161.6 | 15.9 328.3 163.1
16 331.9 164.6 | 16.1 335.5 166.1 | 16.2 339.2 167.7 | 16.3 342.9 169.2 | 16.4 346.6 170.7
16.5 350.3 172.3 | 16.6 354.1 173.8 | 16.7 358 175.4 | 16.8 361.7 177 | 16.9 365.6 178.6
17 369.4 180.2 | 17.1 373.3 181.7 | 17.2 377.1 183.3 | 17.3 381 184.9 | 17.4 384.9 186.5
17.5 388.9 188.1 | 17.6 392.7 189.7 | 17.7 396.7 191.3 | 17.8 400.7 192.9 | 17.9 404.6 194.6
18 408.6 196.2 | 18.1 412.6 197.8 | 18.2 416.7 199.4 | 18.3 420.7 201 | 18.4 424.9 202.6
18.5 429 204.3 | 18.6 433.2 205.9 | 18.7 437.3 207.6 | 18.8 441.5 209.3 | 18.9 445.7 211
19 449.9 212.7 | 19.1 454.2 214.4 | 19.2 458.4 216.1 | 19.3 462.7 217.7 | 19.4 467 219.4
19.5 471.3 221.1 | 19.6 475.7 222.8 | 19.7 479.7 224.5 | 19.8 483.9 226.2 | 19.9 488.6 227.7
20 493.2 229.5 | 20.2 501.5 233 | 20.4 510.8 236.4 | 20.6 519.9 240.1 | 20.8 528.8 243.5
21 538.4 247.1 | 21.2 547.5 250.7 | 21.4 556.7 254.2 | 21.6 566.4 257.8 | 21.8 575.6 261.5
22 585.2 264.9 | 22.2 595 268.6 | 22.4 604.3 272.3 | 22.6 614.2 275.8 | 22.8 624.1 279.6
23 633.6 283.3 | 23.2 643.4 286.8 | 23.4 653.8 290.5 | 23.6 663.3 294.4 | 23.8 673.7 297.9
24 683.9 301.8 | 24.2 694.5 305.6 | 24.4 704.2 309.4 | 24.6 714.9 313 | 24.8 725.7 317
25 736.5 320.9 | 25.2 747.2 324.9 | 25.4 758.2 328.8 | 25.6 769.3 332.7 | 25.8 779.7 336.7
26 790.4 340.5 | 26.2 801.6 344.4 | 26.4 812.8 348.4 | 26.6 824.1 352.3 | 26.8 835.5 356.4
27 847 360.5 | 27.2 857.5 364.6 | 27.4 869 368.3 | 27.6 880.6 372.3 | 27.8 892.3 376.4
28 904.1 380.6 | 28.2 915.8 384.6 | 28.4 927.6 388.8 | 28.6 938.6 393 | 28.8 951.2 396.6
29 963.4 401.1 | 29.2 975.4 405.3 | 29.4 987.1 409.5 | 29.6 998.9 413.5 | 29.8 1011 417.6
30 1023 421.7 | 30.5 1055 432.4 | 31 1086 443.2 | 31.5 1119 454 | 32 1151 464.9
32.5 1184 475.9 | 33 1217 487 | 33.5 1251 498.1 | 34 1286 509.6 | 34.5 1321 521.1
35 1356 532.5 | 35.5 1391 544 | 36 1427 555.6 | 36.5 1464 567.1 | 37 1501 579.3
37.5 1538 591.3 | 38 1575 603.1 | 38.5 1613 615 | 39 1651 627.1 | 39.5 1691 639.2
40 1730 651.8 | 40.5 1770 664.2 | 41 1810 676.6 | 41.5 1851 689.1 | 42 1892 701.9
42.5 1935 714.9 | 43 1978 728.2 | 43.5 2021 741.3 | 44 2064 754.4 | 44.5 2108 767.6
45 2152 780.9 | 45.5 2197 794.5 | 46 2243 808.2 | 46.5 2288 821.9 | 47 2333 835.5
47.5 2380 849.2 | 48 2426 863 | 48.5 2473 876.9 | 49 2521 890.9 | 49.5 2570 905.3
50 2618 919.6 | 50.5 2667 933.6 | 51 2717 948.2 | 51.5 2767 962.9 | 52 2817 977.5
52.5 2867 992.1 | 53 2918 1007 | 53.5 2969 1021 | 54 3020 1036 | 54.5 3073 1051
55 3126 1066 | 55.5 3180 1082 | 56 3233 1097 | 56.5 3286 1112 | 57 3340 1127 | 57.5 3396 1143
58 3452 1159 | 58.5 3507 1175 | 59 3563 1190 | 59.5 3619 1206 | 60 3676 1222 | 60.5 3734 1238
61 3792 1254 | 61.5 3850 1270 | 62 3908 1286 | 62.5 3966 1303 | 63 4026 1319 | 63.5 4087 1336
64 4147 1352 | 64.5 4207 1369 | 65 4268 1386 | 65.5 4329 1402 | 66 4392 1419 | 66.5 4455 1436
67 4517 1454 | 67.5 4580 1471 | 68 4645 1488 | 68.5 4709 1506 | 69 4773 1523 | 69.5 4839 1541
70 4905 1558"""
D2270 = sorted(tuple(float(v) for v in row.split())
               for row in D2270_TABLE.replace("\n", "|").split("|") if row.strip())
D2270_Y = [r[0] for r in D2270]


def d2270_lh(y):
    """L and H of ASTM D2270 for the 100 degC viscosity y (mm^2/s), y >= 2."""
    if y > 70.0:
        return 0.8353 * y * y + 14.67 * y - 216.0, 0.1684 * y * y + 11.85 * y - 97.0
    i = min(max(bisect.bisect_right(D2270_Y, y) - 1, 0), len(D2270) - 2)
    (y0, l0, h0), (y1, l1, h1) = D2270[i], D2270[i + 1]
    t = (y - y0) / (y1 - y0)
    return l0 + t * (l1 - l0), h0 + t * (h1 - h0)


def viscosity_index(u, y):
    """ASTM D2270 VI from nu40 = u and nu100 = y (mm^2/s): procedure A (VI <= 100) or B."""
    low, high = d2270_lh(y)
    if u >= high:
        return (low - u) / (low - high) * 100.0
    n = (math.log10(high) - math.log10(u)) / math.log10(y)
    return (10.0 ** n - 1.0) / 0.00715 + 100.0


def parse(value, kind):
    """SI value of a file value: a number, or a string '<number> <unit>' of the unit table."""
    if kind == "dimensionless":
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"expected a number, got {value!r}")
        return float(value)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)  # SI number (kelvin for temperatures)
    if not isinstance(value, str) or " " not in value.strip():
        raise ValueError(f"expected a number or '<number> <unit>', got {value!r}")
    number, unit = value.strip().split(" ", 1)
    x = float(number)
    unit = unit.strip()
    if kind == "temperature":
        if unit == "K":
            return x
        if unit == "degC":
            return x + 273.15
        raise ValueError(f"unit {unit!r} is not a temperature unit (K, degC)")
    table = UNITS[kind]
    if unit not in table:
        raise ValueError(f"unit {unit!r} not accepted here (one of: {', '.join(table)})")
    return x * table[unit]


def walther(nu40, nu100):
    """A, B of log10(log10(nu_cSt + 0.7)) = A - B log10(T/K) through the 40 and 100 degC points."""
    t1, t2 = 313.15, 373.15
    z1 = math.log10(math.log10(nu40 + 0.7))
    z2 = math.log10(math.log10(nu100 + 0.7))
    b = (z1 - z2) / (math.log10(t2) - math.log10(t1))
    return z1 + b * math.log10(t1), b


def walther_nu(a, b, t_kelvin):
    """Kinematic viscosity in cSt (mm^2/s) at t_kelvin."""
    return 10.0 ** (10.0 ** (a - b * math.log10(t_kelvin))) - 0.7


def check(path):
    """Print one oil's summary; return the list of failures (empty if it passes)."""
    errors = []
    with open(path, "rb") as f:
        data = tomllib.load(f)
    for key in ("name", "source", "base_oil"):
        if not isinstance(data.get(key), str) or not data[key].strip():
            errors.append(f"{key}: missing or not a text")
    if data.get("base_oil") not in BASE_OILS:
        errors.append(f"base_oil: {data.get('base_oil')!r} not one of {BASE_OILS}")
    known = set(KEYS) | {"name", "source", "base_oil", "iso_lubricant_factor", "traction_curves"}
    if data.get("base_oil") == "ester" and "iso_lubricant_factor" not in data:
        errors.append("iso_lubricant_factor: required for an ester (ISO/TS 6336-20 tabulates no X_L for it)")
    if "iso_lubricant_factor" in data and not 0 < data["iso_lubricant_factor"] <= 2:
        errors.append("iso_lubricant_factor: must lie in (0, 2]")
    errors += [f"{key}: unknown key" for key in data if key not in known]
    v = {}
    for key, (kind, required) in KEYS.items():
        if key not in data:
            if required:
                errors.append(f"{key}: missing")
            continue
        try:
            v[key] = parse(data[key], kind)
        except ValueError as e:
            errors.append(f"{key}: {e}")
    if ("pressure_viscosity_coefficient" in data) != ("pressure_viscosity_temperature" in data):
        errors.append("pressure_viscosity_coefficient and _temperature must be given together")
    for key, (lo, hi) in RANGES.items():
        if key in v and not lo <= v[key] <= hi:
            errors.append(f"{key}: {v[key]:.6g} (SI) outside the plausible range [{lo:g}, {hi:g}]")
    if errors and ("kinematic_viscosity_40C" not in v or "kinematic_viscosity_100C" not in v):
        return errors
    nu40, nu100 = v["kinematic_viscosity_40C"] * 1e6, v["kinematic_viscosity_100C"] * 1e6
    if not nu100 < nu40:
        return errors + ["kinematic_viscosity_100C must be below kinematic_viscosity_40C"]
    a, b = walther(nu40, nu100)
    for t, nu_file in ((313.15, nu40), (373.15, nu100)):
        rel = abs(walther_nu(a, b, t) - nu_file) / nu_file
        if not rel <= 1e-9:
            errors.append(f"Walther fit misses the file's value at {t - 273.15:.0f} degC by {rel:.3g} (relative)")
    tmin, tmax = v.get("min_temperature"), v.get("max_temperature")
    if tmin is not None and tmax is not None:
        if not tmin < tmax:
            errors.append("min_temperature must be below max_temperature")
        elif not tmin <= 313.15 and 373.15 <= tmax:
            errors.append("the range [min_temperature, max_temperature] must contain 40 and 100 degC")
        else:
            for t in (tmin, tmax):
                nu_t = walther_nu(a, b, t)
                if not (math.isfinite(nu_t) and 0.0 < nu_t < 1e6):
                    errors.append(f"Walther viscosity {nu_t:.4g} cSt at {t - 273.15:.0f} degC is not plausible")
    vi = viscosity_index(nu40, nu100)
    lo, hi = VI_RANGE.get(data.get("base_oil"), (-1e9, 1e9))
    if not lo <= vi <= hi:
        errors.append(f"viscosity index {vi:.1f} outside the plausible range [{lo}, {hi}] for {data.get('base_oil')}")
    nus = "  ".join(f"{walther_nu(a, b, tc + 273.15):8.2f}" for tc in (40, 70, 80, 90, 100))
    eta80 = float("nan")
    if "density_15C" in v and "density_temperature_coefficient" in v:
        rho80 = v["density_15C"] * (1.0 - v["density_temperature_coefficient"] * 65.0)
        eta80 = walther_nu(a, b, 353.15) * 1e-6 * rho80
    print(f"{path.name:26s} {data.get('base_oil', '?'):8s} {nus}  {vi:6.1f}  {eta80 * 1e3:7.2f}  "
          f"A={a:.5f} B={b:.5f}")
    return errors


def main(argv):
    here = pathlib.Path(__file__).resolve().parent
    files = [pathlib.Path(p) for p in argv[1:]] or sorted(here.glob("*.toml"))
    if not files:
        print("no lubricant files found", file=sys.stderr)
        return 1
    print(f"{'file':26s} {'base':8s} {'nu40':>8s}  {'nu70':>8s}  {'nu80':>8s}  {'nu90':>8s}  {'nu100':>8s}  "
          f"{'VI':>6s}  {'eta80':>7s}   (nu in mm^2/s, eta80 in mPa s, VI per ASTM D2270)")
    failed = 0
    for path in files:
        try:
            errors = check(path)
        except (OSError, tomllib.TOMLDecodeError) as e:
            errors = [str(e)]
        for e in errors:
            print(f"  FAIL {path.name}: {e}")
        failed += bool(errors)
    print(f"{len(files) - failed} of {len(files)} files pass")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
