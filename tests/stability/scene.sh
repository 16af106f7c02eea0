#!/usr/bin/env bash
# One stability scene: make it with make_scene, then run_scene.sh on it.
#   scene.sh NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- LAMMPS_VARS -- CHECK_ARGS
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
"$here/../scripts/run_scene.sh" "$name" "$build/src/lammps/lmp_reinforce" "$np" "$here/in.scene" \
  "$build/tests/check_scene" -- -var data "$data" "$@"
