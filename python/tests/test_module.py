"""The Python module against the command line (same functions: equal to the last digit the
command writes), its exceptions, and the physics it exposes against exact values."""

import concurrent.futures
import csv
import io
import math
import threading
import time
import tomllib

import h5py
import numpy as np
import pytest

import geartrib as gt

DEFAULT = "gears/m6z30.toml"


def csv_rows(text):
    """The rows of a CSV the command printed (comment lines skipped), as dicts of text."""
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    return list(csv.DictReader(io.StringIO("\n".join(lines))))


def as_printed(value):
    """A value as the command's CSV prints it (%.10g): equal text is equal to the last digit printed."""
    return "%.10g" % value


# -- the mesh cycle ------------------------------------------------------------------------------

@pytest.mark.parametrize("changes", [{}, {"torque": "2000 Nm", "rq": "0.4um"}])
def test_run_equals_the_command_bit_for_bit(tool, tmp_path, changes):
    """Every series of `geartrib run`'s HDF5 (float64) equals the module's array exactly."""
    sets = [a for k, v in changes.items() for a in ("--set", f"{k}={v.replace(' ', '')}")]
    tool("run", DEFAULT, *sets, "-q", "-o", tmp_path / "r.h5")
    result = gt.run(gt.load_case(DEFAULT, **{k: v.replace(" ", "") for k, v in changes.items()}), as_dict=True)
    compared = 0
    datasets = []
    with h5py.File(tmp_path / "r.h5") as f:
        for group in ("mesh", "contact", "lubrication"):  # contact/validity inside contact
            f[group].visititems(lambda path, item: datasets.append((path, item[()], item.attrs["units"].decode()))
                                if isinstance(item, h5py.Dataset) and not path.startswith("points") else None)
        if "lubrication" in f:  # the named points: the summary's table, to the last digit
            points = result["attrs"]["lubrication_summary"]["points"]
            for name, item in f["lubrication/points"].items():
                values = item[()]
                if name == "point":
                    assert [x.decode() for x in values] == list(points["point"])
                else:
                    assert np.array_equal(values, np.asarray(points[name])), name
    for path, values, unit in datasets:
        name = path.split("/")[-1]
        assert name in result, f"{path} missing from the module's result"
        assert np.array_equal(values, result[name]), name
        assert unit == result["units"][name], name
        compared += 1
    assert compared > 40  # every group of the lubricated default case was there


def test_tooth_contact_summary_equals_the_command(tool, tmp_path):
    """Under compatibility sharing the run's transmission-error summary (/mesh's attributes) is the
    module's, and the path's transmission_error_m series is there."""
    case = "gears/m6z30-relief.toml"
    tool("run", case, "-q", "-o", tmp_path / "r.h5")
    result = gt.run(gt.load_case(case), as_dict=True)
    path = result["attrs"]["path"]
    with h5py.File(tmp_path / "r.h5") as f:
        attrs = f["mesh"].attrs
        for name in ("transmission_error_mean_m", "transmission_error_peak_to_peak_m", "effective_contact_ratio",
                     "loaded_start_m", "contact_lost"):
            assert attrs[name] == path[name], name
        assert np.array_equal(f["mesh/transmission_error_m"][()], result["transmission_error_m"])
    assert 0.0 < path["transmission_error_peak_to_peak_m"] < path["transmission_error_mean_m"]


def test_rating_equals_the_command(tool, tmp_path):
    """The default case's ratings (its [rating] methods) are the module's: /rating's verdict and
    factor table, and the gears' circles in /mesh's attributes."""
    tool("run", DEFAULT, "-q", "-o", tmp_path / "r.h5")
    result = gt.run(gt.load_case(DEFAULT), as_dict=True)
    rating = result["attrs"]["rating"]
    with h5py.File(tmp_path / "r.h5") as f:
        for name, value in f["rating"].attrs.items():
            if name != "methods":
                assert value == rating[name], name
        symbols = [s.decode() for s in f["rating/symbol"][()]]
        assert symbols == [row["symbol"] for row in rating["factors"]]
        assert np.array_equal(f["rating/value"][()], [row["value"] for row in rating["factors"]])
        assert f["mesh"].attrs["pinion_sap_diameter_m"] == result["attrs"]["path"]["pinion_sap_diameter_m"]
    assert rating["S_F_min"] > rating["S_H_min"] > 0.0


def test_run_as_xarray_dataset():
    xr = pytest.importorskip("xarray")
    ds = gt.run(positions=21)
    assert isinstance(ds, xr.Dataset)
    assert ds.s_m.size == 21 and ds.s_m.attrs["units"] == "m"
    assert ds.real_area_ratio.attrs["units"] == "1"
    assert ds.hertz_p0_Pa.attrs["group"] == "mesh"
    assert ds.attrs["regime"] in ("elastic", "elastic-plastic", "fully plastic")
    assert np.all(np.diff(ds.s_m.values) > 0)  # A -> E


def test_dict_case_equals_the_file_case():
    """A case given as a dict of its tables runs exactly as the file it was read from."""
    with open(DEFAULT, "rb") as f:
        tables = tomllib.load(f)
    from_dict = gt.load_case(tables, directory="gears")
    a = gt.run(from_dict, as_dict=True)
    b = gt.run(gt.load_case(DEFAULT), as_dict=True)
    for name, unit in b["units"].items():
        assert np.array_equal(a[name], b[name]), name


def test_changes_are_recorded_with_their_origin():
    case = gt.load_case().set(torque="2000 Nm", positions=41)
    value, origin = case.parameters["operating.pinion_torque"]
    assert value == "2000 N m" and "--set" in origin
    assert case["contact.positions"] == "41"
    assert gt.load_case()["operating.pinion_torque"] != value  # the original case is unchanged



# -- the deterministic fidelity ------------------------------------------------------------------

DETERMINISTIC = "gears/m6z30-deterministic.toml"
# A coarse, short run (~0.4 s): 2 um elements, at most 3 running-in meshes, 81 positions (running-in
# needs every flank point in the strip at two positions at least: 67 or more here).
DETERMINISTIC_SETS = {"element_size": "2um", "running_in.meshes": "3"}
DETERMINISTIC_POSITIONS = 81


@pytest.fixture(scope="module")
def deterministic():
    """The deterministic case's run as a dict of arrays."""
    return gt.run(gt.load_case(DETERMINISTIC).set(DETERMINISTIC_SETS), positions=DETERMINISTIC_POSITIONS, as_dict=True)


def test_deterministic_run_has_its_parts(deterministic):
    r = deterministic
    n = r["s_m"].size
    assert n == DETERMINISTIC_POSITIONS and r["attrs"]["fidelity"] == "deterministic"
    # The statistical model on the same flanks, beside the boundary elements, over the positions.
    statistical = [k for k in r["units"] if k.startswith("statistical_")]
    assert "statistical_real_area_ratio" in statistical and "statistical_plastic_area_fraction" in statistical
    assert all(r[k].shape == (n,) for k in statistical)
    assert np.all(r["statistical_real_area_ratio"] > 0)
    assert not any(k in r["attrs"] for k in ("statistical", "pressure_profiles", "history"))


def test_deterministic_pressure_profiles_carry_the_line_load(deterministic):
    """The pressure kept at A, B, C, D, E integrates (sum x element width: constant-pressure
    elements) to the position's line load. The strip is dry, so its asperities carry the whole
    load, and with the hardness cap the solver brackets the approach until the load it carries is
    within max(1e-9, 100 x its complementarity tolerance 1e-8) = 1e-6 of the target (else it
    raises: half_plane_bem.cpp, solve_load_capped): 1e-6 relative is the promise; the sum's
    rounding (a few hundred terms) is ~1e-14."""
    r = deterministic
    assert list(r["point"]) == ["A", "B", "C", "D", "E"]
    assert r["position"][0] == 0 and r["position"][-1] == r["s_m"].size - 1  # A and E end the path
    assert np.array_equal(r["position_s_m"], r["s_m"][r["position"]])
    x = r["x_m"]
    dx = x[1] - x[0]
    assert dx == pytest.approx(2e-6, rel=1e-9) and np.allclose(np.diff(x), dx, rtol=1e-9, atol=0)
    assert r["pressure_Pa"].shape == (5, x.size)
    assert r["units"]["pressure_Pa"] == "Pa" and r["units"]["x_m"] == "m"
    for i, p in zip(r["position"], r["pressure_Pa"]):
        assert np.all(p >= 0)
        assert p.sum() * dx == pytest.approx(r["line_load_N_per_m"][i], rel=1e-6), r["point"]
        assert p.max() == r["max_pressure_Pa"][i]


def test_deterministic_running_in_history(deterministic):
    r = deterministic
    ri = r["attrs"]["running_in"]
    assert ri["teeth"] == "pair" and ri["tolerance_m"] == pytest.approx(1e-9)
    rows = r["mesh"].size
    if ri["shakedown_mesh"] == 0:  # not shaken down: every mesh asked for ran
        assert ri["meshes"] == 3 and rows == ri["meshes"] + 1
    else:
        assert ri["meshes"] == ri["shakedown_mesh"] and rows == ri["meshes"] + 1
    assert list(r["mesh"]) == list(range(rows))  # row 0: the new flanks
    history = [k for k in r["units"] if k.startswith("running_in_") and r[k].shape == (rows,)]
    assert len(history) >= 10
    assert np.isnan(r["running_in_new_plastic_deformation_m"][0])  # no contact yet on the new flanks
    assert np.all(np.isfinite(r["running_in_new_plastic_deformation_m"][1:]))
    rq = r["running_in_pinion_rq_m"]
    assert np.all(np.isfinite(rq)) and np.all(np.diff(rq) <= 0), rq  # plastic flattening only lowers peaks
    for gear in ("pinion", "wheel"):
        initial, final = r[f"running_in_{gear}_profile_initial_m"], r[f"running_in_{gear}_profile_final_m"]
        assert initial.shape == final.shape == r[f"running_in_{gear}_arc_m"].shape
        assert np.all(final <= initial) and np.any(final < initial)  # lowered where it yielded, never raised


def test_deterministic_run_as_xarray():
    xr = pytest.importorskip("xarray")
    ds = gt.run(gt.load_case(DETERMINISTIC).set(DETERMINISTIC_SETS), positions=DETERMINISTIC_POSITIONS)
    assert isinstance(ds, xr.Dataset)
    assert ds.statistical_real_area_ratio.dims == ("s_m",)
    assert ds.statistical_real_area_ratio.attrs["group"] == "statistical"
    assert ds.pressure_Pa.dims == ("position", "x_m") and ds.pressure_Pa.attrs["units"] == "Pa"
    at_c = ds.pressure_Pa.sel(position=ds.position[ds.point == "C"].item())
    assert at_c.position_s_m.item() == ds.s_m[at_c.position.item()].item()
    assert ds.running_in_pinion_rq_m.dims == ("mesh",) and ds.running_in_pinion_rq_m.attrs["group"] == "running_in"
    assert ds.running_in_pinion_profile_final_m.dims == ("running_in_pinion_arc_m",)
    assert ds.attrs["running_in.teeth"] == "pair" and ds.attrs["running_in.meshes"] == ds.mesh.size - 1


def test_synthesised_flanks_recorded_as_the_command_records_them(tool, tmp_path):
    """The shipped measured case, deterministic: each flank synthesised from its patch, the record in
    the attrs equal to the command's /synthesis/<gear> attributes."""
    h5py = pytest.importorskip("h5py")
    path = tmp_path / "m.h5"
    tool("run", "gears/m6z30-measured.toml", "--fidelity", "deterministic", "--positions", "5", "-q", "-o", path)
    r = gt.run(gt.load_case("gears/m6z30-measured.toml").set({"contact.fidelity": "deterministic"}), positions=5,
               as_dict=True)
    s = r["attrs"]["synthesis"]
    with h5py.File(path, "r") as f:
        for gear in ("pinion", "wheel"):
            attrs = f["synthesis"][gear].attrs
            assert sorted(f"{gear}.{k}" for k in attrs) == sorted(k for k in s if k.startswith(gear + "."))
            for k, v in attrs.items():
                assert s[f"{gear}.{k}"] == (v.decode() if isinstance(v, bytes) else v), k
    assert s["pinion.method"] == "psd" and s["pinion.seed"] == 1 and s["wheel.seed"] == 1001
    assert "synthesis" not in gt.run(gt.load_case(DETERMINISTIC), positions=5, as_dict=True)["attrs"]


def test_deterministic_run_equals_the_command(tool, tmp_path, deterministic):
    """The command's HDF5 /statistical, /contact/pressure and /running_in (float64) equal the
    module's arrays exactly (NaN where the command has NaN)."""
    h5py = pytest.importorskip("h5py")
    path = tmp_path / "d.h5"
    sets = [a for k, v in DETERMINISTIC_SETS.items() for a in ("--set", f"{k}={v}")]
    tool("run", DETERMINISTIC, "--positions", DETERMINISTIC_POSITIONS, *sets, "-q", "-o", path)
    r = deterministic
    with h5py.File(path) as f:
        for name, item in f["statistical"].items():
            assert np.array_equal(item[()], r[name]), name
            assert item.attrs["units"].decode() == r["units"][name], name
        pressure = f["contact/pressure"]
        assert np.array_equal(pressure["x_m"][()], r["x_m"])
        for row, i in enumerate(r["position"]):
            item = pressure[f"position_{i}"]
            assert np.array_equal(item[()], r["pressure_Pa"][row]), i
            assert item.attrs["point"].decode() == r["point"][row]
            assert item.attrs["s_m"] == r["position_s_m"][row]
        assert len(pressure) == len(r["position"]) + 1  # every profile kept, and x
        running_in = f["running_in"]
        for name, item in running_in.items():
            key = name if name == "mesh" else f"running_in_{name}"
            assert np.array_equal(item[()], r[key], equal_nan=True), name
        ri = r["attrs"]["running_in"]
        for name, value in running_in.attrs.items():
            assert (value.decode() if isinstance(value, bytes) else value) == ri[name], name


# -- the mixed-EHL fidelity ----------------------------------------------------------------------

MIXED_EHL = "gears/m6z30-mixed-ehl.toml"
# A short run (~1.5 s): the shipped flanks with a 30 um correlation length (the shipped 10 um does
# not converge: docs/guide), profiles and nodes every 2 um, windows of one contact width, A, C and E.
MIXED_EHL_SETS = {"pinion.flank.profile.correlation_length": "30um",
                  "wheel.flank.profile.correlation_length": "30um",
                  "pinion.flank.profile.spacing": "2um", "wheel.flank.profile.spacing": "2um",
                  "mixed_ehl.grid_spacing": "2um", "mixed_ehl.window": "1"}
MIXED_EHL_POSITIONS = 3
# Each window series' unit by its name's ending, the longer endings first (the rest are ratios,
# counts or codes: "1").
EHL_UNITS = {"_N_per_m": "N/m", "_W_per_m2": "W/m^2", "_m": "m", "_Pa": "Pa", "_K": "K", "_s": "s"}
EHL_PROFILE_UNITS = {"pressure_Pa": "Pa", "film_m": "m", "shear_Pa": "Pa", "state": "1"}


@pytest.fixture(scope="module")
def mixed_ehl():
    """The mixed-EHL case's run as a dict of arrays."""
    return gt.run(gt.load_case(MIXED_EHL).set(MIXED_EHL_SETS), positions=MIXED_EHL_POSITIONS, as_dict=True)


def ehl_series(r):
    """The windows' series (group mixed_ehl) by name; ehl_regime is the statistical cycle's (/lubrication)."""
    return sorted(k for k in r["units"] if k.startswith("ehl_") and k != "ehl_regime")


def path_mean(r, name):
    """A series' mean over the path as the run takes it: the trapezoidal rule over s."""
    s = r["s_m"]
    return float(np.sum(0.5 * (r[name][1:] + r[name][:-1]) * np.diff(s)) / (s[-1] - s[0]))


def test_mixed_ehl_run_has_its_parts(mixed_ehl):
    """The windows' series over the positions with the units their names say, the statistical model
    beside them, and the summary's extremes and path means those of the series."""
    r = mixed_ehl
    n = r["s_m"].size
    assert n == MIXED_EHL_POSITIONS and r["attrs"]["fidelity"] == "mixed_ehl"
    series = ehl_series(r)
    assert len(series) >= 25
    for name in series:
        assert r[name].shape == (n,), name
        assert np.all(np.isfinite(r[name])), name
        unit = next((u for end, u in EHL_UNITS.items() if name.endswith(end)), "1")
        assert r["units"][name] == unit, name
    assert "statistical_real_area_ratio" in r["units"] and r["statistical_real_area_ratio"].shape == (n,)
    s = r["attrs"]["mixed_ehl"]
    assert s["grid_spacing_m"] == pytest.approx(2e-6, rel=1e-12) and s["window_contact_widths"] == 1.0
    # Extremes and sums are the series' own, exactly; the means are the series' trapezoidal mean
    # over s, to rounding (a few terms: 1e-12).
    assert s["max_asperity_share"] == r["ehl_asperity_share_max"].max()
    assert s["min_film_m"] == r["ehl_min_film_min_m"].min()
    assert s["max_peak_pressure_Pa"] == r["ehl_peak_pressure_max_Pa"].max()
    assert s["max_flash_temperature_K"] == r["ehl_flash_temperature_max_K"].max()
    assert s["max_load_error"] == r["ehl_load_error_max"].max()
    assert s["nodes_max"] == r["ehl_nodes"].max() and s["time_steps"] == r["ehl_time_steps"].sum()
    assert s["mean_asperity_share"] == pytest.approx(path_mean(r, "ehl_asperity_share_mean"), rel=1e-12, abs=1e-300)
    assert s["mean_friction_coefficient"] == pytest.approx(path_mean(r, "ehl_friction_coefficient_mean"), rel=1e-12)


def test_mixed_ehl_shares_and_extremes_are_ordered(mixed_ehl):
    """Shares and fractions lie in [0, 1] with each window's mean at most its maximum; films, peak
    pressure, friction and flash temperature likewise; the statistical cycle's asperity and film
    shares of the load add up to one; every window carries its load to the solver's tolerance."""
    r = mixed_ehl
    for q in ("asperity_share", "contact_fraction"):
        mean, top = r[f"ehl_{q}_mean"], r[f"ehl_{q}_max"]
        assert np.all((0 <= mean) & (mean <= top) & (top <= 1)), q
    for q in ("real_area_ratio_max", "yield_fraction_max"):
        assert np.all((0 <= r[f"ehl_{q}"]) & (r[f"ehl_{q}"] <= 1)), q
    for q in ("peak_pressure_{}_Pa", "friction_coefficient_{}", "flash_temperature_{}_K", "heat_flux_peak_{}_W_per_m2"):
        assert np.all((0 <= r["ehl_" + q.format("mean")]) & (r["ehl_" + q.format("mean")] <= r["ehl_" + q.format("max")])), q
    for q in ("min_film", "central_film"):
        assert np.all(r[f"ehl_{q}_min_m"] <= r[f"ehl_{q}_mean_m"]), q
    assert np.all(r["ehl_min_film_mean_m"] <= r["ehl_central_film_mean_m"])
    shares = r["asperity_load_share"]
    assert np.all((0 <= shares) & (shares <= 1)) and np.any(shares > 0)  # the rough flanks touch (JGP)
    assert np.allclose(shares + r["film_load_share"], 1.0, rtol=0, atol=1e-15)  # one load, two carriers
    assert np.all(r["ehl_load_error_max"] <= r["attrs"]["mixed_ehl"]["tolerance"])
    assert np.all(r["ehl_time_steps"] > 0) and np.all(r["ehl_window_s"] > 0)


def test_mixed_ehl_profiles_carry_the_line_load(mixed_ehl):
    """The profiles through the contact at A, C and E (the points kept): each on its own uniform
    grid over [-inlet b, outlet b] (nodes at the elements' centres), its pressure summed over the
    nodes (constant-pressure elements; the ends are the boundary's zero pressure, so the trapezoidal
    rule gives the same) equal to the position's line load within the window's load error, which
    the run computes the same way from the pressures (<= the solver's tolerance 1e-6) and rounding
    over a few hundred terms (1e-13); the peak instant's highest pressure is the window's highest."""
    r = mixed_ehl
    s = r["attrs"]["mixed_ehl"]
    kept = sorted(int(k.rsplit("_", 1)[1]) for k in r if k.startswith("mixed_ehl_x_m_"))
    assert kept == [0, 1, 2]  # A, C and E: contact.pressure_profiles = "points"
    for k in kept:
        x = r[f"mixed_ehl_x_m_{k}"]
        assert r["units"][f"mixed_ehl_x_m_{k}"] == "m" and x.size == r["ehl_nodes"][k]
        dx = x[1] - x[0]
        assert np.allclose(np.diff(x), dx, rtol=1e-9, atol=0) and dx <= s["grid_spacing_m"] * (1 + 1e-12)
        b = r["hertz_halfwidth_m"][k]
        assert x[0] - 0.5 * dx == pytest.approx(-s["inlet_halfwidths"] * b, rel=1e-9)
        assert x[-1] + 0.5 * dx == pytest.approx(s["outlet_halfwidths"] * b, rel=1e-9)
        w = r["line_load_N_per_m"][k]
        for instant in ("peak", "middle"):
            arrays = {q: r[f"mixed_ehl_{instant}_{q}_{k}"] for q in EHL_PROFILE_UNITS}
            for q, unit in EHL_PROFILE_UNITS.items():
                assert arrays[q].shape == x.shape and r["units"][f"mixed_ehl_{instant}_{q}_{k}"] == unit, (q, k)
            p = arrays["pressure_Pa"]
            assert np.all(p >= 0) and p[0] == 0 and p[-1] == 0
            assert set(np.unique(arrays["state"])) <= {0, 1, 2}  # fluid, cavitated, contact
            load = p.sum() * dx
            assert abs(load - w) <= (r["ehl_load_error_max"][k] + 1e-13) * w, (instant, k)
            assert np.trapz(p, x) == pytest.approx(load, rel=1e-13)
            assert p.max() <= r["ehl_peak_pressure_max_Pa"][k]
        assert r[f"mixed_ehl_peak_pressure_Pa_{k}"].max() == r["ehl_peak_pressure_max_Pa"][k]


def test_mixed_ehl_run_as_xarray():
    xr = pytest.importorskip("xarray")
    ds = gt.run(gt.load_case(MIXED_EHL).set(MIXED_EHL_SETS), positions=MIXED_EHL_POSITIONS)
    assert isinstance(ds, xr.Dataset)
    assert ds.ehl_min_film_min_m.dims == ("s_m",) and ds.ehl_min_film_min_m.attrs["group"] == "mixed_ehl"
    assert ds.ehl_min_film_min_m.attrs["units"] == "m"
    profile = ds.mixed_ehl_peak_pressure_Pa_1
    assert profile.dims == ("mixed_ehl_x_m_1",) and profile.attrs["units"] == "Pa"
    assert ds.attrs["mixed_ehl.tolerance"] == 1e-6 and ds.attrs["mixed_ehl.viscosity_law"] == "roelands"


def test_mixed_ehl_run_equals_the_command(tool, tmp_path, mixed_ehl):
    """The command's HDF5 /mixed_ehl (series, profiles and attributes but the windows' wall times)
    equals the module's arrays and summary exactly."""
    path = tmp_path / "e.h5"
    sets = [a for k, v in MIXED_EHL_SETS.items() for a in ("--set", f"{k}={v}")]
    tool("run", MIXED_EHL, "--positions", MIXED_EHL_POSITIONS, *sets, "-q", "-o", path)
    r = mixed_ehl
    with h5py.File(path) as f:
        g = f["mixed_ehl"]
        names = [n for n, item in g.items() if isinstance(item, h5py.Dataset)]
        assert sorted(names) == ehl_series(r)
        for name in names:
            assert np.array_equal(g[name][()], r[name]), name
            assert g[name].attrs["units"].decode() == r["units"][name], name
        timings = {"windows_seconds", "windows_transform_seconds"}  # wall times: this run's own
        s = r["attrs"]["mixed_ehl"]
        for name, value in g.attrs.items():
            if name == "meaning" or name in timings:
                continue
            assert s[name] == (value.decode() if isinstance(value, bytes) else value), name
        assert sorted(set(g.attrs) - timings - {"meaning"}) == sorted(set(s) - timings)
        for item in g["profiles"].values():
            k = int(item.attrs["position"])
            assert np.array_equal(item["x_m"][()], r[f"mixed_ehl_x_m_{k}"]), k
            for instant in ("peak", "middle"):
                for q in EHL_PROFILE_UNITS:
                    assert np.array_equal(item[f"{instant}_{q}"][()], r[f"mixed_ehl_{instant}_{q}_{k}"]), (k, q)
        assert len(g["profiles"]) == 3

# -- kinematics and asperity laws ----------------------------------------------------------------

def test_kinematics_equals_the_command(tool):
    rows = csv_rows(tool("kinematics", DEFAULT, "--points", "A,B,C,D,E", "--csv").stdout)
    k = gt.kinematics(gt.load_case(DEFAULT))
    assert list(k["point"]) == ["A", "B", "C", "D", "E"]
    for i, row in enumerate(rows):
        for name, text in row.items():
            if name != "point":
                assert as_printed(k[name][i]) == text, (row["point"], name)


def test_kinematics_positions():
    k = gt.kinematics(positions=11)
    assert k["s_m"].size == 11 and np.all(np.diff(k["s_m"]) > 0)
    with pytest.raises(ValueError, match="unknown point 'F'"):
        gt.kinematics(points="AF")


@pytest.mark.parametrize("model", ["continuous", "kogut-etsion", "jackson-green"])
def test_asperity_equals_the_command(tool, model):
    d = [0.5, 1.0, 6.0, 30.0, 200.0]
    rows = csv_rows(tool("asperity", "--case", DEFAULT, "--model", model, "--delta-star",
                         *map(str, d), "--csv").stdout)
    a = gt.asperity(d, model, as_dict=True)
    assert len(rows) == len(d)
    for i, row in enumerate(rows):
        for column, text in row.items():
            name = next(n for n in a["units"] if column == n or column.startswith(n + "_")
                        and column[len(n) + 1:] == a["units"][n])
            assert as_printed(a[name][i]) == text, (model, column)


def test_asperity_laws_keep_their_identities():
    """At delta* = 1 every law is at first yield: F = F_c, A = A_c (Hertz at the critical
    interference; exact up to the laws' fitted constants, 1e-12 for the rounding of the powers)."""
    for model in gt.asperity_models():
        a = gt.asperity([1.0], model, as_dict=True)
        if model in ("hertz", "continuous", "kogut-etsion", "ceb"):
            assert a["load_star"][0] == pytest.approx(1.0, rel=1e-12), model
            assert a["area_star"][0] == pytest.approx(1.0, rel=1e-12), model
    # Load grows with the interference for every law, over nine decades of delta*.
    d = np.logspace(-3, 6, 200)
    for model in gt.asperity_models():
        load = gt.asperity(d, model, stresses=False, as_dict=True)["load"]
        assert np.all(np.isfinite(load)) and np.all(np.diff(load) > 0), model


def test_asperity_given_pair_and_bad_input():
    pair = gt._core.contact_pair(gt.load_case().loaded)
    a = gt.asperity([2.0], "hertz", pair=pair, as_dict=True)
    b = gt.asperity([2.0], "hertz", as_dict=True)
    assert a["load"][0] == b["load"][0]
    with pytest.raises(ValueError, match="delta_star must lie in"):
        gt.asperity([-1.0])
    with pytest.raises(ValueError, match="unknown"):
        gt.asperity([1.0], "no-such-model")


# -- errors --------------------------------------------------------------------------------------

def test_input_error_carries_the_command_lines_message(tool):
    done = tool("run", DEFAULT, "--set", "torque=-5Nm", "-q", "-o", "/nonexistent/x.h5", check=False)
    assert done.returncode == 2
    with pytest.raises(gt.InputError) as e:
        gt.load_case(DEFAULT, torque="-5Nm")
    assert done.stderr.strip() == "geartrib: error: " + str(e.value)
    assert e.value.key == "operating.pinion_torque" and e.value.value == '"-5Nm"'
    assert "positive" in e.value.rule and e.value.file.startswith(DEFAULT)
    assert isinstance(e.value, ValueError)


def test_input_error_points_at_the_line(tmp_path):
    lines = open(DEFAULT).read().splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("module = "))
    lines[at] = 'module = "6 parsecs"'
    bad = tmp_path / "bad.toml"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(gt.InputError) as e:
        gt.load_case(bad)
    assert (e.value.file, e.value.line, e.value.key) == (str(bad), at + 1, "gear_pair.module")
    assert "parsecs" in str(e.value)


def test_unknown_key_is_refused():
    with pytest.raises(gt.InputError, match="no_such_key"):
        gt.load_case(**{"gear_pair.no_such_key": 1})


def test_input_error_message_whole_with_a_nul_in_the_value():
    # A NUL in a value ended the message (str(e) stopped at "--set operating.pinion_torque=1000"):
    # control characters in a change are refused, shown as escapes; the parts keep the text.
    with pytest.raises(gt.InputError) as e:
        gt.load_case(torque="1000\x00 Nm")
    assert str(e.value).endswith("(--set operating.pinion_torque=1000\\x00 Nm): key 'operating.pinion_torque' = "
                                 "1000\\x00 Nm: a --set key or value may not hold control characters (shown as \\xNN)")
    assert e.value.value == "1000\x00 Nm" and e.value.key == "operating.pinion_torque"


# -- surfaces and boundary elements --------------------------------------------------------------

def test_surface_statistics_equal_the_command(tool, tmp_path):
    path = tmp_path / "s.h5"
    tool("surface", "generate", "self-affine", "-o", path)
    rows = {r["quantity"]: r["value"] for r in csv_rows(tool("surface", "stats", path, "--csv").stdout)}
    with h5py.File(path) as f:
        z, dx, dy = f["z"][()], f["z"].attrs["dx"], f["z"].attrs["dy"]
    s = gt.surface_statistics(z, dx, dy)
    assert list(s) == list(rows)  # the same quantities, named alike, in the same order
    for name, text in rows.items():
        assert as_printed(s[name]) == text, name


def test_surface_statistics_of_a_known_surface():
    """A sine of amplitude a along x, whole periods, no form removed: Rq = a/sqrt(2) (the sampled
    sine's mean square is exactly 1/2) and Ra = a (2/N) cot(pi/N) for N points a period (the
    sampled |sin|'s mean, -> 2a/pi); 1e-12 for rounding."""
    nx, ny, periods, a = 256, 16, 8, 1e-6
    x = np.arange(nx) / nx * 2 * np.pi * periods
    z = np.tile(a * np.sin(x), (ny, 1))
    s = gt.surface_statistics(z, 1e-6, form=0)
    assert s["Rq_m"] == pytest.approx(a / math.sqrt(2), rel=1e-12)
    per_period = nx // periods
    assert s["Ra_m"] == pytest.approx(a * 2 / per_period / math.tan(math.pi / per_period), rel=1e-12)
    z[3, 5] = np.nan
    assert gt.surface_statistics(z, 1e-6, form=0)["missing"] == 1
    with pytest.raises(ValueError):
        gt.surface_statistics(np.ones(10), 1e-6)


def test_x3p_from_python_reads_back_bit_for_bit(tool, tmp_path):
    """An X3P the command writes reads into the same heights as its HDF5 twin; one Python writes
    reads back bit for bit (NaN holes kept)."""
    tool("surface", "generate", "self-affine", "--seed", "7", "-o", tmp_path / "a.x3p")
    tool("surface", "generate", "self-affine", "--seed", "7", "-o", tmp_path / "a.h5")
    z, dx, dy = gt.read_surface(tmp_path / "a.x3p")
    z5, dx5, dy5 = gt.read_surface(tmp_path / "a.h5")
    assert (dx, dy) == (dx5, dy5) and np.array_equal(z, z5)
    z[2, 3] = np.nan
    gt.write_surface(tmp_path / "b.x3p", z, dx, 2 * dy)
    back, bdx, bdy = gt.read_surface(tmp_path / "b.x3p")
    assert (bdx, bdy) == (dx, 2 * dy)
    assert back.tobytes() == z.tobytes()  # NaN included: the same bits
    with pytest.raises(gt.InputError, match="nope.x3p"):
        gt.read_surface(tmp_path / "nope.x3p")


def test_threads_writing_one_path_all_succeed(tmp_path):
    """Temporaries are unique per attempt (issue 30, finding 9: named by the PID, 23 of 32 threads
    writing one path failed with "File exists"): every write succeeds, one whole file stays and no
    temporary."""
    path = tmp_path / "same.x3p"
    z = np.random.default_rng(0).normal(0, 3e-7, (256, 256))
    with concurrent.futures.ThreadPoolExecutor(8) as pool:
        list(pool.map(lambda _: gt.write_surface(path, z, 5e-7), range(32)))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["same.x3p"]
    back, _, _ = gt.read_surface(path)
    assert back.tobytes() == z.tobytes()


def test_boundary_elements_reach_hertz():
    """A cylinder of radius R on a half-plane: Hertz's p0 = sqrt(P E*/(pi R)), half-width
    b = sqrt(4 P R/(pi E*)). 4096 elements over 4 b: the peak within 0.5% (the constant-pressure
    elements' discretisation error at b/1000 spacing is ~1e-3)."""
    R, E, P = 10e-3, 2.26e11, 2e5
    b = math.sqrt(4 * P * R / (math.pi * E))
    n = 4096
    dx = 4 * b / n
    x = (np.arange(n) + 0.5) * dx - 2 * b
    r = gt.boundary_elements(-x**2 / (2 * R), dx, E, line_load=P)
    assert r["line_load_N_per_m"] == pytest.approx(P, rel=1e-9)  # load control: the load exactly
    assert r["pressure_Pa"].max() == pytest.approx(math.sqrt(P * E / (math.pi * R)), rel=5e-3)
    half = r["contact_elements"] * dx / 2
    assert half == pytest.approx(b, rel=5e-3)
    with pytest.raises(ValueError, match="one of them"):
        gt.boundary_elements(x, dx, E)


def test_computation_releases_the_gil():
    """While one thread solves a large boundary-element problem, another keeps counting."""
    n = 1 << 17
    dx = 1e-7
    x = (np.arange(n) + 0.5) * dx
    profile = 1e-7 * np.sin(2 * np.pi * x / 5e-6) - (x - x.mean())**2 / 2e-2
    count = [0]
    done = threading.Event()

    def counter():
        while not done.is_set():
            count[0] += 1
            time.sleep(0)

    t = threading.Thread(target=counter)
    t.start()
    start = time.perf_counter()
    before = count[0]
    gt.boundary_elements(profile, dx, 2.26e11, line_load=1e5)
    elapsed = time.perf_counter() - start
    during = count[0] - before
    done.set()
    t.join()
    assert elapsed > 0.02  # long enough for the counter to run many times
    assert during > 100, f"the counter ran {during} times in {elapsed:.3f} s: the GIL was held"


# -- what a review found -------------------------------------------------------------------------

def test_threads_plan_fft_concurrently():
    """FFTW's planner is not thread-safe: boundary elements of many sizes on two threads at once
    (each solve plans and destroys FFTs) give the serial results (bit for bit) and no crash."""
    sizes = list(range(8, 400, 7))

    def solve(n):
        return gt.boundary_elements(np.sin(np.arange(n)) * 1e-7, 1e-7, 1e11, approach=2e-8)["pressure_Pa"]

    serial = [solve(n) for n in sizes]
    results = {}

    def worker(tag, order):
        results[tag] = [solve(n) for n in order]

    threads = [threading.Thread(target=worker, args=("a", sizes)),
               threading.Thread(target=worker, args=("b", sizes[::-1]))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(a, b) for a, b in zip(results["a"], serial))
    assert all(np.array_equal(a, b) for a, b in zip(results["b"], serial[::-1]))


def test_bad_arguments_raise_value_errors(tmp_path):
    with pytest.raises(ValueError, match="no 'radius'"):
        gt.asperity([1.0], pair={})
    pair = gt._core.contact_pair(gt.load_case().loaded)
    with pytest.raises(ValueError, match="'hardness' must be a number"):
        gt.asperity([1.0], pair=dict(pair, hardness="hard"))
    with pytest.raises(ValueError, match="unknown key 'colour'"):
        gt.asperity([1.0], pair=dict(pair, colour=1.0))
    with pytest.raises(ValueError, match="1-D"):
        gt.asperity(np.ones((2, 2)))
    with pytest.raises(ValueError, match="must be finite"):
        gt.boundary_elements([0.0, np.nan, 1e-7, 0.0], 1e-7, 1e11, line_load=100.0)
    with pytest.raises(ValueError, match="line load must be finite"):
        gt.boundary_elements([0.0, 1e-7, 0.0], 1e-7, 1e11, line_load=math.inf)
    with pytest.raises(ValueError, match=r"positions must lie in \[2, 100000\]"):
        gt.kinematics(positions=0)
    with pytest.raises(ValueError, match="m, mm, um or nm"):
        gt.write_surface(tmp_path / "u.csv", np.zeros((4, 4)), 1e-6, unit=2e-6)
    assert not (tmp_path / "u.csv").exists()
    with pytest.raises(ValueError, match="dy must be positive"):
        gt.surface_statistics(np.zeros((4, 4)), 1e-6, -1e-6)
    # Finite but beyond the ranges of the file readers and the case schema (issue 30, finding 13;
    # every case: tests/corpus/27-python-extreme-arguments).
    with pytest.raises(ValueError, match=r"line_load = 1e\+300 N/m: must lie in \[0, "):
        gt.boundary_elements([0.0, 1e-7, 0.0], 1e-7, 1e11, line_load=1e300)
    with pytest.raises(ValueError, match=r"z\[0, 0\] = 1e\+300 m: heights must lie within \+-1 m"):
        gt.surface_statistics(np.ones((4, 4)) * 1e300, 1e-6)
    with pytest.raises(ValueError, match=r"pair\['radius'\] = 1e-300 m: must lie in \[1e-09, 1\] m"):
        gt.asperity([1.0], pair=dict(pair, radius=1e-300))
    with pytest.raises(ValueError, match=r"heights must lie within \+-1 m"):
        gt.write_surface(tmp_path / "huge.x3p", np.ones((8, 8)) * 1e300, 1e-6)
    with pytest.raises(ValueError, match="at least 9 are needed"):
        gt.write_surface(tmp_path / "empty.x3p", np.full((8, 8), np.nan), 1e-6)
    assert not (tmp_path / "huge.x3p").exists() and not (tmp_path / "empty.x3p").exists()


def test_dict_to_toml_round_trips():
    """The dict a case is given as is the dict its TOML text reads back as (tomllib)."""
    tables = {"title": 'a "quoted"\\ title\nover two lines \u00e9', "flag": True, "n": 3, "x": 0.1,
              "list": ["a,b", 'q"', 2.5], "gear_pair": {"module": "6 mm", "odd key": 1, "a.b": {"c": "d"}}}
    assert tomllib.loads(gt._toml(tables)) == tables
    with pytest.raises(ValueError, match="None"):
        gt._toml({"x": None})


def test_a_key_set_again_takes_its_new_value():
    case = gt.Case(DEFAULT).set(torque="-5Nm").set(torque="5Nm")
    assert case["operating.pinion_torque"] == "5 N m"
    assert case.changes == (("torque", "5Nm"),)


def test_case_pickles_and_results_are_netcdf_attributes():
    import pickle
    case = gt.load_case(torque="1500Nm")
    again = pickle.loads(pickle.dumps(case))
    assert again["operating.pinion_torque"] == "1500 N m"
    xr = pytest.importorskip("xarray")
    ds = gt.run(case, positions=11)
    assert isinstance(ds, xr.Dataset)
    assert all(isinstance(v, (str, int, float, np.integer, np.floating)) and not isinstance(v, bool)
               for v in ds.attrs.values())
