#!/usr/bin/env bash
# Builds what the source-built hosts' tests need (run by scripts/test.sh):
#   prepare.sh BUILD_DIR
# with the trees named by the environment, each a source tree or its .tar.gz
# (unpacked into BUILD_DIR/trees/):
#   REINFORCE_LAMMPS_SOURCE    a LAMMPS tree (src/, cmake/): PLUGIN, GRANULAR,
#                              RIGID, EXTRA-FIX must be in it
#   REINFORCE_LIGGGHTS_SOURCE  a LIGGGHTS-PUBLIC tree (src/)
# Configures BUILD_DIR with REINFORCE_SOURCE_HOST_TESTS=ON and builds the
# hosts (tests/source_hosts/CMakeLists.txt) and the tools; exits non-zero
# when anything fails to unpack, configure or build.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${1:?usage: prepare.sh BUILD_DIR}
mkdir -p "$build/trees"
build=$(cd "$build" && pwd)

tree_of() {    # tree_of NAME PATH: prints the tree's top folder
  local name=$1 path=$2 dest="$build/trees/$1"
  if [ -d "$path" ]; then
    (cd "$path" && pwd)
  elif [ -f "$path" ]; then
    if [ ! -f "$dest/.unpacked" ] || [ "$path" -nt "$dest/.unpacked" ]; then
      rm -rf "$dest"; mkdir -p "$dest"
      tar -xzf "$path" -C "$dest" || { echo "prepare.sh: cannot unpack $path" >&2; return 1; }
      touch "$dest/.unpacked"
    fi
    local tops=("$dest"/*/)
    [ ${#tops[@]} -eq 1 ] || { echo "prepare.sh: $path does not hold one top folder" >&2; return 1; }
    (cd "${tops[0]}" && pwd)
  else
    echo "prepare.sh: $name source '$path' is neither a folder nor a file" >&2; return 1
  fi
}

args=(-DCMAKE_BUILD_TYPE=Release -DREINFORCE_SOURCE_HOST_TESTS=ON)
targets=(make_scene check_scene)
# host NAME CMAKE_NAME LABEL: the tree named by REINFORCE_<CMAKE_NAME>_SOURCE, if any.
host() {
  local name=$1 var=REINFORCE_$2_SOURCE tree
  if [ -n "${!var:-}" ]; then
    tree=$(tree_of "$name" "${!var}") || exit 1
    echo "source-built $3: $tree"
    args+=("-DREINFORCE_$2_SOURCE_DIR=$tree")
    targets+=("source_hosts_$name")
  else
    args+=("-DREINFORCE_$2_SOURCE_DIR=")
  fi
}
host lammps LAMMPS LAMMPS
host liggghts LIGGGHTS LIGGGHTS
cmake -S "$top" -B "$build" "${args[@]}" >"$build/configure.log" 2>&1 ||
  { tail -30 "$build/configure.log"; echo "prepare.sh: configure failed ($build/configure.log)"; exit 1; }
start=$(date +%s)
# The hosts' own build output goes to log files (hosts/ep/src/*-stamp/), shown on failure.
cmake --build "$build" -j"${REINFORCE_BUILD_JOBS:-$(nproc)}" --target "${targets[@]}" ||
  { echo "prepare.sh: build failed"; exit 1; }
echo "source-built hosts: built in $(( $(date +%s) - start )) s"
