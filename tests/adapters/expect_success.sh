#!/usr/bin/env bash
# Runs an input that must finish: exit status 0, no ERROR line, the data file
# written at its end ($out/written.data), within 120 s; and the fix must have
# run: its summary line ("fix reinforce/invert: T targets, R relocated, ...")
# appears exactly EXPECT_INVOCATIONS times (default 1), each with T > 0. So
# a finished fix that never stops a later run is tested on a fix that did
# its work once, not on one that never ran.
#   expect_success.sh EXE NPROCS INPUT [-var args...]
set -uo pipefail
exe=$1 np=$2 input=$3
shift 3
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "expect_success"
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
(cd "$(dirname "$input")" && timeout 120 "${launch[@]}" "$exe" -in "$input" -log "$work/log" \
   -screen none -var out "$work" "$@") >"$work/stdout" 2>&1
status=$?
grep -E '^(ERROR|fix reinforce/invert: [0-9])' "$work/log" || true
fail=0
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; tail -3 "$work/stdout"; fail=1; }
! grep -q '^ERROR' "$work/log" || { echo "FAIL: an ERROR line"; fail=1; }
[ -s "$work/written.data" ] || { echo "FAIL: the input did not reach its end (no written.data)"; fail=1; }
want=${EXPECT_INVOCATIONS:-1}
lines=$(grep -c '^fix reinforce/invert: [0-9]' "$work/log" || true)
[ "$lines" -eq "$want" ] ||
  { echo "FAIL: $lines summary lines of the fix, expected $want (one per invocation)"; fail=1; }
empty=$(grep '^fix reinforce/invert: [0-9]' "$work/log" |
        awk '{n++} $4 != "targets," || $3 + 0 <= 0 {bad++} END {print bad + 0}')
[ "$empty" -eq 0 ] || { echo "FAIL: $empty invocations of the fix had no target (or no 'T targets,')"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: the input ran to its end, the fix invoked $want time(s) with targets"
exit "$fail"
