#!/usr/bin/env bash
# The quality tests' figures as a table for README.md, from the verbose log
# of a run of them:
#   ctest -R '^quality_' -V > quality.log; bash figures.sh quality.log
# One row per test that wrote a QUALITY line (scene_quality's figures).
set -euo pipefail
log=${1:?usage: figures.sh CTEST_VERBOSE_LOG}
echo "| test | removed ratio | shell ratio - reference's | largest bin difference | KS | deleted of targets | moved farthest from a bar |"
echo "|---|---|---|---|---|---|---|"
# ctest -V prefixes each output line with the test's number; the test's
# name is on its "Test command" line (quality.sh CASE NP) and its tag (if
# any) in its environment.
awk '
  /Test command: .*quality\.sh/ {
    n = $1; sub(/:$/, "", n)
    for (i = 1; i <= NF; ++i)
      if ($i ~ /quality\.sh"?$/) {
        c = $(i + 1); p = $(i + 2); gsub(/"/, "", c); gsub(/"/, "", p)
        name[n] = "quality_" c "_np" p
      }
  }
  /: QUALITY / {
    n = $1; sub(/:$/, "", n)
    delete f
    for (i = 3; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
    shell = ("shell_vs_reference" in f) ? sprintf("%+.4f", f["shell_vs_reference"]) : "no reference"
    bin = ("bin_diff_max" in f) ? f["bin_diff_max"] : "-"
    printf "| `%s` | %s | %s | %s | %s | %s of %s | %s rmax |\n", name[n], f["removed_ratio"], shell, bin, f["ks"], f["deleted"], f["targets"], f["moved_max_bar_distance_rmax"]
  }' "$log" | sort
