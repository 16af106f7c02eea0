#!/usr/bin/env bash
# Share of targets deleted near subdomain seams against elsewhere.
#   seam_share.sh BEFORE AFTER BAND SEAM_X...
# A target is a matrix sphere (type 1) that moved or disappeared; it is near
# a seam when its old centre lies within BAND of a seam plane x = SEAM_X.
# Fails when the near-seam share exceeds the share elsewhere by more than
# three binomial standard deviations (plus one sphere's worth).
set -euo pipefail
before=$1 after=$2 band=$3
shift 3
awk -v band="$band" -v seams="$*" '
  function atoms(file, store,   line) { }
  FNR == 1 { file++ }
  /^ITEM: ATOMS/ { body = 1; next }
  /^ITEM:/ { body = 0; next }
  body && file == 1 { type[$1] = $2; bx[$1] = $3; key[$1] = $3 " " $4 " " $5 " " $6 }
  body && file == 2 { now[$1] = $3 " " $4 " " $5 " " $6 }
  END {
    n = split(seams, s, " ")
    for (id in type) {
      if (type[id] != 1) continue
      gone = !(id in now)
      if (!gone && now[id] == key[id]) continue
      near = 0
      for (k = 1; k <= n; k++) if (bx[id] - s[k] < band && s[k] - bx[id] < band) near = 1
      t[near]++; d[near] += gone
    }
    if (t[0] == 0 || t[1] == 0) { print "FAIL: no targets near seams or elsewhere"; exit 1 }
    p0 = d[0] / t[0]; p1 = d[1] / t[1]
    margin = 3 * sqrt(p0 * (1 - p0) / t[1]) + 1 / t[1]
    printf "targets near seams %d (deleted %d, share %.3f); elsewhere %d (deleted %d, share %.3f); allowed %.3f\n", t[1], d[1], p1, t[0], d[0], p0, p0 + margin
    if (p1 > p0 + margin) { print "FAIL: more deletions near seams"; exit 1 }
    print "PASS: no thinning at seams"
  }' "$before" "$after"
