#!/usr/bin/env bash
# A packing in an STL cylinder mould (fix mesh/surface + fix wall/gran
# mesh), meshed as an STL mesher does it: 64 segments, each side rectangle
# two slivers spanning the mould's height, each cap a fan of thin triangles
# (256 triangles, walls.py mould; radius 0.05, height 0.1). About 3,400
# matrix spheres inside it (radii 1.5 to 3 mm) and two bars crossing it at
# two heights, their ends 6 mm from its side: targets next to the mould.
# Asserts geometry, not what the fix's settings make of the scene: the fix
# logs the mesh it honours and relocates targets; every moved sphere is
# clear of the mould (at least r (1 - tol) from each triangle) and its path
# crosses no triangle (check_scene --wall-stl), and one ends within its
# radius of the mould (the mould matters here); nothing overlaps, the bars
# are untouched, and the atoms add up (check_scene: before = after +
# deleted; targets = relocated + deleted + kept; moved targets = relocated).
# FIX KEYWORDS are added to the fix (in.walls -var extra), e.g. the
# regrowth, whose relaxation asks about the mould at every step.
#   mould.sh BUILD_DIR NPROCS [FIX KEYWORDS]
set -euo pipefail
build=$1 np=$2 extra=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
exe=$build/src/liggghts/liggghts_reinforce checker=$build/tests/check_scene
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_mould"
fail() { echo "FAIL: $*"; exit 1; }

python3 "$here/walls.py" mould "$work/mould.stl" 0.06 0.06 0.05 0.01 0.11 64
"$build/tests/make_scene" "$work/raw.data" --box 0 0.12 0 0.12 0 0.12 --radius 0.0015 0.003 --fcc \
  --bar 0.02 0.06 0.05 0.1 0.06 0.05 0.004 0.006 --bar 0.06 0.02 0.07 0.06 0.1 0.07 0.004 0.006 >/dev/null
# A clean start: the matrix wholly inside the circle inscribed in the
# mould's polygon and between its caps.
inscribed=$(python3 -c 'import math; print(0.05 * math.cos(math.pi / 64))')
python3 "$here/walls.py" clip "$work/raw.data" "$work/scene.data" --cylinder z 0.06 0.06 "$inscribed" inside \
  --plane 0 0 0.01 0 0 1 --plane 0 0 0.11 0 0 -1

launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
# -screen /dev/null, not none: LIGGGHTS's mesh reader writes to the screen
# without checking it.
(cd "$here" && "${launch[@]}" "$exe" -in in.walls -log "$work/log" -screen /dev/null \
   -var data "$work/scene.data" -var out "$work" -var steps 0 -var extra "$extra" \
   -var wall1 "fix mesh all mesh/surface file $work/mould.stl type 1" \
   -var wall2 "fix mould all wall/gran model hertz tangential history mesh n_meshes 1 meshes mesh") ||
  fail "$exe exited non-zero"
grep -q '^END ke' "$work/log" || fail "the input did not finish"

read -r _ targets relocated deleted kept < <(grep '^TOTALS ' "$work/log" | tail -1) || fail "no TOTALS line"
grep '^fix reinforce/invert: regrowth' "$work/log" || true
echo "mould np=$np: targets $targets relocated $relocated deleted $deleted kept $kept"
[ "$targets" -gt 0 ] && [ "$relocated" -gt 0 ] || fail "nothing relocated: the scene tests nothing"
[ "$targets" -eq $((relocated + deleted + kept)) ] || fail "targets != relocated + deleted + kept"
walls_line="fix reinforce/invert: walls: 1 mesh (256 triangles) of fix mould"
grep -qxF "$walls_line" "$work/log" || fail "the log does not say: $walls_line"
echo "PASS: the log names the mould"

kept_ok=()
[ "$kept" -gt 0 ] && kept_ok=(--kept-ok)
"$checker" --before "$work/before.dump" --after "$work/after.dump" --deleted "$deleted" "${kept_ok[@]}" \
  --wall-stl "$work/mould.stl" | tee "$work/check" || fail "check_scene (above)"
# The mould matters: a moved sphere ends within its own radius of it.
clear=$(sed -nE 's/.*STL .*closest: id [0-9]+, clear by ([0-9.e+-]+) of its radius.*/\1/p' "$work/check")
[ -n "$clear" ] || fail "no closest clearance in check_scene's STL line"
awk -v c="$clear" 'BEGIN {exit !(c < 1)}' || fail "no moved sphere ends within its radius of the mould (closest: $clear radii)"
echo "PASS: a moved sphere ends clear of the mould by $clear of its radius"
moved=$(awk '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == "moved_targets") print $(i + 1)}' "$work/check")
[ "$moved" = "$relocated" ] || fail "check_scene sees $moved targets moved, the fix reports $relocated"
echo "PASS liggghts_mould np=$np"
