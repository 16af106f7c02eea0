#!/usr/bin/env bash
# The fix with bars placed from reinforce_layout's clump outputs, as a user
# places them: scene.layout's hooked bar bar_l4_1 and mesh bar mesh_l5_b2
# (with a stirrup, 229 spheres, the LIGGGHTS run took 18 s against 7 s) put at
# the centres their files state into a packing (make_scene), then
# run_scene.sh (the checker: no overlap, rebar untouched, atoms conserved;
# the counts against the fix's).
#  * LAMMPS: each clump's molecule file (--molecules) by molecule and
#    create_atoms ... mol, type 2, the two one rigid body (fix rigid
#    single), in.scene's setup;
#  * LIGGGHTS: each clump's particletemplate/multisphere sphere list
#    (--liggghts) inserted once at its centre as a fix multisphere body of
#    type 2 (insert/pack, run 1), in.scene's hook1; its screen output to
#    a file (SCENE_SCREEN_FILE=1: with -screen none it crashes).
# Every sphere of both clumps must be there as rebar, type 2, before the
# fix (rebar_count.sh on the dumps), and the fix must have had targets.
#   host_clumps.sh lammps|liggghts NAME NP BUILD_DIR -- MAKE_SCENE_ARGS -- HOST_VARS -- CHECK_ARGS
set -euo pipefail
host=$1 name=$2 np=$3 build=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../scripts/test_env.sh" "layout_${name}"
split_lists "$@"
clumps=(bar_l4_1 mesh_l5_b2)
"$build/src/layout/reinforce_layout" "$here/scene.layout" --molecules "$work/mol" \
  --liggghts "$work/templates.liggghts" >/dev/null
"$build/tests/make_scene" "$work/matrix.data" "${list_a[@]}"
spheres=0
for c in "${clumps[@]}"; do
  spheres=$((spheres + $(awk '$2 == "atoms" {print $1; exit}' "$work/mol/$c.mol")))
done
export SCENE_POST="$here/rebar_count.sh $spheres"
case $host in
  lammps)
    {
      for c in "${clumps[@]}"; do
        centre=$(sed -n 's/^# centre \([^:]*\):.*/\1/p' "$work/mol/$c.mol")
        echo "molecule        $c $work/mol/$c.mol toff 1"
        echo "create_atoms    0 single $centre mol $c 7 rotate 0 0 0 1 units box"
      done
      echo "group           rebar type 2"
      echo "fix             bars rebar rigid single"
    } >"$work/clumps.in"
    "$here/../scripts/run_scene.sh" "$name" "$build/src/lammps/lmp_reinforce" "$np" "$here/../lammps/in.scene" \
      "$build/tests/check_scene" -- -var data "$work/matrix.data" -var setup "include $work/clumps.in" \
      "${list_b[@]}" -- "${list_c[@]}" ;;
  liggghts)
    {
      echo "include         $work/templates.liggghts"
      echo "fix             m1 all property/global youngsModulus peratomtype 1e8 1e8"
      echo "fix             m2 all property/global poissonsRatio peratomtype 0.3 0.3"
      echo "fix             m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3"
      echo "fix             m4 all property/global coefficientFriction peratomtypepair 2 0.0 0.0 0.0 0.0"
      echo "pair_style      gran model hertz tangential history"
      echo "pair_coeff      * *"
      echo "timestep        1e-9"
      # LIGGGHTS takes only primes > 10000 for seeds: two of each.
      tseeds=(15485863 15485867) dseeds=(32452843 32452867) iseeds=(49979687 49979693)
      for k in 0 1; do
        echo "fix             tpl$k all particletemplate/multisphere ${tseeds[k]} atom_type 2 density constant 7800 \${${clumps[k]}} type $((k + 1)) fflag off off off tflag off off off"
        echo "fix             dist$k all particledistribution/discrete ${dseeds[k]} 1 tpl$k 1.0"
      done
      echo "fix             clumps all multisphere allow_group_and_set yes"
      for k in 0 1; do
        read -r cx cy cz < <(sed -n "s/^# ${clumps[k]}: centre //p" "$work/templates.liggghts")
        echo "region          at$k block $(awk -v x="$cx" -v y="$cy" -v z="$cz" 'BEGIN {printf "%.17g %.17g %.17g %.17g %.17g %.17g", x - 1e-6, x + 1e-6, y - 1e-6, y + 1e-6, z - 1e-6, z + 1e-6}') units box volume_limit 1e-20"
        echo "fix             ins$k all insert/pack seed ${iseeds[k]} distributiontemplate dist$k insert_every once overlapcheck no orientation template particles_in_region 1 region at$k"
        echo "run             1"
        echo "unfix           ins$k"
      done
      echo "group           rebar type 2"
    } >"$work/clumps.in"
    SCENE_SCREEN_FILE=1 "$here/../scripts/run_scene.sh" "$name" "$build/src/liggghts/liggghts_reinforce" "$np" "$here/../liggghts/in.scene" \
      "$build/tests/check_scene" -- -var data "$work/matrix.data" -var hook1 "include $work/clumps.in" \
      "${list_b[@]}" -- "${list_c[@]}" ;;
  *) echo "FAIL: unknown host $host"; exit 2 ;;
esac
