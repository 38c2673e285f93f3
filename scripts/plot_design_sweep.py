#!/usr/bin/python3
"""Plot a `geartrib sweep` table: quantities over the sweep's axes.

Usage: scripts/plot_design_sweep.py SWEEP.h5|SWEEP.csv -o OUT.png [--quantity Q ...] [--x AXIS]
           [--lines AXIS] [--at AXIS=VALUE ...] [--logx]

The axes are the sweep's --set keys: the HDF5 file's /sweep attribute "axes"; in the CSV, the
columns between "point" and "status" (the table's layout). An axis with one value is a fixed value
(in the title). Of the axes that vary, the first is x (or --x), the second gives one line per value
(or --lines), the third one column of panels per value; hold the others at one value with
--at AXIS=VALUE (the value as in the table: SI, or the text). A zipped sweep (its points not a grid)
is one line along x.

Quantities (--quantity, repeatable or comma-separated; one row of panels each; "ratings" stands for
a rated sweep's safety factors S_H_min, S_F_min, S_S_min, lambda_GF_min, S_lambda): by default the
mesh-level values of a lubricated sweep that are present (mesh_power_loss_W,
tooth_friction_efficiency, gear_loss_factor_path, bulk_temperature_K, iso_scuffing_safety,
scuffing_safety, min_iso_lambda_gf), else hertz_p0_Pa_max, real_area_ratio_min and
plastic_area_fraction_max. Failed points and missing values (NaN: a dry point's mesh-level values)
are left out. Axes in engineering units: MPa, um or mm, degC (K for a temperature rise), N/mm,
1/min, mPa s. Debian's python3-matplotlib (and python3-h5py for .h5); /usr/bin/python3.
"""
import argparse
import csv
import difflib
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

MESH_LEVEL = ["mesh_power_loss_W", "tooth_friction_efficiency", "gear_loss_factor_path", "bulk_temperature_K",
              "iso_scuffing_safety", "scuffing_safety", "min_iso_lambda_gf"]
DRY = ["hertz_p0_Pa_max", "real_area_ratio_min", "plastic_area_fraction_max"]
RATING = ["S_H_min", "S_F_min", "S_S_min", "lambda_GF_min", "S_lambda"]  # a rated sweep's safety factors ([rating] methods)
MAX_PANELS = 8  # values of the third axis, one column of panels each


class PlotError(Exception):
    """The table or the options do not give a plot; the message says what to do."""


def read_table(path):
    """(columns as lists: numbers as float, text as str; units; the axes' column names)."""
    if path.endswith(".h5"):
        import h5py

        def text(x):
            return x.decode() if isinstance(x, bytes) else str(x)

        with h5py.File(path, "r") as f:
            # Numeric columns: one block /points/values (points x columns, attributes columns and
            # units); text columns: one string dataset each; /points's attribute columns: the order.
            g, block = f["points"], f["points/values"]
            numeric = text(block.attrs["columns"]).split(",")
            numeric_units = dict(zip(numeric, text(block.attrs["units"]).split(",")))
            values = block[()]
            cols, units = {}, {}
            for n in text(g.attrs["columns"]).split(","):
                if n in numeric_units:
                    cols[n] = [float(v) for v in values[:, numeric.index(n)]]
                    units[n] = numeric_units[n]
                else:
                    cols[n] = [text(v) for v in g[n][()]]
                    units[n] = ""
            axes = text(f["sweep"].attrs["axes"]).split(",") if "axes" in f["sweep"].attrs else None
    else:
        with open(path) as f:
            lines = f.read().splitlines()
        unit_line = next((line for line in lines if line.startswith("# units:")), "# units:")
        rows = list(csv.reader(line for line in lines if not line.startswith("#")))
        header, body = rows[0], rows[1:]
        unit_list = unit_line[len("# units:"):].strip().split(",")
        cols, units = {}, {}
        for i, n in enumerate(header):
            vals = [r[i] for r in body]
            try:
                cols[n] = [float(v) for v in vals]
            except ValueError:
                cols[n] = vals
            units[n] = unit_list[i] if i < len(unit_list) else ""
        axes = None
    if axes is None:  # the table's layout: point, the axes, status, ...
        names = list(cols)
        if "point" not in names or "status" not in names:
            raise PlotError(f"{path}: not a geartrib sweep table (no point and status columns)")
        axes = names[names.index("point") + 1:names.index("status")]
    return cols, units, axes


def engineering(name, unit):
    """(function SI -> shown value, the unit shown) for a column."""
    if unit == "Pa":
        return (lambda v: v / 1e6), "MPa"
    if unit == "N/m":
        return (lambda v: v / 1e3), "N/mm"
    if unit == "rad/s":
        return (lambda v: v * 60.0 / (2.0 * math.pi)), "1/min"
    if unit == "Pa s":
        return (lambda v: v * 1e3), "mPa s"
    if unit == "1/Pa":
        return (lambda v: v * 1e9), "1/GPa"
    if unit == "K" and "flash" not in name:  # a flash temperature is a rise: kelvin
        return (lambda v: v - 273.15), "degC"
    return (lambda v: v), ("" if unit == "1" else unit)


def length_scale(values):
    """Lengths in um below 0.1 mm (roughness, films, summits), else mm (module, face width)."""
    finite = [abs(v) for v in values if isinstance(v, float) and math.isfinite(v)]
    return ((lambda v: v * 1e3), "mm") if finite and max(finite) >= 1e-4 else ((lambda v: v * 1e6), "um")


def scale(cols, units, name):
    if units.get(name) == "m":
        return length_scale(cols[name])
    return engineering(name, units.get(name, ""))


def label(name, unit):
    """A column's name without its unit and statistic: hertz_p0_Pa_max -> "hertz p0, max"."""
    stat = ""
    for s in ("_min", "_mean", "_max"):
        if name.endswith(s):
            name, stat = name[:-len(s)], s[1:]
    token = "_" + unit.replace("1/", "per_").replace("/", "_per_").replace(" ", "_") if unit not in ("", "1") else ""
    if token and name.endswith(token):
        name = name[:-len(token)]
    return name.replace("_", " ") + (f", {stat}" if stat else "")


def value_text(cols, units, axis, v):
    """An axis value as shown: "ra = 0.4 um", "fidelity = coupled"."""
    if isinstance(v, str):
        return f"{axis} = {v}"
    f, u = scale(cols, units, axis)
    return f"{axis} = {f(v):g}" + (f" {u}" if u else "")


def distinct(values):
    """An axis's values: numbers ascending, text in order of first appearance."""
    seen = list(dict.fromkeys(values))
    return seen if seen and isinstance(seen[0], str) else sorted(seen)


def held_value(cols, axis, text):
    """The row value of AXIS that --at AXIS=TEXT names (numbers to a relative 1e-9: a lo:hi:n axis)."""
    values = distinct(cols[axis])
    for v in values:
        if isinstance(v, str):
            if v == text:
                return v
        else:
            try:
                if math.isclose(v, float(text), rel_tol=1e-9):
                    return v
            except ValueError:
                break
    raise PlotError(f"--at {axis}={text}: not a value of the sweep ({axis}: {', '.join(f'{v:g}' if not isinstance(v, str) else v for v in values)})")


def plot(table, quantities=None, x=None, lines=None, at=(), logx=False):
    """The figure of a sweep table file (PlotError when the options do not fit the table)."""
    cols, units, axes = read_table(table)
    missing = [a for a in axes if a not in cols]
    if missing:
        raise PlotError(f"{table}: the axes {', '.join(missing)} are not columns of the table")
    rows = [i for i, s in enumerate(cols["status"]) if s == "ok"]
    if not rows:
        raise PlotError(f"{table}: no point ran (status ok)")

    # The quantities: given, or the defaults present (with a value at some point).
    def has_values(name):
        return name in cols and not isinstance(cols[name][0], str) and any(math.isfinite(cols[name][i]) for i in rows)

    if quantities:
        for q in quantities:
            if q not in cols:
                close = difflib.get_close_matches(q, list(cols), n=4, cutoff=0.5)
                raise PlotError(f"{table}: no column '{q}'" + (f" (did you mean {', '.join(close)}?)" if close else ""))
            if isinstance(cols[q][0], str):
                raise PlotError(f"{table}: '{q}' is a text column, not a quantity")
    else:
        quantities = [q for q in MESH_LEVEL if has_values(q)] or [q for q in DRY if has_values(q)]
        if not quantities:
            raise PlotError(f"{table}: none of the default quantities has a value: give --quantity")

    # The axes: held (--at), fixed (one value), and those that vary: x, lines, panels.
    held = {}
    for kv in at:
        axis, eq, text = kv.partition("=")
        if not eq or axis not in axes:
            raise PlotError(f"--at {kv}: expected AXIS=VALUE with AXIS one of the sweep's axes ({', '.join(axes)})")
        held[axis] = held_value(cols, axis, text)
    fixed = {a: cols[a][0] for a in axes if a not in held and len(distinct(cols[a])) == 1}
    fixed.update(held)
    varying = [a for a in axes if a not in fixed]
    for name, option in ((x, "--x"), (lines, "--lines")):
        if name is not None and name not in varying:
            raise PlotError(f"{option} {name}: not an axis that varies here ({', '.join(varying) or 'none'})")
    order = [a for a in (x, lines) if a] + [a for a in varying if a not in (x, lines)]
    if not order:
        raise PlotError(f"{table}: no axis varies (axes: {', '.join(axes)})")
    rows = [i for i in rows if all(cols[a][i] == v for a, v in held.items())]
    # A zipped sweep's points are not a grid: one line along its first axis.
    combos = {tuple(cols[a][i] for a in order) for i in range(len(cols["status"]))}
    grid = len(combos) == math.prod(len(distinct(cols[a])) for a in order)
    if not grid:
        order = order[:1]
    if len(order) > 3:
        raise PlotError(f"{table}: {len(order)} axes vary ({', '.join(order)}): a plot shows three (x, lines, "
                        f"panels); hold the others with --at AXIS=VALUE, e.g. --at {order[3]}={distinct(cols[order[3]])[0]}")
    x_axis = order[0]
    line_axis = order[1] if len(order) > 1 else None
    panel_axis = order[2] if len(order) > 2 else None
    panels = distinct(cols[panel_axis]) if panel_axis else [None]
    if len(panels) > MAX_PANELS:
        raise PlotError(f"{table}: {panel_axis} has {len(panels)} values, one column of panels each (at most "
                        f"{MAX_PANELS}): hold it with --at {panel_axis}=VALUE or make it --x")
    line_values = distinct(cols[line_axis]) if line_axis else [None]

    if panel_axis:
        nrows, ncols = len(quantities), len(panels)
    else:
        ncols = min(len(quantities), 3)
        nrows = math.ceil(len(quantities) / ncols)
    fig, grid_axes = plt.subplots(nrows, ncols, figsize=(4.3 * ncols, 3.1 * nrows + 0.3), dpi=110, squeeze=False,
                                  layout="constrained")
    fx, ux = scale(cols, units, x_axis)
    text_x = isinstance(cols[x_axis][0], str)
    drawn = set()  # the line values with a point in some panel
    for qi, q in enumerate(quantities):
        fy, uy = scale(cols, units, q)
        for pi, panel in enumerate(panels):
            ax = grid_axes[qi][pi] if panel_axis else grid_axes[qi // ncols][qi % ncols]
            title = label(q, units.get(q, ""))
            if panel_axis:
                title += f" ({value_text(cols, units, panel_axis, panel)})"
            ax.set_title(title, fontsize=9)
            for li, lv in enumerate(line_values):
                idx = [i for i in rows if (lv is None or cols[line_axis][i] == lv)
                       and (panel is None or cols[panel_axis][i] == panel) and math.isfinite(cols[q][i])]
                if not idx:
                    continue
                if not text_x:
                    idx.sort(key=lambda i: cols[x_axis][i])
                xs = [cols[x_axis][i] if text_x else fx(cols[x_axis][i]) for i in idx]
                ax.plot(xs, [fy(cols[q][i]) for i in idx], "o-", ms=4, color=f"C{li % 10}",
                        label=None if lv is None else value_text(cols, units, line_axis, lv))
                drawn.add(li)
            if not ax.lines:
                ax.text(0.5, 0.5, "no values", ha="center", va="center", transform=ax.transAxes, color="0.5")
            ax.set_xlabel(f"{x_axis} [{ux}]" if ux else x_axis, fontsize=8)
            ax.set_ylabel(f"[{uy}]" if uy else "[-]", fontsize=8)
            ax.tick_params(labelsize=8)
            if logx and not text_x:
                ax.set_xscale("log")
            elif not text_x:
                ax.ticklabel_format(axis="x", useOffset=False)
            ax.ticklabel_format(axis="y", useOffset=False)  # 0.99998, not 1e-5 + 0.9999
            ax.grid(alpha=0.3)
    if line_axis:  # one legend, each value in its colour in every panel
        grid_axes[0][0].legend(handles=[Line2D([], [], color=f"C{li % 10}", marker="o", ms=4, label=value_text(
            cols, units, line_axis, lv)) for li, lv in enumerate(line_values) if li in drawn], fontsize=7)
    for k in range(len(quantities), nrows * ncols):  # the grid's unused cells
        if not panel_axis:
            grid_axes[k // ncols][k % ncols].set_visible(False)
    notes = [value_text(cols, units, a, v) for a, v in fixed.items()]
    if not grid and len(varying) > 1:
        notes.append(f"zipped: {', '.join(varying[1:])} with {x_axis}")
    if notes:
        fig.suptitle("; ".join(notes), fontsize=9)
    return fig


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("table", help="the sweep's HDF5 file (-o) or CSV (--csv)")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--quantity", action="append", default=[],
                   help="a column to plot (repeatable, or comma-separated; 'ratings': the safety factors); "
                   "default: the mesh-level values")
    p.add_argument("--x", help="the axis along x (default: the first that varies)")
    p.add_argument("--lines", help="the axis with one line per value (default: the second that varies)")
    p.add_argument("--at", action="append", default=[], help="AXIS=VALUE: hold an axis at one value")
    p.add_argument("--logx", action="store_true", help="logarithmic x axis")
    a = p.parse_args(argv[1:])
    quantities = [q for item in a.quantity for q in item.split(",") if q]
    quantities = [r for q in quantities for r in (RATING if q == "ratings" else [q])]
    try:
        fig = plot(a.table, quantities, a.x, a.lines, a.at, a.logx)
    except PlotError as e:
        print(f"plot_design_sweep.py: {e}", file=sys.stderr)
        return 2
    except (OSError, KeyError, IndexError) as e:  # no file, or not a sweep's table
        print(f"plot_design_sweep.py: {a.table}: not a readable geartrib sweep table ({e})", file=sys.stderr)
        return 2
    fig.savefig(a.output)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
