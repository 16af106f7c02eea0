# Sourced by the test scripts, after `set -euo pipefail`, as
#   . "$(dirname "${BASH_SOURCE[0]}")/[../scripts/]test_env.sh" NAME
# Open MPI may run as root and oversubscribe (2 cores, tests up to 8
# processes); `work` is a fresh directory named after NAME, removed on exit.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/${1:-test}.XXXXXX")
trap 'rm -rf "$work"' EXIT
