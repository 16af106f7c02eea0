#!/usr/bin/env bash
# Regenerates the three cached matrix packings of the beam, data/
# matrix_phi050.data.gz, matrix_phi060.data.gz and matrix_phi064.data.gz,
# with Debian's lmp, serially (the random insertion and the dynamics depend
# on the process count; one process gives the same file every time), and
# the bars (data/bars.data). About 2, 3 and 3 minutes of one core
# (PACKING.md). Prints each packing's PACKING line and its times.
#
#   examples/beam/make_packings.sh [050 060 064]     (default: all three)
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p data
for name in "${@:-050 060 064}"; do
  for n in $name; do
    phi=0.${n#0}
    log=data/matrix_phi$n.log
    TIMEFORMAT="%R s wall, %U s cpu"
    times=$( { time lmp -in make_packing.lmp -var phi "$phi" -var seed 48271 \
                 -var out "data/matrix_phi$n.data" -log "$log" -screen none; } 2>&1 )
    echo "matrix_phi$n: $(grep '^PACKING' "$log"), $times"
    gzip -9 -n -f "data/matrix_phi$n.data"
    rm -f "$log"
  done
done
./make_bars.sh
