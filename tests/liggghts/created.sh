#!/usr/bin/env bash
# Atoms created after the fix command: the fix must see them as ordinary
# spheres (their per-atom flag initialised), so defining the fix before or
# after the matrix is created gives the same relocation.
#   created.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/test_env.sh" "liggghts_created"
fix="fix r all reinforce/invert 0 bars radius 0.004 0.01"
mkdir -p "$work/early" "$work/late"
(cd "$here" && "$build/src/liggghts/liggghts_reinforce" -in in.created -var out "$work/early" \
   -var early "$fix" -var late "print fix-already-defined" -log "$work/early/log" -screen none)
(cd "$here" && "$build/src/liggghts/liggghts_reinforce" -in in.created -var out "$work/late" \
   -var early "print no-fix-yet" -var late "$fix" -log "$work/late/log" -screen none)
early=$(grep '^TOTALS' "$work/early/log" | tail -1)
late=$(grep '^TOTALS' "$work/late/log" | tail -1)
echo "fix defined before the matrix: $early"
echo "fix defined after the matrix:  $late"
read -r _ targets _ <<<"$late"
[ "$targets" -gt 0 ] || { echo "FAIL: the scene has no targets"; exit 1; }
[ "$early" = "$late" ] || { echo "FAIL: the totals differ (atoms created after the fix taken for targets?)"; exit 1; }
"$build/tests/check_scene" --same "$work/early/after.dump" "$work/late/after.dump"
echo "PASS: atoms created after the fix"
