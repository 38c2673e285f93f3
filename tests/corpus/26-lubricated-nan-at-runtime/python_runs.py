# Folder 26's Python half: gt.run on the reproducer's loads returns finite arrays (the hot surfaces
# clamped and flagged) or raises, and a sweep point (what each of gt.sweep's Dask tasks runs)
# carries the failure in its status. Prints "python ok" when all hold.
import os
import numpy as np
import geartrib as gt

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
case = gt.load_case(os.path.join(root, "gears", "m6z30.toml"), positions=21)
hot = gt.run(case.set(torque="5e4 N m"), as_dict=True)
bad = [k for k, v in hot.items() if isinstance(v, np.ndarray) and v.dtype.kind == "f" and not np.all(np.isfinite(v))]
assert not bad, f"non-finite arrays: {bad}"
assert hot["flag_oil_temperature_clamped"].max() == 1.0
summary = hot["attrs"]["lubrication_summary"]
assert all(np.isfinite(v) for v in summary.values() if isinstance(v, float)), summary
try:
    gt.run(case.set(torque="1e5 N m"), as_dict=True)
    raise AssertionError("the run at 1e5 N m returned")
except RuntimeError as e:
    assert "bulk_temperature_K" in str(e) and "beyond 400.0 degC" in str(e), e
source = case._portable()
point = gt._run_point(source, list(case.changes), [("torque", "1e5 N m")], 0)
assert not point["ok"] and "bulk_temperature_K" in point["message"], point
point = gt._run_point(source, list(case.changes), [("torque", "5e4 N m")], 1)
assert point["ok"] and all(np.isfinite(v) for _, _, v in point["summary"]), point["message"]
print("python ok")
