# 02 (and 07's surface case): the waviness filter's half-width ceil(cutoff/spacing) overflowed int
# for a denormal spacing or an absurd cut-off, and a 1 m cut-off on a 48 x 48 grid built a 4e6-point
# kernel (minutes). Now spacings lie in 1e-12 m to 1000 m (docs/guide/surface.md#limits), the
# cut-off must lie between two of the finer spacing and the surface's longer side (checked before
# any integer), and long kernels run by FFT: O(points log points) whatever the cut-off.
scratch="$tmp/02"; mkdir -p "$scratch"
check denormal-spacing 2 "tiny-spacing.txt:1: key 'spacing' = 1e-320: spacing must be positive: 0 m after the unit" -- g surface stats tiny-spacing.txt --cutoff "10 um"
check absurd-cutoff 2 "--cutoff '1e300m': must lie in \(0 m, 1000 m\]" -- g surface stats ok-grid.csv --cutoff 1e300m
check cutoff-longer-than-surface 2 "ok-grid.csv: clean-up: cut-off 1 m is longer than the surface \(2.35e-05 x 2.35e-05 m\)" -- g surface stats ok-grid.csv --cutoff 1m
check cutoff-below-two-spacings 2 "ok-grid.csv: clean-up: cut-off 1e-07 m is shorter than two spacings" -- g surface stats ok-grid.csv --cutoff 0.1um
check cutoff-zero 2 "--cutoff '0 um': must lie in \(0 m, 1000 m\]" -- g surface stats ok-grid.csv --cutoff "0 um"
# At the ends of the allowed range the filter runs (the whole side: the FFT path) and writes no NaN.
check cutoff-whole-side 0 "ok-grid.csv: 48 x 48 points" -- g surface clean ok-grid.csv --cutoff 23.5um -o "$scratch/side.csv"
no_nan cutoff-whole-side-finite "$scratch/side.csv"
check cutoff-two-spacings 0 "ok-grid.csv: 48 x 48 points" -- g surface clean ok-grid.csv --cutoff 1um -o "$scratch/two.csv"
no_nan cutoff-two-spacings-finite "$scratch/two.csv"
# A case's topography table takes the same rule (the table's cutoff key).
check cutoff-case 2 "pinion-flank.h5: clean-up: cut-off 1 m is longer than the surface" -- g run ../../../gears/m6z30-measured.toml -o "$scratch/case.h5" --positions 5 -q --set pinion.flank.topography.cutoff=1m
rm -rf "$scratch"
