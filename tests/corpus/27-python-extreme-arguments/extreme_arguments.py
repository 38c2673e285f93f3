# Folder 27 (issue 30, finding 13): finite extreme arguments to the Python module are refused with a
# ValueError naming the argument, the value and the rule (the ranges of the file readers and the
# case schema), never returned as NaN or inf; write_surface refuses what read_surface would refuse;
# and the same functions at the ends of those ranges return finite numbers. One line per check:
# "ok NAME" or "FAIL NAME: why"; the last line "python ok" when every check holds.
import os
import re
import sys
import tempfile
import numpy as np
import geartrib as gt

failed = False


def report(name, ok, why=""):
    global failed
    print(f"ok   {name}" if ok else f"FAIL {name}: {why}")
    failed = failed or not ok


def refused(name, pattern, f, *args, **kw):
    try:
        out = f(*args, **kw)
    except ValueError as e:
        report(name, re.search(pattern, str(e)) is not None, f"message {str(e)!r} lacks /{pattern}/")
        return
    report(name, False, f"returned {type(out).__name__} instead of raising ValueError")


def finite(name, out):
    bad = [k for k, v in (out.items() if isinstance(out, dict) else [("", out)])
           if isinstance(v, (np.ndarray, float)) and not np.all(np.isfinite(v))]
    report(name, not bad, f"non-finite {bad}")


p = np.random.default_rng(2).normal(0, 2e-7, 512)
z = np.random.default_rng(1).normal(0, 3e-7, (64, 64))
# The reproducer's calls (reliability-findings-2/12), each refused at its argument.
refused("bem-line-load-1e300", r"line_load = 1e\+300 N/m: must lie in \[0, 2.8928e\+07\] N/m \(a mean pressure",
        gt.boundary_elements, p, 5e-7, 113e9, line_load=1e300)
refused("bem-approach-1e300", r"approach = 1e\+300 m: must lie in \[-0.000256, 0.000256\] m",
        gt.boundary_elements, p, 5e-7, 113e9, approach=1e300)
refused("bem-modulus-1e-300", r"modulus = 1e-300 Pa: must lie in \[500000, 1.33333e\+13\] Pa \(a plane-strain modulus",
        gt.boundary_elements, p, 5e-7, 1e-300, line_load=100.0)
refused("bem-heights-1e293", r"gap\[[0-9]+\] \(from the profile\) = [0-9.e+]+ m: must lie in \[-2, 2\] m",
        gt.boundary_elements, p * 1e300, 5e-7, 113e9, line_load=100.0)
refused("bem-dx-1e-300", r"dx = 1e-300 m: must lie in \[1e-12, 1000\] m", gt.boundary_elements, p, 1e-300, 113e9,
        line_load=100.0)
refused("stats-heights-1e293", r"z\[0, 0\] = [-0-9.e+]+ m: heights must lie within \+-1 m", gt.surface_statistics,
        z * 1e300, 5e-7)
refused("stats-all-missing", r"z has 0 valid \(not NaN\) heights of 64; at least 9 are needed", gt.surface_statistics,
        np.full((8, 8), np.nan), 5e-7)
extreme = dict(radius=1e-300, modulus=1e300, youngs_modulus=1e300, poisson_ratio=0.3, yield_strength=1e-300,
               hardness=1e-300)
refused("asperity-extreme-pair", r"pair\['radius'\] = 1e-300 m: must lie in \[1e-09, 1\] m \(the case's summit-radius",
        gt.asperity, np.array([1.0, 100.0, 1e6]), pair=extreme)
steel = dict(radius=0.85e-6, modulus=113.19e9, youngs_modulus=210e9, poisson_ratio=0.3, yield_strength=355e6,
             hardness=994e6)
for key, value, pattern in [("modulus", 1e300, r"pair\['modulus'\] = 1e\+300 Pa: must lie in"),
                            ("youngs_modulus", 1e300, r"pair\['youngs_modulus'\] = 1e\+300 Pa: must lie in \[1e\+06, 1e\+13\]"),
                            ("hardness", 1e300, r"pair\['hardness'\] = 1e\+300 Pa: must lie in \[3.55e\+08, 1e\+13\]")]:
    refused(f"asperity-pair-{key}", pattern, gt.asperity, np.array([1.0]), pair=dict(steel, **{key: value}))
refused("asperity-pair-yield-above-modulus", r"pair\['yield_strength'\] = 3e\+11 Pa: must lie in \[0, 2.1e\+11\] Pa",
        gt.asperity, np.array([1.0]), pair=dict(steel, yield_strength=3e11, hardness=5e11))
t = tempfile.mkdtemp()
for name, heights in [("huge-heights", np.ones((8, 8)) * 1e300), ("all-missing", np.full((8, 8), np.nan))]:
    for ext in (".x3p", ".h5", ".csv"):
        path = os.path.join(t, name + ext)
        refused(f"write-{name}{ext}", r"heights must lie within \+-1 m|at least 9 are needed", gt.write_surface, path,
                heights, 5e-7)
        report(f"write-{name}{ext}-nothing-written", not os.path.exists(path), f"{path} written")
# The writer itself (io::write_topography, the command's too) refuses heights no reader takes back.
# At the ends of the ranges: finite.
finite("bem-line-load-at-limit", gt.boundary_elements(p, 5e-7, 113e9, line_load=0.5 * 113e9 * 512 * 5e-7))
finite("bem-modulus-at-limit", gt.boundary_elements(p, 5e-7, 5e5, line_load=100.0))
finite("bem-heights-at-limit", gt.boundary_elements(p / np.abs(p).max(), 5e-7, 113e9, line_load=1e5))
finite("stats-heights-at-limit", gt.surface_statistics(z / np.abs(z).max(), 5e-7))
a = gt.asperity(np.array([0.0, 1.0, 100.0, 1e6]), pair=dict(radius=1e-9, modulus=1.33e13, youngs_modulus=1e13,
                                                        poisson_ratio=0.3, yield_strength=1e6, hardness=1e13),
                as_dict=True)
finite("asperity-pair-at-limits", {k: v for k, v in a.items() if isinstance(v, np.ndarray) and v.dtype.kind == "f"})
path = os.path.join(t, "edge.x3p")
edge = np.full((8, 8), np.nan)
edge[0, :3] = edge[1, :3] = edge[2, :3] = [1.0, -1.0, 0.5]
gt.write_surface(path, edge, 5e-7)
back, dx, dy = gt.read_surface(path)
report("write-read-edge", np.array_equal(np.isnan(back), np.isnan(edge)) and np.nanmax(np.abs(back - edge)) == 0.0,
       "not read back as written")
print("python ok" if not failed else "python FAILED")
sys.exit(1 if failed else 0)
