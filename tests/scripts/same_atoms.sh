#!/usr/bin/env bash
# SCENE_POST for run_scene.sh with SCENE_REFERENCE=1: the scene written by
# this run and by the same input on one process hold identical atoms (ids,
# types, positions and radii, as written with %.17g: bit for bit).
#   same_atoms.sh CHECK_SCENE BEFORE AFTER REFERENCE_AFTER
set -euo pipefail
exec "$1" --same "$3" "$4"
