#!/usr/bin/env bash
# The lost-matrix WARNING with N > 0: once per run, whatever the number of
# invocations of that run that lost matrix (in.lost_every of the host: two
# runs, three invocations or more each that lose some). The WARNING lines
# of the log (without a " (file:line)" suffix) must be exactly those
# lost_every_expect.py derives from the dumps, in order: one per run, with
# the counts of the run's first invocation that lost matrix; each run must
# have two such invocations or more (or the guard is not exercised), and
# the host's atom count at the end must be the last dump's.
#   lost_every.sh lammps|liggghts NP BUILD_DIR
set -euo pipefail
host=$1 np=$2 build=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here/test_env.sh" "lost_every_${host}"
fail() { echo "FAIL: lost_every $host np=$np: $*"; exit 1; }
case $host in
  lammps) exe=$build/src/lammps/lmp_reinforce ;;
  liggghts) exe=$build/src/liggghts/liggghts_reinforce ;;
  *) echo "lost_every.sh: unknown host $host"; exit 2 ;;
esac
# Radii too alike for the voids to hold the targets; a bar along x moving
# up through the packing.
"$build/tests/make_scene" "$work/scene.data" --box 0 0.1 0 0.1 0 0.1 --radius 0.0045 0.005 --fcc \
  --bar 0.01 0.05 0.04 0.09 0.05 0.04 0.005 0.0075 >/dev/null
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
(cd "$here/../$host" && timeout 300 "${launch[@]}" "$exe" -in in.lost_every -var data "$work/scene.data" \
   -var out "$work" -log "$work/log" -screen none) >"$work/stdout" 2>&1 || fail "$exe exited non-zero"
python3 "$here/lost_every_expect.py" "$work/before.dump" "$work/every.dump" 40 70 >"$work/expect" ||
  { cat "$work/expect"; fail "the dumps"; }
grep '^INVOCATION' "$work/expect"
for range in "0 40" "50 70"; do
  read -r a b <<<"$range"
  n=$(awk -v a="$a" -v b="$b" '$1 == "INVOCATION" && $2 >= a && $2 <= b && $8 == 1' "$work/expect" | wc -l)
  [ "$n" -ge 2 ] || fail "the run of steps $a to $b has $n invocations that lose matrix, expected 2 or more"
done
expected=$(sed -n 's/^EXPECT //p' "$work/expect")
got=$(sed -nE 's/^(WARNING: Fix reinforce\/invert regrowth .*[^)])( \([^()]*:[0-9]+\))?$/\1/p' "$work/log")
if [ "$got" != "$expected" ]; then
  echo "expected (from the dumps):"; echo "$expected"
  echo "logged:"; echo "$got"
  fail "the lost-matrix WARNINGs differ from those the dumps call for"
fi
echo "$got"
n=$(grep -c . <<<"$got")
[ "$n" -eq 2 ] || fail "$n lost-matrix WARNINGs, expected one per run (2)"
end=$(sed -n 's/^END //p' "$work/log" | tail -1)
last=$(awk '/^ITEM: NUMBER OF ATOMS/ {getline; n = $1} END {print n}' "$work/every.dump")
[ "$end" = "$last" ] || fail "the host counts $end atoms at the end, the last dump holds $last"
echo "PASS: the lost-matrix WARNING once per run ($n runs, $(grep -c ' 1$' "$work/expect") invocations lost matrix), atoms $end"
echo "PASS lost_every $host np=$np"
