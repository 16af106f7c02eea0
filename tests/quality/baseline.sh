#!/usr/bin/env bash
# The quality figures of the fix (defaults) and of delete_atoms overlap
# (cutoff r_bar + rmax, as bench/) on the quality scenes, one process, no
# assertion: the baseline table of tests/quality/README.md.
#   baseline.sh BUILD_DIR [SCENES]     (SCENES made by make_scenes.sh when missing)
set -euo pipefail
build=$(cd "$1" && pwd)
scenes=${2:-$build/tests/quality/scenes}
here=$(cd "$(dirname "$0")" && pwd)
for c in wide narrow dense; do
  [ -f "$scenes/$c/ref.data" ] || bash "$here/make_scenes.sh" "$build/tests/grow_packing" "$scenes" "$c"
done
tools=("$build/src/lammps/lmp_reinforce" "$build/tests/check_scene" "$build/tests/scene_quality" "$scenes")
printf '%-7s %-13s %7s %7s %8s %8s %8s %8s %8s %7s\n' case method targets deleted shell ref_shell diff removed KS bin_diff
for c in wide narrow dense; do
  cut=0.0125; [ "$c" = narrow ] && cut=0.01    # r_bar + rmax
  for m in fix delete; do
    vars=""; [ "$m" = delete ] && vars="-var method delete -var cut $cut"
    out=$(QUALITY_LMP_VARS="$vars" bash "$here/quality.sh" "$c" 1 "${tools[@]}" 2>&1) || { echo "$out" | tail -5; exit 1; }
    q=$(grep '^QUALITY' <<<"$out")
    get() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$q"; }
    printf '%-7s %-13s %7s %7s %8s %8s %8s %8s %8s %7s\n' "$c" "$m" "$(get targets)" "$(get deleted)" \
      "$(get shell_ratio)" "$(get ref_shell_ratio)" "$(get shell_vs_reference)" "$(get removed_ratio)" "$(get ks)" "$(get bin_diff_max)"
  done
done
