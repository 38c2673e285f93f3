"""Timings of the Python module (docs/guide/python.md, "Cost"): medians of repeated calls.

    PYTHONPATH=build/python /usr/bin/python3 scripts/bench_python.py

gt.run on the default case (xarray and dict results, 201 and 1000 positions), an asperity law over
10^4 delta* with and without stresses, and a 100-point sweep on a two-worker Dask LocalCluster
(running, and started by the call) beside `geartrib sweep --threads 2` of the same points.
"""

import statistics
import subprocess
import time
from pathlib import Path

import numpy as np

import geartrib as gt

TOOL = Path(__file__).resolve().parents[1] / "build" / "geartrib"


def median_seconds(f, n=21):
    times = []
    for _ in range(n):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    from distributed import Client, LocalCluster

    case = gt.load_case()
    gt.run(case)  # xarray imported once
    fine = case.set(positions=1000)
    fine.loaded
    d = np.logspace(-1, 3, 10000)
    rows = [
        ("gt.run, default case (201 positions), xarray Dataset", median_seconds(lambda: gt.run(case))),
        ("gt.run, default case, dict of arrays", median_seconds(lambda: gt.run(case, as_dict=True))),
        ("gt.run, 1000 positions, dict of arrays", median_seconds(lambda: gt.run(fine, as_dict=True))),
        ("gt.asperity, 10^4 delta*, with stresses", median_seconds(lambda: gt.asperity(d, as_dict=True))),
        ("gt.asperity, 10^4 delta*, stresses=False",
         median_seconds(lambda: gt.asperity(d, stresses=False, as_dict=True))),
    ]
    axes = {"torque": "100Nm:1000Nm:100"}
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster, Client(cluster) as c:
        gt.sweep(case, {"torque": ["100Nm"]}, client=c)  # workers warm
        rows.append(("gt.sweep, 100 points, running 2-worker LocalCluster",
                     median_seconds(lambda: gt.sweep(case, axes, client=c), 5)))
    rows.append(("gt.sweep, 100 points, LocalCluster started by the call",
                 median_seconds(lambda: gt.sweep(case, axes), 3)))
    command = [str(TOOL), "sweep", "--set", "torque=100Nm:1000Nm:100", "--threads", "2", "-q", "-o", "/tmp/bench-sweep.h5"]
    rows.append(("geartrib sweep, the same 100 points, 2 threads",
                 median_seconds(lambda: subprocess.run(command, check=True), 5)))
    print("| call | median |\n|---|---|")
    for name, seconds in rows:
        print(f"| {name} | {seconds * 1e3:.3g} ms |")


if __name__ == "__main__":
    main()
