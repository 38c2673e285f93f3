#!/usr/bin/python3
"""Plot a `geartrib dynamics --speed-sweep ... --csv` table: the dynamic factor against speed.

Usage: scripts/plot_speed_sweep.py SWEEP.csv OUT.png [NATURAL_FREQUENCY_HZ]

Draws the dynamic factor (peak mesh force over F) and its ratio to the quasi-static peak against
the mesh frequency (bottom axis) and pinion speed (top axis), shading speeds where contact was
lost, with the natural frequency marked when given. Debian's python3-matplotlib; /usr/bin/python3.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    fm = [float(r["mesh_frequency_Hz"]) for r in rows]
    rpm = [float(r["speed_rpm"]) for r in rows]
    kv = [float(r["dynamic_factor"]) for r in rows]
    kq = [float(r["dynamic_factor_quasi_static"]) for r in rows]
    lost = [r["contact_lost"] == "1" for r in rows]
    fig, ax = plt.subplots(figsize=(7.0, 4.0), dpi=110)
    ax.plot(fm, kv, color="C0", label="peak mesh force / F")
    ax.plot(fm, kq, color="C1", linestyle="--", label="... / quasi-static peak")
    for f, l in zip(fm, lost):
        if l:
            ax.axvspan(f - 0.5 * (fm[1] - fm[0]), f + 0.5 * (fm[1] - fm[0]), color="0.85", linewidth=0)
    if len(argv) == 4:
        fn = float(argv[3])
        ax.axvline(fn, color="C3", linewidth=0.9)
        ax.annotate("f_n", (fn, 0.97), xycoords=("data", "axes fraction"), color="C3", ha="left", va="top",
                    xytext=(3, 0), textcoords="offset points")
    ax.set_xlabel("mesh frequency [Hz]  (grey: contact lost)")
    ax.set_ylabel("dynamic factor")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    top = ax.secondary_xaxis("top", functions=(lambda f: f * rpm[-1] / fm[-1], lambda n: n * fm[-1] / rpm[-1]))
    top.set_xlabel("pinion speed [rpm]")
    fig.tight_layout()
    fig.savefig(argv[2])
    print(f"wrote {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
