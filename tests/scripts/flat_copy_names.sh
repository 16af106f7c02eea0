#!/usr/bin/env bash
# flat_copy_names.sh TOP [HOST_TARBALL ...]: the in-tree LAMMPS package and
# the LIGGGHTS drop-in copy the fix and the engine into a host's flat src/
# (LAMMPS's `make yes-reinforce` copies src/REINFORCE/*.cpp and *.h there).
# Runs both install scripts on empty stand-in trees and checks that every
# source file they copy is named reinforce_* or fix_reinforce_invert.*, and
# that no such name is a file of the given host source tarballs.
set -euo pipefail
top=${1:?usage: flat_copy_names.sh TOP [HOST_TARBALL ...]}
shift
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

mkdir -p "$scratch/lammps/src" "$scratch/lammps/cmake" "$scratch/liggghts/src"
touch "$scratch/lammps/src/lammps.h" "$scratch/liggghts/src/lammps.h" \
      "$scratch/liggghts/src/fix_multisphere.h"
printf 'set(STANDARD_PACKAGES\n  ASPHERE)\n' > "$scratch/lammps/cmake/CMakeLists.txt"
bash "$top/src/lammps/package/install.sh" "$scratch/lammps" > /dev/null
bash "$top/src/liggghts/dropin/install.sh" "$scratch/liggghts" > /dev/null

copied=$( (cd "$scratch/lammps/src/REINFORCE" && ls -- *.cpp *.h; \
           cd "$scratch/liggghts/src" && ls -- *.cpp *.h) | grep -vxE 'lammps\.h|fix_multisphere\.h' | sort -u)
count=$(echo "$copied" | wc -l)
[ "$count" -ge 20 ] || { echo "FAIL: only $count files copied: $copied"; exit 1; }
bad=$(echo "$copied" | grep -vE '^(reinforce_|fix_reinforce_invert\.)' || true)
[ -z "$bad" ] || { echo "FAIL: copied without the reinforce_ prefix: $bad"; exit 1; }

# A host source named but missing or unreadable fails: a check dropped in
# silence would pass without checking anything.
for tarball in "$@"; do
  if [ -d "$tarball" ]; then    # an unpacked source tree
    hosts=$(cd "$tarball" && find . -path '*/src/*' -type f | sed 's|.*/||' | sort -u)
  elif [ -f "$tarball" ] && [[ "$tarball" == *.tar.gz ]]; then
    hosts=$(tar tzf "$tarball" | grep -E '/src/' | sed 's|.*/||' | sort -u) ||
      { echo "FAIL: cannot list host tarball $tarball"; exit 1; }
  else
    echo "FAIL: host source $tarball named but not found (neither a source tree nor a .tar.gz)"; exit 1
  fi
  [ -n "$hosts" ] || { echo "FAIL: no src/ file in host source $tarball"; exit 1; }
  clash=$(comm -12 <(echo "$copied") <(echo "$hosts") | grep -vE '^fix_reinforce_invert\.' || true)
  [ -z "$clash" ] || { echo "FAIL: $(basename "$tarball") has files named like ours: $clash"; exit 1; }
  echo "no name shared with $(basename "$tarball") ($(echo "$hosts" | wc -l) names)"
done
echo "PASS: $count files copied into flat host trees, every one named reinforce_* or fix_reinforce_invert.*"
