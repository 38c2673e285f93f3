# 03: sizes and counts a file declares, trusted before allocating (found: HDF5 /z of 200000 x 200000
# asked for 320 GB, 20000 x 20000 passed 4 GB; 30000 points on a diagonal became a 30000 x 30000
# lattice, 7.2 GB). Now, before anything is allocated (docs/guide/surface.md#limits): a grid holds at
# most 33554432 points; an HDF5 /z must be stored whole within the file (its chunks written, its
# storage within the file's size); a point cloud's lattice may have at most 4 cells a point given.
# make_inputs.py made the HDF5 inputs (h5py); diag-200.xyz is the diagonal at 200 points.
scratch="$tmp/03"; mkdir -p "$scratch"
check huge-dims 2 "huge-dims.h5: key '/z' = 200000 x 200000: more than 33554432 points" -- g surface stats huge-dims.h5
check mid-dims 2 "mid-dims.h5: key '/z' = 20000 x 20000: more than 33554432 points" -- g surface stats mid-dims.h5
check unwritten 2 "unwritten.h5: key '/z' = 4000 x 4000: the file does not store all of /z's values" -- g surface stats unwritten.h5
check truncated 2 "truncated.h5: not a readable HDF5 topography file" -- g surface stats truncated.h5
check diagonal 2 "diag.xyz:1: key 'lattice' = 30000 x 30000 from 30000 points: more than 33554432 grid points" -- g surface stats diag.xyz
check diagonal-small 2 "diag-200.xyz:1: key 'lattice' = 200 x 200 from 200 points: fewer than one point per 4 lattice cells" -- g surface stats diag-200.xyz
# The diagonal binned as the message says: 200 x 200 cells at 0.1 um, nearly all empty; the
# statistics refuse it with the file named (was "error: the grid needs ..." naming nothing).
check diagonal-resampled 2 "diag-200.xyz: the grid needs at least 3 x 3 valid points for slopes" -- g surface stats diag-200.xyz --resample 0.1um
# --resample within the spacing range but giving too many points: the file and the key named.
check resample-too-fine 2 "diag-200.xyz: key 'resample' = 1e-11 m: spacing 1e-11 m gives .* grid points, more than 33554432" -- g surface stats diag-200.xyz --resample 1e-11m
# A device file named as a topography (through a link with a topography extension).
ln -s /dev/zero "$scratch/zero.txt"
check device 2 "zero.txt is not a regular file" -- g surface stats "$scratch/zero.txt"
# The same readers behind multi-asperity --topography.
check huge-dims-multi-asperity 2 "huge-dims.h5: key '/z' = 200000 x 200000" -- g multi-asperity --topography huge-dims.h5 --delta-pc 0.5797nm --elements 2048
rm -rf "$scratch"
