#!/usr/bin/python3
"""Plot a `geartrib sweep` result: one quantity against one swept key, one line per value of a
second swept key; any further swept keys are held at one value each (--at key=value, default the
first value of that key).

Usage: scripts/plot_design_sweep.py SWEEP.csv|SWEEP.h5 QUANTITY X [LINES] -o OUT.png [--at key=value ...] [--logx]

QUANTITY is a column such as hertz_p0_Pa_max, real_area_ratio_min, plastic_area_fraction_max;
X and LINES are swept keys (their column names: module, face_width, rq, ...). Failed points are
left out. Debian's python3-matplotlib (and python3-h5py for .h5); /usr/bin/python3.
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_table(path):
    """Columns as lists (numbers as float, text as str) and their units."""
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
            return cols, units
    with open(path) as f:
        lines = f.read().splitlines()
    unit_line = next((l for l in lines if l.startswith("# units:")), "# units:")
    rows = list(csv.reader(l for l in lines if not l.startswith("#")))
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
    return cols, units


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("table")
    p.add_argument("quantity")
    p.add_argument("x")
    p.add_argument("lines", nargs="?")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--at", action="append", default=[], help="key=value for further swept keys")
    p.add_argument("--logx", action="store_true", help="logarithmic x axis")
    a = p.parse_args(argv[1:])
    cols, units = read_table(a.table)
    for k in [a.quantity, a.x] + ([a.lines] if a.lines else []):
        if k not in cols:
            print(f"{a.table}: no column '{k}' (columns: {', '.join(cols)})", file=sys.stderr)
            return 2
    sweep_keys = [n for n in cols if n not in ("point", "status", "message", "seconds", "contact_ratio", "plasticity_index")
                  and not n.endswith(("_min", "_mean", "_max"))]
    fixed = dict(kv.split("=", 1) for kv in a.at)
    n = len(cols["point"])
    keep = [i for i in range(n) if cols["status"][i] == "ok"]
    for k in sweep_keys:
        if k in (a.x, a.lines):
            continue
        values = sorted(set(cols[k][i] for i in keep), key=lambda v: (isinstance(v, str), v))
        want = fixed.get(k)
        target = (type(values[0])(want) if want is not None else values[0]) if values else None
        keep = [i for i in keep if cols[k][i] == target]
        fixed[k] = target
    groups = sorted(set(cols[a.lines][i] for i in keep)) if a.lines else [None]
    fig, ax = plt.subplots(figsize=(6.5, 4.2), dpi=110)
    for g in groups:
        idx = sorted((i for i in keep if g is None or cols[a.lines][i] == g), key=lambda i: cols[a.x][i])
        label = None if g is None else f"{a.lines} = {g:g} {units.get(a.lines, '')}" if isinstance(g, float) else f"{a.lines} = {g}"
        ax.plot([cols[a.x][i] for i in idx], [cols[a.quantity][i] for i in idx], "o-", label=label)
    ax.set_xlabel(f"{a.x} [{units.get(a.x, '')}]" if units.get(a.x) else a.x)
    ax.set_ylabel(f"{a.quantity} [{units.get(a.quantity, '')}]" if units.get(a.quantity) else a.quantity)
    held = ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}" for k, v in fixed.items() if k in sweep_keys)
    ax.set_title(f"geartrib sweep{': ' + held if held else ''}", fontsize=9)
    if a.logx:
        ax.set_xscale("log")
    ax.grid(alpha=0.3)
    if a.lines:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
