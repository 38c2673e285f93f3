# How the inputs beside the fuzz finds (inf-height.h5, huge-heights.txt, spacing-*.txt) were made.
import math, random
import h5py, numpy as np
rng = np.random.default_rng(5)
z = 0.3e-6 * rng.standard_normal((16, 16))
def w(name, z, **attrs):
    with h5py.File(name, "w") as f:
        d = f.create_dataset("z", data=z)
        for k, v in attrs.items(): d.attrs[k] = v
w("int-heights.h5", (z * 1e9).astype(np.int32), dx=5e-7)
zn = z.copy(); zn[3, 4] = np.nan; zn[10, 2] = np.nan
w("nan-height.h5", zn, dx=5e-7)
zi = z.copy(); zi[7, 9] = -np.inf
w("neg-inf-height.h5", zi, dx=5e-7)
# Lengths in metres without a units line.
random.seed(1)
rows = [" ".join(f"{0.3e-6*math.sin(0.7*i+1.3*j)+0.1e-6*random.random():.4e}" for i in range(16)) for j in range(16)]
open("metres.txt", "w").write("# heights in metres, no units line\n# spacing: 0.5 um\n" + "\n".join(rows) + "\n")
open("metres-spacing.txt", "w").write("# heights and spacing in metres, no units line\n# spacing: 5e-7\n" + "\n".join(rows) + "\n")
pts = [f"{i*1e-5:.6g} {j*1e-5:.6g} {0.3e-6*math.sin(0.7*i+1.3*j)+0.1e-6*random.random():.4e}" for j in range(12) for i in range(12)]
open("metres-coarse.xyz", "w").write("X(m) Y(m) Z(m)\n" + "\n".join(pts) + "\n")
