# How the HDF5 inputs beside dx-array.h5 and dy-array.h5 (the fuzz finds) were made (h5py).
import h5py, numpy as np
z = 0.3e-6 * np.random.default_rng(5).standard_normal((16, 16))
def w(name, z=z, **attrs):
    with h5py.File(name, "w") as f:
        d = f.create_dataset("z", data=z)
        for k, v in attrs.items(): d.attrs[k] = v
w("dx-string.h5", dx=np.bytes_("5e-7"))
w("dx-integer.h5", dx=np.int64(1))
w("dx-one-element.h5", dx=np.array([5e-7]))  # a 1-element array: one number, read
w("dx-tiny.h5", dx=1e-300)
# The spacing limits (tests/test_topography.cpp): 1e-12 m and 1000 m read, beyond them refused.
z8 = 0.3e-6 * np.random.default_rng(5).standard_normal((8, 8))
for name, dx in (("dx-min.h5", 1e-12), ("dx-max.h5", 1e3), ("dx-below.h5", 0.99e-12), ("dx-above.h5", 1000.5)):
    w(name, z=z8, dx=dx)
