#!/usr/bin/env bash
# Installs what the build needs (Debian packages) when it is missing, then
# configures and builds everything into build/. Sourced by the README's main
# command (run-beam.sh) and the benchmark scripts, run by test.sh; safe to
# run again (does nothing that is already done).
#
# A failed install, configure or build stops it with "setup: FAILED: ..."
# and status 1 (returned when sourced, exit status when run), whatever the
# caller's shell options: each step is checked explicitly, because bash
# ignores `set -e` in a file sourced as `source setup.sh || ...`.
#
# Environment: REINFORCE_BUILD_DIR (default build/), REINFORCE_CMAKE_ARGS
# (extra cmake arguments), REINFORCE_SKIP (hosts left out on purpose, e.g.
# "liggghts": their packages are not installed; -DREINFORCE_LIGGGHTS=OFF in
# REINFORCE_CMAKE_ARGS does the same).
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# setup_skips HOST: true when the host is left out on purpose.
setup_skips() {
  local h=$1 H
  H=$(tr '[:lower:]' '[:upper:]' <<<"$h")
  [[ ",${REINFORCE_SKIP:-}," =~ [,[:space:]]$h[,[:space:]] ]] && return 0
  [[ " ${REINFORCE_CMAKE_ARGS:-} " =~ [[:space:]]-DREINFORCE_${H}(:BOOL)?=(OFF|0|NO|FALSE|off|no|false)[[:space:]] ]]
}

packages=(build-essential cmake libopenmpi-dev openmpi-bin libfmt-dev libgtest-dev clang
          libclang-rt-14-dev time ccache     # ccache: the source-built hosts' builds (test.sh)
          python3                            # the layout command (src/layout)
          gnuplot-nox)                       # the plots of bench/ and run-beam.sh (bench/plot.py)
setup_skips lammps || packages+=(lammps liblammps-dev)
setup_skips liggghts || packages+=(liggghts libliggghts-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -q ||
    { echo "setup: FAILED: apt-get update (exit $?)" >&2; return 1 2>/dev/null || exit 1; }
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends \
    "${missing[@]}" ||
    { echo "setup: FAILED: apt-get install ${missing[*]} (exit $?)" >&2; return 1 2>/dev/null || exit 1; }
fi

build="${REINFORCE_BUILD_DIR:-$top/build}"
# Compiled through ccache (installed above), in the folder the source-built
# hosts use: a second clone on the same machine compiles nothing again
# (paths taken relative to the clone's top).
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/reinforce-ccache}" CCACHE_BASEDIR="$top"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
# shellcheck disable=SC2086    # REINFORCE_CMAKE_ARGS: words
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" ${REINFORCE_CMAKE_ARGS:-} >/dev/null ||
  { echo "setup: FAILED: cmake configure of $build (exit $?)" >&2; return 1 2>/dev/null || exit 1; }
cmake --build "$build" -j"${REINFORCE_BUILD_JOBS:-$(nproc)}" ||
  { echo "setup: FAILED: build in $build (exit $?)" >&2; return 1 2>/dev/null || exit 1; }

# Open MPI refuses root and more ranks than cores unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export REINFORCE_BUILD="$build"
