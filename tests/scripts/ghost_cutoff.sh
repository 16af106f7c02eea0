#!/usr/bin/env bash
# What the fix (LAMMPS) logged about the ghost cutoff, one expectation per log:
#   ghost_cutoff.sh EXPECT... LOG...      (as many EXPECTs as LOGs, in order)
# run_scene.sh runs it as SCENE_LOG_POST ("ghost_cutoff.sh kept raised"),
# given the log of the run and that of its 1-process reference run.
#   raised  the scene needs more ghosts than the cutoff gives: at least one
#           line, and every one exactly
#             fix reinforce/invert: ghost cutoff raised from A to B for the STAGE
#           (STAGE: relocation or regrowth)
#           with B > A (a raise that took no effect, or lowered it, fails);
#   kept    the cutoff already reaches far enough (a large comm_modify
#           cutoff): no such line, the fix leaves the cutoff alone.
set -uo pipefail
[ $# -ge 2 ] && [ $(($# % 2)) -eq 0 ] || { echo "FAIL: usage: ghost_cutoff.sh EXPECT... LOG..."; exit 2; }
n=$(($# / 2))
args=("$@")
fail=0
for ((i = 0; i < n; i++)); do
  want=${args[i]} log=${args[i + n]}
  [ -f "$log" ] || { echo "FAIL: ghost cutoff: no log $log"; fail=1; continue; }
  lines=$(grep 'ghost cutoff raised' "$log" || true)
  count=$(grep -c 'ghost cutoff raised' "$log" || true)
  case $want in
    raised)
      if [ "$count" -eq 0 ]; then
        echo "FAIL: ghost cutoff: the scene needs a raise, $log has no 'ghost cutoff raised' line"; fail=1
      elif ! awk '{
            if (!match($0, /^fix reinforce\/invert: ghost cutoff raised from [-+0-9.eE]+ to [-+0-9.eE]+ for the (relocation|regrowth)$/)) {
              print "FAIL: ghost cutoff: not the fix'"'"'s line: " $0; bad = 1; next
            }
            a = $7 + 0; b = $9 + 0
            if (!(b > a)) { print "FAIL: ghost cutoff: raised from " $7 " to " $9 ", not above it"; bad = 1 }
          } END { exit bad }' <<<"$lines"; then
        fail=1
      else
        echo "PASS: ghost cutoff raised ($count lines, e.g. $(head -1 <<<"$lines" | sed 's/.*raised //')) in $(basename "$(dirname "$log")")/$(basename "$log")"
      fi ;;
    kept)
      if [ "$count" -ne 0 ]; then
        echo "FAIL: ghost cutoff: it reached far enough, yet $log says: $(head -1 <<<"$lines")"; fail=1
      else
        echo "PASS: ghost cutoff kept (no raise) in $(basename "$(dirname "$log")")/$(basename "$log")"
      fi ;;
    *) echo "FAIL: ghost cutoff: unknown expectation '$want' (raised, kept)"; fail=1 ;;
  esac
done
exit "$fail"
