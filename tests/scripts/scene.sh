#!/usr/bin/env bash
# One scene test, for either host: make the scene with make_scene, then
# run_scene.sh on it (checks on the written result, the same output twice).
#   scene.sh lammps|liggghts INPUT NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- HOST_VARS -- CHECK_ARGS
# SCENE_INPUT, when set, replaces INPUT.
set -euo pipefail
host=$1 input=${SCENE_INPUT:-$2} name=$3 np=$4 build=$5
shift 5
[ "$1" = "--" ] && shift
make=()
while [ "$1" != "--" ]; do make+=("$1"); shift; done
shift
case $host in
  lammps) exe="$build/src/lammps/lmp_reinforce" ;;
  liggghts) exe="$build/src/liggghts/liggghts_reinforce" ;;
  *) echo "scene.sh: unknown host $host"; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
data=$(mktemp "${TMPDIR:-/tmp}/${host}_${name}.XXXXXX.data")
trap 'rm -f "$data"' EXIT
"$build/tests/make_scene" "$data" "${make[@]}"
"$here/run_scene.sh" "$name" "$exe" "$np" "$input" "$build/tests/check_scene" -- -var data "$data" "$@"
