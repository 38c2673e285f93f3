#!/usr/bin/python3
"""Plot a deterministic `geartrib run` result (contact.fidelity = "deterministic").

Usage: scripts/plot_deterministic.py RESULTS.h5 [-o PREFIX] [--window UM]

Writes, with PREFIX defaulting to RESULTS without its .h5:
  PREFIX-path.png        along the path of contact (s from T1 in mm, points A..E marked): the
                         deterministic contact of the flanks' profiles against the statistical model
                         on the same flanks (/statistical), panel by panel: real-area ratio, plastic
                         area fraction, peak pressure (with the Hertz p0), mean real pressure, the
                         von Mises maximum (subsurface against highest asperity) and its depth
  PREFIX-pressure.png    the pressure profiles kept across the strip, each with the smooth Hertz
                         ellipse p0 sqrt(1 - x^2/b^2) of its position
  PREFIX-running-in.png  (with /running_in) the history against the mesh number and a window
                         (--window, default 200 um) from the middle of each active flank, before
                         and after
Panels whose series the file lacks are left out (contact.outputs may ask for fewer; smooth flanks
have no /statistical). Needs Debian's python3-h5py and python3-matplotlib (scripts/setup.sh
installs them); run with /usr/bin/python3.
"""
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from plot_common import (describe, path_points, pick_profiles, plot_path_panels, plot_script,  # noqa: E402
                         profile_heading, profiles_in, read_group, save, tidy_axis)
from plot_mesh import text  # noqa: E402

NAME = "plot_deterministic.py"
# Path panels: label, scale, deterministic /contact series, statistical /statistical series,
# reference /mesh series (dashed) or None.
PATH = [("real-area ratio [1]", 1.0, "real_area_ratio", "statistical_real_area_ratio", None),
        ("plastic area\nfraction [1]", 1.0, "plastic_area_fraction", "statistical_plastic_area_fraction", None),
        ("peak pressure [GPa]", 1e-9, "max_pressure_Pa", "statistical_max_asperity_pressure_Pa", "hertz_p0_Pa"),
        ("mean real\npressure [GPa]", 1e-9, "mean_real_pressure_Pa", "statistical_mean_real_pressure_Pa", None),
        ("von Mises max [GPa]", 1e-9, "max_von_mises_Pa", "statistical_max_asperity_von_mises_Pa", None),
        ("depth of the von\nMises max [um]", 1e6, "max_von_mises_depth_m", None, None)]
PATH_LEGEND = {"max_von_mises_Pa": ("deterministic (subsurface)", "statistical (highest asperity)"),
               "max_pressure_Pa": ("deterministic", "statistical (highest asperity)")}
REFERENCE_LABEL = {"hertz_p0_Pa": "smooth Hertz p0"}
MAX_PROFILES = 8  # pressure profiles drawn; with more kept, the named points A..E (or an even pick)


def note(message):
    print(f"{NAME}: {message}", file=sys.stderr)


def details(f, params):
    """The title's parts of a deterministic run: the element size, the statistical model."""
    parts = []
    if "contact.element_size" in params:
        parts.append(f"elements {float(params['contact.element_size'].split()[0]) * 1e6:g} um")
    if "meta" in f and text(f["meta"].attrs.get("asperity_model", "")):
        parts.append(f"statistical model {text(f['meta'].attrs['asperity_model'])}")
    return parts


def plot_path(s, points, mesh, contact, statistical, title, out, written):
    panels = [p for p in PATH if p[2] in contact or (p[3] and p[3] in statistical)]
    if not panels:
        note("no deterministic or statistical series along the path: skipped " + out)
        return

    def draw(ax, panel):
        _, scale, det, stat, ref = panel
        shown = []
        det_label, stat_label = PATH_LEGEND.get(det, ("deterministic", "statistical"))
        if det in contact:
            shown.append(contact[det] * scale)
            ax.plot(s, shown[-1], color="C0", label=det_label)
        if stat and stat in statistical:
            shown.append(statistical[stat] * scale)
            ax.plot(s, shown[-1], color="C1", label=stat_label)
        if ref and ref in mesh:
            shown.append(mesh[ref] * scale)
            ax.plot(s, shown[-1], color="0.35", linestyle=":", label=REFERENCE_LABEL.get(ref, ref))
        return shown

    plot_path_panels(points, panels, draw, "deterministic against statistical contact along the path", title, out,
                     written)


def plot_pressure(f, mesh, title, out, written):
    if "contact/pressure" not in f or "x_m" not in f["contact/pressure"]:
        note("no /contact/pressure (contact.pressure_profiles = \"none\"?): skipped " + out)
        return
    group = f["contact/pressure"]
    x = group["x_m"][()] * 1e6
    profiles = profiles_in(group, lambda name, d: name.startswith("position_") and isinstance(d, h5py.Dataset))
    if not profiles:
        note("/contact/pressure holds no profiles: skipped " + out)
        return
    kept = len(profiles)
    profiles, picked = pick_profiles(profiles, MAX_PROFILES)
    if picked:
        note(f"{kept} pressure profiles kept; drawing {len(profiles)} ({picked})")
    fig, axes = plt.subplots(len(profiles), 1, figsize=(7.0, 1.75 * len(profiles) + 0.6), dpi=110, sharex=True,
                             sharey=True, squeeze=False)
    axes = axes[:, 0]
    for ax, (position, point, s_m, d) in zip(axes, profiles):
        p = d[()]
        ax.plot(x, p * 1e-9, color="C0", linewidth=0.8, label="deterministic")
        label = profile_heading(position, point, s_m)
        if "hertz_p0_Pa" in mesh and "hertz_halfwidth_m" in mesh and 0 <= position < len(mesh["hertz_p0_Pa"]):
            p0, b = float(mesh["hertz_p0_Pa"][position]), float(mesh["hertz_halfwidth_m"][position]) * 1e6
            xe = np.linspace(-b, b, 401)
            ax.plot(xe, p0 * 1e-9 * np.sqrt(np.clip(1.0 - (xe / b) ** 2, 0.0, None)), color="C3", linestyle="--",
                    linewidth=1.0, label="smooth Hertz")
            label += f", p0 = {p0 * 1e-9:.3f} GPa, b = {b:.0f} um"
        if len(x) > 1:
            label += f", in contact {np.count_nonzero(p > 0.0) * (x[1] - x[0]):.0f} um"
        ax.set_title(label, fontsize=8, loc="left")
        ax.set_ylabel("p [GPa]", fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper right")
    axes[-1].set_xlabel("x across the strip [um]")
    fig.suptitle(f"pressure across the contact strip (first mesh)\n{title}", fontsize=9)
    fig.tight_layout()
    save(fig, out, written)


def plot_running_in(f, window_um, title, out, written):
    if "running_in" not in f:
        note("no /running_in (running_in.meshes = 0): skipped " + out)
        return
    g = f["running_in"]
    h = read_group(f, "running_in")
    if "mesh" not in h:
        note("/running_in has no mesh column: skipped " + out)
        return
    mesh = h["mesh"]
    shakedown = int(g.attrs.get("shakedown_mesh", 0))
    tolerance = float(g.attrs.get("tolerance_m", np.nan))
    ran = int(g.attrs.get("meshes", mesh.max() if mesh.size else 0))
    gears = ("pinion", "wheel")
    # History panels: label, scale, [(series, legend, style)], log axis.
    history = [("new plastic\ndeformation [nm]", 1e9,
                [("new_plastic_deformation_m", "max over the flanks", "o-")], True),
               ("plastic area\nfraction, mean [1]", 1.0, [("plastic_area_fraction_mean", "path mean", "o-")], False),
               ("real-area ratio,\nmean [1]", 1.0, [("real_area_ratio_mean", "path mean", "o-")], False),
               ("Rq, mean peak\nheight [um]", 1e6,
                [(f"{gr}_{q}_m", f"{gr} {label}", st) for q, label, st in
                 (("rq", "Rq", "o-"), ("peak_height", "peak height", "s--")) for gr in gears], False),
               ("Rsk [1]", 1.0, [(f"{gr}_rsk", gr, "o-") for gr in gears], False),
               ("summit radius [um]", 1e6, [(f"{gr}_summit_radius_m", gr, "o-") for gr in gears], False)]
    history = [(lab, sc, [c for c in cols if c[0] in h], log) for lab, sc, cols, log in history]
    history = [hp for hp in history if hp[2]]
    flanks = [gr for gr in gears
              if f"running_in/{gr}_profile_initial_m" in f and f"running_in/{gr}_profile_final_m" in f]
    rows = (len(history) + 1) // 2
    if rows + len(flanks) == 0:
        note("/running_in holds no history or profiles: skipped " + out)
        return
    fig = plt.figure(figsize=(10.0, 2.3 * rows + 2.4 * len(flanks) + 0.7), dpi=110)
    grid = fig.add_gridspec(rows + len(flanks), 2, height_ratios=[1.0] * rows + [1.15] * len(flanks))
    first = None
    for k, (label, scale, cols, log) in enumerate(history):
        ax = fig.add_subplot(grid[k // 2, k % 2], sharex=first)
        first = first or ax
        shown = []
        colors = {"pinion": "C0", "wheel": "C1"}
        for n, (name, legend, style) in enumerate(cols):
            values = h[name] * scale
            color = next((c for gr, c in colors.items() if name.startswith(gr)), f"C{n}")
            if log:
                values = np.where(values > 0.0, values, np.nan)
            ax.plot(mesh, values, style, color=color, ms=3, linewidth=1.0, label=legend)
            shown.append(values)
        if log:
            ax.set_yscale("log")
            if np.isfinite(tolerance):
                ax.axhline(tolerance * scale, color="C3", linestyle=":", linewidth=1.0, label="shakedown tolerance")
        else:
            tidy_axis(ax, shown)
        if label.startswith("Rq"):
            ax.set_ylim(0.0, 1.15 * np.nanmax(np.concatenate(shown)))  # the legend fits between Rq and the peak height
        if shakedown > 0:
            ax.axvline(shakedown, color="C2", linestyle="--", linewidth=0.8)
        ax.set_ylabel(label, fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, which="both", alpha=0.3)
        if len(cols) > 1 or log:
            ax.legend(fontsize=7, loc="center right" if len(cols) > 2 else "best", ncol=2 if len(cols) > 2 else 1)
        if k >= len(history) - 2:
            ax.set_xlabel("mesh (0: the new flanks)", fontsize=8)
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    for k, gr in enumerate(flanks):
        ax = fig.add_subplot(grid[rows + k, :])
        before = g[f"{gr}_profile_initial_m"][()] * 1e6
        after = g[f"{gr}_profile_final_m"][()] * 1e6
        dx = float(g.attrs.get(f"{gr}_profile_spacing_m", np.nan)) * 1e6
        if not np.isfinite(dx) or dx <= 0.0 or before.size == 0 or before.size != after.size:
            note(f"{gr}: no usable profile spacing or profiles of unequal length: its window left out")
            ax.set_axis_off()
            continue
        middle = before.size // 2
        half = max(1, int(round(0.5 * window_um / dx)))
        sl = slice(max(0, middle - half), min(before.size, middle + half + 1))
        xw = (np.arange(before.size)[sl] - middle) * dx
        ax.plot(xw, before[sl], color="0.55", linewidth=0.8, label="new")
        ax.plot(xw, after[sl], color="C0" if gr == "pinion" else "C1", linewidth=0.9, label=f"after mesh {ran}")
        ax.fill_between(xw, after[sl], before[sl], where=before[sl] > after[sl], color="C3", alpha=0.5, linewidth=0,
                        label="flattened")
        removed = before - after
        ax.set_title(f"{gr}: {before.size * dx * 1e-3:.2f} mm active flank, window {xw[-1] - xw[0]:.0f} um at its "
                     f"middle; largest flattening on the flank {removed.max() * 1e3:.0f} nm, "
                     f"{(removed > 1e-3).mean() * 100:.1f}% of its points lowered > 1 nm", fontsize=8, loc="left")
        ax.set_ylabel("height [um]", fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best", ncol=3)
        ax.set_xlabel(f"distance from the middle of the {gr}'s active flank [um]", fontsize=8)
    state = (f"shakedown at mesh {shakedown}" if shakedown > 0 else
             f"no shakedown in {ran} meshes (tolerance {tolerance * 1e9:g} nm)")
    fig.suptitle(f"running-in, {text(g.attrs.get('teeth', ''))} teeth, {state}\n{title}", fontsize=9)
    fig.tight_layout()
    save(fig, out, written)


def draw(f, a, prefix, written):
    mesh = read_group(f, "mesh")
    s = mesh["s_m"] * 1e3
    contact = read_group(f, "contact")
    statistical = read_group(f, "statistical")
    if "statistical" not in f:
        note("no /statistical (smooth flanks have no statistical model): deterministic curves alone")
    title = describe(f, a.results, details)
    plot_path(s, path_points(f), mesh, contact, statistical, title, f"{prefix}-path.png", written)
    plot_pressure(f, mesh, title, f"{prefix}-pressure.png", written)
    plot_running_in(f, a.window, title, f"{prefix}-running-in.png", written)


def main(argv):
    window = (("--window",), dict(type=float, default=200.0, metavar="UM",
                                  help="width of the running-in profile window in um (default 200)"))
    return plot_script(argv, __doc__, NAME, "deterministic", "scripts/plot_mesh.py", draw, options=[window],
                       check=lambda a: None if a.window > 0.0 else "--window must be positive", unnamed=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
