#!/usr/bin/env bash
# The seam test: the dense beam on a 4 x 1 x 1 grid; the written result must
# pass the checker and show no more deletions near the seams than elsewhere.
#   seams_test.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/seams.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$here/../lammps" && mpirun -np 4 "$build/src/lammps/lmp_reinforce" -in in.seams -var out "$work" \
   -log "$work/log" -screen none)
read -r _ targets relocated deleted kept < <(grep '^TOTALS' "$work/log")
echo "targets $targets relocated $relocated deleted $deleted kept $kept"
"$build/tests/check_scene" --before "$work/before.dump" --after "$work/after.dump" --deleted "$deleted" \
  --rmin 0.0025 --rmax 0.0075 --overlap-ok-before
"$here/seam_share.sh" "$work/before.dump" "$work/after.dump" 0.0075 0.125 0.25 0.375
