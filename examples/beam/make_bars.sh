#!/usr/bin/env bash
# Writes data/bars.data: the seed paper's five straight bars along the beam,
# 65 rebar spheres each (325 in all), radius 5 mm, centres 7.66 mm apart
# (overlapping: each bar is a clump), from x = 5 mm to 495 mm. Cover of
# 40 mm to the bar axis: three bars at the bottom, two at the top.
set -euo pipefail
cd "$(dirname "$0")"
awk 'BEGIN {
  r = 0.005; n = 65; x0 = 0.005; x1 = 0.495
  split("0.04 0.125 0.21 0.04 0.21", y, " "); split("0.04 0.04 0.04 0.21 0.21", z, " ")
  printf "Five bars of the reinforced beam (make_bars.sh)\n\n%d atoms\n1 atom types\n\n", 5 * n
  printf "0 0.5 xlo xhi\n0 0.25 ylo yhi\n0 0.25 zlo zhi\n\nAtoms # sphere\n\n"
  id = 0
  for (b = 1; b <= 5; b++)
    for (i = 0; i < n; i++)
      printf "%d 1 %.6f 7800 %.9f %.6f %.6f\n", ++id, 2 * r, x0 + (x1 - x0) * i / (n - 1), y[b], z[b]
}' > data/bars.data
