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
echo
echo "pictures: $(ls "$top"/examples/beam/out/*.png | tr '\n' ' ')"
