#!/usr/bin/env bash
# One LIGGGHTS scene test: make the scene with make_scene, then run
# liggghts_reinforce on tests/liggghts/in.scene through run_scene.sh (checks
# on the written result, and the same output twice).
#   scene.sh NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- LIGGGHTS_VARS -- CHECK_SCENE_ARGS
set -euo pipefail
name=$1 np=$2 build=$3
shift 3
[ "$1" = "--" ] && shift
make=()
while [ "$1" != "--" ]; do make+=("$1"); shift; done
shift
here=$(cd "$(dirname "$0")" && pwd)
data=$(mktemp "${TMPDIR:-/tmp}/liggghts_${name}.XXXXXX.data")
trap 'rm -f "$data"' EXIT
"$build/tests/make_scene" "$data" "${make[@]}"
"$here/../scripts/run_scene.sh" "$name" "$build/src/liggghts/liggghts_reinforce" "$np" \
  "$here/in.scene" "$build/tests/check_scene" -- -var data "$data" "$@"
