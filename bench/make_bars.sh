#!/usr/bin/env bash
# Writes a bars data file (LAMMPS atom style sphere, one atom type) for a
# box [0,LX]x[0,LY]x[0,LZ]: bars along x at every (y, z) of a grid with
# SPACING, cover COVER, and (with "mesh") bars along y as well; rebar
# spheres of radius 5 mm, 7.66 mm apart (BAR_RADIUS, BAR_STEP in the
# environment change both). Or "line N": N bars along x only,
# spread over the mid-height plane.
# usage: make_bars.sh OUT LX LY LZ mesh SPACING COVER | OUT LX LY LZ line N
set -euo pipefail
out=$1 lx=$2 ly=$3 lz=$4 kind=$5
awk -v r="${BAR_RADIUS:-0.005}" -v step="${BAR_STEP:-0.00766}" -v lx="$lx" -v ly="$ly" -v lz="$lz" -v kind="$kind" -v a="${6:-0.1}" -v cover="${7:-0.04}" '
function bar(x0, y0, z0, x1, y1, z1,    n, i, len) {
  len = sqrt((x1-x0)^2 + (y1-y0)^2 + (z1-z0)^2); n = int(len / step + 0.5)
  for (i = 0; i <= n; i++) { k++; line[k] = sprintf("%d 1 %.9g 7800 %.9f %.9f %.9f", k, 2*r, x0+(x1-x0)*i/n, y0+(y1-y0)*i/n, z0+(z1-z0)*i/n) }
}
BEGIN {
  k = 0
  if (kind == "line") {
    for (b = 1; b <= a; b++) bar(r, ly * b / (a + 1), lz / 2, lx - r, ly * b / (a + 1), lz / 2)
  } else {
    for (z = cover; z <= lz - cover + 1e-9; z += lz - 2 * cover) {
      for (y = cover; y <= ly - cover + 1e-9; y += a) bar(r, y, z, lx - r, y, z)
      for (x = cover; x <= lx - cover + 1e-9; x += a) bar(x, r, z + 2 * r, x, ly - r, z + 2 * r)
    }
  }
  printf "bars (bench/make_bars.sh)\n\n%d atoms\n1 atom types\n\n0 %s xlo xhi\n0 %s ylo yhi\n0 %s zlo zhi\n\nAtoms # sphere\n\n", k, lx, ly, lz
  for (i = 1; i <= k; i++) print line[i]
}' > "$out"
