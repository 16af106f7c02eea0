#!/usr/bin/env bash
# SCENE_POST of host_clumps.sh: the scene before the fix holds exactly N
# rebar spheres (type 2): every sphere of the clumps placed, none lost.
#   rebar_count.sh N BEFORE AFTER
set -euo pipefail
n=$1 before=$2
got=$(awk '/^ITEM: ATOMS/ {for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next}
           /^ITEM:/ {body = 0; next}
           body && $c["type"] == 2 {k++}
           END {print k + 0}' "$before")
[ "$got" -eq "$n" ] || { echo "FAIL: $got rebar spheres before the fix, the clump files hold $n"; exit 1; }
echo "PASS: the $n spheres of the clumps are rebar before the fix"
