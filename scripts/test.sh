#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
cd "$REINFORCE_BUILD"
ctest --output-on-failure -j"${REINFORCE_TEST_JOBS:-2}" "$@"
