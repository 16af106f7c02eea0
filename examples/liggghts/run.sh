#!/usr/bin/env bash
# Runs the LIGGGHTS example twice (default radius range, and a wider one),
# renders pictures with lmp and writes out/table.md.
#   run.sh [path/to/liggghts_reinforce]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${1:-$here/../../build/src/liggghts/liggghts_reinforce}
cd "$here"
mkdir -p out
rm -f out/row_*.md
"$exe" -in in.liggghts -log out/log_default > out/screen_default.txt
"$exe" -in in.liggghts -var extra "radius 0.0015 0.005" -var tag wide -log out/log_wide > out/screen_wide.txt
for tag in default wide; do
  lmp -in render.lmp -var data "out/liggghts_$tag.data" -var png "out/liggghts_$tag.png" -log none -screen none
  grep '^fix reinforce/invert: [0-9]' "out/log_$tag"
done
{
  echo "| run | matrix spheres after | solid fraction after | targets | relocated | deleted | largest overlap / rmin | relocation time (s) |"
  echo "|---|---|---|---|---|---|---|---|"
  cat out/row_default.md out/row_wide.md
} > out/table.md
cat out/table.md
