#!/usr/bin/env bash
# The scene of the N > 0 tests of both hosts (every_test.sh,
# ../liggghts/every.sh): one bar along x in an fcc packing; the inputs
# (in.every) add the later bars between runs.
#   every_scene.sh BUILD_DIR OUT.data
set -euo pipefail
"$1/tests/make_scene" "$2" --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
  --bar 0.01 0.07 0.1 0.39 0.07 0.1 0.005 0.0075
