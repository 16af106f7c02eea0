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
"$here/scripts/every_scene.sh" "$build" "$work/scene.data"
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()    # serial: the executable itself
(cd "$here/lammps" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.every \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none)
"$here/scripts/every_checks.sh" "$build" "$work"
