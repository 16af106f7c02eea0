#!/usr/bin/env bash
# Benchmarks fix reinforce/invert against what a user has, on the same scenes in
# one run, and writes docs/benchmarks.md with bench/report.py (bench/README.md:
# the parts, the options, the raw results).
#   bash bench/run.sh [--quick] [--repeats N]
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
quick=0 repeats=
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 ;;
    --repeats) repeats=$2; shift ;;
    *) echo "usage: bench/run.sh [--quick] [--repeats N]"; exit 2 ;;
  esac
  shift
done
die() { echo "bench: $*" >&2; exit 1; }
[ -n "${REINFORCE_BUILD:-}" ] || source "$top/scripts/setup.sh"    # inside ctest REINFORCE_BUILD names the build
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce" liggghts="$REINFORCE_BUILD/src/liggghts/liggghts_reinforce"
check="$REINFORCE_BUILD/tests/check_scene" quality="$REINFORCE_BUILD/tests/scene_quality"
grow="$REINFORCE_BUILD/tests/grow_packing" make_scene="$REINFORCE_BUILD/tests/make_scene"
# Nothing is installed here: scripts/setup.sh installs the packages and builds.
for need in "$lmp" "$check" "$quality" "$grow" "$make_scene" /usr/bin/python3 /usr/bin/time \
            "$(command -v gnuplot || echo gnuplot)" "$(command -v mpirun || echo mpirun)"; do
  [ -x "$need" ] || die "$need is missing: run scripts/setup.sh (it installs and builds what the benchmark needs)"
done
inputs="$top/bench/lammps" beam="$top/examples/beam/data"
out=${REINFORCE_BENCH_OUT:-$top/bench/out} docs=${REINFORCE_BENCH_DOCS:-$top/docs}
[ "$quick" = 1 ] && [ -z "${REINFORCE_BENCH_OUT:-}" ] && out=$(mktemp -d "${TMPDIR:-/tmp}/bench_quick.XXXXXX")
[ "$quick" = 1 ] && docs="$out/docs"
mkdir -p "$out/scenes" "$out/runs" "$docs"

# --- the tables ---------------------------------------------------------------------------
# methods.tsv: key, method, param, fix keywords, plotted, where it runs (scenes,
# liggghts, slab), description; RMAX, RBAR+RMAX, RBAR+RMIN are filled per scene.
# scenes.tsv: the quick and the full run's scenes, in the order they run: every
# method runs on a "methods" row's scene; the other rows are packings grown
# around the bars (a reference: "around" by grow_packing, "lammps" by the beam's
# own make_packing.lmp) or "alone" (the scene itself, the bars then added);
# a "methods" row names the methods.tsv keys it runs ("all": every one).
mapfile -t methods < <(tail -n +2 "$top/bench/methods.tsv")
mapfile -t scenes < <(awk -F'\t' -v r="$([ "$quick" = 1 ] && echo quick || echo full)" '$1 == r' "$top/bench/scenes.tsv")
if [ "$quick" = 1 ]; then
  # The LIGGGHTS example settles 2,000 steps of its 15,000, and runs the relocation alone: its fix short.
  relax_scenes=(small) relax_chunks=2 relax_steps=20 liggghts_repeats=1 liggghts_methods=norgrow liggghts_settle=2000
  speedups=("small 1") gap_scene=small gap_repeats=1 rbar_lx=0.125 rbar_cut=0.125 rbar_repeats=1
  # The quick case checks that every figure is produced, not its precision.
  export QUALITY_ARGS=${QUALITY_ARGS:---points 200000}
else
  # Sized to finish in about 25 minutes on 2 cores (bench/README.md): the regrowth takes tens of seconds on the
  # 0.64 beam and minutes on the slab, so the slab's speedup runs once and the variants of the defaults run on
  # the 0.60 beam only (scenes.tsv).
  relax_scenes=(beam050 beam060 beam064) relax_chunks=10 relax_steps=300 liggghts_repeats=2 liggghts_settle=15000
  liggghts_methods=defaults speedups=("beam060 7") gap_scene=beam060 gap_repeats=3 rbar_lx=0.5 rbar_cut=0
  rbar_repeats=3 slab_rep="2 2 2" slab_speedups=1 slab_repeats=2 scaling_repeats=2
fi
parts=(reference compare narrow more liggghts cage speedup gap rbar relax slab scaling)
gaps=("1 0.0075" "10 0.075" "100 0.75" "1e20 1e20")    # search in rmax, and in metres
rbars=(1 1e-2 1e-3 1e-4) nps=(1 2)
declare -A grower=([around]=grow_packing [lammps]=make_packing.lmp)
# geometry NAME: grow_packing's box and bars of a scene, one argument a line.
geometry() {
  case $quick$1 in
    1narrow) printf '%s\n' --box 0 0.12 0 0.1 0 0.1 --bar 0.005 0.05 0.05 0.115 0.05 0.05 0.005 0.0075 ;;
    0beam*|0narrow)    # the beam's five bars (examples/beam/make_bars.sh); the narrow scene in half its length,
      # where the regrowth takes minutes a run
      local lx=0.5 && [ "$1" = narrow ] && lx=0.25
      printf '%s\n' --box 0 "$lx" 0 0.25 0 0.25
      for yz in "0.04 0.04" "0.125 0.04" "0.21 0.04" "0.04 0.21" "0.21 0.21"; do
        printf '%s\n' --bar 0.005 ${yz% *} ${yz#* } "$(calc "$lx - 0.005")" ${yz% *} ${yz#* } 0.005 0.00766
      done ;;
    0one|0fibres) bash "$top/tests/quality/make_scenes.sh" --args "$1" ;;
  esac
}

# --- raw results: one header each, one row writer ------------------------------------------
declare -A columns=(
  [results]="scene atoms method param np rep targets relocated deleted volume_before volume_after overlap solves op_seconds wall_seconds peak_kb removed rounds rebar balance busiest blocks"
  [relax]="scene chunk seconds atoms matrix_rebar matrix_matrix"
  [quality]="scene method param shell_ratio shell_ratio_se removed_ratio ks targets deleted moved_nontargets bulk ref_bulk ref_shell_ratio shell_vs_reference bin_diff_max"
  [reference]="scene kind seed matrix rebar box phi radii wall_seconds cpu_seconds grown bulk shell_ratio shell_ratio_se"
  [versus]="scene reference method param shell_ratio shell_ratio_se ref_shell_ratio shell_vs_reference bin_diff_max bulk ref_bulk"
  [profile]="scene reference method param lo_rmax hi_rmax phi phi_se ref_phi ref_phi_se"
  [meta]="key value")
for t in "${!columns[@]}"; do tr ' ' '\t' <<<"${columns[$t]}" > "$out/$t.tsv"; done
# row TABLE KEY=VALUE...: one row of TABLE.tsv in its header's order; a key the
# header lacks is an error, a field not given is left empty.
row() {
  local table=$1 kv k line=() && shift
  local -A v=()
  for kv in "$@"; do
    k=${kv%%=*}
    [[ " ${columns[$table]} " == *" $k "* ]] || die "row: $table has no field $k"
    v[$k]=${kv#*=}
  done
  for k in ${columns[$table]}; do line+=("${v[$k]:-}"); done
  (IFS=$'\t'; echo "${line[*]}") >> "$out/$table.tsv"
}
meta() { row meta key="$1" value="$2"; }
# parse ARRAY LINE: a RESULT line ("KEY VALUE" pairs, both hosts print it) or a
# QUALITY line (KEY=VALUE words), its first word dropped, into ARRAY.
parse() {
  local -n into=$1
  local w k=""
  [ -n "$2" ] || return 1
  for w in ${2#* }; do
    if [[ $w == *=* ]]; then into[${w%%=*}]=${w#*=}
    elif [ -z "$k" ]; then k=$w
    else into[$k]=$w k=""; fi
  done
}
pick() {    # pick ARRAY KEY...: the words KEY=value of ARRAY, for row
  local key && local -n from=$1 && shift
  for key in "$@"; do echo "$key=${from[$key]:-}"; done
}
# count_atoms DATAFILE [TYPE]: the atoms of a data file, or those of one type.
count_atoms() {
  awk -v t="${2:-}" 't == "" && / atoms$/ {print $1; exit}
    /^Atoms/ {on = 1; next} /^[A-Z][a-z]+/ {on = 0}
    on && NF >= 7 && $2 == t {n++} END {if (t != "") print n + 0}' "$1"
}
box_of() {    # box_of DATAFILE: "LX x LY x LZ"
  awk '/xlo xhi/ {x = $2 - $1} /ylo yhi/ {y = $2 - $1} /zlo zhi/ {z = $2 - $1; print x " x " y " x " z; exit}' "$1"
}
calc() { awk "BEGIN {printf \"${2:-%g}\\n\", $1}"; }    # calc EXPR [FORMAT]
part() {    # part NAME: true when the part runs; records it and the load average
  if [[ " ${REINFORCE_BENCH_SKIP:-} " == *" $1 "* ]]; then meta skipped "$1"; echo "== $1: skipped"; return 1; fi
  meta "load_$1" "$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "== $1 ($(date -u +%H:%M:%S), load $(cut -d' ' -f1 /proc/loadavg))"
}

# --- one run of one method ------------------------------------------------------------------
# timed LOG COMMAND...: one run under /usr/bin/time in the inputs' folder; sets wall, peak.
timed() {
  local log=$1 && shift
  (cd "$inputs" && /usr/bin/time -f "%e %M" -o "$log.time" "$@") || { tail -3 "$log" >&2; die "run failed, see $log"; }
  read -r wall peak < "$log.time"
}
# resolve ROW RMIN RMAX RBAR: sets method, param, keywords, plot of a methods.tsv row for a scene.
resolve() {
  IFS=$'\t' read -r _ method param keywords plot _ _ <<<"$1"
  param=${param/RMAX/$3} param=${param/RMIN/$2} keywords=${keywords/RMAX/$3}
  [[ $param == RBAR+* ]] && param=$(calc "$4 + ${param#RBAR+}")
  [ "$keywords" != - ] || keywords=""
}
# run_method NAME SCENE METHOD PARAM KEYWORDS NP REP RMIN: one run, one row of
# results.tsv: delete_atoms with cutoff PARAM, or the fix with KEYWORDS (on the
# scene "liggghts", the LIGGGHTS example); sets run and after (the scene after).
run_method() {
  local name=$1 scene=$2 method=$3 param=$4 keywords=$5 np=$6 rep=$7 rmin=$8 schedule
  run="$out/runs/${name}_$(tr -c 'A-Za-z0-9.\n-' _ <<<"$method $param")_np${np}_$rep" after=$run/after.dump
  mkdir -p "$run"
  local -A R=()
  if [ "$name" = liggghts ]; then
    # LIGGGHTS 3.8 crashes in insert/pack under -screen none: the screen goes to a file.
    inputs="$top/examples/liggghts" timed "$run/log" "$liggghts" -in in.liggghts -var out "$run" -var tag bench \
      -var extra "$keywords" -var settle "$liggghts_settle" -log "$run/log" > "$run/screen"
    after=$run/liggghts_bench.data
  else
    local input=(in.fix -var opts "$keywords")
    [[ $method != delete_atoms* ]] || input=(in.delete -var cutoff "$param")
    timed "$run/log" mpirun -np "$np" "$lmp" -log "$run/log" -screen none -var scene "$scene" -var out "$run" -in "${input[@]}"
  fi
  parse R "$(grep '^RESULT' "$run/log" | tail -1)" || die "no RESULT line in $run/log"
  if [[ $method == delete_atoms* ]]; then    # the wall clock around the command; what it left
    R[seconds]=$(calc "$(cat "$run/t1") - $(cat "$run/t0")" %.6f)
    R[overlap]=$("$check" --stats "$after" --rmin "$rmin" | awk '{print $6}')
  fi
  # The fix's schedule: its blocks with targets, the busiest process's targets, the balance.
  schedule=$(sed -n 's/^fix reinforce\/invert: schedule: .* in \([0-9]*\) blocks, busiest process \([0-9]*\) targets over the rounds, balance \([0-9.]*\) over .*/\1 \2 \3/p' "$run/log" | tail -1)
  [ -z "$schedule" ] || read -r R[blocks] R[busiest] R[balance] <<<"$schedule"
  [ "$name" = liggghts ] && R[atoms]=$((R[atoms] + R[deleted])) || R[atoms]=$(count_atoms "$scene")
  row results scene="$name" method="$method" param="$param" np="$np" rep="$rep" op_seconds="${R[seconds]}" \
    wall_seconds="$wall" peak_kb="$peak" rebar="${REBAR:-}" $(pick R atoms targets relocated deleted volume_before \
    volume_after overlap solves removed rounds balance busiest blocks)
}
# quality NAME BEFORE AFTER METHOD PARAM RMIN RMAX PLOT: scene_quality of AFTER
# (BEFORE "-": none), once against each reference of the scene in turn
# (grow_packing's, or none, gives the quality.tsv row; make_packing.lmp's a
# versus.tsv row: scene_quality takes one reference); a plotted method's
# profile bins go to profile.tsv.
declare -A refs_of=()    # refs_of[SCENE]: "grower=file" words
quality() {
  local name=$1 before=$2 after=$3 method=$4 param=$5 rmin=$6 rmax=$7 plot=$8 ref text refs=${refs_of[$1]:-}
  local args=(--after "$after" --rmin "$rmin" --rmax "$rmax")
  [ "$plot" = yes ] || args+=(--quiet-profile)
  [ "$before" = - ] || args+=(--before "$before")
  [[ $refs == *grow_packing=* ]] || refs="-=- $refs"
  for ref in $refs; do
    local -A Q=()
    text=$("$quality" "${args[@]}" $([ "$ref" = -=- ] || echo --reference "${ref#*=}") ${QUALITY_ARGS:-}) ||
      die "scene_quality failed on $after"
    parse Q "$(grep '^QUALITY' <<<"$text")" || die "no QUALITY line from scene_quality on $after"
    if [ "${ref%%=*}" = make_packing.lmp ]; then
      row versus scene="$name" reference="${ref%%=*}" method="$method" param="$param" $(pick Q shell_ratio \
        shell_ratio_se ref_shell_ratio shell_vs_reference bin_diff_max bulk ref_bulk)
    else
      row quality scene="$name" method="$method" param="$param" $(pick Q shell_ratio shell_ratio_se removed_ratio ks \
        targets deleted moved_nontargets bulk ref_bulk ref_shell_ratio shell_vs_reference bin_diff_max)
    fi
    [ "$plot" = yes ] || continue
    awk -v OFS='\t' -v p="$name"$'\t'"${ref%%=*}"$'\t'"$method"$'\t'"$param" '
      /^ *\[ *[0-9.e+-]+, *[0-9.e+-]+\) rmax / {
        gsub(/[\[\),]/, " "); r1 = r2 = ""
        for (i = 1; i <= NF; i++) if ($i == "ref") { r1 = $(i + 1); r2 = $(i + 3) }
        print p, $1, $2, $4, $6, r1, r2 }' <<<"$text" >> "$out/profile.tsv"
  done
}

# --- scenes and packings ------------------------------------------------------------------
# cached FILE KEY COMMAND...: runs COMMAND (it writes FILE) unless FILE exists with
# the same KEY; FILE.grow keeps "wall cpu date" and the KEY.
cached() {
  local file=$1 key=$2
  shift 2
  [ -f "$file" ] && [ -f "$file.grow" ] && [ "$(sed -n 2p "$file.grow")" = "$key" ] && return 0
  rm -f "$file" "${file%.data}.before.dump"
  /usr/bin/time -f "%e %U" -o "$file.time" "$@" > "$file.log" 2>&1 ||
    { tail -5 "$file.log" >&2; die "making $file failed, see $file.log"; }
  printf '%s %s\n%s\n' "$(cat "$file.time")" "$(date -u '+%Y-%m-%d_%H:%M_UTC')" "$key" > "$file.grow"
  rm "$file.time"
}
# grown NAME KIND SEED RMIN RMAX PHI: a row of the packings table, grown when
# not cached; one reference.tsv row; a reference's own quality.
grown() {
  local name=$1 kind=$2 seed=$3 rmin=$4 rmax=$5 phi=$6 file wall cpu when
  local -A Q=()
  file="$out/scenes/${name}_${kind}_ref.data"
  if [ "$kind" = lammps ]; then
    # Debian's lmp, one process, as a LAMMPS user would run it: several minutes.
    local script="$top/examples/beam/make_packing.lmp" plain_lmp
    plain_lmp=$(command -v lmp || echo "$lmp")
    echo "== $name: make_packing.lmp (several minutes when not cached)"
    cached "$file" "make_packing.lmp -var phi $phi -var seed $seed -var bars bars.data script $(sha1sum < "$script" |
      cut -c1-12) bars $(sha1sum < "$beam/bars.data" | cut -c1-12)" bash -c 'cd "$1" && "$2" -in make_packing.lmp \
      -var phi "$3" -var seed "$4" -var bars "$5" -var out "$6" -log "$6.lmplog" -screen none' - "$top/examples/beam" \
      "$plain_lmp" "$phi" "$seed" "$beam/bars.data" "$file"
    meta "packing_$name" "$(grep '^PACKING' "$file.lmplog" | tail -1 | sed 's/^PACKING //')"
  else
    local args=(--radius "$rmin" "$rmax" --phi "$phi" --seed "$seed")
    mapfile -t -O ${#args[@]} args < <(geometry "$name")
    [ "$kind" = alone ] && file="$out/scenes/$name.data" || args+=(--around-bars)
    cached "$file" "${args[*]}" "$grow" "$file" "${args[@]}" --max-seconds 600
  fi
  if [ "$kind" != alone ]; then
    parse Q "$("$quality" --after "$file" --rmin "$rmin" --rmax "$rmax" --quiet-profile | grep '^QUALITY')"
    refs_of[$name]="${refs_of[$name]:-} ${grower[$kind]}=$file"
  fi
  read -r wall cpu when < "$file.grow"
  row reference scene="$name" kind="$kind" seed="$seed" matrix="$(count_atoms "$file" 1)" \
    rebar="$(count_atoms "$file" 2)" box="$(box_of "$file")" phi="$phi" radii="$rmin-$rmax" wall_seconds="$wall" \
    cpu_seconds="$cpu" grown="$when" $(pick Q bulk shell_ratio shell_ratio_se)
}
# prepared FILE BARS [in.prepare -var pairs]: a beam packing plus bars, once.
prepared() {
  [ -f "$1" ] || mpirun -np 1 "$lmp" -in "$inputs/in.prepare" -var bars "$2" -var out "$1" -log none -screen none "${@:3}"
}
# scene_file NAME: sets data to the scene's data file, made when missing
# (those grown alone come from the packings table).
scene_file() {
  data="$out/scenes/$1.data"
  case $1 in
    liggghts) data=- ;;    # the example makes its own
    cage) # the cage example's scene (examples/cage/run.sh): its cage, laid out by reinforce_layout, in the matrix
      # grown alone in its box; named by the layout's checksum, so that an edited cage is not taken from the cache
      data="$out/scenes/cage_$(sha1sum < "$top/examples/cage/cage.layout" | cut -c1-8).data"
      if [ ! -f "$data" ]; then
        "$REINFORCE_BUILD/src/layout/reinforce_layout" "$top/examples/cage/cage.layout" \
          --data "$out/scenes/cage_bars.data" > /dev/null || die "reinforce_layout failed on the cage"
        "$grow" "$out/scenes/cage_matrix.data" --box 0 0.4 0 0.15 0 0.2 --radius 0.003 0.006 --phi 0.6 --seed 7 \
          --quiet || die "grow_packing failed on the cage's matrix"
        prepared "$data" "$out/scenes/cage_bars.data" -var matrix "$out/scenes/cage_matrix.data"
      fi ;;
    small) [ -f "$data" ] || "$make_scene" "$data" --fcc --box 0 0.2 0 0.1 0 0.1 --radius 0.005 0.0075 \
             --bar 0.01 0.05 0.05 0.19 0.05 0.05 0.005 0.0077 > /dev/null ;;
    beam*) prepared "$data" "$beam/bars.data" -var matrix "$beam/matrix_phi${1#beam}.data.gz" ;;
    slab) # the 0.60 beam replicated (slab_rep: 2 x 2 x 2 is 1.0 x 0.5 x 0.5 m), a mesh of bars 0.1 m apart in
      # two layers; named by its replication, so that a slab of another size is not taken from the cache
      local r && read -r -a r <<<"$slab_rep" && data="$out/scenes/slab_${slab_rep// /x}.data"
      [ -f "$data" ] || bash "$top/bench/make_bars.sh" "$out/scenes/mesh.data" "$(calc "${r[0]} * 0.5")" \
        "$(calc "${r[1]} * 0.25")" "$(calc "${r[2]} * 0.25")" mesh 0.1 0.04
      prepared "$data" "$out/scenes/mesh.data" -var matrix "$beam/matrix_phi060.data.gz" -var rep "$slab_rep" ;;
  esac
}

# --- the parts ----------------------------------------------------------------------------------
# chosen ROW WHERE KEYS: true when the methods.tsv ROW runs on WHERE and its
# key is one of KEYS (comma-separated, or "all").
chosen() {
  [[ ,$(cut -f6 <<<"$1"), == *,$2,* ]] && { [ "$3" = all ] || [[ ,$3, == *,$(cut -f1 <<<"$1"),* ]]; }
}
# bench_scene NAME RMIN RMAX RBAR REPEATS WHERE [KEYS]: the methods of the table
# that run on WHERE (those of KEYS, default all), 1 process, interleaved in each
# repeat; the quality of the first repeat of each (not on the slab).
bench_scene() {
  local name=$1 rmin=$2 rmax=$3 rbar=$4 reps=$5 where=$6 keys=${7:-all} m rep method param keywords plot before=-
  scene_file "$name"
  if [ "$data" != - ]; then    # its size and box; the scene before, as a text dump, for its quality
    echo "== $name ($(count_atoms "$data") atoms)" && meta "box_$name" "$(box_of "$data")" && before=${data%.data}.before.dump
    [ "$where" = slab ] || [ -f "$before" ] || (cd "$inputs" && mpirun -np 1 "$lmp" -in in.dump -var scene "$data" \
      -var out "$before" -log none -screen none) || die "writing $before failed"
  fi
  for rep in $(seq "$reps"); do
    for m in "${methods[@]}"; do
      chosen "$m" "$where" "$keys" || continue
      resolve "$m" "$rmin" "$rmax" "$rbar"
      run_method "$name" "$data" "$method" "$param" "$keywords" 1 "$rep" "$rmin"
      [ "$rep" = 1 ] && [ "$where" != slab ] && quality "$name" "$before" "$after" "$method" "$param" "$rmin" "$rmax" "$plot"
      rm -f "$run/after.dump"
    done
  done
}
# series NAME SCENE METHOD NP REP [PARAM KEYWORDS]: one run of the fix (default:
# its defaults) for a series, no quality.
series() {
  run_method "$1" "$2" "$3" "${6:-1000}" "${7:-}" "$4" "$5" 0.0025
  rm -f "$run/after.dump"
}
# speedup NAME REPEATS: the fix's defaults on 1 and 2 processes, alternating.
speedup() {
  local rep np
  scene_file "$1"
  for rep in $(seq "$2"); do
    for np in "${nps[@]}"; do series "speedup_$1" "$data" "fix defaults" "$np" "$rep"; done
  done
}
# relax NAME RMIN: dynamic relaxation, once, serially: the largest overlaps
# after every chunk of steps (relax.tsv), and one results.tsv row.
relax() {
  local name=$1 rmin=$2 i t0 a mr mm first=
  scene_file "$name"
  run="$out/runs/${name}_relax" && mkdir -p "$run"
  timed "$run/log" mpirun -np 1 "$lmp" -log "$run/log" -screen none -in in.relax -var scene "$data" -var out "$run" \
    -var chunks "$relax_chunks" -var chunk "$relax_steps" -var rmin "$rmin"
  t0=$(cat "$run/relax_0.time")
  for i in $(seq 0 "$relax_chunks"); do
    read -r _ a _ _ _ mr _ mm < <("$check" --stats "$run/relax_$i.dump" --rmin "$rmin")
    row relax scene="$name" chunk="$i" seconds="$(calc "$(cat "$run/relax_$i.time") - $t0" %.4f)" \
      atoms="$a" matrix_rebar="$mr" matrix_matrix="$mm"
    first=${first:-$a}
    rm -f "$run/relax_$i.dump"
  done
  row results scene="$name" atoms="$(count_atoms "$data")" method=relax param="$((relax_chunks * relax_steps)) steps" \
    np=1 rep=1 deleted=$((first - a)) overlap="$mr" op_seconds="$(tail -1 "$out/relax.tsv" | cut -f3)" \
    wall_seconds="$wall" peak_kb="$peak"
}
# scaling NAME LX LY BARS CUT REPLICATION: BARS bars along x in the 0.60 beam
# packing cut at CUT (0: not) and replicated, the fix's defaults scaling_repeats
# times (param: BARS).
scaling() {
  local rep
  bash "$top/bench/make_bars.sh" "$out/scenes/bars.data" "$2" "$3" 0.25 line "$4"
  data="$out/scenes/scaling.data"
  prepared "$data" "$out/scenes/bars.data" -var matrix "$beam/matrix_phi060.data.gz" -var cut "$5" -var rep "$6"
  for rep in $(seq "$scaling_repeats"); do series "$1" "$data" "fix defaults" 1 "$rep" "$4" ""; done
  rm -f "$data"
}

# --- the run ----------------------------------------------------------------------------------------
start_s=$(date +%s)
meta quick "$quick"
meta started "$(date -u '+%Y-%m-%d %H:%M UTC')"
meta commit "$(git -C "$top" rev-parse --short HEAD 2>/dev/null || echo unknown)"
for p in "${parts[@]}"; do
  [ "$quick" = 1 ] && [[ " more cage slab scaling " == *" $p "* ]] && continue
  part "$p" || continue
  for s in "${scenes[@]}"; do
    IFS=$'\t' read -r _ name spart kind rmin rmax rbar reps phi seed keys <<<"$s"
    if [ "$spart" != "$p" ]; then continue
    elif [ "$kind" = methods ]; then bench_scene "$name" "$rmin" "$rmax" "$rbar" "${repeats:-$reps}" scenes "$keys"
    else grown "$name" "$kind" "$seed" "$rmin" "$rmax" "$phi"; fi
  done
  case $p in
    liggghts)
      meta liggghts_settle "$liggghts_settle"
      if [ -x "$liggghts" ]; then bench_scene liggghts 0.003 0.005 0.0025 "$liggghts_repeats" liggghts "$liggghts_methods"
      else meta skipped liggghts; echo "== liggghts: no $liggghts, skipped"; fi ;;
    speedup)
      for s in "${speedups[@]}"; do speedup $s; done
      # The cost of the rounds' exchange against the number of partners (the model of larger runs).
      [ "$quick" = 1 ] || mpirun -np 2 "$REINFORCE_BUILD/bench/exchange_cost" > "$out/exchange_cost.tsv" ;;
    slab) meta slab_replication "$slab_rep"; speedup slab "$slab_speedups"; bench_scene slab 0.0025 0.0075 0.005 "$slab_repeats" slab ;;    # no relaxation: too long
    gap)
      scene_file "$gap_scene"
      for rep in $(seq "$gap_repeats"); do
        for g in "${gaps[@]}"; do series gap "$data" "fix search" 1 "$rep" "${g% *}" "search ${g#* }"; done
      done ;;
    rbar)    # one bar along x at mid-height in the 0.60 beam packing, its rebar radius F times 5 mm; its
      # spheres stay 7.66 mm apart (the 5 mm bar's chain: thinner bars are beads on the same line)
      for rep in $(seq "$rbar_repeats"); do
        for f in "${rbars[@]}"; do
          data="$out/scenes/rbar_$f.data"
          [ -f "$data" ] || BAR_RADIUS=$(calc "0.005 * $f") BAR_STEP=0.00766 \
            bash "$top/bench/make_bars.sh" "$out/scenes/rbar_bars.data" "$rbar_lx" 0.25 0.25 line 1
          prepared "$data" "$out/scenes/rbar_bars.data" -var matrix "$beam/matrix_phi060.data.gz" -var cut "$rbar_cut"
          REBAR=$(count_atoms "$data" 2) series rbar "$data" "fix rebar radius" 1 "$rep" "$f" ""
        done
      done ;;
    relax) for s in "${relax_scenes[@]}"; do relax "$s" 0.0025; done ;;
    scaling)    # one bar in growing scenes (the work fixed), then 1 to 16 bars in one scene (the work grows)
      for r in "0.125 1 1 1" "0 1 1 1" "0 2 2 1" "0 4 2 2"; do
        scaling scaling_size 0.125 0.25 1 ${r% * * *} "${r#* }"
      done
      for n in 1 2 4 8; do scaling scaling_targets 1.0 1.0 "$n" 0 "2 4 1"; done ;;
  esac
done
# The rows this run's tables call for, which report.py --check counts: per scene
# a row of results and of quality per method it runs, the LIGGGHTS example its
# methods, every series point its row.
on() {    # on WHERE KEYS: how many methods run there
  local m k=0
  for m in "${methods[@]}"; do chosen "$m" "$1" "$2" && k=$((k + 1)); done
  echo "$k"
}
n=0 lig=0 grown_rows=0
for s in "${scenes[@]}"; do
  IFS=$'\t' read -r _ _ _ kind _ _ _ _ _ _ keys <<<"$s"
  if [ "$kind" = methods ]; then n=$((n + $(on scenes "$keys"))); else grown_rows=$((grown_rows + 1)); fi
done
[ ! -x "$liggghts" ] || lig=$(on liggghts "$liggghts_methods")
[ "$quick" = 0 ] || meta want "results $((n + lig + ${#relax_scenes[@]} + ${#nps[@]} + ${#gaps[@]} + ${#rbars[@]})) \
quality $((n + lig)) reference $grown_rows relax $((${#relax_scenes[@]} * (relax_chunks + 1)))"
meta load_end "$(cut -d' ' -f1-3 /proc/loadavg)"
meta minutes "$(calc "($(date +%s) - $start_s) / 60" %.1f)"
# README.md's figures from the same run: the repository's own when the page goes
# to docs/, else a copy beside the page (a trial or --quick run).
readme=$top/README.md
if [ "$quick" = 1 ] || [ -n "${REINFORCE_BENCH_DOCS:-}" ]; then readme=$docs/README.md; cp "$top/README.md" "$readme"; fi
/usr/bin/python3 "$top/bench/report.py" "$out" "$docs" "$readme"
if [ "$quick" = 1 ]; then
  /usr/bin/python3 "$top/bench/report.py" --check "$out" "$docs" || die "--quick: incomplete, see $out"
  [ -n "${REINFORCE_BENCH_OUT:-}" ] || rm -rf "$out"
fi
