# 12: corrupt HDF5 files (byte mutations of crafted seeds). Under AddressSanitizer libhdf5 1.10
# itself asks for sizes read from damaged metadata (H5C_protect: 256 GB, 2^64 - ...) and leaks 424
# bytes on one error path: third-party, outside geartrib (diagnosis.txt). With a normal allocator
# malloc returns NULL there and HDF5 reports an error; geartrib's part is that each ends in exit 2
# naming the file, never a crash, through every reader of a topography.
for f in w1-02565.h5 w1-03042.h5 w2-00891.h5; do
  check "$f" 2 "^geartrib: error: $f: (key '/z': cannot open /z as a dataset|not a readable HDF5 topography file)" -- g surface stats "$f" --csv --outliers 5 --fill
  check "$f-multi-asperity" 2 "^geartrib: error: $f: " -- g multi-asperity --topography "$f" --delta-pc 0.5797nm --elements 2048
done
