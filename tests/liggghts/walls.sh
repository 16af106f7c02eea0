#!/usr/bin/env bash
# A packing held by LIGGGHTS walls, a bar close to a wall (in.walls):
#   floor     an ASCII STL floor (floor.stl, z = 0.02, inside a box from
#             z = 0: an empty slab below it), fix mesh/surface + fix wall/gran
#             mesh; a thick bar along x 1 mm above the floor;
#   cylinder  a primitive zcylinder wall (R 0.05, box 0.12 wide: room
#             outside it) and a zplane floor; a bar along z 1 mm from the
#             cylinder;
#   hole      the cylinder scene with a side out region (region keyword): a
#             cylindrical hole 5 mm from the bar.
# The fix is defined before the first run (a mesh is not yet spread over
# the processes then: each holds all of it), or with after_run after a run
# 0 (each holds its own part: gathered).
# Asserts: the fix logs the walls it honours and relocates targets; every
# moved sphere is clear of every wall (at least r (1 - tol) from it), on the
# side where it started, and its path crosses no wall (walls.py check; also
# check_scene's --wall-* checks when the checker has them), with moved
# spheres ending near a wall (the walls matter here: without them the fix
# puts spheres through them); check_scene's usual checks (overlaps, the box,
# rebar untouched, atom accounting, moved = relocated); then 1,000 steps
# under gravity with thermo_modify lost error lose no atom, and the kinetic
# energy at the end is within a factor 10 of that of the same scene after
# delete_atoms overlap instead of the fix.
#   walls.sh BUILD_DIR NPROCS floor|cylinder|hole [after_run]
set -euo pipefail
fixvars=()
build=$1 np=$2 kind=$3 variant=${4:-first}
here=$(cd "$(dirname "$0")" && pwd)
exe=$build/src/liggghts/liggghts_reinforce checker=$build/tests/check_scene
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_walls"
fail() { echo "FAIL: $*"; exit 1; }
gran="wall/gran model hertz tangential history"
case $kind in
  floor)
    "$build/tests/make_scene" "$work/raw.data" --box 0 0.1 0 0.1 0.02 0.12 --radius 0.004 0.008 --fcc \
      --bar 0.005 0.05 0.033 0.095 0.05 0.033 0.012 0.018 >/dev/null
    shape=(--stl "$here/floor.stl") clip=(--zlo 0)
    check_walls=(--wall-stl "$here/floor.stl")
    wall1="fix mesh all mesh/surface file floor.stl type 1"
    wall2="fix floor all $gran mesh n_meshes 1 meshes mesh"
    walls_line="fix reinforce/invert: walls: 1 mesh (2 triangles) of fix floor"
    cut=0.02 ;;
  cylinder | hole)
    "$build/tests/make_scene" "$work/raw.data" --box 0 0.12 0 0.12 0 0.1 --radius 0.004 0.008 --fcc \
      --bar 0.0869 0.0869 0.005 0.0869 0.0869 0.095 0.011 0.015 >/dev/null
    shape=(--cylinder z 0.06 0.06 0.05 inside --plane 0 0 0 0 0 1) clip=()
    check_walls=(--wall-cylinder z 0.06 0.06 0.05 inside --wall-plane 0 0 0 0 0 1)
    wall1="fix cyl all $gran primitive type 1 zcylinder 0.05 0.06 0.06"
    wall2="fix bottom all $gran primitive type 1 zplane 0"
    walls_line="fix reinforce/invert: walls: 1 primitive wall (zcylinder) of fix cyl, 1 primitive wall (zplane) of fix bottom"
    cut=0.019
    if [ "$kind" = hole ]; then
      # The cylinder scene with the region keyword: a side out region, a
      # cylindrical hole next to the bar, holds the matrix (whole spheres
      # outside the hole).
      hole=(z 0.071 0.071 0.006)
      shape+=(--cylinder "${hole[@]}" outside)
      check_walls+=(--wall-cylinder "${hole[@]}" outside)
      fixvars=(-var hook1 "region hole cylinder ${hole[*]} 0 0.1 side out units box" -var extra "region hole")
    fi ;;
  *) echo "walls.sh: unknown scene $kind"; exit 2 ;;
esac
# A clean start: the matrix wholly inside the box and clear of the walls.
python3 "$here/walls.py" clip "$work/raw.data" "$work/scene.data" "${clip[@]}" "${shape[@]}"
prerun="print no-prerun"
[ "$variant" = after_run ] && prerun="run 0"

run() {    # run OUTDIR [in.walls -var args]: 1,000 steps after the relocation
  local dir=$1 launch=(mpirun -np "$np")
  shift
  [ "$np" -eq 1 ] && launch=()
  mkdir -p "$dir"
  # -screen /dev/null, not none: LIGGGHTS's mesh reader writes to the screen
  # without checking it (a crash with -screen none).
  (cd "$here" && "${launch[@]}" "$exe" -in in.walls -log "$dir/log" -screen /dev/null \
     -var data "$work/scene.data" -var out "$dir" -var wall1 "$wall1" -var wall2 "$wall2" \
     -var prerun "$prerun" -var steps 1000 "$@") && grep -q '^END ke' "$dir/log" && return 0
  echo "$exe did not finish:"
  grep -E '^ERROR' "$dir/log" || tail -5 "$dir/log"
  return 1
}
# The dumps of the relocation are checked first, also when the run after it
# failed (a sphere put through a wall is lost, or bounces off).
finished=1
run "$work/fix" "${fixvars[@]}" || finished=0
# The reference: every matrix sphere whose centre is within the bar's radius
# plus the largest matrix radius of a bar's centre deleted instead.
run "$work/ref" -var ref 1 -var cut "$cut" || fail "the reference run failed"
log=$work/fix/log

read -r _ targets relocated deleted kept < <(grep '^TOTALS ' "$log" | tail -1) || fail "no TOTALS line"
echo "$kind np=$np ($variant): targets $targets relocated $relocated deleted $deleted kept $kept"
[ "$(grep -c '^fix reinforce/invert: [0-9]' "$log")" -eq 1 ] || fail "not one summary line"
[ "$targets" -gt 0 ] && [ "$relocated" -gt 0 ] || fail "nothing relocated: the scene tests nothing"
[ "$targets" -eq $((relocated + deleted + kept)) ] || fail "targets != relocated + deleted + kept"

python3 "$here/walls.py" check "$work/fix/before.dump" "$work/fix/after.dump" --near 1 "${shape[@]}" ||
  fail "walls.py check (above)"
extra=()
grep -q -- --wall-plane "$checker" && extra=("${check_walls[@]}")    # the checker's own wall checks
"$checker" --before "$work/fix/before.dump" --after "$work/fix/after.dump" --deleted "$deleted" \
  "${extra[@]}" | tee "$work/check" || fail "check_scene (above)"
moved=$(awk '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == "moved_targets") print $(i + 1)}' "$work/check")
[ "$moved" = "$relocated" ] || fail "check_scene sees $moved targets moved, the fix reports $relocated"

grep '^fix reinforce/invert: walls' "$log" || true
[ "$(grep -c '^fix reinforce/invert: walls' "$log")" -eq 1 ] || fail "not one walls line in the log"
grep -qxF "$walls_line" "$log" || fail "the log does not say: $walls_line"
echo "PASS: the log names the walls honoured"

[ "$finished" = 1 ] || fail "the 1000 steps after the fix did not finish"
read -r _ _ ke_fix _ atoms_fix < <(grep '^END ke' "$log")
read -r _ _ ke_ref _ atoms_ref < <(grep '^END ke' "$work/ref/log")
after=$(awk '/^ITEM: NUMBER OF ATOMS/ {getline; print $1}' "$work/fix/after.dump")
[ "$atoms_fix" = "$after" ] || fail "the run lost atoms: $after after the fix, $atoms_fix at the end"
echo "PASS: 1000 steps, no atom lost ($atoms_fix; reference $atoms_ref)"
awk -v f="$ke_fix" -v r="$ke_ref" 'BEGIN {exit !(f > 0 && r > 0 && f <= 10 * r && r <= 10 * f)}' ||
  fail "kinetic energy after 1000 steps $ke_fix, with delete_atoms overlap $ke_ref: not within 10 times"
echo "PASS: kinetic energy after 1000 steps $ke_fix, with delete_atoms overlap $ke_ref"
echo "PASS liggghts_walls_$kind np=$np"
