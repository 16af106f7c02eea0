#!/usr/bin/env bash
# A communication set-up under which the fix could miss ghost neighbours
# (communicate multi, communicate group): the run must either stop with one
# ERROR line whose message is exactly REFUSAL (the whole line but for
# "ERROR: " and the source location "(file:line)"), or write a correct
# result (check_scene). Never a silent overlap, nor a stop by another ERROR.
#   refused_or_right.sh NAME NP BUILD_DIR REFUSAL -- MAKE_SCENE_ARGS -- LIGGGHTS_VARS -- CHECK_SCENE_ARGS
set -uo pipefail
name=$1 np=$2 build=$3 refusal=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_${name}"
split_lists "${@:5}"    # list_a: make_scene, list_b: host -var, list_c: check_scene
"$build/tests/make_scene" "$work/scene.data" "${list_a[@]}" || { echo "FAIL: make_scene"; exit 1; }
(cd "$here" && timeout 120 mpirun -np "$np" "$build/src/liggghts/liggghts_reinforce" -in in.scene \
   -var data "$work/scene.data" -var out "$work" -log "$work/log" -screen none "${list_b[@]}") \
  >"$work/stdout" 2>&1
status=$?
[ "$status" -ne 124 ] || { echo "FAIL: the run hung"; exit 1; }
if [ "$status" -ne 0 ]; then
  read_errors "$work/log"
  echo "exit $status: $line"
  [ "$errors" -eq 1 ] || { echo "FAIL: $errors ERROR lines, expected one"; exit 1; }
  [ "$message" = "$refusal" ] || { echo "FAIL: the ERROR message is not exactly: $refusal"; exit 1; }
  echo "PASS $name np=$np: refused"
  exit 0
fi
grep '^fix reinforce/invert: [0-9]' "$work/log"
"$build/tests/check_scene" --before "$work/before.dump" --after "$work/after.dump" "${list_c[@]}" ||
  { echo "FAIL: $name np=$np: the fix ran and wrote a wrong result"; exit 1; }
echo "PASS $name np=$np: relocated correctly"
