#!/usr/bin/env bash
# Benchmarks fix reinforce/invert against what a user has, on the same
# scenes in one run, and writes docs/benchmarks.md (bench/report.py): every
# sentence and number of that page comes from this run.
#
#   bash bench/run.sh            full run (about 30 minutes on 2 cores, plus
#                                about 15 the first time: the make_packing.lmp
#                                references, then cached in bench/out/scenes)
#   bash bench/run.sh --quick    one small scene, one repeat, every method and
#                                table; the page goes to a scratch folder
#                                (run by the test suite so the harness cannot rot)
#   REINFORCE_BENCH_SKIP="slab scaling"  leaves parts out (the page says so)
#   REINFORCE_BENCH_OUT=DIR, REINFORCE_BENCH_DOCS=DIR  other folders for the raw
#                                results (bench/out) and the page (docs)
#
# Methods, each timed around its own operation only (not LAMMPS start-up):
#   fix       reinforce/invert: defaults (size keep, choose closest, tries
#             1000, no pushing), size fit (the seed paper's mode), choose
#             first, tries 15 (paper-era budget), push rmax (size keep with
#             pushing), grow each (the regrowth's seeds one by one, in a
#             zone of 3 rmax); time = the fix's own f_ID[9]
#   delete    delete_atoms overlap with cutoff r_bar + rmax (removes every
#             target and more) and r_bar + rmin (misses some); time = wall
#             clock around the command (shell date in the input)
#   relax     dynamic relaxation, bars frozen: largest overlap and atoms
#             lost against elapsed time, a dump every chunk of steps
#   grow      the reference a user would otherwise make: the same packing law
#             grown around the bars from the start (build/tests/grow_packing
#             --around-bars), its wall time and its own scene quality; for
#             the beams also the beam's own law, the LAMMPS growth that
#             made their packings (examples/beam/make_packing.lmp -var bars,
#             minutes each the first time, then cached)
# plus the whole process time and peak memory (/usr/bin/time), scene
# quality (build/tests/scene_quality, before and after dumps, against the
# grown reference where there is one), a narrow-size scene (radii 4-5 mm),
# the LIGGGHTS example (liggghts_reinforce), the fix's time on 1 and 2
# processes interleaved (speedup), and against rebar radius and search gap.
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
  $sudo_cmd apt-get install -y -q gnuplot-nox >/dev/null || echo "bench: no gnuplot, no plots" >&2
fi
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce"
check="$REINFORCE_BUILD/tests/check_scene"
quality="$REINFORCE_BUILD/tests/scene_quality"
make_scene="$REINFORCE_BUILD/tests/make_scene"
grow="$REINFORCE_BUILD/tests/grow_packing"
liggghts="$REINFORCE_BUILD/src/liggghts/liggghts_reinforce"
inputs="$top/bench/lammps"
out=${REINFORCE_BENCH_OUT:-$top/bench/out}
docs=${REINFORCE_BENCH_DOCS:-$top/docs}    # the page and its plots (a trial run can write elsewhere)
if [ "$quick" = 1 ] && [ -z "${REINFORCE_BENCH_OUT:-}" ]; then
  out=$(mktemp -d "${TMPDIR:-/tmp}/bench_quick.XXXXXX")
fi
[ "$quick" = 1 ] && docs="$out/docs"
mkdir -p "$out/scenes" "$out/runs" "$docs"
results="$out/results.tsv"
curves="$out/relax.tsv"
qual="$out/quality.tsv"
meta="$out/meta.tsv"
refs="$out/reference.tsv"
versus="$out/versus.tsv"      # each method against a second reference (make_packing.lmp's)
profiles="$out/profile.tsv"   # the fix's defaults: profile beside each reference's
echo -e "scene\tatoms\tmethod\tparam\tnp\trep\ttargets\trelocated\tdeleted\tvolume_before\tvolume_after\toverlap\tsolves\top_seconds\twall_seconds\tpeak_kb\tremoved\trounds\trebar\tbalance\tbusiest\tblocks" > "$results"
echo -e "scene\tchunk\tseconds\tatoms\tmatrix_rebar\tmatrix_matrix" > "$curves"
echo -e "scene\tmethod\tparam\tshell_ratio\tshell_ratio_se\tremoved_ratio\tks\ttargets\tdeleted\tmoved_nontargets\tbulk\tref_bulk\tref_shell_ratio\tshell_vs_reference\tbin_diff_max" > "$qual"
echo -e "scene\tkind\tseed\tmatrix\trebar\tbox\tphi\tradii\twall_seconds\tcpu_seconds\tgrown\tbulk\tshell_ratio\tshell_ratio_se" > "$refs"
echo -e "scene\treference\tmethod\tparam\tshell_ratio\tshell_ratio_se\tref_shell_ratio\tshell_vs_reference\tbin_diff_max\tbulk\tref_bulk" > "$versus"
echo -e "scene\treference\tmethod\tparam\tlo_rmax\thi_rmax\tphi\tphi_se\tref_phi\tref_phi_se" > "$profiles"
echo -e "key\tvalue" > "$meta"
meta() { echo -e "$1\t$2" >> "$meta"; }
meta quick "$quick"
meta repeats "$repeats"
meta started "$(date -u '+%Y-%m-%d %H:%M UTC')"
meta commit "$(git -C "$top" rev-parse --short HEAD 2>/dev/null || echo unknown)"
start_s=$(date +%s)
part() {    # part NAME: true when the part runs; records it, and the load average
  local p=$1
  if [[ " ${REINFORCE_BENCH_SKIP:-} " == *" $p "* ]]; then
    meta "skipped" "$p"; echo "== $p: skipped (REINFORCE_BENCH_SKIP)"; return 1
  fi
  meta "load_$p" "$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "== $p ($(date -u +%H:%M:%S), load $(cut -d' ' -f1 /proc/loadavg))"
  return 0
}

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
box_of() {    # box_of DATAFILE: "LX x LY x LZ"
  awk '/xlo xhi/ {x = $2 - $1} /ylo yhi/ {y = $2 - $1} /zlo zhi/ {z = $2 - $1; print x " x " y " x " z; exit}' "$1"
}
atoms_of() { awk '/ atoms$/ {print $1; exit}' "$1"; }
rebar_of() {    # rebar spheres of a scene data file (type 2)
  awk '/^Atoms/ {on = 1; next} /^(Velocities|Bonds)/ {on = 0} on && NF >= 7 && $2 == 2 {n++} END {print n + 0}' "$1"
}
before_dump() {    # before_dump SCENE: the scene as a text dump (once)
  local d="${1%.data}.before.dump"
  [ -f "$d" ] || (cd "$inputs" && mpirun -np 1 "$lmp" -in in.dump -var scene "$1" -var out "$d" -log none -screen none)
  echo "$d"
}

# run_fix NAME SCENE METHOD PARAM NP REP [lmp -var pairs...]: one fix run, one row.
# Leaves the run folder's after.dump for the caller (quality), removes older ones.
run_fix() {
  local name=$1 scene=$2 method=$3 param=$4 np=$5 rep=$6
  shift 6
  local run="$out/runs/${name}_$(echo "$method $param" | tr -c 'A-Za-z0-9.\n-' '_')_np${np}_$rep"
  mkdir -p "$run"
  local wall peak
  read -r wall peak < <(timed "$run/log" "$np" -in "$inputs/in.fix" -var scene "$scene" -var out "$run" "$@")
  local v=()
  for k in targets relocated deleted volume_before volume_after overlap solves seconds; do v+=("$(result_value "$run/log" $k)"); done
  local IFS=$'\t'
  # The schedule line: the busiest process's targets over the rounds, the
  # balance between processes (1 = even) and the blocks with targets.
  local sched
  sched=$(sed -n 's/^fix reinforce\/invert: schedule: .* in \([0-9]*\) blocks, busiest process \([0-9]*\) targets over the rounds, balance \([0-9.]*\) over .*/\3\t\2\t\1/p' "$run/log" | tail -1)
  [ -n "$sched" ] || sched=$'\t\t'
  echo -e "$name\t$(atoms_of "$scene")\t$method\t$param\t$np\t$rep\t${v[*]}\t$wall\t$peak\t$(result_value "$run/log" removed)\t$(result_value "$run/log" rounds)\t${REBAR:-}\t$sched" >> "$results"
  last_run=$run
}
# run_delete NAME SCENE CUTOFF NP REP RMIN
run_delete() {
  local name=$1 scene=$2 cut=$3 np=$4 rep=$5 rmin=$6
  local run="$out/runs/${name}_delete_${cut}_np${np}_$rep" wall peak seconds overlap
  mkdir -p "$run"
  read -r wall peak < <(timed "$run/log" "$np" -in "$inputs/in.delete" -var scene "$scene" \
    -var out "$run" -var cutoff "$cut")
  seconds=$(awk 'NR == 1 {a = $1} NR == 2 {printf "%.6f", $1 - a}' "$run/t0" "$run/t1")
  overlap=$("$check" --stats "$run/after.dump" --rmin "$rmin" | awk '{print $6}')
  echo -e "$name\t$(atoms_of "$scene")\tdelete_atoms overlap\t$cut\t$np\t$rep\t\t\t$(result_value "$run/log" deleted)\t\t\t$overlap\t\t$seconds\t$wall\t$peak\t\t\t" >> "$results"
  last_run=$run
}
# quality_of NAME SCENE METHOD PARAM RMIN RMAX [AFTER]: scene_quality of the
# last run's after.dump (or AFTER; no before then when SCENE is "-"),
# against the grown reference ${refs_of[NAME]} when there is one, and
# again against ${lammps_refs_of[NAME]} (make_packing.lmp's) when there is
# one (a row of versus.tsv). For the fix's defaults the profiles beside each
# reference go to profile.tsv.
declare -A refs_of=() lammps_refs_of=()
# The methods whose profiles (solid fraction against distance from the bars)
# go to profile.tsv, for the report's plots.
profiled="|fix defaults|fix size fit (seed paper)|fix grow each|delete_atoms overlap|"
quality_value() {    # quality_value LINE KEY: a value from a QUALITY line
  tr ' ' '\n' <<<"$1" | awk -F= -v k="$2" '$1 == k {print $2}'
}
profile_rows() {    # profile_rows NAME REFERENCE METHOD PARAM < scene_quality output (REFERENCE "-": none)
  awk -v p="$1"$'\t'"$2"$'\t'"$3"$'\t'"$4" '
    /^ *\[ *[0-9.e+-]+, *[0-9.e+-]+\) rmax / {
      line = $0; gsub(/[\[\),]/, " ", line); n = split(line, f, " ")
      ref = ""; for (i = 1; i <= n; i++) if (f[i] == "ref") ref = f[i + 1] "\t" f[i + 3]
      if (ref == "") ref = "\t"
      print p "\t" f[1] "\t" f[2] "\t" f[4] "\t" f[6] "\t" ref
    }' >> "$profiles"
}
quality_of() {
  local name=$1 scene=$2 method=$3 param=$4 rmin=$5 rmax=$6 after=${7:-$last_run/after.dump} line out2
  local quiet=(--quiet-profile)
  [[ "$profiled" == *"|$method|"* ]] && quiet=()
  local args=(--after "$after" --rmin "$rmin" --rmax "$rmax" "${quiet[@]}")
  [ "$scene" != - ] && args+=(--before "$(before_dump "$scene")")
  [ -n "${refs_of[$name]:-}" ] && args+=(--reference "${refs_of[$name]}")
  out2=$("$quality" "${args[@]}" ${QUALITY_ARGS:-}) || { echo "bench: scene_quality failed" >&2; exit 1; }
  line=$(grep '^QUALITY' <<<"$out2") || { echo "bench: scene_quality failed" >&2; exit 1; }
  if [ -z "${quiet[*]}" ]; then
    if [ -n "${refs_of[$name]:-}" ]; then
      profile_rows "$name" grow_packing "$method" "$param" <<<"$out2"
    else
      profile_rows "$name" - "$method" "$param" <<<"$out2"
    fi
  fi
  local q=()
  for k in shell_ratio shell_ratio_se removed_ratio ks targets deleted moved_nontargets bulk ref_bulk \
           ref_shell_ratio shell_vs_reference bin_diff_max; do
    q+=("$(quality_value "$line" "$k")")
  done
  local IFS=$'\t'
  echo -e "$name\t$method\t$param\t${q[*]}" >> "$qual"
  if [ -n "${lammps_refs_of[$name]:-}" ]; then
    out2=$("$quality" --after "$after" --rmin "$rmin" --rmax "$rmax" --reference "${lammps_refs_of[$name]}" \
      "${quiet[@]}") || { echo "bench: scene_quality failed against ${lammps_refs_of[$name]}" >&2; exit 1; }
    line=$(grep '^QUALITY' <<<"$out2") || { echo "bench: scene_quality failed" >&2; exit 1; }
    [ -z "${quiet[*]}" ] && profile_rows "$name" make_packing.lmp "$method" "$param" <<<"$out2"
    q=()
    for k in shell_ratio shell_ratio_se ref_shell_ratio shell_vs_reference bin_diff_max bulk ref_bulk; do
      q+=("$(quality_value "$line" "$k")")
    done
    echo -e "$name\tmake_packing.lmp\t$method\t$param\t${q[*]}" >> "$versus"
  fi
}
# grow_scene NAME KIND OUT SEED RMIN RMAX PHI GROW_ARGS...: a packing by
# grow_packing (KIND "alone": the matrix, then the bars added, the fix's
# input; "around": grown around the bars, the reference), cached in
# scenes/ with its growth time (OUT.grow: wall and CPU seconds, date, then
# the arguments: other arguments grow it again), one row of reference.tsv,
# and for "around" its own scene quality.
grow_scene() {
  local name=$1 kind=$2 file=$3 seed=$4 rmin=$5 rmax=$6 phi=$7 line
  shift 7
  local extra=()
  [ "$kind" = around ] && extra=(--around-bars)
  local args=(--radius "$rmin" "$rmax" --phi "$phi" --seed "$seed" "$@" "${extra[@]}")
  if [ ! -f "$file" ] || [ ! -f "$file.grow" ] || [ "$(sed -n 2p "$file.grow")" != "${args[*]}" ]; then
    rm -f "$file" "${file%.data}.before.dump"
    /usr/bin/time -f "%e %U" -o "$file.time" "$grow" "$file" "${args[@]}" --max-seconds 600 > "$file.log" ||
      { echo "bench: grow_packing failed, see $file.log" >&2; cat "$file.log" >&2; exit 1; }
    printf '%s %s\n%s\n' "$(cat "$file.time")" "$(date -u '+%Y-%m-%d_%H:%M_UTC')" "${args[*]}" > "$file.grow"
    rm -f "$file.time"
  fi
  local wall cpu when matrix rebar box q=("" "" "")
  read -r wall cpu when < <(head -1 "$file.grow")
  matrix=$(awk '/^Atoms/ {on = 1; next} on && NF >= 7 && $2 == 1 {n++} END {print n + 0}' "$file")
  rebar=$(rebar_of "$file")
  box=$(box_of "$file")
  if [ "$kind" = around ]; then
    line=$("$quality" --after "$file" --rmin "$rmin" --rmax "$rmax" --quiet-profile | grep '^QUALITY') ||
      { echo "bench: scene_quality failed on $file" >&2; exit 1; }
    q=()
    for k in bulk shell_ratio shell_ratio_se; do
      q+=("$(tr ' ' '\n' <<<"$line" | awk -F= -v k="$k" '$1 == k {print $2}')")
    done
    refs_of[$name]=$file
  fi
  echo -e "$name\t$kind\t$seed\t$matrix\t$rebar\t$box\t$phi\t$rmin-$rmax\t$wall\t$cpu\t$when\t${q[0]}\t${q[1]}\t${q[2]}" >> "$refs"
}

# lammps_ref NAME OUT PHI SEED BARS RMIN RMAX: the reference grown by the
# beam's own packing law, examples/beam/make_packing.lmp with the bars
# present (frozen) from the start, as a LAMMPS user would run it (Debian's
# lmp, one process, several minutes). Cached in scenes/ like grow_scene:
# OUT.grow holds the wall and CPU seconds and the date, then the key (the
# arguments and checksums of the script and the bars file: another key
# grows it again), OUT.packing its PACKING line. One row of reference.tsv
# (kind "lammps"), its PACKING line in meta.tsv (packing_NAME), and its own
# scene quality; quality_of then measures every method against it too.
lammps_ref() {
  local name=$1 file=$2 phi=$3 seed=$4 bars=$5 rmin=$6 rmax=$7 line
  local script="$top/examples/beam/make_packing.lmp" plain_lmp
  plain_lmp=$(command -v lmp || echo "$lmp")
  local key="make_packing.lmp -var phi $phi -var seed $seed -var bars $(basename "$bars") script $(sha1sum < "$script" | cut -c1-12) bars $(sha1sum < "$bars" | cut -c1-12)"
  if [ ! -f "$file" ] || [ ! -f "$file.grow" ] || [ ! -f "$file.packing" ] || [ "$(sed -n 2p "$file.grow")" != "$key" ]; then
    rm -f "$file" "$file.packing"
    echo "== $name: growing with make_packing.lmp (several minutes)"
    (cd "$top/examples/beam" && /usr/bin/time -f "%e %U" -o "$file.time" "$plain_lmp" -in make_packing.lmp \
      -var phi "$phi" -var seed "$seed" -var bars "$bars" -var out "$file" -log "$file.log" -screen none) &&
      grep '^PACKING' "$file.log" | tail -1 | sed 's/^PACKING //' > "$file.packing" && [ -s "$file.packing" ] ||
      { echo "bench: make_packing.lmp failed, see $file.log" >&2; tail -3 "$file.log" >&2; rm -f "$file"; exit 1; }
    printf '%s %s\n%s\n' "$(cat "$file.time")" "$(date -u '+%Y-%m-%d_%H:%M_UTC')" "$key" > "$file.grow"
    rm -f "$file.time"
  fi
  local wall cpu when matrix rebar box q=()
  read -r wall cpu when < <(head -1 "$file.grow")
  matrix=$(awk '/^Atoms/ {on = 1; next} /^Velocities/ {on = 0} on && NF >= 7 && $2 == 1 {n++} END {print n + 0}' "$file")
  rebar=$(rebar_of "$file")
  box=$(box_of "$file")
  line=$("$quality" --after "$file" --rmin "$rmin" --rmax "$rmax" --quiet-profile | grep '^QUALITY') ||
    { echo "bench: scene_quality failed on $file" >&2; exit 1; }
  for k in bulk shell_ratio shell_ratio_se; do q+=("$(quality_value "$line" "$k")"); done
  lammps_refs_of[$name]=$file
  meta "packing_$name" "$(cat "$file.packing")"
  echo -e "$name\tlammps\t$seed\t$matrix\t$rebar\t$box\t$phi\t$rmin-$rmax\t$wall\t$cpu\t$when\t${q[0]}\t${q[1]}\t${q[2]}" >> "$refs"
}

# bench_scene NAME DATAFILE RMIN RMAX RBAR REPEATS: every method, 1 process,
# repeats interleaved; scene quality of the first repeat of each.
bench_scene() {
  local name=$1 data=$2 rmin=$3 rmax=$4 rbar=$5 reps=$6 rep cut
  echo "== $name ($(atoms_of "$data") atoms)"
  meta "box_$name" "$(box_of "$data")"
  for rep in $(seq "$reps"); do
    run_fix "$name" "$data" "fix defaults" 1000 1 "$rep"
    [ "$rep" = 1 ] && quality_of "$name" "$data" "fix defaults" 1000 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    run_fix "$name" "$data" "$size_fit" 1000 1 "$rep" -var opts "size fit"
    [ "$rep" = 1 ] && quality_of "$name" "$data" "$size_fit" 1000 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    run_fix "$name" "$data" "fix choose first" 1000 1 "$rep" -var choose first
    [ "$rep" = 1 ] && quality_of "$name" "$data" "fix choose first" 1000 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    run_fix "$name" "$data" "fix tries 15" 15 1 "$rep" -var tries 15
    [ "$rep" = 1 ] && quality_of "$name" "$data" "fix tries 15" 15 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    run_fix "$name" "$data" "fix push rmax" 1000 1 "$rep" -var opts "push $rmax"
    [ "$rep" = 1 ] && quality_of "$name" "$data" "fix push rmax" 1000 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    run_fix "$name" "$data" "fix grow each" 1000 1 "$rep" -var opts "grow each"
    [ "$rep" = 1 ] && quality_of "$name" "$data" "fix grow each" 1000 "$rmin" "$rmax"
    rm -f "$last_run/after.dump"
    for cut in "$(awk -v a="$rbar" -v b="$rmax" 'BEGIN {print a + b}')" \
               "$(awk -v a="$rbar" -v b="$rmin" 'BEGIN {print a + b}')"; do
      run_delete "$name" "$data" "$cut" 1 "$rep" "$rmin"
      [ "$rep" = 1 ] && quality_of "$name" "$data" "delete_atoms overlap" "$cut" "$rmin" "$rmax"
      rm -f "$last_run/after.dump"
    done
  done
}
# run_liggghts METHOD REP [KEYWORDS]: the LIGGGHTS example
# (examples/liggghts/in.liggghts: insert/pack, settling, two bars, the fix),
# one row from the fix's log line, scene quality of the data file it writes
# (no before: it writes none).
run_liggghts() {
  local method=$1 rep=$2 extra=${3:-}
  local run="$out/runs/liggghts_$(echo "$method" | tr -c 'A-Za-z0-9.\n-' '_')_$rep" wall peak line
  mkdir -p "$run"
  # LIGGGHTS 3.8 crashes in insert/pack under -screen none: the screen goes to a file.
  (cd "$top/examples/liggghts" && /usr/bin/time -f "%e %M" -o "$run/log.time" "$liggghts" -in in.liggghts \
    -var out "$run" -var tag bench -var extra "$extra" -log "$run/log" > "$run/screen") ||
    { echo "bench: liggghts run failed, see $run/log" >&2; tail -3 "$run/log" >&2; exit 1; }
  read -r wall peak < "$run/log.time"
  line=$(grep '^fix reinforce/invert: [0-9]' "$run/log" | tail -1)
  # "T targets, R relocated, D deleted (...), K kept, volume A -> B, max overlap O rmin,
  #  S solves, ..., N rounds, X s (rmin ...)"
  awk -v scene=liggghts -v method="$method" -v rep="$rep" -v wall="$wall" -v peak="$peak" \
      -v after="$(awk '/ atoms$/ {print $1; exit}' "$run/liggghts_bench.data")" '{
    sub(/^fix reinforce\/invert: /, "")
    for (i = 1; i <= NF; i++) {
      if ($(i + 1) ~ /^targets/) t = $i
      if ($(i + 1) ~ /^relocated/) r = $i
      if ($(i + 1) == "deleted") d = $i
      if ($i == "volume") { vb = $(i + 1); va = $(i + 3); sub(/,$/, "", va) }
      if ($i == "overlap") o = $(i + 1)
      if ($(i + 1) ~ /^solves/) s = $i
      if ($(i + 1) ~ /^rounds/) n = $i
      if ($(i + 1) == "s") x = $i
    }
    printf "%s\t%s\t%s\t1000\t1\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t\t%s\t\n", scene, after + d, method, rep,
      t, r, d, vb, va, o, s, x, wall, peak, n
  }' <<<"$line" >> "$results"
  last_run=$run
}
# relax NAME DATAFILE RMIN CHUNKS STEPS: dynamic relaxation, once, serially.
relax() {
  local name=$1 data=$2 rmin=$3 chunks=$4 steps=$5 run="$out/runs/${1}_relax" wall peak t0 i
  mkdir -p "$run"
  read -r wall peak < <(timed "$run/log" 1 -in "$inputs/in.relax" -var scene "$data" -var out "$run" \
    -var chunks "$chunks" -var chunk "$steps" -var rmin "$rmin")
  t0=$(cat "$run/relax_0.time")
  for i in $(seq 0 "$chunks"); do
    read -r _ a _ _ _ mr _ mm < <("$check" --stats "$run/relax_$i.dump" --rmin "$rmin")
    echo -e "$name\t$i\t$(awk -v a="$t0" -v b="$(cat "$run/relax_$i.time")" 'BEGIN {printf "%.4f", b - a}')\t$a\t$mr\t$mm" >> "$curves"
    rm -f "$run/relax_$i.dump"
  done
  awk -F'\t' -v n="$name" -v steps="$((chunks * steps))" -v w="$wall" -v p="$peak" -v atoms="$(atoms_of "$data")" '
    $1 == n { if (first == "") first = $4; last = $4; t = $3; mr = $5 }
    END { printf "%s\t%s\trelax\t%s steps\t1\t1\t\t\t%d\t\t\t%s\t\t%s\t%s\t%s\t\t\t\n", n, atoms, steps, first - last, mr, t, w, p }' \
    "$curves" >> "$results"
}
# speedup NAME DATAFILE REPEATS: the defaults on 1 and 2 processes, interleaved.
speedup() {
  local name=$1 data=$2 reps=$3 rep np
  for rep in $(seq "$reps"); do
    for np in 1 2; do
      run_fix "speedup_$name" "$data" "fix defaults" 1000 "$np" "$rep"
      rm -f "$last_run/after.dump"
    done
  done
}
# series_gap NAME DATAFILE RMAX REPEATS; series_rbar NAME MATRIX REPEATS CUT
series_gap() {
  local name=$1 data=$2 rmax=$3 reps=$4 rep g
  for rep in $(seq "$reps"); do
    for g in 1 10 100 1e20; do
      local gap
      gap=$([ "$g" = 1e20 ] && echo 1e20 || awk -v g="$g" -v r="$rmax" 'BEGIN {print g * r}')
      run_fix "gap" "$data" "fix search" "$g" 1 "$rep" -var opts "search $gap"
      rm -f "$last_run/after.dump"
    done
  done
}
series_rbar() {
  local matrix=$1 lx=$2 cut=$3 reps=$4 rep f scene
  # One bar along x at mid-height; its spheres stay 7.66 mm apart (the
  # overlapping chain of the 5 mm bar): thinner bars are beads on the same
  # line, so the rebar count stays and only the radius changes.
  for f in 1 1e-2 1e-3 1e-4; do
    scene="$out/scenes/rbar_$f.data"
    if [ ! -f "$scene" ]; then
      BAR_RADIUS=$(awk -v f="$f" 'BEGIN {print 0.005 * f}') BAR_STEP=0.00766 \
        bash "$top/bench/make_bars.sh" "$out/scenes/rbar_bars.data" "$lx" 0.25 0.25 line 1
      mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$matrix" -var bars "$out/scenes/rbar_bars.data" \
        -var out "$scene" -var cut "$cut" -log none -screen none
    fi
  done
  for rep in $(seq "$reps"); do
    for f in 1 1e-2 1e-3 1e-4; do
      scene="$out/scenes/rbar_$f.data"
      REBAR=$(rebar_of "$scene") run_fix "rbar" "$scene" "fix rebar radius" "$f" 1 "$rep"
      rm -f "$last_run/after.dump"
    done
  done
}
finish() {
  meta "load_end" "$(cut -d' ' -f1-3 /proc/loadavg)"
  meta "minutes" "$(awk -v s="$(( $(date +%s) - start_s ))" 'BEGIN {printf "%.1f", s / 60}')"
  # README.md's figures from the same run: the repository's own when the
  # page goes to docs/, else a copy beside the page (a trial or --quick run).
  readme=$top/README.md
  if [ "$quick" = 1 ] || [ -n "${REINFORCE_BENCH_DOCS:-}" ]; then
    readme=$docs/README.md
    cp "$top/README.md" "$readme"
  fi
  /usr/bin/python3 "$top/bench/report.py" "$out" "$docs" "$readme"
  echo "wrote $docs/benchmarks.md"
}

# The seed paper's placement mode, named so in every table.
size_fit="fix size fit (seed paper)"
# liggghts_part REPEATS: the LIGGGHTS example with the fix's defaults and size fit.
liggghts_part() {
  if [ ! -x "$liggghts" ]; then
    meta "skipped" "liggghts"; echo "== liggghts: no $liggghts, skipped"; return 0
  fi
  local rep
  for rep in $(seq "$1"); do
    run_liggghts "fix defaults" "$rep"
    [ "$rep" = 1 ] && quality_of liggghts - "fix defaults" 1000 0.003 0.005 "$last_run/liggghts_bench.data"
    [ "$quick" = 1 ] && return 0
    run_liggghts "$size_fit" "$rep" "size fit"
    [ "$rep" = 1 ] && quality_of liggghts - "$size_fit" 1000 0.003 0.005 "$last_run/liggghts_bench.data"
    run_liggghts "fix grow each" "$rep" "grow each"
    [ "$rep" = 1 ] && quality_of liggghts - "fix grow each" 1000 0.003 0.005 "$last_run/liggghts_bench.data"
  done
  return 0
}

beam="$top/examples/beam/data"
# The beam's five bars (examples/beam/make_bars.sh) in grow_packing's terms:
# 65 spheres of radius 5 mm from x = 5 mm to 495 mm.
beam_bars=(--box 0 0.5 0 0.25 0 0.25)
for yz in "0.04 0.04" "0.125 0.04" "0.21 0.04" "0.04 0.21" "0.21 0.21"; do
  read -r y z <<<"$yz"
  beam_bars+=(--bar 0.005 "$y" "$z" 0.495 "$y" "$z" 0.005 0.00766)
done
if [ "$quick" = 1 ]; then
  # The quick case checks that every figure is produced, not its precision:
  # a tenth of scene_quality's sample points (most of its time).
  export QUALITY_ARGS=${QUALITY_ARGS:---points 200000}
  small="$out/scenes/small.data"
  "$make_scene" "$small" --fcc --box 0 0.2 0 0.1 0 0.1 --radius 0.005 0.0075 \
    --bar 0.01 0.05 0.05 0.19 0.05 0.05 0.005 0.0077
  meta scenes "small narrow liggghts"
  # The narrow scene in small: one bar in a box of about 1,400 spheres.
  narrow_box=(--box 0 0.12 0 0.1 0 0.1 --bar 0.005 0.05 0.05 0.115 0.05 0.05 0.005 0.0075)
  part reference && grow_scene narrow around "$out/scenes/narrow_small_ref.data" 12 0.004 0.005 0.58 "${narrow_box[@]}"
  part compare && bench_scene small "$small" 0.005 0.0075 0.005 1
  if part narrow; then
    grow_scene narrow alone "$out/scenes/narrow_small.data" 11 0.004 0.005 0.58 "${narrow_box[@]}"
    bench_scene narrow "$out/scenes/narrow_small.data" 0.004 0.005 0.005 1
  fi
  part liggghts && liggghts_part 1
  part relax && relax small "$small" 0.005 2 20
  part speedup && speedup small "$small" 1
  part gap && series_gap small "$small" 0.0075 1
  part rbar && series_rbar "$beam/matrix_phi060.data.gz" 0.125 0.125 1
  finish
  rows=$(($(wc -l < "$results") - 1))
  echo "bench --quick: $rows result rows, $(($(wc -l < "$qual") - 1)) quality rows, $(($(wc -l < "$curves") - 1)) relaxation points in $out"
  lig=0
  [ -x "$liggghts" ] && lig=1
  [ "$rows" -eq $((8 + 1 + 2 + 4 + 4 + 8 + lig)) ] && [ "$(wc -l < "$qual")" -eq $((17 + lig)) ] &&
    [ "$(wc -l < "$curves")" -eq 4 ] && [ "$(wc -l < "$refs")" -eq 3 ] ||
    { echo "bench --quick: missing rows"; exit 1; }
  awk -F'\t' 'NR > 1 && $1 == "narrow" && $13 == "" {bad = 1} END {exit bad}' "$qual" \
    || { echo "bench --quick: no reference figures in the narrow scene's quality"; exit 1; }
  awk -F'\t' 'NR > 1 && $3 ~ /^fix/ && ($7 == "" || $14 == "" || $18 == "") {bad = 1} END {exit bad}' "$results" \
    || { echo "bench --quick: fix row incomplete"; exit 1; }
  grep -q "^## Parallel speedup" "$docs/benchmarks.md" && grep -q "^## Scene quality" "$docs/benchmarks.md" &&
    grep -q "^## Cost against rebar radius and search gap" "$docs/benchmarks.md" &&
    grep -q "^## Against a packing grown around the bars" "$docs/benchmarks.md" &&
    grep -q "^## Profiles" "$docs/benchmarks.md" ||
    { echo "bench --quick: report section missing"; exit 1; }
  sed -n '/written by bench\/report.py/,/end of what bench\/report.py writes/p' "$docs/README.md" |
    grep -q "^\* Where the matrix radii are close" ||
    { echo "bench --quick: README.md's figures not written"; exit 1; }
  for sc in small narrow; do
    grep -q '<polyline points="[0-9]' "$docs/img/profile_$sc.svg" ||
      { echo "bench --quick: no profile plot of $sc"; exit 1; }
  done
  [ "$(grep -c '<polyline' "$docs/img/profile_narrow.svg")" -eq 5 ] ||
    { echo "bench --quick: the narrow profile plot lacks a method or its reference"; exit 1; }
  [ -z "${REINFORCE_BENCH_OUT:-}" ] && rm -rf "$out"
  exit 0
fi

meta scenes "beam050 beam060 beam064 narrow one fibres slab liggghts"
for phi in 050 060 064; do
  scene="$out/scenes/beam$phi.data"
  [ -f "$scene" ] || mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi$phi.data.gz" \
    -var bars "$beam/bars.data" -var out "$scene" -log none -screen none
done
# The references: the beam's law at 0.60 (and the narrow scene's) grown
# around the beam's bars; compare and narrow measure against them.
# beam060 has two: grow_packing's (our fast grower, a geometric protocol)
# and make_packing.lmp's (the law that made the beam's packings, by LAMMPS).
if part reference; then
  grow_scene beam050 around "$out/scenes/beam050_ref.data" 12 0.0025 0.0075 0.50 "${beam_bars[@]}"
  grow_scene beam060 around "$out/scenes/beam060_ref.data" 12 0.0025 0.0075 0.60 "${beam_bars[@]}"
  grow_scene narrow around "$out/scenes/narrow_ref.data" 12 0.004 0.005 0.60 "${beam_bars[@]}"
  for phi in 050 060 064; do
    lammps_ref "beam$phi" "$out/scenes/beam${phi}_lammps_ref.data" "0.${phi#0}" 48271 "$beam/bars.data" \
      0.0025 0.0075
  done
fi
part compare && for phi in 050 060 064; do
  bench_scene "beam$phi" "$out/scenes/beam$phi.data" 0.0025 0.0075 0.005 3
done
# The narrow scene: radii 4-5 mm (ratio 1.25) at 0.60 in the beam's box,
# grown alone (grow_packing, seed 11), then the beam's bars added.
if part narrow; then
  grow_scene narrow alone "$out/scenes/narrow.data" 11 0.004 0.005 0.60 "${beam_bars[@]}"
  bench_scene narrow "$out/scenes/narrow.data" 0.004 0.005 0.005 2
fi
# The one-radius and thin-fibre scenes of the quality tests (box 0.18 x
# 0.14 x 0.14 m, walls; defined once, tests/quality/make_scenes.sh): one
# radius 4 mm at 0.56 with three bars, and radii 2.5-7.5 mm at 0.58 with
# 200 fibres of 1 mm spheres. Around the fibres grow_packing jams: that
# scene has no reference.
if part more; then
  mapfile -t one_args < <(bash "$top/tests/quality/make_scenes.sh" --args one)
  mapfile -t fibre_args < <(bash "$top/tests/quality/make_scenes.sh" --args fibres)
  grow_scene one around "$out/scenes/one_ref.data" 12 0.004 0.004 0.56 "${one_args[@]}"
  grow_scene one alone "$out/scenes/one.data" 11 0.004 0.004 0.56 "${one_args[@]}"
  bench_scene one "$out/scenes/one.data" 0.004 0.004 0.005 2
  grow_scene fibres alone "$out/scenes/fibres.data" 11 0.0025 0.0075 0.58 "${fibre_args[@]}"
  bench_scene fibres "$out/scenes/fibres.data" 0.0025 0.0075 0.001 2
fi
part liggghts && liggghts_part 2
if part speedup; then
  speedup beam060 "$out/scenes/beam060.data" 25
  # The cost of the rounds' exchange against the number of partners (the
  # model of larger runs).
  mpirun -np 2 "$REINFORCE_BUILD/bench/exchange_cost" > "$out/exchange_cost.tsv"
fi
part gap && series_gap beam060 "$out/scenes/beam060.data" 0.0075 3
part rbar && series_rbar "$beam/matrix_phi060.data.gz" 0.5 0 3
part relax && for phi in 050 060 064; do
  relax "beam$phi" "$out/scenes/beam$phi.data" 0.0025 10 500
done

# The slab: the 0.60 beam packing replicated 2 x 5 x 2 (1.0 x 1.25 x 0.5 m,
# 573k matrix spheres) with a mesh of bars 0.1 m apart in two layers.
slab="$out/scenes/slab.data"
if [[ " ${REINFORCE_BENCH_SKIP:-} " != *" slab "* ]] && [ ! -f "$slab" ]; then
  bash "$top/bench/make_bars.sh" "$out/scenes/mesh.data" 1.0 1.25 0.5 mesh 0.1 0.04
  mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
    -var bars "$out/scenes/mesh.data" -var out "$slab" -var rep "2 5 2" -log none -screen none
fi
if part slab; then
  speedup slab "$slab" 5
  for rep in 1 2 3; do
    run_fix slab "$slab" "$size_fit" 1000 1 "$rep" -var opts "size fit"
    rm -f "$last_run/after.dump"
    run_delete slab "$slab" 0.0125 1 "$rep" 0.0025; rm -f "$last_run/after.dump"
    run_delete slab "$slab" 0.0075 1 "$rep" 0.0025; rm -f "$last_run/after.dump"
  done
fi

# Scaling: the same single bar in growing scenes (work fixed, size grows),
# and a growing number of bars in one scene (size fixed, work grows).
if part scaling; then
  for rep in "0.125:1 1 1" "0:1 1 1" "0:2 2 1" "0:4 2 2"; do
    cut=${rep%%:*} r=${rep##*:}
    name="size_$(echo "$r" | tr -d ' ')_cut$cut"
    scene="$out/scenes/$name.data"
    bash "$top/bench/make_bars.sh" "$out/scenes/onebar.data" 0.125 0.25 0.25 line 1
    mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
      -var bars "$out/scenes/onebar.data" -var out "$scene" -var rep "$r" -var cut "$cut" -log none -screen none
    for rep_i in 1 2 3; do
      run_fix scaling_size "$scene" "fix defaults" 1000 1 "$rep_i"; rm -f "$last_run/after.dump"
    done
    rm -f "$scene"
  done
  for bars in 1 2 4 8 16; do
    scene="$out/scenes/bars$bars.data"
    bash "$top/bench/make_bars.sh" "$out/scenes/nbars.data" 1.0 1.0 0.25 line "$bars"
    mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var matrix "$beam/matrix_phi060.data.gz" \
      -var bars "$out/scenes/nbars.data" -var out "$scene" -var rep "2 4 1" -log none -screen none
    for rep_i in 1 2 3; do
      run_fix scaling_targets "$scene" "fix defaults" 1000 1 "$rep_i"; rm -f "$last_run/after.dump"
    done
    rm -f "$scene"
  done
fi
finish
