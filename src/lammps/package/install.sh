#!/usr/bin/env bash
# Puts fix reinforce/invert into a LAMMPS source tree as the package
# REINFORCE, for LAMMPS's own two builds (README, "Use with your own LAMMPS"):
#
#   bash src/lammps/package/install.sh /path/to/lammps
#   CMake:  cmake -S /path/to/lammps/cmake -B build -D PKG_REINFORCE=on ...
#   make:   cd /path/to/lammps/src && make yes-reinforce && make mpi
#
# It copies the fix, the shared LAMMPS-family layer (src/host) and the
# engine (src/core, no host headers) into
# src/REINFORCE/, and adds REINFORCE to the package list of cmake/CMakeLists.txt
# (LAMMPS 29Aug2024 has no other way to name a package to its CMake build).
# The engine needs C++17, LAMMPS's own standard since 22Jul2025; for an older
# LAMMPS configure with -D CMAKE_CXX_STANDARD=17 (CMake) or let `make
# yes-reinforce` add -std=c++17 to Makefile.package (Install.sh, as LAMMPS's
# own packages set their flags). Safe to run again: it refreshes the copies
# and patches nothing twice.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/../../.." && pwd)
tree=${1:?usage: install.sh LAMMPS_TREE (the folder holding src/ and cmake/)}
[ -f "$tree/src/lammps.h" ] && [ -f "$tree/cmake/CMakeLists.txt" ] ||
  { echo "install.sh: $tree is not the top of a LAMMPS source tree (src/lammps.h, cmake/CMakeLists.txt)"; exit 1; }

pkg="$tree/src/REINFORCE"
mkdir -p "$pkg"
cp "$top/src/lammps/fix_reinforce_invert.h" "$top/src/lammps/fix_reinforce_invert.cpp" "$pkg/"
cp "$top"/src/host/*.h "$top"/src/host/*.cpp "$pkg/"
cp "$top"/src/core/*.h "$top"/src/core/*.cpp "$pkg/"
cp "$here/Install.sh" "$here/README" "$pkg/"

# CMake: a standard package (sources globbed from src/REINFORCE, styles
# registered from its headers).
cm="$tree/cmake/CMakeLists.txt"
if ! grep -q '^  REINFORCE$' "$cm"; then
  sed -i 's/^set(STANDARD_PACKAGES$/&\n  REINFORCE/' "$cm"
  grep -q '^  REINFORCE$' "$cm" || { echo "install.sh: no STANDARD_PACKAGES list in $cm"; exit 1; }
fi
echo "install.sh: package REINFORCE in $pkg (cmake -D PKG_REINFORCE=on, with -D CMAKE_CXX_STANDARD=17 before LAMMPS 22Jul2025; or make yes-reinforce)"
