#!/usr/bin/env bash
# Makes the quality tests' scenes with grow_packing (tests/quality/README.md):
#   make_scenes.sh GROW_PACKING OUTDIR [CASE...]   (cases: wide narrow dense one fibres)
# For each case, OUTDIR/CASE/ gets
#   before.data   the matrix grown alone, then the bars added (the fix's input)
#   ref.data      the same law grown around the same bars (the reference)
#   boundary      "f f f" or "p p p"
#   make_scenes.sh --args CASE    prints the case's grow_packing arguments
#                                 (box, law, bars), one a line: the benchmark
#                                 grows the same scenes (bench/run.sh)
set -euo pipefail
print_args=""
if [ "${1:-}" = --args ]; then
  print_args=${2:?usage: make_scenes.sh --args CASE}
  set -- "" "" "$print_args"
fi
grow=$1 out=$2
shift 2
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(wide narrow dense)
box=(--box 0 0.18 0 0.14 0 0.14)
# Three bars of overlapping rebar spheres (radius 5 mm, 7.5 mm apart): two
# along x, one of them through the box centre (it crosses the subdomain seams
# at 2 and 4 processes), one along y. With walls the end spheres touch the
# walls; in the periodic box the chains close through the boundary.
walls_bars=(--bar 0.005 0.07 0.07 0.175 0.07 0.07 0.005 0.0075
            --bar 0.005 0.035 0.035 0.175 0.035 0.035 0.005 0.0075
            --bar 0.09 0.005 0.105 0.09 0.135 0.105 0.005 0.0075)
periodic_bars=(--bar 0.00375 0.07 0.07 0.17625 0.07 0.07 0.005 0.0075
               --bar 0.00375 0.035 0.035 0.17625 0.035 0.035 0.005 0.0075
               --bar 0.09 0.00375 0.105 0.09 0.13625 0.105 0.005 0.0075)
# fibre_bars N LX LY LZ: N thin fibres (chains of 1 mm spheres, 1.5 mm
# apart, 30 mm long) in a box LX x LY x LZ, their centres and directions
# from a fixed pseudo-random sequence, each wholly inside the box (centres
# at least 20 mm from each face).
fibre_bars() {
  awk -v n="$1" -v lx="$2" -v ly="$3" -v lz="$4" 'BEGIN {
    s = 12345; pi = 3.141592653589793
    for (f = 0; f < n; f++) {
      for (d = 0; d < 5; d++) { s = (s * 1103515245 + 12345) % 2147483648; u[d] = s / 2147483648 }
      cx = 0.02 + u[0] * (lx - 0.04); cy = 0.02 + u[1] * (ly - 0.04); cz = 0.02 + u[2] * (lz - 0.04)
      ct = 2 * u[3] - 1; st = sqrt(1 - ct * ct); ph = 2 * pi * u[4]
      dx = 0.015 * st * cos(ph); dy = 0.015 * st * sin(ph); dz = 0.015 * ct
      printf "--bar\n%.6f\n%.6f\n%.6f\n%.6f\n%.6f\n%.6f\n0.001\n0.0015\n", cx - dx, cy - dy, cz - dz, cx + dx, cy + dy, cz + dz
    }
  }'
}
# fibres: 200 fibres in the whole box (the benchmark's scene, bench/run.sh).
mapfile -t fibre_bars < <(fibre_bars 200 0.18 0.14 0.14)
# fibres_small: the tests' fibre scene, the same law and fibres at about the
# same number per volume in a box of a quarter of the volume (the
# regrowth of the shrunk targets is most of the fibre tests' time).
small_fibres_box=(--box 0 0.09 0 0.1 0 0.1)
mapfile -t small_fibre_bars < <(fibre_bars 50 0.09 0.1 0.1)
for c in "${cases[@]}"; do
  case $c in
    wide)   args=(--radius 0.0025 0.0075 --phi 0.58 --boundary f f f "${walls_bars[@]}"); bnd="f f f" ;;
    narrow) args=(--radius 0.004 0.005 --phi 0.58 --boundary f f f "${walls_bars[@]}"); bnd="f f f" ;;
    dense)  args=(--radius 0.0025 0.0075 --phi 0.64 --boundary p p p "${periodic_bars[@]}"); bnd="p p p" ;;
    one)    args=(--radius 0.004 0.004 --phi 0.56 --boundary f f f "${walls_bars[@]}"); bnd="f f f" ;;
    fibres) args=(--radius 0.0025 0.0075 --phi 0.58 --boundary f f f "${fibre_bars[@]}"); bnd="f f f" ;;
    fibres_small)
            args=(--radius 0.0025 0.0075 --phi 0.58 --boundary f f f "${small_fibre_bars[@]}"); bnd="f f f" ;;
    *) echo "make_scenes.sh: unknown case $c"; exit 2 ;;
  esac
  cbox=("${box[@]}")
  [ "$c" = fibres_small ] && cbox=("${small_fibres_box[@]}")
  if [ -n "$print_args" ]; then printf '%s\n' "${cbox[@]}" "${args[@]}"; exit 0; fi
  mkdir -p "$out/$c"
  "$grow" "$out/$c/before.data" "${cbox[@]}" "${args[@]}" --seed 11
  # Around 200 thin fibres grow_packing jams (overlaps of 1.6 rmin after
  # 5 minutes): the fibre scene has no reference.
  [[ "$c" == fibres* ]] || "$grow" "$out/$c/ref.data" "${cbox[@]}" "${args[@]}" --seed 12 --around-bars
  echo "$bnd" > "$out/$c/boundary"
done
