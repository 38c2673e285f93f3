# 07: counts an option can set, each with a documented upper bound (found: the commands below ran
# without limit: minutes and gigabytes). The topography filter's kernel is in 02/07's surface cases.
check kinematics-positions 2 "--positions: Value 1000000000 not in range 2 to 100000" -- g kinematics --positions 1000000000 --csv
check kinematics-positions-int-max 2 "--positions" -- g kinematics --positions 2147483647 --csv
check multi-asperity-sweep-count 2 "--sweep-spacing '1um:2um:1000000': COUNT must be a whole number from 2 to 1000" -- g multi-asperity --layout HLH --delta-pc 0.5797nm --elements 2048 --sweep-spacing 1um:2um:1000000 --csv
check dynamics-sweep-count 2 "--speed-sweep '100rpm:9000rpm:1000000000': COUNT must be a whole number from 2 to 10000" -- g dynamics --speed-sweep 100rpm:9000rpm:1000000000 --csv
check asperity-range-count 2 "--range '1:10:10000001': COUNT must be a whole number in \[1, 1e6\]" -- g asperity --range 1:10:10000001 --csv
check sweep-points 2 "the sweep has more than 100000 points \(--set face_width multiplies it by 100000\)" -- g sweep --set module=4mm:8mm:100000 --set face_width=40mm:80mm:100000 --threads 1 -o "$tmp/sw.h5" -q
check sweep-axis-count 2 "100001" -- g sweep --set torque=1Nm:2Nm:100001 -o "$tmp/sw.h5" -q
check sweep-nothing-written 1 "" -- test -e "$tmp/sw.h5"
# An explicit integrator at a speed whose cycle lasts 10^7 natural periods ran for hours.
check dynamics-slow-odeint 2 "--speed = 0.01 rpm: outside the dynamics model's range 0.055 to 5.5e\+06 rpm" -- g dynamics --speed 0.01rpm --integrator odeint --csv
check dynamics-speed-of-the-case 2 "operating.pinion_speed = 0.001 rpm: outside" -- g dynamics --set speed=0.001rpm --csv
