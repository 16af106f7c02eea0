#!/usr/bin/env bash
# Benchmarks fix reinforce/invert against what a user has, on the same
# scenes in one run, and writes docs/benchmarks.md (bench/report.py).
#
#   bash bench/run.sh            full run (about 20 minutes on 2 cores)
#   bash bench/run.sh --quick    one small scene, one repeat, no report
#                                (run by the test suite so the harness cannot rot)
#
# Methods, each timed around its own operation only (not LAMMPS start-up):
#   fix       reinforce/invert, choose first|closest, tries 15|100|1000;
#             time = the fix's own f_ID[9]
#   delete    delete_atoms overlap with cutoff r_bar + rmax (removes every
#             target and more) and r_bar + rmin (misses some); time = wall
#             clock around the command (shell date in the input)
#   relax     dynamic relaxation, bars frozen: largest overlap and atoms
#             lost against elapsed time, a dump every chunk of steps
# plus the whole process time and peak memory (/usr/bin/time).
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
quick=0 repeats=5
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 repeats=1 ;;
    --repeats) repeats=$2; shift ;;
    *) echo "usage: bench/run.sh [--quick] [--repeats N]"; exit 2 ;;
  esac
  shift
done
# Inside ctest the build exists already: REINFORCE_BUILD names it.
if [ -z "${REINFORCE_BUILD:-}" ]; then source "$top/scripts/setup.sh"; fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
if [ "$quick" = 0 ] && ! command -v gnuplot >/dev/null; then
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get install -y -q gnuplot-nox >/dev/null
fi
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce"
check="$REINFORCE_BUILD/tests/check_scene"
make_scene="$REINFORCE_BUILD/tests/make_scene"
inputs="$top/bench/lammps"
out=${REINFORCE_BENCH_OUT:-$top/bench/out}
[ "$quick" = 1 ] && [ -z "${REINFORCE_BENCH_OUT:-}" ] && out=$(mktemp -d "${TMPDIR:-/tmp}/bench_quick.XXXXXX")
mkdir -p "$out/scenes" "$out/runs"
results="$out/results.tsv"
curves="$out/relax.tsv"
echo -e "scene\tatoms\tmethod\tparam\tnp\trep\ttargets\trelocated\tdeleted\tvolume_before\tvolume_after\toverlap\tsolves\top_seconds\twall_seconds\tpeak_kb" > "$results"
echo -e "scene\tchunk\tseconds\tatoms\tmatrix_rebar\tmatrix_matrix" > "$curves"

timed() {    # timed LOGFILE NP ARGS... : runs lmp_reinforce, prints "wall peak_kb"
  local log=$1 np=$2
  shift 2
  (cd "$inputs" && /usr/bin/time -f "%e %M" -o "$log.time" mpirun -np "$np" "$lmp" -log "$log" \
    -screen none "$@") || { echo "bench: run failed, see $log" >&2; tail -3 "$log" >&2; exit 1; }
  cat "$log.time"
}
result_value() {    # result_value LOG KEY : a value from the RESULT line
  grep '^RESULT' "$1" | tail -1 | tr ' ' '\n' | awk -v k="$2" 'prev == k {print; exit} {prev = $0}'
}

# bench_scene NAME DATAFILE RMIN RMAX RBAR NPS RELAX_CHUNKS RELAX_STEPS
bench_scene() {
  local name=$1 data=$2 rmin=$3 rmax=$4 rbar=$5 nps=$6 chunks=$7 steps=$8
  local atoms run np rep wall peak
  atoms=$(awk '/ atoms$/ {print $1; exit}' "$data")
  echo "== $name ($atoms atoms)"
  for np in $nps; do
    for rep in $(seq "$repeats"); do
      for variant in "closest 1000" "first 1000" "closest 100" "closest 15" "first 15"; do
        [ "$quick" = 1 ] && [ "$variant" != "closest 1000" ] && continue
        set -- $variant
        run="$out/runs/${name}_fix_$1_$2_np${np}_$rep"
        mkdir -p "$run"
        read -r wall peak < <(timed "$run/log" "$np" -in "$inputs/in.fix" -var scene "$data" \
          -var out "$run" -var choose "$1" -var tries "$2")
        echo -e "$name\t$atoms\tfix $1\t$2\t$np\t$rep\t$(result_value "$run/log" targets)\t$(result_value "$run/log" relocated)\t$(result_value "$run/log" deleted)\t$(result_value "$run/log" volume_before)\t$(result_value "$run/log" volume_after)\t$(result_value "$run/log" overlap)\t$(result_value "$run/log" solves)\t$(result_value "$run/log" seconds)\t$wall\t$peak" >> "$results"
        rm -f "$run/after.dump"
      done
      for cut in "$(awk -v a="$rbar" -v b="$rmax" 'BEGIN {print a + b}')" \
                 "$(awk -v a="$rbar" -v b="$rmin" 'BEGIN {print a + b}')"; do
        run="$out/runs/${name}_delete_${cut}_np${np}_$rep"
        mkdir -p "$run"
        read -r wall peak < <(timed "$run/log" "$np" -in "$inputs/in.delete" -var scene "$data" \
          -var out "$run" -var cutoff "$cut")
        local seconds overlap
        seconds=$(awk 'NR == 1 {a = $1} NR == 2 {printf "%.6f", $1 - a}' "$run/t0" "$run/t1")
        overlap=$("$check" --stats "$run/after.dump" --rmin "$rmin" | awk '{print $6}')
        echo -e "$name\t$atoms\tdelete_atoms overlap\t$cut\t$np\t$rep\t\t\t$(result_value "$run/log" deleted)\t\t\t$overlap\t\t$seconds\t$wall\t$peak" >> "$results"
        rm -f "$run/after.dump"
      done
    done
  done
  # Dynamic relaxation, once, serially: the largest overlap against time.
  run="$out/runs/${name}_relax"
  mkdir -p "$run"
  read -r wall peak < <(timed "$run/log" 1 -in "$inputs/in.relax" -var scene "$data" -var out "$run" \
    -var chunks "$chunks" -var chunk "$steps" -var rmin "$rmin")
  local t0 i
  t0=$(cat "$run/relax_0.time")
  for i in $(seq 0 "$chunks"); do
    read -r _ a _ _ _ mr _ mm < <("$check" --stats "$run/relax_$i.dump" --rmin "$rmin")
    echo -e "$name\t$i\t$(awk -v a="$t0" -v b="$(cat "$run/relax_$i.time")" 'BEGIN {printf "%.4f", b - a}')\t$a\t$mr\t$mm" >> "$curves"
    rm -f "$run/relax_$i.dump"
  done
  # deleted = atoms lost (thrown out of the box) by the end; overlap and time
  # of the last dump.
  awk -F'\t' -v n="$name" -v steps="$((chunks * steps))" -v w="$wall" -v p="$peak" -v atoms="$atoms" '
    $1 == n { if (first == "") first = $4; last = $4; t = $3; mr = $5 }
    END { printf "%s\t%s\trelax\t%s steps\t1\t1\t\t\t%d\t\t\t%s\t\t%s\t%s\t%s\n", n, atoms, steps, first - last, mr, t, w, p }' \
    "$curves" >> "$results"
}

if [ "$quick" = 1 ]; then
  "$make_scene" "$out/scenes/small.data" --fcc --box 0 0.2 0 0.1 0 0.1 --radius 0.005 0.0075 \
    --bar 0.01 0.05 0.05 0.19 0.05 0.05 0.005 0.0077
  bench_scene small "$out/scenes/small.data" 0.005 0.0075 0.005 "1" 2 20
  lines=$(($(wc -l < "$results") - 1))
  echo "bench --quick: $lines result rows, $(($(wc -l < "$curves") - 1)) relaxation points in $out"
  [ "$lines" -eq 4 ] && [ "$(wc -l < "$curves")" -eq 4 ] || { echo "bench --quick: missing rows"; exit 1; }
  awk -F'\t' 'NR > 1 && $3 == "fix closest" && ($7 == "" || $14 == "") {bad = 1} END {exit bad}' "$results" \
    || { echo "bench --quick: fix row incomplete"; exit 1; }
  [ -z "${REINFORCE_BENCH_OUT:-}" ] && rm -rf "$out"
  exit 0
fi

beam="$top/examples/beam/data"
for phi in 050 060 064; do
  scene="$out/scenes/beam$phi.data"
  [ -f "$scene" ] || mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi$phi.data.gz" \
    -var bars "$beam/bars.data" -var out "$scene" -log none -screen none
  bench_scene "beam$phi" "$scene" 0.0025 0.0075 0.005 "1 2" 20 500
done

# The slab: the 0.60 beam packing replicated 2 x 5 x 2 (1.0 x 1.25 x 0.5 m,
# 573k matrix spheres) with a mesh of bars 0.1 m apart in two layers.
slab="$out/scenes/slab.data"
if [ ! -f "$slab" ]; then
  bash "$top/bench/make_bars.sh" "$out/scenes/mesh.data" 1.0 1.25 0.5 mesh 0.1 0.04
  mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
    -var bars "$out/scenes/mesh.data" -var out "$slab" -var rep "2 5 2" -log none -screen none
fi
repeats_full=$repeats repeats=3
bench_scene slab "$slab" 0.0025 0.0075 0.005 "1 2" 2 100
repeats=$repeats_full

# Scaling: the same single bar in growing scenes (work fixed, size grows),
# and a growing number of bars in one scene (size fixed, work grows).
for rep in "0.125:1 1 1" "0:1 1 1" "0:2 2 1" "0:4 2 2" "0:4 4 2"; do
  cut=${rep%%:*} r=${rep##*:}
  name="size_$(echo "$r" | tr -d ' ')_cut$cut"
  scene="$out/scenes/$name.data"
  # One bar 0.125 m long, at mid-height of the first beam copy, in every scene.
  bash "$top/bench/make_bars.sh" "$out/scenes/onebar.data" 0.125 0.25 0.25 line 1
  mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
    -var bars "$out/scenes/onebar.data" -var out "$scene" -var rep "$r" -var cut "$cut" -log none -screen none
  for rep_i in $(seq "$repeats"); do
    run="$out/runs/${name}_$rep_i"; mkdir -p "$run"
    read -r wall peak < <(timed "$run/log" 1 -in "$inputs/in.fix" -var scene "$scene" -var out "$run")
    atoms=$(awk '/ atoms$/ {print $1; exit}' "$scene")
    echo -e "scaling_size\t$atoms\tfix closest\t1000\t1\t$rep_i\t$(result_value "$run/log" targets)\t$(result_value "$run/log" relocated)\t$(result_value "$run/log" deleted)\t\t\t$(result_value "$run/log" overlap)\t$(result_value "$run/log" solves)\t$(result_value "$run/log" seconds)\t$wall\t$peak" >> "$results"
    rm -f "$run/after.dump"
  done
  rm -f "$scene"
done
for bars in 1 2 4 8 16; do
  scene="$out/scenes/bars$bars.data"
  bash "$top/bench/make_bars.sh" "$out/scenes/nbars.data" 1.0 1.0 0.25 line "$bars"
  mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
    -var bars "$out/scenes/nbars.data" -var out "$scene" -var rep "2 4 1" -log none -screen none
  for rep_i in $(seq "$repeats"); do
    run="$out/runs/bars${bars}_$rep_i"; mkdir -p "$run"
    read -r wall peak < <(timed "$run/log" 1 -in "$inputs/in.fix" -var scene "$scene" -var out "$run")
    atoms=$(awk '/ atoms$/ {print $1; exit}' "$scene")
    echo -e "scaling_targets\t$atoms\tfix closest\t1000\t1\t$rep_i\t$(result_value "$run/log" targets)\t$(result_value "$run/log" relocated)\t$(result_value "$run/log" deleted)\t\t\t$(result_value "$run/log" overlap)\t$(result_value "$run/log" solves)\t$(result_value "$run/log" seconds)\t$wall\t$peak" >> "$results"
    rm -f "$run/after.dump"
  done
  rm -f "$scene"
done

/usr/bin/python3 "$top/bench/report.py" "$out" "$top/docs"
echo "wrote $top/docs/benchmarks.md"
