#!/usr/bin/env bash
# One quality test: run the fix (or delete_atoms overlap) on a scene made by
# make_scenes.sh, check it with check_scene, measure it with scene_quality
# against the reference grown around the same bars.
#   quality.sh CASE NP LMP CHECK_SCENE SCENE_QUALITY SCENES [--] [scene_quality args]
# SCENES/CASE/{before.data,ref.data,boundary} must exist (make_scenes.sh).
# QUALITY_LMP_VARS="-var method delete -var cut 0.0125": more lmp arguments
# (in.quality lists them). QUALITY_FIX="grow together" with QUALITY_TAG=together:
# fix keywords after the defaults, the tag naming the run. QUALITY_REMOVED_MAX=X:
# the removed ratio must be at most X. A scene without ref.data is measured
# without a reference. The scene's md5 (ids, types, positions, radii as
# written) is printed and, without QUALITY_LMP_VARS, written to
# SCENES/CASE/after_npNP[_TAG].md5 before the assertions: same_scene.sh --runs
# compares those of the process counts instead of running the fix again.
set -euo pipefail
case=$1 np=$2 lmp=$3 check=$4 quality=$5 scenes=$6
shift 6
[ "${1:-}" = "--" ] && shift
# shellcheck disable=SC2206    # words of a list of arguments
vars=(${QUALITY_LMP_VARS:-})
[ -n "${QUALITY_FIX:-}" ] && vars+=(-var extra "$QUALITY_FIX")
tag=${QUALITY_TAG:+_$QUALITY_TAG}
[ -n "${QUALITY_FIX:-}" ] && [ -z "$tag" ] && { echo "FAIL: QUALITY_FIX needs QUALITY_TAG"; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
dir=$scenes/$case
[ -f "$dir/before.data" ] || { echo "FAIL: no scene in $dir (make_scenes.sh)"; exit 1; }
reference=()
[ -f "$dir/ref.data" ] && reference=(--reference "$dir/ref.data")
read -r bx by bz < "$dir/boundary"
md5_out=""
[ -n "${QUALITY_LMP_VARS:-}" ] || md5_out=$dir/after_np$np$tag.md5
[ -z "$md5_out" ] || rm -f "$md5_out"    # none left from an earlier run
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "quality_${case}"
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
start=$(date +%s.%N)
(cd "$here" && "${launch[@]}" "$lmp" -in in.quality -log "$work/log" -screen none \
   -var data "$dir/before.data" -var out "$work" -var bx "$bx" -var by "$by" -var bz "$bz" "${vars[@]}") \
  || { echo "FAIL: $lmp exited non-zero"; tail -5 "$work/log"; exit 1; }
end=$(date +%s.%N)
read -r _ targets relocated deleted kept < <(grep '^TOTALS ' "$work/log" | tail -1)
echo "$case${QUALITY_FIX:+ ($QUALITY_FIX)} np=$np: targets $targets relocated $relocated deleted $deleted kept $kept ($(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.2f", b - a}') s with start-up)"
grep '^fix reinforce/invert:' "$work/log" | tail -1 || true
"$check" --before "$work/before.dump" --after "$work/after.dump" --deleted "$deleted" \
  | grep -v '^INFO' || { echo "FAIL: check_scene (above)"; exit 1; }
sum=$(md5sum < "$work/after.dump" | cut -c1-32)
echo "SCENE_MD5 $sum"
[ -z "$md5_out" ] || echo "$sum" > "$md5_out"
status=0
"$quality" --before "$work/before.dump" --after "$work/after.dump" "${reference[@]}" \
  --boundary $bx $by $bz --quiet-profile "$@" | tee "$work/quality" || status=$?
if [ -n "${QUALITY_REMOVED_MAX:-}" ]; then
  removed=$(grep '^QUALITY' "$work/quality" | tr ' ' '\n' | sed -n 's/^removed_ratio=//p')
  # A missing or unreadable figure fails (awk takes "" as 0).
  if awk -v r="$removed" -v m="$QUALITY_REMOVED_MAX" \
       'BEGIN {exit !(r ~ /^[0-9.]+([eE][-+]?[0-9]+)?$/ && r + 0 <= m + 0)}'; then
    echo "PASS: removed ratio $removed <= $QUALITY_REMOVED_MAX"
  else
    echo "FAIL: removed ratio ${removed:-(missing)} not <= $QUALITY_REMOVED_MAX"
    status=1
  fi
fi
exit $status
