#!/usr/bin/env bash
# f_ID[12], the matrix volume removed, against the dumps (in.removed):
# the matrix (every atom but the rebar, type 2) before less the matrix after,
# less what the spheres still there lost (targets placed shrunk: not in
# f_ID[12], the doc page says), to 1e-9 relative.
#   removed_volume.sh NAME NP BUILD_DIR -- MAKE_SCENE_ARGS|beam -- [lmp -var args]
# "beam": the beam at 0.60 of examples/beam (its matrix and bars data).
# REMOVED_DELETED=some: the scene must lose matrix spheres.
set -euo pipefail
name=$1 np=$2 build=$3
shift 3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here/../scripts/test_env.sh" "removed_${name}"
split_lists "$@"
fail() { echo "FAIL: $name np=$np: $*"; exit 1; }
if [ "${list_a[*]}" = beam ]; then
  beam=$here/../../examples/beam/data
  data=(-var data "$beam/matrix_phi060.data.gz" -var bars "$beam/bars.data" -var withbars yes)
else
  "$build/tests/make_scene" "$work/scene.data" "${list_a[@]}" >/dev/null
  data=(-var data "$work/scene.data")
fi
launch=(mpirun -np "$np")
[ "$np" -eq 1 ] && launch=()
(cd "$here" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in in.removed -log "$work/log" -screen none \
   -var out "$work" "${data[@]}" "${list_b[@]}") || fail "lmp_reinforce exited non-zero"
read -r _ targets relocated deleted kept <<<"$(grep '^TOTALS ' "$work/log" | tail -1)"
f12=$(grep '^REMOVED ' "$work/log" | tail -1 | cut -d' ' -f2)
[ -n "$f12" ] || fail "no REMOVED line"
echo "$name np=$np: targets $targets relocated $relocated deleted $deleted kept $kept; f_ID[12] = $f12"
awk -v f12="$f12" -v want_deleted="${REMOVED_DELETED:-any}" '
  function vol(r) { return 4.188790204786391 * r * r * r }    # 4 pi / 3 r^3
  FNR == 1 { file++ }
  /^ITEM: ATOMS/ { delete c; for (i = 3; i <= NF; i++) c[$i] = i - 2; body = 1; next }
  /^ITEM:/ { body = 0; next }
  !body || $c["type"] == 2 { next }
  file == 1 { r[$c["id"]] = $c["radius"]; before += vol($c["radius"]); next }
  {
    id = $c["id"]; after += vol($c["radius"]); there[id] = 1
    if ($c["radius"] != r[id]) { lost += vol(r[id]) - vol($c["radius"]); resized++ }
  }
  END {
    for (id in r) if (!(id in there)) gone++
    removed = before - after - lost
    d = removed - f12; if (d < 0) d = -d
    scale = f12 < 0 ? -f12 : f12
    if (removed > scale) scale = removed
    if (lost > scale) scale = lost
    printf "matrix before %.17g, after %.17g, lost by %d resized spheres %.17g: removed %.17g (%d atoms gone)\n", before, after, resized, lost, removed, gone + 0
    if (want_deleted == "some" && gone == 0) { print "FAIL: no matrix sphere was deleted"; exit 1 }
    if (!(scale > 0) || d > 1e-9 * scale) { printf "FAIL: f_ID[12] = %.17g, the dumps: %.17g\n", f12, removed; exit 1 }
    printf "PASS: f_ID[12] = the matrix volume removed in the dumps (%.17g, to %.1e)\n", removed, d / scale
  }' "$work/before.dump" "$work/after.dump" || exit 1
echo "PASS removed_volume $name np=$np"
