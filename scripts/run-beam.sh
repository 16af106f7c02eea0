#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, and runs the
# seed paper's reinforced beam (examples/beam) at the three densities, with
# lmp_reinforce under mpirun (REINFORCE_BEAM_NP processes, default 2).
# Writes examples/beam/out/: a picture, a dump and a data file per density,
# and table.md.
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
      line=$("$quality" --before "out/before_phi$phi.dump" --after "$dir/beam_phi$phi.dump" \
        --quiet-profile | grep '^QUALITY')
      get() { tr ' ' '\n' <<<"$line" | awk -F= -v k="$1" '$1 == k {print $2}'; }
      case $method in
        fix) name="fix defaults" ;;
        fit) name="fix size fit (seed paper)" ;;
        delete) name="delete_atoms overlap 0.0125" ;;
      esac
      echo "| 0.${phi#0} | $name | $(get deleted) | $(get shell_ratio) ± $(get shell_ratio_se) | $(get removed_ratio) | $(get ks) |"
    done
  done
} > out/quality.md
cat out/quality.md
echo
echo "pictures: $(ls "$top"/examples/beam/out/*.png | tr '\n' ' ')"
