#!/usr/bin/env bash
# Runs one input-script scene test and asserts on the written result.
#
#   run_scene.sh NAME EXE NPROCS INPUT CHECKER -- [lmp -var args] -- [checker args]
#
# The input must write $out/before.dump (the scene as read) and
# $out/after.dump (after the fix), and report the fix's totals with
#   print "TOTALS ${targets} ${relocated} ${deleted} ${kept}"
# Checked, on the written result:
#  * the checker (no overlap above tol, radii, walls, atom conservation with
#    the deleted count the fix reports, rebar untouched), and its counts
#    against the fix's: targets moved = relocated, other spheres moved <=
#    pushed (PUSHED line, f_ID[13] + f_ID[21]; none moved without it), targets left on
#    a bar = kept (unless SCENE_KEPT_ANY=1: atoms outside the fix group may be left
#    on a bar too);
#  * targets = relocated + deleted + kept, one summary line in the log;
#  * moved spheres keep their density (mass scaled with the volume), when
#    the dumps have a mass column; with a STATS line, f_ID[5] and f_ID[6]
#    are the volumes of the targets and of the relocated spheres written,
#    and f_ID[7] is no smaller than the largest overlap the checker finds
#    for a moved sphere (with no kept targets: their overlaps are allowed);
#  * with SCENE_TWICE=1, run twice: identical atoms and identical totals
#    (set on a few scenes at 4 processes; the identity tests, which compare
#    every grid with one process bit for bit, cover the rest).
# Optional lines the input may print, checked when present:
#   print "STATS f1 ... f8 f10"     printed (the stability tests match it)
#   print "ATOMS $(atoms)"          LAMMPS's atom count = atoms in after.dump
#   print "PUSHED f13+f21"          spheres moved to make room: pushed (f_ID[13])
#                                   or moved by the regrowth (f_ID[21])
#   print "PUSHES f13"              the relocation's pushes alone: printed (the
#                                   push tests match it)
#   print "ONCE f1 f2 f3 f4"        after a second run with the same N = 0 fix:
#                                   same totals, no second summary line
#   print "AGAIN t r d k atoms"     a fresh fix afterwards: its targets are
#                                   exactly the kept ones
#   print "KEPT_OVERLAP f11"        f_ID[11], the largest overlap of a
#                                   relocated sphere with a kept target / rmin:
#                                   no smaller than the checker's
#                                   max_overlap_kept (printed whenever targets
#                                   were kept)
# and when after.dump has a c_disp[4] column (compute displace/atom defined
# before the fix), it must equal the distance each atom moved between the
# dumps: other fixes' per-atom data follow the atoms through the deletions.
# SCENE_POST="command args": run as `command args BEFORE AFTER` at the end;
# with SCENE_REFERENCE=1 also given the after dump of the same input run on
# one process (-var procs "1 1 1", and -var setup "$SCENE_REFERENCE_SETUP"
# when that is set: a setup command that needs several processes), as a
# third file. SCENE_REFERENCE_EXTRA, when set (even empty), is the
# reference run's -var extra instead (the keywords a run must match), and
# SCENE_REFERENCE_INPUT its input (another way to the same scene).
# SCENE_SCREEN_FILE=1: each run's screen output to a file beside its log
# instead of -screen none (LIGGGHTS 3.8 inserting multisphere clumps
# writes to the screen unchecked: a segmentation fault without one).
# SCENE_LOG_POST="command args": run as `command args LOG [REFERENCE_LOG]` at
# the end, on what the fix logged (the run's log, and with SCENE_REFERENCE=1
# that of the 1-process run), e.g. ghost_cutoff.sh.
set -euo pipefail
name=$1 exe=$2 np=$3 input=$4 checker=$5
shift 5
[ "$1" = "--" ] && shift
vars=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do vars+=("$1"); shift; done
[ $# -gt 0 ] && shift
check_args=("$@")

. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "scene_${name}"

fail() { echo "FAIL: $*"; exit 1; }
run() {    # run OUTDIR [NP [first lmp args]]; the input: $input
  local dir=$1 n=${2:-$np} indir
  indir=$(cd "$(dirname "$input")" && pwd)
  shift; [ $# -gt 0 ] && shift
  mkdir -p "$dir"
  local launch=(mpirun -np "$n")
  [ "$n" -eq 1 ] && launch=()    # serial: the executable itself (no mpirun start-up)
  local screen=none
  [ "${SCENE_SCREEN_FILE:-0}" = 1 ] && screen=$dir/screen
  (cd "$indir" && "${launch[@]}" "$exe" -in "$input" -log "$dir/log" -screen "$screen" \
     -var out "$dir" "$@" "${vars[@]}") || { echo "FAIL: $exe exited non-zero"; tail -5 "$dir/log"; exit 1; }
}
last() { grep "^$1 " "$2" | tail -1 || true; }    # last line starting with a word

run "$work/a"
log=$work/a/log
totals=$(last TOTALS "$log")
[ -n "$totals" ] || { echo "FAIL: no TOTALS line in the log"; tail -5 "$log"; exit 1; }
read -r _ targets relocated deleted kept <<<"$totals"
summaries=$(grep -c '^fix reinforce/invert: [0-9]' "$log" || true)
[ "$summaries" -ge 1 ] || fail "no summary line"
echo "$name np=$np: targets $targets relocated $relocated deleted $deleted kept $kept"
last STATS "$log"
last PUSHES "$log"
grep '^fix reinforce/invert: regrowth:' "$log" | tail -1 || true
[ "$targets" -eq $((relocated + deleted + kept)) ] || fail "targets != relocated + deleted + kept"

"$checker" --before "$work/a/before.dump" --after "$work/a/after.dump" --deleted "$deleted" \
  "${check_args[@]}" | tee "$work/check" || fail "the checker failed (above)"
summary_field() { awk -v k="$1" '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == k) print $(i + 1)}' "$work/check"; }
moved=$(summary_field moved_targets) pushed_seen=$(summary_field moved_others) ckept=$(summary_field kept)
[ "$moved" = "$relocated" ] || fail "the checker sees $moved targets moved, the fix reports $relocated relocated"
# Spheres pushed to make room: f_ID[13] counts each once per round that
# pushed it, so it bounds the distinct spheres the checker sees moved.
pushed=$(last PUSHED "$log")
if [ -n "$pushed" ]; then
  awk -v s="$pushed_seen" -v f="${pushed#PUSHED }" 'BEGIN {exit !(s + 0 <= f + 0 && (f + 0 == 0) == (s + 0 == 0))}' ||
    fail "the checker sees $pushed_seen other spheres moved, the fix reports ${pushed#PUSHED } pushed"
  echo "PASS: other spheres moved ($pushed_seen) <= pushed (${pushed#PUSHED })"
elif [ "$pushed_seen" != 0 ]; then
  fail "the checker sees $pushed_seen spheres moved that were not targets (no PUSHED line)"
fi
if [ "${SCENE_KEPT_ANY:-0}" != 1 ]; then
  [ "$ckept" = "$kept" ] || fail "the checker sees $ckept targets left on a bar, the fix reports $kept kept"
  echo "PASS: targets moved = relocated ($moved), left on a bar = kept ($kept)"
else
  echo "PASS: targets moved = relocated ($moved); $ckept matrix spheres left on a bar, $kept of them kept targets"
fi
# unplaced keep: how far relocated spheres overlap the kept targets (the
# checker allows it with --kept-ok, and reports it), against the fix's
# f_ID[11] when the input prints it (KEPT_OVERLAP line, -var f11 1).
if [ "$kept" -gt 0 ]; then
  kov=$(awk '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == "max_overlap_kept") print $(i + 1)}' "$work/check")
  echo "kept targets: the largest overlap of a relocated sphere with one is ${kov:-?} rmin (written)"
  f11=$(last KEPT_OVERLAP "$log")
  if [ -n "$f11" ]; then
    awk -v w="$kov" -v f="${f11#KEPT_OVERLAP }" 'BEGIN {exit !(w != "" && w + 0 <= 1.01 * f + 1e-12)}' ||
      fail "f_ID[11] = ${f11#KEPT_OVERLAP } rmin, relocated spheres written overlap kept targets by $kov rmin"
    echo "PASS: f_ID[11] = ${f11#KEPT_OVERLAP } >= the largest overlap of a relocated sphere with a kept target written ($kov)"
  fi
fi

# The fix's reported volumes and residual overlap against the dumps, and the
# mass of each moved sphere (scaled with its volume: same density).
stats=$(last STATS "$log")
# The fix states its rmin (the unit of f_ID[7]) at the end of its summary line.
fix_rmin=$(grep '^fix reinforce/invert: [0-9]' "$log" | tail -1 | sed -nE 's/.*\(rmin ([^)]*)\)$/\1/p')
awk -v stats="$stats" -v kept="$kept" -v fix_rmin="${fix_rmin:-0}" -v check="$(grep '^SUMMARY' "$work/check")" '
  function vol(r) { return 4.188790204786391 * r * r * r }    # 4 pi / 3 r^3
  function rel(a, b,   d, m) { d = a - b; if (d < 0) d = -d; m = (a < 0 ? -a : a); if ((b < 0 ? -b : b) > m) m = (b < 0 ? -b : b); return m > 0 ? d / m : 0 }
  FNR == 1 { file++ }
  /^ITEM: ATOMS/ { delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next }
  /^ITEM:/ { body = 0; next }
  !body { next }
  file == 1 { id = $c["id"]; type[id] = $c["type"]; r[id] = $c["radius"]; m[id] = ("mass" in c) ? $c["mass"] : ""
              key[id] = $c["x"] " " $c["y"] " " $c["z"] " " $c["radius"]; next }
  {
    id = $c["id"]; seen[id] = 1
    if ($c["x"] " " $c["y"] " " $c["z"] " " $c["radius"] == key[id]) next
    moved++
    if (("mass" in c) && m[id] != "") {
      e = rel($c["mass"] / vol($c["radius"]), m[id] / vol(r[id]))
      if (e > 1e-12) { bad_mass++; if (bad_mass <= 3) print "atom " id ": density " m[id] / vol(r[id]) " -> " $c["mass"] / vol($c["radius"]) }
      masses++
    }
  }
  END {
    n = split(check, w, " ")
    for (i = 1; i < n; i++) {
      if (w[i] == "volume_targets_before") v5 = w[i + 1]
      if (w[i] == "volume_relocated_after") v6 = w[i + 1]
    }
    fail = 0
    if (bad_mass) { print "FAIL: " bad_mass " moved spheres changed their density (mass not scaled with the volume)"; fail = 1 }
    else if (masses) print "PASS: " masses " moved spheres kept their density"
    if (split(stats, f, " ") >= 8) {
      if (rel(f[7], v6) > 1e-9) { print "FAIL: f_ID[6] = " f[7] ", the relocated spheres written hold " v6; fail = 1 }
      else if (kept == 0 && rel(f[6], v5) > 1e-9) { print "FAIL: f_ID[5] = " f[6] ", the targets (moved or deleted) held " v5; fail = 1 }
      else print "PASS: f_ID[5], f_ID[6] = the volumes of the dumps" (kept == 0 ? "" : " (f_ID[6] only: targets kept)")
      for (i = 1; i < n; i++) {
        if (w[i] == "max_overlap_moved") written = w[i + 1]
        if (w[i] == "rmin") { checker_rmin = w[i + 1]; sub(/\)$/, "", checker_rmin) }
      }
      # Both in the fix'"'"'s unit (its rmin may differ from the checker'"'"'s).
      if (written != "" && fix_rmin + 0 > 0 && checker_rmin + 0 > 0) written = written * checker_rmin / fix_rmin
      if (kept == 0 && written != "") {
        # f_ID[7] is honest: no moved sphere written overlaps more than it says
        # (1% for the checker'"'"'s 3 digits and an rmin of the checker'"'"'s).
        if (written + 0 > 1.01 * f[8] + 1e-12) { print "FAIL: f_ID[7] = " f[8] " rmin, the written spheres overlap by " written " rmin"; fail = 1 }
        else print "PASS: f_ID[7] = " f[8] " >= the largest overlap written (" written ")"
      }
    }
    exit fail
  }' "$work/a/before.dump" "$work/a/after.dump" || exit 1

dumped=$(awk '/^ITEM: NUMBER OF ATOMS/ {getline; n = $1} END {print n}' "$work/a/after.dump")
atoms=$(last ATOMS "$log")
if [ -n "$atoms" ]; then
  [ "${atoms#ATOMS }" = "$dumped" ] || fail "LAMMPS counts ${atoms#ATOMS } atoms, after.dump holds $dumped"
  echo "PASS: atom count $dumped"
fi
once=$(last ONCE "$log")
if [ -n "$once" ]; then
  [ "${once#ONCE }" = "${totals#TOTALS }" ] || fail "a second run changed the totals: $once"
fi
again=$(last AGAIN "$log")
if [ -n "$again" ]; then
  read -r _ t2 r2 d2 k2 atoms2 <<<"$again"
  [ "$summaries" -eq 2 ] || fail "$summaries summary lines, expected 2 (one per fix, N = 0)"
  [ "$t2" -eq "$kept" ] || fail "a fresh fix finds $t2 targets, expected the $kept kept ones"
  [ "$t2" -eq $((r2 + d2 + k2)) ] || fail "fresh fix: targets != relocated + deleted + kept"
  echo "PASS: once per fix; a fresh fix finds $t2 targets (= kept), then $atoms2 atoms"
fi
awk -v tol=1e-9 '
  /^ITEM: BOX BOUNDS/ { for (k = 1; k <= 3; k++) { getline; len[k] = $2 - $1 }; next }
  /^ITEM: ATOMS/ { ncol = 0; delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next }
  /^ITEM:/ { body = 0; next }
  !body { next }
  FNR == NR { bx[$c["id"]] = $c["x"]; by[$c["id"]] = $c["y"]; bz[$c["id"]] = $c["z"]; next }
  !("c_disp[4]" in c) { exit }
  {
    has = 1; id = $c["id"]; d[1] = $c["x"] - bx[id]; d[2] = $c["y"] - by[id]; d[3] = $c["z"] - bz[id]
    s = 0
    for (k = 1; k <= 3; k++) {
      while (d[k] > len[k] / 2) d[k] -= len[k]    # a periodic wrap is no move
      while (d[k] < -len[k] / 2) d[k] += len[k]
      s += d[k] * d[k]
    }
    e = sqrt(s) - $c["c_disp[4]"]; if (e < 0) e = -e
    if (e > tol * (len[1] + len[2] + len[3])) { bad++; if (bad <= 3) print "atom " id ": moved " sqrt(s) ", displace/atom says " $c["c_disp[4]"] }
  }
  END {
    if (bad) { print "FAIL: displace/atom disagrees with the dumps for " bad " atoms"; exit 1 }
    if (has) print "PASS: displace/atom agrees with the dumps (per-atom data followed the atoms)"
  }' "$work/a/before.dump" "$work/a/after.dump" || exit 1
reference=() reference_log=()
if [ -n "${SCENE_POST:-}${SCENE_LOG_POST:-}" ] && [ "${SCENE_REFERENCE:-0}" = 1 ]; then
  ref_args=(-var procs "1 1 1")    # the same input on one process (the first -var of a name wins)
  [ -n "${SCENE_REFERENCE_SETUP:-}" ] && ref_args+=(-var setup "$SCENE_REFERENCE_SETUP")
  [ -n "${SCENE_REFERENCE_EXTRA+set}" ] && ref_args+=(-var extra "$SCENE_REFERENCE_EXTRA")
  input=${SCENE_REFERENCE_INPUT:-$input} run "$work/ref" 1 "${ref_args[@]}"
  reference=("$work/ref/after.dump") reference_log=("$work/ref/log")
fi
if [ -n "${SCENE_POST:-}" ]; then
  # shellcheck disable=SC2086    # a command and its arguments
  ${SCENE_POST} "$work/a/before.dump" "$work/a/after.dump" "${reference[@]}" || fail "$SCENE_POST"
fi
if [ -n "${SCENE_LOG_POST:-}" ]; then
  # shellcheck disable=SC2086    # a command and its arguments
  ${SCENE_LOG_POST} "$log" "${reference_log[@]}" || fail "$SCENE_LOG_POST"
fi

if [ "${SCENE_TWICE:-0}" = 1 ]; then
  run "$work/b"
  "$checker" --same "$work/a/after.dump" "$work/b/after.dump" || fail "the two runs differ"
  for word in TOTALS STATS; do
    [ "$(last $word "$log")" = "$(last $word "$work/b/log")" ] || fail "the two runs report different $word"
  done
  echo "PASS: the same run twice: the same atoms, totals and figures"
fi
echo "PASS $name np=$np"
