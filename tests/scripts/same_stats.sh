#!/usr/bin/env bash
# The same scene through LAMMPS and LIGGGHTS (serially, same keywords): one
# data file from make_scene, read by lmp_reinforce (atom_style sphere,
# tests/stability/in.scene) and by liggghts_reinforce (atom_style granular,
# tests/liggghts/in.scene). Asserts:
#   * the relocation statistics agree: f_ID[1..4] and f_ID[8] (counts, solves)
#     and f_ID[10] exactly, f_ID[5..6] (volumes) to 1e-12 relative, f_ID[7]
#     (residual overlap, rounding level) to 1e-13 absolute;
#   * the written atoms agree: the same ids and types, centres and radii equal
#     to 1e-12 relative (of the value, or of the box length for coordinates
#     near 0). Whether they are also bit-identical is reported as INFO.
#
#   same_stats.sh BUILD_DIR [--extra "keyword value ..."] MAKE_SCENE_ARGS...
set -euo pipefail
build=$(cd "$1" && pwd)
shift
extra=""
if [ "${1:-}" = "--extra" ]; then
  extra=$2
  shift 2
fi
here=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "same_stats"
"$build/tests/make_scene" "$work/scene.data" "$@"
mkdir -p "$work/lammps" "$work/liggghts"
(cd "$here/stability" && "$build/src/lammps/lmp_reinforce" -in in.scene -var data "$work/scene.data" \
   -var out "$work/lammps" -var extra "$extra" -log "$work/lammps/log" -screen none) ||
  { echo "FAIL: lmp_reinforce exited non-zero"; tail -5 "$work/lammps/log"; exit 1; }
(cd "$here/liggghts" && "$build/src/liggghts/liggghts_reinforce" -in in.scene -var data "$work/scene.data" \
   -var out "$work/liggghts" -var extra "$extra" -log "$work/liggghts/log" -screen none) ||
  { echo "FAIL: liggghts_reinforce exited non-zero"; tail -5 "$work/liggghts/log"; exit 1; }
a=$(grep '^STATS' "$work/lammps/log" | tail -1)
b=$(grep '^STATS' "$work/liggghts/log" | tail -1)
echo "keywords: ${extra:-(defaults)}"
echo "LAMMPS:   $a"
echo "LIGGGHTS: $b"
awk -v a="$a" -v b="$b" 'BEGIN {
  na = split(a, x, " "); nb = split(b, y, " ")
  if (na != 10 || nb != 10) { print "FAIL: STATS lines incomplete"; exit 1 }
  if (x[2] == 0) { print "FAIL: the scene has no targets"; exit 1 }
  # STATS f1 f2 f3 f4 f5 f6 f7 f8 f10: field i holds f_ID[i-1], field 10 f_ID[10]
  for (i = 2; i <= 10; i++) {
    d = x[i] - y[i]; if (d < 0) d = -d
    s = (x[i] < 0 ? -x[i] : x[i]); if (s < 1e-300) s = 1e-300
    if (i == 6 || i == 7) bad_i = d > 1e-12 * s       # volumes
    else if (i == 8) bad_i = d > 1e-13                 # residual overlap / rmin
    else bad_i = d != 0                                # counts
    if (bad_i) { printf "FAIL: f_ID[%d] differs: %s vs %s\n", (i == 10 ? 10 : i - 1), x[i], y[i]; bad = 1 }
  }
  if (bad) exit 1
  printf "PASS: same relocation statistics (targets %s relocated %s deleted %s kept %s solves %s)\n", x[2], x[3], x[4], x[5], x[9]
}'

# The written atoms, by id: columns found from the ITEM: ATOMS header.
awk '
  FNR == 1 { file++; reading = 0; box = 0 }
  /^ITEM: TIMESTEP/ { if (file == 1) { delete one; n1 = 0 } else { delete two; n2 = 0 } }    # the last snapshot counts
  /^ITEM: BOX BOUNDS/ { box = 1; dim = 0; next }
  box && dim < 3 { split($0, f, " "); len = f[2] - f[1]; if (len > L) L = len; dim++; if (dim == 3) box = 0; next }
  /^ITEM: ATOMS/ {
    reading = 1
    for (k = 3; k <= NF; k++) col[file, $k] = k - 2
    next
  }
  /^ITEM:/ { reading = 0; next }
  reading {
    id = $col[file, "id"]
    v = $col[file, "type"] " " $col[file, "x"] " " $col[file, "y"] " " $col[file, "z"] " " $col[file, "radius"]
    if (file == 1) { one[id] = v; n1++ } else { two[id] = v; n2++ }
  }
  END {
    if (n1 == 0) { print "FAIL: no atoms in the LAMMPS dump"; exit 1 }
    if (n1 != n2) { printf "FAIL: %d atoms written by LAMMPS, %d by LIGGGHTS\n", n1, n2; exit 1 }
    worst = 0; exact = 0
    for (id in one) {
      if (!(id in two)) { printf "FAIL: atom %s written by LAMMPS only\n", id; exit 1 }
      split(one[id], p, " "); split(two[id], q, " ")
      if (p[1] != q[1]) { printf "FAIL: atom %s has type %s vs %s\n", id, p[1], q[1]; exit 1 }
      same = 1
      for (k = 2; k <= 5; k++) {
        d = p[k] - q[k]; if (d < 0) d = -d
        s = (p[k] < 0 ? -p[k] : p[k]); t = (q[k] < 0 ? -q[k] : q[k]); if (t > s) s = t
        if (k < 5 && L > s) s = L
        if (d > 0) same = 0
        if (d / s > worst) worst = d / s
        if (d > 1e-12 * s) {
          printf "FAIL: atom %s differs: LAMMPS %s, LIGGGHTS %s\n", id, one[id], two[id]; exit 1
        }
      }
      exact += same
    }
    printf "PASS: the same %d atoms after relocation (largest relative difference %.3g)\n", n1, worst
    printf "INFO: %d of %d atoms have bit-identical centre and radius\n", exact, n1
  }' "$work/lammps/after.dump" "$work/liggghts/after.dump"
