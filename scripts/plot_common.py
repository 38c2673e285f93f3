"""What the fidelities' plot scripts (plot_deterministic.py, plot_mixed_ehl.py) share: the command
line and the run's file, its groups and one-line title, the panels along the path of contact and the
pick of the profiles kept. Not a script; they import it (with plot_mesh's drawing of the points A..E).
"""
import argparse
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_mesh import mark_points, text  # noqa: E402  (one drawing of the path's points A..E)


def tidy_axis(ax, values):
    # Plain tick labels (no offset notation); a visible band for nearly constant data.
    ax.ticklabel_format(axis="y", useOffset=False)
    finite = np.concatenate([np.asarray(v, dtype=float).ravel() for v in values])
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return
    lo, hi = float(finite.min()), float(finite.max())
    if hi - lo <= 1e-3 * max(abs(hi), abs(lo), 1e-300):
        pad = 0.05 * abs(hi) if hi != 0.0 else 0.05
        ax.set_ylim(lo - pad, hi + pad)


def read_group(f, group):
    """The group's 1-D datasets as {name: array}; empty when the group is absent."""
    if group not in f or not isinstance(f[group], h5py.Group):
        return {}
    return {name: d[()] for name, d in f[group].items() if isinstance(d, h5py.Dataset) and d.ndim == 1}


def save(fig, out, written):
    fig.savefig(out)
    plt.close(fig)
    written.append(out)


def describe(f, path, details):
    """A one-line title: the file, the flanks, the parts details(f, params) gives (params: /parameters
    as {key: value}), the regime."""
    params = {}
    if "parameters" in f and "key" in f["parameters"] and "value" in f["parameters"]:
        params = {text(k): text(v) for k, v in zip(f["parameters/key"][()], f["parameters/value"][()])}
    parts = [os.path.basename(path)]
    kinds = {params.get(f"{g}.flank.profile.kind") for g in ("pinion", "wheel")} - {None}
    if kinds:
        flank = "/".join(sorted(kinds))
        if kinds != {"smooth"} and "pinion.flank.profile.rq" in params:
            flank += f" Rq {float(params['pinion.flank.profile.rq'].split()[0]) * 1e6:g} um"
        parts.append(f"{flank} flanks")
    parts += details(f, params)
    if "contact/validity" in f and "regime" in f["contact/validity"].attrs:
        parts.append(f"regime {text(f['contact/validity'].attrs['regime'])}")
    return ", ".join(parts)


def path_points(f):
    """The named points A..E as (name, s from T1 [mm])."""
    return [(q, f["mesh"].attrs[f"s_{q}_m"] * 1e3) for q in "ABCDE" if f"s_{q}_m" in f["mesh"].attrs]


def plot_path_panels(points, panels, draw, heading, title, out, written):
    """One row a panel along the path, the points A..E marked: draw(ax, panel) draws a panel's
    curves against s [mm] and returns the values it drew; a panel's first item is its axis label."""
    fig, axes = plt.subplots(len(panels), 1, figsize=(9.0, 1.9 * len(panels) + 0.8), dpi=110, sharex=True,
                             squeeze=False)
    axes = axes[:, 0]
    for ax, panel in zip(axes, panels):
        tidy_axis(ax, draw(ax, panel))
        mark_points(ax, points)
        ax.set_ylabel(panel[0], fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    axes[-1].set_xlabel("position on the line of action s (from T1) [mm]")
    fig.suptitle(f"{heading}\n{title}", fontsize=9)
    fig.tight_layout()
    save(fig, out, written)


def profiles_in(group, accept):
    """The profiles a group keeps, (position, point name or "", s from T1 [m], the member) each, of the
    members accept(name, member) takes: the position from the member's attribute, else its name
    (position_<k>)."""
    return [(int(m.attrs.get("position", name.split("_", 1)[1])), text(m.attrs.get("point", "")),
             float(m.attrs.get("s_m", np.nan)), m) for name, m in group.items() if accept(name, m)]


def pick_profiles(profiles, most):
    """The profiles to draw of those kept, (position, point name or "", ...) each, sorted by position,
    and how they were picked: all (None) when at most `most`; else the named points A..E when there
    are that few ("the points A..E"); else `most` evenly spaced ("evenly spaced")."""
    profiles = sorted(profiles, key=lambda p: p[0])
    if len(profiles) <= most:
        return profiles, None
    named = [p for p in profiles if p[1]]
    if 0 < len(named) <= most:
        return named, "the points A..E"
    pick = np.unique(np.linspace(0, len(profiles) - 1, most).round().astype(int))
    return [profiles[i] for i in pick], "evenly spaced"


def profile_heading(position, point, s_m):
    """A profile's title: its point, position and s from T1."""
    return f"{point + ': ' if point else ''}position {position}, s = {s_m * 1e3:.2f} mm"


def plot_script(argv, doc, name, fidelity, others, draw, options=(), check=None, unnamed=False):
    """A fidelity's plot script, its exit code. The command line: RESULTS.h5, -o PREFIX and
    `options` ((flags, keywords) of add_argument each), refused with check(arguments)'s message when
    it gives one; the usage (the doc string) without arguments. The file: refused when it is not a
    `geartrib run` result or ran another fidelity than `fidelity` (`others`: the scripts that plot
    those; `unnamed`: a file naming none is taken). Then draw(f, arguments, prefix, written) draws,
    and the files written are listed."""
    if len(argv) == 1:
        print(doc.strip(), file=sys.stderr)
        return 2
    lines = doc.strip().splitlines()
    usage = "%(prog)s " + next(line for line in lines if line.startswith("Usage: ")).split(" ", 2)[2]
    p = argparse.ArgumentParser(prog="scripts/" + name, usage=usage,
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                description="\n".join(line for line in lines if not line.startswith("Usage: ")))
    p.add_argument("results", metavar="RESULTS.h5")
    p.add_argument("-o", "--output", metavar="PREFIX", help="output prefix (default: RESULTS without .h5)")
    for flags, keywords in options:
        p.add_argument(*flags, **keywords)
    a = p.parse_args(argv[1:])
    prefix = a.output or (a.results[:-3] if a.results.endswith(".h5") else a.results)
    refusal = check(a) if check else None
    if refusal:
        print(f"{name}: {refusal}", file=sys.stderr)
        return 2
    try:
        f = h5py.File(a.results, "r")
    except OSError as e:
        print(f"{name}: cannot read {a.results}: {e}", file=sys.stderr)
        return 2
    written = []
    with f:
        if "mesh" not in f or "s_m" not in f["mesh"]:
            print(f"{name}: {a.results} has no /mesh/s_m: not a `geartrib run` result", file=sys.stderr)
            return 2
        ran = text(f["meta"].attrs.get("fidelity", "")) if "meta" in f else ""
        if ran != fidelity and (ran or not unnamed):
            print(f"{name}: {a.results} ran contact.fidelity = \"{ran}\", not \"{fidelity}\"; plot it with {others}",
                  file=sys.stderr)
            return 2
        outdir = os.path.dirname(prefix)
        if outdir:
            os.makedirs(outdir, exist_ok=True)
        draw(f, a, prefix, written)
    for out in written:
        print(f"wrote {out}")
    return 0
