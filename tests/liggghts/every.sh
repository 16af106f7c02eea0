#!/usr/bin/env bash
# N > 0 in LIGGGHTS: four invocations (setup, steps 20, 40, 60; the setup of
# the last run 0 is not one), the second bar's targets relocated by the
# periodic invocation at step 40, the third bar's at step 60, no matrix
# sphere left on a bar, and every pair checked at the last invocation
# (../scripts/last_invocation.sh: the checker on the dumps of steps 59, 60).
#   every.sh BUILD_DIR NPROCS
set -euo pipefail
build=$1 np=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_every"
"$here/../scripts/every_scene.sh" "$build" "$work/scene.data"
(cd "$here" && mpirun -np "$np" "$build/src/liggghts/liggghts_reinforce" -in in.every \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none) ||
  { echo "FAIL: liggghts_reinforce exited non-zero"; tail -5 "$work/log"; exit 1; }
grep -q '^EVERY done' "$work/log" || { echo "FAIL: the input did not finish"; exit 1; }
"$here/../scripts/every_checks.sh" "$build" "$work"
