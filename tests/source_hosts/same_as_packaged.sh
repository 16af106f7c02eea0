#!/usr/bin/env bash
# The same relocation from a source-built LAMMPS (plugin) as from
# lmp_reinforce (packaged LAMMPS 2021) on one scene, serially, with the same
# input (tests/stability/in.scene) and keywords: the fix's statistics
# f_ID[1..8] and f_ID[10] identical (the STATS line), and the written atoms
# identical (check_scene --same).
#   same_as_packaged.sh SOURCE_LMP PACKAGED_LMP TOOLS_DIR "keywords" MAKE_SCENE_ARGS...
set -euo pipefail
src=$1 pkg=$2 tools=$3 extra=$4
shift 4
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/same_as_packaged.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$tools/make_scene" "$work/scene.data" "$@" >/dev/null
for side in src pkg; do
  exe=$src; [ "$side" = pkg ] && exe=$pkg
  mkdir -p "$work/$side"
  (cd "$here/stability" && "$exe" -in in.scene -var data "$work/scene.data" -var out "$work/$side" \
     -var extra "$extra" -log "$work/$side/log" -screen none) ||
    { echo "FAIL: $exe exited non-zero"; tail -5 "$work/$side/log"; exit 1; }
done
a=$(grep '^STATS ' "$work/src/log" | tail -1) b=$(grep '^STATS ' "$work/pkg/log" | tail -1)
echo "source-built: $a"
echo "packaged:     $b"
[ -n "$a" ] && [ "$a" = "$b" ] || { echo "FAIL: the statistics differ"; exit 1; }
"$tools/check_scene" --same "$work/src/after.dump" "$work/pkg/after.dump" || { echo "FAIL: the atoms differ"; exit 1; }
echo "PASS: the same relocation ($(awk '{print $2}' <<<"$a") targets)"
