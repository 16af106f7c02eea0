#!/usr/bin/env bash
# The cage example, end to end (about two minutes on 2 cores), after the
# README's set-up (build/, or REINFORCE_BUILD):
#  1. reinforce_layout lays out the cage (cage.layout -> out/cage.data, and a
#     molecule file per bar and stirrup in out/molecules/);
#  2. grow_packing grows the matrix alone in the beam's box (out/matrix.data;
#     radii 3-6 mm, solid fraction 0.6, seed 7), the packing a user has
#     before the bars go in;
#  3. lmp_reinforce runs in.cage under mpirun (REINFORCE_CAGE_NP processes,
#     default 2): the cage added, fix reinforce/invert with its defaults, the
#     pictures;
#  4. check_scene checks the result (no overlap, rebar untouched, atoms
#     conserved) and scene_quality measures it;
#  5. writes out/table.md, copies the pictures here (cage.png, cut.png) and
#     puts the tables into README.md between its markers.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${REINFORCE_BUILD:-$here/../../build}
np=${REINFORCE_CAGE_NP:-2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
for exe in src/layout/reinforce_layout src/lammps/lmp_reinforce tests/grow_packing tests/check_scene tests/scene_quality; do
  [ -x "$build/$exe" ] || { echo "run.sh: $build/$exe was not built (run the README's set-up)"; exit 1; }
done
cd "$here"
rm -rf out
mkdir -p out
"$build/src/layout/reinforce_layout" cage.layout --data out/cage.data --molecules out/molecules | tee out/layout.txt
"$build/tests/grow_packing" out/matrix.data --box 0 0.4 0 0.15 0 0.2 --radius 0.003 0.006 --phi 0.6 --seed 7 --quiet
echo "cage: mpirun -np $np lmp_reinforce -in in.cage"
mpirun -np "$np" "$build/src/lammps/lmp_reinforce" -in in.cage -var matrix out/matrix.data -var cage out/cage.data \
  -var out out -log out/log.lammps -screen none
grep '^fix reinforce/invert: [0-9]' out/log.lammps
deleted=$(awk -F'|' '{gsub(/ /, "", $6); print $6}' out/fix.md)
"$build/tests/check_scene" --before out/before.dump --after out/after.dump --deleted "$deleted" > out/check.txt ||
  { cat out/check.txt; echo "run.sh: the checker failed"; exit 1; }
overlap=$(grep '^PASS: moved spheres overlap nothing' out/check.txt)
on_bars=$(grep '^PASS: no matrix sphere overlaps a bar' out/check.txt)
"$build/tests/scene_quality" --before out/before.dump --after out/after.dump --quiet-profile > out/quality.txt
line=$(grep '^QUALITY' out/quality.txt)
get() { tr ' ' '\n' <<<"$line" | awk -F= -v k="$1" '$1 == k {print $2}'; }
before=$(sed -n 's/^before: .*shell ratio \([0-9.]*\).*/\1/p' out/quality.txt)
{
  echo "The layout (\`reinforce_layout cage.layout\`):"
  echo
  sed -n 's/^line [0-9]* cage: /* /p; s/^total: /* total: /p' out/layout.txt
  echo
  echo "The fix (\`fix reinforce/invert 0 rebar\`, defaults, $np processes):"
  echo
  echo "| spheres after | rebar spheres | targets | relocated | deleted | largest overlap / rmin | relocation time (s) |"
  echo "|---|---|---|---|---|---|---|"
  cat out/fix.md
  echo
  echo "The checker (\`check_scene\`): ${overlap#PASS: }; ${on_bars#PASS: }."
  echo
  echo "The scene (\`scene_quality\`; the shell is the matrix within 2 rmax of a rebar surface, the bulk beyond 4 rmax):"
  echo
  echo "| shell ratio before | shell ratio after | removed ratio | KS of radii | deleted | other spheres moved | farthest moved from a bar |"
  echo "|---|---|---|---|---|---|---|"
  echo "| $before | $(get shell_ratio) ± $(get shell_ratio_se) | $(get removed_ratio) | $(get ks) | $(get deleted) | $(get moved_nontargets) | $(get moved_max_bar_distance_rmax) rmax |"
} > out/table.md
cat out/table.md
cp out/cage.png out/cut.png .
# README.md: the block between the markers is this run's out/table.md.
bash "$here/../../scripts/fill_readme_block.sh" README.md out/table.md
echo "pictures: $here/cage.png $here/cut.png; README.md updated"
