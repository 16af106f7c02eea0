#!/usr/bin/env bash
# Installs what the build needs (Debian packages) when it is missing, then
# configures and builds everything into build/. Sourced by the two README
# commands; safe to run again (does nothing that is already done).
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(build-essential cmake lammps liblammps-dev liggghts libliggghts-dev
          libopenmpi-dev openmpi-bin libfmt-dev libgtest-dev clang libclang-rt-14-dev time)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

build="${REINFORCE_BUILD_DIR:-$top/build}"
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release ${REINFORCE_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j"$(nproc)"

# Open MPI refuses root and more ranks than cores unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export REINFORCE_BUILD="$build"
