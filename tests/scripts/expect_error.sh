#!/usr/bin/env bash
# Runs an input that must stop with one ERROR line containing a given text
# (an extended regular expression), having written nothing.
#   expect_error.sh EXE NPROCS INPUT 'expected text' [lmp -var args...]
set -uo pipefail
exe=$1 np=$2 input=$3 expected=$4
shift 4
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/expect_error.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$(dirname "$input")" && timeout 120 mpirun -np "$np" "$exe" -in "$input" -log "$work/log" \
   -screen none -var out "$work" "$@") >"$work/stdout" 2>&1
status=$?
errors=$(grep -c '^ERROR' "$work/log" || true)
line=$(grep '^ERROR' "$work/log" | head -1)
echo "exit $status: $line"
fail=0
[ "$status" -ne 0 ] || { echo "FAIL: the run did not stop"; fail=1; }
[ "$status" -ne 124 ] || { echo "FAIL: the run hung"; fail=1; }
[ "$errors" -eq 1 ] || { echo "FAIL: $errors ERROR lines, expected one"; fail=1; }
grep -Eq -- "$expected" <<<"$line" || { echo "FAIL: ERROR line does not say: $expected"; fail=1; }
[ ! -e "$work/written.dump" ] || { echo "FAIL: output was written"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: $expected"
exit "$fail"
