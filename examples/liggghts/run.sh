#!/usr/bin/env bash
# Runs the LIGGGHTS example three times: bars as plain rebar spheres with the
# default radius range and with a wider one, and bars as fix multisphere
# clumps. Renders a picture of each with Debian's lmp (LIGGGHTS 3.8 writes no
# PNG) and writes out/table.md. About a minute on one core.
#   run.sh [path/to/liggghts_reinforce]    (default: build/src/liggghts/liggghts_reinforce)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${1:-$here/../../build/src/liggghts/liggghts_reinforce}
exe=$(cd "$(dirname "$exe")" && pwd)/$(basename "$exe")
[ -x "$exe" ] || { echo "run.sh: no liggghts_reinforce at $exe (build it first)"; exit 1; }
# The shell ratio of each scene (tests/tools/scene_quality; built beside it).
quality=$(dirname "$exe")/../../tests/scene_quality
[ -x "$quality" ] || { echo "run.sh: no scene_quality at $quality (build it first)"; exit 1; }
cd "$here"
mkdir -p out
rm -f out/row_*.txt
# LIGGGHTS 3.8 crashes in insert/pack under -screen none: redirect instead.
run() {    # run TAG liggghts-args...
  local tag=$1
  shift
  "$exe" -in in.liggghts -var tag "$tag" -log "out/log_$tag" "$@" > "out/screen_$tag.txt"
  grep '^fix reinforce/invert: [0-9]' "out/log_$tag"
  lmp -in render.lmp -var data "out/liggghts_$tag.data" -var png "out/liggghts_$tag.png" -log none -screen none
}
run default
run wide -var extra "radius 0.0015 0.005"
run multisphere -var bars multisphere
{
  echo "| run | bars | matrix spheres after | rebar spheres | solid fraction after | targets | relocated | deleted | largest overlap / rmin | relocation time (s) | shell ratio |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for tag in default wide multisphere; do
    case $tag in
      default) bars="plain spheres" ;;
      wide) bars="plain spheres, \`radius 0.0015 0.005\`" ;;
      multisphere) bars="\`fix multisphere\` clumps" ;;
    esac
    # Matrix radii 3-5 mm: the shell is the first 2 rmax from the bars.
    shell=$("$quality" --after "out/liggghts_$tag.data" --rmin 0.003 --rmax 0.005 --quiet-profile |
      tr ' ' '\n' | awk -F= '$1 == "shell_ratio" {r = $2} $1 == "shell_ratio_se" {se = $2} END {print r " ± " se}')
    awk -v bars="$bars" -v shell="$shell" '$1 == "ROW" {
      printf "| %s | %s | %d | %d | %.3f | %d | %d | %d | %.1e | %.3f | %s |\n", $2, bars, $3, $4, $5, $6, $7, $8, $9, $10, shell
    }' "out/row_$tag.txt"
  done
} > out/table.md
cat out/table.md
# README.md: the block between the markers is this run's out/table.md.
bash "$here/../../scripts/fill_readme_block.sh" README.md out/table.md
echo "README.md updated"
