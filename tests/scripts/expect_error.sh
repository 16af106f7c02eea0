#!/usr/bin/env bash
# Runs an input that must stop with one ERROR line containing a given text
# (an extended regular expression), having written nothing: no
# $out/written.dump or $out/written.data (written after the runs), and no
# snapshot in $out/halfway.dump (a dump the input may define before the
# fix). Also: a non-zero exit status, within 120 s (no hang).
#   expect_error.sh EXE NPROCS INPUT 'expected text' [lmp -var args...]
# The expected text is an extended regular expression the ERROR line must
# contain; with EXPECT_EXACT=1 it is the literal message, which must be the
# whole line but for "ERROR: " and the source location "(file:line)".
set -uo pipefail
exe=$1 np=$2 input=$3 expected=$4
shift 4
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "expect_error"
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()    # serial: the executable itself (no mpirun start-up)
(cd "$(dirname "$input")" && timeout 120 "${launch[@]}" "$exe" -in "$input" -log "$work/log" \
   -screen none -var out "$work" "$@") >"$work/stdout" 2>&1
status=$?
if [ ! -e "$work/log" ]; then
  # The host never started (mpirun or MPI_Init failed): its stdout and
  # stderr say why (test_env.sh prints them on the way out).
  echo "FAIL: exit $status before the host wrote its log: the run did not start"
  exit 1
fi
read_errors "$work/log"
echo "exit $status: $line"
fail=0
[ "$status" -ne 0 ] || { echo "FAIL: the run did not stop"; fail=1; }
[ "$status" -ne 124 ] || { echo "FAIL: the run hung"; fail=1; }
[ "$errors" -eq 1 ] || { echo "FAIL: $errors ERROR lines, expected one"; fail=1; }
if [ "${EXPECT_EXACT:-0}" = 1 ]; then
  [ "$message" = "$expected" ] || { echo "FAIL: the ERROR message is not exactly: $expected"; fail=1; }
else
  grep -Eq -- "$expected" <<<"$line" || { echo "FAIL: ERROR line does not say: $expected"; fail=1; }
fi
for f in written.dump written.data; do
  [ ! -e "$work/$f" ] || { echo "FAIL: $f was written"; fail=1; }
done
if [ -e "$work/halfway.dump" ] && grep -q '^ITEM:' "$work/halfway.dump"; then
  echo "FAIL: the dump defined before the fix wrote a snapshot"; fail=1
fi
[ "$fail" -eq 0 ] && echo "PASS: $expected"
exit "$fail"
