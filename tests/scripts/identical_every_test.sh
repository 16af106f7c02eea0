#!/usr/bin/env bash
# N > 0 on any number of processes: the same input (tests/lammps/in.identical_every
# or tests/liggghts/in.identical_every: relocation every 10 steps over 50
# steps while the bars move at constant velocity, nothing else moving the
# matrix) run on NPROCS processes (grid "Px Py Pz") and on one process must
# write identical atoms (id type x y z radius as %.17g, bit for bit) after
# every invocation (steps 0, 10, ..., 50), report the same counts at each,
# and end with the same atoms. Each run must relocate targets at every
# invocation (so the comparison is not vacuous), and the NPROCS run is
# checked by the checker: atom accounting over the run, no matrix sphere on
# a bar at the end, and every pair at the last invocation
# (last_invocation.sh: the checker on the dumps of steps 49 and 50). The
# periodic scene must also delete targets after step 0 and move bar
# spheres through both periodic boundaries.
#   identical_every_test.sh lammps|liggghts BUILD_DIR NPROCS "Px Py Pz" walls|periodic
# On a difference it prints the first invocation whose atoms differ and
# the atoms that differ there (id, then the NPROCS line and the 1-process
# line), and fails.
set -euo pipefail
host=$1 build=$2 np=$3 grid=$4 kind=$5
here=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/test_env.sh" "identical_every"
fail() { echo "FAIL: $*"; exit 1; }
checker=$build/tests/check_scene
case $host in
  lammps) exe=$build/src/lammps/lmp_reinforce indir=$here/lammps ;;
  liggghts) exe=$build/src/liggghts/liggghts_reinforce indir=$here/liggghts ;;
  *) echo "identical_every_test.sh: unknown host $host"; exit 2 ;;
esac

# The scenes. walls (f f f): 4225 spheres, two bars along x and one along y
# (the basic scene of the N = 0 tests), moving along z (through the seams
# of a grid split in z). periodic (p p f): bars along x across the periodic
# boundary in x and along y across the one in y, both moving diagonally in
# x-y: the x bar slides through the periodic boundary in x and across the
# seam y = 0.1, the y bar across the seam x = 0.2 and through the periodic
# boundary in y; few tries (15), so that some targets are deleted during
# the run.
vars=()
case $kind in
  walls)
    "$build/tests/make_scene" "$work/scene.data" --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
      --bar 0.01 0.07 0.1 0.39 0.07 0.1 0.005 0.0075 --bar 0.01 0.13 0.1 0.39 0.13 0.1 0.005 0.0075 \
      --bar 0.2 0.01 0.05 0.2 0.19 0.05 0.005 0.0075
    vars=(-var vel "0 0 40") ;;
  periodic)
    "$build/tests/make_scene" "$work/scene.data" --box 0 0.4 0 0.2 0 0.2 --radius 0.004 0.008 --fcc \
      --bar 0 0.09 0.1 0.3925 0.09 0.1 0.005 0.0075 --bar 0.19 0 0.05 0.19 0.1925 0.05 0.005 0.0075
    vars=(-var bx p -var by p -var vel "30 30 0" -var extra "tries 15 regrow no") ;;
  *) echo "identical_every_test.sh: unknown scene $kind"; exit 2 ;;
esac

run() {    # run DIR NP GRID
  local dir=$1 n=$2 g=$3
  mkdir -p "$dir"
  local launch=(mpirun -np "$n")
  [ "$n" -eq 1 ] && launch=()    # serial: the executable itself
  (cd "$indir" && "${launch[@]}" "$exe" -in in.identical_every -var data "$work/scene.data" -var out "$dir" \
     -var procs "$g" "${vars[@]}" -log "$dir/log" -screen none) ||
    { tail -5 "$dir/log" || true; fail "$host with $n processes exited non-zero"; }
  grep -q '^END ' "$dir/log" || fail "$host with $n processes did not finish the input"
  grep '^fix reinforce/invert: [0-9]' "$dir/log" >"$dir/lines" || true
}
# The counts of each invocation: targets relocated deleted kept.
counts() {
  awk '{ for (i = 2; i <= NF; i++) { w = $i; sub(/,$/, "", w)
           if (w == "targets") t = $(i - 1); if (w == "relocated") r = $(i - 1)
           if (w == "deleted") d = $(i - 1); if (w == "kept") k = $(i - 1) }
         print t, r, d, k }' "$1"
}

run "$work/n" "$np" "$grid"
run "$work/ref" 1 "1 1 1"

steps=(0 10 20 30 40 50)
for d in n ref; do
  label="$np processes"; [ $d = ref ] && label="1 process"
  counts "$work/$d/lines" >"$work/$d/counts"
  echo "$label ($([ $d = ref ] && echo "1 1 1" || echo "$grid")): targets relocated deleted kept at steps ${steps[*]}:"
  paste -d' ' <(printf '  step %s:\n' "${steps[@]}") "$work/$d/counts"
  n_inv=$(wc -l <"$work/$d/counts")
  [ "$n_inv" -eq 6 ] || fail "$label: $n_inv invocations, expected 6 (steps ${steps[*]})"
  # Not vacuous: the moving bars find new targets at every invocation, and
  # they are relocated.
  idle=$(awk '$2 <= 0' "$work/$d/counts" | wc -l)
  [ "$idle" -eq 0 ] || fail "$label: $idle invocations relocated nothing: the comparison would test little"
  read -r _ start < <(grep '^START' "$work/$d/log")
  read -r _ end < <(grep '^END' "$work/$d/log")
  deleted=$(awk '{s += $3} END {print s}' "$work/$d/counts")
  written=$(awk '/^ITEM: NUMBER OF ATOMS/ {getline; print $1}' "$work/$d/after.dump")
  [ "$end" -eq $((start - deleted)) ] || fail "$label: $end atoms at the end, expected $start - $deleted deleted"
  [ "$written" -eq "$end" ] || fail "$label: $written atoms written, $host counts $end"
done
if [ "$kind" = periodic ]; then
  later=$(awk 'NR > 1 {s += $3} END {print s + 0}' "$work/n/counts")
  [ "$later" -gt 0 ] || fail "no deletion after step 0: the scene does not test deletions during the run"
  # The bars move towards +x and +y: a bar sphere whose x (y) is smaller at
  # the end than at step 0 went through the periodic boundary in x (y).
  read -r wx wy < <(awk '/^ITEM: ATOMS/ {delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next}
      /^ITEM:/ {body = 0; next}
      !body || $c["type"] != 2 {next}
      FNR == NR {if (!($c["id"] in x)) {x[$c["id"]] = $c["x"]; y[$c["id"]] = $c["y"]}; next}
      {if ($c["x"] < x[$c["id"]]) nx++; if ($c["y"] < y[$c["id"]]) ny++}
      END {print nx + 0, ny + 0}' "$work/n/every.dump" "$work/n/after.dump")
  echo "bar spheres through the periodic boundary: $wx in x, $wy in y"
  if [ "$wx" -eq 0 ] || [ "$wy" -eq 0 ]; then fail "the bars did not cross both periodic boundaries"; fi
fi

# The snapshots after each invocation, one file per step.
split_dump() {    # split_dump DUMP DIR: DIR/<step> per snapshot
  awk -v dir="$2" '/^ITEM: TIMESTEP/ {getline; f = dir "/" $1; print "ITEM: TIMESTEP" >f; print $1 >f; next}
                   {print >f}' "$1"
}
mkdir -p "$work/n/snap" "$work/ref/snap"
split_dump "$work/n/every.dump" "$work/n/snap"
split_dump "$work/ref/every.dump" "$work/ref/snap"
first_diff=""
for s in "${steps[@]}"; do
  for d in n ref; do [ -f "$work/$d/snap/$s" ] || fail "no snapshot of step $s in $d/every.dump"; done
  if ! cmp -s "$work/n/snap/$s" "$work/ref/snap/$s"; then first_diff=$s; break; fi
done
if [ -n "$first_diff" ]; then
  echo "the atoms differ first after the invocation at step $first_diff ($np processes, grid $grid, against 1 process):"
  awk '/^ITEM: ATOMS/ {body = 1; next} /^ITEM:/ {body = 0; next} body {print}' "$work/n/snap/$first_diff" | sort -k1,1n >"$work/n.atoms"
  awk '/^ITEM: ATOMS/ {body = 1; next} /^ITEM:/ {body = 0; next} body {print}' "$work/ref/snap/$first_diff" | sort -k1,1n >"$work/ref.atoms"
  # The atoms missing from one run or whose line differs, by id: the line
  # of the NPROCS run, then the 1-process run's.
  awk -v np="$np" 'FNR == NR {a[$1] = $0; next} {b[$1] = $0}
    END { for (id in a) if (!(id in b)) print id, 0, "np=" np ": " a[id], "(not in the 1-process run)"
          for (id in b) if (!(id in a)) print id, 1, "np=1: " b[id], "(not in the " np "-process run)"
          for (id in a) if ((id in b) && a[id] != b[id]) { print id, 0, "np=" np ": " a[id]; print id, 1, "np=1: " b[id] } }' \
    "$work/n.atoms" "$work/ref.atoms" | sort -k1,1n -k2,2n >"$work/differ"
  ndiff=$(cut -d' ' -f1 "$work/differ" | uniq | wc -l)
  cut -d' ' -f1,3- "$work/differ" | head -40 | sed 's/^/  id /'
  echo "  $ndiff atoms differ$([ "$ndiff" -gt 20 ] && echo " (the first 20 or so shown)")"
  diff <(head -9 "$work/n/snap/$first_diff" | grep -v '^ITEM: ATOMS') <(head -9 "$work/ref/snap/$first_diff" | grep -v '^ITEM: ATOMS') ||
    echo "  (the header lines above differ)"
  echo "counts at each invocation ($np processes | 1 process):"
  paste -d'|' "$work/n/counts" "$work/ref/counts"
  fail "the atoms after the invocation at step $first_diff differ between $np processes and 1 process"
fi
echo "PASS: identical atoms after each of the 6 invocations (steps ${steps[*]}), $(awk '/^ITEM: NUMBER OF ATOMS/ {getline; print $1}' "$work/n/snap/50") atoms at the end"
cmp -s "$work/n/counts" "$work/ref/counts" || {
  paste -d'|' "$work/n/counts" "$work/ref/counts"; fail "the counts of the invocations differ (above: $np processes | 1 process)"; }
echo "PASS: the same counts at each invocation"
for f in before_last.dump after.dump; do
  cmp -s "$work/n/$f" "$work/ref/$f" || fail "$f differs between $np processes and 1 process"
done
"$checker" --same "$work/n/after.dump" "$work/ref/after.dump" || fail "check_scene --same: the end differs"

# The checker on the NPROCS run: no matrix sphere on a bar at the end, and
# every pair at the last invocation.
read -r _ _ _ _ _ matrix_rebar _ _ < <("$checker" --stats "$work/n/after.dump" --rmin 0.004)
echo "largest matrix-bar overlap at the end: $matrix_rebar rmin"
awk -v o="$matrix_rebar" 'BEGIN {exit !(o <= 1e-6)}' || fail "a matrix sphere overlaps a bar"
"$here/scripts/last_invocation.sh" "$checker" "$work/n/before_last.dump" "$work/n/after.dump" \
  "$(sed -n 6p "$work/n/lines")" --rmin 0.004 --rmax 0.008 || exit 1
echo "PASS identical_every $host $kind np=$np"
