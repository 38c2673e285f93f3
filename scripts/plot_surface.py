#!/usr/bin/python3
"""Plot a surface written by `geartrib surface generate|clean|equivalent -o FILE.h5`.

Usage: scripts/plot_surface.py SURFACE.h5 OUT.png

Left: the height map (um; missing points blank). Right: the height distribution against the
Gaussian of the same Rq (skewness and kurtosis show as departures), and below it the mean
profile across the rows (along x). Debian's python3-h5py and python3-matplotlib; /usr/bin/python3.
Convert other formats first: geartrib surface clean FILE.asc -o FILE.h5 --form 1
"""
import math
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with h5py.File(argv[1], "r") as f:
        z = np.array(f["z"]) * 1e6
        dx = float(f["z"].attrs["dx"]) * 1e6
        dy = float(f["z"].attrs.get("dy", f["z"].attrs["dx"])) * 1e6
    ny, nx = z.shape
    valid = z[np.isfinite(z)]
    z = z - valid.mean()
    valid = valid - valid.mean()
    rq = float(np.sqrt(np.mean(valid**2)))
    fig = plt.figure(figsize=(10.0, 4.6), dpi=110)
    grid = fig.add_gridspec(2, 2, width_ratios=(1.15, 1.0))
    ax = fig.add_subplot(grid[:, 0])
    im = ax.imshow(z, origin="lower", extent=(0, (nx - 1) * dx, 0, (ny - 1) * dy), cmap="viridis", aspect="equal")
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y [um]")
    ax.set_title(f"{argv[1].split('/')[-1]}: {nx} x {ny}, Rq {rq:.3g} um")
    fig.colorbar(im, ax=ax, label="height [um]")
    hist = fig.add_subplot(grid[0, 1])
    hist.hist(valid, bins=60, density=True, color="0.6", label="heights")
    h = np.linspace(valid.min(), valid.max(), 200)
    if rq > 0:
        hist.plot(h, np.exp(-0.5 * (h / rq) ** 2) / (rq * math.sqrt(2 * math.pi)), "k-", label="Gaussian, same Rq")
    hist.set_xlabel("height [um]")
    hist.legend(fontsize=8)
    prof = fig.add_subplot(grid[1, 1])
    prof.plot(np.arange(nx) * dx, np.nanmean(z, axis=0), "k-", lw=0.8)
    prof.set_xlabel("x [um]")
    prof.set_ylabel("mean over y [um]")
    fig.tight_layout()
    fig.savefig(argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
