#!/usr/bin/env bash
# The main job end to end: HDF5 layout and units, finiteness, the stages a case asks for, the
# plot script, atomic output. Usage: run_outputs.sh path/to/geartrib (from the source tree).
set -u
bin="$1"
py=/usr/bin/python3
fail=0
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
ok() { echo "ok   $1"; }
bad() { echo "FAIL $1"; fail=1; }

"$bin" run -q -o "$tmp/m6z30.h5" --csv "$tmp/m6z30.csv" >/dev/null && ok run-default || bad run-default
"$py" - "$tmp/m6z30.h5" <<'PY' && ok hdf5-layout || bad hdf5-layout
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
mesh = ["s_m", "roll_angle_rad", "load_share", "line_load_N_per_m", "r_eq_m", "hertz_p0_Pa", "hertz_halfwidth_m",
        "sliding_m_per_s", "entrainment_m_per_s", "srr"]
contact = ["real_area_ratio", "real_area_per_width_m", "mean_real_pressure_Pa", "max_asperity_pressure_Pa",
           "max_asperity_von_mises_Pa", "plastic_area_fraction", "plastic_contact_fraction", "contacts_per_width_per_m"]
for group, names in (("mesh", mesh), ("contact", contact)):
    for n in names:
        d = f[group][n]
        assert d.shape == (201,), (n, d.shape)
        assert np.all(np.isfinite(d[()])), n
        assert "units" in d.attrs, n
assert f["mesh/s_m"].attrs["units"] in (b"m", "m")
assert b"m6z30" in f["scene"][()] or b"m6 z30" in f["scene"][()]
assert f["meta"].attrs["version"]
names = [n.decode() if isinstance(n, bytes) else n for n in f["meta/stage_names"][()]]
assert "surface_table" in names and any(n.startswith("asperity_stress") for n in names), names
assert f["meta/stage_seconds"].shape == (len(names),)
# The load shares of the tracked pair go 1/3 -> 1 -> 1/3 (ISO)
share = f["mesh/load_share"][()]
assert abs(share[0] - 1 / 3) < 1e-12 and abs(share[-1] - 1 / 3) < 1e-12 and abs(share.max() - 1) < 1e-12
# Where the models hold: per position with units, flags 0/1, one verdict with the counts.
v = f["contact/validity"]
for n in ["plasticity_index", "separation_over_summit_sigma", "max_delta_star", "max_interference_over_summit_radius",
          "max_contact_radius_over_summit_radius", "max_contact_radius_over_half_summit_spacing"]:
    assert v[n].shape == (201,) and np.all(np.isfinite(v[n][()])) and v[n].attrs["units"] in (b"1", "1"), n
for n in ["beyond_fitted_range", "beyond_paraboloid", "fully_plastic_limit", "summits_interact", "deep_separation"]:
    flags = v["flag_" + n][()]
    assert set(np.unique(flags)) <= {0.0, 1.0}, n
    assert v.attrs["positions_" + n] == flags.sum(), n
regime = v.attrs["regime"]
assert (regime.decode() if isinstance(regime, bytes) else regime) == "fully plastic"
verdict = v.attrs["verdict"]
assert "201 of 201 positions beyond continuous" in (verdict.decode() if isinstance(verdict, bytes) else verdict)
# The default scene runs lubricated: /lubrication with units, shares in [0, 1] adding to 1, the
# film and temperatures positive, wear zero only near the pitch point.
lub = f["lubrication"]
for n in ["film_m", "lambda_smooth_film", "mean_gap_m", "lambda_mean_gap", "asperity_load_share", "film_load_share",
          "friction_coefficient", "pair_power_loss_W", "flash_temperature_K", "contact_temperature_K",
          "iso_flash_temperature_K", "iso_contact_temperature_K", "blok_flash_temperature_iso_mu_K", "iso_film_hy_m",
          "iso_lambda_gf", "wear_depth_pinion_m", "wear_depth_wheel_m", "mean_plane_separation_m", "ehl_regime",
          "flag_low_peclet", "flag_share_depends_on_closure", "flag_oil_extrapolated", "flag_oil_temperature_clamped"]:
    assert lub[n].shape == (201,) and np.all(np.isfinite(lub[n][()])) and "units" in lub[n].attrs, n
# The default oil stays inside its data (0 to 120 degC) everywhere: nothing extrapolated or clamped.
assert not lub["flag_oil_extrapolated"][()].any() and lub.attrs["positions_oil_temperature_clamped"] == 0
a, fs = lub["asperity_load_share"][()], lub["film_load_share"][()]
assert np.all((a >= 0) & (a <= 1)) and np.allclose(a + fs, 1.0, rtol=0, atol=1e-15)
assert np.all(lub["film_m"][()] > 0) and np.all(lub["contact_temperature_K"][()] >= lub.attrs["bulk_temperature_K"])
assert lub.attrs["oil_temperature_K"] == 343.15 and lub.attrs["mean_friction_iso"] > 0
# The named points, B and D with the single pair's load (the largest line load on the path).
pts = lub["points"]
names = [x.decode() if isinstance(x, bytes) else x for x in pts["point"][()]]
assert names == ["A", "AB", "B", "C", "D", "DE", "E"], names
w = pts["line_load_N_per_m"][()]
assert abs(w[2] / f["mesh/line_load_N_per_m"][()].max() - 1) < 1e-12 and abs(w[4] / w[2] - 1) < 1e-12
PY
"$bin" run -o "$tmp/v.h5" --positions 11 2>/dev/null | grep -c "^Validity: fully plastic regime" | grep -qx 1 \
  && ok verdict-printed-once || bad verdict-printed-once
head -1 "$tmp/m6z30.csv" | grep -q "^s_m,roll_angle_rad" && ok csv-header || bad csv-header
[[ $(wc -l < "$tmp/m6z30.csv") -eq 202 ]] && ok csv-rows || bad csv-rows

# Plots
"$py" scripts/plot_mesh.py "$tmp/m6z30.h5" "$tmp/plots" >/dev/null && [[ -s "$tmp/plots/overview.png" ]] \
  && [[ $(ls "$tmp/plots"/*.png | wc -l) -ge 20 ]] && ok plots || bad plots
"$bin" surface clean gears/surfaces/wheel-flank.h5 -o "$tmp/wheel.h5" --form 1 2>/dev/null \
  && "$py" scripts/plot_surface.py "$tmp/wheel.h5" "$tmp/wheel.png" && [[ -s "$tmp/wheel.png" ]] && ok surface-plot || bad surface-plot
# The deterministic plots (they draw the path's points with plot_mesh's marker).
"$bin" run gears/m6z30-deterministic.toml --positions 11 -q -o "$tmp/det.h5" >/dev/null 2>&1 \
  && "$py" scripts/plot_deterministic.py "$tmp/det.h5" -o "$tmp/det" >/dev/null && [[ -s "$tmp/det-path.png" ]] \
  && ok deterministic-plots || bad deterministic-plots
# The mixed-EHL run (issue 32), thick film on a coarse grid: its group with units, the profiles at
# the points kept, the statistical cycle beside it, and its plots.
"$bin" run gears/m6z30-mixed-ehl.toml --positions 3 -q -o "$tmp/ehl.h5" --set pinion.flank.profile.rq=10nm \
  --set wheel.flank.profile.rq=10nm --set pinion.flank.profile.spacing=2um --set wheel.flank.profile.spacing=2um \
  --set mixed_ehl.grid_spacing=2um --set mixed_ehl.window=1 >/dev/null 2>&1 \
  && "$py" scripts/plot_mixed_ehl.py "$tmp/ehl.h5" -o "$tmp/ehl" >/dev/null && [[ -s "$tmp/ehl-path.png" ]] \
  && [[ -s "$tmp/ehl-contact.png" ]] && ok mixed-ehl-plots || bad mixed-ehl-plots
"$py" - "$tmp/ehl.h5" <<'PY' && ok mixed-ehl-hdf5 || bad mixed-ehl-hdf5
import sys, h5py
f = h5py.File(sys.argv[1], "r")
g = f["mixed_ehl"]
text = lambda v: v.decode() if isinstance(v, bytes) else v
assert text(f["meta"].attrs["fidelity"]) == "mixed_ehl"
assert text(g["ehl_min_film_mean_m"].attrs["units"]) == "m" and text(g["ehl_peak_pressure_max_Pa"].attrs["units"]) == "Pa"
assert g["ehl_asperity_share_mean"].shape == (3,) and g.attrs["grid_spacing_m"] == 2e-6 and text(g.attrs["meaning"])
p = g["profiles/position_0"]
assert text(p.attrs["point"]) == "A" and text(p["peak_pressure_Pa"].attrs["units"]) == "Pa"
assert p["x_m"].shape == p["middle_film_m"].shape == p["peak_state"].shape
assert "statistical" in f and "asperity_load_share" in f["lubrication"] and "max_von_mises_Pa" in f["contact"]
PY
"$py" - "$tmp/wheel.h5" <<'PY' && ok surface-hdf5-attributes || bad surface-hdf5-attributes
import sys, h5py
f = h5py.File(sys.argv[1], "r")
assert f["z"].attrs["units"] in (b"m", "m") and f["z"].attrs["dx"] == 0.25e-6 and f.attrs["geartrib_version"]
PY

# Persson's closure on measured flanks (issue 35): it takes the patches' radial spectrum, says so on the
# terminal and in /lubrication, its rq the flanks' composite Rq (the average keeps each patch's variance).
"$bin" run gears/m6z30-measured.toml --positions 11 -o "$tmp/persson.h5" --set lubricant.file=../lubricants/mineral-vg220.toml \
  --set operating.oil_temperature=70degC --set lubrication.asperity_pressure=persson 2>/dev/null \
  | grep -q "^Persson's spectrum: measured (rq 1.407 um" && ok persson-measured-printed || bad persson-measured-printed
"$py" - "$tmp/persson.h5" <<'PY' && ok persson-measured-recorded || bad persson-measured-recorded
import sys, h5py
a = h5py.File(sys.argv[1], "r")["lubrication"].attrs
text = lambda v: v.decode() if isinstance(v, bytes) else v
assert text(a["persson_spectrum"]) == "measured", a["persson_spectrum"]
assert abs(a["persson_spectrum_rq_m"] / a["composite_rq_m"] - 1) < 1e-12
assert 0.9 < a["persson_spectrum_rms_gradient"] < 1.0, a["persson_spectrum_rms_gradient"]  # the patches' 0.934
PY

# Only what the case asks for: real area only, mu = 0 (no side contact), coupled fidelity.
mkdir -p "$tmp/g"
sed -e 's/^outputs = .*/outputs = ["real_area"]/' -e 's#"../materials/#"'"$PWD"'/materials/#' -e 's#"../lubricants/#"'"$PWD"'/lubricants/#' gears/m6z30.toml > "$tmp/g/area.toml"
"$bin" run -q "$tmp/g/area.toml" -o "$tmp/area.h5" >/dev/null && ok run-area-only || bad run-area-only
"$py" - "$tmp/area.h5" <<'PY' && ok outputs-gated || bad outputs-gated
import sys, h5py
f = h5py.File(sys.argv[1], "r")
assert "real_area_ratio" in f["contact"] and "plastic_area_fraction" not in f["contact"]
assert "max_asperity_von_mises_Pa" not in f["contact"]
names = [n.decode() if isinstance(n, bytes) else n for n in f["meta/stage_names"][()]]
assert not any(n.startswith("asperity_stress") for n in names), names
PY
sed -e 's/^mu = 0.1 .*/mu = 0.0/' -e 's#"../materials/#"'"$PWD"'/materials/#' -e 's#"../lubricants/#"'"$PWD"'/lubricants/#' gears/m6z30.toml > "$tmp/g/frictionless.toml"
"$bin" run -q "$tmp/g/frictionless.toml" -o "$tmp/mu0.h5" --positions 11 >/dev/null && ok run-mu0 || bad run-mu0
"$py" -c "
import h5py
f = h5py.File('$tmp/mu0.h5', 'r')
names = [n.decode() if isinstance(n, bytes) else n for n in f['meta/stage_names'][()]]
assert 'asperity_stress_normal_contact' in names and 'asperity_stress_side_contact' not in names, names
assert f['mesh/s_m'].shape == (11,)
" && ok no-side-contact-at-mu0 || bad no-side-contact-at-mu0
"$bin" run -q --fidelity coupled --positions 21 -o "$tmp/coupled.h5" >/dev/null && ok run-coupled || bad run-coupled
"$py" -c "
import h5py
f = h5py.File('$tmp/coupled.h5', 'r')
assert f['meta'].attrs['fidelity'] in (b'coupled', 'coupled')
names = [n.decode() if isinstance(n, bytes) else n for n in f['meta/stage_names'][()]]
assert 'strip_contact_coupled' in names, names
" && ok coupled-recorded || bad coupled-recorded

# Dynamic loads: a case asking for dynamics records the stage and the dynamic load factor.
sed -e 's/^dynamics = "none" .*/dynamics = "odeint"/' -e 's#"../materials/#"'"$PWD"'/materials/#' -e 's#"../lubricants/#"'"$PWD"'/lubricants/#' gears/m6z30.toml > "$tmp/g/dynamic.toml"
"$bin" run -q "$tmp/g/dynamic.toml" -o "$tmp/dynamic.h5" --positions 21 >/dev/null && ok run-dynamic || bad run-dynamic
"$py" -c "
import h5py, numpy as np
f = h5py.File('$tmp/dynamic.h5', 'r')
names = [n.decode() if isinstance(n, bytes) else n for n in f['meta/stage_names'][()]]
assert 'dynamics_odeint' in names, names
k = f['mesh/dynamic_load_factor'][()]
assert np.all(np.isfinite(k)) and k.max() > 1.0, k
" && ok dynamic-load-recorded || bad dynamic-load-recorded

# Atomic output: a failing write leaves nothing behind.
"$bin" run -q -o "$tmp/missing-dir/x.h5" >/dev/null 2>&1 && bad write-error-status || ok write-error-status
ls -a "$tmp" | grep -q '\.tmp\.' && bad temporary-left || ok no-temporary-left
# What ran is what the file records: --fidelity and --positions are --set changes, every key is in
# /parameters with its value and origin.
"$bin" run -q --positions 21 --set torque=500Nm -o "$tmp/p.h5" >/dev/null && ok run-shorthands || bad run-shorthands
"$py" - "$tmp/p.h5" <<'PY' && ok parameters-recorded || bad parameters-recorded
import sys, h5py
f = h5py.File(sys.argv[1], "r")
text = lambda d: [x.decode() if isinstance(x, bytes) else x for x in d[()]]
p = dict(zip(text(f["parameters/key"]), zip(text(f["parameters/value"]), text(f["parameters/origin"]))))
assert p["contact.positions"] == ("21", "--set"), p["contact.positions"]
assert p["operating.pinion_torque"] == ("500 N m", "--set"), p["operating.pinion_torque"]
assert p["gear_pair.module"][0] == "0.006 m" and "m6z30.toml:" in p["gear_pair.module"][1], p["gear_pair.module"]
assert p["gear_pair.center_distance"] == ("0 m", "default")
assert f["mesh/s_m"].shape == (21,)
assert b"--set contact.positions=21" in f["scene"][()]
PY
exit $fail
