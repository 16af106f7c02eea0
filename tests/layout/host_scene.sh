#!/usr/bin/env bash
# The fix on a packing around reinforcement laid out by reinforce_layout
# (scene.layout: a cage with hooks, a mesh, fibres apart), through
# run_scene.sh: the checker on the written result (no overlap, rebar
# untouched, atoms conserved), the counts against the fix's; with
# SCENE_REFERENCE=1 and SCENE_POST (same_atoms.sh) the
# same scene as on one process.
#   host_scene.sh lammps|liggghts NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- HOST_VARS -- CHECK_ARGS
# LAMMPS adds the bars as a user would (read_data FILE add append offset 1
# 0 0 0 0 group rebar); LIGGGHTS 3.8 has no read_data add: the bars are
# appended to the data file (merge_data.py), as type 2.
set -euo pipefail
host=$1 name=$2 np=$3 build=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../scripts/test_env.sh" "layout_${name}"
split_lists "$@"
"$build/src/layout/reinforce_layout" "$here/scene.layout" --data "$work/bars.data"
"$build/tests/make_scene" "$work/matrix.data" "${list_a[@]}"
case $host in
  lammps)
    exe=$build/src/lammps/lmp_reinforce
    "$here/../scripts/run_scene.sh" "$name" "$exe" "$np" "$here/../lammps/in.scene" "$build/tests/check_scene" -- \
      -var data "$work/matrix.data" -var setup "read_data $work/bars.data add append offset 1 0 0 0 0 group rebar" \
      "${list_b[@]}" -- "${list_c[@]}" ;;
  liggghts)
    exe=$build/src/liggghts/liggghts_reinforce
    "$here/merge_data.py" "$work/matrix.data" "$work/bars.data" 1 "$work/scene.data"
    "$here/../scripts/run_scene.sh" "$name" "$exe" "$np" "$here/../liggghts/in.scene" "$build/tests/check_scene" -- \
      -var data "$work/scene.data" "${list_b[@]}" -- "${list_c[@]}" ;;
  *) echo "FAIL: unknown host $host"; exit 2 ;;
esac
