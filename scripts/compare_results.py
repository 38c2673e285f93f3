#!/usr/bin/python3
"""List what moved between two `geartrib run` results: every dataset and attribute of the HDF5
files, identical, moved (by how much), added or removed.

Usage: scripts/compare_results.py BEFORE.h5 AFTER.h5 [--all]

Numbers are compared element by element: "moved" gives the largest relative change (over the
larger magnitude of each pair) and where; texts compare as texts. /meta's stage times, the
version and the scene's text are skipped (they move every run). --all also lists the identical
ones. Needs python3-h5py and python3-numpy.
"""
import sys

import h5py
import numpy as np

SKIP = {"/meta/stage_seconds", "/meta/stage_names", "/meta@version", "/scene", "/scene@file", "/meta/warnings"}


def items(f):
    out = {}

    def visit(name, obj):
        path = "/" + name
        for k, v in obj.attrs.items():
            out[f"{path}@{k}"] = v
        if isinstance(obj, h5py.Dataset):
            out[path] = obj[()]
    for k, v in f.attrs.items():
        out[f"/@{k}"] = v
    f.visititems(visit)
    return out


def compare(a, b):
    if isinstance(a, bytes):
        a = a.decode()
    if isinstance(b, bytes):
        b = b.decode()
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind in "OSU" or b.dtype.kind in "OSU":
        same = a.shape == b.shape and all(str(x) == str(y) for x, y in zip(a.ravel(), b.ravel()))
        return ("identical", "") if same else ("moved", "text differs")
    if a.shape != b.shape:
        return "moved", f"shape {a.shape} -> {b.shape}"
    a, b = a.astype(float).ravel(), b.astype(float).ravel()
    if np.array_equal(a, b, equal_nan=True):
        return "identical", ""
    scale = np.maximum(np.abs(a), np.abs(b))
    rel = np.where(scale > 0, np.abs(a - b) / np.where(scale > 0, scale, 1), 0.0)
    k = int(np.nanargmax(rel))
    return "moved", f"max rel change {rel[k]:.3g} (element {k}: {a[k]:.6g} -> {b[k]:.6g})"


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with h5py.File(argv[1]) as fa, h5py.File(argv[2]) as fb:
        a, b = items(fa), items(fb)
    rows = {"identical": [], "moved": [], "added": [], "removed": []}
    for k in sorted(set(a) | set(b)):
        if k in SKIP:
            continue
        if k not in b:
            rows["removed"].append((k, ""))
        elif k not in a:
            rows["added"].append((k, ""))
        else:
            verdict, detail = compare(a[k], b[k])
            rows[verdict].append((k, detail))
    for verdict in ("moved", "added", "removed") + (("identical",) if "--all" in argv else ()):
        print(f"{verdict} ({len(rows[verdict])}):")
        for k, detail in rows[verdict]:
            print(f"  {k}  {detail}")
    if "--all" not in argv:
        print(f"identical ({len(rows['identical'])})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
