#!/usr/bin/env bash
# The adapter's WARNING and ERROR lines, asserted by their exact text (but
# for LIGGGHTS's "WARNING: " and " (file:line)"), on the cylinder scene of
# walls.sh (in.walls):
#   pre_no         run 0, then the fix, then run 0 pre no: the setup is
#                  skipped, one WARNING; the next run (pre yes) relocates
#                  (regrow no: the regrowth's own WARNING is not this test's).
#   spring_self    fix spring/self on the matrix (regrow no): one WARNING
#                  naming it and the number of atoms moved (the relocated
#                  targets).
#   spring_self_push  the same where room is made: N = the spheres moved
#                  (relocated or pushed, each once; check_scene).
#   wall_unseen    fix wall/region (geometry the adapter cannot read): stops
#                  at setup with the one ERROR line (../scripts/expect_error.sh).
#   wall_region    the same with the region keyword: no ERROR, the log line
#                  says the wall was not read, and the region keeps whole
#                  spheres inside it (walls.py check).
#   two_bars       two fixes on group all, one per crossing bar (in.two_bars):
#                  both bars untouched (check_scene --rebar-type 2,3), each
#                  fix logs that it left the other's bar alone.
#   wall_rebar_only  fix wall/region on the bars alone: not read, no ERROR.
#   walls_ignore   the same with walls ignore: no ERROR, no walls line.
#   region_no_surface  a region without the surface distance that keeps
#                  whole spheres inside (wedge, side out): the ERROR line.
#   messages.sh BUILD_DIR NPROCS CASE
set -euo pipefail
build=$1 np=$2 case=$3
here=$(cd "$(dirname "$0")" && pwd)
exe=$build/src/liggghts/liggghts_reinforce
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_messages"
fail() { echo "FAIL: $*"; exit 1; }
gran="wall/gran model hertz tangential history"
"$build/tests/make_scene" "$work/raw.data" --box 0 0.12 0 0.12 0 0.1 --radius 0.004 0.008 --fcc \
  --bar 0.0869 0.0869 0.005 0.0869 0.0869 0.095 0.011 0.015 >/dev/null
shape=(--cylinder z 0.06 0.06 0.05 inside --plane 0 0 0 0 0 1)
python3 "$here/walls.py" clip "$work/raw.data" "$work/scene.data" "${shape[@]}" >/dev/null
vars=(-var data "$work/scene.data" -var out "$work"
      -var wall1 "fix cyl all $gran primitive type 1 zcylinder 0.05 0.06 0.06"
      -var wall2 "fix bottom all $gran primitive type 1 zplane 0")
region="region inner cylinder z 0.06 0.06 0.05 0 0.1 units box"
unseen="fix w all wall/region inner lj93 1e-9 0.001 0.0025"

run() {    # run [in.walls -var args]
  local launch=(mpirun -np "$np")
  [ "$np" -eq 1 ] && launch=()
  (cd "$here" && "${launch[@]}" "$exe" -in in.walls -log "$work/log" -screen /dev/null "${vars[@]}" "$@") ||
    { echo "FAIL: $exe exited non-zero"; grep '^ERROR' "$work/log" || tail -5 "$work/log"; exit 1; }
  grep -q '^END ke' "$work/log" || fail "the input did not finish"
}
warnings() { { grep '^WARNING' "$work/log" || true; } | sed -E 's/^WARNING: //; s/ \([^()]*:[0-9]+\)$//'; }
expect_warning() {    # expect_warning TEXT: the only WARNING line of the log
  warnings | sed 's/^/  /'
  local n
  n=$(grep -c '^WARNING' "$work/log" || true)
  [ "$n" -eq 1 ] || fail "$n WARNING lines, expected one"
  [ "$(warnings)" = "$1" ] || fail "the WARNING is not exactly: $1"
  echo "PASS: WARNING: $1"
}
summaries() { grep -c '^fix reinforce/invert: [0-9]' "$work/log" || true; }

case $case in
  pre_no)
    # regrow no: the regrowth's WARNING on matrix lost is not this test's
    # (lammps_messages_lost_matrix_*); here the only WARNING is pre no's.
    run -var prerun "run 0" -var fixrun "run 0 pre no" -var extra "regrow no"
    expect_warning "Fix reinforce/invert did not relocate: the setup of this run was skipped (run pre no); it relocates at the setup of a run with pre yes"
    # Nothing before the warning, one relocation at the next run (pre yes).
    first=$(grep -n -m1 '^fix reinforce/invert: [0-9]' "$work/log" | cut -d: -f1)
    warned=$(grep -n -m1 '^WARNING' "$work/log" | cut -d: -f1)
    [ "$(summaries)" -eq 1 ] && [ "$first" -gt "$warned" ] ||
      fail "expected one relocation, after the warning, at the run with pre yes"
    echo "PASS: relocated at the next run with pre yes" ;;
  spring_self)
    run -var hook1 "fix anchor matrix spring/self 1000" -var extra "regrow no"    # as pre_no
    read -r _ _ relocated _ _ < <(grep '^TOTALS ' "$work/log") || fail "no TOTALS line"
    [ "$relocated" -gt 0 ] || fail "nothing relocated"
    expect_warning "Fix reinforce/invert moved $relocated atoms held by fix anchor (spring/self): their anchors are still the old positions" ;;
  spring_self_push)
    # Radii too alike for the voids to hold the targets: room is made by
    # pushing, and a sphere relocated and then pushed, or pushed twice,
    # counts once: N = the spheres the checker sees moved (> relocated).
    "$build/tests/make_scene" "$work/raw.data" --box 0 0.12 0 0.12 0 0.1 --radius 0.0045 0.005 --fcc \
      --bar 0.0869 0.0869 0.005 0.0869 0.0869 0.095 0.011 0.015 >/dev/null
    python3 "$here/walls.py" clip "$work/raw.data" "$work/scene.data" "${shape[@]}" >/dev/null
    run -var hook1 "fix anchor matrix spring/self 1000" -var extra "size keep push 0.004 regrow no"
    read -r _ _ relocated deleted _ < <(grep '^TOTALS ' "$work/log") || fail "no TOTALS line"
    moved=$("$build/tests/check_scene" --before "$work/before.dump" --after "$work/after.dump" \
              --deleted "$deleted" | awk '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == "moved") print $(i + 1)}')
    [ "${moved:-0}" -gt "$relocated" ] || fail "the checker sees ${moved:-no} spheres moved, $relocated relocated: no push"
    expect_warning "Fix reinforce/invert moved $moved atoms held by fix anchor (spring/self): their anchors are still the old positions" ;;
  wall_unseen)
    EXPECT_EXACT=1 "$here/../scripts/expect_error.sh" "$exe" "$np" "$here/in.walls" \
      "Fix reinforce/invert cannot see the walls of fix w (wall/region): give a region that holds the matrix (region keyword: whole spheres are kept inside it) or walls ignore" \
      "${vars[@]}" -var hook1 "$region" -var hook2 "$unseen" || exit 1 ;;
  wall_region)
    run -var hook1 "$region" -var hook2 "$unseen" -var extra "region inner"
    line="fix reinforce/invert: walls: 1 primitive wall (zcylinder) of fix cyl, 1 primitive wall (zplane) of fix bottom; fix w (wall/region) not read: region inner holds the matrix"
    grep -qxF "$line" "$work/log" || { grep 'walls:' "$work/log" || true; fail "the log does not say: $line"; }
    [ "$(summaries)" -eq 1 ] || fail "no relocation"
    [ "$(grep -c '^ERROR' "$work/log")" -eq 0 ] || fail "an ERROR"
    python3 "$here/walls.py" check "$work/before.dump" "$work/after.dump" "${shape[@]}" || fail "walls.py check"
    echo "PASS: $line" ;;
  region_no_surface)
    EXPECT_EXACT=1 "$here/../scripts/expect_error.sh" "$exe" "$np" "$here/in.walls" \
      "Fix reinforce/invert region 'w' (wedge, side out) has no surface distance: whole spheres cannot be kept inside it" \
      "${vars[@]}" -var extra "region w" \
      -var hook1 "region w wedge axis z center 0.06 0.06 radius 0.05 bounds 0 0.1 angle0 0 angle 90 side out units box" || exit 1 ;;
  wall_rebar_only)
    # A wall fix on the bars alone acts on nothing the fix moves: neither
    # read nor refused (wall_unseen: the same on all stops the run).
    run -var hook1 "$region" -var hook2 "${unseen/ all / rebar }"
    line="fix reinforce/invert: walls: 1 primitive wall (zcylinder) of fix cyl, 1 primitive wall (zplane) of fix bottom"
    grep -qxF "$line" "$work/log" || { grep 'walls:' "$work/log" || true; fail "the log does not say: $line"; }
    [ "$(summaries)" -eq 1 ] || fail "no relocation"
    echo "PASS: wall on the bars alone: $line" ;;
  two_bars)
    # Two fixes on group all, one per crossing bar (in.two_bars): neither
    # moves the other's bar, and each says it left it alone.
    "$build/tests/make_scene" "$work/raw.data" --box 0 0.2 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
      --bar 0.01 0.1 0.1 0.19 0.1 0.1 0.005 0.0075 --bar 0.1 0.01 0.105 0.1 0.19 0.105 0.005 0.0075 >/dev/null
    sed 's/^2 atom types$/3 atom types/' "$work/raw.data" >"$work/scene.data"    # LIGGGHTS has no extra/atom/types
    launch=(mpirun -np "$np")
    [ "$np" -eq 1 ] && launch=()
    (cd "$here" && "${launch[@]}" "$exe" -in in.two_bars -log "$work/log" -screen /dev/null \
       -var data "$work/scene.data" -var out "$work") || { grep '^ERROR' "$work/log" || tail -5 "$work/log"; fail "$exe exited non-zero"; }
    value() { awk -v w="$1" '$1 == w {$1 = ""; v = $0} END {print v}' "$work/log"; }
    read -r b1 b2 <<<"$(value BARS)"
    { [ "$b1" -gt 0 ] && [ "$b2" -gt 0 ]; } || fail "bars of $b1 and $b2 spheres"
    read -r _ r1 d1 <<<"$(value TOTALS1)"
    read -r _ r2 d2 <<<"$(value TOTALS2)"
    { [ "$r1" -gt 0 ] && [ "$r2" -gt 0 ]; } || fail "each fix must relocate targets of its bar ($r1, $r2)"
    "$build/tests/check_scene" --before "$work/before.dump" --after "$work/after.dump" --rebar-type 2,3 \
      --deleted $((d1 + d2)) || fail "the checker failed (above)"
    for other in r2 r1; do
      line=$(left_alone_line "$work/log" "$other") || fail "no (or several) line: left alone N atoms ... rebar of fix $other"
      echo "PASS: $line"
    done ;;
  walls_ignore)
    # Relocated spheres may now cross the cylinder (the user's risk): the
    # wall/region fix gets a region that holds them all.
    run -var hook1 "region big block -1 1 -1 1 -1 1 units box" -var hook2 "${unseen/inner/big}" \
      -var extra "walls ignore"
    [ "$(grep -c 'walls:' "$work/log")" -eq 0 ] || fail "walls ignore, yet the walls were read"
    [ "$(summaries)" -eq 1 ] || fail "no relocation"
    echo "PASS: walls ignore: nothing read, no ERROR" ;;
  *) echo "messages.sh: unknown case $case"; exit 2 ;;
esac
echo "PASS liggghts_messages_$case np=$np"
