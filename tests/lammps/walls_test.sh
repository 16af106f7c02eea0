#!/usr/bin/env bash
# Fix reinforce/invert and the walls of other fixes (LAMMPS, in.walls): a
# dense granular packing (grow_packing, 0.58) held by a wall, a bar close to
# the wall, so that a relocation blind to the wall puts spheres into or
# through it (walls ignore: 14 of the 29 relocated in the cylinder, 12 of
# the 23 above the plane; and the same on the code before walls were
# handled, with or without the region, whose centres were then inside it).
#
#   walls_test.sh MODE SCENE NP BUILD_DIR
#
# SCENE, the wall fix (on group all):
#   cylinder     wall/gran zcylinder 0.08 (the z axis through the box centre)
#   gran_region  wall/gran/region on the cylinder region wcyl (radius 0.08)
#   plane        wall/gran zplane 0.03 NULL (the matrix above z = 0.03)
#   reflect, harmonic, wall_region   wall/reflect zlo 0.03, wall/harmonic
#                zlo 0.03, wall/region on the block z >= 0.03 (plane scene)
# MODE:
#   error   the fix cannot read the wall's geometry: the run after the fix
#           stops with exactly one ERROR line, exactly the expected message
#           (expect_error.sh: nothing written after)
#   region  the fix is given a region that holds the matrix (cylinder:
#           region inside, the wall's cylinder; gran_region: the wall's own
#           region wcyl; plane: the block z >= 0.03): the run goes through;
#           the checker with the wall (--wall-cylinder z 0 0 0.08 inside,
#           or --wall-plane 0 0 0.03 0 0 1 and --inside-box for the block):
#           no moved sphere overlaps it, and all the usual checks; then
#           1,000 steps (wall, granular pair style, small random velocities,
#           thermo_modify lost error) lose no atom and end with a kinetic
#           energy within a factor 10 of the same scene's with delete_atoms
#           overlap instead of the fix, run the same steps
#   ignore  walls ignore: the run goes through (no ERROR line), and the
#           scene is a test of the walls: the checker finds moved spheres
#           through the wall
#   other_group   the wall fix acts on the bars only (group rebar): not on
#           the fix's matrix, so no ERROR; the run goes through
set -euo pipefail
mode=$1 scene=$2 np=$3 build=$4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
input=$here/in.walls
exe=$build/src/lammps/lmp_reinforce
checker=$build/tests/check_scene
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "walls_${mode}_${scene}"
fail() { echo "FAIL: $mode $scene np=$np: $*"; exit 1; }

# The granular model of every wall/gran fix and of the pair style.
GRAN="hooke 2000 NULL 50 NULL 0.5 0"
case $scene in
  cylinder | gran_region)
    grow=(--box -0.09 0.09 -0.09 0.09 0 0.15 --radius 0.004 0.008 --phi 0.58 --seed 1
          --bar 0.066 0 0.01 0.066 0 0.14 0.005 0.0075)
    # centres within 0.072 of the axis: every sphere wholly inside the wall
    keep="region held cylinder z 0 0 0.072 -1 1 units box"
    walls=(--wall-cylinder z 0 0 0.08 inside) inside=()
    if [ "$scene" = cylinder ]; then
      wall="fix w all wall/gran $GRAN zcylinder 0.08" style=wall/gran
      setup="region inside cylinder z 0 0 0.08 -1 1 units box" region=inside
    else
      wall="fix w all wall/gran/region $GRAN region wcyl" style=wall/gran/region
      setup="region wcyl cylinder z 0 0 0.08 -1 1 units box" region=wcyl
    fi
    ;;
  plane | reflect | harmonic | wall_region)
    grow=(--box -0.06 0.06 -0.06 0.06 0 0.12 --radius 0.004 0.008 --phi 0.58 --seed 2
          --bar -0.055 0 0.044 0.055 0 0.044 0.005 0.0075)
    keep="region held block INF INF INF INF 0.038 INF units box"
    walls=(--wall-plane 0 0 0.03 0 0 1) inside=(--inside-box -INF INF -INF INF 0.03 INF)
    setup="region above block INF INF INF INF 0.03 INF units box" region=above
    case $scene in
      plane) wall="fix w all wall/gran $GRAN zplane 0.03 NULL" style=wall/gran ;;
      reflect) wall="fix w all wall/reflect zlo 0.03" style=wall/reflect ;;
      harmonic) wall="fix w all wall/harmonic zlo 0.03 1.0 1.0 0.005" style=wall/harmonic ;;
      wall_region) wall="fix w all wall/region above harmonic 1.0 1.0 0.005" style=wall/region ;;
    esac
    ;;
  *) echo "walls_test.sh: unknown scene $scene"; exit 2 ;;
esac
"$build/tests/grow_packing" "$work/scene.data" "${grow[@]}" --quiet >/dev/null || fail "grow_packing failed"
vars=(-var data "$work/scene.data" -var keep "$keep" -var setup "$setup")

# launch DIR [lmp -var args]: in.walls on NP processes; sets status
launch() {
  local dir=$1
  shift
  mkdir -p "$dir"
  local mpi=(mpirun -np "$np")
  [ "$np" -eq 1 ] && mpi=()
  status=0
  (cd "$here" && timeout 120 "${mpi[@]}" "$exe" -in "$input" -log "$dir/log" -screen none \
     -var out "$dir" "${vars[@]}" "$@") >"$dir/stdout" 2>&1 || status=$?
}
# succeeded DIR: the run exited 0 with no ERROR line, or the test fails
succeeded() {
  [ "$status" -eq 0 ] || { grep -E '^ERROR' "$1/log" || tail -3 "$1/log"; fail "$exe exited with status $status"; }
  ! grep -q '^ERROR' "$1/log" || fail "an ERROR line: $(grep '^ERROR' "$1/log" | head -1)"
}
run() { launch "$@"; succeeded "$1"; }
# field N of the last line of FILE that starts with WORD
field() { awk -v w="$1" -v n="$2" '$1 == w {v = $n} END {print v}' "$3"; }

FIX="fix r all reinforce/invert 0 rebar"
case $mode in
  error)
    message="Fix reinforce/invert cannot see the walls of fix w ($style): give a region that holds the matrix (region keyword: whole spheres are kept inside it) or walls ignore"
    EXPECT_EXACT=1 "$here/../scripts/expect_error.sh" "$exe" "$np" "$input" "$message" \
      "${vars[@]}" -var wall "$wall" -var relocate "$FIX" || fail "no refusal (above)"
    echo "PASS walls $mode $scene np=$np"
    ;;
  region)
    # the checker on what the fix wrote first, then whether the steps after
    # it went through
    launch "$work/fix" -var wall "$wall" -var relocate "$FIX region $region"
    log=$work/fix/log
    grep '^fix reinforce/invert: [0-9]' "$log" || { succeeded "$work/fix"; fail "no summary line"; }
    read -r _ targets relocated deleted kept <<<"$(grep '^TOTALS' "$log" | tail -1)"
    echo "targets $targets relocated $relocated deleted $deleted kept $kept"
    [ "$relocated" -gt 0 ] || fail "nothing relocated: the scene tests nothing"
    "$checker" --before "$work/fix/before.dump" --after "$work/fix/after.dump" --deleted "$deleted" \
      "${walls[@]}" "${inside[@]}" || fail "the checker failed (above)"
    succeeded "$work/fix"
    atoms0=$(field ATOMS0 2 "$log") ke=$(field KE 2 "$log") atoms=$(field KE 4 "$log")
    { [ -n "$ke" ] && [ "$atoms" = "$atoms0" ]; } || fail "the run after the fix lost atoms ($atoms0 -> $atoms)"
    echo "PASS: the run after the fix lost no atom ($atoms atoms)"
    run "$work/ref" -var wall "$wall" -var relocate "delete_atoms overlap 0.013 matrix rebar compress no"
    ke_ref=$(field KE 2 "$work/ref/log")
    [ -n "$ke_ref" ] || fail "no KE line in the reference run"
    awk -v a="$ke" -v b="$ke_ref" 'BEGIN {exit !(b > 0 && a <= 10 * b && a >= b / 10)}' ||
      fail "kinetic energy after the steps $ke, with delete_atoms overlap instead of the fix $ke_ref (not within a factor 10)"
    echo "PASS: kinetic energy after the steps $ke, with delete_atoms overlap instead of the fix $ke_ref (within a factor 10)"
    echo "PASS walls $mode $scene np=$np"
    ;;
  ignore)
    run "$work/fix" -var wall "$wall" -var relocate "$FIX walls ignore" -var steps 0
    log=$work/fix/log
    grep '^fix reinforce/invert: [0-9]' "$log" || fail "no summary line"
    echo "PASS: walls ignore: the run went through, no ERROR line"
    read -r _ targets relocated deleted kept <<<"$(grep '^TOTALS' "$log" | tail -1)"
    out=$("$checker" --before "$work/fix/before.dump" --after "$work/fix/after.dump" --deleted "$deleted" \
      "${walls[@]}" || true)
    grep -E '^FAIL: moved spheres clear of the walls \(.*: [1-9][0-9]* of [0-9]+ moved' <<<"$out" |
      sed 's/^FAIL: /as it should, the checker fails: /' | grep . ||
      fail "the fix, told to ignore the walls, put no sphere through them: the scene does not test the walls"$'\n'"$out"
    echo "PASS: the scene tests the walls: blind to them, the fix puts spheres through"
    echo "PASS walls $mode $scene np=$np"
    ;;
  other_group)
    run "$work/fix" -var wall "${wall/fix w all/fix w rebar}" -var relocate "$FIX" -var steps 0
    grep '^fix reinforce/invert: [0-9]' "$work/fix/log" || fail "no summary line"
    echo "PASS: a wall on the bars only: no ERROR line, the run went through"
    echo "PASS walls $mode $scene np=$np"
    ;;
  *) echo "walls_test.sh: unknown mode $mode"; exit 2 ;;
esac
