# 10: exit 0 with NaN or inf in the output (found: dynamics at 1e-300 rpm wrote -nan deflections;
# asperity at delta* 1e308 wrote -nan loads). Now refused with the option and its range named;
# at the ends of the ranges the outputs are finite. (surface generate's spacing: 05/10 surface cases.)
check dynamics-tiny-speed 2 "--speed = 1e-300 rpm: outside the dynamics model's range" -- g dynamics --speed 1e-300rpm --integrator odeint --csv
check dynamics-huge-speed 2 "--speed = 1e\+07 rpm: outside" -- g dynamics --speed 1e7rpm --csv
check asperity-huge-delta 2 "--delta-star 1e\+308: delta\* must be from 0 to 1e\+06" -- g asperity --delta-star 1e308 --csv
check asperity-range-past 2 "--range 1e\+07: delta\* must be from 0 to 1e\+06" -- g asperity --range 1:1e7:3 --csv
g dynamics --speed 0.06rpm --csv > "$tmp/slow.csv" 2>/dev/null
no_nan dynamics-slowest-finite "$tmp/slow.csv"
for m in hertz ceb kogut-etsion jackson-green continuous; do
  g asperity --model $m --delta-star 0,1e-9,1e6 --csv > "$tmp/$m.csv" 2>/dev/null
  no_nan "asperity-$m-ends-finite" "$tmp/$m.csv"
done
