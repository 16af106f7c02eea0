#!/usr/bin/env bash
# scene_quality's own tests (and grow_packing's): each assertion passes on a
# scene made to pass it and fails on one made to fail it.
#   test_scene_quality.sh GROW_PACKING SCENE_QUALITY
set -uo pipefail
grow_exe=$1 sq=$2
grow() { "$grow_exe" "$@" --max-seconds 60; }
work=$(mktemp -d "${TMPDIR:-/tmp}/sq_selftest.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
# expect STATUS PATTERN -- command...: exit status and a line of its output
expect() {
  local want=$1 pattern=$2
  shift 3
  local out status
  out=$("$@" 2>&1); status=$?
  if [ "$status" -ne "$want" ] || ! grep -q -- "$pattern" <<<"$out"; then
    echo "NOT OK: expected exit $want and '$pattern' from: $*"
    echo "$out" | tail -15
    failures=$((failures + 1))
  else
    echo "ok: exit $status, '$pattern'"
  fi
}
box=(--box 0 0.08 0 0.06 0 0.06)
bar=(--bar 0.004 0.03 0.03 0.076 0.03 0.03 0.004 0.006)
# Packings: radius ratio 3 and 1.25, alone and around a bar.
expect 0 "grow_packing: ok" -- grow "$work/ref.data" "${box[@]}" --radius 0.002 0.006 --phi 0.50 "${bar[@]}" --around-bars --seed 3
expect 0 "grow_packing: ok" -- grow "$work/before.data" "${box[@]}" --radius 0.002 0.006 --phi 0.50 "${bar[@]}" --seed 4
expect 0 "grow_packing: ok" -- grow "$work/narrow.data" "${box[@]}" --radius 0.004 0.005 --phi 0.50 "${bar[@]}" --around-bars --seed 5
expect 0 "grow_packing: ok" -- grow "$work/periodic.data" "${box[@]}" --boundary p p f --radius 0.002 0.006 --phi 0.55 --seed 6
expect 2 "grow_packing: --around-bars without --bar" -- grow "$work/x.data" "${box[@]}" --radius 0.002 0.006 --phi 0.58 --around-bars
Q=("$sq" --points 300000)
# The same scene as before, after and reference: KS 0, nothing moved, the
# shell equal to the reference's, sampling agrees with the volumes.
expect 0 "QUALITY .*ks=0.00000" -- "${Q[@]}" --before "$work/ref.data" --after "$work/ref.data" --reference "$work/ref.data" \
  --shell-vs-reference -0.01 0.02 --bin-diff 0.06 3 --ks-max 0 --moved-within 0 --check-sampling
expect 0 "PASS: sampled solid fraction" -- "${Q[@]}" --after "$work/narrow.data" --check-sampling
expect 0 "PASS: sampled solid fraction" -- "${Q[@]}" --after "$work/periodic.data" --boundary p p f --check-sampling
# A hollow shell: matrix spheres whose centre is within rmax of the bar
# surface removed. Fails the shell and the bin assertions.
awk '/^Atoms/ {atoms = 1; print; next}
     atoms && NF >= 7 && $2 == 1 { d = sqrt(($6 - 0.03)^2 + ($7 - 0.03)^2) - 0.004; if (d < 0.006) next }
     {print}' "$work/ref.data" > "$work/hollow.data"
expect 1 "FAIL: shell ratio minus the reference" -- "${Q[@]}" --after "$work/hollow.data" --reference "$work/ref.data" --shell-vs-reference -0.01 0.02
expect 1 "FAIL: no profile bin out to 3 rmax" -- "${Q[@]}" --after "$work/hollow.data" --reference "$work/ref.data" --bin-diff 0.06 3
# Over-dense is caught by --shell-max-over-reference: the reference against
# the hollow scene as its "reference".
expect 1 "FAIL: shell ratio minus the reference's .* <= 0.02" -- "${Q[@]}" --after "$work/ref.data" --reference "$work/hollow.data" --shell-max-over-reference 0.02
expect 0 "PASS: shell ratio minus the reference's .* <= 0.02" -- "${Q[@]}" --after "$work/hollow.data" --reference "$work/ref.data" --shell-max-over-reference 0.02
# The larger half of the radii deleted (ids are in radius order): KS = 0.5.
n=$(awk '/^Atoms/ {a = 1; next} a && NF >= 7 && $2 == 1 {n++} END {print n}' "$work/ref.data")
awk -v half=$((n / 2)) '/^Atoms/ {a = 1; print; next} a && NF >= 7 && $2 == 1 && $1 > half {next} {print}' \
  "$work/ref.data" > "$work/half.data"
expect 1 "FAIL: KS statistic 0.5" -- "${Q[@]}" --before "$work/ref.data" --after "$work/half.data" --ks-max 0.45
# One sphere far from the bar moved by 1e-6 (1e-4 of the box): fails
# --moved-within 3rmax, passes when the limit reaches it.
far=$(awk '/^Atoms/ {a = 1; next} a && NF >= 7 && $2 == 1 { d = sqrt(($6 - 0.03)^2 + ($7 - 0.03)^2); if (d > best) {best = d; id = $1} } END {print id}' "$work/ref.data")
awk -v id="$far" '/^Atoms/ {a = 1; print; next} a && NF >= 7 && $1 == id { $5 = sprintf("%.17g", $5 + 1e-6) } {print}' \
  "$work/ref.data" > "$work/moved.data"
expect 1 "FAIL: 1 non-target spheres farther than" -- "${Q[@]}" --before "$work/ref.data" --after "$work/moved.data" --moved-within 3rmax
expect 0 "PASS: 0 non-target spheres farther than" -- "${Q[@]}" --before "$work/ref.data" --after "$work/moved.data" --moved-within 1
# Targets: the packing grown without the bar has matrix spheres on it.
expect 0 "QUALITY .*targets=[1-9]" -- "${Q[@]}" --before "$work/before.data" --after "$work/before.data"
# Union volume against the exact one: two unit spheres 1 apart (a lens of
# 5 pi / 12 in common) and one of radius 0.5: 29 pi / 12.
cat > "$work/union.data" <<'DATA'
union test

4 atoms
2 atom types

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Atoms

1 2 2 7800 5 5 5
2 2 2 7800 6 5 5
3 2 1 7800 2 2 2
4 1 1 2500 8 8 8
DATA
expect 0 "PASS: union volume" -- "$sq" --after "$work/union.data" --expect-union 7.592182246175333 --points 10000
expect 1 "FAIL: union volume" -- "$sq" --after "$work/union.data" --expect-union 8.901179185171081 --points 10000
expect 2 "needs --reference" -- "$sq" --after "$work/union.data" --shell-vs-reference -0.01 0.02
if [ "$failures" -gt 0 ]; then echo "FAIL: $failures cases"; exit 1; fi
echo "PASS: all cases"
