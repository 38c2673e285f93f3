# How the shard files here were made: a 4-point sweep in 3 shards (shard 0 owns points 0 and 3,
# shard 1 point 1, shard 2 point 2), then each crafted file one edit of one shard (h5py).
# Run from this folder: GEARTRIB=path/to/geartrib /usr/bin/python3 make_inputs.py
import os, shutil, subprocess
import h5py, numpy as np

g = os.environ.get("GEARTRIB", "../../../build/geartrib")
root = "../../.."
for i in range(3):
    subprocess.run([g, "sweep", "gears/m6z30-dry.toml", "--set", "positions=5", "--set",
                    "torque=250Nm,500Nm,1000Nm,2000Nm", "--shard", f"{i}/3", "-o",
                    os.path.abspath(f"s{i}.h5"), "-q"], cwd=root, check=True)

def text(v):  # a fixed-length UTF-8 string, as geartrib writes them
    b = v.encode()
    return np.array(b, dtype=h5py.string_dtype("utf-8", max(1, len(b))))

def craft(name, src, attrs={}, edit=None):
    shutil.copy(src, name)
    with h5py.File(name, "r+") as h:
        for k, v in attrs.items():
            if k in h["sweep"].attrs: del h["sweep"].attrs[k]
            if v is not None: h["sweep"].attrs.create(k, text(v))
        if edit: edit(h)

# The /sweep attributes (issue 30, finding 3: crashes, out-of-bounds writes, 12.5 GB, "error: stoul").
craft("shard-huge.h5", "s1.h5", {"shard": "4000000000000/3"})
craft("shard-past-count.h5", "s1.h5", {"shard": "100000/3"})
craft("shard-not-a-number.h5", "s1.h5", {"shard": "x/3"})
craft("shard-other-count.h5", "s1.h5", {"shard": "1/4"})
craft("count-zero.h5", "s0.h5", {"shard_count": "0"})
craft("count-huge.h5", "s0.h5", {"shard_count": "99999999999"})
craft("total-huge.h5", "s0.h5", {"points_total": "99999999999"})
craft("total-abc.h5", "s0.h5", {"points_total": "abc"})
craft("total-signed.h5", "s0.h5", {"points_total": "+4"})
craft("total-missing.h5", "s0.h5", {"points_total": None})
# Consistency between shards: the totals (shard 2 of a 3-point sweep owns 1 point, as of 4).
craft("total-other.h5", "s2.h5", {"points_total": "3"})
craft("sets-other.h5", "s2.h5", {"sets": "torque=1Nm"})
def scene(h):
    del h["scene"]
    h.create_dataset("scene", data=text("[gear_pair]\nmodule = 1\n"))
craft("scene-other.h5", "s2.h5", edit=scene)

# The /points datasets: the point column (values block) and the text columns.
def point(value, row=0):
    def edit(h):
        names = h["points/values"].attrs["columns"].decode().split(",")
        block = h["points/values"][()]
        block[row, names.index("point")] = value
        h["points/values"][...] = block
    return edit
craft("point-nan.h5", "s1.h5", edit=point(np.nan))
craft("point-negative.h5", "s1.h5", edit=point(-1.0))
craft("point-huge.h5", "s1.h5", edit=point(1e300))
craft("point-fraction.h5", "s1.h5", edit=point(1.5))
craft("point-other-shard.h5", "s1.h5", edit=point(2.0))  # shard 2's point
craft("point-twice.h5", "s0.h5", edit=point(0.0, row=1))  # shard 0: points 0 and 0
def rows(n):  # the shard's table cut (or grown) to n rows, every column
    def edit(h):
        p = h["points"]
        block = p["values"][()]
        attrs = dict(p["values"].attrs)
        block = np.resize(block, (n, block.shape[1]))
        del p["values"]
        p.create_dataset("values", data=block)
        for k, v in attrs.items(): p["values"].attrs[k] = v
        for name in p.attrs["columns"].decode().split(","):
            if name in p and name != "values":
                cells = list(p[name][()])
                del p[name]
                p.create_dataset(name, data=np.array((cells * n)[:n], dtype=h5py.string_dtype("utf-8", 64)))
    return edit
craft("rows-short.h5", "s0.h5", edit=rows(1))
craft("rows-long.h5", "s1.h5", edit=rows(3))
def status(h):
    del h["points/status"]
    h["points"].create_dataset("status", data=np.array([b"done"], dtype=h5py.string_dtype("utf-8", 4)))
craft("status-other.h5", "s1.h5", edit=status)
def no_status(h):
    p = h["points"]
    p.attrs["columns"] = np.bytes_(p.attrs["columns"].decode().replace("status,", ""))
craft("status-missing.h5", "s1.h5", edit=no_status)
def listed_twice(h):  # a numeric column listed 1000 times: would copy its values each time
    p = h["points"]
    p.attrs["columns"] = np.bytes_(p.attrs["columns"].decode() + ",point" * 1000)
craft("column-listed-twice.h5", "s1.h5", edit=listed_twice)
def long_text(h):  # a variable-length text column declaring 10^9 strings (its cells unwritten)
    del h["points/message"]
    h["points"].create_dataset("message", shape=(10**9,), dtype=h5py.string_dtype(), chunks=(1024,))
craft("text-column-huge.h5", "s1.h5", edit=long_text)
