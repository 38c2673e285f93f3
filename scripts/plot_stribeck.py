#!/usr/bin/python3
"""Plot a Stribeck curve from a `geartrib sweep` over the pinion speed of a lubricated case.

Usage: scripts/plot_stribeck.py SWEEP.csv OUT.png

SWEEP.csv: `geartrib sweep gears/m6z30.toml --set speed=... --csv SWEEP.csv -o SWEEP.h5`. Draws
the mean friction coefficient along the path against the mean entrainment speed (log axis), with
the asperities' mean load share and the minimum lambda: boundary (share near 1), mixed, and full
film (share near 0). Debian's python3-matplotlib; run with /usr/bin/python3.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#")) if r["status"] == "ok"]
    if not rows or "friction_coefficient_mean" not in rows[0]:
        print("plot_stribeck.py: the sweep has no friction_coefficient_mean column (is the case lubricated?)",
              file=sys.stderr)
        return 2
    rows.sort(key=lambda r: float(r["entrainment_m_per_s_mean"]))
    u = [float(r["entrainment_m_per_s_mean"]) for r in rows]
    mu = [float(r["friction_coefficient_mean"]) for r in rows]
    share = [float(r["asperity_load_share_mean"]) for r in rows]
    lam = [float(r["lambda_smooth_film_min"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7.0, 4.2), dpi=110)
    ax.semilogx(u, mu, "o-", color="C0", label="friction coefficient (path mean)")
    ax.set_xlabel("entrainment speed, path mean [m/s]")
    ax.set_ylabel("friction coefficient [1]")
    ax.grid(True, which="both", alpha=0.3)
    right = ax.twinx()
    right.semilogx(u, share, "s--", color="C1", label="asperity load share (path mean)")
    right.set_ylabel("asperity load share [1]")
    right.set_ylim(-0.02, 1.02)
    top = ax.secondary_xaxis("top", functions=(lambda x: x, lambda x: x))
    top.set_xticks(u[:: max(1, len(u) // 6)])
    top.set_xticklabels([f"{x:.2g}" for x in lam[:: max(1, len(u) // 6)]])
    top.set_xlabel("lambda, smooth film (path minimum)")
    lines = ax.get_legend_handles_labels()[0] + right.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1] + right.get_legend_handles_labels()[1]
    ax.legend(lines, labels, fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(argv[2])
    print(f"wrote {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
