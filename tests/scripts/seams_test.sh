#!/usr/bin/env bash
# The seam test: the dense beam (tests/lammps/in.seams) on 4 processes
# (grid 4 x 1 x 1: seams at x = 0.125, 0.25, 0.375 across all five bars) and
# on one; both results must pass the checker, and the 4-process one must
# show no more deletions near the seams than elsewhere, nor than the
# 1-process run on the same targets (seam_share.sh).
#   seams_test.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "seams"
for np in 1 4; do
  mkdir -p "$work/np$np"
  procs="4 1 1"
  [ "$np" -eq 1 ] && procs="1 1 1"
  launch=(mpirun -np "$np")
  [ "$np" -eq 1 ] && launch=()    # serial: the executable itself
  (cd "$here/../lammps" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.seams \
     -var out "$work/np$np" -var procs "$procs" -log "$work/np$np/log" -screen none) \
    || { echo "FAIL: lmp_reinforce exited non-zero"; tail -5 "$work/np$np/log"; exit 1; }
  read -r _ targets relocated deleted kept < <(grep '^TOTALS' "$work/np$np/log")
  echo "np=$np: targets $targets relocated $relocated deleted $deleted kept $kept"
  "$build/tests/check_scene" --before "$work/np$np/before.dump" --after "$work/np$np/after.dump" \
    --deleted "$deleted" --rmin 0.0025 --rmax 0.0075 --overlap-ok-before | grep -E '^(PASS|FAIL|SUMMARY)' \
    || { echo "FAIL: check_scene"; exit 1; }
done
SEAM_BOTH=1 "$here/seam_share.sh" 0.0075 "x=0.125,0.25,0.375" "$work/np4/before.dump" "$work/np4/after.dump" \
  "$work/np1/after.dump"
