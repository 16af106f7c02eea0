#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, and runs the
# seed paper's reinforced beam (examples/beam) at the three densities, with
# lmp_reinforce under mpirun (REINFORCE_BEAM_NP processes, default 2).
# Writes examples/beam/out/: a picture, a dump, a data file and a profile
# plot (solid fraction against distance from the bars) per density,
# table.md and quality.md; with the three densities, puts the two tables
# into examples/beam/README.md between its markers.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce"
[ -x "$lmp" ] || { echo "run-beam: $lmp was not built (is LAMMPS installed?)"; exit 1; }
np=${REINFORCE_BEAM_NP:-2}
cd "$top/examples/beam"
mkdir -p out
rm -f out/row_phi*.md
for phi in ${REINFORCE_BEAM_PHIS:-050 060 064}; do
  echo "beam, solid fraction 0.${phi#0}: mpirun -np $np lmp_reinforce -in in.beam -var phi $phi"
  mpirun -np "$np" "$lmp" -in in.beam -var phi "$phi" -var out out -log "out/log_phi$phi.lammps" \
    -screen none
  grep '^fix reinforce/invert: [0-9]' "out/log_phi$phi.lammps"
done
{
  echo "| spheres | solid fraction after | targets | relocated | deleted | largest overlap / rmin | relocation time (s) |"
  echo "|---|---|---|---|---|---|---|"
  cat out/row_phi*.md
} > out/table.md
echo
cat out/table.md
# The scene each method leaves (tests/tools/scene_quality, docs/design.md
# "Scene quality"): the fix above, the seed paper's size fit, and
# delete_atoms overlap, each against the scene before.
quality="$REINFORCE_BUILD/tests/scene_quality"
[ -x "$quality" ] || { echo "run-beam: $quality was not built"; exit 1; }
echo
echo "scene quality: size fit and delete_atoms overlap on the same beams"
{
  echo "| solid fraction | method | deleted | shell ratio | removed ratio | KS of radii |"
  echo "|---|---|---|---|---|---|"
  for phi in ${REINFORCE_BEAM_PHIS:-050 060 064}; do
    rm -f "out/profile_phi$phi.tsv"
    for method in fix fit delete; do
      dir=out
      if [ "$method" != fix ]; then
        dir=out/$method
        mkdir -p "$dir"
        vars=(-var method delete)
        [ "$method" = fit ] && vars=(-var extra "size fit")
        mpirun -np "$np" "$lmp" -in in.beam -var phi "$phi" -var out "$dir" "${vars[@]}" \
          -log "$dir/log_phi$phi.lammps" -screen none
      fi
      report=$("$quality" --before "out/before_phi$phi.dump" --after "$dir/beam_phi$phi.dump")
      line=$(grep '^QUALITY' <<<"$report")
      get() { tr ' ' '\n' <<<"$line" | awk -F= -v k="$1" '$1 == k {print $2}'; }
      case $method in
        fix) name="fix defaults" ;;
        fit) name="fix size fit (seed paper)" ;;
        delete) name="delete_atoms overlap 0.0125" ;;
      esac
      echo "| 0.${phi#0} | $name | $(get deleted) | $(get shell_ratio) ± $(get shell_ratio_se) | $(get removed_ratio) | $(get ks) |"
      # The profile (solid fraction by distance from the bars) for the plot.
      awk -v m="$name" '/^ *\[ *[0-9.e+-]+, *[0-9.e+-]+\) rmax / {
          l = $0; gsub(/[\[\),]/, " ", l); split(l, f, " ")
          print m "\t" f[1] "\t" f[2] "\t" f[4] "\t" f[6] }' <<<"$report" >> "out/profile_phi$phi.tsv"
    done
  done
} > out/quality.md
cat out/quality.md
echo
# One plot per density: solid fraction against distance from the bars.
for phi in ${REINFORCE_BEAM_PHIS:-050 060 064}; do
  python3 "$top/bench/plot.py" "out/profile_phi$phi.svg" \
    "beam, solid fraction 0.${phi#0}: matrix solid fraction near the bars" < "out/profile_phi$phi.tsv"
done
echo "profiles: $(ls "$top"/examples/beam/out/profile_phi*.svg | tr '\n' ' ')"
echo "pictures: $(ls "$top"/examples/beam/out/*.png | tr '\n' ' ')"
# README.md: each block between markers is this run's table (the three
# densities only, so that a partial run leaves the README as it was).
if [ "${REINFORCE_BEAM_PHIS:-050 060 064}" = "050 060 064" ]; then
  bash "$top/scripts/fill_readme_block.sh" README.md out/table.md
  bash "$top/scripts/fill_readme_block.sh" README.md out/quality.md
  echo "README.md updated"
fi
