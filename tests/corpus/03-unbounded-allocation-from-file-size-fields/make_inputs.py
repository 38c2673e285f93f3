# How the inputs were made (h5py): a chunked /z with a fill value and no data written is ~1.4 KB.
import h5py
for name, shape, dt in (("huge-dims.h5", (200000, 200000), "f8"), ("mid-dims.h5", (20000, 20000), "f4")):
    with h5py.File(name, "w") as f:
        d = f.create_dataset("z", shape=shape, dtype=dt, chunks=(256, 256), fillvalue=0.0, compression="gzip")
        d.attrs["dx"] = 1e-6
# A 518 KB point cloud of 30000 points on a diagonal: 30000 distinct x and y -> a 30000 x 30000 lattice.
open("diag.xyz", "w").write("".join(f"{i*0.1:.1f} {i*0.1:.1f} 0.0\n" for i in range(30000)))
# At the grid limit (8192 x 4096 = 33554432 points: the size passes, the unwritten chunks do not)
# and one row past it; unwritten.h5 is the same at 4000 x 4000 (tests/test_topography.cpp reads these).
for name, shape in (("at-limit.h5", (4096, 8192)), ("past-limit.h5", (4097, 8192)), ("unwritten.h5", (4000, 4000))):
    with h5py.File(name, "w") as f:
        d = f.create_dataset("z", shape=shape, dtype="f8", chunks=(256, 256), fillvalue=0.0, compression="gzip")
        d.attrs["dx"] = 1e-6
# truncated.h5: a written 64 x 64 contiguous /z (dx 5e-7) cut to half its bytes.
# diag-200.xyz: the diagonal at 200 points.
open("diag-200.xyz", "w").write("".join(f"{i*0.1:.1f} {i*0.1:.1f} 0.0\n" for i in range(200)))
