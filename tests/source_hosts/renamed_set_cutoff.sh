#!/usr/bin/env bash
# LAMMPS since its August 2026 feature release names NeighRequest::set_cutoff
# (double) set_cutoff_fixed (same meaning); the adapter picks the name at
# compile time (set_fixed_cutoff in src/lammps/fix_reinforce_invert.cpp).
# Two steps (lammps.cmake):
#
#   renamed_set_cutoff.sh tree LAMMPS_SRC DEST
#     copies LAMMPS_SRC (a tree's src/) to DEST with every set_cutoff( call
#     and declaration renamed set_cutoff_fixed(, and checks that
#     neigh_request.h declares set_cutoff_fixed(double) and that no
#     set_cutoff( is left in the copy (a tree that already has the new name
#     is copied as it is);
#
#   renamed_set_cutoff.sh test BUILD_DIR TARGET PLUGIN_SO PLAIN_PLUGIN_SO NM
#     builds TARGET (reinforceplugin.so compiled and linked as the plugin is,
#     against that copy) in BUILD_DIR: a compile error, e.g. the call
#     ->set_cutoff(list_cutoff) with no dispatch, fails the test. Then checks
#     with NM which name each plugin calls: PLUGIN_SO (renamed tree)
#     set_cutoff_fixed(double) only, PLAIN_PLUGIN_SO (the tree as it is)
#     set_cutoff(double) only.
set -euo pipefail
mode=${1:?usage: renamed_set_cutoff.sh tree LAMMPS_SRC DEST | test BUILD_DIR TARGET PLUGIN_SO PLAIN_PLUGIN_SO NM}
shift
case $mode in
tree)
  src=${1:?LAMMPS_SRC} dest=${2:?DEST}
  [ -f "$src/neigh_request.h" ] || { echo "FAIL: $src/neigh_request.h not found"; exit 1; }
  rm -rf "$dest"
  mkdir -p "$(dirname "$dest")"
  cp -R "$src" "$dest"    # new times: what is built from the copy is rebuilt
  { grep -rlE '\bset_cutoff\(' "$dest" || true; } | while IFS= read -r f; do
    sed -i -E 's/\bset_cutoff\(/set_cutoff_fixed(/g' "$f"
  done
  grep -qE '^[[:space:]]*void set_cutoff_fixed\(double\);' "$dest/neigh_request.h" ||
    { echo "FAIL: $dest/neigh_request.h declares no set_cutoff_fixed(double)"; exit 1; }
  if left=$(grep -rnE '\bset_cutoff\(' "$dest"); then
    echo "FAIL: set_cutoff( left in $dest:"; echo "$left"; exit 1
  fi
  touch "$dest/neigh_request.h"    # the build step's output, renamed or not
  echo "renamed_set_cutoff.sh: $dest: NeighRequest::set_cutoff renamed set_cutoff_fixed"
  ;;
test)
  build=${1:?BUILD_DIR} target=${2:?TARGET} plugin=${3:?PLUGIN_SO} plain=${4:?PLAIN_PLUGIN_SO} nm=${5:?NM}
  echo "== cmake --build $build --target $target"
  cmake --build "$build" --target "$target" ||
    { echo "FAIL: the adapter does not build against a LAMMPS with set_cutoff renamed set_cutoff_fixed"; exit 1; }
  # calls SO: the NeighRequest cutoff setters SO needs from lmp, one a line
  calls() { "$nm" -DC --undefined-only "$1" | grep -oE 'LAMMPS_NS::NeighRequest::set_cutoff[A-Za-z_]*\(double\)' | sort -u; }
  [ -f "$plain" ] || { echo "FAIL: $plain not built"; exit 1; }
  got=$(calls "$plugin") want="LAMMPS_NS::NeighRequest::set_cutoff_fixed(double)"
  [ "$got" = "$want" ] || { echo "FAIL: $plugin calls '${got//$'\n'/, }', not $want"; exit 1; }
  got=$(calls "$plain") want="LAMMPS_NS::NeighRequest::set_cutoff(double)"
  [ "$got" = "$want" ] || { echo "FAIL: $plain calls '${got//$'\n'/, }', not $want"; exit 1; }
  echo "PASS: the plugin builds against set_cutoff_fixed (renamed tree) and calls it; against the tree as it is it calls set_cutoff"
  ;;
*)
  echo "renamed_set_cutoff.sh: unknown mode '$mode' (tree or test)"; exit 2
  ;;
esac
