#!/usr/bin/env bash
# make_scene, then every atom ID raised by 5,000,000,000 (past 32 bits), for
# the LAMMPS built with LAMMPS_SIZES=bigbig (64-bit atom IDs).
#   make_scene_big_ids.sh MAKE_SCENE DATA_FILE [make_scene args...]
set -euo pipefail
make_scene=$1 data=$2
shift 2
"$make_scene" "$data" "$@"
awk 'BEGIN { shift = 5000000000 }
     /^Atoms/ { atoms = 1; print; next }
     atoms && /^[A-Z]/ { atoms = 0 }
     atoms && NF > 0 { $1 = sprintf("%.0f", $1 + shift) }
     { print }' "$data" >"$data.big"
mv "$data.big" "$data"
