#!/usr/bin/env bash
# Runs one input-script scene test and asserts on the written result.
#
#   run_scene.sh NAME EXE NPROCS INPUT CHECKER -- [lmp -var args] -- [checker args]
#
# The input must write $out/before.dump (the scene as read) and
# $out/after.dump (after the fix), and report the fix's totals with
#   print "TOTALS ${targets} ${relocated} ${deleted} ${kept}"
# The script checks the dumps (no overlap, radii, atom conservation, rebar
# untouched), that the deleted count the fix reports is what disappeared,
# and, run twice, that the output is identical.
set -euo pipefail
name=$1 exe=$2 np=$3 input=$4 checker=$5
shift 5
[ "$1" = "--" ] && shift
vars=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do vars+=("$1"); shift; done
[ $# -gt 0 ] && shift
check_args=("$@")

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/scene_${name}.XXXXXX")
trap 'rm -rf "$work"' EXIT
indir=$(cd "$(dirname "$input")" && pwd)

run() {    # run OUTDIR
  mkdir -p "$1"
  (cd "$indir" && mpirun -np "$np" "$exe" -in "$input" -log "$1/log" -screen none \
     -var out "$1" "${vars[@]}") || { echo "FAIL: $exe exited non-zero"; tail -5 "$1/log"; exit 1; }
}
run "$work/a"
totals=$(grep '^TOTALS' "$work/a/log" | tail -1)
[ -n "$totals" ] || { echo "FAIL: no TOTALS line in the log"; tail -5 "$work/a/log"; exit 1; }
read -r _ targets relocated deleted kept <<<"$totals"
grep -q '^fix reinforce/invert: ' "$work/a/log" || { echo "FAIL: no summary line"; exit 1; }
echo "$name np=$np: targets $targets relocated $relocated deleted $deleted kept $kept"
[ "$targets" -eq $((relocated + deleted + kept)) ] || { echo "FAIL: targets != relocated + deleted + kept"; exit 1; }
"$checker" --before "$work/a/before.dump" --after "$work/a/after.dump" --deleted "$deleted" "${check_args[@]}"

run "$work/b"
"$checker" --same "$work/a/after.dump" "$work/b/after.dump"
echo "PASS $name np=$np"
