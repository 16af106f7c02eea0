#!/usr/bin/env bash
# After the overlaps are dealt with by each method (the fix, delete_atoms
# overlap, a partial dynamic relaxation, nothing), a stiff Hertz run of 1000
# steps: the largest kinetic energy it reaches. Writes docs/stiff.md.
#   bash bench/stiff.sh       (after bench/run.sh has made the scenes, or it makes beam060)
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${REINFORCE_BUILD:-}" ]; then source "$top/scripts/setup.sh"; fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce"
out=${REINFORCE_BENCH_OUT:-$top/bench/out}/stiff
scene=${REINFORCE_BENCH_OUT:-$top/bench/out}/scenes/beam060.data
mkdir -p "$out" "$(dirname "$scene")"
[ -f "$scene" ] || "$lmp" -in "$top/bench/lammps/in.prepare" -var matrix "$top/examples/beam/data/matrix_phi060.data.gz" \
  -var bars "$top/examples/beam/data/bars.data" -var out "$scene" -log none -screen none
commit=$(git -C "$top" rev-parse --short HEAD 2>/dev/null || echo unknown)
spheres=$(awk '/ atoms$/ {printf "%\047d", $1; exit}' "$scene")
rows=()
for method in fix delete relax none; do
  mkdir -p "$out/$method"
  start=$(date +%s.%N)
  (cd "$top/bench/lammps" && "$lmp" -in in.stiff -var scene "$scene" -var method "$method" -var out "$out/$method" \
     -log "$out/$method/log" -screen none)
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}')
  atoms=$(grep '^STIFF' "$out/$method/log" | awk '{print $5}')
  kemax=$(awk '!/^#/ && $2 > m {m = $2} END {printf "%.3g", m}' "$out/$method/ke.txt")
  keend=$(awk '!/^#/ {e = $2} END {printf "%.3g", e}' "$out/$method/ke.txt")
  echo "$method: atoms $atoms, largest kinetic energy $kemax J, at the end $keend J"
  rows+=("| $method | $atoms | $kemax | $keend | $seconds |")
done
{
  echo "# The stiff follow-on run after each method"
  echo
  echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') at commit $commit on $(nproc) cores by \`bash bench/stiff.sh\`"
  echo "(this page is written by it; the whole run's time is wall clock on a shared machine). Scene: the"
  echo "beam at solid fraction 0.60 with its five bars ($spheres spheres). Each method first deals with"
  echo "the overlaps with the bars: \`fix reinforce/invert\` (defaults), \`delete_atoms overlap 0.0125\`"
  echo "(r_bar + rmax), a partial dynamic relaxation (2000 steps of soft, damped Hertz contacts with"
  echo "walls, E = 10 MPa), or nothing. Then every method gets the same stiff run: frictionless Hertz,"
  echo "E = 30 GPa (concrete), no damping, bars frozen, time step 0.2 of the Rayleigh time of the"
  echo "smallest sphere, 1000 steps. Any overlap left becomes kinetic energy. The packing's own"
  echo "overlaps from its compression (below 1e-6 rmin) are there for every method."
  echo
  echo "| method | atoms | largest kinetic energy (J) | kinetic energy at the end (J) | whole run (s) |"
  echo "|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} > "$top/docs/stiff.md"
cat "$top/docs/stiff.md"
