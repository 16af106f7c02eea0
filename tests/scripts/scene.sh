#!/usr/bin/env bash
# One scene test, for either host: make the scene with make_scene, then
# run_scene.sh on it (checks on the written result; the same output twice with SCENE_TWICE=1).
#   scene.sh lammps|liggghts INPUT NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- HOST_VARS -- CHECK_ARGS
# SCENE_INPUT, when set, replaces INPUT. SCENE_DENSITY_SPREAD=1 gives each
# matrix sphere its own density (1500 + 50 (id mod 23) kg/m^3) in the data
# file, so that a relocation which recomputed masses from anything but the
# sphere's own density (mass / volume) would show in the checker's density
# check.
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
if [ "${SCENE_DENSITY_SPREAD:-0}" = 1 ]; then
  awk '/^Atoms/ {atoms = 1; print; next}
       /^[A-Z]/ {atoms = 0}
       atoms && NF == 7 && $2 == 1 {$4 = 1500 + 50 * ($1 % 23)}
       {print}' "$data" >"$data.spread" && mv "$data.spread" "$data"
  n=$(awk '/^Atoms/ {a = 1; next} /^[A-Z]/ {a = 0} a && NF == 7 && $2 == 1 {d[$4] = 1} END {print length(d)}' "$data")
  echo "matrix densities: $n distinct"
  [ "$n" -ge 2 ] || { echo "FAIL: SCENE_DENSITY_SPREAD: the data file was not changed"; exit 1; }
fi
"$here/run_scene.sh" "$name" "$exe" "$np" "$input" "$build/tests/check_scene" -- -var data "$data" "$@"
