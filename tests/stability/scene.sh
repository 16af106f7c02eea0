#!/usr/bin/env bash
# One scene: make it with make_scene, then run_scene.sh on it.
#   scene.sh NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- HOST_VARS -- CHECK_ARGS
# SCENE_HOST=liggghts runs liggghts_reinforce on liggghts/in.scene instead of
# lmp_reinforce on stability/in.scene.
set -euo pipefail
name=$1 np=$2 build=$3
shift 3
[ "$1" = "--" ] && shift
make=()
while [ "$1" != "--" ]; do make+=("$1"); shift; done
shift
here=$(cd "$(dirname "$0")" && pwd)
data=$(mktemp "${TMPDIR:-/tmp}/stability_${name}.XXXXXX.data")
trap 'rm -f "$data"' EXIT
"$build/tests/make_scene" "$data" "${make[@]}"
if [ "${SCENE_HOST:-lammps}" = liggghts ]; then
  exe="$build/src/liggghts/liggghts_reinforce" input="$here/../liggghts/in.scene"
else
  exe="$build/src/lammps/lmp_reinforce" input="$here/in.scene"
fi
"$here/../scripts/run_scene.sh" "$name" "$exe" "$np" "$input" \
  "$build/tests/check_scene" -- -var data "$data" "$@"
