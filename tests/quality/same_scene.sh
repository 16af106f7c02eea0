#!/usr/bin/env bash
# The fix with its defaults on a quality scene at several process counts:
# the scenes written after it must be identical (ids, types, positions and
# radii as written, %.17g).
#   same_scene.sh CASE LMP SCENES NP...
#   same_scene.sh CASE --runs SCENES NP...   compares the scenes the
#       quality tests (quality.sh CASE NP, the same defaults) wrote, from
#       their SCENES/CASE/after_npNP.md5, without running the fix again
#       (QUALITY_TAG=T: after_npNP_T.md5, the runs tagged T)
set -euo pipefail
case=$1 lmp=$2 scenes=$3
shift 3
if [ "$lmp" = --runs ]; then
  first=""
  for np in "$@"; do
    tag=${QUALITY_TAG:+_$QUALITY_TAG}
    f=$scenes/$case/after_np$np$tag.md5
    [ -s "$f" ] || { echo "FAIL: no scene of quality_${case}${tag}_np$np ($f): did that test run?"; exit 1; }
    sum=$(cat "$f")
    echo "$case np=$np: scene $sum (quality_${case}${tag}_np$np)"
    [ -z "$first" ] && first=$sum
    [ "$sum" = "$first" ] || { echo "FAIL: the scene at $np processes differs from the one at $1"; exit 1; }
  done
  echo "PASS: $case: the same scene at $* processes"
  exit 0
fi
here=$(cd "$(dirname "$0")" && pwd)
dir=$scenes/$case
[ -f "$dir/before.data" ] || { echo "FAIL: no scene in $dir (make_scenes.sh)"; exit 1; }
read -r bx by bz < "$dir/boundary"
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "same_${case}"
first=""
for np in "$@"; do
  launch=(mpirun -np "$np")
  [ "$np" -eq 1 ] && launch=()
  mkdir -p "$work/$np"
  (cd "$here" && "${launch[@]}" "$lmp" -in in.quality -log "$work/$np/log" -screen none \
     -var data "$dir/before.data" -var out "$work/$np" -var bx "$bx" -var by "$by" -var bz "$bz") \
    || { echo "FAIL: $lmp exited non-zero at $np processes"; tail -5 "$work/$np/log"; exit 1; }
  sum=$(md5sum < "$work/$np/after.dump" | cut -c1-32)
  echo "$case np=$np: $(grep '^TOTALS ' "$work/$np/log" | tail -1) scene $sum"
  [ -z "$first" ] && first=$sum
  [ "$sum" = "$first" ] || { echo "FAIL: the scene at $np processes differs from the one at $1"; exit 1; }
done
echo "PASS: $case: the same scene at $* processes"
