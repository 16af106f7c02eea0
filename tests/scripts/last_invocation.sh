#!/usr/bin/env bash
# Every pair at the last invocation of an N > 0 test: the checker on the
# scene the invocation started from (BEFORE, dumped just before it, with
# nothing else moving in between) and the scene after it (AFTER): no moved
# sphere overlaps anything (matrix or rebar), no matrix sphere overlaps a
# bar, radii in range, walls, density, rebar untouched, atoms before = after
# + the deletions the fix reported; and the targets the checker sees moved
# are the ones the fix reports relocated (at least one: the check is not
# vacuous). Spheres pushed to make room are checked like any moved sphere.
#   last_invocation.sh CHECKER BEFORE AFTER "SUMMARY LINE" [checker args]
# SUMMARY LINE: the fix's log line of that invocation,
#   fix reinforce/invert: T targets, R relocated, D deleted (...), K kept, ...
set -euo pipefail
checker=$1 before=$2 after=$3 line=$4
shift 4
read -r targets relocated deleted kept < <(awk '{
    for (i = 2; i <= NF; i++) {
      w = $i; sub(/,$/, "", w)
      if (w == "targets") t = $(i - 1); if (w == "relocated") r = $(i - 1)
      if (w == "deleted") d = $(i - 1); if (w == "kept") k = $(i - 1)
    }
    print t, r, d, k }' <<<"$line")
echo "last invocation: $targets targets, $relocated relocated, $deleted deleted, $kept kept"
[ "$relocated" -gt 0 ] || { echo "FAIL: nothing relocated at the last invocation: the check would test nothing"; exit 1; }
out=$("$checker" --before "$before" --after "$after" --deleted "$deleted" "$@") ||
  { echo "$out"; echo "FAIL: the checker failed at the last invocation (above)"; exit 1; }
echo "$out" | grep -E '^(PASS|FAIL|SUMMARY)'
field() { awk -v k="$1" '/^SUMMARY/ {for (i = 1; i < NF; i++) if ($i == k) print $(i + 1)}' <<<"$out"; }
# Targets moved (a checker that tells targets from spheres pushed to make
# room prints moved_targets; otherwise every moved sphere is a target).
moved=$(field moved_targets)
[ -n "$moved" ] || moved=$(field moved)
[ "$moved" = "$relocated" ] ||
  { echo "FAIL: the checker sees $moved targets moved at the last invocation, the fix reports $relocated"; exit 1; }
grep -q '^PASS: moved spheres kept their density' <<<"$out" ||
  { echo "FAIL: the dumps have no mass column: density not checked"; exit 1; }
echo "PASS: every pair at the last invocation ($moved moved, $deleted deleted)"
