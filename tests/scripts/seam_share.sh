#!/usr/bin/env bash
# "No thinning at seams": the share of targets deleted near subdomain seams
# against the share elsewhere (and, given a reference result of the same
# scene on one process, against the reference's share on the same targets).
#   seam_share.sh BAND SEAMS BEFORE AFTER [REFERENCE_AFTER]
# SEAMS names the seam planes per dimension: "x=0.125,0.25,0.375" or
# "x=0,0.3/y=0,0.15" (the periodic boundary is a seam too: list it). A target
# is a matrix sphere (type 1) of BEFORE that moved or disappeared in AFTER;
# it is near a seam when its old centre lies within BAND of a seam plane
# (minimum image in the dimensions BEFORE marks periodic, "pp").
#
# The margin: if deletion does not depend on seam proximity, the number of
# deleted among the t near-seam targets is binomial(t, p) with p the share
# elsewhere; the test fails above p + 3 standard deviations of the share
# (normal approximation, one-sided 0.13%) plus one sphere (1/t, for small t
# and p near 0). The runs are deterministic, so this does not flicker. A
# thinning at seams such as LIGGGHTS's insert/pack leaves (places refused
# near subdomain borders) drives the near-seam share towards 1. With no
# deletion elsewhere, any deletion near a seam fails (margin 0).
# Near-seam and other targets may differ in kind (a bar lying on a seam,
# bars crossing there): then the within-run comparison is confounded by the
# geometry, and the comparison with the reference on the very same targets
# is the one that decides. So with REFERENCE_AFTER the within-run shares are
# only reported, unless SEAM_BOTH=1.
set -euo pipefail
band=$1 seams=$2 before=$3 after=$4 reference=${5:-}
awk -v band="$band" -v seams="$seams" -v ref="$reference" -v both="${SEAM_BOTH:-0}" '
  FNR == 1 { file++ }
  /^ITEM: BOX BOUNDS/ {
    if (file == 1) for (k = 1; k <= 3; k++) { per[k] = ($(3 + k) == "pp"); getline; len[k] = $2 - $1 }
    next
  }
  /^ITEM: ATOMS/ { delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next }
  /^ITEM:/ { body = 0; next }
  !body { next }
  file == 1 { type[$c["id"]] = $c["type"]; pos[$c["id"]] = $c["x"] " " $c["y"] " " $c["z"]
              key[$c["id"]] = $c["x"] " " $c["y"] " " $c["z"] " " $c["radius"]; next }
  file == 2 { now[$c["id"]] = $c["x"] " " $c["y"] " " $c["z"] " " $c["radius"]; next }
  file == 3 { refnow[$c["id"]] = $c["x"] " " $c["y"] " " $c["z"] " " $c["radius"]; next }
  function near(id,   p, k, j, d) {
    split(pos[id], p, " ")
    for (k = 1; k <= 3; k++)
      for (j = 1; j <= nplane[k]; j++) {
        d = p[k] - plane[k, j]; if (d < 0) d = -d
        if (per[k] && len[k] - d < d) d = len[k] - d
        if (d < band) return 1
      }
    return 0
  }
  function allowed(p, t) { return p + 3 * sqrt(p * (1 - p) / t) + (p > 0 ? 1 / t : 0) }
  END {
    ndim = split(seams, dims, "/")
    for (i = 1; i <= ndim; i++) {
      split(dims[i], kv, "=")
      k = index("xyz", kv[1]); if (k == 0) { print "FAIL: bad seams " seams; exit 1 }
      nplane[k] = split(kv[2], v, ",")
      for (j = 1; j <= nplane[k]; j++) plane[k, j] = v[j]
    }
    for (id in type) {
      if (type[id] != 1) continue
      gone = !(id in now)
      if (!gone && now[id] == key[id]) continue
      n = near(id); t[n]++; d[n] += gone
      if (ref != "") { if (!(id in refnow)) r[n]++ }
    }
    if (t[1] == 0) { print "FAIL: no target near a seam (the scene does not test seams)"; exit 1 }
    p1 = d[1] / t[1]; p0 = t[0] ? d[0] / t[0] : 0
    printf "targets near seams %d (deleted %d, share %.3f); elsewhere %d (deleted %d, share %.3f); allowed %.3f\n", t[1], d[1], p1, t[0], d[0], p0, allowed(p0, t[1])
    bad = p1 > allowed(p0, t[1]) + 1e-12
    if (bad && ref != "" && both != 1) { print "INFO: more deletions near seams than elsewhere (the reference decides)"; bad = 0 }
    if (bad) print "FAIL: more deletions near seams than elsewhere"
    if (ref != "") {
      pr = r[1] / t[1]
      printf "the same near-seam targets on one process (no seams): deleted %d (share %.3f); allowed %.3f\n", r[1], pr, allowed(pr, t[1])
      if (p1 > allowed(pr, t[1]) + 1e-12) { print "FAIL: more deletions near seams than on one process"; bad = 1 }
    }
    if (bad) exit 1
    print "PASS: no thinning at seams"
  }' "$before" "$after" ${reference:+"$reference"}
