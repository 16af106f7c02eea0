#!/usr/bin/env bash
# The test command's family check (scripts/test.sh): reads the output of
# `ctest -N` (the tests a part will run) on stdin and checks that each family
# of the part, a table row of scripts/test_families.txt, has at least its
# minimum of tests. So a family that drops out (its tests no longer
# registered, a host built without them) fails the command by name, where a
# count of "any test of the host" would not notice.
#   count_families.sh PART [HOST...] < ctest-N-output
# HOSTs are the hosts expected (not skipped by name): lammps, liggghts, and
# for the part "source" lammps_source, liggghts_source (the trees named). A
# row applies when every host it names (comma-separated; - for none) is
# given. Prints one line per family that applies; for each one short:
#   test: FAILED: part PART: family 'NAME' (REGEX): N tests, expected at least M
# Exits with the number of families short (0: all there); 2 when the table
# is missing or has no row for the part.
set -uo pipefail
part=${1:?usage: count_families.sh PART [HOST...] < ctest-N-output}
shift
table=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/test_families.txt
[ -f "$table" ] || { echo "test: FAILED: part $part: no family table $table"; exit 2; }
names=$(sed -nE 's/^ *Test +#[0-9]+: +([^ ]+).*/\1/p')
awk -v part="$part" -v hosts=" $* " -v names="$names" '
  BEGIN { n = split(names, name, "\n"); if (names == "") n = 0 }
  /^[[:space:]]*(#|$)/ { next }
  $1 != part { next }
  {
    rows++
    host = $2; min = $3; re = $4
    fam = $5; for (i = 6; i <= NF; i++) fam = fam " " $i
    if (host != "-") {
      k = split(host, need, ",")
      for (i = 1; i <= k; i++) if (index(hosts, " " need[i] " ") == 0) next
    }
    c = 0
    for (i = 1; i <= n; i++) if (name[i] ~ re) c++
    if (c < min) {
      printf "test: FAILED: part %s: family '\''%s'\'' (%s): %d tests, expected at least %d\n", part, fam, re, c, min
      short++
    } else printf "  family %s: %s: %d tests (at least %d)\n", part, fam, c, min
  }
  END {
    if (!rows) { printf "test: FAILED: part %s: no family of it in %s\n", part, FILENAME; exit 2 }
    exit short > 125 ? 125 : short
  }' "$table"
