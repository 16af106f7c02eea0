#!/usr/bin/env bash
# The N > 0 test: four invocations (setup, steps 20, 40, 60), the second bar's
# targets relocated by a periodic invocation at step 40, the third bar's at
# step 60, no matrix sphere left on a bar, and every pair checked at the last
# invocation (last_invocation.sh: the checker on the dumps of steps 59 and 60).
#   every_test.sh BUILD_DIR NPROCS
set -euo pipefail
build=$1 np=$2
here=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "every"
"$build/tests/make_scene" "$work/scene.data" --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
  --bar 0.01 0.07 0.1 0.39 0.07 0.1 0.005 0.0075
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()    # serial: the executable itself
(cd "$here/lammps" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.every \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none)
grep '^fix reinforce/invert: [0-9]' "$work/log"
invocations=$(grep -c '^fix reinforce/invert: [0-9]' "$work/log")
[ "$invocations" -eq 4 ] || { echo "FAIL: $invocations invocations, expected 4"; exit 1; }
# The summary line: "fix reinforce/invert: T targets, R relocated, D deleted ...".
later=$(grep '^fix reinforce/invert: [0-9]' "$work/log" | sed -n 3p | sed -nE 's/^fix reinforce\/invert: [0-9]+ targets, ([0-9]+) relocated, .*/\1/p')
echo "relocated at step 40: ${later:-?}"
[ "${later:-0}" -gt 0 ] || { echo "FAIL: the second bar's targets were not relocated at step 40"; exit 1; }
last=$(grep '^fix reinforce/invert: [0-9]' "$work/log" | sed -n 4p)
"$here/scripts/last_invocation.sh" "$build/tests/check_scene" "$work/before_last.dump" "$work/after.dump" \
  "$last" --rmin 0.004 --rmax 0.008 || exit 1
read -r _ _ _ _ _ matrix_rebar _ _ < <("$build/tests/check_scene" --stats "$work/after.dump" --rmin 0.004)
echo "largest matrix-bar overlap at the end: $matrix_rebar rmin"
awk -v o="$matrix_rebar" 'BEGIN {exit !(o <= 1e-6)}' || { echo "FAIL: a matrix sphere overlaps a bar"; exit 1; }
echo "PASS: relocation every N steps"
