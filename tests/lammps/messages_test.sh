#!/usr/bin/env bash
# What fix reinforce/invert says, and two fixes side by side (LAMMPS):
#
#   messages_test.sh CASE NP BUILD_DIR [EXPECTED]
#
# CASE (input; what is asserted besides exit 0 and no ERROR line):
#   two_bars          in.two_bars: fixes r1 and r2 on group all, one per
#                     crossing bar (types 2 and 3): both bars untouched and
#                     every other check (check_scene --rebar-type 2,3); each
#                     fix logs that it left the other's bar alone, exactly:
#                     "fix reinforce/invert: left alone N atoms that overlap
#                     the bars: they are rebar of fix r2" (and "... fix r1"),
#                     N > 0
#   no_matrix_empty   in.messages, fix group an empty group
#   no_matrix_bars    in.messages, fix group the bars again (another group
#                     of the same atoms): exactly one line "WARNING: Fix
#                     reinforce/invert has no matrix sphere (an atom of the
#                     fix group outside the rebar group): nothing to
#                     relocate", the scene unchanged
#   pre_no            run 0, the fix, run 0 pre no, run 0: exactly one
#                     line "WARNING: Fix reinforce/invert did not relocate:
#                     the setup of this run was skipped (run pre no); it
#                     relocates at the setup of a run with pre yes", no
#                     relocation before it and the relocation at the next
#                     run (pre yes) after it
#   spring_self       fix s all spring/self 10.0 before the fix: exactly one
#                     line "WARNING: Fix reinforce/invert moved N atoms held
#                     by fix s (spring/self): their anchors are still the
#                     old positions", N = the spheres the checker sees moved
#                     (> 0) = the fix's relocated count
#   wall_rebar_only   fix wall/lj93 on the bars alone: no ERROR, no walls
#                     line, targets relocated
#   spring_self_push  the same with push: N = the spheres the checker sees
#                     moved, relocated or pushed, each once (> relocated)
#   lost_matrix       in.messages with the defaults (radii 4.5 to 5 mm: few
#                     voids), then a second run 0:
#                     exactly one line "WARNING: Fix reinforce/invert
#                     regrowth left N targets smaller than their own radius
#                     and deleted M targets beyond the K whose centre lies
#                     inside the bars: the targets keep S of their volume"
#                     (either part alone when the other is 0), N =
#                     f_ID[26], M = f_ID[3] - f_ID[16], K = f_ID[16], S =
#                     f_ID[6] / f_ID[5], N + M > 0; with regrow no, none
#   unplaced_isolated in.messages -var single yes: one matrix sphere alone
#                     in an empty box, on a bar: deleted, and the unplaced
#                     line names the cause: it contains EXPECTED
# WARNING lines are compared without LAMMPS's " (file:line)" suffix.
set -euo pipefail
case=$1 np=$2 build=$3 expected=${4:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
exe=$build/src/lammps/lmp_reinforce
checker=$build/tests/check_scene
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "messages_${case}"
fail() { echo "FAIL: $case np=$np: $*"; exit 1; }

# run INPUT [lmp -var args]: on NP processes, into $work; must exit 0 with no ERROR line
run() {
  local input=$1
  shift
  local launch=(mpirun -np "$np")
  [ "$np" -eq 1 ] && launch=()
  (cd "$here" && timeout 120 "${launch[@]}" "$exe" -in "$input" -log "$work/log" -screen none \
     -var out "$work" "$@") >"$work/stdout" 2>&1 ||
    { grep -E '^ERROR' "$work/log" || tail -3 "$work/log"; fail "$exe exited non-zero"; }
  ! grep -q '^ERROR' "$work/log" || fail "an ERROR line: $(grep '^ERROR' "$work/log" | head -1)"
}
# the WARNING lines of the log, without the source location
warnings() { sed -nE 's/^(WARNING: .*) \([^()]*:[0-9]+\)$/\1/p' "$work/log"; }
# exactly one WARNING line, exactly TEXT
one_warning() {
  local text=$1 n
  n=$(warnings | grep -cxF -- "$text" || true)
  [ "$n" -eq 1 ] || { warnings; fail "$n lines '$text', expected exactly one"; }
  echo "PASS: one line: $text"
}
totals() { awk -v w="$1" '$1 == w {$1 = ""; v = $0} END {print v}' "$work/log"; }

small() { "$build/tests/make_scene" "$work/scene.data" --box 0 0.1 0 0.1 0 0.1 --radius 0.004 0.008 --fcc \
            --bar 0.01 0.05 0.05 0.09 0.05 0.05 0.005 0.0075 >/dev/null; }
NO_MATRIX="WARNING: Fix reinforce/invert has no matrix sphere (an atom of the fix group outside the rebar group): nothing to relocate"
case $case in
  two_bars)
    "$build/tests/make_scene" "$work/scene.data" --box 0 0.2 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
      --bar 0.01 0.1 0.1 0.19 0.1 0.1 0.005 0.0075 --bar 0.1 0.01 0.105 0.1 0.19 0.105 0.005 0.0075 >/dev/null
    run in.two_bars -var data "$work/scene.data"
    read -r b1 b2 <<<"$(totals BARS)"
    { [ "$b1" -gt 0 ] && [ "$b2" -gt 0 ]; } || fail "bars of $b1 and $b2 spheres"
    read -r t1 r1 d1 _ <<<"$(totals TOTALS1)"
    read -r t2 r2 d2 _ <<<"$(totals TOTALS2)"
    echo "r1: $t1 targets, $r1 relocated, $d1 deleted; r2: $t2 targets, $r2 relocated, $d2 deleted"
    { [ "$r1" -gt 0 ] && [ "$r2" -gt 0 ]; } || fail "each fix must relocate targets of its bar"
    "$checker" --before "$work/before.dump" --after "$work/after.dump" --rebar-type 2,3 \
      --deleted $((d1 + d2)) || fail "the checker failed (above)"
    for other in r2 r1; do
      line=$(left_alone_line "$work/log" "$other") || fail "no (or several) line: left alone N atoms ... rebar of fix $other"
      n=$(awk '{print $5}' <<<"$line")
      [ "$n" -gt 0 ] || fail "left alone $n atoms"
      echo "PASS: $line"
    done
    ;;
  no_matrix_empty | no_matrix_bars)
    small
    group=nothing
    [ "$case" = no_matrix_bars ] && group=barsonly
    run in.messages -var data "$work/scene.data" -var fixgroup $group
    one_warning "$NO_MATRIX"
    "$checker" --same "$work/before.dump" "$work/after.dump" || fail "the scene changed"
    ;;
  pre_no)
    small
    run in.messages -var data "$work/scene.data" -var before "run 0" -var runcmd "run 0 pre no" -var after "run 0"
    text="WARNING: Fix reinforce/invert did not relocate: the setup of this run was skipped (run pre no); it relocates at the setup of a run with pre yes"
    one_warning "$text"
    read -r t r d _ <<<"$(totals TOTALS)"
    [ "$t $r" = "0 0" ] || fail "relocated at the run with pre no ($t targets, $r relocated)"
    read -r t r d _ <<<"$(totals TOTALS_AFTER)"
    [ "$r" -gt 0 ] || fail "the next run (pre yes) did not relocate"
    # the order: the warning, then the relocation's summary line, once
    # (W: the warning, S: a summary line)
    order=$(awk '/^WARNING: Fix reinforce\/invert did not relocate/ {printf "W"}
                 /^fix reinforce\/invert: [0-9]+ targets/ {printf "S"}' "$work/log")
    [ "$order" = WS ] || fail "the warning, then one relocation (WS) expected; the log has $order"
    echo "PASS: no relocation at the run with pre no; $r relocated at the next run"
    ;;
  spring_self|spring_self_push)
    extra=""    # with push, spheres relocated and then pushed, or pushed twice, count once
    if [ "$case" = spring_self ]; then
      small
    else    # radii too alike for the voids to hold the targets: room is made
      "$build/tests/make_scene" "$work/scene.data" --box 0 0.1 0 0.1 0 0.1 --radius 0.0045 0.005 --fcc \
        --bar 0.01 0.05 0.05 0.09 0.05 0.05 0.005 0.0075 >/dev/null
      extra="size keep push 0.004 regrow no"
    fi
    run in.messages -var data "$work/scene.data" -var before "fix s all spring/self 10.0" -var fixextra "$extra"
    line=$(warnings | grep -E '^WARNING: Fix reinforce/invert moved [0-9]+ atoms held by fix s \(spring/self\): their anchors are still the old positions$' || true)
    [ "$(grep -c . <<<"$line")" -eq 1 ] || { warnings; fail "expected exactly one spring/self warning"; }
    n=$(awk '{print $5}' <<<"$line")
    read -r t r d _ <<<"$(totals TOTALS)"
    moved=$("$checker" --before "$work/before.dump" --after "$work/after.dump" --deleted "$d" |
            awk '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == "moved") print $(i + 1)}')
    if [ "$case" = spring_self ]; then
      { [ "$n" -gt 0 ] && [ "$n" = "$moved" ] && [ "$n" = "$r" ]; } ||
        fail "the warning says $n atoms moved; the checker sees $moved moved, the fix reports $r relocated"
      echo "PASS: $line (= the spheres moved, = relocated)"
    else
      { [ "$n" -gt "$r" ] && [ "$n" = "$moved" ]; } ||
        fail "the warning says $n atoms moved; the checker sees $moved moved, the fix reports $r relocated (pushes expected)"
      echo "PASS: $line (= the spheres moved, more than the $r relocated)"
    fi
    ;;
  wall_rebar_only)
    # A wall fix on the bars alone acts on nothing the fix moves: neither
    # read nor refused (the same wall/lj93 on the matrix stops the run:
    # lammps_walls_*).
    small
    run in.messages -var data "$work/scene.data" -var before "fix w barsonly wall/lj93 zlo EDGE 1.0 1.0 2.5 units box"
    read -r t r d _ <<<"$(totals TOTALS)"
    [ "$r" -gt 0 ] || fail "nothing relocated"
    ! grep -q 'walls:' "$work/log" || fail "a walls line: $(grep 'walls:' "$work/log")"
    echo "PASS: wall on the bars alone: no ERROR, no walls line, $r relocated"
    ;;
  lost_matrix)
    # Radii too alike for the voids to hold the targets: the regrowth deletes
    # beyond the bars' centres (the volume balance) or leaves some shrunk.
    "$build/tests/make_scene" "$work/scene.data" --box 0 0.1 0 0.1 0 0.1 --radius 0.0045 0.005 --fcc \
      --bar 0.01 0.05 0.05 0.09 0.05 0.05 0.005 0.0075 >/dev/null
    lost='^WARNING: Fix reinforce/invert regrowth '
    run in.messages -var data "$work/scene.data" -var fixextra "regrow no" -var after "run 0"
    [ "$(warnings | grep -c -- "$lost" || true)" -eq 0 ] || fail "a lost-matrix warning with regrow no"
    run in.messages -var data "$work/scene.data" -var after "run 0"
    read -r shrunk d k before after <<<"$(totals LOST)"
    m=$((d - k))
    [ $((shrunk + m)) -gt 0 ] || fail "nothing shrunk or deleted beyond the bars: nothing to warn of"
    what=""
    [ "$shrunk" -gt 0 ] && what="left $shrunk targets smaller than their own radius"
    [ "$m" -gt 0 ] && what="$what${what:+ and }deleted $m targets beyond the $k whose centre lies inside the bars"
    share=$(awk -v a="$after" -v b="$before" 'BEGIN {printf "%.2f", a / b}')
    one_warning "WARNING: Fix reinforce/invert regrowth $what: the targets keep $share of their volume"
    [ "$(warnings | grep -c -- "$lost" || true)" -eq 1 ] || fail "more than one lost-matrix warning"
    ;;
  unplaced_isolated)
    [ -n "$expected" ] || { echo "messages_test.sh: unplaced_isolated needs EXPECTED"; exit 2; }
    run in.messages -var data none -var single yes -var fixextra "regrow no"
    read -r t r d _ <<<"$(totals TOTALS)"
    [ "$t $r $d" = "1 0 1" ] || fail "expected 1 target, 0 relocated, 1 deleted; got $t $r $d"
    line=$(grep '^fix reinforce/invert: unplaced:' "$work/log" || true)
    [ -n "$line" ] || fail "no unplaced line"
    grep -qF -- "$expected" <<<"$line" || fail "the unplaced line does not say '$expected': $line"
    echo "PASS: $line"
    ;;
  *) echo "messages_test.sh: unknown case $case"; exit 2 ;;
esac
echo "PASS messages $case np=$np"
