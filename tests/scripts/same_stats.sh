#!/usr/bin/env bash
# The same scene through LAMMPS and LIGGGHTS (serially): the relocation
# statistics (f_ID[1..8], f_ID[10]) and the written atoms must agree.
#   same_stats.sh BUILD_DIR MAKE_SCENE_ARGS...
set -euo pipefail
build=$1
shift
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/same_stats.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$build/tests/make_scene" "$work/scene.data" "$@"
mkdir -p "$work/lammps" "$work/liggghts"
(cd "$here/stability" && "$build/src/lammps/lmp_reinforce" -in in.scene -var data "$work/scene.data" \
   -var out "$work/lammps" -log "$work/lammps/log" -screen none)
(cd "$here/liggghts" && "$build/src/liggghts/liggghts_reinforce" -in in.scene -var data "$work/scene.data" \
   -var out "$work/liggghts" -log "$work/liggghts/log" -screen none)
a=$(grep '^STATS' "$work/lammps/log" | tail -1)
b=$(grep '^STATS' "$work/liggghts/log" | tail -1)
echo "LAMMPS:   $a"
echo "LIGGGHTS: $b"
awk -v a="$a" -v b="$b" 'BEGIN {
  na = split(a, x, " "); nb = split(b, y, " ")
  if (na != 10 || nb != 10) { print "FAIL: STATS lines incomplete"; exit 1 }
  if (x[2] == 0) { print "FAIL: the scene has no targets"; exit 1 }
  for (i = 2; i <= 10; i++) {
    d = x[i] - y[i]; if (d < 0) d = -d
    s = (x[i] < 0 ? -x[i] : x[i]); if (s < 1e-300) s = 1e-300
    # counts exact; volumes to 1e-12 relative; the residual overlap (~1e-14) to 1e-13 absolute
    if (i == 8 ? d > 1e-13 : d > 1e-12 * s) { printf "FAIL: value %d differs: %s vs %s\n", i - 1, x[i], y[i]; bad = 1 }
  }
  if (bad) exit 1
  print "PASS: same relocation statistics"
}'
"$build/tests/check_scene" --same "$work/lammps/after.dump" "$work/liggghts/after.dump"
