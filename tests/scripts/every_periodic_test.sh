#!/usr/bin/env bash
# N > 0 across seams and the periodic boundary (tests/lammps/in.every_periodic):
# four invocations; deletions during the run as well as at its setup; the
# atom count LAMMPS keeps = start - every deletion the fix reported + the 40
# spheres of the second bar = the atoms written; no matrix sphere left on a
# bar after the last invocation, and every pair checked at it
# (last_invocation.sh: the checker on the dumps of steps 59 and 60).
#   every_periodic_test.sh BUILD_DIR NPROCS
set -euo pipefail
build=$1 np=$2
here=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "every_periodic"
fail() { echo "FAIL: $*"; exit 1; }
"$build/tests/make_scene" "$work/scene.data" --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
  --bar 0 0.07 0.1 0.3925 0.07 0.1 0.005 0.0075
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()    # serial: the executable itself
(cd "$here/lammps" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.every_periodic \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none) \
  || { tail -5 "$work/log"; fail "lmp_reinforce exited non-zero"; }
grep '^fix reinforce/invert: [0-9]' "$work/log" >"$work/lines" || true
cat "$work/lines"
[ "$(wc -l <"$work/lines")" -eq 4 ] || fail "$(wc -l <"$work/lines") invocations, expected 4"
read -r _ start < <(grep '^START' "$work/log")
read -r _ end < <(grep '^END' "$work/log")
deleted=$(awk '{s += $7} END {print s}' "$work/lines")
later=$(awk 'NR > 1 {s += $7} END {print s + 0}' "$work/lines")
# The summary line: "fix reinforce/invert: T targets, R relocated, D deleted ...".
bar_relocated=$(sed -n 3p "$work/lines" | sed -nE 's/^fix reinforce\/invert: [0-9]+ targets, ([0-9]+) relocated, .*/\1/p')
dumped=$(awk '/^ITEM: NUMBER OF ATOMS/ {getline; print $1}' "$work/after.dump")
echo "atoms: start $start, deleted $deleted ($later during the runs), +40 bar spheres, end $end, written $dumped"
[ "$later" -gt 0 ] || fail "no deletion during the runs: the scene does not test it"
[ "${bar_relocated:-0}" -gt 0 ] || fail "the second bar's targets were not relocated at step 40 (${bar_relocated:-no} relocated)"
[ "$end" -eq $((start - deleted + 40)) ] || fail "atom count $end, expected $((start - deleted + 40))"
[ "$dumped" -eq "$end" ] || fail "$dumped atoms written, LAMMPS counts $end"
read -r _ _ _ _ _ matrix_rebar _ _ < <("$build/tests/check_scene" --stats "$work/after.dump" --rmin 0.004)
echo "largest matrix-bar overlap after the last invocation: $matrix_rebar rmin"
awk -v o="$matrix_rebar" 'BEGIN {exit !(o <= 1e-6)}' || fail "a matrix sphere overlaps a bar"
"$here/scripts/last_invocation.sh" "$build/tests/check_scene" "$work/before_last.dump" "$work/after.dump" \
  "$(sed -n 4p "$work/lines")" --rmin 0.004 --rmax 0.008 || exit 1
echo "PASS: relocation every N steps across seams and the periodic boundary"
