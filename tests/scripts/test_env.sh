# Sourced by the test scripts, after `set -euo pipefail`, as
#   . "$(dirname "${BASH_SOURCE[0]}")/[../scripts/]test_env.sh" NAME
# Open MPI may run as root and oversubscribe (2 cores, tests up to 8
# processes); `work` is a fresh directory named after NAME, removed on exit;
# split_lists parses the scripts' "-- A -- B -- C" arguments.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/${1:-test}.XXXXXX")
trap 'rm -rf "$work"' EXIT

# split_lists -- A... -- B... -- C...: the three lists as the arrays
# list_a, list_b and list_c (a missing one empty).
split_lists() {
  list_a=() list_b=() list_c=()
  [ "${1:-}" = "--" ] && shift
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do list_a+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do list_b+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  list_c=("$@")
}
