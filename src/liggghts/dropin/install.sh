#!/usr/bin/env bash
# Drops fix reinforce/invert into a LIGGGHTS-PUBLIC source tree (README, "Use
# with your own LAMMPS"):
#
#   bash src/liggghts/dropin/install.sh /path/to/LIGGGHTS-PUBLIC
#   then configure afresh and build as usual, e.g.
#   cmake -S /path/to/LIGGGHTS-PUBLIC/src -B build && cmake --build build
#   (or make auto / make mpi in src/)
#
# It copies the fix (with its walls, reinforce_liggghts_walls.* and
# reinforce_primitive_wall_access.cpp), the shared LAMMPS-family layer
# (src/host) and the engine (src/core, no host headers) into src/.
# LIGGGHTS's own style generator finds the FixStyle block in
# fix_reinforce_invert.h and registers the style like any other: no
# liggghts_reinforce and no reaching into Modify on this path (the walls
# still need reinforce_primitive_wall_access.cpp). Safe to run again (it refreshes the
# copies).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../../.." && pwd)
tree=${1:?usage: install.sh LIGGGHTS_TREE (the folder holding src/)}
[ -f "$tree/src/lammps.h" ] && [ -f "$tree/src/fix_multisphere.h" ] ||
  { echo "install.sh: $tree is not the top of a LIGGGHTS-PUBLIC source tree (src/lammps.h, src/fix_multisphere.h)"; exit 1; }
ours=("$top"/src/core/*.h "$top"/src/core/*.cpp "$top"/src/host/*.h "$top"/src/host/*.cpp
      "$top"/src/liggghts/reinforce_*.h "$top"/src/liggghts/reinforce_*.cpp)
for f in "${ours[@]}"; do
  b=$(basename "$f")
  if [ -e "$tree/src/$b" ] && ! grep -q 'reinforce' "$tree/src/$b"; then
    echo "install.sh: $tree/src/$b exists and is not ours: not overwriting it"; exit 1
  fi
done
cp "$top/src/liggghts/fix_reinforce_invert.h" "$top/src/liggghts/fix_reinforce_invert.cpp" "${ours[@]}" "$tree/src/"
echo "install.sh: fix reinforce/invert copied into $tree/src (configure afresh to register it)"
