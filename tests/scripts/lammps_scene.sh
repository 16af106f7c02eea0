#!/usr/bin/env bash
# One LAMMPS scene test: make the scene with make_scene, then run_scene.sh
# with tests/lammps/in.scene (or the input given by SCENE_INPUT).
#   lammps_scene.sh NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- LMP_VARS -- CHECK_ARGS
set -euo pipefail
name=$1 np=$2 build=$3
shift 3
[ "$1" = "--" ] && shift
make=()
while [ "$1" != "--" ]; do make+=("$1"); shift; done
shift
here=$(cd "$(dirname "$0")" && pwd)
data=$(mktemp "${TMPDIR:-/tmp}/lammps_${name}.XXXXXX.data")
trap 'rm -f "$data"' EXIT
"$build/tests/make_scene" "$data" "${make[@]}"
"$here/run_scene.sh" "$name" "$build/src/lammps/lmp_reinforce" "$np" \
  "${SCENE_INPUT:-$here/../lammps/in.scene}" "$build/tests/check_scene" -- -var data "$data" "$@"
