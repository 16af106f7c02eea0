#!/usr/bin/env bash
# A set-up the fix may refuse or must get right (e.g. ghost atoms only of
# one group: neighbours the fix cannot see). Runs tests/lammps/in.scene on a
# make_scene scene once; passes when LAMMPS stops with exactly one ERROR
# line whose message is exactly REFUSAL (the whole line but for "ERROR: "
# and the source location "(file:line)", as expect_error.sh with
# EXPECT_EXACT=1) and writes no after.dump, or when it runs and the checker
# passes on what it wrote. A run that completes with a wrong result fails,
# and so does a stop by any other ERROR.
#   refused_or_right.sh NAME NP BUILD_DIR REFUSAL -- MAKE_SCENE_ARGS -- LMP_VARS -- CHECK_ARGS
set -uo pipefail
name=$1 np=$2 build=$3 refusal=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "refused_${name}"
split_lists "${@:5}"    # list_a: make_scene, list_b: host -var, list_c: check_scene
"$build/tests/make_scene" "$work/scene.data" "${list_a[@]}" || exit 2
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
(cd "$here/../lammps" && timeout 120 "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.scene \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none "${list_b[@]}") >"$work/stdout" 2>&1
status=$?
grep '^fix reinforce/invert: [0-9]' "$work/log" | head -1
if [ "$status" -ne 0 ]; then
  read_errors "$work/log"
  echo "exit $status: $line"
  [ "$status" -ne 124 ] || { echo "FAIL: $name np=$np: the run hung"; exit 1; }
  [ "$errors" -eq 1 ] || { echo "FAIL: $name np=$np: $errors ERROR lines"; exit 1; }
  [ "$message" = "$refusal" ] ||
    { echo "FAIL: $name np=$np: the ERROR message is not exactly: $refusal"; exit 1; }
  [ ! -s "$work/after.dump" ] || ! grep -q '^ITEM:' "$work/after.dump" \
    || { echo "FAIL: $name np=$np: refused after writing a result"; exit 1; }
  echo "PASS $name np=$np: refused"
  exit 0
fi
deleted=$(awk '/^TOTALS/ {print $4}' "$work/log" | tail -1)
"$build/tests/check_scene" --before "$work/before.dump" --after "$work/after.dump" --deleted "${deleted:-0}" "${list_c[@]}" \
  || { echo "FAIL: $name np=$np: the fix ran and wrote a wrong result"; exit 1; }
echo "PASS $name np=$np: right"
