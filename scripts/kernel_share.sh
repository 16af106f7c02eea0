#!/usr/bin/env bash
# How much of an invocation's time the kernel takes under the defaults:
# runs the beam at solid fraction 0.60 (examples/beam, the fix's defaults,
# REINFORCE_BEAM_NP processes, default 2) and reads the fix's log lines:
# the invocation's time and kernel solves (the summary line) and the
# regrowth's time (the regrowth line). The kernel's time per solve is
# docs/kernel.md's table (inversion, and inversion + 1 Newton, on the
# well-conditioned set: the engine polishes only the solutions its filter
# keeps, so its cost per solve lies between the two). Rewrites the
# paragraph of docs/kernel.md between the kernel-share markers.
#   bash scripts/kernel_share.sh
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${REINFORCE_BUILD:-}" ]; then source "$top/scripts/setup.sh"; fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
lmp="$REINFORCE_BUILD/src/lammps/lmp_reinforce"
[ -x "$lmp" ] || { echo "kernel_share: $lmp was not built"; exit 1; }
np=${REINFORCE_BEAM_NP:-2}
page="$top/docs/kernel.md"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
load=$(cut -d' ' -f1 /proc/loadavg)
(cd "$top/examples/beam" &&
   mpirun -np "$np" "$lmp" -in in.beam -var phi 060 -var out "$out" -log "$out/log" -screen none)
summary=$(grep '^fix reinforce/invert: [0-9]* targets' "$out/log")
regrowth=$(grep '^fix reinforce/invert: regrowth: [0-9]' "$out/log" || true)
echo "$summary"
echo "$regrowth"
total=$(sed -E 's/.*rounds, ([0-9.]+) s .*/\1/' <<<"$summary")
solves=$(sed -E 's/.* ([0-9]+) solves.*/\1/' <<<"$summary")
targets=$(sed -E 's/^fix reinforce\/invert: ([0-9]+) targets.*/\1/' <<<"$summary")
regrow=0 steps=0
if [ -n "$regrowth" ]; then
  regrow=$(sed -E 's/.* ([0-9.]+) s(;.*)?$/\1/' <<<"$regrowth")
  steps=$(sed -E 's/.* ([0-9]+) steps,.*/\1/' <<<"$regrowth")
fi
# ns per solve from the page's own table.
ns() { awk -F'|' -v s="$1" '$2 ~ /well-conditioned/ && $3 ~ "^ " s " $" {gsub(/ /, "", $7); print $7}' "$page"; }
raw=$(ns "inversion") polished=$(ns "inversion \\+ 1 Newton")
[ -n "$raw" ] && [ -n "$polished" ] || { echo "kernel_share: no ns/solve in $page"; exit 1; }
paragraph=$(awk -v t="$total" -v g="$regrow" -v s="$solves" -v n="$targets" -v st="$steps" \
                -v a="$raw" -v b="$polished" -v np="$np" -v load="$load" -v day="$(date +%Y-%m-%d)" 'BEGIN {
  rest = t - g; lo = s * a * 1e-9; hi = s * b * 1e-9
  printf "Under the defaults the kernel is not where an invocation spends its time:\n"
  printf "the regrowth is. The beam at 0.60 (`bash scripts/kernel_share.sh`: `examples/beam`,\n"
  printf "the fix'\''s defaults, %d processes, %s, load average %s at the start) took %.2f s,\n", np, day, load, t
  printf "of which the regrowth took %.2f s (%.0f%%, %d FIRE steps) and the relocation with the\n", g, 100 * g / t, st
  printf "rest of the invocation %.2f s. Its %d targets made %d kernel solves: at %s to %s ns\n", rest, n, s, a, b
  printf "a solve (the table above: the engine polishes only the solutions its filter keeps),\n"
  printf "%.2f to %.2f s of kernel: %.0f%% to %.0f%% of the relocation'\''s %.2f s, %.0f%% to %.0f%% of the\n", lo, hi, 100 * lo / rest, 100 * hi / rest, rest, 100 * lo / t, 100 * hi / t
  printf "invocation. Fewer solves per target (`choose first`, a smaller `tries`) or a faster\n"
  printf "kernel would shorten the relocation, not the invocation: the regrowth'\''s FIRE steps\n"
  printf "are where its time goes. The fix'\''s lines of that run:\n"
}')
paragraph+=$'\n\n'"$(grep -E '^fix reinforce/invert: (regrowth: [0-9]|[0-9]+ targets)' "$out/log" | sed 's/^/    /')"
python3 - "$page" "$paragraph" <<'EOF'
import sys
page, paragraph = sys.argv[1], sys.argv[2]
text = open(page).read()
begin, end = "<!-- kernel-share: written by scripts/kernel_share.sh -->", "<!-- /kernel-share -->"
i, j = text.find(begin), text.find(end)
if i < 0 or j < i:
    sys.exit(f"kernel_share: no markers {begin} ... {end} in {page}")
open(page, "w").write(text[:i + len(begin)] + "\n" + paragraph + "\n" + text[j:])
EOF
echo
echo "$paragraph"
