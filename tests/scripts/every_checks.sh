#!/usr/bin/env bash
# The checks of the N > 0 tests of both hosts (every_test.sh,
# ../liggghts/every.sh), on what their run wrote: four invocations (setup,
# steps 20, 40, 60), targets at the first, the second bar's targets
# relocated at step 40, every pair checked at the last invocation
# (last_invocation.sh: the checker on the dumps of steps 59 and 60), and no
# matrix sphere left on a bar.
#   every_checks.sh BUILD_DIR WORK     (WORK holds log, before_last.dump, after.dump)
set -euo pipefail
build=$1 work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
summaries() { grep '^fix reinforce/invert: [0-9]' "$work/log"; }
summaries
invocations=$(summaries | wc -l)
[ "$invocations" -eq 4 ] || { echo "FAIL: $invocations invocations, expected 4"; exit 1; }
first=$(summaries | sed -n 1p | awk '{print $3}')
[ "$first" -gt 0 ] || { echo "FAIL: no targets at the first invocation"; exit 1; }
# The summary line: "fix reinforce/invert: T targets, R relocated, D deleted ...".
later=$(summaries | sed -n 3p | sed -nE 's/^fix reinforce\/invert: [0-9]+ targets, ([0-9]+) relocated, .*/\1/p')
echo "relocated at step 40: ${later:-?}"
[ "${later:-0}" -gt 0 ] || { echo "FAIL: the second bar's targets were not relocated at step 40"; exit 1; }
"$here/last_invocation.sh" "$build/tests/check_scene" "$work/before_last.dump" "$work/after.dump" \
  "$(summaries | sed -n 4p)" --rmin 0.004 --rmax 0.008 || exit 1
read -r _ _ _ _ _ matrix_rebar _ _ < <("$build/tests/check_scene" --stats "$work/after.dump" --rmin 0.004)
echo "largest matrix-bar overlap at the end: $matrix_rebar rmin"
awk -v o="$matrix_rebar" 'BEGIN {exit !(o <= 1e-6)}' || { echo "FAIL: a matrix sphere overlaps a bar"; exit 1; }
echo "PASS: relocation every N steps"
