#!/usr/bin/python3
"""Plot a mixed-EHL `geartrib run` result (contact.fidelity = "mixed_ehl").

Usage: scripts/plot_mixed_ehl.py RESULTS.h5 [-o PREFIX]

Writes, with PREFIX defaulting to RESULTS without its .h5:
  PREFIX-path.png      along the path of contact (s from T1 in mm, points A..E marked): the mixed-EHL
                       windows' time means (lines; the band: the window's extremes) against the
                       statistical lubricated cycle on the same flanks (/lubrication), panel by
                       panel: the asperity share of the load, the film (mixed EHL central and least
                       against the statistical cycle's smooth film and mean gap), the friction
                       coefficient, the peak pressure (with the Hertz p0) and the flash temperature
                       (mixed EHL from its local heat flux, statistical by Blok's formula); with
                       mixed_ehl.whole_path the whole path's transient solve is drawn dotted
  PREFIX-contact.png   the film and the pressure through the contact at the positions kept
                       (contact.pressure_profiles), each at its window's instant of highest peak
                       pressure and at its middle, asperity contact nodes marked
Panels whose series the file lacks are left out. Needs Debian's python3-h5py and
python3-matplotlib (scripts/setup.sh installs them); run with /usr/bin/python3.
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
                         profile_heading, profiles_in, read_group, save)

NAME = "plot_mixed_ehl.py"
# Path panels: label, scale, [(group, series, legend, style)], [(group, low, high)] bands.
PATH = [("asperity share\nof the load [1]", 1.0,
         [("mixed_ehl", "ehl_asperity_share_mean", "mixed EHL (time mean)", "C0-"),
          ("mixed_ehl", "ehl_path_asperity_share", "mixed EHL, whole path", "C0:"),
          ("lubrication", "asperity_load_share", "statistical (JGP sharing)", "C1-")],
         [("mixed_ehl", "ehl_asperity_share_mean", "ehl_asperity_share_max")]),
        ("film [um]", 1e6,
         [("mixed_ehl", "ehl_central_film_mean_m", "mixed EHL central", "C0-"),
          ("mixed_ehl", "ehl_min_film_mean_m", "mixed EHL least", "C2-"),
          ("mixed_ehl", "ehl_path_min_film_m", "mixed EHL least, whole path", "C2:"),
          ("lubrication", "film_m", "statistical: smooth film", "C1-"),
          ("lubrication", "mean_gap_m", "statistical: mean gap", "C1--")],
         [("mixed_ehl", "ehl_min_film_min_m", "ehl_min_film_mean_m")]),
        ("friction\ncoefficient [1]", 1.0,
         [("mixed_ehl", "ehl_friction_coefficient_mean", "mixed EHL (time mean)", "C0-"),
          ("mixed_ehl", "ehl_path_friction_coefficient", "mixed EHL, whole path", "C0:"),
          ("lubrication", "friction_coefficient", "statistical", "C1-")],
         [("mixed_ehl", "ehl_friction_coefficient_mean", "ehl_friction_coefficient_max")]),
        ("peak pressure [GPa]", 1e-9,
         [("mixed_ehl", "ehl_peak_pressure_mean_Pa", "mixed EHL (time mean)", "C0-"),
          ("mesh", "hertz_p0_Pa", "smooth Hertz p0", "0.35:")],
         [("mixed_ehl", "ehl_peak_pressure_mean_Pa", "ehl_peak_pressure_max_Pa")]),
        ("flash\ntemperature [K]", 1.0,
         [("mixed_ehl", "ehl_flash_temperature_mean_K", "mixed EHL (time mean)", "C0-"),
          ("lubrication", "flash_temperature_K", "statistical (Blok)", "C1-")],
         [("mixed_ehl", "ehl_flash_temperature_mean_K", "ehl_flash_temperature_max_K")])]
STATES = {2: ("asperity contact", "C3")}
MAX_PROFILES = 5  # profiles drawn; with more kept, the named points A..E (or an even pick)


def note(message):
    print(f"{NAME}: {message}", file=sys.stderr)


def details(f, params):
    """The title's part of a mixed-EHL run: the grid, the window and the time step (smooth flanks,
    whose title would leave out Rq, are refused by a mixed-EHL run)."""
    if "mixed_ehl" not in f:
        return []
    a = f["mixed_ehl"].attrs
    return [f"nodes {float(a.get('grid_spacing_m', np.nan)) * 1e6:.3g} um, window "
            f"{float(a.get('window_contact_widths', np.nan)):g} x 2b, Courant {float(a.get('time_step_courant', np.nan)):g}"]


def plot_path(s, points, groups, title, out, written):
    panels = [p for p in PATH if any(name in groups.get(g, {}) for g, name, _, _ in p[2])]
    if not panels:
        note("no mixed-EHL or statistical series along the path: skipped " + out)
        return

    def draw(ax, panel):
        _, scale, lines, bands = panel
        shown = []
        for g, lo, hi in bands:
            if lo in groups.get(g, {}) and hi in groups.get(g, {}):
                ax.fill_between(s, groups[g][lo] * scale, groups[g][hi] * scale, color="C0", alpha=0.15, linewidth=0,
                                label="mixed EHL: window's range")
        for g, name, legend, style in lines:
            if name not in groups.get(g, {}):
                continue
            values = groups[g][name] * scale
            shown.append(values)
            color, line = (style[:2], style[2:]) if style.startswith("C") else (style[:4], style[4:])
            ax.plot(s, values, color=color, linestyle=line, marker="o", ms=2.5, linewidth=1.0, label=legend)
        return shown

    plot_path_panels(points, panels, draw, "mixed EHL against the statistical lubricated cycle along the path", title,
                     out, written)


def plot_contact(f, mesh, title, out, written):
    if "mixed_ehl/profiles" not in f:
        note("no /mixed_ehl/profiles (contact.pressure_profiles = \"none\"?): skipped " + out)
        return
    profiles = profiles_in(f["mixed_ehl/profiles"], lambda name, g: isinstance(g, h5py.Group) and "x_m" in g)
    if not profiles:
        note("/mixed_ehl/profiles holds none: skipped " + out)
        return
    kept = len(profiles)
    profiles, picked = pick_profiles(profiles, MAX_PROFILES)
    if picked:
        note(f"{kept} profiles kept; drawing {len(profiles)}")
    fig, axes = plt.subplots(len(profiles), 2, figsize=(11.0, 2.0 * len(profiles) + 0.8), dpi=110, squeeze=False)
    for row, (position, point, s_m, g) in enumerate(profiles):
        x = g["x_m"][()]
        b = float(mesh["hertz_halfwidth_m"][position]) if "hertz_halfwidth_m" in mesh else 1.0
        xb = x / b
        head = profile_heading(position, point, s_m)
        ax_p, ax_h = axes[row]
        for instant, style in (("peak", "C0-"), ("middle", "C2-")):
            if f"{instant}_pressure_Pa" not in g:
                continue
            t = float(g.attrs.get(f"{instant}_time_s", np.nan)) * 1e6
            legend = f"{'highest peak' if instant == 'peak' else 'middle'} (t = {t:.1f} us)"
            p = g[f"{instant}_pressure_Pa"][()] * 1e-9
            h = g[f"{instant}_film_m"][()] * 1e6
            state = g[f"{instant}_state"][()] if f"{instant}_state" in g else np.zeros_like(p)
            ax_p.plot(xb, p, style[:2], linewidth=0.8, label=legend)
            ax_h.plot(xb, h, style[:2], linewidth=0.8, label=legend)
            for code, (what, color) in STATES.items():
                on = state == code
                if on.any():
                    ax_p.plot(xb[on], p[on], ".", color=color, ms=2.5, label=f"{what} ({instant})")
        if "hertz_p0_Pa" in mesh:
            p0 = float(mesh["hertz_p0_Pa"][position]) * 1e-9
            xe = np.linspace(-1.0, 1.0, 201)
            ax_p.plot(xe, p0 * np.sqrt(1.0 - xe ** 2), color="0.35", linestyle=":", linewidth=1.0,
                      label="smooth Hertz")
        ax_p.set_title(head + f", b = {b * 1e6:.0f} um", fontsize=8, loc="left")
        ax_p.set_ylabel("p [GPa]", fontsize=8)
        ax_h.set_ylabel("h [um]", fontsize=8)
        hmax = max(np.percentile(g["peak_film_m"][()], 60) * 1e6 if "peak_film_m" in g else 1.0, 1e-3)
        ax_h.set_ylim(0.0, hmax)  # the inlet's film grows as x^2: the contact's part shown
        for ax in (ax_p, ax_h):
            ax.tick_params(labelsize=8)
            ax.grid(True, alpha=0.3)
        if row == 0:
            ax_p.legend(fontsize=6, loc="upper left")
            ax_h.legend(fontsize=6, loc="upper left")
    for ax in axes[-1]:
        ax.set_xlabel("x / b (rolling direction; inlet at x < 0)", fontsize=8)
    fig.suptitle(f"pressure and film through the contact\n{title}", fontsize=9)
    fig.tight_layout()
    save(fig, out, written)


def draw(f, a, prefix, written):
    groups = {g: read_group(f, g) for g in ("mesh", "mixed_ehl", "lubrication", "contact")}
    s = groups["mesh"]["s_m"] * 1e3
    title = describe(f, a.results, details)
    plot_path(s, path_points(f), groups, title, f"{prefix}-path.png", written)
    plot_contact(f, groups["mesh"], title, f"{prefix}-contact.png", written)


def main(argv):
    return plot_script(argv, __doc__, NAME, "mixed_ehl", "scripts/plot_mesh.py or scripts/plot_deterministic.py", draw)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
