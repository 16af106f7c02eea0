#!/usr/bin/env bash
# The in-tree package for LAMMPS's traditional make: install.sh into a copy
# of the tree, then `make yes-reinforce` puts the fix and the engine into
# src/ with C++17 in Makefile.package, and `make no-reinforce` takes them out.
# (The make build itself is not run: the CMake build of the package is.)
#   make_install_test.sh LAMMPS_TREE
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/make_install.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -a "$1/src" "$1/cmake" "$work/"
bash "$here/../../src/lammps/package/install.sh" "$work"
cd "$work/src"
make yes-reinforce
for f in fix_reinforce_invert.cpp fix_reinforce_invert.h reinforce_fix_base.cpp reinforce_fix_host.cpp reinforce_invocation.cpp reinforce_relocation.cpp; do
  [ -f "$f" ] || { echo "FAIL: make yes-reinforce did not install $f"; exit 1; }
done
grep -q '^PKG_INC = -std=c++17' Makefile.package || { echo "FAIL: no -std=c++17 in Makefile.package"; exit 1; }
grep -q 'FixStyle(reinforce/invert' fix_reinforce_invert.h || { echo "FAIL: no style block"; exit 1; }
make no-reinforce
[ ! -e fix_reinforce_invert.cpp ] || { echo "FAIL: make no-reinforce left the fix in src/"; exit 1; }
grep -q 'std=c++17' Makefile.package && { echo "FAIL: make no-reinforce left -std=c++17"; exit 1; }
echo "PASS: make yes-reinforce / no-reinforce"
