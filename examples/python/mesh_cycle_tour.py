"""A worked example of geartrib from Python: the default case's mesh cycle, the real-area ratio
along the path of contact, and a small design sweep on a Dask cluster.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/mesh_cycle_tour.py [OUTPUT_FOLDER]

(no PYTHONPATH once geartrib is installed). It prints what it finds and draws
OUTPUT_FOLDER/real_area_ratio.png (default: examples/python/output, where its saved output is:
tour.txt and the figure).

A script that starts a Dask LocalCluster runs its work under `if __name__ == "__main__":` (the
workers are new Python processes that import the script).
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import geartrib as gt


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent / "output")
    out.mkdir(parents=True, exist_ok=True)

    # 1. The case: the thesis's pair (m = 6 mm, z = 30/30, 45 steel), lubricated, as a case file
    #    gives it. Every key is there with its value and where the value came from.
    case = gt.load_case()
    print(f"case: {case.loaded.title}")
    for key in ("gear_pair.module", "operating.pinion_torque", "operating.pinion_speed", "pinion.flank.ra"):
        value, origin = case.parameters[key]
        print(f"  {key:<26} {value:<14} ({Path(origin).name})")

    # 2. The mesh cycle: one xarray Dataset over the path coordinate s_m, every variable with units.
    ds = gt.run(case)
    print(f"mesh cycle: {ds.s_m.size} positions A -> E, regime: {ds.attrs['regime']}")
    peak = ds.real_area_ratio.argmax().item()
    print(f"  real-area ratio: max {ds.real_area_ratio[peak].item():.4g} at s = {ds.s_m[peak].item() * 1e3:.2f} mm"
          f" ({ds.real_area_ratio.attrs['units']})")
    print(f"  film lambda: min {ds['lambda_smooth_film'].min().item():.3f}, asperity load share max "
          f"{ds.asperity_load_share.max().item():.3f}")

    # 3. The plot: real-area ratio along the line of action, with the points A..E marked.
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    ax.plot(ds.s_m * 1e3, ds.real_area_ratio, color="C0")
    for name in "ABCDE":
        s = ds.attrs[f"path.s_{name}_m"] * 1e3
        ax.axvline(s, color="0.8", lw=0.8, zorder=0)
        ax.text(s, ax.get_ylim()[1], name, ha="center", va="bottom")
    ax.set_xlabel("s along the line of action [mm]")
    ax.set_ylabel("real-area ratio A_r/A_n [1]")
    ax.set_title(f"{case.loaded.title[:48]}...", fontsize=9, pad=14)
    fig.tight_layout()
    fig.savefig(out / "real_area_ratio.png", dpi=110)
    print("  drew real_area_ratio.png")

    # 4. A small sweep on Dask: torque x roughness. Without a client geartrib starts a LocalCluster;
    #    with one (dask-jobqueue's SLURMCluster, a scheduler address) the same call runs there.
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster, Client(cluster) as client:
        table = gt.sweep(case, {"torque": ["500Nm", "1000Nm", "2000Nm"], "ra": ["0.4um", "0.8um"]}, client=client)
    print(f"sweep: {len(table)} points, {sum(table.status == 'error')} failed")
    print(f"  {'torque N m':>10} {'Ra um':>6} {'p0 max MPa':>11} {'lambda min':>11} {'Ar/An max':>10}  regime")
    for _, row in table.iterrows():
        print(f"  {row.torque:>10.0f} {row.ra * 1e6:>6.1f} {row.hertz_p0_Pa_max / 1e6:>11.0f} "
              f"{row.lambda_smooth_film_min:>11.3f} {row.real_area_ratio_max:>10.4g}  {row.regime}")


if __name__ == "__main__":
    main()
