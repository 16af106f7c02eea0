#!/usr/bin/env bash
# A host run under mpirun for a test that has no script of its own, with
# the test scripts' Open MPI settings and its own Open MPI session directory
# (test_env.sh: the shared /tmp tree lets concurrent runs break each other).
#   mpi_run.sh NAME NP COMMAND...
set -euo pipefail
name=$1 np=$2
shift 2
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "$name"
mpirun -np "$np" "$@"
