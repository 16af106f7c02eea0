#!/usr/bin/env bash
# Both hosts read what reinforce_layout wrote for scene.layout (a cage with
# hooked bars, a mesh, fibres):
#  * LAMMPS (in.read_lammps): the data file by read_data ... add append group
#    rebar (every sphere, as written); a hooked bar's and a stirrup's molecule
#    files by create_atoms single at the centre the file states, then fix
#    rigid on the clump: its spheres where the data file has them (1e-12 of
#    the box), its mass the molecule's;
#  * LIGGGHTS (in.read_liggghts): the hooked bar's and the stirrup's
#    particletemplate/multisphere sphere lists, inserted as fix multisphere
#    clumps: every sphere, the shape kept (1e-9 of the box; LIGGGHTS puts a
#    clump by its Monte Carlo centre of mass).
#   host_read.sh lammps|liggghts BUILD_DIR [NP]
set -euo pipefail
host=$1 build=$2 np=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../scripts/test_env.sh" "layout_read_${host}"
"$build/src/layout/reinforce_layout" "$here/scene.layout" --data "$work/bars.data" --molecules "$work/mol" \
  --liggghts "$work/templates.liggghts" > "$work/summary.txt"
launch=()
[ "$np" -gt 1 ] && launch=(mpirun -np "$np")
for clump in bar_l4_1 stirrup_l4_2; do
  if [ "$host" = lammps ]; then
    centre=$(sed -n 's/^# centre \([^:]*\):.*/\1/p' "$work/mol/$clump.mol")
    (cd "$work" && "${launch[@]}" "$build/src/lammps/lmp_reinforce" -in "$here/in.read_lammps" -log "$work/log_$clump" \
       -screen none -var bars "$work/bars.data" -var mol "$work/mol/$clump.mol" -var centre "$centre" -var out "$work") ||
      { echo "FAIL: lmp_reinforce exited non-zero"; tail -5 "$work/log_$clump"; exit 1; }
    grep '^REBAR' "$work/log_$clump"
  else
    sed "s/@CLUMP@/$clump/" "$here/in.read_liggghts" > "$work/in.read_liggghts"
    read -r cx cy cz < <(sed -n "s/^# $clump: centre //p" "$work/templates.liggghts")
    (cd "$work" && "${launch[@]}" "$build/src/liggghts/liggghts_reinforce" -in "$work/in.read_liggghts" \
       -log "$work/log_$clump" -var templates "$work/templates.liggghts" -var out "$work" \
       -var cx "$cx" -var cy "$cy" -var cz "$cz" \
       > "$work/screen_$clump") || { echo "FAIL: liggghts_reinforce exited non-zero"; tail -5 "$work/log_$clump"; exit 1; }
  fi
  python3 "$here/check_read.py" "$host" "$work/bars.data" "$work/mol/$clump.mol" "$work/read.dump" "$work/log_$clump" ||
    { echo "FAIL: $clump read back by $host"; exit 1; }
done
echo "PASS layout read $host np=$np"
