#!/usr/bin/python3
"""Pareto plot of a `geartrib tradeoff --csv` table: run time against the worst relative error of
the three outputs (real-area ratio, plastic fraction, peak asperity stress), one series per knob,
the tolerance as a line and each knob's recommended setting ringed.

Usage: scripts/plot_tradeoff.py TRADEOFF.csv OUT.png [TOLERANCE]
Debian's python3-matplotlib; /usr/bin/python3.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    tol = float(argv[3]) if len(argv) == 4 else 0.01
    with open(argv[1]) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    floor = 1e-12  # errors below this (the references themselves) are drawn at the floor
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    knobs = []
    for r in rows:
        if r["knob"] not in knobs and r["knob"] != "combined":
            knobs.append(r["knob"])
    markers = "os^vD<>ph*"
    colors = plt.get_cmap("tab10").colors
    for n, k in enumerate(knobs + ["combined"]):
        sel = [r for r in rows if r["knob"] == k]
        t = [float(r["time_s"]) for r in sel]
        # The worst of the outputs the model has (a ladder's Persson has no peak stress: nan).
        e = [max([floor] + [x for x in (float(r["error_real_area"]), float(r["error_plastic_fraction"]),
                                        float(r["error_peak_stress"])) if not math.isnan(x)])
             for r in sel]
        style = "s--" if k == "combined" else markers[n % len(markers)] + "-"
        line, = ax.plot(t, e, style, ms=4, lw=0.8, label=k, color="k" if k == "combined" else colors[n % len(colors)])
        for r, ti, ei in zip(sel, t, e):
            if "recommended" in r["note"]:
                ax.plot([ti], [ei], "o", ms=11, mfc="none", mec=line.get_color(), mew=1.5)
            if (k == "combined" and "reference" not in r["note"]) or "recommended" in r["note"]:
                ax.annotate(r["setting"], (ti, ei), fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax.axhline(tol, color="k", lw=0.8, ls=":")
    ax.annotate(f"tolerance {tol:g}", (0.01, tol), xycoords=("axes fraction", "data"), fontsize=7, va="bottom")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("mesh-cycle time [s]")
    ax.set_ylabel("worst relative error of the three outputs")
    ax.set_title("geartrib tradeoff: each knob against its highest setting (ringed: recommended;\n"
                 f"references drawn at {floor:g})", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, ncol=2)
    # PNG whatever the name: geartrib passes its temporary (.NAME.tmp.XXXXXXXXXX), renamed when complete.
    fig.savefig(argv[2], bbox_inches="tight", format="png")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
