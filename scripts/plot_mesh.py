#!/usr/bin/python3
"""Plot a `geartrib run` result along the path of contact.

Usage: scripts/plot_mesh.py RESULTS.h5 OUTDIR

Draws every /mesh, /contact and /lubrication quantity against the position s on the line of
action (mm) as OUTDIR/<group>_<name>.png, in engineering units (MPa, um, N/mm, degC for
temperatures, K for temperature rises), with the points A..E marked by the pinion diameter
they lie on; OUTDIR/overview.png with the main quantities stacked and, for a lubricated run,
OUTDIR/lubrication.png: film, mean gap and h_Y, the lambdas, the load shares, friction with the
gear-mean laws beside it, contact temperatures, wear depth per engagement. Needs Debian's
python3-h5py and python3-matplotlib (scripts/setup.sh installs them); run with /usr/bin/python3.
"""
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OVERVIEW = [("mesh", "load_share"), ("mesh", "hertz_p0_Pa"), ("contact", "real_area_ratio"),
            ("contact", "plastic_area_fraction"), ("contact", "max_asperity_von_mises_Pa"), ("mesh", "srr")]
# Lubricated runs: each panel one or more /lubrication series sharing a unit.
LUBRICATION = [("film [um]", 1e6, ["film_m", "mean_gap_m", "iso_film_hy_m"]),
               ("lambda [1]", 1.0, ["lambda_smooth_film", "lambda_mean_gap", "iso_lambda_gf"]),
               ("load share [1]", 1.0, ["asperity_load_share", "film_load_share"]),
               ("friction [1]", 1.0, ["friction_coefficient"]),
               ("temperature [degC]", 1.0, ["contact_temperature_K", "iso_contact_temperature_K"]),
               ("wear per engagement [nm]", 1e9, ["wear_depth_pinion_m", "wear_depth_wheel_m"])]
# The gear-mean friction laws (attributes of /lubrication) drawn beside the local friction.
MEAN_FRICTION = ["mean_friction_iso", "mean_friction_iso_flash", "mean_friction_schlenk", "mean_friction_fernandes"]


def engineering(name, values, units):
    """Values and unit label in the units an engineer reads: MPa, um or mm, N/mm, degC."""
    if units == "Pa":
        return values * 1e-6, "MPa"
    if units == "N/m":
        return values * 1e-3, "N/mm"
    if units == "m":
        top = max(abs(float(v)) for v in values) if len(values) else 0.0
        return (values * 1e6, "um") if top < 1e-3 else (values * 1e3, "mm")
    if units == "K" and "temperature" in name and "flash" not in name and "rise" not in name:
        return values - 273.15, "degC"
    return values, units


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def tidy_axis(ax, values):
    # Plain tick labels (no offset notation); a visible band for nearly constant data.
    ax.ticklabel_format(axis="y", useOffset=False)
    lo, hi = float(min(values)), float(max(values))
    if hi - lo <= 1e-9 * max(abs(hi), abs(lo), 1e-300):
        pad = 0.05 * max(abs(hi), 1e-300)
        ax.set_ylim(lo - pad, hi + pad)


def mark_points(ax, points):
    """points: (name, s mm) or (name, s mm, pinion diameter mm) per point."""
    for name, s, *diameter in points:
        ax.axvline(s, color="0.6", linestyle="--", linewidth=0.8)
        label = f"{name}\nd1 {diameter[0]:.1f}" if diameter and diameter[0] else name
        ax.annotate(label, (s, 0.03), xycoords=("data", "axes fraction"), ha="left", va="bottom", fontsize=7,
                    xytext=(2, 0), textcoords="offset points")


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    path, outdir = argv[1], argv[2]
    os.makedirs(outdir, exist_ok=True)
    with h5py.File(path, "r") as f:
        s_m = f["mesh/s_m"][()]
        s = s_m * 1e3
        # The pinion's base radius from the roll angle rho1/r_b1 (rho1 = s); the diameter through
        # each point: 2 sqrt(r_b1^2 + s^2) [mm].
        roll = f["mesh/roll_angle_rad"][()]
        k = int(abs(roll).argmax())
        base = s_m[k] / roll[k] if roll[k] else 0.0
        points = []
        for p in "ABCDE":
            at = f["mesh"].attrs[f"s_{p}_m"]
            points.append((p, at * 1e3, 2e3 * (base * base + at * at) ** 0.5 if base else 0.0))
        mean_friction = {}
        if "lubrication" in f:
            for key in MEAN_FRICTION:
                if key in f["lubrication"].attrs:
                    mean_friction[key] = float(f["lubrication"].attrs[key])
        title = f"{text(f['meta'].attrs['asperity_model'])}, {text(f['meta'].attrs['fidelity'])} strip"
        series = {}
        for group in ("mesh", "contact", "contact/validity", "lubrication"):
            if group not in f:
                continue
            for name, data in f[group].items():
                if name != "s_m" and isinstance(data, h5py.Dataset):
                    series[(group, name)] = (data[()], text(data.attrs["units"]))
    written = []
    for (group, name), (raw, raw_units) in series.items():
        values, units = engineering(name, raw, raw_units)
        fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=110)
        ax.plot(s, values, color="C0")
        tidy_axis(ax, values)
        mark_points(ax, points)
        ax.set_xlabel("position on the line of action s [mm]")
        ax.set_ylabel(f"{name} [{units}]")
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        out = os.path.join(outdir, f"{group.replace('/', '_')}_{name}.png")
        fig.savefig(out)
        plt.close(fig)
        written.append(out)
    wanted = [k for k in OVERVIEW if k in series]
    if wanted:
        fig, axes = plt.subplots(len(wanted), 1, figsize=(7.0, 1.9 * len(wanted)), dpi=110, sharex=True)
        for ax, key in zip(axes if len(wanted) > 1 else [axes], wanted):
            values, units = engineering(key[1], *series[key])
            ax.plot(s, values, color="C0")
            tidy_axis(ax, values)
            mark_points(ax, points)
            ax.set_ylabel(f"{key[1]}\n[{units}]", fontsize=8)
            ax.grid(True, alpha=0.3)
        axes[-1].set_xlabel("position on the line of action s [mm]")
        fig.suptitle(title, fontsize=9)
        fig.tight_layout()
        out = os.path.join(outdir, "overview.png")
        fig.savefig(out)
        plt.close(fig)
        written.append(out)
    if any(g == "lubrication" for g, _ in series):
        fig, axes = plt.subplots(len(LUBRICATION), 1, figsize=(7.0, 1.9 * len(LUBRICATION)), dpi=110, sharex=True)
        for ax, (label, scale, names) in zip(axes, LUBRICATION):
            for k, name in enumerate(names):
                if ("lubrication", name) not in series:
                    continue
                values, _ = series[("lubrication", name)]
                shown = values - 273.15 if name.endswith("_K") else values * scale
                ax.plot(s, shown, color=f"C{k}", label=name)
            if label.startswith("friction"):
                for k, (key, value) in enumerate(mean_friction.items()):
                    ax.axhline(value, color=f"C{k + 1}", linestyle=":", linewidth=1.0,
                               label=key.replace("mean_friction_", "gear-mean ").replace("_", "-"))
            mark_points(ax, points)
            ax.set_ylabel(label, fontsize=8)
            ax.legend(fontsize=7, loc="best")
            ax.grid(True, alpha=0.3)
        axes[-1].set_xlabel("position on the line of action s [mm]")
        fig.suptitle(f"lubricated: {title}", fontsize=9)
        fig.tight_layout()
        out = os.path.join(outdir, "lubrication.png")
        fig.savefig(out)
        plt.close(fig)
        written.append(out)
    print(f"wrote {len(written)} plots to {outdir}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
