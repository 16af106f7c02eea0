#!/usr/bin/env bash
# The examples' bars, made by the layout command, are the files committed
# and the same spheres as before the command existed:
#  beam      examples/beam/bars.layout -> data/bars.data, byte for byte; and
#            its atoms, as numbers, exactly those of the five bars of the
#            seed paper's beam as the examples wrote them by awk before
#            (x0 + (x1 - x0) i / 64, printed %.9f; y, z, diameter %.6f)
#  liggghts  examples/liggghts/bar.layout -> bar_template.liggghts, byte for
#            byte; its 25 spheres exactly the list typed before
#            (-0.0900 ... 0.0900 every 0.0075, radius 0.005)
#   examples_same.sh beam|liggghts BUILD_DIR
set -euo pipefail
example=$1 build=$2
here=$(cd "$(dirname "$0")" && pwd)
top=$here/../..
. "$here/../scripts/test_env.sh" "layout_example_${example}"
layout=$build/src/layout/reinforce_layout
fail() { echo "FAIL: $*"; exit 1; }
numbers() {    # the atoms of a data file, every number as the double it reads as
  awk '/^Atoms/ {a = 1; next}
       a && NF == 7 {printf "%s %s %.17g %.17g %.17g %.17g %.17g\n", $1, $2, $3, $4, $5, $6, $7}' "$1"
}
case $example in
  beam)
    (cd "$top/examples/beam" && "$layout" bars.layout --data "$work/bars.data" > /dev/null)
    cmp "$work/bars.data" "$top/examples/beam/data/bars.data" || fail "data/bars.data is not what bars.layout makes"
    echo "PASS: data/bars.data is what make_bars.sh (the layout command) writes"
    awk 'BEGIN {
      split("0.04 0.125 0.21 0.04 0.21", y, " "); split("0.04 0.04 0.04 0.21 0.21", z, " ")
      print "Atoms"
      for (b = 1; b <= 5; b++) for (i = 0; i < 65; i++)
        printf "%d 1 %.6f 7800 %.9f %.6f %.6f\n", ++id, 0.01, 0.005 + 0.49 * i / 64, y[b], z[b] }' > "$work/awk.data"
    diff <(numbers "$work/awk.data") <(numbers "$work/bars.data") > /dev/null || fail "the bars differ from the awk bars"
    [ "$(numbers "$work/bars.data" | wc -l)" = 325 ] || fail "not 325 atoms"
    echo "PASS: the 325 atoms equal the awk bars' exactly (type, diameter, density, x, y, z as doubles)"
    ;;
  liggghts)
    (cd "$top/examples/liggghts" && "$layout" bar.layout --liggghts "$work/bar.liggghts" > /dev/null)
    cmp "$work/bar.liggghts" "$top/examples/liggghts/bar_template.liggghts" ||
      fail "bar_template.liggghts is not what bar.layout makes"
    echo "PASS: bar_template.liggghts is what make_bars.sh (the layout command) writes"
    made=$(sed -n 's/^variable bar string "nspheres 25 ntry 1000000 spheres \(.*\)"$/\1/p' "$work/bar.liggghts" |
           awk '{for (i = 1; i <= NF; i++) printf "%.17g\n", $i}')
    typed=$(awk 'BEGIN {for (i = 0; i < 25; i++)
                          printf "%.17g\n%.17g\n%.17g\n%.17g\n", sprintf("%.4f", -0.09 + 0.0075 * i), 0, 0, 0.005}')
    [ "$made" = "$typed" ] || fail "the sphere list differs from the typed one"
    echo "PASS: the 25 spheres equal the list typed before exactly"
    ;;
esac
echo "PASS layout example $example"
