#!/usr/bin/env bash
# The same relocation from a source-built LAMMPS (plugin) as from
# lmp_reinforce (packaged LAMMPS 2021) on one scene, serially, with the same
# input (tests/stability/in.scene) and keywords: the fix's statistics
# f_ID[1..8] and f_ID[10] identical (the STATS line), and the written atoms
# identical (check_scene --same).
#   same_as_packaged.sh SOURCE_LMP PACKAGED_LMP TOOLS_DIR "keywords" MAKE_SCENE_ARGS...
# Optional, from the environment:
#   SAME_INPUT=FILE      another input with the same variables and STATS line
#                        (default tests/stability/in.scene)
#   SAME_VARS="-var ..." more variables for both runs (e.g. periodic bounds)
#   SAME_NP=N            the source-built run on N processes (mpirun); the
#                        packaged one stays serial: the engine's result does
#                        not depend on the process count
#   SAME_TARGETS_BY=list|grid  the source-built log must say that the targets
#                        were found with LAMMPS's neighbor list (or with the
#                        engine's grid); the packaged log says neither
set -euo pipefail
src=$1 pkg=$2 tools=$3 extra=$4
shift 4
here=$(cd "$(dirname "$0")/.." && pwd)
input=${SAME_INPUT:-$here/stability/in.scene}
read -r -a vars <<<"${SAME_VARS:-}"
np=${SAME_NP:-1}
work=$(mktemp -d "${TMPDIR:-/tmp}/same_as_packaged.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$tools/make_scene" "$work/scene.data" "$@" >/dev/null
for side in src pkg; do
  run=("$src"); [ "$side" = pkg ] && run=("$pkg")
  [ "$side" = src ] && [ "$np" -gt 1 ] && run=(mpirun -np "$np" "$src")
  mkdir -p "$work/$side"
  (cd "$(dirname "$input")" && "${run[@]}" -in "$(basename "$input")" -var data "$work/scene.data" \
     -var out "$work/$side" -var extra "$extra" "${vars[@]}" -log "$work/$side/log" -screen none) ||
    { echo "FAIL: ${run[*]} exited non-zero"; tail -5 "$work/$side/log"; exit 1; }
done
how=$(grep '^fix reinforce/invert: targets found with' "$work/src/log" || true)
echo "source-built (np $np): ${how:-no line on how the targets were found}"
case "${SAME_TARGETS_BY:-}" in
  list) grep -q "^fix reinforce/invert: targets found with LAMMPS's occasional full neighbor list" \
          <<<"$how" || { echo "FAIL: the targets were not found with LAMMPS's neighbor list"; exit 1; } ;;
  grid) grep -q "^fix reinforce/invert: targets found with the engine's grid" <<<"$how" ||
          { echo "FAIL: the targets were not found with the engine's grid"; exit 1; } ;;
esac
if grep -q '^fix reinforce/invert: targets found with' "$work/pkg/log"; then
  echo "FAIL: the packaged LAMMPS has no neighbor list hook, yet its log names one"; exit 1
fi
a=$(grep '^STATS ' "$work/src/log" | tail -1) b=$(grep '^STATS ' "$work/pkg/log" | tail -1)
echo "source-built: $a"
echo "packaged:     $b"
if [ "$np" -eq 1 ]; then
  [ -n "$a" ] && [ "$a" = "$b" ] || { echo "FAIL: the statistics differ"; exit 1; }
else
  # On several processes the volumes f_ID[5..6] are sums of per-process sums
  # (another order of additions): 1e-12 relative; everything else exactly.
  awk -v a="$a" -v b="$b" 'BEGIN {
    na = split(a, x, " "); nb = split(b, y, " ")
    if (na != 10 || nb != 10) { print "FAIL: STATS lines incomplete"; exit 1 }
    for (k = 2; k <= 10; ++k) {
      if (k == 6 || k == 7) {
        d = x[k] - y[k]; if (d < 0) d = -d
        m = (x[k] < 0 ? -x[k] : x[k]); if (d > 1e-12 * m) { print "FAIL: the statistics differ"; exit 1 }
      } else if (x[k] != y[k]) { print "FAIL: the statistics differ"; exit 1 }
    }
  }' || exit 1
fi
"$tools/check_scene" --same "$work/src/after.dump" "$work/pkg/after.dump" || { echo "FAIL: the atoms differ"; exit 1; }
echo "PASS: the same relocation ($(awk '{print $2}' <<<"$a") targets)"
