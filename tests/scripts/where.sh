#!/usr/bin/env bash
# Where spheres went, for scene tests (SCENE_POST).
#   where.sh moved 'COND' BEFORE AFTER      every moved atom (any type: a
#                                           moved bar breaks a region too)
#                                           satisfies COND at its new place
#                                           (a region test)
#   where.sh unchanged 'COND' BEFORE AFTER  every sphere that satisfied COND
#                                           before is there, unmoved (matrix
#                                           spheres, type 1, outside the fix
#                                           group)
# COND is an awk expression of x, y, z and r (the radius).
set -euo pipefail
mode=$1 cond=$2 before=$3 after=$4
case $mode in moved | unchanged) ;; *) echo "where.sh: unknown mode $mode"; exit 2 ;; esac
awk -v mode="$mode" -v cond="$cond" '
  FNR == 1 { file++ }
  /^ITEM: ATOMS/ { delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next }
  /^ITEM:/ { body = 0; next }
  !body || (mode == "unchanged" && $c["type"] != 1) { next }
  {
    id = $c["id"]; x = $c["x"]; y = $c["y"]; z = $c["z"]; r = $c["radius"]
    line = x " " y " " z " " r
    ok = ('"$cond"')
  }
  file == 1 { old[id] = line; if (mode == "unchanged" && ok) { want[id] = 1; n++ } ; next }
  {
    if (mode == "unchanged" && (id in want)) { seen[id] = 1; if (line != old[id]) { bad++; if (bad <= 3) print "atom " id " moved: " old[id] " -> " line } }
    if (mode == "moved" && line != old[id]) { n++; if (!ok) { bad++; if (bad <= 3) print "atom " id " moved to " line } }
  }
  END {
    if (mode == "unchanged") for (id in want) if (!(id in seen)) { bad++; if (bad <= 3) print "atom " id " is gone" }
    if (bad) { printf "FAIL: %d of %d %s spheres break (%s)\n", bad, n, mode, cond; exit 1 }
    if (n == 0) { printf "FAIL: no %s sphere to test (%s)\n", mode, cond; exit 1 }
    printf "PASS: %d %s spheres: %s\n", n, mode, cond
  }' "$before" "$after"
